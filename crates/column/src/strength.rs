//! Ice strength P (N/m): Rothrock (1975) energetics as in CICE/Icepack
//! `icepack_ice_strength` (`kstrength = 1`), or Hibler (1979) (`kstrength = 0`).
//!
//! Rothrock (1975):
//! P = C_f·C_p·Σ_n a_Pn(⟨h_r²⟩_n/k_n − h_n²) / (a_P0 + Σ_n a_Pn(1 − 1/k_n)),
//! C_p = g·ρ_i·(ρ_w − ρ_i)/(2ρ_w); with a C_f table, C_f(h_n) moves inside the sum.
//! Hibler (1979): P = P*·V·exp(−C*(1 − A)), V = Σ vicen, A = Σ aicen.

// Several parallel per-category arrays are indexed by the category number, as in CICE.
#![allow(clippy::needless_range_loop)]

use ndarray::{ArrayView1, ArrayView2, ArrayViewMut1, Axis};

use super::cf::{Cf, CfProvider};
use super::lanes;
use super::params::{ItdParams, Participation, Redistribution, StrengthFormula};
use super::participation::ExpCache;
use super::redistribution::mean_square_ridge_thickness;
use super::{ColumnError, ItdError, Workspace, check_column, check_len, check_shape};

/// Options of the strength routine. `StrengthOptions::default()` is CICE's default
/// (exponential participation, exponential redistribution, Rothrock, C_f = 17).
#[derive(Debug, Clone, Default)]
pub struct StrengthOptions {
    /// Participation function (CICE `krdg_partic`).
    pub participation: Participation,
    /// Ridged-ice redistribution (CICE `krdg_redist`).
    pub redistribution: Redistribution,
    /// Strength formula (CICE `kstrength`).
    pub formula: StrengthFormula,
    /// Frictional factor C_f (Rothrock only).
    pub cf: Cf,
    /// Physical constants and tunables.
    pub params: ItdParams,
}

impl StrengthOptions {
    /// Checks option values that could otherwise give garbage (C_f).
    pub fn validate(&self) -> Result<(), ItdError> {
        self.cf.validate()
    }
}

/// Result of the strength routine for one column.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ColumnStrength {
    /// Ice strength P (N/m).
    pub strength: f64,
    /// True when a C_f table was queried outside its thickness range (value clamped).
    pub cf_clamped: bool,
    /// True when a μ_rdg table ([`Redistribution::Table`]) was queried outside its thickness
    /// range for a category that ridges (the end value used).
    pub mu_rdg_clamped: bool,
    /// The share of P (dimensionless, 0–1) carried by the categories whose C_f was held at
    /// the table's end value: how much the clamp can matter. Every ice column of a
    /// realistic distribution has some participation, however small, of its thickest
    /// category, so `cf_clamped` alone flags nearly every column beyond a table's thick
    /// end; this says whether the flag is material ([`CF_CLAMPED_MATERIAL_SHARE`]). 0 when
    /// nothing was clamped.
    pub cf_clamped_share: f64,
}

/// The share of a column's strength from clamped C_f lookups
/// ([`ColumnStrength::cf_clamped_share`]) at or above which the clamp counts as material in
/// [`BatchSummary::cf_clamped_material_columns`]: 1 %. Below it, even a C_f wrong by a
/// factor of two moves P by under 1 %, less than the table's own seed spread.
pub const CF_CLAMPED_MATERIAL_SHARE: f64 = 0.01;

impl ColumnStrength {
    /// A strength with nothing clamped.
    const fn unclamped(strength: f64) -> ColumnStrength {
        ColumnStrength {
            strength,
            cf_clamped: false,
            mu_rdg_clamped: false,
            cf_clamped_share: 0.0,
        }
    }
}

