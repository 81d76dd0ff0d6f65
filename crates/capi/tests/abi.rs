//! The C ABI (`pressridge_capi`) called as C would call it: values equal to the Rust API's to
//! the bit in every layout, errors as codes and messages, never a crash, thread safety.

#[path = "../../../tests/common/mod.rs"]
mod common;
mod support;

use support::last_error;

use std::ffi::c_char;
use std::path::Path;
use std::ptr::{null, null_mut};
use std::sync::Arc;

use ndarray::{Array1, Array2};
use pressridge::io::itd_netcdf::{read_itd, write_cf_table};
use pressridge::itd::{
    CategoryBounds, Cf, RidgeOptions, StrengthOptions, category_bounds,
    details::{
        CfTable, Participation, Redistribution, RidgeBatchForcing, RidgeRatesMut, StrengthFormula,
    },
    ridge_batch, strength_batch,
};
use pressridge_capi::itd::*;
use pressridge_capi::scene::*;
use pressridge_capi::tables::*;
use pressridge_capi::*;

/// The fields of the sample grid the tests use.
struct Sample {
    aicen: Array2<f64>,
    vicen: Array2<f64>,
    aice0: Option<Array1<f64>>,
    divu: Option<Array1<f64>>,
    shear: Option<Array1<f64>>,
}

/// `data/sample_itd.nc` (4 800 columns of five categories); under Miri
/// (`scripts/check-ub.sh`), which cannot call the NetCDF library and interprets every
/// operation, 24 synthetic columns of five categories: ice-free, opening and converging
/// columns, category thicknesses near CICE's.
fn sample_grid() -> Sample {
    if !cfg!(miri) {
        let g = read_itd(&common::repo().join("data/sample_itd.nc")).unwrap();
        return Sample {
            aicen: g.aicen,
            vicen: g.vicen,
            aice0: g.aice0,
            divu: g.divu,
            shear: g.shear,
        };
    }
    let (ncat, ncol) = (5, 24);
    let hmid = [0.3, 1.0, 1.9, 3.0, 4.5];
    let mut aicen = Array2::zeros((ncat, ncol));
    let mut vicen = Array2::zeros((ncat, ncol));
    let mut aice0 = Array1::ones(ncol);
    for c in (0..ncol).filter(|c| c % 8 != 0) {
        let w: Vec<f64> = (0..ncat)
            .map(|n| 0.2 + ((7 * c + 3 * n) % 10) as f64 / 10.0)
            .collect();
        let (open, sum) = (0.02 + 0.01 * c as f64, w.iter().sum::<f64>());
        for n in 0..ncat {
            aicen[[n, c]] = (1.0 - open) * w[n] / sum;
            vicen[[n, c]] = aicen[[n, c]] * hmid[n] * (0.8 + 0.04 * ((c + n) % 10) as f64);
        }
        aice0[c] = 1.0 - aicen.column(c).sum();
    }
    let divu = Array1::from_iter((0..ncol).map(|c| {
        if c % 4 == 1 {
            2e-6
        } else {
            -1e-6 * (1 + c % 3) as f64
        }
    }));
    Sample {
        aicen,
        vicen,
        aice0: Some(aice0),
        divu: Some(divu),
        shear: Some(Array1::from_elem(ncol, 3e-6)),
    }
}

fn sample() -> (Array2<f64>, Array2<f64>, Array1<f64>) {
    let g = sample_grid();
    (g.aicen, g.vicen, g.aice0.unwrap())
}

fn last_column() -> i64 {
    let (mut code, mut col) = (0, 0);
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    unsafe { pressridge_last_error_info(&mut code, &mut col) };
    col
}

fn fortran_grid(ncat: usize, ncol: usize) -> PressridgeGrid {
    let mut g = PressridgeGrid {
        ncat: 0,
        ncol: 0,
        cat_stride: 0,
        col_stride: 0,
        len: 0,
        col_stride_1d: 0,
        len_1d: 0,
    };
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_grid_fortran(ncat as i64, ncol as i64, &mut g) },
        PRESSRIDGE_OK
    );
    g
}

fn default_options() -> PressridgeOptions {
    let mut o = std::mem::MaybeUninit::<PressridgeOptions>::uninit();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_options_default(o.as_mut_ptr()) },
        PRESSRIDGE_OK
    );
    // SAFETY: pressridge_options_default returned OK (asserted above), so every field is written.
    unsafe { o.assume_init() }
}

/// Column-major copy (Fortran `aicen(ncat, ncol)`).
fn fortran_order(a: &Array2<f64>) -> Vec<f64> {
    a.t().iter().copied().collect()
}

#[test]
fn strength_matches_rust_api_in_every_layout_and_option() {
    let (a, v, a0) = sample();
    let (ncat, ncol) = a.dim();
    let table = Arc::new(CfTable::new(vec![0.5, 1.0, 3.0], vec![8.0, 12.0, 20.0]).unwrap());
    let mut handle = null_mut();
    let (h, c) = (table.thickness().to_vec(), table.values().to_vec());
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_new(h.as_ptr(), c.as_ptr(), 3, &mut handle) },
        PRESSRIDGE_OK
    );
    let af = fortran_order(&a);
    let vf = fortran_order(&v);
    for (part, redist, law, cf) in [
        (1, 1, 1, 0),
        (0, 0, 1, 0),
        (0, 1, 1, 1),
        (1, 0, 0, 0),
        (1, 1, 1, 1),
    ] {
        let mut o = default_options();
        o.participation = part;
        o.redistribution = redist;
        o.strength_law = law;
        o.cf_source = cf;
        o.cf_table = handle;
        o.cf = PRESSRIDGE_CF_FLATO1991;
        let ro = StrengthOptions {
            participation: [Participation::Thorndike, Participation::Exponential][part as usize],
            redistribution: [Redistribution::Uniform, Redistribution::Exponential][redist as usize],
            formula: [StrengthFormula::Hibler1979, StrengthFormula::Rothrock][law as usize],
            cf: if cf == 1 {
                Cf::Table(table.clone())
            } else {
                Cf::Constant(15.0)
            },
            ..Default::default()
        };
        let mut want = Array1::zeros(ncol);
        let s = strength_batch(a.view(), v.view(), Some(a0.view()), &ro, want.view_mut()).unwrap();

        // Fortran layout.
        let g = fortran_grid(ncat, ncol);
        let mut got = vec![f64::NAN; ncol];
        let mut clamped = -1i64;
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe {
            pressridge_strength(
                &g,
                af.as_ptr(),
                vf.as_ptr(),
                a0.as_ptr(),
                null(),
                &o,
                got.as_mut_ptr(),
                &mut clamped,
            )
        };
        assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
        assert_eq!(clamped, s.cf_clamped_columns as i64);
        for (x, y) in got.iter().zip(&want) {
            assert_eq!(x.to_bits(), y.to_bits(), "{x} vs {y}");
        }

        // C layout, straight from the NetCDF (ncat, nj*ni) arrays.
        let mut gc = g;
        assert_eq!(
            // SAFETY: every non-null pointer is a live local or buffer of at least the length
            // passed; the entry point checks nulls, sizes and handles itself (the C ABI's
            // contract).
            unsafe { pressridge_grid_c(ncat as i64, ncol as i64, &mut gc) },
            PRESSRIDGE_OK
        );
        let mut got_c = vec![f64::NAN; ncol];
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe {
            pressridge_strength(
                &gc,
                a.as_ptr(),
                v.as_ptr(),
                a0.as_ptr(),
                null(),
                &o,
                got_c.as_mut_ptr(),
                null_mut(),
            )
        };
        assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
        assert_eq!(got, got_c);
    }
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    assert_eq!(unsafe { pressridge_cf_table_free(handle) }, PRESSRIDGE_OK);
}

