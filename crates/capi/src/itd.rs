//! Ice strength and the ridging step through the C ABI: options in C layout, and batched
//! calls over `ncol` columns laid out as a [`PressridgeGrid`] describes.

use std::cell::RefCell;
use std::sync::Arc;

use ndarray::{Array1, ArrayViewMut1};

use super::layout::{Layout, Region, check_disjoint, check_ptr};
use super::mu_rdg_table::PressridgeMuRdgTable;
use super::tables::PressridgeCfTable;
use super::{FfiError, FfiResult, PRESSRIDGE_ERR_BAD_VALUE, PressridgeGrid, guard, put};
use pressridge::itd::details::validate_bounds;
use pressridge::itd::details::{FAST_MAX_NCAT, StrengthConsts, strength_column_constant_cf};
use pressridge::itd::{
    CategoryBounds, Cf, ColumnStrength, ItdError, ItdParams, RidgeDiagnostics, RidgeForcing,
    RidgeOptions, StrengthOptions, Workspace, category_bounds,
    details::{
        CfPreset, Participation, Redistribution, RidgeBatchForcing, RidgeRatesMut, StrengthFormula,
        strength_batch_masked,
    },
    ridge_batch, ridge_column, strength_column,
};

/// Scratch space of the single-column strength call (Icepack-style hosts call once per
/// cell): one per thread, reused, so that such calls do not allocate.
struct ColumnScratch {
    ws: Workspace,
    a: Vec<f64>,
    v: Vec<f64>,
}

mod options;
pub use options::{
    PRESSRIDGE_CF_CICE, PRESSRIDGE_CF_FLATO1991, PRESSRIDGE_CF_HIBLER1980,
    PRESSRIDGE_CF_SOURCE_CONSTANT, PRESSRIDGE_CF_SOURCE_TABLE,
    PRESSRIDGE_PARTICIPATION_EXPONENTIAL, PRESSRIDGE_PARTICIPATION_THORNDIKE,
    PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL, PRESSRIDGE_REDISTRIBUTION_TABLE,
    PRESSRIDGE_REDISTRIBUTION_UNIFORM, PRESSRIDGE_STRENGTH_HIBLER1979,
    PRESSRIDGE_STRENGTH_ROTHROCK, PressridgeOptions, PressridgeParams, pressridge_options_default,
};

thread_local! {
    static SCRATCH: RefCell<Option<ColumnScratch>> = const { RefCell::new(None) };
    /// The parameters this thread last found valid (compared bit for bit; NaN never equals).
    static LAST_VALID_PARAMS: std::cell::Cell<Option<PressridgeParams>> =
        const { std::cell::Cell::new(None) };
}

/// Runs `f` with the calling thread's scratch space for `ncat` categories.
fn with_scratch<T>(ncat: usize, f: impl FnOnce(&mut ColumnScratch) -> T) -> T {
    SCRATCH.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.as_ref().is_none_or(|sc| sc.ws.ncat() != ncat) {
            *slot = Some(ColumnScratch {
                ws: Workspace::new(ncat),
                a: vec![0.0; ncat],
                v: vec![0.0; ncat],
            });
        }
        f(slot.as_mut().expect("just filled"))
    })
}

/// One ridging step of one column with the calling thread's reusable workspace: the same
/// checks and call (`ridge_column`) that `ridge_batch` makes for a single column, without its
/// per-call allocations. On error the column is left unchanged, as in `ridge_batch`.
fn ridge_one(
    mut a: ndarray::ArrayViewMut1<'_, f64>,
    mut v: ndarray::ArrayViewMut1<'_, f64>,
    aice0: &mut f64,
    hin_max: &[f64],
    forcing: RidgeForcing,
    opts: &RidgeOptions,
) -> FfiResult<RidgeDiagnostics> {
    validate_bounds(hin_max)?;
    with_scratch(a.len(), |sc| {
        sc.a.iter_mut().zip(a.iter()).for_each(|(d, s)| *d = *s);
        sc.v.iter_mut().zip(v.iter()).for_each(|(d, s)| *d = *s);
        let mut a0 = *aice0;
        let d = ridge_column(
            &mut sc.a, &mut sc.v, &mut a0, hin_max, forcing, opts, &mut sc.ws,
        )
        .map_err(|source| FfiError::from(ItdError::Column { column: 0, source }))?;
        a.iter_mut().zip(&sc.a).for_each(|(d, s)| *d = *s);
        v.iter_mut().zip(&sc.v).for_each(|(d, s)| *d = *s);
        *aice0 = a0;
        Ok(d)
    })
}

