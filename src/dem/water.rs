//! Buoyancy and water drag on blocks (Hopkins 1994, "Dynamic Ridge Model": "the buoyancy of
//! the sheet and ice rubble are rigorously modeled by calculating their submerged area").
//!
//! Buoyancy is ρ_w·g·A_s, upward, at the centroid of the submerged part A_s of the block.
//! The paper names water drag as a dissipation mechanism but does not give its law; ours is
//! a quadratic form drag on the submerged part (documented in `docs/model.md`):
//!
//! - force  F = −(½·ρ_w·C_d·ℓ·|v_s| + c_lin·A_s)·v_s at the submerged centroid, where v_s is
//!   the velocity of that point and ℓ the width of the submerged part seen by the flow
//!   (its extent perpendicular to v_s);
//! - moment M = −(ρ_w·C_d·D⁴/64)·|ω|·ω, the strip-theory moment on a plate of length D
//!   spinning about its middle, with D the diagonal of the submerged part's bounding box.
//!
//! By default drag acts on free blocks and rubble, not on the blocks of the sheet or the
//! floe ([`DragBodies::Rubble`]): the paper models the water's damping of those by the
//! viscous forces of eqs (7)–(8) and the floe's dashpots. (Form drag on each sheet block
//! would also be wrong in itself: the blocks of a continuous sheet moving through water
//! shield one another.) [`DragBodies::All`] puts it on every free body in the water, to
//! measure that choice (`docs/choices.md`).

use super::body::{Bodies, Role};
use super::geometry::{ClipPoly, V2, area_centroid, clip_below_into};
use serde::{Deserialize, Serialize};

/// The water: level, density and drag law.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WaterParams {
    /// Still-water level (m). Default 0.
    pub level: f64,
    /// Sea-water density ρ_w (kg/m³). Default 1010 (Hopkins 1994, Table 1).
    pub density: f64,
    /// Form-drag coefficient C_d (dimensionless). Default 1.0, an order-one bluff-body
    /// value; the paper gives none. Set 0 to switch form drag off.
    pub drag_coefficient: f64,
    /// Linear drag coefficient c_lin (kg/(m³·s) : N/m per m² submerged per m/s). Default 0;
    /// verification scenes use it to settle quickly without changing the equilibrium.
    pub linear_drag: f64,
    /// Which bodies feel drag (both laws). Default [`DragBodies::Rubble`].
    pub drag_bodies: DragBodies,
}

/// Which bodies feel water drag. The paper names drag among the dissipative mechanisms
/// without saying on what; held (kinematic) bodies never feel it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DragBodies {
    /// Free blocks and rubble only (the default): the sheet and the floe feel the water
    /// through eqs (7)–(8) and the floe's dashpots, which would otherwise count it twice.
    #[default]
    Rubble,
    /// Every body in the water, the sheet's and the floe's blocks too.
    All,
}

impl DragBodies {
    /// True for [`DragBodies::Rubble`] (a serde skip test).
    pub fn is_rubble(&self) -> bool {
        *self == DragBodies::Rubble
    }
}

impl Default for WaterParams {
    fn default() -> Self {
        Self {
            level: 0.0,
            density: 1010.0,
            drag_coefficient: 1.0,
            linear_drag: 0.0,
            drag_bodies: DragBodies::Rubble,
        }
    }
}

/// Per-body water forces of the current step, kept for the energy ledger.
#[derive(Clone, Debug, Default)]
pub(crate) struct WaterForces {
    /// Buoyant force (N/m, upward) and the submerged centroid (m).
    pub buoyancy: Vec<(f64, V2)>,
    /// Drag force (N/m), its point (m) and drag moment (N·m/m).
    pub drag: Vec<(V2, V2, f64)>,
    scratch: ClipPoly,
}

/// Work absorbed from the bodies by water forces (J/m).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub(crate) struct WaterWork {
    /// Work done against buoyancy: the buoyancy part of ΔPE in eq (10).
    pub buoyancy: f64,
    /// Work dissipated by drag.
    pub drag: f64,
}

