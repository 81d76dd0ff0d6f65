//! μ_rdg tables through the C ABI (issue 34): `PRESSRIDGE_REDISTRIBUTION_TABLE` with a
//! `PressridgeMuRdgTable` handle gives, for a table of one value, the bits of that constant
//! μ_rdg in the per-cell strength (whose options cache must not keep a handle), and the
//! handles' errors are codes with messages.

#[path = "../../../tests/common/mod.rs"]
mod common;
mod support;

use support::last_error;

use std::ptr::null_mut;

use pressridge_capi::itd::*;
use pressridge_capi::mu_rdg_table::*;
use pressridge_capi::*;

fn options() -> PressridgeOptions {
    let mut o = std::mem::MaybeUninit::uninit();
    // SAFETY: `o` is valid for one write.
    let rc = unsafe { pressridge_options_default(o.as_mut_ptr()) };
    assert_eq!(rc, PRESSRIDGE_OK);
    // SAFETY: filled by the call above.
    unsafe { o.assume_init() }
}

fn cell(a: &[f64], v: &[f64], a0: f64, o: &PressridgeOptions) -> f64 {
    let mut p = f64::NAN;
    // SAFETY: `a`, `v` hold `a.len()` values, `o` and `p` are live locals.
    let rc =
        unsafe { pressridge_strength_cell(a.len() as i64, a.as_ptr(), v.as_ptr(), a0, o, &mut p) };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    p
}

#[test]
fn a_table_handle_of_one_value_is_that_mu_rdg() {
    let (h, m) = ([1e-3, 1e3], [2.0, 2.0]);
    let mut t = null_mut();
    // SAFETY: two nodes each, `t` a live local.
    let rc = unsafe { pressridge_mu_rdg_table_new(h.as_ptr(), m.as_ptr(), 2, &mut t) };
    assert_eq!(rc, PRESSRIDGE_OK);
    let mut with = options();
    with.redistribution = PRESSRIDGE_REDISTRIBUTION_TABLE;
    with.mu_rdg_table = t;
    let mut constant = options();
    constant.params.mu_rdg = 2.0;
    let (a, v) = ([0.2, 0.3, 0.2], [0.1, 0.6, 0.9]);
    // Alternating calls: the per-cell cache may keep neither the handle nor a stale result.
    for _ in 0..3 {
        let x = cell(&a, &v, 0.3, &with);
        let y = cell(&a, &v, 0.3, &constant);
        assert_eq!(x.to_bits(), y.to_bits());
        assert_ne!(x, cell(&a, &v, 0.3, &options()), "μ_rdg = 3 differs");
    }
    let (mut mu, mut clamped) = (0.0, -1);
    // SAFETY: `t` is live; the outputs are locals.
    let rc = unsafe { pressridge_mu_rdg_table_lookup(t, 5e3, &mut mu, &mut clamped) };
    assert_eq!(rc, PRESSRIDGE_OK);
    assert_eq!((mu, clamped), (2.0, 1));
    // SAFETY: freed once.
    assert_eq!(unsafe { pressridge_mu_rdg_table_free(t) }, PRESSRIDGE_OK);
}

#[test]
fn handle_errors_in_memory_are_codes_with_messages() {
    let mut o = options();
    o.redistribution = PRESSRIDGE_REDISTRIBUTION_TABLE;
    let mut p = 0.0;
    let (a, v) = ([0.5], [0.5]);
    // SAFETY: a one-category column; `o` has a null table, which the call must refuse.
    let rc = unsafe { pressridge_strength_cell(1, a.as_ptr(), v.as_ptr(), 0.5, &o, &mut p) };
    assert_eq!(rc, PRESSRIDGE_ERR_NULL_POINTER);
    assert!(last_error().contains("mu_rdg_table"), "{}", last_error());
    o.redistribution = 7;
    // SAFETY: as above.
    let rc = unsafe { pressridge_strength_cell(1, a.as_ptr(), v.as_ptr(), 0.5, &o, &mut p) };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    assert!(last_error().contains("2 (table)"), "{}", last_error());
    let mut t = null_mut();
    let bad = [1.0, 0.5];
    // SAFETY: two nodes; `t` a live local.
    let rc = unsafe { pressridge_mu_rdg_table_new(bad.as_ptr(), bad.as_ptr(), 2, &mut t) };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    assert!(t.is_null() && last_error().contains("strictly increasing"));
}

/// The NetCDF half of the handle: apart, so that Miri (which cannot call the NetCDF C
/// library) runs the tests above (`scripts/check-ub.sh miri`).
#[test]
fn tables_from_files_open_look_up_and_name_what_is_missing() {
    let mut t = null_mut();
    // A ridging table without `mu_rdg` (records without ridge columns) says so.
    let dir = common::scratch("ffi-mu-rdg");
    let old = dir.join("no-mu-rdg.nc");
    common::write_table_without_mu_rdg(&old, &[0.2, 0.3]);
    let path = old.to_str().unwrap();
    // SAFETY: `path` holds `path.len()` bytes; `t` a live local.
    let rc = unsafe {
        pressridge_mu_rdg_table_open(path.as_ptr().cast(), path.len() as i64, 1.0, 0.6, &mut t)
    };
    assert_ne!(rc, PRESSRIDGE_OK);
    assert!(last_error().contains("ridge columns"), "{}", last_error());
    // The shipped table holds the simulated μ_rdg at the Figure 5 friction.
    let path = common::repo().join("data/ridging_table.nc");
    let path = path.to_str().unwrap();
    // SAFETY: as above.
    let rc = unsafe {
        pressridge_mu_rdg_table_open(path.as_ptr().cast(), path.len() as i64, 1.0, 0.6, &mut t)
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    let (mut mu, mut clamped) = (0.0, -1);
    // SAFETY: `t` is live.
    unsafe { pressridge_mu_rdg_table_lookup(t, 1.0, &mut mu, &mut clamped) };
    assert!((1.0..4.0).contains(&mu) && clamped == 0, "{mu} {clamped}");
    // SAFETY: `t` came from the open above and is freed once.
    unsafe { pressridge_mu_rdg_table_free(t) };
    t = null_mut();
    // A file's table at a friction pair it holds.
    let f = dir.join("t.nc");
    common::write_mu_rdg_table(&f, &[0.2, 2.0], [&[1.0, 2.0], &[3.0, 4.0]]);
    let f = f.to_str().unwrap();
    // SAFETY: as above.
    let rc = unsafe {
        pressridge_mu_rdg_table_open(f.as_ptr().cast(), f.len() as i64, 0.4, 0.6, &mut t)
    };
    assert_eq!(rc, PRESSRIDGE_OK, "{}", last_error());
    let (mut mu, mut clamped) = (0.0, -1);
    // SAFETY: `t` is live.
    unsafe { pressridge_mu_rdg_table_lookup(t, 1.1, &mut mu, &mut clamped) };
    assert_eq!((mu, clamped), (1.5, 0));
    // SAFETY: freed once; null is accepted.
    unsafe {
        pressridge_mu_rdg_table_free(t);
        pressridge_mu_rdg_table_free(null_mut());
    }
}
