//! Boundary conditions of the ridging experiment (Hopkins 1994, "Boundary Conditions on the
//! Sheet and Floe", Figure 1):
//!
//! - the leftmost sheet block moves at the constant speed U (its x velocity is prescribed;
//!   it floats freely in y and θ), and the sheet keeps its length: every block broken off at
//!   the right is replaced by a new block joined at the left, which takes over the drive;
//! - eqs (7)–(8): on every sheet block a viscous force F_x = −k′(u_i − u_1), F_y = −k′v_i with
//!   k′ = k_nv·h·exp(−c·(x_i − x_1)/(x_n − x_1)), c = 4 ("arrived at empirically"). Eq (8)
//!   writes k_nv, the contact's viscous coefficient (kg/(m²·s), multiplying an area rate in
//!   eq 3); to act on a velocity it is multiplied by the sheet thickness h, i.e. it is the
//!   damping of a contact along a face of height h (kg/(m·s));
//! - a vertical spring and dashpot on every floe block towards its position at rest, standing
//!   for the support of a three-dimensional floe; the pin joint of point C is the rightmost
//!   floe block held in x and y (free to rotate), see [`crate::scene`].

use super::body::{Bodies, BodyId};
use super::geometry::V2;
use super::joint::JointMaterial;
use serde::{Deserialize, Serialize};

/// The pushed sheet: what is needed to drive it and to grow it at the left.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct SheetBoundary {
    /// Speed U (m/s).
    pub(crate) speed: f64,
    /// The driven block is also held at its height and orientation.
    pub(crate) clamp: bool,
    /// Block width W (m).
    pub(crate) width: f64,
    /// Thickness h (m).
    pub(crate) thickness: f64,
    /// Skeletal layer without joint (m).
    pub(crate) skeletal: f64,
    /// Nominal joint material; each new joint varies E by ±`modulus_variation`.
    pub(crate) material: JointMaterial,
    /// Relative amplitude of the random variation of E at each joint (0.01 = ±1 %).
    pub(crate) modulus_variation: f64,
    /// Seed of the variation.
    pub(crate) seed: u64,
    /// Joints made so far (the variation of joint k is drawn from (seed, k)).
    pub(crate) joints_made: u64,
    /// Bevel leg at the bottom of the sheet tip, point B (m): its drop up the tip's face.
    pub(crate) tip_bevel: f64,
    /// The tip bevel's run along the sheet's bottom (m), or `None` at 45° (run = drop).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) tip_bevel_run: Option<f64>,
    /// Bevel leg on the corners of a broken face (m).
    pub(crate) corner_bevel: f64,
    /// Decay constant of eq (8) (dimensionless).
    pub(crate) decay: f64,
    /// k_nv·h of eq (8) (kg/(m·s)).
    pub(crate) viscosity: f64,
    /// Sheet blocks from left (driven) to right (tip).
    pub(crate) blocks: Vec<BodyId>,
}

/// The supports of the floe blocks.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct FloeSupport {
    /// Floe blocks with their rest height (m).
    pub(crate) blocks: Vec<(BodyId, f64)>,
    /// Spring stiffness per block (N/m per m of depth).
    pub(crate) stiffness: Vec<f64>,
    /// Dashpot coefficient per block (kg/(m·s)).
    pub(crate) damping: Vec<f64>,
    /// Bevel leg on the corners of a broken face (m).
    pub(crate) corner_bevel: f64,
}

/// Boundary conditions present in a world.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub(crate) struct Boundary {
    /// The pushed sheet, if any.
    pub(crate) sheet: Option<SheetBoundary>,
    /// The floe supports, if any.
    pub(crate) floe: Option<FloeSupport>,
    /// Forces of the current step for the ledger: (body, viscous force of eq 7, support
    /// spring force, support dashpot force), all at the centroid (N/m).
    #[serde(skip)]
    pub(crate) forces: Vec<(BodyId, V2, V2, V2)>,
}

