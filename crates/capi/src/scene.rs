//! Running the ridge simulator through the C ABI: a scene as TOML text in, a run handle with
//! its summary (JSON or one number at a time) out.

use std::ffi::c_char;

use super::layout::check_ptr;
use super::{
    FfiError, FfiResult, PRESSRIDGE_ERR_BAD_VALUE, PRESSRIDGE_ERR_NOT_FOUND, guard, put,
    read_string, write_string,
};
use pressridge::scene::Scene;
use pressridge::simulation::{Summary, run as run_scene};

/// The result of a simulator run (its summary). Opaque; create with
/// [`pressridge_scene_run`], release with [`pressridge_run_free`].
#[derive(Debug)]
pub struct PressridgeRun {
    summary: Summary,
    json: String,
}

/// # Safety
/// `r` must be null or a live handle.
unsafe fn handle<'a>(r: *const PressridgeRun) -> FfiResult<&'a PressridgeRun> {
    check_ptr(r, "run")?;
    // SAFETY: non-null and aligned; a live handle is the caller's promise.
    Ok(unsafe { &*r })
}

/// Runs the scene given as TOML text (`toml_len` bytes of UTF-8, the format of
/// `data/scenes/*.toml`; every key optional, unknown keys rejected) to its duration on the
/// calling thread, and returns the run in `*run`. No files are written. The call takes as
/// long as the simulation (seconds to minutes; `docs/performance.md`). Errors:
/// `PRESSRIDGE_ERR_PARSE` for TOML and unknown keys, `PRESSRIDGE_ERR_BAD_VALUE` for
/// parameters out of range.
///
/// # Safety
/// `toml` must be valid for `toml_len` bytes; `run` valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_scene_run(
    toml: *const c_char,
    toml_len: i64,
    run: *mut *mut PressridgeRun,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        check_ptr(run, "run")?;
        let text = read_string(toml, toml_len, "toml")?;
        let scene = Scene::from_toml(text)?;
        let out = run_scene(&scene, &mut |_| true)?;
        let json = serde_json::to_string_pretty(&out.summary).map_err(|e| {
            FfiError::new(
                super::PRESSRIDGE_ERR_PANIC,
                format!("summary could not be serialised: {e}"),
            )
        })?;
        let h = Box::into_raw(Box::new(PressridgeRun {
            summary: out.summary,
            json,
        }));
        put(run, h, "run")
    })
}

/// The run's summary as JSON (the `summary.json` of `pressridge simulate`: energies in J/m,
/// times in s, forces in N/m) by the required-length protocol of
/// [`super::pressridge_last_error`]: call with a null `buf` to get `*required`, then again
/// with a buffer of that many bytes.
///
/// # Safety
/// `run` must be a live handle; `buf` null or valid for `len` bytes; `required` null or
/// valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_run_summary_json(
    run: *const PressridgeRun,
    buf: *mut c_char,
    len: i64,
    required: *mut i64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe { write_string(&handle(run)?.json, buf, len, required) })
}

/// One number of the run's summary by its JSON key (`key_len` bytes; e.g. `work`,
/// `potential_energy`, `ratio_work_to_pe`, `ridged_volume`, `steps`), in the units of
/// `summary.json`, into `*value`. Unknown keys give `PRESSRIDGE_ERR_NOT_FOUND`; keys whose
/// value is not a number give `PRESSRIDGE_ERR_BAD_VALUE`.
///
/// # Safety
/// `run` must be a live handle; `key` valid for `key_len` bytes; `value` for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_run_summary_value(
    run: *const PressridgeRun,
    key: *const c_char,
    key_len: i64,
    value: *mut f64,
) -> i32 {
    // SAFETY: as above.
    guard(|| unsafe {
        let r = handle(run)?;
        let k = read_string(key, key_len, "key")?;
        check_ptr(value, "value")?;
        let v = serde_json::to_value(&r.summary)
            .map_err(|e| FfiError::new(super::PRESSRIDGE_ERR_PANIC, format!("summary: {e}")))?;
        let field = v.get(k).ok_or_else(|| {
            let known: Vec<&str> = v
                .as_object()
                .map(|o| o.keys().map(String::as_str).collect())
                .unwrap_or_default();
            FfiError::new(
                PRESSRIDGE_ERR_NOT_FOUND,
                format!(
                    "the summary has no key `{k}` (it has: {})",
                    known.join(", ")
                ),
            )
        })?;
        let x = field.as_f64().ok_or_else(|| {
            FfiError::new(
                PRESSRIDGE_ERR_BAD_VALUE,
                format!("summary key `{k}` is not a number"),
            )
        })?;
        put(value, x, "value")
    })
}

/// Releases a run handle (null is accepted and ignored).
///
/// # Safety
/// `run` must be null or a handle not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_run_free(run: *mut PressridgeRun) -> i32 {
    guard(|| {
        if !run.is_null() {
            // SAFETY: a handle from Box::into_raw, freed once (caller promise).
            drop(unsafe { Box::from_raw(run) });
        }
        Ok(())
    })
}
