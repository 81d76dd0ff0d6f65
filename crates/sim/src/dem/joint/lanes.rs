//! Eq (1) for [`L`] joints at a time: the joint law of [`super::apply_all`], written once, over
//! lanes of structure-of-arrays data ([`F4`]), so that the compiler evaluates the lanes with
//! SIMD (AVX2 where the CPU has it, chosen at run time). Each lane performs exactly the
//! operations of one joint in the same order, with no fused multiply-add (Rust never
//! contracts), so the results are the same bits whatever the instruction set (checked by
//! the `dem::joint` tests and by the 40-s default run's bit-for-bit comparison).

use super::{Joint, JointForces, frame_of, modulus_at};
use crate::dem::body::Bodies;
use crate::dem::lanes::{F4, Vec2};

/// Joints per group.
pub(crate) const L: usize = 4;

/// Inputs and results of one group of joints, one lane per joint.
#[derive(Clone, Copy, Default)]
pub(crate) struct JointLanes {
    // The two blocks: axes (cos θ, sin θ), centroids (m), half-step velocities (m/s, rad/s).
    ea: Vec2<F4>,
    eb: Vec2<F4>,
    xa: Vec2<F4>,
    xb: Vec2<F4>,
    va: Vec2<F4>,
    vb: Vec2<F4>,
    wa: F4,
    wb: F4,
    // The joint: face centres in the blocks' frames (m), gauge W (m), face height h (m),
    // moduli at the surfaces (Pa), intact span (m), Gauss points [s, w, E, G, η_E, η_G].
    pa: Vec2<F4>,
    pb: Vec2<F4>,
    gauge: F4,
    h: F4,
    e_top: F4,
    e_bottom: F4,
    s_lo: F4,
    s_hi: F4,
    gauss: [[F4; 6]; 3],
    // Results: elastic stresses at the ends of the span (Pa), elastic and viscous forces.
    top: F4,
    bottom: F4,
    el: Forces<F4>,
    vi: Forces<F4>,
}

/// [`JointForces`] of any [`Real`](crate::dem::lanes::Real).
#[derive(Clone, Copy, Default)]
struct Forces<F> {
    fa: Vec2<F>,
    ma: F,
    fb: Vec2<F>,
    mb: F,
}

impl Forces<F4> {
    #[inline(always)]
    fn lane(&self, l: usize) -> JointForces {
        JointForces {
            fa: self.fa.lane(l),
            ma: self.ma.0[l],
            fb: self.fb.lane(l),
            mb: self.mb.0[l],
        }
    }
}

impl JointLanes {
    /// Puts joint `j` (intact, its Gauss points current) and its bodies into lane `l`.
    #[inline(always)]
    pub(crate) fn load(&mut self, l: usize, j: &Joint, b: &Bodies) {
        let (ia, ib) = (j.a as usize, j.b as usize);
        self.ea.set_lane(l, b.axis[ia]);
        self.eb.set_lane(l, b.axis[ib]);
        self.xa.set_lane(l, b.pos[ia]);
        self.xb.set_lane(l, b.pos[ib]);
        self.va.set_lane(l, b.vel[ia]);
        self.vb.set_lane(l, b.vel[ib]);
        self.wa.0[l] = b.omega[ia];
        self.wb.0[l] = b.omega[ib];
        self.pa.set_lane(l, j.pa);
        self.pb.set_lane(l, j.pb);
        self.gauge.0[l] = j.gauge;
        self.h.0[l] = j.h;
        self.e_top.0[l] = j.mat.e_top;
        self.e_bottom.0[l] = j.mat.e_bottom;
        self.s_lo.0[l] = j.s_lo;
        self.s_hi.0[l] = j.s_hi;
        for (k, p) in j.gauss.point.iter().enumerate() {
            for (q, &v) in p.iter().enumerate() {
                self.gauss[k][q].0[l] = v;
            }
        }
    }

    /// Calls `f` on every input.
    fn for_each_input(&mut self, mut f: impl FnMut(&mut F4)) {
        for v in [
            &mut self.ea,
            &mut self.eb,
            &mut self.xa,
            &mut self.xb,
            &mut self.va,
            &mut self.vb,
            &mut self.pa,
            &mut self.pb,
        ] {
            f(&mut v.x);
            f(&mut v.y);
        }
        for a in [
            &mut self.wa,
            &mut self.wb,
            &mut self.gauge,
            &mut self.h,
            &mut self.e_top,
            &mut self.e_bottom,
            &mut self.s_lo,
            &mut self.s_hi,
        ] {
            f(a);
        }
        self.gauss.iter_mut().flatten().for_each(f);
    }

    /// Fills lanes `from..L` with copies of lane 0 (their results are not used).
    pub(crate) fn pad(&mut self, from: usize) {
        self.for_each_input(|a| {
            for l in from..L {
                a.0[l] = a.0[0];
            }
        });
    }

    /// Lane `l`'s results: elastic surface stresses (top, bottom) (Pa) and the elastic and
    /// viscous forces.
    #[inline(always)]
    pub(crate) fn result(&self, l: usize) -> ((f64, f64), JointForces, JointForces) {
        (
            (self.top.0[l], self.bottom.0[l]),
            self.el.lane(l),
            self.vi.lane(l),
        )
    }

