//! Least-squares fits of ridging energetics against ridged volume (Hopkins 1994, eqs 13–16).
//!
//! Hopkins fits, over **all** samples of an experiment set (every run sampled every 25 s),
//! the work done by the driving sheet and the potential energy of the ridge as quadratics
//! through the origin in the ridged volume `V`:
//!
//! - eq (13) `Work(V) = V·(a_W·V + b_W)`,
//! - eq (14) `PE(V)   = V·(a_P·V + b_P)`.
//!
//! Each is a linear least-squares problem on the basis `{V², V}` with no intercept; it is
//! solved here by a Householder QR factorisation (via `faer`), never by the normal equations,
//! and the coefficient covariance `s²·(XᵀX)⁻¹` is formed from the triangular factor as
//! `s²·R⁻¹R⁻ᵀ`, so its conditioning is that of `R`, not of `XᵀX`.
//!
//! Derived quantities:
//!
//! - eq (15) the mean ridging force `F(V) = h·dW/dV = h·(2·a_W·V + b_W)` for a sheet of
//!   thickness `h` ([`force`]);
//! - eq (16) the ratio `dWork/dPE = (2·a_W·V + b_W)/(2·a_P·V + b_P)` ([`ratio`]);
//! - the plain ratio `W/PE` of the fitted curves ([`fitted_ratio`]) and of data
//!   ([`data_ratio`]).
//!
//! Units (SI; the model is two-dimensional with a depth of 1 m): ridged volume `V` in m³/m
//! (= m²), work and potential energy in J/m, so `a` is in J/m⁵ (= N/m⁴) and `b` in J/m³
//! (= N/m²); the force of eq (15) is in N/m (per metre of ridge).
//!
//! Intervals use the Student-t distribution with `n − 2` degrees of freedom, whose quantile
//! is computed in this module ([`student_t_quantile`]).
//!
//! **Caveat.** All standard errors and bands assume independent residuals of constant
//! variance. Successive 25 s samples of one run are serially correlated and the scatter
//! grows with `V`, so with pooled ridging samples the intervals are optimistic (too narrow);
//! the coefficients themselves are the paper's least-squares estimates regardless.
//!
//! ```
//! use pressridge::table::fit::{Band, fit_through_origin, force, ratio};
//!
//! // Pooled samples of an experiment set: V (m³/m), work and potential energy (J/m).
//! let v: [f64; 6] = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0];
//! let w: Vec<f64> = v.iter().map(|&x| x * (1.8e3 * x + 2.4e4) + 10.0 * x.sin()).collect();
//! let pe: Vec<f64> = v.iter().map(|&x| x * (4.0e2 * x + 1.0e3) + 5.0 * x.cos()).collect();
//! let fit_w = fit_through_origin(&v, &w)?; // eq (13)
//! let fit_pe = fit_through_origin(&v, &pe)?; // eq (14)
//! let f = force(&fit_w, 0.5, 2.0); // eq (15), N/m for a 0.5 m sheet at V = 2 m³/m
//! assert!((f / (0.5 * (2.0 * 1.8e3 * 2.0 + 2.4e4)) - 1.0).abs() < 1e-2);
//! let r = ratio(&fit_w, &fit_pe, 2.0); // eq (16)
//! assert!(r > 1.0);
//! let band = Band::linspace(&fit_w, 0.0, 3.0, 31, 0.95);
//! assert!(band.conf_lo[10] < band.fit[10] && band.fit[10] < band.conf_hi[10]);
//! # Ok::<(), pressridge::table::fit::FitError>(())
//! ```
//!
//! The uncertainties, e.g. of fits to one's own ensembles (records read with
//! [`crate::campaign::read_campaign`]): intervals of the coefficients, bands of the curve,
//! standard errors of eqs (15)–(16), and a p-value from the t distribution.
//!
//! ```
//! use pressridge::table::fit::{
//!     cross_covariance, data_ratio, fit_through_origin, fitted_ratio, force, force_std_error,
//!     ratio, ratio_std_error, student_t_cdf,
//! };
//!
//! let v: [f64; 6] = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0]; // m³/m
//! let w: Vec<f64> = v.iter().map(|&x| x * (1.8e3 * x + 2.4e4) + 10.0 * x.sin()).collect();
//! let pe: Vec<f64> = v.iter().map(|&x| x * (4.0e2 * x + 1.0e3) + 5.0 * x.cos()).collect();
//! let (fit_w, fit_pe) = (fit_through_origin(&v, &w)?, fit_through_origin(&v, &pe)?);
//! // 95 % intervals of a_W (J/m⁵) and b_W (J/m³); bands of the work curve at V = 2 m³/m
//! // (J/m): of the mean curve, and for a new sample (wider).
//! let [(a_lo, a_hi), (b_lo, b_hi)] = fit_w.coefficient_intervals(0.95);
//! assert!(a_lo < fit_w.a && fit_w.a < a_hi && b_lo < fit_w.b && fit_w.b < b_hi);
//! let (lo, hi) = fit_w.confidence_band(2.0, 0.95);
//! let (plo, phi) = fit_w.prediction_band(2.0, 0.95);
//! assert!(plo < lo && lo < fit_w.eval(2.0) && fit_w.eval(2.0) < hi && hi < phi);
//! // Eq (15) for a 0.5 m sheet at V = 2 m³/m and its standard error (N/m), and the
//! // two-sided p-value of "no force" with n − 2 degrees of freedom.
//! let (f, se) = (force(&fit_w, 0.5, 2.0), force_std_error(&fit_w, 0.5, 2.0));
//! let p = 2.0 * (1.0 - student_t_cdf(f / se, fit_w.dof as f64));
//! assert!(p < 1e-3);
//! // Eq (16) with its delta-method standard error (dimensionless): the two fits share
//! // their samples, so their errors are correlated.
//! let cross = cross_covariance(&v, &w, &pe, &fit_w, &fit_pe)?;
//! let r = ratio(&fit_w, &fit_pe, 2.0);
//! let se_r = ratio_std_error(&fit_w, &fit_pe, Some(&cross), 2.0);
//! assert!(r > 1.0 && se_r.is_finite());
//! // Plain W/PE (dimensionless): of the fitted curves, and sample by sample.
//! let (r_fit, r_data) = (fitted_ratio(&fit_w, &fit_pe, 2.0), data_ratio(&w, &pe)?);
//! assert!((r_data[3] / r_fit - 1.0).abs() < 0.05); // the sample at V = 2 m³/m
//! # Ok::<(), pressridge::table::fit::FitError>(())
//! ```

