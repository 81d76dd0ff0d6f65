//! Block kernel of the Rothrock strength: the same operations as
//! [`strength_column`](super::strength::strength_column), evaluated for `L` columns at a time
//! with selects instead of branches so that the compiler can use SIMD across columns. It gives
//! bit-identical results (checked by `tests/itd_strength.rs`); any block with a column that
//! needs the scalar path (bad input, empty column, masked column) is left to the scalar path.

// Several parallel per-category arrays are indexed by the category number, as in CICE.
#![allow(clippy::needless_range_loop)]

use std::cmp::Ordering;

use super::params::{ItdParams, Participation, Redistribution};
use super::participation::ExpCache;
use super::vexp::exp_in_place;

/// Columns per block.
pub(crate) const L: usize = 8;
/// Largest number of categories the block kernel handles.
pub(crate) const MAX_NCAT: usize = 16;

/// One block of `L` columns gathered from the batch arrays, and the kernel's scratch (kept
/// between blocks, so that it is not zeroed for each; the kernel writes every entry it
/// reads).
pub(crate) struct Block {
    pub a: [[f64; L]; MAX_NCAT],
    pub v: [[f64; L]; MAX_NCAT],
    pub a0: [f64; L],
    /// G(k) at index k + 1, k = −1..=ncat.
    g: [[f64; L]; MAX_NCAT + 2],
    /// a_Pn, n = 0..=ncat.
    ap: [[f64; L]; MAX_NCAT + 1],
    /// The exponentials of the participation.
    ex: [[f64; L]; MAX_NCAT + 1],
}

impl Block {
    pub(crate) fn new() -> Self {
        Self {
            a: [[0.0; L]; MAX_NCAT],
            v: [[0.0; L]; MAX_NCAT],
            a0: [0.0; L],
            g: [[0.0; L]; MAX_NCAT + 2],
            ap: [[0.0; L]; MAX_NCAT + 1],
            ex: [[0.0; L]; MAX_NCAT + 1],
        }
    }
}

/// What every block of a batched call is computed with.
#[derive(Clone, Copy)]
pub(crate) struct BlockCall<'a> {
    /// Number of categories (≤ [`MAX_NCAT`]).
    pub ncat: usize,
    /// Whether the block's `a0` holds aice0 (else it is 1 − Σ aicen).
    pub aice0_given: bool,
    pub part: Participation,
    pub redist: Redistribution,
    pub p: &'a ItdParams,
    /// C_f (dimensionless).
    pub cf: f64,
    /// The exponential participation's constants for `p.astar`.
    pub e: &'a ExpCache,
}

