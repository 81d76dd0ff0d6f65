//! Viscous-elastic joints between the component blocks of the sheet, the floe and every
//! rubble piece, Hopkins (1994) eq (1) and Figure 2.
//!
//! Two blocks a (left) and b (right) meet at a face of height h. A point at height s on the
//! face (s from −h/2 at the bottom to +h/2 at the top, in the blocks' own frames) is
//! stretched by the fibre δ(s) = P_b(s) − P_a(s), the vector from the material point on a to
//! the point on b that coincided with it in the undeformed state. In the joint frame (n along
//! the mean axis of the two blocks, t = n⊥) the stresses are
//!
//! - normal σ(s) = E(s)·δ_n(s)/W + η(s)·δ̇_n(s), eq (1), with E linear from E_bottom at
//!   s = −h/2 to E_top at s = +h/2 and η = f·2·sqrt(ρ_i·E(s)) (f = 0.1);
//! - shear τ(s) = G(s)·δ_t(s)/W + η_G(s)·δ̇_t(s) with G = E/(2(1 + ν)) (k_te = G/W) and
//!   η_G = f·2·sqrt(ρ_i·G(s)),
//!
//! integrated over the intact span [s_lo, s_hi]: the skeletal layer (the bottom 20 % of h,
//! at most 6 cm) carries nothing, and cracks eat into the span from the top and the bottom
//! (`dem::fracture`, docs/model.md "Fracture"). W is the distance between the two block
//! centres (the width of a block for equal blocks). The fibre force acts on each block at
//! its own face point, so the work it absorbs is exactly ∫(σ·δ̇_n + τ·δ̇_t) ds in the limit
//! of small rotations.

use super::body::{Bodies, BodyId};
use super::geometry::V2;
use super::lanes::{Real, Vec2};
use super::numerics::Dashpot;
use lanes::JointLanes;
use serde::{Deserialize, Serialize};

mod lanes;

/// Gauss–Legendre nodes and weights on [−1, 1], 3 points (exact to degree 5).
const GAUSS_X: [f64; 3] = [-0.774_596_669_241_483_4, 0.0, 0.774_596_669_241_483_4];
const GAUSS_W: [f64; 3] = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];

/// Material of a joint.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct JointMaterial {
    /// Young's modulus at the top surface (Pa).
    pub e_top: f64,
    /// Young's modulus at the bottom surface (Pa).
    pub e_bottom: f64,
    /// Poisson's ratio ν (dimensionless).
    pub poisson: f64,
    /// Fraction of the critical damping 2·sqrt(ρ_i·E) used for η (dimensionless).
    pub damping_fraction: f64,
    /// Tensile strength at the top surface (Pa).
    pub strength_top: f64,
    /// Tensile strength at the bottom surface (Pa).
    pub strength_bottom: f64,
}

/// A joint between the right face of body `a` and the left face of body `b`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Joint {
    /// Left body.
    pub a: BodyId,
    /// Right body.
    pub b: BodyId,
    /// Centre of the joint face in a's frame, relative to a's centroid (m).
    pub pa: V2,
    /// Centre of the joint face in b's frame, relative to b's centroid (m).
    pub pb: V2,
    /// Face height h (m).
    pub h: f64,
    /// Gauge length W (m): the distance between the block centres at rest.
    pub(crate) gauge: f64,
    /// Material.
    pub(crate) mat: JointMaterial,
    /// Bottom of the intact span (m, face coordinate).
    pub(crate) s_lo: f64,
    /// Top of the intact span (m, face coordinate).
    pub(crate) s_hi: f64,
    /// A crack is running down from the top.
    pub(crate) crack_top: bool,
    /// A crack is running up from the bottom.
    pub(crate) crack_bottom: bool,
    /// Time at which the first crack started (s), or negative.
    pub crack_started: f64,
    /// Elastic work absorbed by the joint so far (J/m).
    pub(crate) elastic_work: f64,
    /// Forces of the current step for the ledger: elastic (on a, moment on a, on b, moment
    /// on b) and viscous.
    #[serde(skip)]
    pub(crate) forces: [JointForces; 2],
    /// Elastic stresses at the ends of the intact span at the last step (Pa),
    /// the input of the fracture test.
    #[serde(skip)]
    pub stress: SurfaceStress,
    /// The elastic surface stresses filtered over the incubation time, when the fracture
    /// test uses one ([`crate::dem::WorldParams::incubation_time`]), or the last pose's
    /// stresses for the two-pose mean ([`crate::dem::WorldParams::fracture_step_mean`]);
    /// kept in the state so that a resumed run continues exactly.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) stress_filtered: Option<SurfaceStress>,
    /// The Gauss points of the intact span and their moduli, kept between steps (they
    /// change only when a crack moves an end of the span).
    #[serde(skip)]
    gauss: GaussCache,
}

