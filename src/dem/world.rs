//! The time step: gather forces, integrate with the leapfrog scheme of eqs (5)–(6), book
//! the energy ledger.
//!
//! One step from tⁿ to tⁿ⁺¹:
//! 1. outlines and bounding boxes at the positions xⁿ;
//! 2. gravity, buoyancy and drag; candidate pairs by sort-and-sweep; contact forces from
//!    eqs (2)–(4) with the half-step velocities vⁿ⁻½;
//! 3. vⁿ⁺½ = vⁿ⁻½ + Δt·Fⁿ/m (eq 5; likewise v and ω), prescribed velocities where a
//!    degree of freedom is driven;
//! 4. the ledger books every force with v̄ⁿ = (vⁿ⁻½ + vⁿ⁺½)/2;
//! 5. xⁿ⁺¹ = xⁿ + Δt·vⁿ⁺½ (eq 6; likewise y and θ).
//!
//! Everything is sequential and in a fixed order, so the same world stepped the same number
//! of times gives bit-identical states.

use super::body::{Block, Bodies, BodyId, Drive, Role, Shape, ShapeError};
use super::boundary::Boundary;
use super::broadphase::{SweepAndPrune, pair_key};
use super::contact::{Contact, ContactParams, ContactSet};
use super::fracture::JointSet;
use super::geometry::{V2, below_line, overlap};
use super::joint::{Joint, JointMaterial};
use super::ledger::{Accumulators, EnergyBudget, Stored};
use super::water::{WaterForces, WaterParams};
use serde::{Deserialize, Serialize};

/// Physical and numerical parameters of a world.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WorldParams {
    /// Acceleration of gravity g (m/s²). Default 9.81.
    pub gravity: f64,
    /// Ice density ρ_i (kg/m³). Default 920 (Hopkins 1994, Table 1).
    pub ice_density: f64,
    /// Contact law, eqs (2)–(4).
    pub contact: ContactParams,
    /// The water, or `None` for a dry scene (no buoyancy, no drag, μ everywhere).
    pub water: Option<WaterParams>,
    /// Safety factor on the stable time step of [`World::stable_time_step`]
    /// (dimensionless, in (0, 1]). Default [`DEFAULT_TIME_STEP_SAFETY`].
    pub time_step_safety: f64,
    /// A fixed time step (s) overriding the derived one, or `None`. It must not exceed the
    /// stable limit of [`World::stable_time_step`].
    pub time_step: Option<f64>,
    /// How the viscous normal force of eq (3) is advanced in time. Default
    /// [`Dashpot::Implicit`].
    #[serde(default)]
    pub contact_dashpot: Dashpot,
    /// Speed at which a crack crosses a joint (m/s). Default 50 m/s; see
    /// [`crate::dem::fracture`] and docs/model.md ("Fracture").
    pub crack_speed: f64,
    /// Mass-proportional numerical damping γ (1/s): F = −γ·m·v, M = −γ·I·ω. Default 0;
    /// used only to relax verification scenes to their static state.
    pub global_damping: f64,
}

impl Default for WorldParams {
    fn default() -> Self {
        Self {
            gravity: 9.81,
            ice_density: 920.0,
            contact: ContactParams::default(),
            water: Some(WaterParams::default()),
            time_step_safety: DEFAULT_TIME_STEP_SAFETY,
            time_step: None,
            contact_dashpot: Dashpot::default(),
            crack_speed: 50.0,
            global_damping: 0.0,
        }
    }
}

/// Default safety factor on the stable time step (dimensionless): see docs/model.md ("Time
/// step") and docs/speed-vs-error.md for the ensembles that chose it.
pub const DEFAULT_TIME_STEP_SAFETY: f64 = 0.8;

/// How the viscous normal contact force of eq (3), F_v = k_nv·(Aⁿ − Aⁿ⁻¹)/Δt, is advanced.
///
/// The overlap rate (Aⁿ − Aⁿ⁻¹)/Δt is the approach speed at n − ½ times the chord L, so
/// eq (3) is a dashpot c = k_nv·L on the normal velocity. Taken explicitly, a dashpot of
/// damping ratio ζ limits the leapfrog step to ω·Δt < 2·(sqrt(1 + ζ²) − ζ): 0.49 for the
/// stiffest contact of a ridge (ζ ≈ 1.9), a quarter of the undamped limit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Dashpot {
    /// Eq (3) as the paper writes it, explicit in the overlap rate.
    Explicit,
    /// Eq (3) at the pair's mid-step approach speed: with u⁻ = (Aⁿ − Aⁿ⁻¹)/(Δt·L) (the
    /// paper's rate) and c = k_nv·L, F_v = c·ū where ū = u⁻ − ½·Δt·(aₙ + κ·F_v): aₙ is
    /// the relative acceleration along the normal of the two contact points under every
    /// other force of the step (gravity, buoyancy, joints, all contacts' elastic forces),
    /// κ the pair's inverse effective mass along the normal (1/m + (r×n)²/I per body, over
    /// its free degrees of freedom). Solved: F_v = (k_nv·(Aⁿ − Aⁿ⁻¹)/Δt − ½·c·Δt·aₙ)/(1 + x),
    /// x = ½·c·Δt·κ. ū is the leapfrog's mid-step approach speed, so the dashpot is centred
    /// in time; it tends to eq (3) as Δt → 0, is zero on a contact at rest, and an
    /// isolated pair is stable for ω·Δt < 2 whatever ζ.
    #[default]
    Implicit,
}