use faer::prelude::*;
use thiserror::Error;

pub use super::student_t::{student_t_cdf, student_t_quantile};

/// Ratio `|R₂₂|/|R₁₁|` of the triangular factor of the column-normalised design matrix
/// below which the basis `{V², V}` is declared rank-deficient (a condition number above
/// 10¹² leaves no significant digit worth tabulating).
const RANK_TOL: f64 = 1e-12;

/// Why a fit could not be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitError {
    /// The two sample slices have different lengths.
    #[error("length mismatch: {left} values of V but {right} values of the response")]
    LengthMismatch {
        /// Number of ridged-volume samples.
        left: usize,
        /// Number of response samples.
        right: usize,
    },
    /// Fewer than 3 samples: two coefficients need at least one residual degree of freedom.
    #[error("too few points: {n} (a quadratic through the origin needs at least 3)")]
    TooFewPoints {
        /// Number of samples given.
        n: usize,
    },
    /// A sample is NaN or infinite.
    #[error("non-finite {which} at index {index}")]
    NonFinite {
        /// Which input: `"V"` or `"y"` (or `"W"`, `"PE"`).
        which: &'static str,
        /// Index of the first offending sample.
        index: usize,
    },
    /// All ridged volumes are equal, so `V²` and `V` are proportional.
    #[error("all V are equal ({value}); V² and V cannot be separated")]
    AllVEqual {
        /// The common value of V (m³/m).
        value: f64,
    },
    /// The basis `{V², V}` is (numerically) rank-deficient on these samples, e.g. only one
    /// distinct non-zero `V`.
    #[error("rank-deficient design: |R22|/|R11| = {ratio:e} (fewer than two distinct non-zero V?)")]
    RankDeficient {
        /// `|R₂₂|/|R₁₁|` of the QR factor of the column-normalised design matrix.
        ratio: f64,
    },
    /// A fit passed in does not belong to the samples passed in.
    #[error("fit was made from {fit_n} samples but {n} were given")]
    FitMismatch {
        /// Samples the fit was made from.
        fit_n: usize,
        /// Samples given now.
        n: usize,
    },
}