impl WaterForces {
    /// Computes buoyancy and drag on every body from its current outline and half-step
    /// velocities, and adds them to the body forces. `g` is gravity (m/s²).
    pub fn apply(&mut self, bodies: &mut Bodies, w: &WaterParams, g: f64) {
        let n = bodies.len();
        self.buoyancy.resize(n, (0.0, V2::default()));
        self.drag.resize(n, (V2::default(), V2::default(), 0.0));
        let drag_on = w.drag_coefficient > 0.0 || w.linear_drag > 0.0;
        for i in 0..n {
            let aabb = bodies.aabb[i];
            // Held bodies are external agents: no water forces on them.
            if aabb.min.y >= w.level || bodies.drive[i].is_kinematic() {
                self.buoyancy[i] = (0.0, V2::default());
                self.drag[i] = (V2::default(), V2::default(), 0.0);
                continue;
            }
            let partly = aabb.max.y > w.level;
            let (area, c) = if partly {
                clip_below_into(&bodies.world[i], w.level, &mut self.scratch);
                self.scratch.area_centroid()
            } else {
                area_centroid(bodies.world[i].verts())
            };
            if area <= 0.0 {
                self.buoyancy[i] = (0.0, V2::default());
                self.drag[i] = (V2::default(), V2::default(), 0.0);
                continue;
            }
            let fb = w.density * g * area;
            bodies.apply(i, V2::new(0.0, fb), c);
            self.buoyancy[i] = (fb, c);
            // The sheet and the floe feel the water's damping through their own boundary
            // forces (eqs 7–8; the floe's dashpots): by default drag acts on free blocks
            // and rubble only.
            let shielded =
                w.drag_bodies.is_rubble() && matches!(bodies.role[i], Role::Sheet | Role::Floe);
            if !drag_on || shielded {
                self.drag[i] = (V2::default(), V2::default(), 0.0);
                continue;
            }
            let verts = if partly {
                self.scratch.verts()
            } else {
                bodies.world[i].verts()
            };
            let vs = bodies.point_velocity(i, c);
            let speed = vs.norm();
            let mut f = vs * (-w.linear_drag * area);
            if speed > 0.0 && w.drag_coefficient > 0.0 {
                let across = vs.perp() * (1.0 / speed);
                let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
                for &p in verts {
                    let s = p.dot(across);
                    lo = lo.min(s);
                    hi = hi.max(s);
                }
                f = f + vs * (-0.5 * w.density * w.drag_coefficient * (hi - lo) * speed);
            }
            let om = bodies.omega[i];
            let mut m = 0.0;
            if om != 0.0 && w.drag_coefficient > 0.0 {
                let (mut x0, mut x1, mut y0, mut y1) = (
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                );
                for &p in verts {
                    x0 = x0.min(p.x);
                    x1 = x1.max(p.x);
                    y0 = y0.min(p.y);
                    y1 = y1.max(p.y);
                }
                let d2 = (x1 - x0).powi(2) + (y1 - y0).powi(2);
                m = -w.density * w.drag_coefficient * d2 * d2 / 64.0 * om.abs() * om;
            }
            bodies.apply(i, f, c);
            bodies.torque[i] += m;
            self.drag[i] = (f, c, m);
        }
    }

    /// Books this step's water work with mid-step velocities (see `dem::ledger`).
    pub fn book_work(
        &self,
        bodies: &Bodies,
        vbar: &[V2],
        wbar: &[f64],
        dt: f64,
        work: &mut WaterWork,
    ) {
        for i in 0..self.buoyancy.len() {
            let (fb, c) = self.buoyancy[i];
            if fb == 0.0 {
                continue;
            }
            let v = vbar[i] + (c - bodies.pos[i]).perp() * wbar[i];
            work.buoyancy -= fb * v.y * dt;
            let (f, p, m) = self.drag[i];
            let vd = vbar[i] + (p - bodies.pos[i]).perp() * wbar[i];
            work.drag -= (f.dot(vd) + m * wbar[i]) * dt;
        }
    }
}