/// An error in a world's parameters or bodies.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum WorldError {
    /// A parameter is out of its physical range.
    #[error("parameter `{name}` = {value} is invalid: {why}")]
    Param {
        /// Parameter name.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What is required.
        why: &'static str,
    },
    /// A saved state does not fit this build.
    #[error("invalid saved state: {0}")]
    State(String),
    /// A block could not be made.
    #[error("block: {0}")]
    Shape(#[from] ShapeError),
    /// A fixed time step above the stable limit.
    #[error(
        "time step {dt:.4e} s is above the stable limit {limit:.4e} s of this scene \
         (the stiffest joint and contact, see docs/model.md \"Time step\"); use at most \
         {limit:.4e} s or leave the time step to be derived"
    )]
    Unstable {
        /// The requested time step (s).
        dt: f64,
        /// The stable limit (s).
        limit: f64,
    },
    /// The state turned non-finite.
    #[error(
        "the run turned non-finite at step {step} (t = {time:.6} s): body {body} has a \
         non-finite {what}; no results were written"
    )]
    NonFinite {
        /// The step that produced the non-finite value.
        step: u64,
        /// Simulated time at the end of that step (s).
        time: f64,
        /// The first body found with a non-finite value.
        body: usize,
        /// Which value: velocity, angular velocity, position or orientation.
        what: &'static str,
    },
}

impl WorldParams {
    /// Checks every parameter; the message names the first offending one.
    pub fn validate(&self) -> Result<(), WorldError> {
        let pos = |name, value: f64| {
            if value > 0.0 && value.is_finite() {
                Ok(())
            } else {
                Err(WorldError::Param {
                    name,
                    value,
                    why: "must be positive and finite",
                })
            }
        };
        let nonneg = |name, value: f64| {
            if value >= 0.0 && value.is_finite() {
                Ok(())
            } else {
                Err(WorldError::Param {
                    name,
                    value,
                    why: "must be non-negative and finite",
                })
            }
        };
        nonneg("gravity", self.gravity)?;
        pos("ice_density", self.ice_density)?;
        let c = &self.contact;
        pos("contact.normal_stiffness", c.normal_stiffness)?;
        nonneg("contact.damping_fraction", c.damping_fraction)?;
        pos("contact.tangential_fraction", c.tangential_fraction)?;
        pos("contact.reference_thickness", c.thickness())?;
        nonneg("contact.mu", c.mu)?;
        nonneg("contact.mu_water", c.mu_water)?;
        if let Some(w) = &self.water {
            pos("water.density", w.density)?;
            nonneg("water.drag_coefficient", w.drag_coefficient)?;
            nonneg("water.linear_drag", w.linear_drag)?;
            if !w.level.is_finite() {
                return Err(WorldError::Param {
                    name: "water.level",
                    value: w.level,
                    why: "must be finite",
                });
            }
        }
        pos("time_step_safety", self.time_step_safety)?;
        if self.time_step_safety > 1.0 {
            return Err(WorldError::Param {
                name: "time_step_safety",
                value: self.time_step_safety,
                why: "must lie in (0, 1]: the stable time step is a limit",
            });
        }
        pos("crack_speed", self.crack_speed)?;
        nonneg("global_damping", self.global_damping)?;
        if let Some(dt) = self.time_step {
            pos("time_step", dt)?;
        }
        Ok(())
    }
}

/// A set of blocks in a vertical plane with water, stepping in time.
#[derive(Clone, Debug)]
pub struct World {
    /// Body state arrays.
    pub bodies: Bodies,
    params: WorldParams,
    k_nv: f64,
    contacts: ContactSet,
    joints: JointSet,
    /// Boundary conditions of the ridging experiment.
    pub boundary: Boundary,
    loads: Vec<(BodyId, V2)>,
    broad: SweepAndPrune,
    water: WaterForces,
    acc: Accumulators,
    blocks_broken: u64,
    handovers: Handovers,
    dt: f64,
    time: f64,
    steps: u64,
    /// Set when a step produced a non-finite state; the world then no longer steps.
    fault: Option<WorldError>,
    /// While set, adding bodies and joints leaves Δt alone; [`World::finish_time_step`]
    /// derives it once when the world is complete.
    defer_time_step: bool,
    // Scratch, reused every step.
    vel_old: Vec<V2>,
    omega_old: Vec<f64>,
    vbar: Vec<V2>,
    wbar: Vec<f64>,
}

impl World {
    /// An empty world.
    pub fn new(params: WorldParams) -> Result<World, WorldError> {
        params.validate()?;
        let k_nv = params.contact.viscous_coefficient(params.ice_density);
        Ok(World {
            bodies: Bodies::default(),
            params,
            k_nv,
            contacts: ContactSet::default(),
            joints: JointSet::default(),
            boundary: Boundary::default(),
            loads: Vec::new(),
            broad: SweepAndPrune::default(),
            water: WaterForces::default(),
            acc: Accumulators::default(),
            blocks_broken: 0,
            handovers: Handovers::default(),
            dt: 0.0,
            time: 0.0,
            steps: 0,
            fault: None,
            defer_time_step: false,
            vel_old: Vec::new(),
            omega_old: Vec::new(),
            vbar: Vec::new(),
            wbar: Vec::new(),
        })
    }