/// A least-squares quadratic through the origin, `y(V) = V·(a·V + b)` (eqs 13–14).
///
/// For the work fit `y` is in J/m, `a` in J/m⁵ and `b` in J/m³ (V in m³/m); likewise for
/// potential energy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadFit {
    /// Coefficient of `V²` (J/m⁵ for work or potential energy).
    pub a: f64,
    /// Coefficient of `V` (J/m³ for work or potential energy).
    pub b: f64,
    /// Covariance of `(a, b)`: `s²·(XᵀX)⁻¹` with `X = [V², V]`; `cov[0][0]` is Var(a)
    /// ((J/m⁵)²), `cov[1][1]` Var(b) ((J/m³)²), `cov[0][1] = cov[1][0]` Cov(a, b).
    pub cov: [[f64; 2]; 2],
    /// `(XᵀX)⁻¹` alone (the covariance per unit residual variance), kept so that the
    /// cross-covariance of two fits on the same `V` can be formed ([`cross_covariance`]).
    pub xtx_inv: [[f64; 2]; 2],
    /// Residual variance `s² = Σ rᵢ² / (n − 2)` (units of `y`², e.g. (J/m)²).
    pub residual_variance: f64,
    /// Residual degrees of freedom, `n − 2`.
    pub dof: usize,
    /// Number of samples.
    pub n: usize,
    /// Uncentred coefficient of determination `1 − Σ rᵢ² / Σ yᵢ²`, the usual definition for
    /// a model without intercept (as R's `summary.lm` reports it); 1 when all `y` are 0.
    /// It is not comparable with the centred R² of a model with intercept.
    pub r_squared: f64,
}

