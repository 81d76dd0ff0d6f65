//! Reading and writing files. Physics modules never touch files; this module does. Only
//! this module touches NetCDF.

pub(crate) mod digest;
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

/// The temporary file beside `path` that [`write_atomic_with`] writes before renaming: in
/// the same directory (so the rename is atomic), hidden, unique per process and call, and
/// ending in the target's file name (so a writer that picks its format from the extension,
/// as the PNG encoder does, still sees `.png`).
fn temporary_beside(path: &Path) -> Result<PathBuf, IoError> {
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path
        .file_name()
        .ok_or_else(|| IoError::format(path, "not a file path"))?;
    Ok(path.with_file_name(format!(
        ".tmp-{}-{}-{}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed),
        name.to_string_lossy()
    )))
}

/// Writes the file at `path` atomically through `write`: `write` gets a temporary path in
/// the same directory (created if missing) and must leave a complete file there; on success
/// the temporary file is synced and renamed to `path`, on error (or a panic) it is removed.
/// A reader, or a run killed at any moment, sees either the old file at `path` (or none) or
/// the complete new one, never a partial one. Every writer of the crate goes through this
/// one function (JSON, CSV, NetCDF, PNG/SVG).
pub fn write_atomic_with<T, E: From<IoError>>(
    path: &Path,
    write: impl FnOnce(&Path) -> Result<T, E>,
) -> Result<T, E> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty());
    if let Some(d) = dir {
        std::fs::create_dir_all(d).map_err(|e| IoError::os(d, e))?;
    }
    let tmp = temporary_beside(path)?;
    /// Removes the temporary file unless disarmed (error paths and unwinding alike).
    struct Cleanup<'a>(Option<&'a Path>);
    impl Drop for Cleanup<'_> {
        fn drop(&mut self) {
            if let Some(p) = self.0 {
                let _ = std::fs::remove_file(p);
            }
        }
    }
    let mut guard = Cleanup(Some(&tmp));
    let value = write(&tmp)?;
    // Data on disk before the name: a crash after the rename never shows an empty file.
    std::fs::File::open(&tmp)
        .and_then(|f| f.sync_all())
        .map_err(|e| IoError::os(path, e))?;
    std::fs::rename(&tmp, path).map_err(|e| IoError::os(path, e))?;
    guard.0 = None;
    Ok(value)
}

/// Writes `bytes` to `path` atomically ([`write_atomic_with`]): to a temporary file beside
/// it, then renamed, so a reader (or an interrupted run) never sees a half-written file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), IoError> {
    write_atomic_with(path, |tmp| {
        std::fs::write(tmp, bytes).map_err(|e| IoError::os(path, e))
    })
}

/// The path `p` resolves to: symlinks and `..` followed, for a file that does not exist
/// yet through its directory. `None` when not even the directory exists.
fn resolve(p: &Path) -> Option<PathBuf> {
    if let Ok(c) = std::fs::canonicalize(p) {
        return Some(c);
    }
    let name = p.file_name()?;
    let dir = p.parent().filter(|d| !d.as_os_str().is_empty());
    let dir = match dir {
        Some(d) => std::fs::canonicalize(d).ok()?,
        None => std::env::current_dir().ok()?,
    };
    Some(dir.join(name))
}

/// Refuses an output path that resolves to one of the inputs (the same path, a symlink to
/// it, or a hard link to it): writing it would destroy the input. `what` names the output
/// flag in the message, e.g. `--output`.
pub fn refuse_output_over_input(
    output: &Path,
    what: &str,
    inputs: &[(&str, &Path)],
) -> Result<(), IoError> {
    let out = resolve(output);
    #[cfg(unix)]
    let out_id = {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(output).ok().map(|m| (m.dev(), m.ino()))
    };
    for (flag, input) in inputs {
        let same_path = out.is_some() && out == resolve(input);
        #[cfg(unix)]
        let same_file = {
            use std::os::unix::fs::MetadataExt;
            out_id.is_some() && out_id == std::fs::metadata(input).ok().map(|m| (m.dev(), m.ino()))
        };
        #[cfg(not(unix))]
        let same_file = false;
        if same_path || same_file {
            return Err(IoError::format(
                output,
                format!(
                    "{what} is the {flag} file {}: writing it would destroy the input; choose another output path",
                    input.display()
                ),
            ));
        }
    }
    Ok(())
}

/// The current UTC time as `YYYY-MM-DDTHH:MM:SSZ` (RFC 3339, whole seconds), from the
/// system clock: for the `history` of output files and the dates of tables.
pub fn utc_now() -> String {
    humantime::format_rfc3339_seconds(std::time::SystemTime::now()).to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("pressridge-io-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_failed_atomic_write_keeps_the_old_file_and_leaves_no_temporary() {
        let d = scratch("fail");
        let p = d.join("a.txt");
        write_atomic(&p, b"old").unwrap();
        let r: Result<(), IoError> = write_atomic_with(&p, |tmp| {
            std::fs::write(tmp, b"half").unwrap();
            Err(IoError::format(&p, "deliberate"))
        });
        assert!(r.is_err());
        assert_eq!(std::fs::read(&p).unwrap(), b"old");
        let names: Vec<_> = std::fs::read_dir(&d)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("a.txt")]);
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn outputs_resolving_to_an_input_are_refused() {
        let d = scratch("alias");
        let input = d.join("in.nc");
        std::fs::write(&input, b"x").unwrap();
        let link = d.join("link.nc");
        #[cfg(unix)]
        std::os::unix::fs::symlink(&input, &link).unwrap();
        let dotted = d.join(".").join("in.nc");
        for out in [&input, &dotted, &link] {
            let e = refuse_output_over_input(out, "--output", &[("--input", &input)]);
            assert!(e.is_err(), "{}", out.display());
        }
        refuse_output_over_input(&d.join("new.nc"), "--output", &[("--input", &input)]).unwrap();
        let _ = std::fs::remove_dir_all(&d);
    }
}
