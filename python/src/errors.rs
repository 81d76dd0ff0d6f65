//! Errors on their way to Python, and the guard around every library call.
//!
//! Owns `BindError` (`Send`, so it can leave a GIL-free section) and its conversions from
//! the library's errors (parameter overrides included) to `ValueError`, `OSError`,
//! `FileNotFoundError` and (for a panic, a bug) `RuntimeError`; `guarded` and `detached`,
//! which run library code with panics caught and, for `detached`, the GIL released; and the
//! `_panic_for_test` hook that tests them.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use pressridge::campaign::CampaignError;
use pressridge::io::IoError;
use pressridge::io::itd_netcdf::NetcdfError;
use pressridge::itd::details::ParamError;
use pressridge::scene::{SceneError, SceneLoadError};

/// An error on its way to Python; `Send`, so it can leave a GIL-free section.
#[derive(Debug)]
pub(crate) enum BindError {
    Value(String),
    Os(String),
    NotFound(String),
    Internal(String),
    Interrupted(PyErr),
}

impl From<BindError> for PyErr {
    fn from(e: BindError) -> PyErr {
        match e {
            BindError::Value(m) => PyValueError::new_err(m),
            BindError::Os(m) => PyOSError::new_err(m),
            BindError::NotFound(m) => PyFileNotFoundError::new_err(m),
            BindError::Internal(m) => PyRuntimeError::new_err(format!(
                "pressridge internal error (a bug: please report it): {m}"
            )),
            BindError::Interrupted(e) => e,
        }
    }
}

pub(crate) fn value_err(m: impl ToString) -> BindError {
    BindError::Value(m.to_string())
}

/// The library's error of a parameter override: Python's parameters are keywords of the
/// call, so an unknown name is an unknown keyword or parameter.
impl From<ParamError> for BindError {
    fn from(e: ParamError) -> Self {
        BindError::Value(e.message_as("keyword or parameter"))
    }
}

impl From<IoError> for BindError {
    fn from(e: IoError) -> Self {
        match &e {
            IoError::Os { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
                BindError::NotFound(e.to_string())
            }
            IoError::Os { .. } => BindError::Os(e.to_string()),
            IoError::Format { .. } => BindError::Value(e.to_string()),
        }
    }
}

impl From<NetcdfError> for BindError {
    fn from(e: NetcdfError) -> Self {
        match &e {
            NetcdfError::Netcdf { .. } => BindError::Os(e.to_string()),
            _ => BindError::Value(e.to_string()),
        }
    }
}

impl From<CampaignError> for BindError {
    fn from(e: CampaignError) -> Self {
        match e {
            CampaignError::Io(io) => io.into(),
            other => BindError::Value(other.to_string()),
        }
    }
}

impl From<SceneLoadError> for BindError {
    fn from(e: SceneLoadError) -> Self {
        match e {
            SceneLoadError::Read { path, source } => IoError::Os { path, source }.into(),
            other => BindError::Value(other.to_string()),
        }
    }
}

impl From<SceneError> for BindError {
    fn from(e: SceneError) -> Self {
        BindError::Value(e.to_string())
    }
}

/// Runs `f`, turning a panic into [`BindError::Internal`] so that none reaches Python.
pub(crate) fn guarded<T>(f: impl FnOnce() -> Result<T, BindError>) -> Result<T, BindError> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => {
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "panic".into());
            Err(BindError::Internal(msg))
        }
    }
}

/// Runs `f` without the GIL and without letting a panic out.
pub(crate) fn detached<T: Send>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, BindError> + Send,
) -> PyResult<T> {
    py.detach(|| guarded(f)).map_err(PyErr::from)
}

pub(crate) fn file_missing(path: &Path) -> Result<(), BindError> {
    if path.exists() {
        Ok(())
    } else {
        Err(BindError::NotFound(format!(
            "{}: No such file or directory",
            path.display()
        )))
    }
}

/// Test hook: panics inside the library-call guard, with (`detach = true`) or without the
/// GIL released; must raise `RuntimeError`, never abort the interpreter.
#[pyfunction]
#[pyo3(name = "_panic_for_test")]
pub(crate) fn panic_for_test(py: Python<'_>, detach: bool) -> PyResult<()> {
    let boom = || -> Result<(), BindError> { panic!("deliberate test panic") };
    if detach {
        detached(py, boom)
    } else {
        guarded(boom).map_err(PyErr::from)
    }
}