/// Per Gauss point of the intact span [`GaussCache::span`]: face coordinate s (m), weight
/// (m), E(s) and G(s) (Pa), and the viscosities f·2·sqrt(ρ_i·E) and f·2·sqrt(ρ_i·G)
/// (Pa·s/m) for the density `rho` (kg/m³).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct GaussCache {
    span: (f64, f64),
    rho: f64,
    point: [[f64; 6]; 3],
}

/// The resultant of a joint's stresses on its two blocks (N/m and N·m/m about each
/// centroid).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct JointForces {
    /// Force on a.
    pub(crate) fa: V2,
    /// Moment on a.
    pub(crate) ma: f64,
    /// Force on b.
    pub(crate) fb: V2,
    /// Moment on b.
    pub(crate) mb: f64,
}

/// Elastic stresses at the two ends of the intact span, for the fracture test (Pa, tension
/// positive).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SurfaceStress {
    /// Normal stress at the top of the intact span (Pa).
    pub top: f64,
    /// Normal stress at the bottom of the intact span (Pa).
    pub bottom: f64,
}

/// Where a joint sits and how deep it is: the shape of eq (1)'s glued faces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct JointGeometry {
    /// Centre of the right face of body a, in a's frame (m).
    pub(crate) pa: V2,
    /// Centre of the left face of body b, in b's frame (m).
    pub(crate) pb: V2,
    /// Face height (m): the thinner block's thickness.
    pub(crate) h: f64,
    /// Skeletal layer at the bottom of the face, without joint (m).
    pub(crate) skeletal: f64,
    /// Gauge length (m): the spring's length, half of each block.
    pub(crate) gauge: f64,
}

impl Joint {
    /// A joint at rest between the right face of `a` and the left face of `b`, shaped as
    /// `geom` says.
    pub(crate) fn new(a: BodyId, b: BodyId, geom: JointGeometry, mat: JointMaterial) -> Joint {
        let JointGeometry {
            pa,
            pb,
            h,
            skeletal,
            gauge,
        } = geom;
        Joint {
            a,
            b,
            pa,
            pb,
            h,
            gauge,
            mat,
            s_lo: -0.5 * h + skeletal,
            s_hi: 0.5 * h,
            crack_top: false,
            crack_bottom: false,
            crack_started: -1.0,
            elastic_work: 0.0,
            forces: [JointForces::default(); 2],
            stress: SurfaceStress::default(),
            stress_filtered: None,
            gauss: GaussCache::default(),
        }
    }

    /// True while any part of the joint is intact.
    #[inline]
    pub fn is_intact(&self) -> bool {
        self.s_hi > self.s_lo
    }

    /// Young's modulus at face height s (Pa).
    #[inline]
    pub(crate) fn modulus(&self, s: f64) -> f64 {
        modulus_at(self.mat.e_top, self.mat.e_bottom, self.h, s)
    }

