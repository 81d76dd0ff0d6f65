//! The Rothrock strength with a constant C_f for up to 16 categories
//! ([`strength_column_constant_cf`]): the same checks and operations as
//! [`super::strength_column`] (so the same bits), on the stack, with the option constants made
//! once by the caller ([`StrengthConsts`]) and the categories' terms four at a time. The C
//! ABI's per-cell strength.

use super::column_prelude;
use super::{ColumnStrength, StrengthOptions};
use crate::ColumnError;
use crate::cf::Cf;
use crate::lanes;
use crate::params::{ItdParams, Redistribution, StrengthFormula};
use crate::participation::{ExpCache, participation_with};

/// k_n and −h_n² + ⟨h_r²⟩_n/k_n of every category (k_n = 1 for a category with area ≤ puny,
/// whose term is not used), with the operations of [`ridge_geometry`](crate::details::ridge_geometry) and
/// [`mean_square_ridge_thickness`](crate::details::mean_square_ridge_thickness) (checked bit for bit by the tests), evaluated branch-free
/// in groups of 4 categories.
#[inline]
fn category_terms(
    aicen: &[f64],
    vicen: &[f64],
    shape: FastShape,
    p: &ItdParams,
) -> ([f64; lanes::MAX_NCAT], [f64; lanes::MAX_NCAT]) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above).
            return unsafe { category_terms_avx2(aicen, vicen, shape, p) };
        }
    }
    category_terms_generic(aicen, vicen, shape, p)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn category_terms_avx2(
    aicen: &[f64],
    vicen: &[f64],
    shape: FastShape,
    p: &ItdParams,
) -> ([f64; lanes::MAX_NCAT], [f64; lanes::MAX_NCAT]) {
    category_terms_generic(aicen, vicen, shape, p)
}

/// A category's thickness v/a (m), or 1 m where it holds no ice (`live` false, its terms
/// unused): the empty categories and the padding lanes then divide by 1, not 0, so that a
/// host that traps floating-point exceptions (gfortran's `-ffpe-trap=invalid,zero`, CICE's
/// debug build) sees none; a category with ice gets v/a itself, so the same bits.
#[inline(always)]
fn thickness_or_one(live: bool, v: f64, a: f64) -> f64 {
    // The operands are chosen before the division, so that a vectorised form divides no lane
    // by zero either.
    let (num, den) = if live { (v, a) } else { (1.0, 1.0) };
    num / den
}

#[inline(always)]
fn category_terms_generic(
    aicen: &[f64],
    vicen: &[f64],
    shape: FastShape,
    p: &ItdParams,
) -> ([f64; lanes::MAX_NCAT], [f64; lanes::MAX_NCAT]) {
    const M: usize = lanes::MAX_NCAT;
    let ncat = aicen.len();
    let mut a = [0.0; M];
    let mut v = [0.0; M];
    a[..ncat].copy_from_slice(aicen);
    v[..ncat].copy_from_slice(&vicen[..ncat]);
    let mut krdg = [1.0; M];
    let mut term = [0.0; M];
    let groups = ncat.div_ceil(4);
    let (puny, maxraft) = (p.puny, p.maxraft);
    match shape {
        FastShape::Uniform => {
            let hstar = p.hstar;
            for gi in 0..groups {
                for j in 0..4 {
                    let n = 4 * gi + j;
                    let live = a[n] > puny;
                    let hi = thickness_or_one(live, v[n], a[n]);
                    let hrmin = f64::min(2.0 * hi, hi + maxraft);
                    let hrmax = f64::max(2.0 * (hstar * hi).sqrt(), hrmin + puny);
                    let k = 0.5 * (hrmin + hrmax) / hi;
                    let cube = |x: f64| x * x * x;
                    let h2 = (1.0 / 3.0) * (cube(hrmax) - cube(hrmin)) / (hrmax - hrmin);
                    krdg[n] = if live { k } else { 1.0 };
                    term[n] = -hi * hi + h2 / k;
                }
            }
        }
        FastShape::Exponential => {
            let mu_rdg = p.mu_rdg;
            for gi in 0..groups {
                for j in 0..4 {
                    let n = 4 * gi + j;
                    let live = a[n] > puny;
                    let hi = thickness_or_one(live, v[n], a[n]);
                    let hc = f64::max(hi, puny);
                    let hrmin = f64::min(2.0 * hc, hc + maxraft);
                    let hrexp = mu_rdg * hc.sqrt();
                    let k = (hrmin + hrexp) / hc;
                    let h2 = hrmin * hrmin + 2.0 * hrmin * hrexp + 2.0 * hrexp * hrexp;
                    krdg[n] = if live { k } else { 1.0 };
                    term[n] = -hi * hi + h2 / k;
                }
            }
        }
    }
    (krdg, term)
}