/// Work absorbed by boundary forces (J/m).
///
/// The viscous force of eq (7) acts on a sheet block's velocity relative to the driven
/// block, i.e. it is a dashpot to a frame that moves with the push at U (the far field of a
/// three-dimensional sheet). The work the bodies do against it, −F·v̄·Δt, therefore splits
/// into the dashpot's dissipation −F·(v̄ − U·x̂)·Δt, which is k′·|v − U·x̂|²·Δt ≥ 0 to
/// first order, and the remainder F_x·U·Δt, the work the moving frame does on the bodies: a second
/// input of the push next to the driver's (it is large and positive while the sheet at rest
/// is brought up to speed, which, booked as dissipation, made that negative).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub(crate) struct BoundaryWork {
    /// Dissipation of the eq (7)–(8) dashpots (relative to the moving frame) and of the
    /// floe dashpots.
    pub damping: f64,
    /// Work booked into the floe support springs: the elastic energy they hold (a linear
    /// spring's booked work telescopes, so this is what it holds to the step's accuracy).
    pub springs: f64,
    /// Work done on the bodies by the frame of eq (7) moving at U (an input, J/m).
    pub frame: f64,
}

impl SheetBoundary {
    /// The random factor (1 ± variation) of joint number `k`, from the seed alone, so that
    /// the sequence does not depend on when joints are made.
    pub(crate) fn modulus_factor(&self, k: u64) -> f64 {
        // SplitMix64 (Steele, Lea & Flood 2014) of (seed, k): a counter-based generator,
        // so a restored run draws the same numbers without carrying generator state.
        let mut z = self
            .seed
            .wrapping_mul(0x9E37_79B9_7F4A_7C15)
            .wrapping_add(k.wrapping_add(1).wrapping_mul(0xBF58_476D_1CE4_E5B9));
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        1.0 + self.modulus_variation * (2.0 * u - 1.0)
    }
}

impl Boundary {
    /// Adds the forces of eqs (7)–(8) and of the floe supports to the bodies.
    pub(crate) fn apply(&mut self, b: &mut Bodies) {
        self.forces.clear();
        if let Some(s) = &self.sheet {
            let n = s.blocks.len();
            if n > 0 && s.viscosity > 0.0 {
                let first = s.blocks[0] as usize;
                let last = s.blocks[n - 1] as usize;
                let (x1, u1) = (b.pos[first].x, b.vel[first].x);
                let span = b.pos[last].x - x1;
                for &id in &s.blocks {
                    let i = id as usize;
                    let frac = if span > 0.0 {
                        (b.pos[i].x - x1) / span
                    } else {
                        0.0
                    };
                    let k = s.viscosity * (-s.decay * frac).exp();
                    let f = V2::new(-k * (b.vel[i].x - u1), -k * b.vel[i].y);
                    b.force[i] = b.force[i] + f;
                    self.forces.push((id, f, V2::default(), V2::default()));
                }
            }
        }
        if let Some(fl) = &self.floe {
            for (k, &(id, y0)) in fl.blocks.iter().enumerate() {
                let i = id as usize;
                let fs = V2::new(0.0, -fl.stiffness[k] * (b.pos[i].y - y0));
                let fd = V2::new(0.0, -fl.damping[k] * b.vel[i].y);
                b.force[i] = b.force[i] + fs + fd;
                self.forces.push((id, V2::default(), fs, fd));
            }
        }
    }

    /// Books the boundary forces' work with mid-step velocities: the eq (7) dashpots
    /// relative to their frame moving at U, the frame's own work, the floe dashpots and
    /// springs (see [`BoundaryWork`]).
    pub(crate) fn book_work(&self, vbar: &[V2], dt: f64, w: &mut BoundaryWork) {
        let u = self.sheet.as_ref().map_or(0.0, |s| s.speed);
        for &(id, fv, fs, fd) in &self.forces {
            let v = vbar[id as usize];
            let rel = V2::new(v.x - u, v.y);
            w.damping -= (fv.dot(rel) + fd.dot(v)) * dt;
            w.frame += fv.x * u * dt;
            w.springs -= fs.dot(v) * dt;
        }
    }
}
