//! Lookup tables through the C ABI: C_f tables (`thickness`, `cf`) and ridging lookup
//! tables written by `pressridge tabulate`, as opaque handles.

use std::ffi::c_char;
use std::path::Path;
use std::sync::Arc;

use super::layout::check_ptr;
use super::{
    FfiError, FfiResult, PRESSRIDGE_ERR_BAD_SIZE, PRESSRIDGE_ERR_BAD_VALUE, guard, put, read_path,
    read_string, write_string,
};
use pressridge::io::itd_netcdf::read_cf_table_at_friction;
use pressridge::itd::details::{CfProvider, CfTable};
use pressridge::table::lookup::RidgeLookup;

/// A C_f table: C_f (dimensionless) against the ridging ice's thickness (m), linear between
/// nodes, clamped (and flagged) outside. Opaque; create with [`pressridge_cf_table_open`] or
/// [`pressridge_cf_table_new`], release with [`pressridge_cf_table_free`].
#[derive(Debug)]
pub struct PressridgeCfTable {
    pub(crate) table: Arc<CfTable>,
}

/// A ridging lookup table (fields on set × thickness × volume) as `pressridge tabulate`
/// writes it. Opaque; create with [`pressridge_ridge_table_open`], release with
/// [`pressridge_ridge_table_free`].
#[derive(Debug)]
pub struct PressridgeRidgeTable {
    table: RidgeLookup,
    /// Field names in the order of [`pressridge_ridge_table_variable_name`].
    names: Vec<String>,
}

/// # Safety
/// `t` must be null or a live handle.
unsafe fn handle<'a, T>(t: *const T, what: &str) -> FfiResult<&'a T> {
    check_ptr(t, what)?;
    // SAFETY: non-null and aligned; a live handle is the caller's promise.
    Ok(unsafe { &*t })
}

fn index(i: i64, n: usize, what: &str) -> FfiResult<usize> {
    if i < 0 || i as u64 >= n as u64 {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_VALUE,
            format!("{what} = {i} is out of range 0..{n} (indices count from 0)"),
        ));
    }
    Ok(i as usize)
}

/// Copies `src` into the caller's array `dst` of `len` elements (`len` ≥ `src.len()`).
///
/// # Safety
/// `dst` must be valid for `len` writes.
unsafe fn copy_out(src: &[f64], dst: *mut f64, len: i64, what: &str) -> FfiResult<()> {
    check_ptr(dst, what)?;
    if len < src.len() as i64 {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_SIZE,
            format!(
                "{what} has room for {len} values but {} are needed",
                src.len()
            ),
        ));
    }
    // SAFETY: checked non-null, aligned and long enough.
    unsafe { std::ptr::copy_nonoverlapping(src.as_ptr(), dst, src.len()) };
    Ok(())
}

/// Opens a C_f table from a NetCDF file with 1-D variables `thickness` (m, strictly
/// increasing) and `cf` (dimensionless, > 0) — a plain C_f table, or a ridging table of
/// `pressridge tabulate`, of which it takes the C_f at the default friction μ = 1.0,
/// μ_w = 0.6 ([`pressridge_cf_table_open_at_friction`] chooses another). `path` is
/// `path_len` bytes of UTF-8 (no NUL needed). On success `*table` is a new handle.
///
/// # Safety
/// `path` must be valid for `path_len` bytes; `table` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_open(
    path: *const c_char,
    path_len: i64,
    table: *mut *mut PressridgeCfTable,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        let p = read_path(path, path_len, "path")?;
        let t = read_cf_table_at_friction(Path::new(p), None)?;
        let h = Box::into_raw(Box::new(PressridgeCfTable { table: Arc::new(t) }));
        put(table, h, "table")
    })
}

/// Checks a friction coefficient given through the C ABI (dimensionless, finite, ≥ 0).
pub(super) fn friction_arg(x: f64, name: &str) -> FfiResult<f64> {
    if x.is_finite() && x >= 0.0 {
        Ok(x)
    } else {
        Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_VALUE,
            format!("{name} = {x}: a friction coefficient must be finite and non-negative"),
        ))
    }
}

