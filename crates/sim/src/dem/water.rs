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
//! - moment M = −½·ρ_w·C_d·|ω|·ω·J, the same quadratic pressure ½·ρ_w·C_d·v_n² on every
//!   element of the submerged outline that the spin drives into the water (v_n = ω·q, its
//!   normal speed, q = (p − x_c) × n its lever about the body's centroid x_c), summed as a
//!   moment: J = ∫ max(±q, 0)³ ds over the wetted edges (the water line is no face), the
//!   sign that of ω. J belongs to the outline, so the moment does not change when the
//!   same block turns ([`spin_drag_lever`]); for a plate of length D it is D⁴/32, the
//!   strip-theory moment ρ_w·C_d·D⁴/64·ω² of a plate spinning about its middle. (Until
//!   2026-12-01 J was taken from the diagonal of the submerged part's axis-aligned bounding
//!   box, which made a block tilted by 45° feel up to three times the moment of the same
//!   block level.)
//!
//! By default drag acts on free blocks and rubble, not on the blocks of the sheet or the
//! floe ([`DragBodies::Rubble`]): the paper models the water's damping of those by the
//! viscous forces of eqs (7)–(8) and the floe's dashpots. (Form drag on each sheet block
//! would also be wrong in itself: the blocks of a continuous sheet moving through water
//! shield one another.) [`DragBodies::All`] puts it on every free body in the water, to
//! measure that choice (`docs/choices.md`).

use super::body::{Bodies, Role};
use super::broadphase::unpack;
use super::contact::Contact;
use super::geometry::{ClipPoly, V2, area_centroid, clip_below_into};
use rayon::prelude::*;
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
    /// Shielding of packed rubble (count of contacts): a body with at least this many
    /// contacts centred below the water line at the last step feels no form drag, force or
    /// moment (its faces are against other blocks, not open water). Default 0: never
    /// shielded, every submerged block feels the drag of an isolated one.
    pub shielding_contacts: u32,
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
            shielding_contacts: 0,
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
    /// Which of them act on each body this step.
    applied: Vec<Applied>,
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
    /// velocities, and adds them to the body forces. `g` is gravity (m/s²). `shielded[i]`
    /// (when not empty) exempts body `i` from form drag ([`WaterParams::shielding_contacts`]).
    /// With a thread `pool` the bodies are computed in parallel; each body's forces are its
    /// own, so the result is the same to the bit on any number of threads.
    pub fn apply(
        &mut self,
        bodies: &mut Bodies,
        w: &WaterParams,
        g: f64,
        shielded: &[bool],
        pool: Option<&rayon::ThreadPool>,
    ) {
        let n = bodies.len();
        self.buoyancy.resize(n, (0.0, V2::default()));
        self.drag.resize(n, (V2::default(), V2::default(), 0.0));
        self.applied.resize(n, Applied::None);
        let b: &Bodies = bodies;
        let one = |i: usize, scratch: &mut ClipPoly| body_water(b, i, w, g, shielded, scratch);
        match pool {
            Some(pool) => pool.install(|| {
                self.buoyancy
                    .par_iter_mut()
                    .zip(self.drag.par_iter_mut())
                    .zip(self.applied.par_iter_mut())
                    .enumerate()
                    .for_each_init(ClipPoly::default, |scratch, (i, ((bu, dr), ap))| {
                        (*bu, *dr, *ap) = one(i, scratch);
                    })
            }),
            None => {
                for i in 0..n {
                    (self.buoyancy[i], self.drag[i], self.applied[i]) = one(i, &mut self.scratch);
                }
            }
        }
        for i in 0..n {
            let a = self.applied[i];
            if a == Applied::None {
                continue;
            }
            let (fb, c) = self.buoyancy[i];
            bodies.apply(i, V2::new(0.0, fb), c);
            if a == Applied::BuoyancyAndDrag {
                let (f, p, m) = self.drag[i];
                bodies.apply(i, f, p);
                bodies.torque[i] += m;
            }
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
            if self.applied[i] == Applied::None {
                continue;
            }
            let (fb, c) = self.buoyancy[i];
            let v = vbar[i] + (c - bodies.pos[i]).perp() * wbar[i];
            work.buoyancy -= fb * v.y * dt;
            let (f, p, m) = self.drag[i];
            let vd = vbar[i] + (p - bodies.pos[i]).perp() * wbar[i];
            work.drag -= (f.dot(vd) + m * wbar[i]) * dt;
        }
    }
}

/// Which water forces act on a body this step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Applied {
    /// None: above the water, held, or without a submerged area.
    #[default]
    None,
    /// Buoyancy alone (no drag on it: drag off, the sheet or floe under the default, or
    /// shielded).
    Buoyancy,
    /// Buoyancy and drag.
    BuoyancyAndDrag,
}

