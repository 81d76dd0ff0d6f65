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

use super::body::{Block, Bodies, BodyId, Drive, Role, Shape};
use super::boundary::Boundary;
use super::broadphase::{SweepAndPrune, pair_key};
use super::contact::{Contact, ContactLaw, ContactSet, ContactTally};
use super::fracture::JointSet;
use super::geometry::{V2, below_line, overlap};
use super::joint::{Joint, JointGeometry, JointMaterial};
use super::ledger::{Accumulators, Stored, budget};
use super::numerics::{Dashpot, StepNumerics};
use super::water::{WaterForces, shielded_bodies};
use crate::energy::EnergyBudget;
use serde::{Deserialize, Serialize};

mod energy;
mod fracture;
mod params;
mod snapshot;
mod timestep;

pub(crate) use params::is_zero;
pub use params::{
    DEFAULT_REFINE_FRACTION, DEFAULT_REFINE_IMPACT, DEFAULT_REFINE_LOAD, DEFAULT_REFINE_WINDOW,
    DEFAULT_TIME_STEP_SAFETY, MAX_CONTACT_DASHPOT_SWEEPS, WorldError, WorldParams,
};
pub use snapshot::{BodyState, Snapshot};

/// A set of blocks in a vertical plane with water, stepping in time.
///
/// Scenes build worlds ([`crate::scene::Scene::build`]); verification scenes build them by
/// hand. Its state is read through `&` accessors ([`World::bodies`], [`World::joints`],
/// [`World::contacts`], [`World::energy`], [`World::snapshot`]) and changed only through its
/// methods, so that the energy ledger stays closed. Positions are in m, velocities in m/s,
/// forces in N/m and energies in J/m (per metre of depth).
///
/// ```
/// use pressridge_sim::dem::{Block, Drive, JointMaterial, Role, V2, World, WorldParams};
///
/// // Two 0.25 m × 0.30 m blocks centred on the water line (y = 0 m), joined face to face:
/// // the left one held, the right one free to sag under gravity and buoyancy.
/// let mut w = World::new(WorldParams::default())?;
/// let block = Block::new(0.25, 0.30, [0.0; 4]); // m: width, thickness, bevel legs
/// let a = w.add_rect(block, V2::new(0.125, 0.0), 0.0, Drive::FIXED, Role::Sheet)?;
/// let b = w.add_rect(block, V2::new(0.375, 0.0), 0.0, Drive::FREE, Role::Sheet)?;
/// let mat = JointMaterial {
///     e_top: 1.0e8,            // Pa
///     e_bottom: 6.7e7,         // Pa
///     poisson: 0.3,
///     damping_fraction: 0.1,
///     strength_top: 7.5e5,     // Pa
///     strength_bottom: 3.5e5,  // Pa
/// };
/// w.join(a, b, 0.06, mat)?; // 0.06 m skeletal layer
/// while w.time() < 0.05 {
///     w.step(); // by w.dt() s, derived from the stiffest joint and contact
/// }
/// let e = w.energy(); // J/m
/// assert!(e.residual.abs() <= 1e-9 * e.largest_term()); // the ledger closes
/// assert!(w.joints()[0].is_intact() && w.blocks_broken() == 0);
/// # Ok::<(), pressridge_sim::dem::WorldError>(())
/// ```
#[derive(Clone, Debug)]
pub struct World {
    /// Body state arrays (read through [`World::bodies`]).
    pub(crate) bodies: Bodies,
    params: WorldParams,
    k_nv: f64,
    contacts: ContactSet,
    joints: JointSet,
    /// Boundary conditions of the ridging experiment.
    pub(crate) boundary: Boundary,
    loads: Vec<(BodyId, V2)>,
    broad: SweepAndPrune,
    water: WaterForces,
    acc: Accumulators,
    blocks_broken: u64,
    handovers: Handovers,
    dt: f64,
    /// The last step's Δt (s), 0 before the first: what the next step's rates are read
    /// over and its kick averages with ([`crate::dem::numerics::StepNumerics`]).
    last_dt: f64,
    /// With [`WorldParams::refine_window`]: the time (s) until which steps are refined,
    /// from the last severed joint.
    refine_until: f64,
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
    /// Bodies shielded from form drag this step (`dem::water::shielded_bodies`).
    shielded: Vec<bool>,
    /// Threads the force phases of a step run on ([`World::set_threads`]); none: one.
    pool: Option<std::sync::Arc<rayon::ThreadPool>>,
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
            last_dt: 0.0,
            refine_until: f64::NEG_INFINITY,
            time: 0.0,
            steps: 0,
            fault: None,
            defer_time_step: false,
            vel_old: Vec::new(),
            omega_old: Vec::new(),
            vbar: Vec::new(),
            wbar: Vec::new(),
            shielded: Vec::new(),
            pool: None,
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
        let geom = JointGeometry {
            pa: ba.rect_centre() + V2::new(0.5 * ba.width, 0.0),
            pb: bb.rect_centre() + V2::new(-0.5 * bb.width, 0.0),
            h: ba.thickness.min(bb.thickness),
            skeletal,
            gauge: 0.5 * (ba.width + bb.width),
        };
        let k = self.joints.push(Joint::new(a, b, geom, mat));
        // The time step is derived while the world is built and then kept for the run
        // (blocks the sheet grows later are alike and need no new bound).
        if self.steps == 0 && !self.defer_time_step {
            self.refresh_time_step();
        }
        Ok(k)
    }

    /// The bodies' state, read-only: one entry per body ([`BodyId`] as the index) in each
    /// array. SI units per metre of depth: centroid positions `pos` (m), orientations
    /// `theta` (rad, counter-clockwise), velocities `vel` (m/s) and angular velocities
    /// `omega` (rad/s) at the half step n − ½ before a step and n + ½ after it (the
    /// leapfrog's staggering), masses `mass` (kg/m), moments of inertia `inertia` about the
    /// centroid (kg·m²/m). Bodies change only through the world ([`World::add_rect`],
    /// [`World::set_velocity`], [`World::step`]), so that the energy ledger stays closed.
    ///
    /// ```
    /// use pressridge_sim::dem::{Block, Drive, Role, V2, World, WorldParams};
    ///
    /// let mut w = World::new(WorldParams::default())?;
    /// let block = Block::new(0.25, 0.30, [0.0; 4]); // m: width, thickness, bevel legs
    /// let id = w.add_rect(block, V2::new(0.0, 0.0), 0.0, Drive::FREE, Role::Rubble)?;
    /// for _ in 0..100 {
    ///     w.step(); // gravity and buoyancy move it towards its floating level
    /// }
    /// let b = w.bodies();
    /// let (y, v) = (b.pos[id as usize].y, b.vel[id as usize].y); // m, m/s
    /// assert_eq!(b.len(), 1);
    /// assert!((b.mass[id as usize] - 920.0 * 0.25 * 0.30).abs() < 1e-9); // kg/m
    /// assert!(y.is_finite() && v.is_finite());
    /// # Ok::<(), pressridge_sim::dem::WorldError>(())
    /// ```
    pub fn bodies(&self) -> &Bodies {
        &self.bodies
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

    /// Adds the damping ratio ζ of every active contact to the contacts' tally (call it at
    /// regular instants, e.g. at every sample of a run): see [`World::contact_tally`].
    pub fn tally_contacts(&mut self) {
        self.contacts.tally_zeta();
    }

    /// The contacts' tally so far: the restitution of every impact, and the damping ratios
    /// counted by [`World::tally_contacts`].
    pub fn contact_tally(&self) -> &ContactTally {
        &self.contacts.tally
    }

    /// Number of joints severed so far.
    pub fn blocks_broken(&self) -> u64 {
        self.blocks_broken
    }

    /// Contacts born overlapping so far (from a severed joint, or a sheet block grown
    /// through rubble), and the largest such overlap (m²): see `dem::contact`.
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

    /// Runs the force phases of every step (outlines, water, joints, the contact geometry)
    /// on `threads` threads (1: on the calling thread, the default). Everything that is
    /// summed is summed in the same order whatever the count, so the same world gives the
    /// same bits on any number of threads; a count is a speed, not a parameter (it is in no
    /// scene or saved state). An error when the threads cannot be started.
    pub fn set_threads(&mut self, threads: usize) -> Result<(), WorldError> {
        self.pool = if threads <= 1 {
            None
        } else {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .thread_name(|k| format!("pressridge-step-{k}"))
                .build()
                .map_err(|e| WorldError::State(format!("{threads} threads: {e}")))?;
            Some(std::sync::Arc::new(pool))
        };
        Ok(())
    }

    /// Runs `f` on this world inside its thread pool (on the calling thread without one), so
    /// that the steps `f` takes hand their force phases to the pool's threads without
    /// blocking the caller at each phase: the pool's own threads take the phases' work as it
    /// comes (rayon's work stealing), and the caller waits once, for all of `f`.
    pub fn in_pool<R: Send>(&mut self, f: impl FnOnce(&mut World) -> R + Send) -> R {
        match self.pool.clone() {
            Some(pool) => pool.install(|| f(self)),
            None => f(self),
        }
    }

    /// The number of threads a step runs on ([`World::set_threads`]).
    pub fn threads(&self) -> usize {
        self.pool.as_ref().map_or(1, |p| p.current_num_threads())
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

    /// Why the world stopped stepping, if it did: a step that produced a non-finite
    /// velocity ([`WorldError::NonFinite`], naming the step, the time and the first body).
    pub fn fault(&self) -> Option<&WorldError> {
        self.fault.as_ref()
    }

    /// Advances the world by one time step. A world without free bodies has no stability
    /// bound and does not move: set a time step with [`World::set_time_step`] to step it.
    /// A step that produces a non-finite velocity records a [`World::fault`] and leaves
    /// the positions; later calls do nothing.
    ///
    /// The phases, in order: every force at the poses and half-step velocities
    /// (`gather_forces`), the leapfrog velocities (eq 5, `integrate`), the ledger with the
    /// mid-step velocities (eqs 9–12, `book_ledger`), the positions (eq 6) and fracture
    /// (`advance_positions`).
    pub fn step(&mut self) {
        if self.dt.is_nan() || self.dt <= 0.0 || self.dt.is_infinite() || self.fault.is_some() {
            return;
        }
        let dt = self.step_length();
        let dt_prev = if self.last_dt > 0.0 { self.last_dt } else { dt };
        let num = self.params.step_numerics(dt, dt_prev);
        self.gather_forces(&num);
        let driver = self.integrate(num.kick);
        if self.fault.is_some() {
            return;
        }
        self.book_ledger(num.kick, driver);
        self.advance_positions(&num);
        self.last_dt = dt;
    }

    /// Outlines at the present poses, then every force of the step into `bodies.force` and
    /// `bodies.torque`: gravity, buoyancy and drag, joints (eq 1), boundary conditions
    /// (eqs 7–8, floe supports), external loads, numerical damping, contacts (eqs 2–4).
    fn gather_forces(&mut self, num: &StepNumerics) {
        let n = self.bodies.len();
        let g = self.params.gravity;
        let pool = self.pool.as_deref();
        let b = &mut self.bodies;
        b.update_all(pool);
        for i in 0..n {
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
            shielded_bodies(self.contacts.contacts(), n, w, &mut self.shielded);
            self.water.apply(b, w, g, &self.shielded, pool);
        }
        // Joints (eq 1) and boundary conditions (eqs 7–8, floe supports).
        self.joints
            .apply(b, self.params.ice_density, num.joint_dashpot, pool);
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
        let law = ContactLaw {
            params: &self.params.contact,
            k_nv: self.k_nv,
            water_level: self.params.water.as_ref().map(|w| w.level),
        };
        self.contacts
            .update(b, pairs, &law, num, &mut self.acc.contact, pool);
        if num.joint_dashpot == Dashpot::Implicit {
            self.joints.apply_viscous(b, num.kick);
        }
        self.note_impacts();
    }

    /// Leapfrog velocities, eq (5), over the kick `dt` (s; [`StepNumerics::kick`]); prescribed degrees of freedom take their value and the
    /// driver supplies whatever force that takes. Keeps the velocities before the step and
    /// the mid-step velocities for the ledger; returns the driver's work (J/m). A
    /// non-finite velocity records the fault.
    fn integrate(&mut self, dt: f64) -> f64 {
        let n = self.bodies.len();
        let b = &mut self.bodies;
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
        driver
    }

    /// The ledger, eqs (9)–(12): every force's work over the step with the mid-step
    /// velocities, so that it agrees with the kinetic energy exactly.
    fn book_ledger(&mut self, dt: f64, driver: f64) {
        let n = self.bodies.len();
        let g = self.params.gravity;
        let gamma = self.params.global_damping;
        let b = &self.bodies;
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
    }

    /// Positions, eq (6), the clock, then fracture: new cracks at the new poses, running
    /// cracks advance, and what they sever is handled ([`World::after_fracture`]).
    fn advance_positions(&mut self, num: &StepNumerics) {
        let dt = num.dt;
        let b = &mut self.bodies;
        for i in 0..b.len() {
            b.pos[i] = b.pos[i] + b.vel[i] * dt;
            b.theta[i] += b.omega[i] * dt;
        }
        self.time += dt;
        self.steps += 1;
        if !self.joints.is_empty() {
            self.joints.advance(
                self.params.crack_speed,
                self.time,
                num,
                &mut self.acc.joints,
            );
            if !self.joints.severed().is_empty() {
                if let Some(w) = self.params.refine_window {
                    self.refine_until = self.time + w;
                }
                self.after_fracture();
            }
        }
    }
}

/// Contacts born overlapping, their overlap forgiven (see `dem::contact`): from a
/// joint that severed while its blocks overlapped, or a sheet block grown through rubble.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Handovers {
    /// How many contacts were born overlapping.
    pub count: u64,
    /// The largest such overlap (m² per metre of depth, i.e. the overlap area).
    pub max_area: f64,
}