/// Opens the C_f at friction `mu` (between blocks above the water line) and `mu_w` (below
/// it; both dimensionless) of a ridging table written by `pressridge tabulate`: the set with
/// that friction pair (equal to 1e-9), or [`super::PRESSRIDGE_ERR_NOT_FOUND`] with a message
/// listing the pairs the table has. A plain C_f table is accepted only when its `cf`
/// attributes `mu`, `mu_w` say it is for that pair. The handle remembers the pair
/// ([`pressridge_cf_table_friction`]).
///
/// # Safety
/// `path` must be valid for `path_len` bytes; `table` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_open_at_friction(
    path: *const c_char,
    path_len: i64,
    mu: f64,
    mu_w: f64,
    table: *mut *mut PressridgeCfTable,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        let p = read_path(path, path_len, "path")?;
        let friction = (friction_arg(mu, "mu")?, friction_arg(mu_w, "mu_w")?);
        let t = read_cf_table_at_friction(Path::new(p), Some(friction))?;
        let h = Box::into_raw(Box::new(PressridgeCfTable { table: Arc::new(t) }));
        put(table, h, "table")
    })
}

/// The friction pair a C_f table is for, μ into `*mu` and μ_w into `*mu_w`
/// (dimensionless), and into `*known` 1 — or NaN, NaN and 0 when the table does not say
/// (a table from nodes, or a plain file without `mu`, `mu_w` attributes).
///
/// # Safety
/// `table` must be a live handle; `mu`, `mu_w`, `known` valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_friction(
    table: *const PressridgeCfTable,
    mu: *mut f64,
    mu_w: *mut f64,
    known: *mut i32,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        let f = t.table.friction();
        let (a, b) = f.unwrap_or((f64::NAN, f64::NAN));
        put(mu, a, "mu")?;
        put(mu_w, b, "mu_w")?;
        put(known, i32::from(f.is_some()), "known")
    })
}

/// A C_f table from `n` nodes: `thickness` (m, finite, strictly increasing) and `cf`
/// (dimensionless, finite, > 0). On success `*table` is a new handle.
///
/// # Safety
/// `thickness` and `cf` must be valid for `n` reads; `table` for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_new(
    thickness: *const f64,
    cf: *const f64,
    n: i64,
    table: *mut *mut PressridgeCfTable,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        check_ptr(thickness, "thickness")?;
        check_ptr(cf, "cf")?;
        if n <= 0 {
            return Err(FfiError::new(
                PRESSRIDGE_ERR_BAD_SIZE,
                format!("n = {n} must be positive"),
            ));
        }
        let h = std::slice::from_raw_parts(thickness, n as usize).to_vec();
        let c = std::slice::from_raw_parts(cf, n as usize).to_vec();
        let t = CfTable::new(h, c)?;
        let h = Box::into_raw(Box::new(PressridgeCfTable { table: Arc::new(t) }));
        put(table, h, "table")
    })
}

/// Number of nodes of a C_f table into `*n`.
///
/// # Safety
/// `table` must be a live handle; `n` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_len(
    table: *const PressridgeCfTable,
    n: *mut i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        put(n, t.table.thickness().len() as i64, "n")
    })
}

/// Copies the nodes of a C_f table: `thickness` (m) and `cf` (dimensionless), each with room
/// for `len` ≥ [`pressridge_cf_table_len`] values.
///
/// # Safety
/// `table` must be a live handle; `thickness` and `cf` valid for `len` writes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_nodes(
    table: *const PressridgeCfTable,
    thickness: *mut f64,
    cf: *mut f64,
    len: i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        copy_out(t.table.thickness(), thickness, len, "thickness")?;
        copy_out(t.table.values(), cf, len, "cf")
    })
}