    /// Adds an ice block of the given shape with its centroid at `pos` (m), orientation
    /// `theta` (rad), at rest (or moving as `drive` prescribes). The time step is
    /// re-derived.
    pub fn add_block(&mut self, shape: Shape, pos: V2, theta: f64, drive: Drive) -> BodyId {
        let id = self
            .bodies
            .push(shape, self.params.ice_density, pos, theta, drive);
        if self.steps == 0 && !self.defer_time_step {
            self.refresh_time_step();
        }
        self.acc.kinetic_start += self.body_kinetic_energy(id as usize);
        id
    }

    /// Adds a rectangular block `b` (with its bevels) whose rectangle is centred at `centre`
    /// (m), rotated by `theta` (rad). Returns its index.
    pub fn add_rect(
        &mut self,
        b: Block,
        centre: V2,
        theta: f64,
        drive: Drive,
        role: Role,
    ) -> Result<BodyId, WorldError> {
        let shape = b.shape()?;
        let (s, c) = theta.sin_cos();
        let pos = centre - b.rect_centre().rotate(c, s);
        let id = self
            .bodies
            .push(shape, self.params.ice_density, pos, theta, drive);
        self.bodies.role[id as usize] = role;
        self.bodies.block[id as usize] = Some(b);
        self.acc.kinetic_start += self.body_kinetic_energy(id as usize);
        if self.steps == 0 && !self.defer_time_step {
            self.refresh_time_step();
        }
        Ok(id)
    }

    /// Joins the right face of rectangular block `a` to the left face of rectangular block
    /// `b` (eq 1), with a skeletal layer of `skeletal` (m) at the bottom.
    pub fn join(
        &mut self,
        a: BodyId,
        b: BodyId,
        skeletal: f64,
        mat: JointMaterial,
    ) -> Result<usize, WorldError> {
        let (ba, bb) = match (self.bodies.block[a as usize], self.bodies.block[b as usize]) {
            (Some(x), Some(y)) => (x, y),
            _ => {
                return Err(WorldError::State(format!(
                    "bodies {a} and {b} must both be rectangular blocks to be joined"
                )));
            }
        };
        let pa = ba.rect_centre() + V2::new(0.5 * ba.width, 0.0);
        let pb = bb.rect_centre() + V2::new(-0.5 * bb.width, 0.0);
        let h = ba.thickness.min(bb.thickness);
        let gauge = 0.5 * (ba.width + bb.width);
        let k = self
            .joints
            .push(Joint::new(a, b, pa, pb, h, skeletal, gauge, mat));
        // The time step is derived while the world is built and then kept for the run
        // (blocks the sheet grows later are alike and need no new bound).
        if self.steps == 0 && !self.defer_time_step {
            self.refresh_time_step();
        }
        Ok(k)
    }

    /// The joints.
    pub fn joints(&self) -> &[Joint] {
        self.joints.joints()
    }

    /// How far the leading edge of the intact lead sheet lies past the floe's nose (m):
    /// the right end of the tip block's bounding box minus the left end of the floe's;
    /// negative while the sheet is short of the floe. `None` without a sheet or a floe. A
    /// sheet that breaks against the floe keeps this near zero; a sheet that rafts over (or
    /// under) the floe drives it up by the length it overrides.
    pub fn sheet_overrun(&self) -> Option<f64> {
        let tip = *self.boundary.sheet.as_ref()?.blocks.last()?;
        let nose = self
            .boundary
            .floe
            .as_ref()?
            .blocks
            .iter()
            .map(|&(id, _)| self.bodies.aabb[id as usize].min.x)
            .reduce(f64::min)?;
        Some(self.bodies.aabb[tip as usize].max.x - nose)
    }

    /// Number of joints severed so far.
    pub fn blocks_broken(&self) -> u64 {
        self.blocks_broken
    }

    /// Contacts born overlapping so far (from a severed joint, or a sheet block grown
    /// through rubble), and the largest such overlap (m²): see [`crate::dem::contact`].
    pub fn handovers(&self) -> Handovers {
        self.handovers
    }

    /// Applies a constant external force `f` (N/m) at the centroid of body `id` from now
    /// on (replacing any earlier load on it); its work is counted in `work`.
    pub fn set_load(&mut self, id: BodyId, f: V2) {
        self.loads.retain(|&(i, _)| i != id);
        if f != V2::default() {
            self.loads.push((id, f));
        }
    }

    fn body_kinetic_energy(&self, i: usize) -> f64 {
        let b = &self.bodies;
        0.5 * b.mass[i] * b.vel[i].dot(b.vel[i]) + 0.5 * b.inertia[i] * b.omega[i] * b.omega[i]
    }

    /// Sets the velocity (m/s) and angular velocity (rad/s) of body `id` as an initial
    /// condition: the ledger's starting kinetic energy is adjusted, so the change is not
    /// counted as work. Call it before stepping.
    pub fn set_velocity(&mut self, id: BodyId, vel: V2, omega: f64) {
        let i = id as usize;
        let before = self.body_kinetic_energy(i);
        self.bodies.vel[i] = vel;
        self.bodies.omega[i] = omega;
        self.acc.kinetic_start += self.body_kinetic_energy(i) - before;
    }

