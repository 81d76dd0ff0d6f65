//! μ_rdg tables through the C ABI (issue 34): Lipscomb's e-folding parameter against the
//! ridging ice's thickness, for `PRESSRIDGE_REDISTRIBUTION_TABLE`, as opaque handles.

use std::ffi::c_char;
use std::path::Path;

use super::layout::check_ptr;
use super::tables::friction_arg;
use super::{FfiError, PRESSRIDGE_ERR_BAD_SIZE, guard, put, read_path};
use pressridge::io::itd_netcdf::read_mu_rdg_table_at_friction;
use pressridge::itd::details::MuRdgTable;

/// A μ_rdg table: μ_rdg (m^½) against the ridging ice's thickness (m), linear between nodes,
/// held at the end values outside them (and counted). Opaque; create with
/// [`pressridge_mu_rdg_table_open`] or [`pressridge_mu_rdg_table_new`], release with
/// [`pressridge_mu_rdg_table_free`]; give it to the strength and ridging calls in
/// `PressridgeOptions::mu_rdg_table` with `redistribution = PRESSRIDGE_REDISTRIBUTION_TABLE`.
#[derive(Debug)]
pub struct PressridgeMuRdgTable {
    pub(crate) table: MuRdgTable,
}

/// Opens the μ_rdg (`mu_rdg`, m^½) at friction `mu` (between blocks above the water line) and
/// `mu_w` (below it; both dimensionless) of a ridging table written by `pressridge tabulate`
/// from records with ridge columns. `path` is `path_len` bytes of UTF-8 (no NUL needed). On
/// success `*table` is a new handle; a table without `mu_rdg`, or without that friction pair,
/// is an error saying so.
///
/// # Safety
/// `path` must be valid for `path_len` bytes; `table` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_mu_rdg_table_open(
    path: *const c_char,
    path_len: i64,
    mu: f64,
    mu_w: f64,
    table: *mut *mut PressridgeMuRdgTable,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        let p = read_path(path, path_len, "path")?;
        let friction = (friction_arg(mu, "mu")?, friction_arg(mu_w, "mu_w")?);
        let t = read_mu_rdg_table_at_friction(Path::new(p), Some(friction))?;
        let h = Box::into_raw(Box::new(PressridgeMuRdgTable { table: t }));
        put(table, h, "table")
    })
}

/// A μ_rdg table from `n` nodes (1 to 32): `thickness` (m, finite, strictly increasing) and
/// `mu_rdg` (m^½, in (0, 50]). On success `*table` is a new handle.
///
/// # Safety
/// `thickness` and `mu_rdg` must be valid for `n` reads; `table` for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_mu_rdg_table_new(
    thickness: *const f64,
    mu_rdg: *const f64,
    n: i64,
    table: *mut *mut PressridgeMuRdgTable,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        check_ptr(thickness, "thickness")?;
        check_ptr(mu_rdg, "mu_rdg")?;
        if n <= 0 {
            return Err(FfiError::new(
                PRESSRIDGE_ERR_BAD_SIZE,
                format!("n = {n} must be positive"),
            ));
        }
        let h = std::slice::from_raw_parts(thickness, n as usize);
        let m = std::slice::from_raw_parts(mu_rdg, n as usize);
        let t = MuRdgTable::new(h, m)?;
        put(
            table,
            Box::into_raw(Box::new(PressridgeMuRdgTable { table: t })),
            "table",
        )
    })
}

/// μ_rdg (m^½) of a table at thickness `h` (m) into `*mu_rdg`, and into `*clamped` 1 where `h`
/// lay outside the nodes (the end value is used), else 0.
///
/// # Safety
/// `table` must be a live handle; `mu_rdg`, `clamped` valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_mu_rdg_table_lookup(
    table: *const PressridgeMuRdgTable,
    h: f64,
    mu_rdg: *mut f64,
    clamped: *mut i32,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        let l = (*table).table.lookup(h);
        put(mu_rdg, l.value, "mu_rdg")?;
        put(clamped, i32::from(l.clamped), "clamped")
    })
}

/// Releases a μ_rdg table handle (null is accepted and ignored). Options that refer to it
/// must not be used afterwards; calls running on other threads must have returned.
///
/// # Safety
/// `table` must be null or a handle not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_mu_rdg_table_free(table: *mut PressridgeMuRdgTable) -> i32 {
    guard(|| {
        if !table.is_null() {
            // SAFETY: a handle from Box::into_raw, freed once (caller promise).
            drop(unsafe { Box::from_raw(table) });
        }
        Ok(())
    })
}