/// C_f (dimensionless) for ridging ice of thickness `h` (m) into `*cf`, and into `*clamped`
/// (may be null) 1 when `h` lay outside the table and the end value was used, else 0.
///
/// # Safety
/// `table` must be a live handle; `cf` valid for one write; `clamped` null or valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_lookup(
    table: *const PressridgeCfTable,
    h: f64,
    cf: *mut f64,
    clamped: *mut i32,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        if !h.is_finite() {
            return Err(FfiError::new(
                super::PRESSRIDGE_ERR_NOT_FINITE,
                format!("thickness h = {h} is not finite"),
            ));
        }
        let l = t.table.lookup(h);
        put(cf, l.value, "cf")?;
        if !clamped.is_null() {
            put(clamped, i32::from(l.clamped), "clamped")?;
        }
        Ok(())
    })
}

/// Releases a C_f table handle (null is accepted and ignored). Options that refer to it must
/// not be used afterwards; calls running on other threads must have returned.
///
/// # Safety
/// `table` must be null or a handle not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_cf_table_free(table: *mut PressridgeCfTable) -> i32 {
    guard(|| {
        if !table.is_null() {
            // SAFETY: a handle from Box::into_raw, freed once (caller promise).
            drop(unsafe { Box::from_raw(table) });
        }
        Ok(())
    })
}

/// Opens a ridging lookup table (the NetCDF file of `pressridge tabulate`). `path` is
/// `path_len` bytes of UTF-8. On success `*table` is a new handle.
///
/// # Safety
/// `path` must be valid for `path_len` bytes; `table` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_open(
    path: *const c_char,
    path_len: i64,
    table: *mut *mut PressridgeRidgeTable,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        check_ptr(table, "table")?;
        let p = read_path(path, path_len, "path")?;
        let t = RidgeLookup::open(Path::new(p))?;
        let names = t.variables().map(str::to_string).collect();
        let h = Box::into_raw(Box::new(PressridgeRidgeTable { table: t, names }));
        put(table, h, "table")
    })
}

/// Sizes of a ridging lookup table: number of sets, thickness nodes, volume nodes and
/// fields (variables). Any out-pointer may be null.
///
/// # Safety
/// `table` must be a live handle; each other pointer null or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_dims(
    table: *const PressridgeRidgeTable,
    nsets: *mut i64,
    nthickness: *mut i64,
    nvolume: *mut i64,
    nvariables: *mut i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        for (p, v, name) in [
            (nsets, t.table.sets().len(), "nsets"),
            (nthickness, t.table.thickness().len(), "nthickness"),
            (nvolume, t.table.volume().len(), "nvolume"),
            (nvariables, t.names.len(), "nvariables"),
        ] {
            if !p.is_null() {
                put(p, v as i64, name)?;
            }
        }
        Ok(())
    })
}

/// The thickness axis (m) of a ridging lookup table into `out` (room for `len` ≥ nthickness
/// values).
///
/// # Safety
/// `table` must be a live handle; `out` valid for `len` writes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_thickness(
    table: *const PressridgeRidgeTable,
    out: *mut f64,
    len: i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe { copy_out(handle(table, "table")?.table.thickness(), out, len, "out") })
}

/// The volume axis (m³/m, ridged volume per metre of ridge) of a ridging lookup table into
/// `out` (room for `len` ≥ nvolume values).
///
/// # Safety
/// `table` must be a live handle; `out` valid for `len` writes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_volume(
    table: *const PressridgeRidgeTable,
    out: *mut f64,
    len: i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe { copy_out(handle(table, "table")?.table.volume(), out, len, "out") })
}

/// The label of set `set` (0-based; e.g. `contact.mu=1`) by the required-length protocol of
/// [`super::pressridge_last_error`].
///
/// # Safety
/// `table` must be a live handle; `buf` null or valid for `len` bytes; `required` null or
/// valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_set_name(
    table: *const PressridgeRidgeTable,
    set: i64,
    buf: *mut c_char,
    len: i64,
    required: *mut i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        let s = index(set, t.table.sets().len(), "set")?;
        write_string(&t.table.sets()[s], buf, len, required)
    })
}

/// The name of field `index` (0-based, sorted by name) by the required-length protocol of
/// [`super::pressridge_last_error`].
///
/// # Safety
/// As [`pressridge_ridge_table_set_name`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_variable_name(
    table: *const PressridgeRidgeTable,
    index_: i64,
    buf: *mut c_char,
    len: i64,
    required: *mut i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        let i = index(index_, t.names.len(), "index")?;
        write_string(&t.names[i], buf, len, required)
    })
}