#[test]
fn single_column_calls_equal_the_batch() {
    // Icepack-style hosts call once per cell: that path (a reused per-thread workspace) must
    // give the batch's numbers and errors.
    let (a, v, a0) = sample();
    let (ncat, ncol) = a.dim();
    let af = fortran_order(&a);
    let vf = fortran_order(&v);
    let mut table = null_mut();
    let (h, c) = ([0.5, 2.0], [10.0, 20.0]);
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    unsafe { pressridge_cf_table_new(h.as_ptr(), c.as_ptr(), 2, &mut table) };
    for cf_source in [PRESSRIDGE_CF_SOURCE_CONSTANT, PRESSRIDGE_CF_SOURCE_TABLE] {
        let mut o = default_options();
        o.cf_source = cf_source;
        o.cf_table = table;
        let g = fortran_grid(ncat, ncol);
        let mut batch = vec![0.0; ncol];
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe {
            pressridge_strength(
                &g,
                af.as_ptr(),
                vf.as_ptr(),
                a0.as_ptr(),
                null(),
                &o,
                batch.as_mut_ptr(),
                null_mut(),
            )
        };
        assert_eq!(rc, PRESSRIDGE_OK);
        let g1 = fortran_grid(ncat, 1);
        for col in 0..ncol {
            let (mut p, mut clamped) = (f64::NAN, -1i64);
            // SAFETY: every non-null pointer is a live local or buffer of at least the length
            // passed; the entry point checks nulls, sizes and handles itself (the C ABI's
            // contract).
            let rc = unsafe {
                pressridge_strength(
                    &g1,
                    af[col * ncat..].as_ptr(),
                    vf[col * ncat..].as_ptr(),
                    &a0[col],
                    null(),
                    &o,
                    &mut p,
                    &mut clamped,
                )
            };
            assert_eq!(rc, PRESSRIDGE_OK);
            assert_eq!(p.to_bits(), batch[col].to_bits(), "column {col}");
            assert!(clamped == 0 || clamped == 1);
            // The per-cell entry point, twice (the second call reuses the options).
            for _ in 0..2 {
                let mut q = f64::NAN;
                // SAFETY: every non-null pointer is a live local or buffer of at least the length
                // passed; the entry point checks nulls, sizes and handles itself (the C ABI's
                // contract).
                let rc = unsafe {
                    pressridge_strength_cell(
                        ncat as i64,
                        af[col * ncat..].as_ptr(),
                        vf[col * ncat..].as_ptr(),
                        a0[col],
                        &o,
                        &mut q,
                    )
                };
                assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
                assert_eq!(q.to_bits(), batch[col].to_bits(), "cell call, column {col}");
            }
        }
    }
    // The per-cell entry point refuses what the grid call refuses, naming it; a changed
    // option after a cached one is seen.
    let (a1, v1) = ([0.3, 0.4], [0.3, 0.8]);
    let mut q = 0.0;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let cell = |ncat: i64, a: *const f64, o: *const PressridgeOptions, q: *mut f64| unsafe {
        pressridge_strength_cell(ncat, a, v1.as_ptr(), 0.3, o, q)
    };
    assert_eq!(
        cell(0, a1.as_ptr(), null(), &mut q),
        PRESSRIDGE_ERR_BAD_SIZE
    );
    assert!(last_error().contains("ncat"), "{}", last_error());
    assert_eq!(cell(2, null(), null(), &mut q), PRESSRIDGE_ERR_NULL_POINTER);
    assert!(last_error().contains("aicen"), "{}", last_error());
    assert_eq!(
        cell(2, a1.as_ptr(), null(), null_mut()),
        PRESSRIDGE_ERR_NULL_POINTER
    );
    let nan = [f64::NAN, 0.4];
    assert_eq!(
        cell(2, nan.as_ptr(), null(), &mut q),
        PRESSRIDGE_ERR_NOT_FINITE
    );
    assert_eq!(last_column(), 0);
    let mut o = default_options();
    assert_eq!(cell(2, a1.as_ptr(), &o, &mut q), PRESSRIDGE_OK);
    let p17 = q;
    o.cf *= 2.0;
    assert_eq!(cell(2, a1.as_ptr(), &o, &mut q), PRESSRIDGE_OK);
    assert_eq!(q, 2.0 * p17, "C_f doubled, strength doubled");
    o.cf = f64::NAN;
    assert_eq!(cell(2, a1.as_ptr(), &o, &mut q), PRESSRIDGE_ERR_NOT_FINITE);
    // The same bad bits again: checked again, never taken from the cache.
    assert_eq!(cell(2, a1.as_ptr(), &o, &mut q), PRESSRIDGE_ERR_NOT_FINITE);
    // A parameter deep in the struct changes the cached answer.
    o.cf = 17.0;
    assert_eq!(cell(2, a1.as_ptr(), &o, &mut q), PRESSRIDGE_OK);
    assert_eq!(q, p17);
    o.params.mu_rdg = 4.0;
    assert_eq!(cell(2, a1.as_ptr(), &o, &mut q), PRESSRIDGE_OK);
    assert!(
        q > p17,
        "a larger mu_rdg makes thicker ridges: {q} <= {p17}"
    );
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    unsafe { pressridge_cf_table_free(table) };
    // Errors of a single column, and a different ncat afterwards on the same thread.
    let bad = [0.1, -0.2, 0.1];
    let mut p = 0.0;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &fortran_grid(3, 1),
            bad.as_ptr(),
            bad.as_ptr(),
            null(),
            null(),
            null(),
            &mut p,
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    assert_eq!(last_column(), 0);
    let one = [0.5];
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &fortran_grid(1, 1),
            one.as_ptr(),
            one.as_ptr(),
            null(),
            null(),
            null(),
            &mut p,
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
}

