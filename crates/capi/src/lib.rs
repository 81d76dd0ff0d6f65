//! The C ABI: what C, C++ and Fortran host models link against (`libpressridge.so`,
//! `libpressridge.a`, header `include/pressridge.h`, Fortran module in `fortran-bridge/`).
//!
//! This layer only converts and calls the library: raw pointers, strides and integer codes
//! in, [`pressridge::itd`], [`pressridge::io`], [`pressridge::table`] and [`pressridge::simulation`] calls, error
//! codes out. There is no physics here. Units are SI throughout, as in the library.
//!
//! Conventions (see `docs/c-api.md`):
//! - every function returns an `int32_t` status: [`PRESSRIDGE_OK`] (0) or one of the
//!   `PRESSRIDGE_ERR_*` codes; the message of the last failure on the calling thread is read
//!   with [`pressridge_last_error`] (thread-local, so OpenMP threads do not see each other's
//!   errors);
//! - sizes, lengths, strides and indices are `int64_t` (Fortran has no unsigned integers);
//!   zero or negative sizes are errors, never wrapped;
//! - buffers belong to the caller; strings go in as (pointer, length in bytes, UTF-8, no NUL
//!   needed) and come out through the required-length protocol of [`pressridge_last_error`];
//! - handles (`PressridgeCfTable`, `PressridgeRidgeTable`, `PressridgeRun`) are created by
//!   `*_open`/`*_new`/`*_run` and released by `*_free`; they are immutable, so one handle may
//!   be used from several threads at once, but not freed while in use;
//! - no panic crosses the boundary: each entry point runs under `catch_unwind` and turns a
//!   panic into [`PRESSRIDGE_ERR_PANIC`].

#![warn(missing_docs)]

use std::cell::RefCell;
use std::ffi::c_char;
use std::panic::{AssertUnwindSafe, catch_unwind};

mod convert;
pub mod itd;
mod layout;
pub mod mu_rdg_table;
pub mod ridge_step;
pub mod scene;
pub mod tables;

pub use layout::{PressridgeGrid, pressridge_grid_c, pressridge_grid_fortran};

/// Success.
pub const PRESSRIDGE_OK: i32 = 0;
/// A required pointer is null, or a pointer is not aligned for its type.
pub const PRESSRIDGE_ERR_NULL_POINTER: i32 = 1;
/// A size, length or stride is zero, negative, inconsistent with another, or the buffers it
/// describes overlap or are too short.
pub const PRESSRIDGE_ERR_BAD_SIZE: i32 = 2;
/// A value is out of its range: a negative area or volume, an area sum that is not 1, an
/// unknown option code, a parameter out of range, an index out of range.
pub const PRESSRIDGE_ERR_BAD_VALUE: i32 = 3;
/// A value is NaN or infinite.
pub const PRESSRIDGE_ERR_NOT_FINITE: i32 = 4;
/// A file could not be opened or read (operating system or NetCDF error, missing variable,
/// bad dimensions or contents).
pub const PRESSRIDGE_ERR_IO: i32 = 5;
/// Text could not be parsed: invalid UTF-8, TOML syntax, an unknown scene key.
pub const PRESSRIDGE_ERR_PARSE: i32 = 6;
/// An output buffer is too short; the required length was returned and as much as fitted
/// was written (NUL-terminated).
pub const PRESSRIDGE_ERR_BUFFER_TOO_SMALL: i32 = 7;
/// A name (table variable, summary key) is not known.
pub const PRESSRIDGE_ERR_NOT_FOUND: i32 = 8;
/// A numerical procedure failed (the ridging iteration did not converge).
pub const PRESSRIDGE_ERR_NUMERICAL: i32 = 9;
/// An internal error (a Rust panic) was caught at the boundary. Please report it.
pub const PRESSRIDGE_ERR_PANIC: i32 = 10;

/// Version of the C ABI (the layout of the structs and the function signatures). Bumped on
/// every incompatible change; compare with [`pressridge_abi_version`] at run time.
pub const PRESSRIDGE_ABI_VERSION: i32 = 3;

/// An error on its way to the caller: a status code, a message and, for errors in one
/// column, the column's 0-based index.
#[derive(Debug, Clone)]
pub(crate) struct FfiError {
    pub code: i32,
    pub message: String,
    pub column: Option<usize>,
}

impl FfiError {
    pub(crate) fn new(code: i32, message: impl Into<String>) -> Self {
        Self {
            code,
            message: message.into(),
            column: None,
        }
    }
}

