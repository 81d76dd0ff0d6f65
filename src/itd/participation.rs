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
    let mut cache = (f64::NAN, f64::NAN);
    participation_cached(kind, params, aice0, aicen, gsum, apartic, &mut cache);
}

/// As [`participation`], with `cache` = (a*, 1/(1 − e^{−1/a*})) kept between calls so the
/// constant is not recomputed for every column (same numbers).
pub(crate) fn participation_cached(
    kind: Participation,
    params: &ItdParams,
    aice0: f64,
    aicen: &[f64],
    gsum: &mut [f64],
    apartic: &mut [f64],
    cache: &mut (f64, f64),
) {
    let ncat = aicen.len();
    debug_assert!(gsum.len() == ncat + 2 && apartic.len() == ncat + 1);
    let puny = params.puny;
    // gsum[k + 1] = G(k), k = -1..=ncat.
    gsum[0] = 0.0;
    gsum[1] = if aice0 > puny { aice0 } else { 0.0 };
    for n in 1..=ncat {
        let a = aicen[n - 1];
        gsum[n + 1] = if a > puny { gsum[n] + a } else { gsum[n] };
    }
    let total = gsum[ncat + 1];
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
            let astari = 1.0 / params.astar;
            if cache.0 != params.astar {
                *cache = (params.astar, 1.0 / (1.0 - (-astari).exp()));
            }
            let xtmp = cache.1;
            // G(-1) = 0 and exp(-0) = 1 exactly.
            let mut prev = xtmp;
            for n in 0..=ncat {
                // An empty category has G(n) = G(n-1): the same exponential, zero share.
                let cur = if gsum[n + 1] == gsum[n] {
                    prev
                } else {
                    (-gsum[n + 1] * astari).exp() * xtmp
                };
                apartic[n] = prev - cur;
                prev = cur;
            }
        }
    }
}