#[test]
fn strided_per_column_arrays_and_mask() {
    // Every other column of the sample, per-column arrays with stride 3, a mask.
    let (a, v, a0) = sample();
    let (ncat, ncol_all) = a.dim();
    let ncol = ncol_all / 2;
    let af = fortran_order(&a);
    let vf = fortran_order(&v);
    let g = PressridgeGrid {
        ncat: ncat as i64,
        ncol: ncol as i64,
        cat_stride: 1,
        col_stride: 2 * ncat as i64,
        len: af.len() as i64,
        col_stride_1d: 3,
        len_1d: 3 * ncol as i64,
    };
    let mut a0s = vec![f64::NAN; 3 * ncol];
    let mut valid = vec![0i32; 3 * ncol];
    for c in 0..ncol {
        a0s[3 * c] = a0[2 * c];
        valid[3 * c] = i32::from(c % 7 != 3);
    }
    let mut o = default_options();
    o.fill = -1.0;
    let mut out = vec![f64::NAN; 3 * ncol];
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &g,
            af.as_ptr(),
            vf.as_ptr(),
            a0s.as_ptr(),
            valid.as_ptr(),
            &o,
            out.as_mut_ptr(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    let mut want = Array1::zeros(ncol_all);
    strength_batch(
        a.view(),
        v.view(),
        Some(a0.view()),
        &StrengthOptions::default(),
        want.view_mut(),
    )
    .unwrap();
    for c in 0..ncol {
        let w = if c % 7 == 3 { -1.0 } else { want[2 * c] };
        assert_eq!(out[3 * c].to_bits(), w.to_bits(), "column {c}");
        assert!(out[3 * c + 1].is_nan(), "gaps are not written");
    }
}

#[test]
fn strength_errors_are_codes_with_messages() {
    let ncat = 5;
    let ncol = 4;
    let mut a = vec![0.1; ncat * ncol];
    let v = vec![0.2; ncat * ncol];
    let a0 = vec![0.5; ncol];
    let mut out = vec![0.0; ncol];
    let g = fortran_grid(ncat, ncol);
    type P = *const f64;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let call = |g: &PressridgeGrid, a: P, v: P, a0: P, out: *mut f64| unsafe {
        pressridge_strength(g, a, v, a0, null(), null(), out, null_mut())
    };
    assert_eq!(
        call(&g, a.as_ptr(), v.as_ptr(), a0.as_ptr(), out.as_mut_ptr()),
        PRESSRIDGE_OK
    );
    assert_eq!(last_error(), "");

    // Null pointers.
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_strength(
                null(),
                a.as_ptr(),
                v.as_ptr(),
                null(),
                null(),
                null(),
                out.as_mut_ptr(),
                null_mut(),
            )
        },
        PRESSRIDGE_ERR_NULL_POINTER
    );
    assert!(last_error().contains("grid"), "{}", last_error());
    assert_eq!(
        call(&g, null(), v.as_ptr(), null(), out.as_mut_ptr()),
        PRESSRIDGE_ERR_NULL_POINTER
    );
    assert!(last_error().contains("aicen"));
    assert_eq!(
        call(&g, a.as_ptr(), v.as_ptr(), null(), null_mut()),
        PRESSRIDGE_ERR_NULL_POINTER
    );
    assert!(last_error().contains("strength"));
    // Misaligned pointer.
    let bytes = a.as_ptr().cast::<u8>();
    // SAFETY: one byte into the live array `a`, still inside it (only read by the entry point,
    // which refuses it as misaligned).
    let mis = unsafe { bytes.add(1) }.cast::<f64>();
    assert_eq!(
        call(
            &fortran_grid(1, 1),
            mis,
            v.as_ptr(),
            null(),
            out.as_mut_ptr()
        ),
        PRESSRIDGE_ERR_NULL_POINTER
    );
    assert!(last_error().contains("aligned"));

    // Sizes.
    for bad in [
        PressridgeGrid { ncat: 0, ..g },
        PressridgeGrid { ncol: -3, ..g },
        PressridgeGrid {
            len: g.len - 1,
            ..g
        },
        PressridgeGrid { len_1d: 3, ..g },
        PressridgeGrid { col_stride: 2, ..g },
        PressridgeGrid {
            col_stride_1d: 0,
            ..g
        },
    ] {
        assert_eq!(
            call(&bad, a.as_ptr(), v.as_ptr(), a0.as_ptr(), out.as_mut_ptr()),
            PRESSRIDGE_ERR_BAD_SIZE,
            "{bad:?}"
        );
        assert!(last_error().contains("grid"), "{}", last_error());
    }
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_grid_fortran(-1, 4, &mut PressridgeGrid { ..g }) },
        PRESSRIDGE_ERR_BAD_SIZE
    );
    // Output overlapping an input.
    assert_eq!(
        call(&g, a.as_ptr(), v.as_ptr(), a0.as_ptr(), a.as_mut_ptr()),
        PRESSRIDGE_ERR_BAD_SIZE
    );
    assert!(last_error().contains("overlap"));

    // Values: NaN, negative area, area sum, with the column index.
    a[2 * ncat + 1] = f64::NAN;
    assert_eq!(
        call(&g, a.as_ptr(), v.as_ptr(), a0.as_ptr(), out.as_mut_ptr()),
        PRESSRIDGE_ERR_NOT_FINITE
    );
    assert!(last_error().contains("column 2"), "{}", last_error());
    assert!(
        last_error().contains("Fortran column 3"),
        "{}",
        last_error()
    );
    assert_eq!(last_column(), 2);
    a[2 * ncat + 1] = -0.1;
    assert_eq!(
        call(&g, a.as_ptr(), v.as_ptr(), a0.as_ptr(), out.as_mut_ptr()),
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert!(last_error().contains("negative"), "{}", last_error());
    a[2 * ncat + 1] = 0.3;
    assert_eq!(
        call(&g, a.as_ptr(), v.as_ptr(), a0.as_ptr(), out.as_mut_ptr()),
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert!(last_error().contains("total area"), "{}", last_error());
    a[2 * ncat + 1] = 0.1;

    // Options.
    let mut o = default_options();
    o.participation = 7;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &g,
            a.as_ptr(),
            v.as_ptr(),
            a0.as_ptr(),
            null(),
            &o,
            out.as_mut_ptr(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    assert!(last_error().contains("participation"));
    let mut o = default_options();
    o.cf = f64::NAN;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &g,
            a.as_ptr(),
            v.as_ptr(),
            a0.as_ptr(),
            null(),
            &o,
            out.as_mut_ptr(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_NOT_FINITE, "{}", last_error());
    let mut o = default_options();
    o.params.rhow = 900.0;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &g,
            a.as_ptr(),
            v.as_ptr(),
            a0.as_ptr(),
            null(),
            &o,
            out.as_mut_ptr(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    assert!(last_error().contains("rhow"), "{}", last_error());
    let mut o = default_options();
    o.cf_source = PRESSRIDGE_CF_SOURCE_TABLE;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &g,
            a.as_ptr(),
            v.as_ptr(),
            a0.as_ptr(),
            null(),
            &o,
            out.as_mut_ptr(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_NULL_POINTER);
    assert!(last_error().contains("cf_table"));
    // Consistent densities changed together are accepted in any field order.
    let mut o = default_options();
    o.params.rhoi = 1100.0;
    o.params.rhow = 1200.0;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_strength(
            &g,
            a.as_ptr(),
            v.as_ptr(),
            a0.as_ptr(),
            null(),
            &o,
            out.as_mut_ptr(),
            null_mut(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    assert_eq!(last_column(), -1);
}

#[test]
fn string_outputs_follow_the_required_length_protocol() {
    let mut need = 0i64;
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_version(null_mut(), 0, &mut need) },
        PRESSRIDGE_ERR_BUFFER_TOO_SMALL
    );
    let v = env!("CARGO_PKG_VERSION");
    assert_eq!(need, v.len() as i64 + 1);
    let mut buf = [0x55u8; 3];
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_version(buf.as_mut_ptr().cast(), 3, &mut need) },
        PRESSRIDGE_ERR_BUFFER_TOO_SMALL
    );
    assert_eq!(
        &buf,
        &[v.as_bytes()[0], v.as_bytes()[1], 0],
        "truncated, NUL-terminated"
    );
    assert!(last_error().contains("too small"));
    let mut buf = vec![0u8; need as usize];
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_version(buf.as_mut_ptr().cast(), need, null_mut()) },
        PRESSRIDGE_OK
    );
    assert_eq!(&buf[..v.len()], v.as_bytes());
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_version(buf.as_mut_ptr().cast(), -1, null_mut()) },
        PRESSRIDGE_ERR_BAD_SIZE
    );
    let mut abi = 0;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    assert_eq!(unsafe { pressridge_abi_version(&mut abi) }, PRESSRIDGE_OK);
    assert_eq!(abi, PRESSRIDGE_ABI_VERSION);
    let mut name = [0u8; 64];
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    unsafe {
        pressridge_status_name(
            PRESSRIDGE_ERR_NOT_FINITE,
            name.as_mut_ptr().cast(),
            64,
            null_mut(),
        )
    };
    assert!(name.starts_with(b"PRESSRIDGE_ERR_NOT_FINITE\0"));
    // Reading the last error does not clear it.
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    unsafe { pressridge_abi_version(null_mut()) };
    assert!(last_error().contains("version"));
    assert!(last_error().contains("null"));
}