/// Fits `y = V·(a·V + b)` by linear least squares on the basis `{V², V}` (no intercept),
/// eqs (13) and (14).
///
/// `v` are ridged volumes (m³/m), `y` the work or potential energy (J/m) at the same
/// samples. The design matrix is scaled by `max|V|` and its columns normalised before a
/// Householder QR factorisation (faer), so the result does not depend on the units chosen.
///
/// # Errors
/// [`FitError::LengthMismatch`], [`FitError::TooFewPoints`] (n < 3),
/// [`FitError::NonFinite`], [`FitError::AllVEqual`], [`FitError::RankDeficient`].
pub fn fit_through_origin(v: &[f64], y: &[f64]) -> Result<QuadFit, FitError> {
    if v.len() != y.len() {
        return Err(FitError::LengthMismatch {
            left: v.len(),
            right: y.len(),
        });
    }
    let n = v.len();
    if n < 3 {
        return Err(FitError::TooFewPoints { n });
    }
    check_finite(v, "V")?;
    check_finite(y, "y")?;
    if v.iter().all(|&x| x == v[0]) {
        return Err(FitError::AllVEqual { value: v[0] });
    }
    // Scale V to u = V / vmax ∈ [-1, 1]; then normalise the columns u², u.
    let vmax = v.iter().fold(0.0_f64, |m, &x| m.max(x.abs()));
    let d1 = v.iter().map(|&x| (x / vmax).powi(4)).sum::<f64>().sqrt();
    let d2 = v.iter().map(|&x| (x / vmax).powi(2)).sum::<f64>().sqrt();
    let xs = Mat::<f64>::from_fn(n, 2, |i, j| {
        let u = v[i] / vmax;
        if j == 0 { u * u / d1 } else { u / d2 }
    });
    // Column j of X = [V², V] is s_j times column j of xs, s = (vmax²·d1, vmax·d2); the
    // divisions below are done factor by factor so that no product of scales overflows.
    let unscale = |j: usize, x: f64| {
        if j == 0 {
            x / d1 / vmax / vmax
        } else {
            x / d2 / vmax
        }
    };
    let qr = xs.qr();
    let r = qr.thin_R();
    let (r11, r12, r22) = (r[(0, 0)], r[(0, 1)], r[(1, 1)]);
    let ratio = (r22 / r11).abs();
    if ratio.is_nan() || ratio <= RANK_TOL {
        return Err(FitError::RankDeficient { ratio });
    }
    let rhs = Col::<f64>::from_fn(n, |i| y[i]);
    let beta_s = qr.solve_lstsq(&rhs);
    let a = unscale(0, beta_s[0]);
    let b = unscale(1, beta_s[1]);

    // (XsᵀXs)⁻¹ = R⁻¹R⁻ᵀ with R⁻¹ = [[1/r11, -r12/(r11 r22)], [0, 1/r22]].
    let (i00, i01, i11) = (1.0 / r11, -r12 / (r11 * r22), 1.0 / r22);
    let m = [[i00 * i00 + i01 * i01, i01 * i11], [i01 * i11, i11 * i11]];
    let mut xtx_inv = [[0.0; 2]; 2];
    for (j, row) in xtx_inv.iter_mut().enumerate() {
        for (k, e) in row.iter_mut().enumerate() {
            *e = unscale(k, unscale(j, m[j][k]));
        }
    }

    let (mut rss, mut syy) = (0.0, 0.0);
    for (&vi, &yi) in v.iter().zip(y) {
        let res = yi - vi * (a * vi + b);
        rss += res * res;
        syy += yi * yi;
    }
    let dof = n - 2;
    let s2 = rss / dof as f64;
    let cov = xtx_inv.map(|row| row.map(|e| e * s2));
    let r_squared = if syy > 0.0 { 1.0 - rss / syy } else { 1.0 };
    Ok(QuadFit {
        a,
        b,
        cov,
        xtx_inv,
        residual_variance: s2,
        dof,
        n,
        r_squared,
    })
}

fn check_finite(x: &[f64], which: &'static str) -> Result<(), FitError> {
    match x.iter().position(|e| !e.is_finite()) {
        Some(index) => Err(FitError::NonFinite { which, index }),
        None => Ok(()),
    }
}

/// `gᵀ·M·g` for a symmetric 2×2 `M`, clamped at 0 against rounding.
fn quad_form(m: &[[f64; 2]; 2], g: [f64; 2]) -> f64 {
    (m[0][0] * g[0] * g[0] + 2.0 * m[0][1] * g[0] * g[1] + m[1][1] * g[1] * g[1]).max(0.0)
}

/// Two-sided interval level → upper Student-t quantile, with a check of the level.
fn two_sided_t(level: f64, dof: usize) -> f64 {
    assert!(
        level > 0.0 && level < 1.0,
        "confidence level must lie in (0, 1), got {level}"
    );
    student_t_quantile(0.5 + 0.5 * level, dof as f64)
}

impl QuadFit {
    /// The fitted curve `y(V) = V·(a·V + b)` (eq 13 or 14), in the units of `y` (J/m).
    pub fn eval(&self, v: f64) -> f64 {
        v * (self.a * v + self.b)
    }

