//! Failure behaviour of the C ABI (docs/failure.md): a path with a NUL inside and a scene
//! that would run no step are refused with the parameter named; the command line's failure
//! tests are `crates/cli/tests/failure.rs`, the library's the root package's
//! `tests/failure.rs`.

#[path = "../../../tests/common/mod.rs"]
mod common;

mod support;

use common::scratch;
use support::last_error;

#[test]
fn c_abi_refuses_paths_with_nul_and_runs_of_no_step() {
    use pressridge_capi::scene::{pressridge_run_free, pressridge_scene_run};
    use pressridge_capi::tables::{pressridge_cf_table_free, pressridge_cf_table_open};
    use pressridge_capi::{PRESSRIDGE_ERR_BAD_VALUE, PRESSRIDGE_OK};
    let d = scratch("ffi");
    let path = d.join("cf.nc");
    let t = pressridge::itd::details::CfTable::new(vec![0.2, 1.0], vec![5.0, 14.0]).unwrap();
    pressridge::io::itd_netcdf::write_cf_table(&path, &t).unwrap();
    // The file exists under the part before the NUL: the old code opened it.
    let p = format!("{}\0.other", path.display());
    let mut h = std::ptr::null_mut();
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe { pressridge_cf_table_open(p.as_ptr().cast(), p.len() as i64, &mut h) };
    assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
    assert!(last_error().contains("NUL"), "{}", last_error());
    assert!(h.is_null());
    let p = path.to_str().unwrap();
    // SAFETY: every non-null pointer is a live local or buffer of at least the length passed; the
    // entry point checks nulls, sizes and handles itself (the C ABI's contract).
    let rc = unsafe { pressridge_cf_table_open(p.as_ptr().cast(), p.len() as i64, &mut h) };
    assert_eq!(rc, PRESSRIDGE_OK);
    // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
    unsafe { pressridge_cf_table_free(h) };
    for (text, key) in [
        (
            "duration = 0.1\n[numerics]\ntime_step = 0.5\n",
            "numerics.time_step",
        ),
        ("duration = 1e-7\n[pile]\nblocks = 4\n", "duration"),
        // No free body: nothing sets a stable step.
        ("duration = 1.0\n", "numerics.time_step"),
    ] {
        let mut run = std::ptr::null_mut();
        // SAFETY: every non-null pointer is a live local or buffer of at least the length passed;
        // the entry point checks nulls, sizes and handles itself (the C ABI's contract).
        let rc = unsafe { pressridge_scene_run(text.as_ptr().cast(), text.len() as i64, &mut run) };
        assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE, "{text}");
        let e = last_error();
        assert!(
            e.contains(key) && (e.contains("no step") || e.contains("stable step")),
            "{e}"
        );
        // SAFETY: a handle from its *_new/*_open (or null), freed once and not used after.
        unsafe { pressridge_run_free(run) };
    }
    let _ = std::fs::remove_dir_all(&d);
}