    /// Evaluates eq (1) in every lane, with the instruction set the CPU offers.
    pub(crate) fn evaluate(&mut self) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2 (checked just above).
                unsafe { self.evaluate_avx2() };
                return;
            }
        }
        self.law();
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn evaluate_avx2(&mut self) {
        self.law();
    }

    /// The joint law, eq (1), integrated over the intact span by 3-point Gauss: the fibre
    /// δ(s) between the two face points, its rate, the elastic and viscous stresses, and
    /// their resultants on each block (docs/model.md, "Joints").
    #[inline(always)]
    fn law(&mut self) {
        let (xa, xb, va, vb, wa, wb) = (self.xa, self.xb, self.va, self.vb, self.wa, self.wb);
        let gauge = self.gauge;
        let [n, t, ua, ub, oa, ob] = frame_of(self.pa, self.pb, xa, xb, self.ea, self.eb);
        let d0 = ob - oa;
        let d1 = ub - ua;
        let sig =
            |s: F4| modulus_at(self.e_top, self.e_bottom, self.h, s) * (d0 + d1 * s).dot(n) / gauge;
        self.top = sig(self.s_hi);
        self.bottom = sig(self.s_lo);
        let mut el = Forces::<F4>::default();
        let mut vi = Forces::<F4>::default();
        for &[s, w, e, g, eta_e, eta_g] in &self.gauss {
            let pa = oa + ua * s;
            let pb = ob + ub * s;
            let d = d0 + d1 * s;
            let ddot = (vb + (pb - xb).perp() * wb) - (va + (pa - xa).perp() * wa);
            // Stresses (Pa) times the Gauss weight (m): force per metre of depth.
            let sig_e = e * d.dot(n) / gauge;
            let tau_e = g * d.dot(t) / gauge;
            let sig_v = eta_e * ddot.dot(n);
            let tau_v = eta_g * ddot.dot(t);
            // Tension (δ_n > 0) pulls b back towards a.
            let fe = (n * sig_e + t * tau_e) * (-w);
            let fv = (n * sig_v + t * tau_v) * (-w);
            el.fb = el.fb + fe;
            el.mb += (pb - xb).cross(fe);
            el.fa = el.fa - fe;
            el.ma -= (pa - xa).cross(fe);
            vi.fb = vi.fb + fv;
            vi.mb += (pb - xb).cross(fv);
            vi.fa = vi.fa - fv;
            vi.ma -= (pa - xa).cross(fv);
        }
        self.el = el;
        self.vi = vi;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Four joints in different poses and states, with made-up but finite values.
    fn group() -> JointLanes {
        let mut x = JointLanes::default();
        let mut r = 0.123_456_789_f64;
        let mut next = || {
            r = (r * 9.87 + 0.314).fract();
            r - 0.5
        };
        for l in 0..L {
            let (ta, tb) = (0.3 * next(), 0.3 * next());
            x.ea.set_lane(l, crate::dem::V2::new(ta.cos(), ta.sin()));
            x.eb.set_lane(l, crate::dem::V2::new(tb.cos(), tb.sin()));
            for v in [&mut x.xa, &mut x.xb, &mut x.va, &mut x.vb] {
                v.set_lane(l, crate::dem::V2::new(next(), next()));
            }
            x.xb.x.0[l] += 0.3;
            x.wa.0[l] = next();
            x.wb.0[l] = next();
            x.pa.set_lane(l, crate::dem::V2::new(0.15, 0.01 * next()));
            x.pb.set_lane(l, crate::dem::V2::new(-0.15, 0.01 * next()));
            x.gauge.0[l] = 0.3;
            x.h.0[l] = 0.3;
            x.e_top.0[l] = 3e9 * (1.0 + 0.1 * next());
            x.e_bottom.0[l] = 2e9;
            x.s_lo.0[l] = -0.09;
            x.s_hi.0[l] = 0.15 - 0.05 * next().abs();
            for (k, xk) in [-0.7, 0.0, 0.7].into_iter().enumerate() {
                for q in 0..6 {
                    x.gauss[k][q].0[l] = if q == 0 {
                        0.1 * xk
                    } else {
                        1e3 * (1.5 + next())
                    };
                }
            }
        }
        x
    }

    fn bits(x: &JointLanes, l: usize) -> Vec<u64> {
        let ((top, bottom), el, vi) = x.result(l);
        let mut v = vec![top.to_bits(), bottom.to_bits()];
        for f in [el, vi] {
            v.extend([f.fa.x, f.fa.y, f.ma, f.fb.x, f.fb.y, f.mb].map(f64::to_bits));
        }
        v
    }

    #[test]
    fn every_instruction_set_and_lane_gives_the_same_bits() {
        let mut portable = group();
        portable.law();
        let mut dispatched = group();
        dispatched.evaluate();
        for l in 0..L {
            assert_eq!(bits(&portable, l), bits(&dispatched, l), "lane {l}");
            // The same joint alone in lane 0, the others padded with copies of it.
            let mut alone = group();
            alone.for_each_input(|a| a.0[0] = a.0[l]);
            alone.pad(1);
            alone.evaluate();
            assert_eq!(bits(&alone, 0), bits(&dispatched, l), "lane {l} alone");
        }
        assert!(portable.top.0.iter().all(|s| s.is_finite() && *s != 0.0));
    }
}
