//! Flexural fracture of joints (Hopkins 1994, "Dynamic Ridge Model"): "When the tensile
//! stress in a joint at either surface of the sheet or a rubble block exceeds the specified
//! strength, a crack is initiated. The crack propagates at constant speed across the joint,
//! requiring many time steps for completion."
//!
//! - The test uses the elastic stress E·δ_n/W at the ends of the intact span (the top surface
//!   and the top of the skeletal layer), against 750 kPa (top) and 350 kPa (bottom). The
//!   viscous stress is left out of the test: it exists to damp the discretisation's
//!   oscillations, and a fast but small vibration should not break ice.
//! - A crack, once started, runs at `crack_speed` (m/s) whatever the stress does, eating the
//!   intact span from its side; the intact part keeps carrying load. A joint whose span is
//!   gone is severed: the two blocks then interact by contact only, and the piece they
//!   belonged to is split. Pieces keep their other joints and can break again.

use super::body::Bodies;
use super::broadphase::pair_key;
use super::geometry::V2;
use super::joint::{Joint, SurfaceStress};
use super::numerics::{Dashpot, StepNumerics};
use serde::{Deserialize, Serialize};

/// All joints of a world, with the index of intact pairs for the contact exclusion.
#[derive(Clone, Debug, Default)]
pub(crate) struct JointSet {
    joints: Vec<Joint>,
    /// Per body, up to two partners held by an intact joint (`NONE` for an empty slot):
    /// the broad phase asks for every candidate pair, so this answers in O(1). A block of
    /// a sheet, floe or rubble piece has at most two joints (left and right).
    partners: Vec<[u32; 2]>,
    /// Sorted keys of intact joints that did not fit in `partners` (bodies with more than
    /// two joints, which the scenes never make).
    overflow: Vec<u64>,
    /// Joints severed in the last step (indices into `joints`).
    severed: Vec<usize>,
    /// The largest tested stress over strength of the intact joints at the last
    /// [`JointSet::advance`] (dimensionless), kept only with [`StepNumerics::track_load`].
    max_load: f64,
}

/// An empty slot of [`JointSet::partners`].
const NONE: u32 = u32::MAX;

/// Work absorbed by joints (J/m).
///
/// A joint holds the elastic work booked into it (its running elastic work), as a contact
/// holds its elastic normal work: the books then close exactly, and the O(Δt²) difference
/// between booked work and the closed-form energy ½∫(E·δ_n² + G·δ_t²)/W (which also carries
/// the joint law's small non-conservative part under large rotations) stays with the
/// intact joint instead of leaking into the fracture term. When a joint is severed, the
/// work it holds is released: that is the fracture dissipation, and it cannot be negative
/// except by that O(Δt²) difference on a joint that breaks unloaded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub(crate) struct JointWork {
    /// Work of the elastic stresses on all joints, intact or severed.
    pub elastic: f64,
    /// Work of the viscous stresses: joint dissipation.
    pub viscous: f64,
    /// Elastic work held by joints at the moment they were severed: the fracture
    /// dissipation.
    pub released: f64,
}

impl JointWork {
    /// Elastic energy held by the intact joints (J/m).
    pub fn held(&self) -> f64 {
        self.elastic - self.released
    }
}