/// The water forces on body `i` of `b` ([`WaterForces::apply`]): buoyancy (N/m) at the
/// submerged centroid (m), drag force (N/m), its point (m) and moment (N·m/m), and which of
/// them act. `scratch` holds the submerged part of a body the water line cuts.
fn body_water(
    b: &Bodies,
    i: usize,
    w: &WaterParams,
    g: f64,
    shielded: &[bool],
    scratch: &mut ClipPoly,
) -> ((f64, V2), (V2, V2, f64), Applied) {
    let none = (
        (0.0, V2::default()),
        (V2::default(), V2::default(), 0.0),
        Applied::None,
    );
    let aabb = b.aabb[i];
    // Held bodies are external agents: no water forces on them.
    if aabb.min.y >= w.level || b.drive[i].is_kinematic() {
        return none;
    }
    let partly = aabb.max.y > w.level;
    let (area, c) = if partly {
        clip_below_into(&b.world[i], w.level, scratch);
        scratch.area_centroid()
    } else {
        area_centroid(b.world[i].verts())
    };
    if area <= 0.0 {
        return none;
    }
    let fb = w.density * g * area;
    let buoyancy = (fb, c);
    // The sheet and the floe feel the water's damping through their own boundary forces
    // (eqs 7–8; the floe's dashpots): by default drag acts on free blocks and rubble only.
    let drag_on = w.drag_coefficient > 0.0 || w.linear_drag > 0.0;
    let boundary_body = w.drag_bodies.is_rubble() && matches!(b.role[i], Role::Sheet | Role::Floe);
    let packed = shielded.get(i).copied().unwrap_or(false);
    if !drag_on || boundary_body || packed {
        return (buoyancy, none.1, Applied::Buoyancy);
    }
    let verts = if partly {
        scratch.verts()
    } else {
        b.world[i].verts()
    };
    let vs = b.point_velocity(i, c);
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
    let om = b.omega[i];
    let mut m = 0.0;
    if om != 0.0 && w.drag_coefficient > 0.0 {
        let lever = spin_drag_lever(verts, b.pos[i], w.level, om > 0.0);
        m = -0.5 * w.density * w.drag_coefficient * lever * om.abs() * om;
    }
    (buoyancy, (f, c, m), Applied::BuoyancyAndDrag)
}

/// Which of the `n` bodies are shielded from form drag ([`WaterParams::shielding_contacts`]):
/// those with at least that many of `contacts` (the last step's) centred below the water
/// line. Left empty when shielding is off.
pub(crate) fn shielded_bodies(
    contacts: &[Contact],
    n: usize,
    w: &WaterParams,
    out: &mut Vec<bool>,
) {
    out.clear();
    if w.shielding_contacts == 0 {
        return;
    }
    let mut count = vec![0u32; n];
    for c in contacts.iter().filter(|c| c.point.y < w.level) {
        let (a, b) = unpack(c.key);
        count[a as usize] += 1;
        count[b as usize] += 1;
    }
    out.extend(count.into_iter().map(|k| k >= w.shielding_contacts));
}

/// The lever J (m⁴) of the spin drag moment M = −½·ρ_w·C_d·|ω|·ω·J on the wetted outline
/// `verts` (a convex, counter-clockwise polygon, m) of a body turning about `centre` (m),
/// for a positive spin when `positive` (else a negative one): J = ∫ max(±q, 0)³ ds over its
/// edges, q = (p − centre) × n the lever of the outward normal n at p. Along an edge q falls
/// at unit rate (dq/ds = −1), so each edge gives (max(±q_a, 0)⁴ − max(±q_b, 0)⁴)/4 from its
/// ends a and b. Edges on the water line `level` (m) are the surface, not a face, and are
/// left out. It depends on the outline alone, not on how the body is turned.
pub(crate) fn spin_drag_lever(verts: &[V2], centre: V2, level: f64, positive: bool) -> f64 {
    let n = verts.len();
    let sign = if positive { 1.0 } else { -1.0 };
    let on_surface = |p: V2| (p.y - level).abs() <= 1e-9;
    let mut j = 0.0;
    for k in 0..n {
        let (a, b) = (verts[k], verts[(k + 1) % n]);
        if on_surface(a) && on_surface(b) {
            continue;
        }
        let e = b - a;
        let len = e.norm();
        if len == 0.0 {
            continue;
        }
        let normal = V2::new(e.y / len, -e.x / len);
        let qa = sign * (a - centre).cross(normal);
        let qb = sign * (b - centre).cross(normal);
        j += (qa.max(0.0).powi(4) - qb.max(0.0).powi(4)).abs() * 0.25;
    }
    j
}

#[cfg(test)]
mod tests {
    use super::*;

    /// J of a thin plate of length D is D⁴/32 (strip theory: the moment ρ_w·C_d·D⁴/64·ω²);
    /// of a rectangle turned by any angle (a⁴ + b⁴)/32; a face on the water line adds
    /// nothing, so the half below the line of a rectangle whose centroid lies on it has the
    /// lever of its three wetted faces.
    #[test]
    fn spin_drag_lever_of_plates_rectangles_and_cut_outlines() {
        let rect = |a: f64, b: f64, th: f64| {
            let (s, c) = th.sin_cos();
            [(-a, -b), (a, -b), (a, b), (-a, b)]
                .map(|(x, y)| V2::new(0.5 * x, 0.5 * y).rotate(c, s))
        };
        let plate = spin_drag_lever(&rect(2.0, 1e-9, 0.0), V2::default(), -10.0, true);
        assert!((plate - 16.0 / 32.0).abs() < 1e-9, "{plate}");
        for th in [0.0, 0.3, 0.8, 2.0] {
            let j = spin_drag_lever(&rect(1.0, 0.3, th), V2::default(), -10.0, th > 1.0);
            assert!(
                (j - (1.0 + 0.3f64.powi(4)) / 32.0).abs() < 1e-12,
                "{th}: {j}"
            );
        }
        // The lower half of a 1 × 0.3 rectangle, cut at its centroid's level y = 0, spun
        // anticlockwise: the bottom face drives water ahead of its right half (0.5⁴/4), the
        // wetted right face ahead of itself (0.15⁴/4), the left face not, the cut face is
        // the surface.
        let half = [
            V2::new(-0.5, -0.15),
            V2::new(0.5, -0.15),
            V2::new(0.5, 0.0),
            V2::new(-0.5, 0.0),
        ];
        let j = spin_drag_lever(&half, V2::default(), 0.0, true);
        let want = 0.5f64.powi(4) / 4.0 + 0.15f64.powi(4) / 4.0;
        assert!((j - want).abs() < 1e-12, "{j} against {want}");
    }
}