    /// The parameters.
    pub fn params(&self) -> &WorldParams {
        &self.params
    }
    /// The time step Δt (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }
    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        self.time
    }
    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }
    /// Active contacts of the last step.
    pub fn contacts(&self) -> &[Contact] {
        self.contacts.contacts()
    }
    /// The ledger's running integrals.
    pub fn accumulators(&self) -> &Accumulators {
        &self.acc
    }

    /// Re-derives the time step from the bodies and joints present (unless fixed):
    /// `time_step_safety` × [`World::stable_time_step`].
    pub fn refresh_time_step(&mut self) {
        self.dt = match self.params.time_step {
            Some(dt) => dt,
            None => self.params.time_step_safety * self.stable_time_step(),
        };
    }

    /// Stops [`World::add_block`], [`World::add_rect`] and [`World::join`] re-deriving the
    /// time step (each derivation solves one eigenproblem per joint) until
    /// [`World::finish_time_step`].
    pub(crate) fn defer_time_step(&mut self) {
        self.defer_time_step = true;
    }

    /// Ends [`World::defer_time_step`]: derives the time step once from the bodies and
    /// joints present, as [`World::refresh_time_step`], and checks it against the stable
    /// limit, as [`World::check_time_step`].
    pub(crate) fn finish_time_step(&mut self) -> Result<(), WorldError> {
        self.defer_time_step = false;
        let limit = self.stable_time_step();
        self.dt = match self.params.time_step {
            Some(dt) => dt,
            None => self.params.time_step_safety * limit,
        };
        if self.dt > limit {
            return Err(WorldError::Unstable { dt: self.dt, limit });
        }
        Ok(())
    }

    /// Checks a fixed time step against the stable limit of the bodies and joints present;
    /// the error gives the limit.
    pub fn check_time_step(&self) -> Result<(), WorldError> {
        let limit = self.stable_time_step();
        if self.dt > limit {
            return Err(WorldError::Unstable { dt: self.dt, limit });
        }
        Ok(())
    }

    /// The stable time step of the leapfrog scheme (s) for the bodies and joints present:
    /// the smaller of a contact limit and a joint limit (docs/model.md, "Time step").
    ///
    /// Contacts. A contact along a chord of length L has normal stiffness k_ne·L (N/m²)
    /// and a dashpot k_nv·L. For bodies a and b, with inverse effective masses
    /// κᵢ = (1 + rᵢ²mᵢ/Iᵢ)/mᵢ at a point a distance rᵢ from the centroid and
    /// L ≤ min(dₐ, d_b) (d a body's diameter), ω² ≤ 2·k_ne·max(d·κ) and the damping ratio
    /// ζ ≤ ½·k_nv·sqrt(2·max(d·κ)/k_ne). With the explicit dashpot the step is stable for
    /// Δt < (2/ω)·(sqrt(1 + ζ²) − ζ); with the implicit one ([`Dashpot::Implicit`]) for
    /// Δt < √2/ω whatever ζ.
    ///
    /// Joints. Each joint's mass-scaled stiffness and damping have largest eigenvalues λ
    /// (1/s²) and μ (1/s) ([`Joint::modal_bounds`]); ω² of the joined blocks is at most the
    /// largest sum of λ over one body's joints plus one contact's ω_c² (a jointed block may
    /// be in contact too), the damping rate d likewise, and the step is stable for
    /// Δt < 2/(sqrt(ω² + d²/4) + d/2).
    ///
    /// Infinite for a world without free bodies (nothing can go unstable).
    pub fn stable_time_step(&self) -> f64 {
        let b = &self.bodies;
        let inv = |i: usize| {
            if b.drive[i].is_kinematic() {
                0.0
            } else {
                let s = &b.shape[i];
                (1.0 + s.radius().powi(2) * b.mass[i] / b.inertia[i]) / b.mass[i]
            }
        };
        // The explicit step of a mode of frequency ω and damping rate d (1/s) is stable for
        // Δt < 2/(sqrt(ω² + d²/4) + d/2), which falls as ω or d grows: upper bounds on both
        // give a safe limit.
        let limit = |w2: f64, d: f64| 2.0 / ((w2 + 0.25 * d * d).sqrt() + 0.5 * d);
        let mut dt = f64::INFINITY;
        let mut dc: f64 = 0.0;
        for i in 0..b.len() {
            dc = dc.max(b.shape[i].diameter() * inv(i));
        }
        // One contact: ω_c² and its damping rate in the explicit form (the implicit form is
        // stable at any damping).
        let k_ne = self.params.contact.normal_stiffness;
        let contact_w2 = 2.0 * k_ne * dc;
        let contact_d = match self.params.contact_dashpot {
            Dashpot::Implicit => 0.0,
            Dashpot::Explicit => 2.0 * self.k_nv * dc,
        };
        if dc > 0.0 {
            dt = dt.min(match self.params.contact_dashpot {
                Dashpot::Implicit => std::f64::consts::SQRT_2 / contact_w2.sqrt(),
                Dashpot::Explicit => limit(contact_w2, contact_d),
            });
        }
        // Joints: each joint's mass-scaled stiffness K̃ⱼ and damping C̃ⱼ are positive
        // semi-definite and act on two bodies, so xᵀK̃x = Σⱼ xᵀK̃ⱼx ≤ Σᵢ |xᵢ|²·Σ_{j∋i} λⱼ:
        // ω² ≤ max over bodies of the sum of λⱼ over the body's joints (2λ inside a sheet,
        // exact for its alternating mode), and likewise the damping rate d ≤ Σμⱼ. A jointed
        // block may also be in contact: one contact's ω_c² and rate are added to its row.
        let scale = |i: usize| {
            if b.drive[i].is_kinematic() {
                [0.0; 3]
            } else {
                let m = 1.0 / b.mass[i].sqrt();
                [m, m, 1.0 / b.inertia[i].sqrt()]
            }
        };
        let mut rate = vec![(0.0f64, 0.0f64); b.len()];
        for j in self.joints.joints() {
            let (l, m) = j.modal_bounds(
                b,
                self.params.ice_density,
                scale(j.a as usize),
                scale(j.b as usize),
            );
            for i in [j.a as usize, j.b as usize] {
                rate[i].0 += l;
                rate[i].1 += m;
            }
        }
        for &(w2, d) in &rate {
            if w2 > 0.0 {
                dt = dt.min(limit(w2 + contact_w2, d + contact_d));
            }
        }
        dt
    }

    /// Sets the time step (s) explicitly, e.g. for convergence studies. It must not exceed
    /// [`World::stable_time_step`].
    pub fn set_time_step(&mut self, dt: f64) -> Result<(), WorldError> {
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(WorldError::Param {
                name: "time_step",
                value: dt,
                why: "must be positive and finite",
            });
        }
        let limit = self.stable_time_step();
        if dt > limit {
            return Err(WorldError::Unstable { dt, limit });
        }
        self.params.time_step = Some(dt);
        self.dt = dt;
        Ok(())
    }

    /// Why the world stopped stepping, if it did: a step that produced a non-finite
    /// velocity ([`WorldError::NonFinite`], naming the step, the time and the first body).
    pub fn fault(&self) -> Option<&WorldError> {
        self.fault.as_ref()
    }

    /// Advances the world by one time step. A world without free bodies has no stability
    /// bound and does not move: set a time step with [`World::set_time_step`] to step it.
    /// A step that produces a non-finite velocity records a [`World::fault`] and leaves
    /// the positions; later calls do nothing.
    pub fn step(&mut self) {
        let dt = self.dt;
        if dt.is_nan() || dt <= 0.0 || dt.is_infinite() || self.fault.is_some() {
            return;
        }
        let n = self.bodies.len();
        let g = self.params.gravity;
        let b = &mut self.bodies;
        for i in 0..n {
            b.update_world(i);
            b.force[i] = V2::default();
            b.torque[i] = 0.0;
        }
        // Body forces: gravity at the centroid, then buoyancy and drag.
        for i in 0..n {
            if !b.drive[i].is_kinematic() {
                b.force[i].y -= b.mass[i] * g;
            }
        }
        if let Some(w) = &self.params.water {
            self.water.apply(b, w, g);
        }
        // Joints (eq 1) and boundary conditions (eqs 7–8, floe supports).
        self.joints.apply(b, self.params.ice_density);
        self.boundary.apply(b);
        for &(id, f) in &self.loads {
            b.force[id as usize] = b.force[id as usize] + f;
        }
        let gamma = self.params.global_damping;
        if gamma > 0.0 {
            for i in 0..n {
                b.force[i] = b.force[i] - b.vel[i] * (gamma * b.mass[i]);
                b.torque[i] -= gamma * b.inertia[i] * b.omega[i];
            }
        }
        // Contacts, except between blocks still joined.
        let drive = &b.drive;
        let joints = &self.joints;
        let pairs = self.broad.pairs(&b.aabb, |i, j| {
            (drive[i as usize].is_kinematic() && drive[j as usize].is_kinematic())
                || joints.joined(i, j)
        });
        let level = self.params.water.as_ref().map(|w| w.level);
        self.contacts.update(
            b,
            pairs,
            &self.params.contact,
            self.k_nv,
            dt,
            level,
            self.params.contact_dashpot,
            &mut self.acc.contact,
        );
        // Leapfrog velocities, eq (5); prescribed degrees of freedom take their value and
        // the driver supplies whatever force that takes.
        self.vel_old.clear();
        self.vel_old.extend_from_slice(&b.vel);
        self.omega_old.clear();
        self.omega_old.extend_from_slice(&b.omega);
        self.vbar.resize(n, V2::default());
        self.wbar.resize(n, 0.0);
        let mut driver = 0.0;
        for i in 0..n {
            let d = b.drive[i];
            let (m, inertia) = (b.mass[i], b.inertia[i]);
            let f = b.force[i];
            let v0 = b.vel[i];
            let w0 = b.omega[i];
            let u1 = d.u.unwrap_or(v0.x + dt * f.x / m);
            let v1 = d.v.unwrap_or(v0.y + dt * f.y / m);
            let w1 = d.omega.unwrap_or(w0 + dt * b.torque[i] / inertia);
            let vbar = V2::new(0.5 * (v0.x + u1), 0.5 * (v0.y + v1));
            let wbar = 0.5 * (w0 + w1);
            if d.u.is_some() {
                driver += (m * (u1 - v0.x) - dt * f.x) * vbar.x;
            }
            if d.v.is_some() {
                driver += (m * (v1 - v0.y) - dt * f.y) * vbar.y;
            }
            if d.omega.is_some() {
                driver += (inertia * (w1 - w0) - dt * b.torque[i]) * wbar;
            }
            b.vel[i] = V2::new(u1, v1);
            b.omega[i] = w1;
            self.vbar[i] = vbar;
            self.wbar[i] = wbar;
            if !(u1.is_finite() && v1.is_finite() && w1.is_finite()) && self.fault.is_none() {
                self.fault = Some(WorldError::NonFinite {
                    step: self.steps + 1,
                    time: self.time + dt,
                    body: i,
                    what: if w1.is_finite() {
                        "velocity"
                    } else {
                        "angular velocity"
                    },
                });
            }
        }
        if self.fault.is_some() {
            return;
        }
        // Ledger, eqs (9)–(12), with the mid-step velocities.
        self.acc.work += driver;
        let mut grav = 0.0;
        for i in 0..n {
            if !b.drive[i].is_kinematic() {
                grav += b.mass[i] * g * self.vbar[i].y;
            }
        }
        self.acc.gravity += grav * dt;
        if self.params.water.is_some() {
            self.water
                .book_work(b, &self.vbar, &self.wbar, dt, &mut self.acc.water);
        }
        self.contacts
            .book_work(b, &self.vbar, &self.wbar, dt, &mut self.acc.contact);
        self.joints
            .book_work(&self.vbar, &self.wbar, dt, &mut self.acc.joints);
        self.boundary
            .book_work(&self.vbar, dt, &mut self.acc.boundary);
        for &(id, f) in &self.loads {
            self.acc.loads += f.dot(self.vbar[id as usize]) * dt;
        }
        if gamma > 0.0 {
            for i in 0..n {
                // The damping force used the velocity before the step.
                let f = self.vel_old[i] * (gamma * b.mass[i]);
                let m = gamma * b.inertia[i] * self.omega_old[i];
                self.acc.global_damping += (f.dot(self.vbar[i]) + m * self.wbar[i]) * dt;
            }
        }
        // Positions, eq (6).
        for i in 0..n {
            b.pos[i] = b.pos[i] + b.vel[i] * dt;
            b.theta[i] += b.omega[i] * dt;
        }
        self.time += dt;
        self.steps += 1;
        // Fracture: new cracks at the new poses, running cracks advance.
        if !self.joints.is_empty() {
            self.joints
                .advance(self.params.crack_speed, self.time, dt, &mut self.acc.joints);
            if !self.joints.severed().is_empty() {
                self.after_fracture();
            }
        }
    }

    /// Handles joints severed in the last step: bevels the corners of the broken faces,
    /// turns what broke off the sheet into rubble, and grows the sheet at its left end.
    fn after_fracture(&mut self) {
        // Outlines at the new positions, once: the hand-overs below test overlaps, and
        // reshaping or adding a body keeps its own outline current.
        for i in 0..self.bodies.len() {
            self.bodies.update_world(i);
        }
        let severed: Vec<usize> = self.joints.severed().to_vec();
        for k in severed {
            self.blocks_broken += 1;
            let j = self.joints.joints()[k];
            let (a, b) = (j.a as usize, j.b as usize);
            let mut on_sheet = None;
            if let Some(sh) = &self.boundary.sheet
                && self.bodies.role[a] == Role::Sheet
                && self.bodies.role[b] == Role::Sheet
            {
                on_sheet = sh.blocks.iter().position(|&x| x == j.a);
            }
            let (corner, tip) = if let Some(sh) = &self.boundary.sheet {
                (sh.corner_bevel, sh.tip_bevel)
            } else if let Some(fl) = &self.boundary.floe {
                (fl.corner_bevel, 0.0)
            } else {
                (0.0, 0.0)
            };
            match on_sheet {
                Some(pos) => {
                    // The new sheet tip gets the tip bevel underneath (point B); the piece
                    // that broke off becomes rubble with bevelled corners.
                    self.bevel(a, [0.0, tip.max(corner), corner, 0.0]);
                    self.bevel(b, [corner, 0.0, 0.0, corner]);
                    let sh = self.boundary.sheet.as_mut().expect("sheet present");
                    let lost: Vec<BodyId> = sh.blocks.drain(pos + 1..).collect();
                    for &id in &lost {
                        self.bodies.role[id as usize] = Role::Rubble;
                    }
                    for _ in 0..lost.len() {
                        self.grow_sheet();
                    }
                }
                None => {
                    self.bevel(a, [0.0, corner, corner, 0.0]);
                    self.bevel(b, [corner, 0.0, 0.0, corner]);
                }
            }
            // Blocks that were joined may overlap (joined blocks are exempt from contact):
            // their contact is born with that overlap forgiven, see `contact`.
            self.hand_over(a, b);
        }
    }

    /// Hands the overlap of bodies `a` and `b` (outlines current), if any, to a contact
    /// born with that overlap forgiven (see [`crate::dem::contact`]), and counts it.
    fn hand_over(&mut self, a: usize, b: usize) {
        let (lo, hi) = (a.min(b), a.max(b));
        let bd = &self.bodies;
        if let Some(ov) = overlap(&bd.world[lo], &bd.world[hi], bd.pos[lo], bd.pos[hi]) {
            self.contacts.hand_over(
                pair_key(lo as u32, hi as u32),
                ov.area,
                ov.centroid,
                ov.normal,
            );
            self.handovers.count += 1;
            self.handovers.max_area = self.handovers.max_area.max(ov.area);
        }
    }

    /// Raises the bevel legs of block `i` to at least `legs` (m), re-cutting its shape.
    fn bevel(&mut self, i: usize, legs: [f64; 4]) {
        let Some(old) = self.bodies.block[i] else {
            return;
        };
        let mut new = old;
        for (b, l) in new.bevel.iter_mut().zip(legs) {
            *b = b.max(l);
        }
        if new == old {
            return;
        }
        let Ok(shape) = new.shape() else {
            // A block too small for the bevel keeps its corners.
            return;
        };
        let shift = old.rect_centre() - new.rect_centre();
        let dke = self
            .bodies
            .reshape(i, shape, shift, self.params.ice_density);
        self.acc.cut_away -= dke;
        self.bodies.block[i] = Some(new);
        for j in self.joints.joints_mut() {
            if j.a as usize == i {
                j.pa = j.pa - shift;
            }
            if j.b as usize == i {
                j.pb = j.pb - shift;
            }
        }
    }

    /// Adds a block at the left end of the sheet, joined to the current leftmost block, and
    /// hands it the drive. Its kinetic energy enters the ledger as inflow, not work.
    fn grow_sheet(&mut self) {
        let Some(sh) = self.boundary.sheet.as_ref() else {
            return;
        };
        let first = sh.blocks[0] as usize;
        let (w, h, u, clamp) = (sh.width, sh.thickness, sh.speed, sh.clamp);
        let k = sh.joints_made;
        let mut mat = sh.material;
        let f = sh.modulus_factor(k);
        mat.e_top *= f;
        mat.e_bottom *= f;
        let skeletal = sh.skeletal;
        let b = &self.bodies;
        let th = b.theta[first];
        let (s, c) = th.sin_cos();
        let rect_first = b.pos[first]
            + b.block[first]
                .map_or(V2::default(), |x| x.rect_centre())
                .rotate(c, s);
        let centre = rect_first - V2::new(w, 0.0).rotate(c, s);
        let v = b.vel[first] + (centre - b.pos[first]).perp() * b.omega[first];
        let omega = b.omega[first];
        let block = Block {
            width: w,
            thickness: h,
            bevel: [0.0; 4],
        };
        let drive = Drive {
            u: Some(u),
            v: clamp.then_some(0.0),
            omega: clamp.then_some(0.0),
        };
        let Ok(id) = self.add_rect(block, centre, th, drive, Role::Sheet) else {
            return;
        };
        // The new block's kinetic energy is inflow, not work.
        let ke0 = self.body_kinetic_energy(id as usize);
        let (vy, om) = if clamp { (0.0, 0.0) } else { (v.y, omega) };
        self.bodies.vel[id as usize] = V2::new(u, vy);
        self.bodies.omega[id as usize] = om;
        self.acc.kinetic_start += self.body_kinetic_energy(id as usize) - ke0;
        self.bodies.drive[first] = Drive::FREE;
        let _ = self.join(id, first as BodyId, skeletal, mat);
        let sh = self.boundary.sheet.as_mut().expect("sheet present");
        sh.joints_made += 1;
        sh.blocks.insert(0, id);
        // A block grown where rubble already lies (a sheet that rafted far enough for its
        // driven end to reach the ridge) starts with its overlaps forgiven, see `contact`.
        // Outlines are current here (see `after_fracture`).
        let id = id as usize;
        for i in 0..self.bodies.len() {
            if i == id || i == first {
                continue;
            }
            if self.bodies.aabb[i].overlaps(&self.bodies.aabb[id]) {
                self.hand_over(i, id);
            }
        }
    }

    /// The energy budget now (J/m).
    pub fn energy(&self) -> EnergyBudget {
        let (sn, st) = self.contacts.stored_energy();
        let stored = Stored {
            contact_normal: sn,
            contact_tangential: st,
        };
        EnergyBudget::from_parts(self.time, &self.acc, self.bodies.kinetic_energy(), &stored)
    }

    /// The ridging force of eq (9) (N/m): minus the x component of the contact forces
    /// that bodies of other roles exert on the sheet, i.e. the resistance the sheet pushes
    /// against (positive when the ridge resists the push).
    pub fn ridging_force(&self) -> f64 {
        let r = &self.bodies.role;
        let mut fx = 0.0;
        for c in self.contacts.contacts() {
            let (a, b) = ((c.key >> 32) as usize, (c.key & 0xffff_ffff) as usize);
            let (sa, sb) = (r[a] == Role::Sheet, r[b] == Role::Sheet);
            if sa == sb {
                continue;
            }
            let f = c.normal * (c.fn_elastic + c.fn_viscous) + c.normal.perp() * c.ft;
            fx += if sb { f.x } else { -f.x };
        }
        -fx
    }

    /// Potential energy of the current state (J/m): Σ ρ_i·g·A·y_c − ρ_w·g·A_s·y_s over the
    /// bodies that are not held, with y_s the depth of the submerged centroid (the work to
    /// lift each block and to displace its water). Its change between two instants equals
    /// the ΔPE booked by eq (10) up to the discretisation error of the step.
    pub fn potential_energy(&self) -> f64 {
        let b = &self.bodies;
        let g = self.params.gravity;
        let mut pe = 0.0;
        for i in 0..b.len() {
            if b.drive[i].is_kinematic() {
                continue;
            }
            pe += b.mass[i] * g * b.pos[i].y;
            if let Some(w) = &self.params.water {
                let (s, c) = b.theta[i].sin_cos();
                let mut o = super::geometry::Outline::default();
                o.set_transformed(b.shape[i].outline(), c, s, b.pos[i]);
                let (a, cen) = below_line(&o, w.level);
                pe -= w.density * g * a * (cen.y - w.level);
            }
        }
        pe
    }

    /// A complete, serialisable copy of the state: restoring it and stepping gives the
    /// same results bit for bit as stepping this world.
    pub fn snapshot(&self) -> Snapshot {
        let b = &self.bodies;
        Snapshot {
            format: SNAPSHOT_FORMAT,
            time: self.time,
            steps: self.steps,
            dt: self.dt,
            params: self.params.clone(),
            bodies: (0..b.len())
                .map(|i| BodyState {
                    shape: b.shape[i],
                    pos: b.pos[i],
                    theta: b.theta[i],
                    vel: b.vel[i],
                    omega: b.omega[i],
                    drive: b.drive[i],
                    role: b.role[i],
                    block: b.block[i],
                })
                .collect(),
            contacts: self.contacts.contacts().to_vec(),
            joints: self.joints.joints().to_vec(),
            boundary: self.boundary.clone(),
            loads: self.loads.clone(),
            blocks_broken: self.blocks_broken,
            handovers: self.handovers,
            ledger: self.acc,
        }
    }

    /// Rebuilds a world from a [`Snapshot`].
    pub fn from_snapshot(s: &Snapshot) -> Result<World, WorldError> {
        if s.format != SNAPSHOT_FORMAT {
            return Err(WorldError::State(format!(
                "format {} is not the supported {SNAPSHOT_FORMAT}",
                s.format
            )));
        }
        let mut w = World::new(s.params.clone())?;
        for bs in &s.bodies {
            let i = w
                .bodies
                .push(bs.shape, w.params.ice_density, bs.pos, bs.theta, bs.drive);
            w.bodies.vel[i as usize] = bs.vel;
            w.bodies.omega[i as usize] = bs.omega;
            w.bodies.role[i as usize] = bs.role;
            w.bodies.block[i as usize] = bs.block;
        }
        if s.joints
            .iter()
            .any(|j| j.a as u64 >= nb_of(s) || j.b as u64 >= nb_of(s))
        {
            return Err(WorldError::State("a joint names a missing body".into()));
        }
        w.joints.restore(s.joints.clone());
        w.boundary = s.boundary.clone();
        w.loads = s.loads.clone();
        w.blocks_broken = s.blocks_broken;
        w.handovers = s.handovers;
        let nb = w.bodies.len() as u64;
        if s.contacts
            .iter()
            .any(|c| (c.key >> 32) >= nb || (c.key & 0xffff_ffff) >= nb)
        {
            return Err(WorldError::State("a contact names a missing body".into()));
        }
        w.contacts.restore(s.contacts.clone());
        w.acc = s.ledger;
        w.time = s.time;
        w.steps = s.steps;
        w.dt = s.dt;
        Ok(w)
    }
}