#[test]
fn ridge_step_matches_rust_api_and_conserves() {
    let g = sample_grid();
    let (ncat, ncol) = g.aicen.dim();
    let conv: Array1<f64> = g.divu.as_ref().unwrap().mapv(|x| f64::max(-x, 0.0));
    let shear = g.shear.clone().unwrap();
    let hin = category_bounds(&CategoryBounds::RoundNumbers, ncat).unwrap();
    let dt = 3600.0;

    let (mut ra, mut rv, mut ra0) = (g.aicen.clone(), g.vicen.clone(), g.aice0.clone().unwrap());
    let mut rates: [Array1<f64>; 5] = std::array::from_fn(|_| Array1::zeros(ncol));
    {
        let [c, o, d1, d2, dv] = &mut rates;
        ridge_batch(
            ra.view_mut(),
            rv.view_mut(),
            ra0.view_mut(),
            &hin,
            RidgeBatchForcing {
                convergence: conv.view(),
                shear: shear.view(),
                dt,
                valid: None,
            },
            &RidgeOptions::default(),
            RidgeRatesMut {
                closing: c.view_mut(),
                opening: o.view_mut(),
                dardg1dt: d1.view_mut(),
                dardg2dt: d2.view_mut(),
                dvirdgdt: dv.view_mut(),
                fill: f64::NAN,
            },
        )
        .unwrap();
    }

    let mut af = fortran_order(&g.aicen);
    let mut vf = fortran_order(&g.vicen);
    let vol0: f64 = vf.iter().sum();
    let mut a0 = g.aice0.clone().unwrap().to_vec();
    let mut closing = vec![0.0; ncol];
    let mut dvirdgdt = vec![0.0; ncol];
    let r = PressridgeRidgeRates {
        closing: closing.as_mut_ptr(),
        opening: null_mut(),
        dardg1dt: null_mut(),
        dardg2dt: null_mut(),
        dvirdgdt: dvirdgdt.as_mut_ptr(),
    };
    let grid = fortran_grid(ncat, ncol);
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridge_step(
            &grid,
            af.as_mut_ptr(),
            vf.as_mut_ptr(),
            a0.as_mut_ptr(),
            null(), // CICE default bounds
            0,
            conv.as_ptr(),
            shear.as_ptr(),
            dt,
            null(),
            null(),
            &r,
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    let want_a = fortran_order(&ra);
    let want_v = fortran_order(&rv);
    for (x, y) in af.iter().zip(&want_a).chain(vf.iter().zip(&want_v)) {
        assert_eq!(x.to_bits(), y.to_bits());
    }
    for c in 0..ncol {
        assert_eq!(a0[c].to_bits(), ra0[c].to_bits());
        assert_eq!(closing[c].to_bits(), rates[0][c].to_bits());
        assert_eq!(dvirdgdt[c].to_bits(), rates[4][c].to_bits());
    }
    let vol1: f64 = vf.iter().sum();
    assert!((vol1 - vol0).abs() <= 1e-12 * vol0);

    // Errors: wrong number of bounds, bad dt, output aliasing an input.
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let call = |af: &mut Vec<f64>, hin: *const f64, nb: i64, dt: f64, conv_p: *const f64| unsafe {
        pressridge_ridge_step(
            &grid,
            af.as_mut_ptr(),
            vf.clone().as_mut_ptr(),
            a0.clone().as_mut_ptr(),
            hin,
            nb,
            conv_p,
            shear.as_ptr(),
            dt,
            null(),
            null(),
            null(),
        )
    };
    let mut af2 = af.clone();
    assert_eq!(
        call(&mut af2, hin.as_ptr(), ncat as i64, dt, conv.as_ptr()),
        PRESSRIDGE_ERR_BAD_SIZE
    );
    assert!(last_error().contains("hin_max"));
    let bad_hin = [0.0, 1.0, 0.5, 2.0, 3.0, 4.0];
    assert_eq!(
        call(&mut af2, bad_hin.as_ptr(), 6, dt, conv.as_ptr()),
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert_eq!(
        call(&mut af2, hin.as_ptr(), 6, f64::NAN, conv.as_ptr()),
        PRESSRIDGE_ERR_NOT_FINITE
    );
    assert!(last_error().contains("dt"), "{}", last_error());
    assert_eq!(
        call(&mut af2, hin.as_ptr(), 6, dt, null()),
        PRESSRIDGE_ERR_NULL_POINTER
    );
    let alias = af2.as_ptr();
    assert_eq!(
        call(&mut af2, hin.as_ptr(), 6, dt, alias),
        PRESSRIDGE_ERR_BAD_SIZE
    );
    assert!(last_error().contains("overlap"));
}

#[test]
fn single_column_ridging_equals_the_batch_and_leaves_bad_columns_unchanged() {
    let g = sample_grid();
    let (ncat, ncol) = g.aicen.dim();
    let conv: Vec<f64> = g
        .divu
        .as_ref()
        .unwrap()
        .iter()
        .map(|x| f64::max(-x, 0.0))
        .collect();
    let shear = g.shear.clone().unwrap().to_vec();
    let mut ab = fortran_order(&g.aicen);
    let mut vb = fortran_order(&g.vicen);
    let mut a0b = g.aice0.clone().unwrap().to_vec();
    let mut cb = vec![0.0; ncol];
    let rb = PressridgeRidgeRates {
        closing: cb.as_mut_ptr(),
        opening: null_mut(),
        dardg1dt: null_mut(),
        dardg2dt: null_mut(),
        dvirdgdt: null_mut(),
    };
    let (mut a1, mut v1, mut a01) = (ab.clone(), vb.clone(), a0b.clone());
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridge_step(
            &fortran_grid(ncat, ncol),
            ab.as_mut_ptr(),
            vb.as_mut_ptr(),
            a0b.as_mut_ptr(),
            null(),
            0,
            conv.as_ptr(),
            shear.as_ptr(),
            1800.0,
            null(),
            null(),
            &rb,
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK);
    let g1 = fortran_grid(ncat, 1);
    for c in 0..ncol {
        let mut closing = f64::NAN;
        let r1 = PressridgeRidgeRates {
            closing: &mut closing,
            ..rb
        };
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe {
            pressridge_ridge_step(
                &g1,
                a1[c * ncat..].as_mut_ptr(),
                v1[c * ncat..].as_mut_ptr(),
                &mut a01[c],
                null(),
                0,
                &conv[c],
                &shear[c],
                1800.0,
                null(),
                null(),
                &r1,
            )
        };
        assert_eq!(rc, PRESSRIDGE_OK);
        assert_eq!(closing.to_bits(), cb[c].to_bits());
    }
    assert!(a1.iter().zip(&ab).all(|(x, y)| x.to_bits() == y.to_bits()));
    assert!(v1.iter().zip(&vb).all(|(x, y)| x.to_bits() == y.to_bits()));
    assert!(
        a01.iter()
            .zip(&a0b)
            .all(|(x, y)| x.to_bits() == y.to_bits())
    );
    // A bad column is left as it was.
    let mut a = [0.2, 0.2, f64::NAN, 0.1, 0.1];
    let mut v = [0.1; 5];
    let mut a0 = 0.3;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe {
        pressridge_ridge_step(
            &fortran_grid(5, 1),
            a.as_mut_ptr(),
            v.as_mut_ptr(),
            &mut a0,
            null(),
            0,
            &1e-6,
            &0.0,
            60.0,
            null(),
            null(),
            null(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_ERR_NOT_FINITE);
    assert_eq!((a[0], v[0], a0), (0.2, 0.1, 0.3));
}

#[test]
fn cf_tables_load_query_free() {
    let dir = common::scratch("ffi-cf");
    let path = dir.join("cf.nc");
    let t = CfTable::new(vec![0.2, 0.5, 1.0], vec![5.0, 10.0, 14.0]).unwrap();
    write_cf_table(&path, &t).unwrap();
    let p = path.to_str().unwrap();
    let mut h = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_open(p.as_ptr().cast(), p.len() as i64, &mut h) },
        PRESSRIDGE_OK
    );
    let mut n = 0;
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    assert_eq!(unsafe { pressridge_cf_table_len(h, &mut n) }, PRESSRIDGE_OK);
    assert_eq!(n, 3);
    let (mut th, mut cf) = ([0.0; 3], [0.0; 3]);
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_nodes(h, th.as_mut_ptr(), cf.as_mut_ptr(), 2) },
        PRESSRIDGE_ERR_BAD_SIZE
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_nodes(h, th.as_mut_ptr(), cf.as_mut_ptr(), 3) },
        PRESSRIDGE_OK
    );
    assert_eq!(th, [0.2, 0.5, 1.0]);
    assert_eq!(cf, [5.0, 10.0, 14.0]);
    let (mut c, mut clamped) = (0.0, -1);
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_lookup(h, 0.75, &mut c, &mut clamped) },
        PRESSRIDGE_OK
    );
    assert_eq!((c, clamped), (12.0, 0));
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_lookup(h, 3.0, &mut c, &mut clamped) },
        PRESSRIDGE_OK
    );
    assert_eq!((c, clamped), (14.0, 1));
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_lookup(h, f64::NAN, &mut c, null_mut()) },
        PRESSRIDGE_ERR_NOT_FINITE
    );
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    assert_eq!(unsafe { pressridge_cf_table_free(h) }, PRESSRIDGE_OK);
    assert_eq!(
        // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
        unsafe { pressridge_cf_table_free(null_mut()) },
        PRESSRIDGE_OK
    );

    // Unreadable tables.
    let missing = dir.join("nope.nc");
    let m = missing.to_str().unwrap();
    let mut h = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_open(m.as_ptr().cast(), m.len() as i64, &mut h) },
        PRESSRIDGE_ERR_IO
    );
    assert!(last_error().contains("nope.nc"), "{}", last_error());
    assert!(h.is_null());
    let sample = common::repo().join("data/sample_itd.nc");
    let sample = sample.to_str().unwrap();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_open(sample.as_ptr().cast(), sample.len() as i64, &mut h) },
        PRESSRIDGE_ERR_IO
    );
    assert!(last_error().contains("thickness"), "{}", last_error());
    let bad_utf8 = [0xffu8, 0xfe];
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_open(bad_utf8.as_ptr().cast(), 2, &mut h) },
        PRESSRIDGE_ERR_PARSE
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_open(null(), 2, &mut h) },
        PRESSRIDGE_ERR_NULL_POINTER
    );
    let unsorted = [1.0, 0.5];
    let mut h2 = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_new(unsorted.as_ptr(), unsorted.as_ptr(), 2, &mut h2) },
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_new(unsorted.as_ptr(), unsorted.as_ptr(), 0, &mut h2) },
        PRESSRIDGE_ERR_BAD_SIZE
    );
}