    /// The derivative `dy/dV = 2·a·V + b` (J/m³ = N/m² for work or potential energy).
    pub fn slope(&self, v: f64) -> f64 {
        2.0 * self.a * v + self.b
    }

    /// Standard errors `[se(a), se(b)]` (J/m⁵, J/m³): square roots of the diagonal of
    /// [`QuadFit::cov`].
    pub fn standard_errors(&self) -> [f64; 2] {
        [self.cov[0][0].sqrt(), self.cov[1][1].sqrt()]
    }

    /// Two-sided `level` confidence intervals `[(a_lo, a_hi), (b_lo, b_hi)]` of the
    /// coefficients, `coef ± t_{(1+level)/2, n−2}·se`.
    ///
    /// # Panics
    /// If `level` is not in (0, 1).
    pub fn coefficient_intervals(&self, level: f64) -> [(f64, f64); 2] {
        let t = two_sided_t(level, self.dof);
        let se = self.standard_errors();
        [
            (self.a - t * se[0], self.a + t * se[0]),
            (self.b - t * se[1], self.b + t * se[1]),
        ]
    }

    /// Standard error of the fitted mean curve at `v`: `sqrt(gᵀ·cov·g)` with `g = (V², V)`
    /// (units of `y`).
    pub fn mean_std_error(&self, v: f64) -> f64 {
        quad_form(&self.cov, [v * v, v]).sqrt()
    }

    /// Standard error for a new observation at `v`: `sqrt(s² + gᵀ·cov·g)` (units of `y`).
    pub fn prediction_std_error(&self, v: f64) -> f64 {
        (self.residual_variance + quad_form(&self.cov, [v * v, v])).sqrt()
    }

    /// Two-sided `level` (e.g. 0.95) pointwise confidence band `(lo, hi)` for the mean
    /// curve at `v`: `eval(v) ± t_{(1+level)/2, n−2}·mean_std_error(v)` (units of `y`).
    ///
    /// # Panics
    /// If `level` is not in (0, 1).
    pub fn confidence_band(&self, v: f64, level: f64) -> (f64, f64) {
        let t = two_sided_t(level, self.dof);
        let (c, h) = (self.eval(v), t * self.mean_std_error(v));
        (c - h, c + h)
    }

    /// Two-sided `level` prediction band `(lo, hi)` for a new observation at `v`:
    /// `eval(v) ± t_{(1+level)/2, n−2}·prediction_std_error(v)` (units of `y`). Assumes
    /// independent residuals of constant variance; successive 25 s samples of one run are
    /// serially correlated, so read it as indicative.
    ///
    /// # Panics
    /// If `level` is not in (0, 1).
    pub fn prediction_band(&self, v: f64, level: f64) -> (f64, f64) {
        let t = two_sided_t(level, self.dof);
        let (c, h) = (self.eval(v), t * self.prediction_std_error(v));
        (c - h, c + h)
    }
}

/// Eq (15): the mean ridging force per metre of ridge (N/m) on a sheet of thickness `h` (m)
/// at ridged volume `v` (m³/m), from the work fit: `F = h·dW/dV = h·(2·a_W·V + b_W)`.
///
/// Derivation: a sheet of thickness `h` pushed at speed `U` feeds ridged volume at
/// `dV/dt = U·h`, and the driver does work at the rate `dW/dt = F·U`; hence
/// `F = (dW/dV)·(dV/dt)/U = h·dW/dV`.
pub fn force(fit_w: &QuadFit, h: f64, v: f64) -> f64 {
    h * fit_w.slope(v)
}

/// Standard error of [`force`] (N/m): `h·sqrt(gᵀ·cov_W·g)` with `g = (2V, 1)`. The force is
/// linear in `(a_W, b_W)`, so this is exact (no delta-method approximation), given `h`
/// without error.
pub fn force_std_error(fit_w: &QuadFit, h: f64, v: f64) -> f64 {
    h.abs() * quad_form(&fit_w.cov, [2.0 * v, 1.0]).sqrt()
}