pub(crate) type FfiResult<T> = Result<T, FfiError>;

struct LastError {
    code: i32,
    message: String,
    column: i64,
}

thread_local! {
    static LAST_ERROR: RefCell<LastError> = const {
        RefCell::new(LastError { code: PRESSRIDGE_OK, message: String::new(), column: -1 })
    };
}

fn record(code: i32, message: &str, column: Option<usize>) {
    LAST_ERROR.with(|l| {
        let mut l = l.borrow_mut();
        l.code = code;
        l.message.clear();
        l.message.push_str(message);
        l.column = column.map_or(-1, |c| c as i64);
    });
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    let what = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown cause".into());
    format!("internal error (panic caught at the C boundary): {what}")
}

/// Runs the body of an entry point: clears the thread's last error, catches panics, records
/// the error and returns its code.
pub(crate) fn guard(body: impl FnOnce() -> FfiResult<()>) -> i32 {
    record(PRESSRIDGE_OK, "", None);
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => PRESSRIDGE_OK,
        Ok(Err(e)) => {
            record(e.code, &e.message, e.column);
            e.code
        }
        Err(payload) => {
            record(PRESSRIDGE_ERR_PANIC, &panic_message(&*payload), None);
            PRESSRIDGE_ERR_PANIC
        }
    }
}

/// As [`guard`], but leaves the thread's last error as it was (for the functions that read
/// it).
fn guard_keep(body: impl FnOnce() -> FfiResult<()>) -> i32 {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => PRESSRIDGE_OK,
        Ok(Err(e)) => e.code,
        Err(_) => PRESSRIDGE_ERR_PANIC,
    }
}

/// Writes `s` into the caller's buffer `buf` of `len` bytes by the required-length protocol:
/// `*required` (if not null) receives `strlen(s) + 1`; as much of `s` as fits (cut at a
/// character boundary) is copied, followed by a NUL, when `buf` is not null and `len > 0`.
/// Returns [`PRESSRIDGE_ERR_BUFFER_TOO_SMALL`] when the whole string did not fit.
///
/// # Safety
/// `buf` must be null or valid for `len` bytes of writes; `required` null or valid.
pub(crate) unsafe fn write_string(
    s: &str,
    buf: *mut c_char,
    len: i64,
    required: *mut i64,
) -> FfiResult<()> {
    let need = s.len() as i64 + 1;
    if !required.is_null() {
        layout::check_aligned(required, "required")?;
        // SAFETY: checked non-null and aligned; the caller promises validity.
        unsafe { *required = need };
    }
    if len < 0 {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_SIZE,
            format!("buffer length {len} is negative"),
        ));
    }
    if !buf.is_null() && len > 0 {
        let mut n = s.len().min(len as usize - 1);
        while !s.is_char_boundary(n) {
            n -= 1;
        }
        // SAFETY: `buf` is valid for `len` bytes and n + 1 <= len.
        unsafe {
            std::ptr::copy_nonoverlapping(s.as_ptr(), buf.cast::<u8>(), n);
            *buf.add(n) = 0;
        }
    }
    if len < need {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BUFFER_TOO_SMALL,
            format!("output buffer of {len} bytes is too small: {need} bytes are needed"),
        ));
    }
    Ok(())
}

/// Reads a caller's string given as (pointer, length in bytes). UTF-8 is required.
///
/// # Safety
/// `ptr` must be valid for `len` bytes of reads (it is checked for null).
pub(crate) unsafe fn read_string<'a>(
    ptr: *const c_char,
    len: i64,
    what: &str,
) -> FfiResult<&'a str> {
    if ptr.is_null() {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_NULL_POINTER,
            format!("{what} is a null pointer"),
        ));
    }
    if len < 0 {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_SIZE,
            format!("length of {what} is negative ({len})"),
        ));
    }
    // SAFETY: non-null; the caller promises `len` readable bytes.
    let bytes = unsafe { std::slice::from_raw_parts(ptr.cast::<u8>(), len as usize) };
    std::str::from_utf8(bytes).map_err(|e| {
        FfiError::new(
            PRESSRIDGE_ERR_PARSE,
            format!("{what} is not valid UTF-8: {e}"),
        )
    })
}