/// A small ridging lookup table in the layout `pressridge tabulate` writes.
fn write_ridge_table(path: &Path) {
    let mut f = netcdf::create_with(path, netcdf::Options::_64BIT_OFFSET).unwrap();
    f.add_dimension("set", 2).unwrap();
    f.add_dimension("thickness", 3).unwrap();
    f.add_dimension("volume", 2).unwrap();
    f.add_attribute("sets", "contact.mu=1; contact.mu=0.5")
        .unwrap();
    f.add_variable::<f64>("thickness", &["thickness"]).unwrap();
    f.add_variable::<f64>("volume", &["volume"]).unwrap();
    f.add_variable::<f64>("cf_by_set", &["set", "thickness"])
        .unwrap();
    f.add_variable::<f64>("work_mean", &["set", "thickness", "volume"])
        .unwrap();
    f.enddef().unwrap();
    f.variable_mut("thickness")
        .unwrap()
        .put_values(&[0.2, 0.3, 0.45], ..)
        .unwrap();
    f.variable_mut("volume")
        .unwrap()
        .put_values(&[0.0, 10.0], ..)
        .unwrap();
    f.variable_mut("cf_by_set")
        .unwrap()
        .put_values(&[10.0, 12.0, 14.0, 6.0, 7.0, 8.0], ..)
        .unwrap();
    let work: Vec<f64> = (0..12).map(|k| 1000.0 * k as f64).collect();
    f.variable_mut("work_mean")
        .unwrap()
        .put_values(&work, ..)
        .unwrap();
    f.close().unwrap();
}

