//! Thickness-category bounds `hin_max(0:ncat)` (m), as CICE/Icepack's `kcatbound` options
//! (`icepack_itd.F90`, `icepack_init_itd`; Lipscomb 2001 for the original formula).

use super::ItdError;

/// How the category bounds are chosen (CICE `kcatbound`).
#[derive(Debug, Clone, PartialEq, Default)]
pub enum CategoryBounds {
    /// `kcatbound = 0` with linear remapping (`kitd = 1`), Lipscomb (2001):
    /// H(n) = H(n−1) + c₁ + c₂(1 + tanh(c₃((n−1)/N − 1))), c₁ = 3/N, c₂ = 15c₁, c₃ = 3, H(0) = 0.
    Original,
    /// `kcatbound = 1` (CICE default): H(n) = n(d₁ + (n−1)d₂), d₁ = 3/N, d₂ = 0.5/N
    /// (0.6, 1.4, 2.4, 3.6, 5.0 m for N = 5).
    #[default]
    RoundNumbers,
    /// `kcatbound = 2`: WMO classes; N = 5, 6 or 7 (upper bounds 0.10, 0.15, 0.30, 0.70, 1.20,
    /// 2.00, 999 m, the thinnest merged for N < 7).
    Wmo,
    /// `kcatbound = 3`: H(n) = b₁(n + b₃·n(n+1)/(2N(N−1))), b₁ = 0.1 m, b₃ = max(N(N−1), 2b₂/b₁),
    /// b₂ = 3 m.
    Asymptotic,
    /// `kcatbound = −1`: one category, bounds 0 and 100 m (N must be 1).
    SingleCategory,
    /// User-supplied bounds (m): N + 1 finite, non-negative, strictly increasing values.
    User(Vec<f64>),
}

/// Returns the `ncat + 1` category bounds `hin_max` (m) for the chosen option.
///
/// Errors: `ncat == 0`; WMO with `ncat` not 5, 6 or 7; the single category with `ncat != 1`;
/// asymptotic with `ncat == 1` (its formula divides by N − 1); user bounds of the wrong length
/// or not strictly increasing.
pub fn category_bounds(kind: &CategoryBounds, ncat: usize) -> Result<Vec<f64>, ItdError> {
    if ncat == 0 {
        return Err(ItdError::Bounds("ncat must be at least 1".into()));
    }
    let rncat = ncat as f64;
    let mut h = vec![0.0; ncat + 1];
    match kind {
        CategoryBounds::Original => {
            let cc1 = 3.0 / rncat;
            let cc2 = 15.0 * cc1;
            let cc3 = 3.0;
            for n in 1..=ncat {
                let x1 = (n - 1) as f64 / rncat;
                h[n] = h[n - 1] + cc1 + cc2 * (1.0 + (cc3 * (x1 - 1.0)).tanh());
            }
        }
        CategoryBounds::RoundNumbers => {
            let d1 = 3.0 / rncat;
            let d2 = 0.5 / rncat;
            for (n, hn) in h.iter_mut().enumerate().skip(1) {
                let rn = n as f64;
                *hn = rn * (d1 + (rn - 1.0) * d2);
            }
        }
        CategoryBounds::Wmo => {
            let upper: &[f64] = match ncat {
                5 => &[0.30, 0.70, 1.20, 2.00, 999.0],
                6 => &[0.15, 0.30, 0.70, 1.20, 2.00, 999.0],
                7 => &[0.10, 0.15, 0.30, 0.70, 1.20, 2.00, 999.0],
                _ => {
                    return Err(ItdError::Bounds(format!(
                        "WMO bounds need ncat = 5, 6 or 7, got {ncat}"
                    )));
                }
            };
            h[1..].copy_from_slice(upper);
        }
        CategoryBounds::Asymptotic => {
            if ncat < 2 {
                return Err(ItdError::Bounds("asymptotic bounds need ncat >= 2".into()));
            }
            let b1 = 0.1;
            let b2 = 3.0;
            let b3 = f64::max(rncat * (rncat - 1.0), 2.0 * b2 / b1);
            for (n, hn) in h.iter_mut().enumerate().skip(1) {
                let rn = n as f64;
                *hn = b1 * (rn + b3 * rn * (rn + 1.0) / (2.0 * rncat * (rncat - 1.0)));
            }
        }
        CategoryBounds::SingleCategory => {
            if ncat != 1 {
                return Err(ItdError::Bounds(format!(
                    "the single-category bounds need ncat = 1, got {ncat}"
                )));
            }
            h[1] = 100.0;
        }
        CategoryBounds::User(v) => {
            if v.len() != ncat + 1 {
                return Err(ItdError::Bounds(format!(
                    "user bounds have {} values, ncat + 1 = {} needed",
                    v.len(),
                    ncat + 1
                )));
            }
            h.copy_from_slice(v);
        }
    }
    validate_bounds(&h)?;
    Ok(h)
}

/// Checks that `hin_max` (m) has at least two values, all finite, the first non-negative and
/// the sequence strictly increasing.
pub fn validate_bounds(hin_max: &[f64]) -> Result<(), ItdError> {
    if hin_max.len() < 2 {
        return Err(ItdError::Bounds(format!(
            "need at least 2 values, got {}",
            hin_max.len()
        )));
    }
    for (i, &h) in hin_max.iter().enumerate() {
        if !h.is_finite() {
            return Err(ItdError::Bounds(format!(
                "hin_max[{i}] = {h} is not finite"
            )));
        }
    }
    if hin_max[0] < 0.0 {
        return Err(ItdError::Bounds(format!(
            "hin_max[0] = {} is negative",
            hin_max[0]
        )));
    }
    for i in 1..hin_max.len() {
        if hin_max[i] <= hin_max[i - 1] {
            return Err(ItdError::Bounds(format!(
                "not strictly increasing: hin_max[{}] = {} <= hin_max[{}] = {}",
                i,
                hin_max[i],
                i - 1,
                hin_max[i - 1]
            )));
        }
    }
    Ok(())
}