/// Reads a caller's file path given as (pointer, length in bytes): UTF-8 without NUL bytes.
/// A path with an embedded NUL would be cut short by the C library that opens it, opening
/// another file than the one named, so it is refused.
///
/// # Safety
/// As [`read_string`].
pub(crate) unsafe fn read_path<'a>(ptr: *const c_char, len: i64, what: &str) -> FfiResult<&'a str> {
    // SAFETY: the caller's promise, passed on.
    let p = unsafe { read_string(ptr, len, what) }?;
    if let Some(i) = p.find('\0') {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_VALUE,
            format!(
                "{what} has a NUL byte at offset {i} of its {len} bytes: pass the path's length without any terminating NUL"
            ),
        ));
    }
    if p.is_empty() {
        return Err(FfiError::new(
            PRESSRIDGE_ERR_BAD_VALUE,
            format!("{what} is empty"),
        ));
    }
    Ok(p)
}

/// Stores `value` through the out-pointer `out`, which must not be null.
///
/// # Safety
/// `out` must be null or valid for one write of `T`.
pub(crate) unsafe fn put<T>(out: *mut T, value: T, what: &str) -> FfiResult<()> {
    layout::check_ptr(out, what)?;
    // SAFETY: checked non-null and aligned; validity is the caller's promise.
    unsafe { out.write(value) };
    Ok(())
}

/// The message of the last failed call on this thread (empty after a successful call),
/// by the required-length protocol: `*required` (if `required` is not null) receives the
/// message length in bytes plus 1; as much as fits in `buf` (`len` bytes) is written,
/// NUL-terminated. Returns [`PRESSRIDGE_OK`] when it all fitted, else
/// [`PRESSRIDGE_ERR_BUFFER_TOO_SMALL`]. Does not change the last error.
///
/// # Safety
/// `buf` must be null or valid for `len` bytes; `required` null or valid for one `int64_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_last_error(
    buf: *mut c_char,
    len: i64,
    required: *mut i64,
) -> i32 {
    guard_keep(|| {
        LAST_ERROR.with(|l| {
            let l = l.borrow();
            // SAFETY: forwarded caller promises.
            unsafe { write_string(&l.message, buf, len, required) }
        })
    })
}

/// The status code of the last call on this thread ([`PRESSRIDGE_OK`] after a success)
/// into `*code`, and into `*column` the 0-based index of the column that failed, or −1 when
/// the error was not about one column. Either pointer may be null. Does not change the last
/// error.
///
/// # Safety
/// `code` and `column` must each be null or valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_last_error_info(code: *mut i32, column: *mut i64) -> i32 {
    guard_keep(|| {
        let (c, col) = LAST_ERROR.with(|l| {
            let l = l.borrow();
            (l.code, l.column)
        });
        if !code.is_null() {
            // SAFETY: caller promise, checked by `put`.
            unsafe { put(code, c, "code")? };
        }
        if !column.is_null() {
            // SAFETY: as above.
            unsafe { put(column, col, "column")? };
        }
        Ok(())
    })
}

/// Records an error found by a language binding (for example the Fortran module's shape
/// checks) as the calling thread's last error, so that [`pressridge_last_error`] reports
/// it like the library's own: `code` (one of the `PRESSRIDGE_ERR_*` codes) and `message_len`
/// bytes of UTF-8 at `message` (invalid bytes are replaced). Returns [`PRESSRIDGE_OK`] when
/// recorded, [`PRESSRIDGE_ERR_BAD_VALUE`] (recording nothing) when `code` is not an error
/// code.
///
/// # Safety
/// `message` must be valid for `message_len` bytes, or null with `message_len` 0.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_set_error(
    code: i32,
    message: *const c_char,
    message_len: i64,
) -> i32 {
    guard_keep(|| {
        if !(PRESSRIDGE_ERR_NULL_POINTER..=PRESSRIDGE_ERR_PANIC).contains(&code) {
            return Err(FfiError::new(
                PRESSRIDGE_ERR_BAD_VALUE,
                "unknown status code",
            ));
        }
        let text = if message.is_null() || message_len <= 0 {
            String::new()
        } else {
            // SAFETY: the caller promises `message_len` readable bytes.
            let b =
                unsafe { std::slice::from_raw_parts(message.cast::<u8>(), message_len as usize) };
            String::from_utf8_lossy(b).into_owned()
        };
        record(code, &text, None);
        Ok(())
    })
}