#[test]
fn ridge_tables_load_query_and_give_cf_tables() {
    let dir = common::scratch("ffi-rt");
    let path = dir.join("table.nc");
    write_ridge_table(&path);
    let p = path.to_str().unwrap();
    let mut t = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_open(p.as_ptr().cast(), p.len() as i64, &mut t) },
        PRESSRIDGE_OK,
        "{}",
        last_error()
    );
    let (mut ns, mut nh, mut nv, mut nf) = (0, 0, 0, 0);
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_dims(t, &mut ns, &mut nh, &mut nv, &mut nf) },
        PRESSRIDGE_OK
    );
    assert_eq!((ns, nh, nv, nf), (2, 3, 2, 2));
    let mut th = [0.0; 3];
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_thickness(t, th.as_mut_ptr(), 3) },
        PRESSRIDGE_OK
    );
    assert_eq!(th, [0.2, 0.3, 0.45]);
    let mut vol = [0.0; 2];
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_volume(t, vol.as_mut_ptr(), 2) },
        PRESSRIDGE_OK
    );
    let name = |f: &dyn Fn(*mut c_char, i64, *mut i64) -> i32| {
        let mut need = 0;
        f(null_mut(), 0, &mut need);
        let mut b = vec![0u8; need as usize];
        assert_eq!(f(b.as_mut_ptr().cast(), need, null_mut()), PRESSRIDGE_OK);
        b.pop();
        String::from_utf8(b).unwrap()
    };
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        name(&|b, l, r| unsafe { pressridge_ridge_table_set_name(t, 1, b, l, r) }),
        "contact.mu=0.5"
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        name(&|b, l, r| unsafe { pressridge_ridge_table_variable_name(t, 1, b, l, r) }),
        "work_mean"
    );
    let (mut x, mut clamped) = (0.0, -1);
    let key = "work_mean";
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_ridge_table_value(
                t,
                key.as_ptr().cast(),
                9,
                1,
                0.3,
                5.0,
                &mut x,
                &mut clamped,
            )
        },
        PRESSRIDGE_OK
    );
    // Set 1, thickness node 1, halfway between volume nodes: (8000 + 9000)/2.
    assert_eq!((x, clamped), (8500.0, 0));
    let bad = "nope";
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_ridge_table_value(t, bad.as_ptr().cast(), 4, 0, 0.3, 5.0, &mut x, null_mut())
        },
        PRESSRIDGE_ERR_NOT_FOUND
    );
    assert!(last_error().contains("work_mean"), "lists the known fields");
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_ridge_table_value(t, key.as_ptr().cast(), 9, 2, 0.3, 5.0, &mut x, null_mut())
        },
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_ridge_table_value(
                t,
                key.as_ptr().cast(),
                9,
                -1,
                0.3,
                5.0,
                &mut x,
                null_mut(),
            )
        },
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_cf(t, 0, 1.0, &mut x, &mut clamped) },
        PRESSRIDGE_OK
    );
    assert_eq!((x, clamped), (14.0, 1));

    // The C_f of a set as a C_f table for the strength call.
    let mut cft = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_cf_table(t, 1, &mut cft) },
        PRESSRIDGE_OK
    );
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    assert_eq!(unsafe { pressridge_ridge_table_free(t) }, PRESSRIDGE_OK);
    let mut c = 0.0;
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_cf_table_lookup(cft, 0.3, &mut c, null_mut()) },
        PRESSRIDGE_OK
    );
    assert_eq!(c, 7.0);
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    assert_eq!(unsafe { pressridge_cf_table_free(cft) }, PRESSRIDGE_OK);

    let missing = dir.join("missing.nc");
    let m = missing.to_str().unwrap();
    let mut t = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_ridge_table_open(m.as_ptr().cast(), m.len() as i64, &mut t) },
        PRESSRIDGE_ERR_IO
    );
}

const TINY_SCENE: &str = "name = \"tiny\"\nduration = 0.05\n[pile]\nblocks = 4\ncolumns = 2\n";

#[test]
fn scene_runs_and_returns_its_summary() {
    let scene = pressridge::scene::Scene::from_toml(TINY_SCENE).unwrap();
    let want = pressridge::simulation::run(&scene, &mut |_| true)
        .unwrap()
        .summary;
    let mut run = null_mut();
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe {
            pressridge_scene_run(
                TINY_SCENE.as_ptr().cast(),
                TINY_SCENE.len() as i64,
                &mut run,
            )
        },
        PRESSRIDGE_OK,
        "{}",
        last_error()
    );
    let mut need = 0;
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_run_summary_json(run, null_mut(), 0, &mut need) },
        PRESSRIDGE_ERR_BUFFER_TOO_SMALL
    );
    let mut buf = vec![0u8; need as usize];
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_run_summary_json(run, buf.as_mut_ptr().cast(), need, &mut need) },
        PRESSRIDGE_OK
    );
    buf.pop();
    let got: pressridge::simulation::Summary = serde_json::from_slice(&buf).unwrap();
    assert_eq!(got.steps, want.steps);
    let (ge, we) = (got.energy(), want.energy());
    assert_eq!(ge.work.to_bits(), we.work.to_bits());
    assert_eq!(ge.potential_energy.to_bits(), we.potential_energy.to_bits());
    let mut x = 0.0;
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_run_summary_value(run, "steps".as_ptr().cast(), 5, &mut x) },
        PRESSRIDGE_OK
    );
    assert_eq!(x, want.steps as f64);
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_run_summary_value(run, "scene".as_ptr().cast(), 5, &mut x) },
        PRESSRIDGE_ERR_BAD_VALUE
    );
    assert_eq!(
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        unsafe { pressridge_run_summary_value(run, "nope".as_ptr().cast(), 4, &mut x) },
        PRESSRIDGE_ERR_NOT_FOUND
    );
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    assert_eq!(unsafe { pressridge_run_free(run) }, PRESSRIDGE_OK);

    for (text, code) in [
        ("duration = ", PRESSRIDGE_ERR_PARSE),
        ("durration = 1.0", PRESSRIDGE_ERR_PARSE),
        ("duration = -1.0", PRESSRIDGE_ERR_BAD_VALUE),
    ] {
        let mut run = null_mut();
        assert_eq!(
            // SAFETY: every non-null pointer is a live local or buffer of at least the length
            // passed; the entry point checks nulls, sizes and handles itself (the C ABI's
            // contract).
            unsafe { pressridge_scene_run(text.as_ptr().cast(), text.len() as i64, &mut run) },
            code,
            "{text}"
        );
        assert!(run.is_null());
    }
    assert!(last_error().contains("duration"), "{}", last_error());
}