/// Strength of one column with the calling thread's reusable workspace: the same call
/// (`strength_column`) and checks that `strength_batch` makes for a single column, without
/// its per-call allocations.
fn strength_one(
    a: ndarray::ArrayView1<'_, f64>,
    v: ndarray::ArrayView1<'_, f64>,
    a0: Option<f64>,
    opts: &StrengthOptions,
) -> FfiResult<ColumnStrength> {
    opts.validate()?;
    with_scratch(a.len(), |sc| {
        sc.a.iter_mut().zip(a.iter()).for_each(|(d, s)| *d = *s);
        sc.v.iter_mut().zip(v.iter()).for_each(|(d, s)| *d = *s);
        strength_column(&sc.a, &sc.v, a0, opts, &mut sc.ws)
            .map_err(|source| ItdError::Column { column: 0, source }.into())
    })
}

/// Validity flags (nonzero = compute the column) as the library's mask; one allocation per
/// call, not per column.
///
/// # Safety
/// `valid` must be null or valid for the layout's per-column reads.
unsafe fn mask(l: &Layout, valid: *const i32) -> FfiResult<Option<Array1<bool>>> {
    if valid.is_null() {
        return Ok(None);
    }
    // SAFETY: forwarded.
    let v = unsafe { l.view1(valid, "valid")? };
    Ok(Some(v.mapv(|x| x != 0)))
}

/// Ice strength P (N/m) of `grid->ncol` columns of `grid->ncat` categories: Rothrock (1975)
/// or Hibler (1979) as CICE/Icepack `icepack_ice_strength`, with the options' participation,
/// redistribution and C_f.
///
/// Inputs, laid out as `grid` says: `aicen` (ice area fraction per category, dimensionless),
/// `vicen` (ice volume per unit area per category, m), optional `aice0` (open-water fraction,
/// dimensionless; null: 1 − Σ aicen), optional `valid` (per column, nonzero = compute; null:
/// all columns; other columns get `options->fill` and are not checked), optional `options`
/// (null: CICE defaults). Output: `strength` (N/m, per column) and, if not null,
/// `*cf_clamped_columns` = number of columns where a C_f table was queried outside its
/// thickness range (values clamped to the end nodes).
///
/// Errors: null or misaligned pointers, a bad grid, overlapping output, a bad option, and the
/// first column with a NaN/infinite or negative value or with |aice0 + Σ aicen − 1| >
/// `params.area_tolerance` (the column index is in [`super::pressridge_last_error_info`]).
/// On error the contents of `strength` are unspecified. No allocation per column.
///
/// # Safety
/// Every non-null pointer must be valid for the reads (writes for `strength`,
/// `cf_clamped_columns`) that `grid` describes; `options->cf_table`, when used, must be a
/// live handle.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_strength(
    grid: *const PressridgeGrid,
    aicen: *const f64,
    vicen: *const f64,
    aice0: *const f64,
    valid: *const i32,
    options: *const PressridgeOptions,
    strength: *mut f64,
    cf_clamped_columns: *mut i64,
) -> i32 {
    // SAFETY: every pointer is checked for null and alignment before use; validity for the
    // extent of the grid is the caller's promise.
    guard(|| unsafe {
        let l = Layout::from_ptr(grid)?;
        let o = PressridgeOptions::from_ptr(options)?;
        check_disjoint(
            &[l.region_1d(strength, "strength")],
            &[
                l.region_2d(aicen, "aicen"),
                l.region_2d(vicen, "vicen"),
                l.region_1d(aice0, "aice0"),
                l.region_1d(valid, "valid"),
            ],
        )?;
        let a = l.view2(aicen, "aicen")?;
        let v = l.view2(vicen, "vicen")?;
        let a0 = if aice0.is_null() {
            None
        } else {
            Some(l.view1(aice0, "aice0")?)
        };
        let m = mask(&l, valid)?;
        let mut out = l.view1_mut(strength, "strength")?;
        let so = o.strength_options()?;
        let clamped = if l.ncol == 1 && m.is_none() {
            let r = strength_one(a.column(0), v.column(0), a0.map(|x| x[0]), &so)?;
            out[0] = r.strength;
            usize::from(r.cf_clamped)
        } else {
            strength_batch_masked(a, v, a0, m.as_ref().map(|m| m.view()), o.fill, &so, out)?
                .cf_clamped_columns
        };
        if !cf_clamped_columns.is_null() {
            put(cf_clamped_columns, clamped as i64, "cf_clamped_columns")?;
        }
        Ok(())
    })
}