/// Strength P (N/m) of one column.
///
/// Inputs: `aicen` (dimensionless) and `vicen` (m) of length `ncat = ws.ncat()`, and the
/// open-water fraction `aice0` (dimensionless), or `None` to use 1 − Σ aicen. Errors on
/// NaN/infinite or negative values and on a total area that differs from 1 by more than
/// [`ItdParams::area_tolerance`]. An empty column (`aice0` and every `aicen` exactly 0, e.g.
/// land) has strength 0, where CICE divides 0 by 0. Does not allocate.
///
/// # Panics
/// If the slice lengths differ from `ws.ncat()` (the batched driver checks shapes first).
///
/// # Example
/// ```
/// use pressridge_column::{StrengthOptions, Workspace, strength_column};
///
/// // Five categories: areas (dimensionless) and volumes per unit area (m), i.e. ice
/// // 0.3, 1.0, 1.9, 3.0 and 4.0 m thick, and 10 % open water.
/// let aicen = [0.2, 0.3, 0.2, 0.15, 0.05];
/// let vicen = [0.06, 0.3, 0.38, 0.45, 0.2];
/// let mut ws = Workspace::new(aicen.len()); // reuse it for every column
/// // CICE's defaults: exponential participation and redistribution, Rothrock, C_f = 17.
/// let opts = StrengthOptions::default();
/// let p = strength_column(&aicen, &vicen, None, &opts, &mut ws)?; // aice0 = 1 − Σ aicen
/// assert!(p.strength > 0.0 && !p.cf_clamped); // N/m
/// # Ok::<(), pressridge_column::ColumnError>(())
/// ```
pub fn strength_column(
    aicen: &[f64],
    vicen: &[f64],
    aice0: Option<f64>,
    opts: &StrengthOptions,
    ws: &mut Workspace,
) -> Result<ColumnStrength, ColumnError> {
    let ncat = ws.ncat;
    assert!(
        aicen.len() == ncat && vicen.len() == ncat,
        "column length differs from ncat"
    );
    let p = &opts.params;
    let Some((aice0, sum)) = column_prelude(aicen, vicen, aice0, p)? else {
        // Empty column (land, or no data): defined as zero strength (CICE: 0/0).
        return Ok(ColumnStrength::unclamped(0.0));
    };

    if opts.formula == StrengthFormula::Hibler1979 {
        let vice: f64 = vicen.iter().sum();
        let strength = p.pstar * vice * (-p.cstar * (1.0 - sum)).exp();
        return Ok(ColumnStrength::unclamped(strength));
    }

    let aksum = ws.prepare_ridging(
        opts.participation,
        &opts.redistribution,
        p,
        aice0,
        aicen,
        vicen,
    );
    if aksum <= 0.0 {
        // Nothing participates (no area above puny): defined as zero strength.
        return Ok(ColumnStrength::unclamped(0.0));
    }

    let mut total = 0.0;
    let mut clamped = false;
    // The part of `total` from categories whose C_f was clamped.
    let mut clamped_part = 0.0;
    let term = |ws: &Workspace, n: usize| {
        let g = super::redistribution::RidgeGeometry {
            hi: ws.hi[n],
            hrmin: ws.hrmin[n],
            hrmax: ws.hrmax[n],
            hrexp: ws.hrexp[n],
            krdg: ws.krdg[n],
            mu_clamped: ws.mu_clamped[n],
        };
        let h2rdg = mean_square_ridge_thickness(&opts.redistribution, &g);
        -g.hi * g.hi + h2rdg / g.krdg
    };
    match &opts.cf {
        Cf::Constant(_) => {
            for n in 0..ncat {
                let ap = ws.apartic[n + 1];
                if aicen[n] > p.puny && ap > 0.0 {
                    total += ap * term(ws, n);
                }
            }
        }
        Cf::Table(_) | Cf::Custom(_) => {
            for n in 0..ncat {
                let ap = ws.apartic[n + 1];
                if aicen[n] > p.puny && ap > 0.0 {
                    let l = match &opts.cf {
                        Cf::Table(t) => t.lookup(ws.hi[n]),
                        Cf::Custom(c) => {
                            let l = c.lookup(ws.hi[n]);
                            if !crate::limits::CF.contains(l.value) {
                                return Err(ColumnError::CfOutOfRange {
                                    category: n,
                                    thickness: ws.hi[n],
                                    value: l.value,
                                });
                            }
                            l
                        }
                        Cf::Constant(_) => unreachable!(),
                    };
                    let part = l.value * ap * term(ws, n);
                    if l.clamped {
                        clamped = true;
                        clamped_part += part;
                    }
                    total += part;
                }
            }
        }
    }
    let strength = match opts.cf {
        Cf::Constant(cf) => cf * p.cp() * total / aksum,
        _ => p.cp() * total / aksum,
    };
    let mu_rdg_clamped =
        (0..ncat).any(|n| ws.mu_clamped[n] && aicen[n] > p.puny && ws.apartic[n + 1] > 0.0);
    Ok(ColumnStrength {
        strength,
        cf_clamped: clamped,
        mu_rdg_clamped,
        // The share in P of the clamped categories: P is proportional to `total`.
        cf_clamped_share: if clamped && total > 0.0 {
            (clamped_part / total).clamp(0.0, 1.0)
        } else {
            0.0
        },
    })
}