/// Contacts born overlapping, their overlap forgiven (see [`crate::dem::contact`]): from a
/// joint that severed while its blocks overlapped, or a sheet block grown through rubble.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Handovers {
    /// How many contacts were born overlapping.
    pub count: u64,
    /// The largest such overlap (m² per metre of depth, i.e. the overlap area).
    pub max_area: f64,
}

/// Version of the [`Snapshot`] layout.
pub const SNAPSHOT_FORMAT: u32 = 2;

fn nb_of(s: &Snapshot) -> u64 {
    s.bodies.len() as u64
}

/// One body in a [`Snapshot`].
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyState {
    /// Outline relative to the centroid.
    pub shape: Shape,
    /// Centroid (m).
    pub pos: V2,
    /// Orientation (rad).
    pub theta: f64,
    /// Velocity at the last half step (m/s).
    pub vel: V2,
    /// Angular velocity at the last half step (rad/s).
    pub omega: f64,
    /// Prescribed degrees of freedom.
    pub drive: Drive,
    /// Role in the scene.
    #[serde(default)]
    pub role: Role,
    /// Nominal rectangle and bevels, for rectangular blocks.
    #[serde(default)]
    pub block: Option<Block>,
}

impl BodyState {
    /// The body's outline in world coordinates (m).
    pub fn world_outline(&self) -> super::geometry::Outline {
        let (s, c) = self.theta.sin_cos();
        let mut o = super::geometry::Outline::default();
        o.set_transformed(self.shape.outline(), c, s, self.pos);
        o
    }
}

/// The complete state of a [`World`], serialisable (JSON via [`crate::io`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Snapshot {
    /// Layout version, [`SNAPSHOT_FORMAT`].
    pub format: u32,
    /// Simulated time (s).
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// Time step (s).
    pub dt: f64,
    /// Parameters.
    pub params: WorldParams,
    /// Bodies.
    pub bodies: Vec<BodyState>,
    /// Active contacts with their history.
    pub contacts: Vec<Contact>,
    /// Joints with their cracks.
    pub joints: Vec<Joint>,
    /// Boundary conditions.
    pub boundary: Boundary,
    /// External loads.
    pub loads: Vec<(BodyId, V2)>,
    /// Joints severed so far.
    pub blocks_broken: u64,
    /// Contacts born overlapping so far (absent in older snapshots, which predate the
    /// hand-over).
    #[serde(default)]
    pub handovers: Handovers,
    /// Ledger integrals.
    pub ledger: Accumulators,
}