#[test]
fn calls_from_many_threads_agree_and_keep_their_own_errors() {
    let (a, v, a0) = sample();
    let (ncat, ncol) = a.dim();
    let af = Arc::new(fortran_order(&a));
    let vf = Arc::new(fortran_order(&v));
    let a0 = Arc::new(a0.to_vec());
    let mut want = Array1::zeros(ncol);
    strength_batch(
        a.view(),
        v.view(),
        Some(ndarray::ArrayView1::from(&a0[..])),
        &StrengthOptions::default(),
        want.view_mut(),
    )
    .unwrap();
    let want = Arc::new(want);
    let handles: Vec<_> = (0..4)
        .map(|t| {
            let (af, vf, a0, want) = (af.clone(), vf.clone(), a0.clone(), want.clone());
            std::thread::spawn(move || {
                for rep in 0..20 {
                    if (t + rep) % 3 == 0 {
                        // An error on this thread, with its own message.
                        let bad = [f64::NAN; 5];
                        let g = fortran_grid(5, 1);
                        let mut out = [0.0];
                        // SAFETY: every non-null pointer is a live local or buffer of at least the
                        // length passed; the entry point checks nulls, sizes and handles itself
                        // (the C ABI's contract).
                        let rc = unsafe {
                            pressridge_strength(
                                &g,
                                bad.as_ptr(),
                                bad.as_ptr(),
                                null(),
                                null(),
                                null(),
                                out.as_mut_ptr(),
                                null_mut(),
                            )
                        };
                        assert_eq!(rc, PRESSRIDGE_ERR_NOT_FINITE);
                        assert!(last_error().contains("not finite"));
                    } else {
                        let g = fortran_grid(ncat, ncol);
                        let mut out = vec![0.0; ncol];
                        // SAFETY: every non-null pointer is a live local or buffer of at least the
                        // length passed; the entry point checks nulls, sizes and handles itself
                        // (the C ABI's contract).
                        let rc = unsafe {
                            pressridge_strength(
                                &g,
                                af.as_ptr(),
                                vf.as_ptr(),
                                a0.as_ptr(),
                                null(),
                                null(),
                                out.as_mut_ptr(),
                                null_mut(),
                            )
                        };
                        assert_eq!(rc, PRESSRIDGE_OK);
                        assert_eq!(last_error(), "", "another thread's error is not seen");
                        assert!(
                            out.iter()
                                .zip(want.iter())
                                .all(|(x, y)| x.to_bits() == y.to_bits())
                        );
                    }
                }
            })
        })
        .collect();
    for h in handles {
        h.join().unwrap();
    }
}

/// A C_f table handle shared by the threads of a test.
#[derive(Clone, Copy)]
struct SharedTable(*const PressridgeCfTable);
// SAFETY: a C_f table is never changed after it is made and may be read from any thread (the
// C ABI's contract, docs/c-api.md); the test frees it only after joining every thread.
unsafe impl Send for SharedTable {}
// SAFETY: as for `Send`: the threads only read through the handle.
unsafe impl Sync for SharedTable {}

/// The per-cell option sets of the thread test: CICE's defaults, Thorndike/uniform, Hibler's
/// strength, another constant C_f, C_f from a shared table, and a changed parameter.
fn cell_options(k: usize, table: SharedTable) -> PressridgeOptions {
    let mut o = default_options();
    match k {
        1 => {
            o.participation = PRESSRIDGE_PARTICIPATION_THORNDIKE;
            o.redistribution = PRESSRIDGE_REDISTRIBUTION_UNIFORM;
        }
        2 => o.strength_law = PRESSRIDGE_STRENGTH_HIBLER1979,
        3 => o.cf = 12.0,
        4 => {
            o.cf_source = PRESSRIDGE_CF_SOURCE_TABLE;
            o.cf_table = table.0;
        }
        5 => o.params.mu_rdg = 4.0,
        _ => {}
    }
    o
}