    /// Largest eigenvalues of the joint's stiffness K and damping C, linearised about the
    /// present pose and scaled by the bodies' masses: λ = max eig(S·K·S) (1/s²) and
    /// μ = max eig(S·C·S) (1/s), S = diag(`scale_a`, `scale_b`) with each body's
    /// (1/√m, 1/√m, 1/√I) (zeros for a body that does not move). Over the degrees of freedom
    /// q = (xₐ, yₐ, θₐ, x_b, y_b, θ_b) the fibre at s stretches by g_n·q along n and g_t·q
    /// along t, with g = (−e, −rₐ×e, e, r_b×e) and r the arm from each centroid; K and C
    /// integrate E/W·g_n g_nᵀ + G/W·g_t g_tᵀ and the matching η terms of eq (1) over the
    /// intact span (3-point Gauss, exact: the integrand is cubic in s). The input of the
    /// joint limit of [`crate::dem::World::stable_time_step`].
    pub(crate) fn modal_bounds(
        &self,
        b: &Bodies,
        rho_i: f64,
        scale_a: [f64; 3],
        scale_b: [f64; 3],
    ) -> (f64, f64) {
        if !self.is_intact() {
            return (0.0, 0.0);
        }
        let (n, t, ua, ub, oa, ob) = self.frame(b);
        let (xa, xb) = (b.pos[self.a as usize], b.pos[self.b as usize]);
        let sc = [
            scale_a[0], scale_a[1], scale_a[2], scale_b[0], scale_b[1], scale_b[2],
        ];
        let mut k = faer::Mat::<f64>::zeros(6, 6);
        let mut c = faer::Mat::<f64>::zeros(6, 6);
        for &[s, w, e, g, eta_e, eta_g] in &self.gauss_points(rho_i).point {
            let (ra, rb) = (oa + ua * s - xa, ob + ub * s - xb);
            for (dir, stiff, damp) in [(n, e / self.gauge, eta_e), (t, g / self.gauge, eta_g)] {
                let v = [-dir.x, -dir.y, -ra.cross(dir), dir.x, dir.y, rb.cross(dir)];
                for r in 0..6 {
                    for col in 0..6 {
                        let vv = sc[r] * v[r] * v[col] * sc[col] * w;
                        k[(r, col)] += stiff * vv;
                        c[(r, col)] += damp * vv;
                    }
                }
            }
        }
        let top = |m: &faer::Mat<f64>| {
            m.self_adjoint_eigenvalues(faer::Side::Lower)
                .ok()
                .and_then(|ev| ev.last().copied())
                .unwrap_or(f64::INFINITY)
        };
        (top(&k), top(&c))
    }

    /// Frame of the joint and the fibre geometry ([`frame_of`]) for block axes `ea`, `eb`
    /// ((cos θ, sin θ) of each block).
    #[inline]
    fn frame_with(&self, b: &Bodies, ea: V2, eb: V2) -> (V2, V2, V2, V2, V2, V2) {
        let (xa, xb) = (b.pos[self.a as usize], b.pos[self.b as usize]);
        let v = Vec2::<f64>::from;
        let [n, t, ua, ub, oa, ob] = frame_of(v(self.pa), v(self.pb), v(xa), v(xb), v(ea), v(eb));
        (
            n.into(),
            t.into(),
            ua.into(),
            ub.into(),
            oa.into(),
            ob.into(),
        )
    }

    /// [`Joint::frame_with`] from the bodies' present orientations.
    fn frame(&self, b: &Bodies) -> (V2, V2, V2, V2, V2, V2) {
        let (sa, ca) = b.theta[self.a as usize].sin_cos();
        let (sb, cb) = b.theta[self.b as usize].sin_cos();
        self.frame_with(b, V2::new(ca, sa), V2::new(cb, sb))
    }

    /// Elastic energy held by the intact span (J/m): ∫(E·δ_n² + G·δ_t²)/(2W) ds.
    pub fn stored_energy(&self, b: &Bodies) -> f64 {
        if !self.is_intact() {
            return 0.0;
        }
        let (n, t, ua, ub, oa, ob) = self.frame(b);
        let d0 = ob - oa;
        let d1 = ub - ua;
        let g_ratio = 1.0 / (2.0 * (1.0 + self.mat.poisson));
        let mut e = 0.0;
        for &[s, w, em, ..] in &self.gauss_points(0.0).point {
            let d = d0 + d1 * s;
            let (dn, dt) = (d.dot(n), d.dot(t));
            e += w * em * (dn * dn + g_ratio * dt * dt) / (2.0 * self.gauge);
        }
        e
    }

    /// The Gauss points of the present intact span for ice density `rho_i` (kg/m³).
    fn gauss_points(&self, rho_i: f64) -> GaussCache {
        let half = 0.5 * (self.s_hi - self.s_lo);
        let mid = 0.5 * (self.s_hi + self.s_lo);
        let g_ratio = 1.0 / (2.0 * (1.0 + self.mat.poisson));
        let f2 = self.mat.damping_fraction * 2.0;
        let mut point = [[0.0; 6]; 3];
        for k in 0..3 {
            let s = mid + half * GAUSS_X[k];
            let e = self.modulus(s);
            let g = e * g_ratio;
            point[k] = [
                s,
                GAUSS_W[k] * half,
                e,
                g,
                f2 * (rho_i * e).sqrt(),
                f2 * (rho_i * g).sqrt(),
            ];
        }
        GaussCache {
            span: (self.s_lo, self.s_hi),
            rho: rho_i,
            point,
        }
    }