/// Strength of a block; `None` when any column needs the scalar path.
/// `T`: Thorndike participation (else exponential); `U`: uniform redistribution (else
/// exponential). Monomorphised so that each option pair is a straight-line loop.
#[inline(always)]
fn kernel<const T: bool, const U: bool>(b: &mut Block, call: &BlockCall) -> Option<[f64; L]> {
    let BlockCall {
        ncat,
        aice0_given,
        p,
        cf,
        e,
        ..
    } = *call;
    let puny = p.puny;
    let thick_max = crate::limits::CATEGORY_THICKNESS.max;
    // Validation (the scalar path reports the errors).
    let mut ok = [true; L];
    let mut sum = [0.0; L];
    for n in 0..ncat {
        for l in 0..L {
            let (a, v) = (b.a[n][l], b.v[n][l]);
            ok[l] &= a.is_finite() & (a >= 0.0) & v.is_finite() & (v >= 0.0) & (v <= thick_max);
            ok[l] &= (a <= puny) | (v / a <= thick_max);
            sum[l] += a;
        }
    }
    let mut a0 = [0.0; L];
    for l in 0..L {
        if aice0_given {
            let x = b.a0[l];
            let total = x + sum[l];
            ok[l] &= x.is_finite() & (x > 0.0 || sum[l] != 0.0) & (x >= 0.0);
            ok[l] &= (total - 1.0).abs() <= p.area_tolerance;
            a0[l] = x;
        } else {
            ok[l] &= sum[l] <= 1.0 + p.area_tolerance;
            a0[l] = f64::max(1.0 - sum[l], 0.0);
        }
    }
    if !ok.iter().all(|&x| x) {
        return None;
    }

    let Block { g, ap, ex, .. } = b;
    // Cumulative areas G(k), k = -1..=ncat, at index k + 1.
    g[0] = [0.0; L];
    for l in 0..L {
        g[1][l] = if a0[l] > puny { a0[l] } else { 0.0 };
    }
    for n in 1..=ncat {
        for l in 0..L {
            let a = b.a[n - 1][l];
            g[n + 1][l] = if a > puny { g[n][l] + a } else { g[n][l] };
        }
    }
    for l in 0..L {
        if g[ncat + 1][l].partial_cmp(&0.0) != Some(Ordering::Greater) {
            return None;
        }
    }
    let mut work = [0.0; L];
    for l in 0..L {
        work[l] = 1.0 / g[ncat + 1][l];
    }
    for k in 1..=ncat + 1 {
        for l in 0..L {
            g[k][l] *= work[l];
        }
    }

    // Participation a_Pn, n = 0..=ncat.
    match T {
        true => {
            let gstar = p.gstar;
            let gstari = 1.0 / gstar;
            for n in 0..=ncat {
                for l in 0..L {
                    let g1 = g[n][l];
                    let g2 = g[n + 1][l];
                    let below = gstari * (g2 - g1) * (2.0 - gstari * (g1 + g2));
                    let straddle = gstari * (gstar - g1) * (2.0 - gstari * (gstar + g1));
                    let straddle = if g1 < gstar { straddle } else { 0.0 };
                    ap[n][l] = if g2 < gstar { below } else { straddle };
                }
            }
        }
        false => {
            let (astari, xtmp) = (e.astari, e.xtmp);
            // Every boundary's exponential at once (`vexp`: the same bits as one `exp`
            // each; at G = 1 it is e^{−1/a*}, so `at_one` is not needed here).
            for n in 0..=ncat {
                for l in 0..L {
                    ex[n][l] = -g[n + 1][l] * astari;
                }
            }
            exp_in_place(ex[..=ncat].as_flattened_mut());
            let mut prev = [xtmp; L];
            for n in 0..=ncat {
                for l in 0..L {
                    let cur = ex[n][l] * xtmp;
                    ap[n][l] = prev[l] - cur;
                    prev[l] = cur;
                }
            }
        }
    }

    // Geometry, net-to-gross ratio and the strength sum.
    let mut aksum = ap[0];
    let mut total = [0.0; L];
    for n in 0..ncat {
        for l in 0..L {
            let (a, v) = (b.a[n][l], b.v[n][l]);
            let live = a > puny;
            let hi = v / a;
            let (krdg, h2rdg) = match U {
                true => {
                    let hrmin = f64::min(2.0 * hi, hi + p.maxraft);
                    let hrmax = f64::max(2.0 * (p.hstar * hi).sqrt(), hrmin + puny);
                    let krdg = 0.5 * (hrmin + hrmax) / hi;
                    let cube = |x: f64| x * x * x;
                    let h2 = (1.0 / 3.0) * (cube(hrmax) - cube(hrmin)) / (hrmax - hrmin);
                    (krdg, h2)
                }
                false => {
                    let hc = f64::max(hi, puny);
                    let hrmin = f64::min(2.0 * hc, hc + p.maxraft);
                    let hrexp = p.mu_rdg * hc.sqrt();
                    let krdg = (hrmin + hrexp) / hc;
                    let h2 = hrmin * hrmin + 2.0 * hrmin * hrexp + 2.0 * hrexp * hrexp;
                    (krdg, h2)
                }
            };
            let krdg = if live { krdg } else { 1.0 };
            let apn = ap[n + 1][l];
            aksum[l] += apn * (1.0 - 1.0 / krdg);
            let term = apn * (-hi * hi + h2rdg / krdg);
            total[l] += if live && apn > 0.0 { term } else { 0.0 };
        }
    }
    let mut out = [0.0; L];
    let cp = p.cp();
    for l in 0..L {
        if aksum[l].partial_cmp(&0.0) != Some(Ordering::Greater) {
            return None;
        }
        out[l] = cf * cp * total[l] / aksum[l];
    }
    Some(out)
}

#[inline(always)]
fn dispatch(b: &mut Block, call: &BlockCall) -> Option<[f64; L]> {
    let thorndike = call.part == Participation::Thorndike;
    let uniform = call.redist == Redistribution::Uniform;
    match (thorndike, uniform) {
        (true, true) => kernel::<true, true>(b, call),
        (true, false) => kernel::<true, false>(b, call),
        (false, true) => kernel::<false, true>(b, call),
        (false, false) => kernel::<false, false>(b, call),
    }
}

/// [`dispatch`] compiled for the target features `$features` (x86-64 only).
///
/// # Safety
/// The CPU must have the features `$features`; the caller checks them at run time.
macro_rules! dispatch_for {
    ($(#[$doc:meta])* $name:ident, $features:literal) => {
        $(#[$doc])*
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        unsafe fn $name(b: &mut Block, call: &BlockCall) -> Option<[f64; L]> {
            dispatch(b, call)
        }
    };
}

dispatch_for!(
    /// With AVX2: SIMD across the block's columns, no FMA (the rounding of the scalar path).
    dispatch_avx2,
    "avx2"
);
dispatch_for!(
    /// With AVX2 and FMA, where `vexp` uses them: the participation's exponentials are
    /// evaluated in registers. Rust never fuses a multiply and an add on its own, so every
    /// other operation rounds as in the scalar path.
    dispatch_avx2_fma,
    "avx2,fma"
);

/// Strength of one block (dispatching to AVX2, with FMA for the exponentials only, where the
/// CPU has them; the rounding is the same as the scalar path's).
pub(crate) fn strength_block(b: &mut Block, call: &BlockCall) -> Option<[f64; L]> {
    #[cfg(target_arch = "x86_64")]
    {
        if super::vexp::fused() {
            // SAFETY: `fused()` holds only on a CPU with AVX2 and FMA.
            return unsafe { dispatch_avx2_fma(b, call) };
        }
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above).
            return unsafe { dispatch_avx2(b, call) };
        }
    }
    dispatch(b, call)
}