/// The options of a thread's last [`pressridge_strength_cell`] call, what they convert to
/// and, for Rothrock with a constant C_f, the constants that depend on them only.
struct CellOptions {
    raw: PressridgeOptions,
    opts: StrengthOptions,
    consts: Option<StrengthConsts>,
}

thread_local! {
    /// The options of this thread's last [`pressridge_strength_cell`] call with a constant
    /// C_f, compared bit for bit ([`same_options`]). Options that fail their checks are never
    /// kept, so a bad value is checked again every call.
    static CELL_OPTIONS: RefCell<Option<CellOptions>> = const { RefCell::new(None) };
}

/// Ice strength P (N/m) of one grid cell: the per-cell call of CICE's `icepack_ice_strength`,
/// without a grid descriptor. `aicen` (dimensionless) and `vicen` (m) are `ncat` contiguous
/// values; `aice0` is the open-water fraction (dimensionless). The result is that of
/// [`pressridge_strength`] on a one-column grid, bit for bit; errors are reported the same
/// way. `options` may be null (CICE's defaults). A thread that calls with unchanged options
/// (constant C_f) skips their conversion and checks.
///
/// # Safety
/// `aicen` and `vicen` must be valid for `ncat` reads, `options` null or valid for one read
/// and `strength` for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_strength_cell(
    ncat: i64,
    aicen: *const f64,
    vicen: *const f64,
    aice0: f64,
    options: *const PressridgeOptions,
    strength: *mut f64,
) -> i32 {
    // SAFETY: every pointer is checked for null and alignment before use; validity for
    // `ncat` values is the caller's promise.
    guard(|| unsafe {
        if ncat <= 0 {
            return Err(FfiError::new(
                super::PRESSRIDGE_ERR_BAD_SIZE,
                format!("ncat must be positive, got {ncat}"),
            ));
        }
        check_ptr(aicen, "aicen")?;
        check_ptr(vicen, "vicen")?;
        check_ptr(strength.cast_const(), "strength")?;
        let n = ncat as usize;
        let a = std::slice::from_raw_parts(aicen, n);
        let v = std::slice::from_raw_parts(vicen, n);
        let out = strength as usize;
        for (what, x) in [("aicen", aicen as usize), ("vicen", vicen as usize)] {
            if out + 8 > x && out < x + 8 * n {
                return Err(FfiError::new(
                    super::PRESSRIDGE_ERR_BAD_SIZE,
                    format!("strength overlaps {what}"),
                ));
            }
        }
        // Read in place (no copy of the options on the usual path).
        let default;
        let o: &PressridgeOptions = if options.is_null() {
            default = PressridgeOptions::default();
            &default
        } else {
            check_ptr(options, "options")?;
            &*options
        };
        let r = CELL_OPTIONS.with(|cache| -> FfiResult<ColumnStrength> {
            let mut cache = cache.borrow_mut();
            // Options with a table handle are never kept: a handle may be freed and another
            // made at its address.
            let constant = o.cf_source == PRESSRIDGE_CF_SOURCE_CONSTANT
                && o.redistribution != PRESSRIDGE_REDISTRIBUTION_TABLE;
            let hit = constant && cache.as_ref().is_some_and(|c| same_options(&c.raw, o));
            if !hit {
                let so = o.strength_options()?;
                so.validate()?;
                *cache = Some(CellOptions {
                    raw: *o,
                    consts: StrengthConsts::new(&so),
                    opts: so,
                });
            }
            let c = cache.as_ref().expect("just filled");
            let r = match &c.consts {
                // Rothrock with a constant C_f (CICE's case): on the stack.
                Some(k) if n <= FAST_MAX_NCAT => {
                    strength_column_constant_cf(a, v, Some(aice0), &c.opts, k)
                }
                _ => with_scratch(n, |sc| {
                    strength_column(a, v, Some(aice0), &c.opts, &mut sc.ws)
                }),
            }
            .map_err(|source| ItdError::Column { column: 0, source }.into());
            if !constant {
                // A table handle may be freed and another made at its address: never kept.
                *cache = None;
            }
            r
        })?;
        strength.write(r.strength);
        Ok(())
    })
}