    /// Computes the joint's forces from the current poses (with the block axes cached in
    /// `bodies.axis`) and half-step velocities, adds them to the bodies and keeps them for
    /// the ledger, with the elastic surface stresses for the fracture test. (One joint of
    /// [`apply_all`], which evaluates them four at a time.)
    #[cfg(test)]
    pub(crate) fn apply(&mut self, bodies: &mut Bodies, rho_i: f64, dashpot: Dashpot) {
        apply_all(std::slice::from_mut(self), bodies, rho_i, dashpot, None);
    }

    /// Readies an intact joint for [`JointLanes::load`]: the Gauss points of its present
    /// span for ice density `rho_i` (kg/m³).
    #[inline]
    fn prepare(&mut self, rho_i: f64) {
        if self.gauss.span != (self.s_lo, self.s_hi) || self.gauss.rho != rho_i {
            self.gauss = self.gauss_points(rho_i);
        }
    }

    /// Takes lane `l`'s results: keeps the stresses and the forces (the viscous ones zero for
    /// the implicit dashpot: they follow in [`Joint::apply_viscous`]), for
    /// [`Joint::add_forces`].
    #[inline]
    fn finish(&mut self, x: &JointLanes, l: usize, dashpot: Dashpot) {
        let ((top, bottom), el, mut vi) = x.result(l);
        self.stress = SurfaceStress { top, bottom };
        if dashpot == Dashpot::Implicit {
            // The viscous stress follows once every other force is known (`apply_viscous`).
            vi = JointForces::default();
        }
        self.forces = [el, vi];
    }

    /// Adds the forces kept by [`Joint::finish`] to the bodies: the elastic, then the
    /// viscous, each on `a` then `b`.
    #[inline]
    fn add_forces(&self, bodies: &mut Bodies) {
        let (ia, ib) = (self.a as usize, self.b as usize);
        for f in &self.forces {
            bodies.force[ia] = bodies.force[ia] + f.fa;
            bodies.torque[ia] += f.ma;
            bodies.force[ib] = bodies.force[ib] + f.fb;
            bodies.torque[ib] += f.mb;
        }
    }