impl JointSet {
    /// The joints.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }
    /// Mutable access to the joints (for re-anchoring after a block is reshaped).
    pub fn joints_mut(&mut self) -> &mut [Joint] {
        &mut self.joints
    }
    /// Adds a joint; returns its index.
    pub fn push(&mut self, j: Joint) -> usize {
        self.link(j.a, j.b);
        self.joints.push(j);
        self.joints.len() - 1
    }
    /// Replaces all joints (restoring a saved state).
    pub fn restore(&mut self, joints: Vec<Joint>) {
        self.partners.clear();
        self.overflow.clear();
        for j in joints.iter().filter(|j| j.is_intact()) {
            self.link(j.a, j.b);
        }
        self.joints = joints;
        self.severed.clear();
    }
    /// Records the intact pair (a, b).
    fn link(&mut self, a: u32, b: u32) {
        let n = a.max(b) as usize + 1;
        if self.partners.len() < n {
            self.partners.resize(n, [NONE; 2]);
        }
        let free = |p: &[u32; 2]| p.iter().position(|&x| x == NONE);
        match (
            free(&self.partners[a as usize]),
            free(&self.partners[b as usize]),
        ) {
            (Some(i), Some(k)) => {
                self.partners[a as usize][i] = b;
                self.partners[b as usize][k] = a;
            }
            _ => {
                let key = pair_key(a.min(b), a.max(b));
                let pos = self.overflow.partition_point(|&x| x < key);
                self.overflow.insert(pos, key);
            }
        }
    }
    /// Forgets the intact pair (a, b).
    fn unlink(&mut self, a: u32, b: u32) {
        let key = pair_key(a.min(b), a.max(b));
        if let Ok(p) = self.overflow.binary_search(&key) {
            self.overflow.remove(p);
            return;
        }
        for (x, y) in [(a, b), (b, a)] {
            if let Some(slot) = self.partners[x as usize].iter_mut().find(|s| **s == y) {
                *slot = NONE;
            }
        }
    }
    /// True when bodies `a` and `b` are held together by a joint that is not severed.
    #[inline]
    pub fn joined(&self, a: u32, b: u32) -> bool {
        match self.partners.get(a as usize) {
            Some(p) if p[0] == b || p[1] == b => true,
            _ => {
                !self.overflow.is_empty()
                    && self
                        .overflow
                        .binary_search(&pair_key(a.min(b), a.max(b)))
                        .is_ok()
            }
        }
    }
    /// Joints severed during the last call to [`JointSet::advance`].
    pub fn severed(&self) -> &[usize] {
        &self.severed
    }
    /// True when a crack runs in some joint that is not yet severed.
    pub fn any_cracking(&self) -> bool {
        self.joints
            .iter()
            .any(|j| j.is_intact() && (j.crack_top || j.crack_bottom))
    }
    /// The largest tested stress over strength of the intact joints at the last step
    /// (dimensionless; 0 unless [`StepNumerics::track_load`]).
    pub fn max_load(&self) -> f64 {
        self.max_load
    }
    /// Sets [`JointSet::max_load`] (a restored world's).
    pub fn set_max_load(&mut self, load: f64) {
        self.max_load = load;
    }
    /// True when there is no joint.
    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// Applies every intact joint's forces to the bodies: all of them for the explicit
    /// dashpot, the elastic ones for the implicit one (then [`JointSet::apply_viscous`]).
    pub fn apply(
        &mut self,
        bodies: &mut Bodies,
        rho_i: f64,
        dashpot: Dashpot,
        pool: Option<&rayon::ThreadPool>,
    ) {
        super::joint::apply_all(&mut self.joints, bodies, rho_i, dashpot, pool);
    }

    /// Applies every intact joint's viscous force at the mid-step velocities, once every
    /// other force of the step is in the bodies ([`Dashpot::Implicit`] for joints).
    pub fn apply_viscous(&mut self, bodies: &mut Bodies, dt: f64) {
        for j in self.joints.iter_mut() {
            j.apply_viscous(bodies, dt);
        }
    }

    /// Books the joints' work for this step.
    pub fn book_work(&mut self, vbar: &[V2], wbar: &[f64], dt: f64, w: &mut JointWork) {
        for j in self.joints.iter_mut() {
            if j.is_intact() {
                let (e, v) = j.book_work(vbar, wbar, dt);
                w.elastic += e;
                w.viscous += v;
            }
        }
    }