/// Options equal bit for bit, field by field: integers and the table handle by value, every
/// f64 by its bits. Exact for a cache of options that passed their checks: the same bits pass
/// the same checks and give the same results (NaN included), and values equal as numbers but
/// not in bits (±0) are checked again. Safe code in place of a comparison of the struct's
/// bytes, which relied on its having no padding; it costs 18 instructions more per call of
/// about 1 400 (docs/notes/performance-itd.md).
fn same_options(a: &PressridgeOptions, b: &PressridgeOptions) -> bool {
    // Names every field (no `..`): one added to either struct stops the build here.
    let PressridgeOptions {
        participation: _,
        redistribution: _,
        strength_law: _,
        cf_source: _,
        cf: _,
        fill: _,
        cf_table: _,
        mu_rdg_table: _,
        params:
            PressridgeParams {
                rhoi: _,
                rhow: _,
                gravit: _,
                gstar: _,
                astar: _,
                hstar: _,
                maxraft: _,
                mu_rdg: _,
                cs: _,
                pstar: _,
                cstar: _,
                puny: _,
                exp_argmax: _,
                big: _,
                area_tolerance: _,
                max_area_before_ridging: _,
                nitermax: _,
            },
    } = a;
    let (p, q) = (&a.params, &b.params);
    // Every pair's bits XORed and ORed together: zero only where all are equal. Branch-free,
    // so that it costs about what the byte comparison it replaced did.
    let words = [
        (a.participation as u64, b.participation as u64),
        (a.redistribution as u64, b.redistribution as u64),
        (a.strength_law as u64, b.strength_law as u64),
        (a.cf_source as u64, b.cf_source as u64),
        (a.cf.to_bits(), b.cf.to_bits()),
        (a.fill.to_bits(), b.fill.to_bits()),
        (a.cf_table.addr() as u64, b.cf_table.addr() as u64),
        (a.mu_rdg_table.addr() as u64, b.mu_rdg_table.addr() as u64),
        (p.rhoi.to_bits(), q.rhoi.to_bits()),
        (p.rhow.to_bits(), q.rhow.to_bits()),
        (p.gravit.to_bits(), q.gravit.to_bits()),
        (p.gstar.to_bits(), q.gstar.to_bits()),
        (p.astar.to_bits(), q.astar.to_bits()),
        (p.hstar.to_bits(), q.hstar.to_bits()),
        (p.maxraft.to_bits(), q.maxraft.to_bits()),
        (p.mu_rdg.to_bits(), q.mu_rdg.to_bits()),
        (p.cs.to_bits(), q.cs.to_bits()),
        (p.pstar.to_bits(), q.pstar.to_bits()),
        (p.cstar.to_bits(), q.cstar.to_bits()),
        (p.puny.to_bits(), q.puny.to_bits()),
        (p.exp_argmax.to_bits(), q.exp_argmax.to_bits()),
        (p.big.to_bits(), q.big.to_bits()),
        (p.area_tolerance.to_bits(), q.area_tolerance.to_bits()),
        (
            p.max_area_before_ridging.to_bits(),
            q.max_area_before_ridging.to_bits(),
        ),
        (p.nitermax as u64, q.nitermax as u64),
    ];
    words.iter().fold(0, |d, (x, y)| d | (x ^ y)) == 0
}