/// Strength (N/m) of one cell through `pressridge_strength_cell`, and the same column after
/// one area-only ridging step (`pressridge_ridge_step` on a one-column grid), with the option
/// set `k`, over the first `ncat` categories of the column.
fn cell_results(a: &[f64], v: &[f64], ncat: usize, k: usize, table: SharedTable) -> Vec<u64> {
    let o = cell_options(k, table);
    let a0 = 1.0 - a[..ncat].iter().sum::<f64>();
    let mut p = f64::NAN;
    // SAFETY: `a` and `v` hold at least `ncat` values, `o` and `p` are live locals; the table
    // handle outlives every call (freed after the threads are joined).
    let rc =
        unsafe { pressridge_strength_cell(ncat as i64, a.as_ptr(), v.as_ptr(), a0, &o, &mut p) };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    let (mut ra, mut rv, mut ra0) = (a[..ncat].to_vec(), v[..ncat].to_vec(), [a0]);
    let (conv, shear) = ([2e-6], [3e-6]);
    // SAFETY: as above; the one-column grid matches the buffers' lengths.
    let rc = unsafe {
        pressridge_ridge_step(
            &fortran_grid(ncat, 1),
            ra.as_mut_ptr(),
            rv.as_mut_ptr(),
            ra0.as_mut_ptr(),
            null(),
            0,
            conv.as_ptr(),
            shear.as_ptr(),
            3600.0,
            null(),
            &o,
            null(),
        )
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    std::iter::once(p)
        .chain(ra)
        .chain(rv)
        .chain(ra0)
        .map(f64::to_bits)
        .collect()
}

/// The per-cell entry points from 16 threads at once, each changing its options (six sets,
/// a shared C_f table among them) and its number of categories (5 and 3) from call to call,
/// give what one thread gives calling them one after the other: the per-thread options
/// cache and scratch space never mix threads or stale options. (Under Miri,
/// `scripts/check-ub.sh`, its data-race detector watches the same calls.)
#[test]
fn per_cell_calls_from_16_threads_with_changing_options_equal_a_serial_run() {
    let (a, v, _) = sample();
    // Columns of pack ice (open water below Thorndike's G* = 0.15, so that every option set
    // gives its own strength).
    let cols: Arc<Vec<(Vec<f64>, Vec<f64>)>> = Arc::new(
        (0..a.ncols())
            .filter(|&c| a.column(c).sum() > 0.9)
            .take(if cfg!(miri) { 2 } else { 120 })
            .map(|c| (a.column(c).to_vec(), v.column(c).to_vec()))
            .collect(),
    );
    let ncol = cols.len();
    assert!(ncol >= 2);
    let mut handle = null_mut();
    let (h, c) = ([0.5, 2.0, 4.0], [9.0, 14.0, 21.0]);
    // SAFETY: `h` and `c` hold 3 values; `handle` is a live local.
    let rc = unsafe { pressridge_cf_table_new(h.as_ptr(), c.as_ptr(), 3, &mut handle) };
    assert_eq!(rc, PRESSRIDGE_OK);
    let table = SharedTable(handle);
    let sets = 6;
    let key = move |c: usize, k: usize, three: bool| (c * sets + k) * 2 + usize::from(three);
    let mut want = vec![Vec::new(); ncol * sets * 2];
    for (c, (a, v)) in cols.iter().enumerate() {
        for k in 0..sets {
            for three in [false, true] {
                want[key(c, k, three)] = cell_results(a, v, if three { 3 } else { 5 }, k, table);
            }
        }
    }
    // Every option set gives its own strength.
    let p: Vec<u64> = (0..sets).map(|k| want[key(0, k, false)][0]).collect();
    assert!((1..sets).all(|k| !p[..k].contains(&p[k])), "{p:?}");
    let want = Arc::new(want);
    let calls = ncol * sets * 2;
    let handles: Vec<_> = (0..16)
        .map(|t| {
            let (cols, want) = (cols.clone(), want.clone());
            std::thread::spawn(move || {
                // Under Miri (scripts/check-ub.sh) a share of them: each call is interpreted.
                for i in 0..if cfg!(miri) { 6 } else { calls } {
                    // Each thread walks the calls in its own order, so that neighbouring calls
                    // of one thread differ in options, categories and column.
                    let j = (i * 7 + t * 13) % calls;
                    let (c, k, three) = (j / (sets * 2), (j / 2) % sets, j % 2 == 1);
                    let (a, v) = &cols[c];
                    let got = cell_results(a, v, if three { 3 } else { 5 }, k, table);
                    assert_eq!(
                        got,
                        want[key(c, k, three)],
                        "thread {t}, column {c}, set {k}"
                    );
                }
            })
        })
        .collect();
    for h in handles {
        h.join().unwrap();
    }
    // SAFETY: the handle came from pressridge_cf_table_new and no thread uses it any more.
    assert_eq!(unsafe { pressridge_cf_table_free(handle) }, PRESSRIDGE_OK);
}

#[test]
fn preset_constants_match_the_library() {
    use pressridge::itd::details::CfPreset;
    assert_eq!(PRESSRIDGE_CF_HIBLER1980, CfPreset::Hibler1980.value());
    assert_eq!(PRESSRIDGE_CF_FLATO1991, CfPreset::Flato1991.value());
    assert_eq!(PRESSRIDGE_CF_CICE, CfPreset::Cice.value());
    let o = default_options();
    let d = pressridge::itd::ItdParams::default();
    assert_eq!(o.params.mu_rdg, d.mu_rdg);
    assert_eq!(o.params.nitermax, d.nitermax as i64);
    assert_eq!(o.cf, 17.0);
    assert_eq!(o.participation, PRESSRIDGE_PARTICIPATION_EXPONENTIAL);
    assert_eq!(o.strength_law, PRESSRIDGE_STRENGTH_ROTHROCK);
}

#[test]
fn ice_thicker_than_any_is_refused_on_every_path() {
    // vicen = 1e160 m overflowed the squares of the strength into NaN (issue 16); 0.1 m of ice
    // on 7e-9 of area, 10⁷ m thick, made h_min + puny round to h_min and ⟨h_r²⟩ 0/0 under
    // PRESSRIDGE_OK (a fuzzing find, fuzz/findings/strength_cell/). Every path refuses both,
    // naming the variable and the category.
    for (a, v, what) in [
        ([0.5, 0.3], [1e160, 0.6], "vicen"),
        ([7e-9, 0.8], [0.1, 0.6], "vicen/aicen"),
    ] {
        let a0 = 1.0 - a[0] - a[1];
        let mut q = 0.0;
        // SAFETY: every non-null pointer is a live local or buffer of at least the length
        // passed; the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe { pressridge_strength_cell(2, a.as_ptr(), v.as_ptr(), a0, null(), &mut q) };
        assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE, "{what}: strength {q}");
        let e = last_error();
        assert!(
            e.contains(&format!("{what}[category 0]")) && e.contains("1000"),
            "{e}"
        );
        // The batched grid call with 16 columns (the 8-lane kernel), one of them too thick.
        let ncol = 16;
        let (mut af, mut vf, mut a0s) = (Vec::new(), Vec::new(), Vec::new());
        for c in 0..ncol {
            let bad = c == 11;
            af.extend_from_slice(if bad { &a } else { &[0.5, 0.3] });
            vf.extend_from_slice(if bad { &v } else { &[0.5, 0.6] });
            a0s.push(if bad { a0 } else { 0.2 });
        }
        let mut out = vec![0.0; ncol];
        // SAFETY: every non-null pointer is a live local or buffer of at least the length
        // passed; the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe {
            pressridge_strength(
                &fortran_grid(2, ncol),
                af.as_ptr(),
                vf.as_ptr(),
                a0s.as_ptr(),
                null(),
                null(),
                out.as_mut_ptr(),
                null_mut(),
            )
        };
        assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE, "{what}");
        assert_eq!(last_column(), 11);
        assert!(last_error().contains(what), "{}", last_error());
    }
    // The sliver's volume on an area at puny or below is not ice the strength sees: computed.
    let (a, v) = ([1e-12, 0.8], [0.1, 0.6]);
    let mut q = f64::NAN;
    // SAFETY: as above.
    let rc =
        unsafe { pressridge_strength_cell(2, a.as_ptr(), v.as_ptr(), 0.2 - 1e-12, null(), &mut q) };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    assert!(q.is_finite());
}