    /// The viscous stress of eq (1) at the mid-step velocities ([`Dashpot::Implicit`] for
    /// joints), added to the bodies after every other force of the step.
    ///
    /// The relative velocity of the two faces is affine along the face, δ̇(s) = A + B·s
    /// (A at s = 0, B = ω_b·u_b⊥ − ω_a·u_a⊥), so the dashpot acts on the four rates
    /// u = (A·n, A·t, B·n, B·t) with the generalised force Q = −D·ū, D the Gauss sums of
    /// w·η·(1, s, s²) for the normal and the tangential pair. With J the map from the two
    /// bodies' velocities to u, K = J·M⁻¹·Jᵀ and a_u the rates' acceleration under every
    /// other force, the leapfrog's mid-step rates are ū = u⁻ + ½·Δt·(a_u + K·Q):
    /// (I + ½·Δt·K·D)·ū = u⁻ + ½·Δt·a_u, solved per joint (other joints' and contacts'
    /// viscous forces are taken as they stand, as the contacts' implicit dashpot does).
    /// As Δt → 0 this is the explicit dashpot; a single joint is stable at any damping.
    pub(crate) fn apply_viscous(&mut self, bodies: &mut Bodies, dt: f64) {
        if !self.is_intact() {
            return;
        }
        let (ia, ib) = (self.a as usize, self.b as usize);
        let (n, t, ua, ub, oa, ob) = self.frame_with(bodies, bodies.axis[ia], bodies.axis[ib]);
        let (ra, rb) = (oa - bodies.pos[ia], ob - bodies.pos[ib]);
        // Rows of J over (v_a, ω_a, v_b, ω_b), in the order of u.
        let row = |e: V2, along: bool| -> [f64; 6] {
            if along {
                [0.0, 0.0, -ua.cross(e), 0.0, 0.0, ub.cross(e)]
            } else {
                [-e.x, -e.y, -ra.cross(e), e.x, e.y, rb.cross(e)]
            }
        };
        let j = [row(n, false), row(t, false), row(n, true), row(t, true)];
        let minv = {
            let [ax, ay, aw] = bodies.inverse_masses(ia);
            let [bx, by, bw] = bodies.inverse_masses(ib);
            [ax, ay, aw, bx, by, bw]
        };
        let v = [
            bodies.vel[ia].x,
            bodies.vel[ia].y,
            bodies.omega[ia],
            bodies.vel[ib].x,
            bodies.vel[ib].y,
            bodies.omega[ib],
        ];
        let acc = {
            let [ax, ay, aw] = bodies.acceleration(ia);
            let [bx, by, bw] = bodies.acceleration(ib);
            [ax, ay, aw, bx, by, bw]
        };
        let dot6 = |r: &[f64; 6], x: &[f64; 6]| (0..6).map(|k| r[k] * x[k]).sum::<f64>();
        // D over u: normal pair (0, 2), tangential pair (1, 3).
        let mut d = [[0.0; 4]; 4];
        for &[s, w, _, _, eta_e, eta_g] in &self.gauss.point {
            for (p, q, eta) in [(0, 2, eta_e), (1, 3, eta_g)] {
                d[p][p] += w * eta;
                d[p][q] += w * eta * s;
                d[q][p] += w * eta * s;
                d[q][q] += w * eta * s * s;
            }
        }
        let mut k = [[0.0; 4]; 4];
        for p in 0..4 {
            for q in 0..4 {
                k[p][q] = (0..6).map(|m| j[p][m] * minv[m] * j[q][m]).sum();
            }
        }
        let h = 0.5 * dt;
        let mut a = [[0.0; 4]; 4];
        let mut rhs = [0.0; 4];
        for p in 0..4 {
            rhs[p] = dot6(&j[p], &v) + h * dot6(&j[p], &acc);
            for q in 0..4 {
                a[p][q] = if p == q { 1.0 } else { 0.0 }
                    + h * (0..4).map(|m| k[p][m] * d[m][q]).sum::<f64>();
            }
        }
        let ubar = solve4(a, rhs);
        let qf: [f64; 4] = std::array::from_fn(|p| -(0..4).map(|m| d[p][m] * ubar[m]).sum::<f64>());
        let fb = n * qf[0] + t * qf[1];
        let mb =
            rb.cross(n) * qf[0] + rb.cross(t) * qf[1] + ub.cross(n) * qf[2] + ub.cross(t) * qf[3];
        let ma = -(ra.cross(n) * qf[0]
            + ra.cross(t) * qf[1]
            + ua.cross(n) * qf[2]
            + ua.cross(t) * qf[3]);
        let vi = JointForces {
            fa: -fb,
            ma,
            fb,
            mb,
        };
        bodies.force[ia] = bodies.force[ia] + vi.fa;
        bodies.torque[ia] += vi.ma;
        bodies.force[ib] = bodies.force[ib] + vi.fb;
        bodies.torque[ib] += vi.mb;
        self.forces[1] = vi;
    }

    /// Work absorbed by the joint in this step with mid-step velocities: (elastic, viscous)
    /// (J/m). The elastic part is also added to the joint's own running total.
    pub(crate) fn book_work(&mut self, vbar: &[V2], wbar: &[f64], dt: f64) -> (f64, f64) {
        let (ia, ib) = (self.a as usize, self.b as usize);
        let p = |f: &JointForces| {
            -(f.fa.dot(vbar[ia]) + f.ma * wbar[ia] + f.fb.dot(vbar[ib]) + f.mb * wbar[ib]) * dt
        };
        let e = p(&self.forces[0]);
        let v = p(&self.forces[1]);
        self.elastic_work += e;
        (e, v)
    }
}

