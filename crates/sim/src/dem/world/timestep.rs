//! The time step of a [`World`]: the stable limit of the leapfrog scheme from the joints
//! and contacts present (docs/model.md, "Time step"), its safety factor, a fixed step
//! checked against the limit, and the step refined around fracture and impacts.

use super::*;

impl World {
    /// This step's Δt (s): [`World::dt`], or its [`WorldParams::refine_fraction`] while a
    /// joint is cracking or within [`WorldParams::refine_window`] of the last severed joint,
    /// or while a joint is loaded beyond [`WorldParams::refine_load`] of its strength.
    pub(super) fn step_length(&self) -> f64 {
        let p = &self.params;
        let after_break = p.refine_window.is_some()
            && (self.time < self.refine_until || self.joints.any_cracking());
        let loaded = p.refine_load.is_some_and(|f| self.joints.max_load() > f);
        if after_break || loaded {
            self.dt * p.refine_fraction.unwrap_or(params::DEFAULT_REFINE_FRACTION)
        } else {
            self.dt
        }
    }

    /// With [`WorldParams::refine_impact`]: an impact (a contact born this step, its blocks
    /// approaching faster than that) refines the step for [`WorldParams::refine_window`]
    /// after it, as a severed joint does.
    pub(super) fn note_impacts(&mut self) {
        if let (Some(v), Some(w)) = (self.params.refine_impact, self.params.refine_window)
            && self
                .contacts
                .contacts()
                .iter()
                .any(|c| c.steps == 1 && c.approach > v)
        {
            self.refine_until = self.refine_until.max(self.time + w);
        }
    }

    /// The length of the last step taken (s); [`World::dt`] before the first and whenever
    /// the step is not refined ([`WorldParams::refine_window`]).
    pub fn last_step(&self) -> f64 {
        if self.last_dt > 0.0 {
            self.last_dt
        } else {
            self.dt
        }
    }

    /// Re-derives the time step from the bodies and joints present (unless fixed):
    /// `time_step_safety` × [`World::stable_time_step`].
    pub(crate) fn refresh_time_step(&mut self) {
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
    /// limit ([`WorldError::Unstable`] when a fixed time step exceeds it).
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

    /// The stable time step of the leapfrog scheme (s) for the bodies and joints present:
    /// the smaller of a contact limit and a joint limit (docs/model.md, "Time step").
    ///
    /// Contacts. A contact along a chord of length L has normal stiffness k_ne·L (N/m²)
    /// and a dashpot k_nv·L. For bodies a and b, with inverse effective masses
    /// κᵢ = (1 + rᵢ²mᵢ/Iᵢ)/mᵢ at a point a distance rᵢ from the centroid and
    /// L ≤ min(dₐ, d_b) (d a body's diameter), ω² ≤ 2·k_ne·max(d·κ) and the damping ratio
    /// ζ ≤ ½·k_nv·sqrt(2·max(d·κ)/k_ne). With the explicit dashpot the step is stable for
    /// Δt < (2/ω)·(sqrt(1 + ζ²) − ζ); with the implicit one ([`Dashpot::Implicit`]) for
    /// Δt < √2/ω whatever ζ. The contact's tangential spring k_te of eq (4), which does not
    /// scale with L, has ω_t² ≤ 2·k_te·max κ; ω² is the larger of the two bounds. (With the
    /// paper's k_te = 0.6·k_ne·h and blocks at least h across, the normal one; a scene with a
    /// stiffer tangential spring gets the tangential one. The √2 of the implicit limit
    /// covers both springs of a contact acting at once: ω_n² + ω_t² ≤ 2·max.)
    ///
    /// Joints. Each joint's mass-scaled stiffness and damping have largest eigenvalues λ
    /// (1/s²) and μ (1/s) (`Joint::modal_bounds`); ω² of the joined blocks is at most the
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
        // One contact: ω_c² of its stiffer spring, normal or tangential, and its damping rate
        // in the explicit form (the implicit form is stable at any damping).
        let c = &self.params.contact;
        let k_ne = c.normal_stiffness;
        // Eq (4)'s k_te = f·k_ne·L with L ≤ d, like the normal spring's.
        let tangential = c.tangential_stiffness_per_chord() * dc;
        let contact_w2 = 2.0 * (k_ne * dc).max(tangential);
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
            // The implicit joint dashpot is stable at any damping, like the contacts'.
            let m = if self.params.joint_dashpot == Dashpot::Implicit {
                0.0
            } else {
                m
            };
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
}
