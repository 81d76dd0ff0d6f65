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
use super::joint::Joint;
use serde::{Deserialize, Serialize};

/// All joints of a world, with the index of intact pairs for the contact exclusion.
#[derive(Clone, Debug, Default)]
pub struct JointSet {
    joints: Vec<Joint>,
    /// Sorted keys of joints not yet severed: these pairs have no contact.
    joined: Vec<u64>,
    /// Joints severed in the last step (indices into `joints`).
    severed: Vec<usize>,
}

/// Work absorbed by joints (J/m).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct JointWork {
    /// Work of the elastic stresses: the elastic energy held plus what cracks released.
    pub elastic: f64,
    /// Work of the viscous stresses: joint dissipation.
    pub viscous: f64,
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
        let k = pair_key(j.a.min(j.b), j.a.max(j.b));
        let pos = self.joined.partition_point(|&x| x < k);
        self.joined.insert(pos, k);
        self.joints.push(j);
        self.joints.len() - 1
    }
    /// Replaces all joints (restoring a saved state).
    pub fn restore(&mut self, joints: Vec<Joint>) {
        self.joints = joints;
        self.joined = self
            .joints
            .iter()
            .filter(|j| j.is_intact())
            .map(|j| pair_key(j.a.min(j.b), j.a.max(j.b)))
            .collect();
        self.joined.sort_unstable();
        self.severed.clear();
    }
    /// True when bodies `a < b` are held together by a joint that is not severed.
    #[inline]
    pub fn joined(&self, a: u32, b: u32) -> bool {
        !self.joined.is_empty() && self.joined.binary_search(&pair_key(a, b)).is_ok()
    }
    /// Joints severed during the last call to [`JointSet::advance`].
    pub fn severed(&self) -> &[usize] {
        &self.severed
    }
    /// Number of joints.
    pub fn len(&self) -> usize {
        self.joints.len()
    }
    /// True when there is no joint.
    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// Applies every intact joint's forces to the bodies.
    pub fn apply(&mut self, bodies: &mut Bodies, rho_i: f64) {
        for j in self.joints.iter_mut() {
            j.apply(bodies, rho_i);
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
    /// lose their last intact part are listed in [`JointSet::severed`].
    pub fn advance(&mut self, crack_speed: f64, time: f64, dt: f64) {
        self.severed.clear();
        for (k, j) in self.joints.iter_mut().enumerate() {
            if !j.is_intact() {
                continue;
            }
            let s = j.stress;
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
                self.severed.push(k);
            }
        }
        if !self.severed.is_empty() {
            for &k in &self.severed {
                let j = &self.joints[k];
                let key = pair_key(j.a.min(j.b), j.a.max(j.b));
                if let Ok(p) = self.joined.binary_search(&key) {
                    self.joined.remove(p);
                }
            }
        }
    }

    /// Elastic energy held by all intact joints (J/m).
    pub fn stored_energy(&self, bodies: &Bodies) -> f64 {
        self.joints.iter().map(|j| j.stored_energy(bodies)).sum()
    }
}