/// Largest number of categories [`strength_column_constant_cf`] handles.
pub const FAST_MAX_NCAT: usize = lanes::MAX_NCAT;

/// Constants of the Rothrock strength with a constant C_f that depend on the options only,
/// computed once as Icepack computes them, so with the same bits: those of the exponential
/// participation and C_f·C_p (Icepack's `Cf * Cp * strength / aksum` multiplies left to
/// right). A host's per-cell loop (the C ABI's) makes them once per call with
/// [`StrengthConsts::new`] and passes them to [`strength_column_constant_cf`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrengthConsts {
    pub(crate) exp: ExpCache,
    pub(crate) cfcp: f64,
    shape: FastShape,
}

/// The redistribution shapes [`strength_column_constant_cf`] evaluates: one μ_rdg or H* for
/// every category (a μ_rdg table goes through [`strength_column`](super::strength_column), which counts its clamps).
#[derive(Debug, Clone, Copy, PartialEq)]
enum FastShape {
    Uniform,
    Exponential,
}

impl StrengthConsts {
    /// The constants of `opts`, or `None` unless Rothrock with a constant C_f and one μ_rdg
    /// (a μ_rdg table goes through [`strength_column`](super::strength_column), which counts its clamps).
    pub fn new(opts: &StrengthOptions) -> Option<Self> {
        let shape = match opts.redistribution {
            Redistribution::Uniform => FastShape::Uniform,
            Redistribution::Exponential => FastShape::Exponential,
            Redistribution::Table(_) => return None,
        };
        match (opts.formula, &opts.cf) {
            (StrengthFormula::Rothrock, Cf::Constant(cf)) => Some(StrengthConsts {
                exp: ExpCache::new(opts.params.astar),
                cfcp: cf * opts.params.cp(),
                shape,
            }),
            _ => None,
        }
    }
}

/// [`strength_column`](super::strength_column) for Rothrock with a constant C_f and `ncat ≤ 16`, the constants
/// `k = StrengthConsts::new(opts)` computed once by the caller: the same checks, errors and
/// operations (so the same bits), on the stack, without a workspace.
///
/// # Panics
/// If the slice lengths differ or exceed 16.
pub fn strength_column_constant_cf(
    aicen: &[f64],
    vicen: &[f64],
    aice0: Option<f64>,
    opts: &StrengthOptions,
    k: &StrengthConsts,
) -> Result<ColumnStrength, ColumnError> {
    const ZERO: ColumnStrength = ColumnStrength::unclamped(0.0);
    let ncat = aicen.len();
    assert!(
        vicen.len() == ncat && ncat <= lanes::MAX_NCAT,
        "column length differs from ncat"
    );
    debug_assert!(Some(*k) == StrengthConsts::new(opts));
    let p = &opts.params;
    let Some((aice0, _)) = column_prelude(aicen, vicen, aice0, p)? else {
        return Ok(ZERO);
    };
    let mut gsum = [0.0; lanes::MAX_NCAT + 2];
    let mut apartic = [0.0; lanes::MAX_NCAT + 1];
    let apartic = &mut apartic[..ncat + 1];
    participation_with(
        opts.participation,
        p,
        aice0,
        aicen,
        &mut gsum[..ncat + 2],
        apartic,
        &k.exp,
    );
    // Per category k_n and the strength term, as strength_column computes them, in groups
    // of 4 categories without branches (so SIMD across categories), then net_to_gross and
    // the strength sum in the same order as strength_column.
    let (krdg, term) = category_terms(aicen, vicen, k.shape, p);
    let mut aksum = apartic[0];
    let mut total = 0.0;
    for n in 0..ncat {
        let ap = apartic[n + 1];
        aksum += ap * (1.0 - 1.0 / krdg[n]);
        if aicen[n] > p.puny && ap > 0.0 {
            total += ap * term[n];
        }
    }
    if aksum <= 0.0 {
        // Nothing participates (no area above puny): defined as zero strength.
        return Ok(ZERO);
    }
    Ok(ColumnStrength::unclamped(k.cfcp * total / aksum))
}