/// Field `name` (`name_len` bytes of UTF-8) of set `set` (0-based) at sheet thickness
/// `thickness` (m) and ridged volume `volume` (m³/m), interpolated linearly, into `*value`
/// (in the field's units; NaN where the table has no data) and into `*clamped` (may be null)
/// 1 when a coordinate lay outside the table and was clamped, else 0. Unknown names give
/// `PRESSRIDGE_ERR_NOT_FOUND`.
///
/// # Safety
/// `table` must be a live handle; `name` valid for `name_len` bytes; `value` valid for one
/// write; `clamped` null or valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_value(
    table: *const PressridgeRidgeTable,
    name: *const c_char,
    name_len: i64,
    set: i64,
    thickness: f64,
    volume: f64,
    value: *mut f64,
    clamped: *mut i32,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        let n = read_string(name, name_len, "name")?;
        check_ptr(value, "value")?;
        let s = index(set, t.table.sets().len(), "set")?;
        let l = t.table.value(n, s, thickness, volume)?;
        put(value, l.value, "value")?;
        if !clamped.is_null() {
            put(clamped, i32::from(l.clamped), "clamped")?;
        }
        Ok(())
    })
}

/// C_f (dimensionless; ensemble mean of the final work over potential energy) of set `set`
/// (0-based) for ridging ice of thickness `thickness` (m) into `*cf`, with the clamping flag
/// as [`pressridge_ridge_table_value`].
///
/// # Safety
/// As [`pressridge_ridge_table_value`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_cf(
    table: *const PressridgeRidgeTable,
    set: i64,
    thickness: f64,
    cf: *mut f64,
    clamped: *mut i32,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        check_ptr(cf, "cf")?;
        let s = index(set, t.table.sets().len(), "set")?;
        let l = t.table.cf(s, thickness)?;
        put(cf, l.value, "cf")?;
        if !clamped.is_null() {
            put(clamped, i32::from(l.clamped), "clamped")?;
        }
        Ok(())
    })
}

/// A new C_f table handle holding the C_f of set `set` (0-based) of a ridging lookup table
/// (the thicknesses where it is not NaN, a NaN marking a node no run reached), for
/// `PressridgeOptions::cf_table`.
/// The new handle is independent of `table` and must be freed with
/// [`pressridge_cf_table_free`].
///
/// # Safety
/// `table` must be a live handle; `cf_table` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_cf_table(
    table: *const PressridgeRidgeTable,
    set: i64,
    cf_table: *mut *mut PressridgeCfTable,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        check_ptr(cf_table, "cf_table")?;
        let s = index(set, t.table.sets().len(), "set")?;
        let c = t.table.cf_table(s)?;
        let h = Box::into_raw(Box::new(PressridgeCfTable { table: Arc::new(c) }));
        put(cf_table, h, "cf_table")
    })
}

/// The 0-based set of a ridging table at friction `mu`, `mu_w` (dimensionless, equal to
/// 1e-9) into `*set`; [`super::PRESSRIDGE_ERR_NOT_FOUND`] when no set has that pair (the
/// message lists those it has) or the table has no friction coordinates.
///
/// # Safety
/// `table` must be a live handle; `set` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_friction_set(
    table: *const PressridgeRidgeTable,
    mu: f64,
    mu_w: f64,
    set: *mut i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let t = handle(table, "table")?;
        check_ptr(set, "set")?;
        let s = t
            .table
            .friction_set(friction_arg(mu, "mu")?, friction_arg(mu_w, "mu_w")?)?;
        put(set, s as i64, "set")
    })
}

/// Releases a ridging lookup table handle (null is accepted and ignored).
///
/// # Safety
/// `table` must be null or a handle not yet freed, not in use on another thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridge_table_free(table: *mut PressridgeRidgeTable) -> i32 {
    guard(|| {
        if !table.is_null() {
            // SAFETY: a handle from Box::into_raw, freed once (caller promise).
            drop(unsafe { Box::from_raw(table) });
        }
        Ok(())
    })
}