/// Eq (16): the ratio of incremental work to incremental potential energy at ridged volume
/// `v` (m³/m), `dWork/dPE = (2·a_W·V + b_W)/(2·a_P·V + b_P)` (dimensionless).
pub fn ratio(fit_w: &QuadFit, fit_pe: &QuadFit, v: f64) -> f64 {
    fit_w.slope(v) / fit_pe.slope(v)
}

/// Delta-method (first-order) standard error of [`ratio`] (dimensionless).
///
/// With `N = 2a_W V + b_W`, `D = 2a_P V + b_P`, `g = (2V, 1)` and `R = N/D`:
/// `Var(R) ≈ [Var N − 2R·Cov(N, D) + R²·Var D] / D²`, where `Var N = gᵀC_W g`,
/// `Var D = gᵀC_P g` and `Cov(N, D) = gᵀC_{WP} g`. The approximation linearises `N/D`
/// about the estimates; it is poor when `D` is within a few standard errors of 0.
///
/// Work and potential energy fitted on the same samples have correlated errors: pass their
/// cross-covariance from [`cross_covariance`]. `None` treats the two fits as independent.
pub fn ratio_std_error(
    fit_w: &QuadFit,
    fit_pe: &QuadFit,
    cross_cov: Option<&[[f64; 2]; 2]>,
    v: f64,
) -> f64 {
    let g = [2.0 * v, 1.0];
    let (num, den) = (fit_w.slope(v), fit_pe.slope(v));
    let r = num / den;
    let var_n = quad_form(&fit_w.cov, g);
    let var_d = quad_form(&fit_pe.cov, g);
    let cov_nd = cross_cov.map_or(0.0, |c| {
        c[0][0] * g[0] * g[0] + (c[0][1] + c[1][0]) * g[0] * g[1] + c[1][1] * g[1] * g[1]
    });
    ((var_n - 2.0 * r * cov_nd + r * r * var_d).max(0.0)).sqrt() / den.abs()
}

/// Cross-covariance `Cov(β_W, β_P) = s_{WP}·(XᵀX)⁻¹` of two fits made on the same ridged
/// volumes `v` (m³/m) — pass exactly the `v` both fits were made from (only the count is
/// checked) — with `s_{WP} = Σ r_{W,i}·r_{P,i} / (n − 2)` the residual
/// cross-covariance ((J/m)²). Entry `[j][k]` is Cov(coefficient j of W, coefficient k of
/// PE), coefficients ordered `(a, b)`.
///
/// # Errors
/// [`FitError::LengthMismatch`] or [`FitError::FitMismatch`] if the slices do not match each
/// other or the fits; [`FitError::NonFinite`] for NaN/inf samples.
pub fn cross_covariance(
    v: &[f64],
    w: &[f64],
    pe: &[f64],
    fit_w: &QuadFit,
    fit_pe: &QuadFit,
) -> Result<[[f64; 2]; 2], FitError> {
    for other in [w.len(), pe.len()] {
        if other != v.len() {
            return Err(FitError::LengthMismatch {
                left: v.len(),
                right: other,
            });
        }
    }
    for fit in [fit_w, fit_pe] {
        if fit.n != v.len() {
            return Err(FitError::FitMismatch {
                fit_n: fit.n,
                n: v.len(),
            });
        }
    }
    check_finite(v, "V")?;
    check_finite(w, "W")?;
    check_finite(pe, "PE")?;
    let s_wp = v
        .iter()
        .zip(w.iter().zip(pe))
        .map(|(&vi, (&wi, &pi))| (wi - fit_w.eval(vi)) * (pi - fit_pe.eval(vi)))
        .sum::<f64>()
        / fit_w.dof as f64;
    Ok(fit_w.xtx_inv.map(|row| row.map(|e| e * s_wp)))
}