/// The checks of a column shared by the strength routines: finite, non-negative values, no
/// thicker ice than the squares allow, and the area sum. Returns (aice0, Σ aicen), or `None`
/// for an empty column (`aice0` and every `aicen` exactly 0, e.g. land).
#[inline]
fn column_prelude(
    aicen: &[f64],
    vicen: &[f64],
    aice0: Option<f64>,
    p: &ItdParams,
) -> Result<Option<(f64, f64)>, ColumnError> {
    let sum = check_column(aicen, vicen, aice0)?;
    // Squares of thicker ice overflow into NaN (the ridging paths take such volumes). A
    // category's own thickness too: a volume on a sliver of area (vicen/aicen of 10⁷ m) makes
    // h_min + puny round to h_min, and eq. ⟨h_r²⟩ 0/0 (a fuzzing find).
    for (n, (&a, &v)) in aicen.iter().zip(vicen).enumerate() {
        super::too_thick("vicen", n, v)?;
        if a > p.puny {
            super::too_thick("vicen/aicen", n, v / a)?;
        }
    }
    let aice0 = match aice0 {
        Some(a0) if a0 == 0.0 && sum == 0.0 => return Ok(None),
        Some(a0) => {
            let total = a0 + sum;
            if (total - 1.0).abs() > p.area_tolerance {
                return Err(ColumnError::AreaSum {
                    total,
                    tolerance: p.area_tolerance,
                });
            }
            a0
        }
        None => {
            if sum > 1.0 + p.area_tolerance {
                return Err(ColumnError::IceAreaAboveOne {
                    total: sum,
                    tolerance: p.area_tolerance,
                });
            }
            f64::max(1.0 - sum, 0.0)
        }
    };
    Ok(Some((aice0, sum)))
}

/// Strength P (N/m) of `ncol` columns into `out` (length `ncol`).
///
/// `aicen` (dimensionless) and `vicen` (m) have shape `(ncat, ncol)` with any strides
/// (Fortran `aicen(ncat, ncol)` or a NetCDF `(ncat, y, x)` block reshaped to `(ncat, ncol)`).
/// `aice0` has length `ncol`, or `None` for 1 − Σ aicen. Stops at the first bad column with
/// [`ItdError::Column`] naming its flat index. One workspace per call; no allocation per
/// column.
pub fn strength_batch(
    aicen: ArrayView2<f64>,
    vicen: ArrayView2<f64>,
    aice0: Option<ArrayView1<f64>>,
    opts: &StrengthOptions,
    out: ArrayViewMut1<f64>,
) -> Result<BatchSummary, ItdError> {
    strength_batch_masked(aicen, vicen, aice0, None, f64::NAN, opts, out)
}

