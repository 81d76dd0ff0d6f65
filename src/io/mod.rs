//! Reading and writing files. Physics modules never touch files; this module does. Only
//! this module touches NetCDF.

pub mod itd_netcdf;
pub mod report;
pub mod series;
pub mod state;
pub mod table_netcdf;

use std::path::{Path, PathBuf};

/// An error reading or writing a file, with its path.
#[derive(Debug, thiserror::Error)]
pub enum IoError {
    /// The operating system refused.
    #[error("{path}: {source}")]
    Os {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The content could not be parsed or does not fit.
    #[error("{path}: {msg}")]
    Format {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        msg: String,
    },
}

impl IoError {
    pub(crate) fn os(path: &Path, source: std::io::Error) -> Self {
        IoError::Os {
            path: path.to_path_buf(),
            source,
        }
    }
    pub(crate) fn format(path: &Path, msg: impl ToString) -> Self {
        IoError::Format {
            path: path.to_path_buf(),
            msg: msg.to_string(),
        }
    }
}

/// Writes `bytes` to `path` atomically: to a temporary file beside it, then renamed, so a
/// reader (or an interrupted run) never sees a half-written file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), IoError> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty());
    if let Some(d) = dir {
        std::fs::create_dir_all(d).map_err(|e| IoError::os(d, e))?;
    }
    let name = path
        .file_name()
        .ok_or_else(|| IoError::format(path, "not a file path"))?;
    let tmp = path.with_file_name(format!(
        ".{}.tmp{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    std::fs::write(&tmp, bytes).map_err(|e| IoError::os(&tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| IoError::os(path, e))
}