/// The plain ratio of the fitted curves, `W/PE = (a_W·V + b_W)/(a_P·V + b_P)`
/// (dimensionless), written with the common factor `V` cancelled so that `V = 0` gives the
/// limit `b_W/b_P`.
pub fn fitted_ratio(fit_w: &QuadFit, fit_pe: &QuadFit, v: f64) -> f64 {
    (fit_w.a * v + fit_w.b) / (fit_pe.a * v + fit_pe.b)
}

/// The plain ratio `W/PE` of data, sample by sample (dimensionless). Samples with `PE = 0`
/// give ±∞ or NaN, as IEEE division does.
///
/// # Errors
/// [`FitError::LengthMismatch`] if the slices differ in length.
pub fn data_ratio(w: &[f64], pe: &[f64]) -> Result<Vec<f64>, FitError> {
    if w.len() != pe.len() {
        return Err(FitError::LengthMismatch {
            left: w.len(),
            right: pe.len(),
        });
    }
    Ok(w.iter().zip(pe).map(|(&a, &b)| a / b).collect())
}

/// A fitted curve with its pointwise confidence and prediction bands on a grid of ridged
/// volumes, for plotting and tabulation. All vectors have the length of `v`.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// Two-sided level of both bands (dimensionless, e.g. 0.95).
    pub level: f64,
    /// Ridged volumes (m³/m).
    pub v: Vec<f64>,
    /// Fitted curve `V·(a·V + b)` (units of `y`, J/m).
    pub fit: Vec<f64>,
    /// Lower edge of the confidence band of the mean curve (units of `y`, J/m).
    pub conf_lo: Vec<f64>,
    /// Upper edge of the confidence band of the mean curve (units of `y`, J/m).
    pub conf_hi: Vec<f64>,
    /// Lower edge of the prediction band for a new observation (units of `y`, J/m).
    pub pred_lo: Vec<f64>,
    /// Upper edge of the prediction band for a new observation (units of `y`, J/m).
    pub pred_hi: Vec<f64>,
}

impl Band {
    /// Evaluates `fit` and its `level` bands ([`QuadFit::confidence_band`],
    /// [`QuadFit::prediction_band`]) at the ridged volumes `v` (m³/m). The t quantile is
    /// computed once.
    ///
    /// # Panics
    /// If `level` is not in (0, 1).
    pub fn new(fit: &QuadFit, v: &[f64], level: f64) -> Band {
        let t = two_sided_t(level, fit.dof);
        let k = v.len();
        let mut band = Band {
            level,
            v: v.to_vec(),
            fit: Vec::with_capacity(k),
            conf_lo: Vec::with_capacity(k),
            conf_hi: Vec::with_capacity(k),
            pred_lo: Vec::with_capacity(k),
            pred_hi: Vec::with_capacity(k),
        };
        for &x in v {
            let c = fit.eval(x);
            let (hc, hp) = (t * fit.mean_std_error(x), t * fit.prediction_std_error(x));
            band.fit.push(c);
            band.conf_lo.push(c - hc);
            band.conf_hi.push(c + hc);
            band.pred_lo.push(c - hp);
            band.pred_hi.push(c + hp);
        }
        band
    }

    /// [`Band::new`] on `points` equally spaced ridged volumes from `v_min` to `v_max`
    /// inclusive (m³/m); `points == 1` gives `v_min` alone.
    ///
    /// # Panics
    /// If `level` is not in (0, 1).
    pub fn linspace(fit: &QuadFit, v_min: f64, v_max: f64, points: usize, level: f64) -> Band {
        let step = if points > 1 {
            (v_max - v_min) / (points - 1) as f64
        } else {
            0.0
        };
        let v: Vec<f64> = (0..points)
            .map(|i| {
                if i + 1 == points && points > 1 {
                    v_max
                } else {
                    v_min + step * i as f64
                }
            })
            .collect();
        Band::new(fit, &v, level)
    }
}

#[cfg(test)]
mod tests;