    /// Tests for new cracks with the stresses of the last [`JointSet::apply`] (the poses at
    /// the start of the step) and advances running ones by `crack_speed·dt` (m). Joints that
    /// lose their last intact part are listed in [`JointSet::severed`], and the elastic
    /// work they held is added to `w.released`.
    ///
    /// With an `incubation` time τ (s) the stresses tested are the elastic ones filtered by
    /// dσ_f/dt = (σ − σ_f)/τ, advanced exactly over the step for σ held constant. With
    /// `step_mean` they are the mean of the last two poses' stresses, (σⁿ⁻¹ + σⁿ)/2 (the
    /// first step of a joint: σⁿ): for every mode of the leapfrog scheme that mean swings
    /// as far as the exact motion of the same energy, where σⁿ overshoots by 1/cos(θ/2)
    /// (θ the mode's phase per step; docs/speed-vs-error.md).
    pub(crate) fn advance(
        &mut self,
        crack_speed: f64,
        time: f64,
        num: &StepNumerics,
        w: &mut JointWork,
    ) {
        let (incubation, step_mean, dt) = (num.incubation_time, num.fracture_step_mean, num.dt);
        self.severed.clear();
        let gain = incubation.map(|tau| -(-dt / tau).exp_m1());
        let track = num.track_load;
        let mut max_load: f64 = 0.0;
        for (k, j) in self.joints.iter_mut().enumerate() {
            if !j.is_intact() {
                continue;
            }
            let s = match gain {
                None if step_mean => {
                    let last = j.stress_filtered.replace(j.stress).unwrap_or(j.stress);
                    SurfaceStress {
                        top: 0.5 * (last.top + j.stress.top),
                        bottom: 0.5 * (last.bottom + j.stress.bottom),
                    }
                }
                None => j.stress,
                Some(a) => {
                    let f = j.stress_filtered.get_or_insert_with(Default::default);
                    f.top += a * (j.stress.top - f.top);
                    f.bottom += a * (j.stress.bottom - f.bottom);
                    *f
                }
            };
            if track {
                max_load = max_load
                    .max(s.top / j.mat.strength_top)
                    .max(s.bottom / j.mat.strength_bottom);
            }
            if !j.crack_top && s.top > j.mat.strength_top {
                j.crack_top = true;
            }
            if !j.crack_bottom && s.bottom > j.mat.strength_bottom {
                j.crack_bottom = true;
            }
            if (j.crack_top || j.crack_bottom) && j.crack_started < 0.0 {
                j.crack_started = time;
            }
            let step = crack_speed * dt;
            if j.crack_top {
                j.s_hi -= step;
            }
            if j.crack_bottom {
                j.s_lo += step;
            }
            if !j.is_intact() {
                j.s_hi = j.s_lo;
                w.released += j.elastic_work;
                self.severed.push(k);
            }
        }
        self.max_load = max_load;
        for i in 0..self.severed.len() {
            let j = self.joints[self.severed[i]];
            self.unlink(j.a, j.b);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::joint::{JointMaterial, SurfaceStress};

    /// One joint whose elastic surface stress is held at `top` (Pa) from t = 0, strength
    /// 500 kPa: the time (s) of the step at which its top crack starts.
    fn first_crack(top: f64, incubation: Option<f64>, dt: f64) -> Option<f64> {
        first_crack_of(|_| top, incubation, false, dt)
    }

    /// One joint whose elastic top stress at step n is `top(n)` (Pa), strength 500 kPa:
    /// the time (s) of the step at which its top crack starts.
    fn first_crack_of(
        top: impl Fn(usize) -> f64,
        incubation: Option<f64>,
        step_mean: bool,
        dt: f64,
    ) -> Option<f64> {
        let mat = JointMaterial {
            e_top: 1e8,
            e_bottom: 1e8,
            poisson: 0.3,
            damping_fraction: 0.1,
            strength_top: 5e5,
            strength_bottom: 5e5,
        };
        let mut set = JointSet::default();
        let k = set.push(Joint::new(
            0,
            1,
            crate::dem::joint::JointGeometry {
                pa: V2::new(0.125, 0.0),
                pb: V2::new(-0.125, 0.0),
                h: 0.3,
                skeletal: 0.06,
                gauge: 0.25,
            },
            mat,
        ));
        let mut w = JointWork::default();
        let num = StepNumerics {
            dt,
            dt_prev: dt,
            kick: dt,
            contact_dashpot: Dashpot::Implicit,
            contact_onset: crate::dem::ContactOnset::Area,
            contact_dashpot_sweeps: 0,
            joint_dashpot: Dashpot::Explicit,
            incubation_time: incubation,
            fracture_step_mean: step_mean,
            track_load: false,
        };
        for n in 1..=20_000 {
            set.joints[k].stress = SurfaceStress {
                top: top(n),
                bottom: 0.0,
            };
            let t = n as f64 * dt;
            set.advance(50.0, t, &num, &mut w);
            if set.joints[k].crack_top {
                return Some(t);
            }
        }
        None
    }

    /// Without an incubation time a stress above the strength starts a crack at once; with
    /// τ the filtered stress σ(1 − e^{−t/τ}) reaches the strength S at t* = −τ·ln(1 − S/σ)
    /// (to within one step), and a stress below S never does.
    #[test]
    fn incubation_time_delays_initiation_as_the_filter_predicts() {
        let dt = 1e-5;
        assert_eq!(first_crack(6e5, None, dt), Some(dt));
        let tau: f64 = 2e-3;
        for sigma in [5.5e5f64, 7.5e5, 1.5e6] {
            let expect = -tau * (1.0 - 5e5 / sigma).ln();
            let got = first_crack(sigma, Some(tau), dt).unwrap();
            assert!(
                (got - expect).abs() <= dt,
                "σ = {sigma} Pa: crack at {got} s, expected {expect} s"
            );
        }
        assert_eq!(first_crack(4.9e5, Some(tau), dt), None);
        // The step does not matter beyond its own resolution (exact exponential update).
        let coarse = first_crack(7.5e5, Some(tau), 4e-4).unwrap();
        let fine = first_crack(7.5e5, Some(tau), 1e-5).unwrap();
        assert!((coarse - fine).abs() <= 4e-4, "{coarse} against {fine}");
    }

    /// A mode of frequency ω loaded at once by a stress σ_eq swings exactly to 2·σ_eq. The
    /// leapfrog recurrence yₖ₊₁ = 2yₖ − yₖ₋₁ − (ωΔt)²·(yₖ − 1) from rest (y₋₁ = y₀ = 0)
    /// swings to 1 + 1/cos(θ/2), sin(θ/2) = ωΔt/2: 2.67 at ωΔt = 1.6 (0.8 of the bound).
    /// Tested on the pose's stress, a σ_eq of 0.8 of half the strength breaks the joint;
    /// tested on the two-pose mean, the joint breaks exactly when 2·σ_eq passes the strength
    /// (±2 %), as the exact motion would.
    #[test]
    fn the_two_pose_mean_removes_the_leapfrog_overshoot_of_a_sudden_load() {
        let leapfrog = |r: f64, n_max: usize| {
            let (mut prev, mut y) = (0.0f64, 0.0f64);
            let mut ys = vec![0.0];
            for _ in 0..n_max {
                let next = 2.0 * y - prev - r * r * (y - 1.0);
                (prev, y) = (y, next);
                ys.push(y);
            }
            ys
        };
        let dt = 1e-4;
        let strength = 5e5;
        for r in [1.6, 1.2, 0.5] {
            let ys = leapfrog(r, 20_001);
            let half = (r / 2.0f64).asin();
            let peak = ys.iter().cloned().fold(0.0, f64::max);
            let predicted = 1.0 + 1.0 / half.cos();
            assert!(
                (peak - predicted).abs() < 1e-3 * predicted,
                "{peak} against {predicted}"
            );
            for (ratio, breaks) in [(1.02, true), (0.98, false)] {
                let s_eq = ratio * strength / 2.0;
                let got = first_crack_of(|n| s_eq * ys[n - 1], None, true, dt).is_some();
                assert_eq!(got, breaks, "ωΔt = {r}, 2σ_eq = {ratio} × strength");
            }
        }
        // The pose's stress overshoots: at ωΔt = 1.6 a load of 0.8 × half the strength
        // breaks the joint.
        let ys = leapfrog(1.6, 20_001);
        let s_eq = 0.8 * strength / 2.0;
        assert!(first_crack_of(|n| s_eq * ys[n - 1], None, false, dt).is_some());
        assert!(first_crack_of(|n| s_eq * ys[n - 1], None, true, dt).is_none());
    }

    /// The two-pose mean and the incubation time both filter the tested stress: a world
    /// that sets both is refused, naming the parameter (the scene's check:
    /// `scene::tests`).
    #[test]
    fn the_two_pose_mean_and_an_incubation_time_exclude_each_other() {
        use crate::dem::{World, WorldError, WorldParams};
        let p = WorldParams {
            incubation_time: Some(2e-3),
            fracture_step_mean: true,
            ..WorldParams::default()
        };
        match World::new(p) {
            Err(WorldError::Param { name, .. }) => assert_eq!(name, "fracture_step_mean"),
            other => panic!("{:?}", other.map(|_| ())),
        }
    }

    /// A world built by hand is refused a zero, negative or non-finite incubation time,
    /// with the parameter named (a negative τ would make the filter grow without bound).
    #[test]
    fn a_bad_incubation_time_is_refused_by_name() {
        use crate::dem::{World, WorldError, WorldParams};
        for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
            let p = WorldParams {
                incubation_time: Some(bad),
                ..WorldParams::default()
            };
            match World::new(p) {
                Err(WorldError::Param { name, .. }) => assert_eq!(name, "incubation_time"),
                other => panic!("τ = {bad}: {:?}", other.map(|_| ())),
            }
        }
        let p = WorldParams {
            incubation_time: Some(2e-3),
            ..WorldParams::default()
        };
        assert!(World::new(p).is_ok());
    }
}
