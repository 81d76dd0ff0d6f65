//! `--param NAME=VALUE` and `--param-file` of `strength` and `ridge-step`: a thin adapter of
//! the library's parser ([`NamedParams::apply_setting`]: names, units, checks, messages and
//! the did-you-mean hint are the library's) that reads the file and says where a bad setting
//! was given.

use std::path::Path;

use pressridge::itd::details::{NamedParams, ParamError};

use crate::BoxError;

/// A `NAME=VALUE` setting and where it was given.
pub struct Setting {
    /// `FILE:LINE` of --param-file; `None`: --param.
    at: Option<String>,
    /// The setting as written.
    item: String,
}

/// The settings of `file` (--param-file: one `NAME = VALUE` per line, `#` starts a comment),
/// then those of --param, in order (a later one wins).
pub fn settings(file: Option<&Path>, params: &[String]) -> Result<Vec<Setting>, BoxError> {
    let mut out = Vec::new();
    if let Some(path) = file {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("--param-file {}: {e}", path.display()))?;
        for (k, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if !line.is_empty() {
                out.push(Setting {
                    at: Some(format!("{}:{}", path.display(), k + 1)),
                    item: line.to_string(),
                });
            }
        }
    }
    out.extend(params.iter().map(|p| Setting {
        at: None,
        item: p.clone(),
    }));
    Ok(out)
}

/// Applies `settings` in order to `set`; returns the name and the value as written of each.
/// An error is the library's message after where the setting was given.
pub fn apply<P: NamedParams>(
    set: &mut P,
    settings: &[Setting],
) -> Result<Vec<(&'static str, String)>, BoxError> {
    settings
        .iter()
        .map(|s| {
            set.apply_setting(&s.item)
                .map(|(name, value)| (name, value.to_string()))
                .map_err(|e| located(s, e))
        })
        .collect()
}

/// The library's error `e` of the setting `s`, after where it was given.
fn located(s: &Setting, e: ParamError) -> BoxError {
    // An unreadable setting is named by the library's message itself.
    let names_item = matches!(
        e,
        ParamError::Malformed { .. } | ParamError::NotANumber { .. }
    );
    match (&s.at, names_item) {
        (None, true) => format!("--param {e}"),
        (None, false) => format!("--param {}: {e}", s.item),
        (Some(at), _) => format!("{at}: {e}"),
    }
    .into()
}
