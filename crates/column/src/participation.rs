//! Participation function: the fraction a_Pn of the area lost to ridging and closing that
//! comes from open water (n = 0) and from each category n (Thorndike et al. 1975;
//! Lipscomb et al. 2007; CICE/Icepack `ridge_itd`).
//!
//! G(n) is the cumulative area of open water and categories 1..n, normalised by the total
//! area (open water first). Categories and open water with area ≤ `puny` are ignored, as in
//! CICE. With b(h) the weighting of Thorndike et al. (1975), a_Pn = ∫ b dG over
//! [G(n−1), G(n)]:
//! - Thorndike: b = (2/G*)(1 − G/G*) for G < G*, so
//!   a_Pn = (ΔG/G*)(2 − (G(n−1) + G(n))/G*) while G(n) < G*, truncated at G*.
//! - Exponential: b ∝ exp(−G/a*), a_Pn = (e^{−G(n−1)/a*} − e^{−G(n)/a*}) / (1 − e^{−1/a*}).

// Several parallel per-category arrays are indexed by the category number, as in CICE.
#![allow(clippy::needless_range_loop)]

use super::params::{ItdParams, Participation};

/// Fills `apartic[0..=ncat]` (dimensionless, sums to 1 unless the column holds no area) from
/// open water `aice0` and category areas `aicen` (dimensionless).
///
/// `gsum` is scratch of length `ncat + 2`. A column without any area above `puny` gets
/// a_Pn = 0 everywhere (CICE does the same here; its callers then divide by zero).
pub fn participation(
    kind: Participation,
    params: &ItdParams,
    aice0: f64,
    aicen: &[f64],
    gsum: &mut [f64],
    apartic: &mut [f64],
) {
    let mut cache = ExpCache::EMPTY;
    participation_cached(kind, params, aice0, aicen, gsum, apartic, &mut cache);
}

/// Constants of the exponential participation that depend on a* only, computed once as
/// Icepack computes them (so with the same bits): 1/a*, x = 1/(1 − e^{−1/a*}) and the
/// term e^{−G·/a*}·x at G = 1, which the last category of every column reaches when the
/// normalisation gives exactly 1 (Icepack evaluates `exp(-Gsum(n)*astari) * xtmp` there, and
/// −1·(1/a*) is −1/a* exactly).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ExpCache {
    astar: f64,
    /// 1/a*.
    pub astari: f64,
    /// 1/(1 − e^{−1/a*}).
    pub xtmp: f64,
    /// e^{−1/a*}·xtmp.
    pub at_one: f64,
}

impl ExpCache {
    /// Not yet computed (NaN never equals a*).
    pub(crate) const EMPTY: ExpCache = ExpCache {
        astar: f64::NAN,
        astari: f64::NAN,
        xtmp: f64::NAN,
        at_one: f64::NAN,
    };

    /// The constants for `astar`.
    pub(crate) fn new(astar: f64) -> Self {
        let astari = 1.0 / astar;
        let xtmp = 1.0 / (1.0 - (-astari).exp());
        ExpCache {
            astar,
            astari,
            xtmp,
            // −1·(1/a*) = −1/a* exactly.
            at_one: (-astari).exp() * xtmp,
        }
    }

    /// Recomputes the constants if `astar` changed.
    #[inline]
    pub(crate) fn update(&mut self, astar: f64) {
        if self.astar != astar {
            *self = Self::new(astar);
        }
    }
}

/// As [`participation`], with the exponential participation's constants kept in `cache`
/// between calls so they are not recomputed for every column (same numbers).
pub(crate) fn participation_cached(
    kind: Participation,
    params: &ItdParams,
    aice0: f64,
    aicen: &[f64],
    gsum: &mut [f64],
    apartic: &mut [f64],
    cache: &mut ExpCache,
) {
    if kind == Participation::Exponential {
        cache.update(params.astar);
    }
    participation_with(kind, params, aice0, aicen, gsum, apartic, cache);
}

/// As [`participation`], with the exponential participation's constants `k` (for
/// `params.astar`; unused by Thorndike's).
#[inline]
pub(crate) fn participation_with(
    kind: Participation,
    params: &ItdParams,
    aice0: f64,
    aicen: &[f64],
    gsum: &mut [f64],
    apartic: &mut [f64],
    k: &ExpCache,
) {
    let ncat = aicen.len();
    debug_assert!(gsum.len() == ncat + 2 && apartic.len() == ncat + 1);
    let puny = params.puny;
    // gsum[k + 1] = G(k), k = -1..=ncat.
    gsum[0] = 0.0;
    // The running sum stays in a register (same additions in the same order).
    let mut run = if aice0 > puny { aice0 } else { 0.0 };
    gsum[1] = run;
    for (g, &a) in gsum[2..ncat + 2].iter_mut().zip(aicen) {
        if a > puny {
            run += a;
        }
        *g = run;
    }
    let total = run;
    if total > 0.0 {
        let work = 1.0 / total;
        for g in gsum[1..].iter_mut() {
            *g *= work;
        }
    }
    match kind {
        Participation::Thorndike => {
            let gstar = params.gstar;
            let gstari = 1.0 / gstar;
            for n in 0..=ncat {
                let g1 = gsum[n]; // G(n-1)
                let g2 = gsum[n + 1]; // G(n)
                apartic[n] = if g2 < gstar {
                    gstari * (g2 - g1) * (2.0 - gstari * (g1 + g2))
                } else if g1 < gstar {
                    gstari * (gstar - g1) * (2.0 - gstari * (gstar + g1))
                } else {
                    0.0
                };
            }
        }
        Participation::Exponential => {
            debug_assert!(k.astar == params.astar);
            let (astari, xtmp) = (k.astari, k.xtmp);
            // G(-1) = 0 and exp(-0) = 1 exactly.
            let mut prev = xtmp;
            for n in 0..=ncat {
                let g = gsum[n + 1];
                // An empty category has G(n) = G(n-1): the same exponential, zero share.
                let cur = if g == gsum[n] {
                    prev
                } else if g == 1.0 {
                    k.at_one
                } else {
                    (-g * astari).exp() * xtmp
                };
                apartic[n] = prev - cur;
                prev = cur;
            }
        }
    }
}