/// As [`strength_batch`], skipping the columns where `valid[c]` is false (land, missing
/// data): they get `fill` in `out` and are neither validated nor counted in
/// [`BatchSummary::columns`].
pub fn strength_batch_masked(
    aicen: ArrayView2<f64>,
    vicen: ArrayView2<f64>,
    aice0: Option<ArrayView1<f64>>,
    valid: Option<ArrayView1<bool>>,
    fill: f64,
    opts: &StrengthOptions,
    mut out: ArrayViewMut1<f64>,
) -> Result<BatchSummary, ItdError> {
    opts.validate()?;
    let (ncat, ncol) = aicen.dim();
    check_shape("vicen", vicen.shape(), &[ncat, ncol])?;
    if let Some(a0) = &aice0 {
        check_len("aice0", a0.len(), ncol)?;
    }
    check_len("strength", out.len(), ncol)?;
    if let Some(m) = &valid {
        check_len("valid", m.len(), ncol)?;
    }
    let mut ws = Workspace::new(ncat);
    let mut abuf = vec![0.0; ncat];
    let mut vbuf = vec![0.0; ncat];
    let mut summary = BatchSummary {
        columns: ncol,
        ..BatchSummary::default()
    };
    let mut scalar = |c: usize, out: &mut ArrayViewMut1<f64>| -> Result<(), ItdError> {
        if let Some(m) = &valid
            && !m[c]
        {
            out[c] = fill;
            summary.columns -= 1;
            return Ok(());
        }
        let acol = aicen.index_axis(Axis(1), c);
        let vcol = vicen.index_axis(Axis(1), c);
        let a: &[f64] = match acol.as_slice() {
            Some(s) => s,
            None => {
                abuf.iter_mut().zip(acol.iter()).for_each(|(d, s)| *d = *s);
                &abuf
            }
        };
        let v: &[f64] = match vcol.as_slice() {
            Some(s) => s,
            None => {
                vbuf.iter_mut().zip(vcol.iter()).for_each(|(d, s)| *d = *s);
                &vbuf
            }
        };
        let a0 = aice0.as_ref().map(|x| x[c]);
        let r = strength_column(a, v, a0, opts, &mut ws)
            .map_err(|source| ItdError::Column { column: c, source })?;
        out[c] = r.strength;
        summary.add(&r);
        Ok(())
    };

    // Block path: Rothrock with a constant C_f, L columns at a time, same numbers.
    let mut c = 0;
    if let (StrengthFormula::Rothrock, Cf::Constant(cf)) = (opts.formula, &opts.cf)
        && ncat <= lanes::MAX_NCAT
        && opts.redistribution.mu_rdg_table().is_none()
    {
        let p = &opts.params;
        let e = ExpCache::new(p.astar);
        let mut b = lanes::Block::new();
        let call = lanes::BlockCall {
            ncat,
            aice0_given: aice0.is_some(),
            part: opts.participation,
            redist: opts.redistribution,
            p,
            cf: *cf,
            e: &e,
        };
        while c + lanes::L <= ncol {
            let masked = valid
                .as_ref()
                .is_some_and(|m| (c..c + lanes::L).any(|k| !m[k]));
            let r = if masked {
                None
            } else {
                for n in 0..ncat {
                    for l in 0..lanes::L {
                        // SAFETY: n < ncat and c + l < ncol, the arrays' shape (checked
                        // on entry); unchecked because the bounds checks of this gather
                        // cost about a tenth of the batched strength.
                        unsafe {
                            b.a[n][l] = *aicen.uget([n, c + l]);
                            b.v[n][l] = *vicen.uget([n, c + l]);
                        }
                    }
                }
                if let Some(a0) = &aice0 {
                    for l in 0..lanes::L {
                        b.a0[l] = a0[c + l];
                    }
                }
                lanes::strength_block(&mut b, &call)
            };
            match r {
                Some(vals) => {
                    for l in 0..lanes::L {
                        out[c + l] = vals[l];
                    }
                }
                None => {
                    for k in c..c + lanes::L {
                        scalar(k, &mut out)?;
                    }
                }
            }
            c += lanes::L;
        }
    }
    for k in c..ncol {
        scalar(k, &mut out)?;
    }
    Ok(summary)
}

mod fast;
mod summary;
pub use fast::{FAST_MAX_NCAT, StrengthConsts, strength_column_constant_cf};
pub use summary::BatchSummary;

#[cfg(test)]
mod tests;