/// Applies every intact joint of `joints` to the bodies, in order: the stresses and forces
/// of eq (1), kept in each joint for the fracture test and the ledger. The joint law is
/// evaluated [`lanes::L`] joints at a time (each lane on its own, so a joint's result does
/// not depend on its neighbours in the lanes), on the threads of `pool` when given, in
/// chunks; the forces are then added to the bodies joint by joint in the order of `joints`,
/// so that the sums are those of one joint after another on any number of threads.
pub(crate) fn apply_all(
    joints: &mut [Joint],
    bodies: &mut Bodies,
    rho_i: f64,
    dashpot: Dashpot,
    pool: Option<&rayon::ThreadPool>,
) {
    let b: &Bodies = bodies;
    match pool {
        Some(pool) => pool.install(|| {
            use rayon::prelude::*;
            joints
                .par_chunks_mut(JOINT_CHUNK)
                .for_each(|chunk| evaluate(chunk, b, rho_i, dashpot));
        }),
        None => evaluate(joints, b, rho_i, dashpot),
    }
    for j in joints.iter().filter(|j| j.is_intact()) {
        j.add_forces(bodies);
    }
}

/// Joints per chunk of a parallel evaluation ([`apply_all`]): a multiple of [`lanes::L`].
const JOINT_CHUNK: usize = 16 * lanes::L;

/// Evaluates the joint law of every intact joint of `joints`, [`lanes::L`] at a time, and
/// keeps the results in each joint ([`Joint::finish`]); the bodies are only read.
fn evaluate(joints: &mut [Joint], bodies: &Bodies, rho_i: f64, dashpot: Dashpot) {
    let mut x = JointLanes::default();
    let mut group = [0usize; lanes::L];
    let mut n = 0;
    let flush = |x: &mut JointLanes, group: &[usize], joints: &mut [Joint]| {
        x.pad(group.len());
        x.evaluate();
        for (l, &i) in group.iter().enumerate() {
            joints[i].finish(x, l, dashpot);
        }
    };
    for i in 0..joints.len() {
        let j = &mut joints[i];
        j.forces = [JointForces::default(); 2];
        if !j.is_intact() {
            continue;
        }
        j.prepare(rho_i);
        x.load(n, j, bodies);
        group[n] = i;
        n += 1;
        if n == lanes::L {
            flush(&mut x, &group, joints);
            n = 0;
        }
    }
    if n > 0 {
        flush(&mut x, &group[..n], joints);
    }
}

/// Frame of a joint and its fibre geometry, from the face centres `pa`, `pb` in the blocks'
/// frames (m), the centroids `xa`, `xb` (m) and the block axes `ea`, `eb` ((cos θ, sin θ)):
/// [n, t, face direction of a, face direction of b, face centre of a, face centre of b] in
/// world coordinates. n is the bisector of the two axes: the direction of the mean angle,
/// found without trigonometry.
#[inline(always)]
fn frame_of<F: Real>(
    pa: Vec2<F>,
    pb: Vec2<F>,
    xa: Vec2<F>,
    xb: Vec2<F>,
    ea: Vec2<F>,
    eb: Vec2<F>,
) -> [Vec2<F>; 6] {
    let m = ea + eb;
    let n = m * (F::splat(1.0) / m.norm());
    let t = n.perp();
    let oa = xa + pa.rotate(ea.x, ea.y);
    let ob = xb + pb.rotate(eb.x, eb.y);
    [n, t, ea.perp(), eb.perp(), oa, ob]
}

/// Young's modulus (Pa) at face height `s` (m) of a face of height `h` (m), linear from
/// `e_bottom` at s = −h/2 to `e_top` at s = +h/2 (Pa).
#[inline(always)]
fn modulus_at<F: Real>(e_top: F, e_bottom: F, h: F, s: F) -> F {
    let f = (s + F::splat(0.5) * h) / h;
    e_bottom + (e_top - e_bottom) * f
}

/// Solves the 4 × 4 system a·x = b by Gaussian elimination with partial pivoting. The joint
/// dashpot's matrix I + ½·Δt·K·D is never singular (K·D is similar to the positive
/// semi-definite D^½·K·D^½, so its eigenvalues are at least 1). Written here rather than
/// through faer, whose dense solvers allocate, for a system this small.
fn solve4(mut a: [[f64; 4]; 4], mut b: [f64; 4]) -> [f64; 4] {
    for c in 0..4 {
        let p = (c..4)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, p);
        b.swap(c, p);
        let pivot = a[c];
        for r in c + 1..4 {
            let f = a[r][c] / pivot[c];
            for (x, &y) in a[r][c..].iter_mut().zip(&pivot[c..]) {
                *x -= f * y;
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = [0.0; 4];
    for r in (0..4).rev() {
        let s: f64 = (r + 1..4).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

#[cfg(test)]
mod tests;