/// The name of a status code (`"PRESSRIDGE_ERR_BAD_SIZE"`, ...) by the required-length
/// protocol of [`pressridge_last_error`]; unknown codes give `"unknown status"`.
///
/// # Safety
/// As [`pressridge_last_error`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_status_name(
    code: i32,
    buf: *mut c_char,
    len: i64,
    required: *mut i64,
) -> i32 {
    let name = match code {
        PRESSRIDGE_OK => "PRESSRIDGE_OK",
        PRESSRIDGE_ERR_NULL_POINTER => "PRESSRIDGE_ERR_NULL_POINTER",
        PRESSRIDGE_ERR_BAD_SIZE => "PRESSRIDGE_ERR_BAD_SIZE",
        PRESSRIDGE_ERR_BAD_VALUE => "PRESSRIDGE_ERR_BAD_VALUE",
        PRESSRIDGE_ERR_NOT_FINITE => "PRESSRIDGE_ERR_NOT_FINITE",
        PRESSRIDGE_ERR_IO => "PRESSRIDGE_ERR_IO",
        PRESSRIDGE_ERR_PARSE => "PRESSRIDGE_ERR_PARSE",
        PRESSRIDGE_ERR_BUFFER_TOO_SMALL => "PRESSRIDGE_ERR_BUFFER_TOO_SMALL",
        PRESSRIDGE_ERR_NOT_FOUND => "PRESSRIDGE_ERR_NOT_FOUND",
        PRESSRIDGE_ERR_NUMERICAL => "PRESSRIDGE_ERR_NUMERICAL",
        PRESSRIDGE_ERR_PANIC => "PRESSRIDGE_ERR_PANIC",
        _ => "unknown status",
    };
    // SAFETY: forwarded caller promises.
    guard_keep(|| unsafe { write_string(name, buf, len, required) })
}

/// The library version (`"0.1.0"`) by the required-length protocol of
/// [`pressridge_last_error`].
///
/// # Safety
/// As [`pressridge_last_error`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_version(buf: *mut c_char, len: i64, required: *mut i64) -> i32 {
    // SAFETY: forwarded caller promises.
    guard(|| unsafe { write_string(env!("CARGO_PKG_VERSION"), buf, len, required) })
}

/// The C ABI version of the library into `*version`; it must equal the header's
/// `PRESSRIDGE_ABI_VERSION`.
///
/// # Safety
/// `version` must be valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_abi_version(version: *mut i32) -> i32 {
    // SAFETY: checked by `put`; validity is the caller's promise.
    guard(|| unsafe { put(version, PRESSRIDGE_ABI_VERSION, "version") })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message() -> String {
        LAST_ERROR.with(|l| l.borrow().message.clone())
    }

    #[test]
    fn panics_become_codes_and_messages() {
        let rc = guard(|| panic!("boom"));
        assert_eq!(rc, PRESSRIDGE_ERR_PANIC);
        assert!(message().contains("boom"), "{}", message());
        assert_eq!(guard(|| Ok(())), PRESSRIDGE_OK);
        assert_eq!(message(), "");
        let rc = guard(|| Err(FfiError::new(PRESSRIDGE_ERR_IO, "x.nc: no such file")));
        assert_eq!(rc, PRESSRIDGE_ERR_IO);
        assert_eq!(message(), "x.nc: no such file");
        let m = "shape of vicen";
        // SAFETY: `m` is 14 bytes of valid UTF-8 that outlive the call.
        let rc = unsafe { pressridge_set_error(PRESSRIDGE_ERR_BAD_SIZE, m.as_ptr().cast(), 14) };
        assert_eq!(rc, PRESSRIDGE_OK);
        assert_eq!(message(), m);
        // SAFETY: as above.
        let rc = unsafe { pressridge_set_error(PRESSRIDGE_OK, m.as_ptr().cast(), 14) };
        assert_eq!(rc, PRESSRIDGE_ERR_BAD_VALUE);
        assert_eq!(message(), m, "unchanged");
    }

    #[test]
    fn strings_are_cut_at_character_boundaries() {
        let mut buf = [0x55u8; 3];
        let mut need = 0;
        // SAFETY: `buf` holds the 3 bytes the call is told it may write.
        let r = unsafe { write_string("aé", buf.as_mut_ptr().cast(), 3, &mut need) };
        assert_eq!(r.unwrap_err().code, PRESSRIDGE_ERR_BUFFER_TOO_SMALL);
        assert_eq!(need, 4);
        assert_eq!(buf, [b'a', 0, 0x55]);
    }
}