/// Caller-owned outputs of [`pressridge_ridge_step`], one value per column laid out as the
/// grid's per-column arrays. Any pointer may be null (that rate is not returned).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct PressridgeRidgeRates {
    /// Net closing rate (1/s).
    pub closing: *mut f64,
    /// Opening rate (1/s).
    pub opening: *mut f64,
    /// Rate of area loss by ridging ice (1/s), CICE `dardg1dt`.
    pub dardg1dt: *mut f64,
    /// Rate of area gain by new ridges (1/s), CICE `dardg2dt`.
    pub dardg2dt: *mut f64,
    /// Rate of ice volume ridged (m/s), CICE `dvirdgdt`.
    pub dvirdgdt: *mut f64,
}

/// One ridging step of `dt` seconds over `grid->ncol` columns, in place: CICE/Icepack
/// `ridge_ice` without snow and tracers (see `docs/strength.md`).
///
/// In/out: `aicen` (dimensionless), `vicen` (m) as `grid` says, `aice0` (per column,
/// dimensionless). Inputs: `hin_max` (`nbounds = ncat + 1` category bounds in m, shared by
/// all columns; null: CICE's default bounds for `ncat`, `kcatbound = 1`, and `nbounds` is
/// ignored), `convergence` and `shear` (per column, 1/s, ≥ 0), `dt` (s, > 0), optional
/// `valid` (nonzero = step the column; others untouched, their rates set to
/// `options->fill`), optional `options` (null: CICE defaults), optional `rates`.
///
/// Errors as [`pressridge_strength`], plus a bad `hin_max`, a total area above
/// `params.max_area_before_ridging` and [`super::PRESSRIDGE_ERR_NUMERICAL`] when the
/// iteration does not converge. On error the columns before the failing one have been
/// stepped; the failing one and those after it are unchanged.
///
/// # Safety
/// Every non-null pointer must be valid for the reads and writes that `grid` describes
/// (`hin_max` for `nbounds` reads); outputs must not overlap inputs (checked).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_step(
    grid: *const PressridgeGrid,
    aicen: *mut f64,
    vicen: *mut f64,
    aice0: *mut f64,
    hin_max: *const f64,
    nbounds: i64,
    convergence: *const f64,
    shear: *const f64,
    dt: f64,
    valid: *const i32,
    options: *const PressridgeOptions,
    rates: *const PressridgeRidgeRates,
) -> i32 {
    // SAFETY: as `pressridge_strength`.
    guard(|| unsafe {
        let l = Layout::from_ptr(grid)?;
        let o = PressridgeOptions::from_ptr(options)?;
        let r = if rates.is_null() {
            PressridgeRidgeRates {
                closing: std::ptr::null_mut(),
                opening: std::ptr::null_mut(),
                dardg1dt: std::ptr::null_mut(),
                dardg2dt: std::ptr::null_mut(),
                dvirdgdt: std::ptr::null_mut(),
            }
        } else {
            check_ptr(rates, "rates")?;
            *rates
        };
        let bounds: Vec<f64> = if hin_max.is_null() {
            category_bounds(&CategoryBounds::RoundNumbers, l.ncat)?
        } else {
            check_ptr(hin_max, "hin_max")?;
            if nbounds != l.ncat as i64 + 1 {
                return Err(FfiError::new(
                    super::PRESSRIDGE_ERR_BAD_SIZE,
                    format!(
                        "nbounds = {nbounds}: hin_max must have ncat + 1 = {} values",
                        l.ncat + 1
                    ),
                ));
            }
            std::slice::from_raw_parts(hin_max, nbounds as usize).to_vec()
        };
        let hin_region = Region::new(hin_max, bounds.len(), "hin_max");
        check_disjoint(
            &[
                l.region_2d(aicen, "aicen"),
                l.region_2d(vicen, "vicen"),
                l.region_1d(aice0, "aice0"),
                l.region_1d(r.closing, "rates.closing"),
                l.region_1d(r.opening, "rates.opening"),
                l.region_1d(r.dardg1dt, "rates.dardg1dt"),
                l.region_1d(r.dardg2dt, "rates.dardg2dt"),
                l.region_1d(r.dvirdgdt, "rates.dvirdgdt"),
            ],
            &[
                l.region_1d(convergence, "convergence"),
                l.region_1d(shear, "shear"),
                l.region_1d(valid, "valid"),
                if hin_max.is_null() {
                    Region::new(hin_max, 0, "hin_max")
                } else {
                    hin_region
                },
            ],
        )?;
        let a = l.view2_mut(aicen, "aicen")?;
        let v = l.view2_mut(vicen, "vicen")?;
        let a0 = l.view1_mut(aice0, "aice0")?;
        let conv = l.view1(convergence, "convergence")?;
        let sh = l.view1(shear, "shear")?;
        let m = mask(&l, valid)?;
        if l.ncol == 1 && m.is_none() {
            // One cell (Icepack-style hosts): no allocation.
            let mut a = a;
            let mut v = v;
            let mut a0 = a0;
            let forcing = RidgeForcing {
                convergence: conv[0],
                shear: sh[0],
                dt,
            };
            let ro = o.ridge_options()?;
            let d = ridge_one(
                a.column_mut(0),
                v.column_mut(0),
                &mut a0[0],
                &bounds,
                forcing,
                &ro,
            )?;
            for (p, x, name) in [
                (r.closing, d.closing, "rates.closing"),
                (r.opening, d.opening, "rates.opening"),
                (r.dardg1dt, d.dardg1dt, "rates.dardg1dt"),
                (r.dardg2dt, d.dardg2dt, "rates.dardg2dt"),
                (r.dvirdgdt, d.dvirdgdt, "rates.dvirdgdt"),
            ] {
                if !p.is_null() {
                    put(p, x, name)?;
                }
            }
            return Ok(());
        }
        // Rates the caller did not ask for go to scratch space (one allocation per call).
        let ptrs = [
            (r.closing, "rates.closing"),
            (r.opening, "rates.opening"),
            (r.dardg1dt, "rates.dardg1dt"),
            (r.dardg2dt, "rates.dardg2dt"),
            (r.dvirdgdt, "rates.dvirdgdt"),
        ];
        let mut scratch: [Array1<f64>; 5] = Default::default();
        let mut views: Vec<ArrayViewMut1<'_, f64>> = Vec::with_capacity(5);
        for ((p, name), s) in ptrs.into_iter().zip(scratch.iter_mut()) {
            if p.is_null() {
                *s = Array1::zeros(l.ncol);
                views.push(s.view_mut());
            } else {
                views.push(l.view1_mut(p, name)?);
            }
        }
        let [closing, opening, dardg1dt, dardg2dt, dvirdgdt]: [ArrayViewMut1<'_, f64>; 5] =
            views.try_into().expect("five views");
        let rates = RidgeRatesMut {
            closing,
            opening,
            dardg1dt,
            dardg2dt,
            dvirdgdt,
            fill: o.fill,
        };
        let ro = o.ridge_options()?;
        let forcing = RidgeBatchForcing {
            convergence: conv,
            shear: sh,
            dt,
            valid: m.as_ref().map(|m| m.view()),
        };
        ridge_batch(a, v, a0, &bounds, forcing, &ro, rates)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cached_options_are_compared_bit_for_bit() {
        let a = PressridgeOptions::default();
        let mut b = a;
        assert!(same_options(&a, &b));
        b.params.nitermax += 1;
        assert!(!same_options(&a, &b));
        b = a;
        b.params.max_area_before_ridging =
            f64::from_bits(a.params.max_area_before_ridging.to_bits() ^ 1);
        assert!(!same_options(&a, &b), "the last parameter, one bit off");
        b = a;
        b.cf_table = std::ptr::NonNull::dangling().as_ptr();
        assert!(!same_options(&a, &b), "another table handle");
        b = a;
        b.cf = -0.0;
        let mut c = a;
        c.cf = 0.0;
        assert!(!same_options(&b, &c), "equal as numbers, not in bits");
        b.cf = f64::NAN;
        c.cf = f64::NAN;
        assert!(
            same_options(&b, &c),
            "the same NaN bits are the same options"
        );
    }
}
