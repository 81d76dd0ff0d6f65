//! Parameters set by name: the one mechanism behind every face's parameter overrides.
//!
//! A [`NamedParams`] set lists its parameters with their units ([`ParamMeta`], in
//! labelled [`ParamGroup`]s) and sets one by name with its own checks. From that, this
//! module parses `NAME=VALUE` settings (the command line's `--param`, `--param-file`) and
//! `(name, value)` pairs (Python's keywords) and words their errors ([`ParamError`]): the
//! setting or parameter concerned, and for an unknown name the closest valid one and every
//! valid name. The sets: [`ItdParams`](super::ItdParams) (ridging and strength),
//! [`RidgeStepParams`](crate::details::RidgeStepParams) (the complete step's thermodynamic
//! constants) and [`RidgeStepOptions`](super::RidgeStepOptions) (every constant of the
//! complete step: both).

use super::ItdError;

/// Name, units and meaning of one settable parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamMeta {
    /// Field name, accepted by `set` (e.g. `mu_rdg`).
    pub name: &'static str,
    /// SI units (CF notation, e.g. `kg m-3`; `1` dimensionless).
    pub units: &'static str,
    /// What it is, with CICE/Icepack's name.
    pub description: &'static str,
}

impl ParamMeta {
    /// The entry `name`, `units`, `description`.
    pub const fn new(name: &'static str, units: &'static str, description: &'static str) -> Self {
        Self {
            name,
            units,
            description,
        }
    }
}

/// Parameters under a label, as the message of an unknown name lists them (e.g.
/// `valid names: rhoi, rhow, ...`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamGroup {
    /// What the message calls them.
    pub label: &'static str,
    /// The parameters, in order.
    pub fields: &'static [ParamMeta],
}

/// A set of numeric parameters, each read and set by its name; the provided methods parse
/// overrides by name for every face.
pub trait NamedParams: Default {
    /// Every parameter, in groups; no name occurs twice.
    const GROUPS: &'static [ParamGroup];

    /// The value of the parameter `name`, in its units; `None` for an unknown name.
    fn get(&self, name: &str) -> Option<f64>;

    /// Sets the parameter `name` (units as listed) after the set's checks; a rejected value
    /// leaves `self` unchanged.
    fn set(&mut self, name: &str, value: f64) -> Result<(), ItdError>;

    /// Every parameter, in the order of [`NamedParams::GROUPS`].
    fn fields() -> impl Iterator<Item = &'static ParamMeta> {
        Self::GROUPS.iter().flat_map(|g| g.fields)
    }

    /// The parameter called `name` (surrounding blanks ignored); an unknown name is
    /// [`ParamError::Unknown`], whose message names the closest valid name and all.
    fn check_name(name: &str) -> Result<&'static ParamMeta, ParamError> {
        let name = name.trim();
        Self::fields()
            .find(|f| f.name == name)
            .ok_or_else(|| ParamError::Unknown {
                name: name.into(),
                groups: Self::GROUPS,
            })
    }

    /// The valid name closest to `name` when it is close (a likely misspelling): edit
    /// distance at most 2 + len/4 and below len (not every letter replaced).
    fn closest_name(name: &str) -> Option<&'static str> {
        closest_name(Self::GROUPS, name)
    }

    /// Sets the parameter `name` (surrounding blanks ignored) as [`NamedParams::set`] does;
    /// an unknown name is [`ParamError::Unknown`].
    fn set_named(&mut self, name: &str, value: f64) -> Result<(), ParamError> {
        let meta = Self::check_name(name)?;
        Ok(self.set(meta.name, value)?)
    }

    /// Applies one `NAME=VALUE` setting (blanks around the name and the value ignored); an
    /// unknown name is reported before a bad value. Returns the name and the value as
    /// written (trimmed).
    fn apply_setting<'a>(&mut self, item: &'a str) -> Result<(&'static str, &'a str), ParamError> {
        let (name, value) = item
            .split_once('=')
            .ok_or_else(|| ParamError::Malformed { item: item.into() })?;
        let meta = Self::check_name(name)?;
        let value = value.trim();
        let v: f64 = value.parse().map_err(|_| ParamError::NotANumber {
            item: item.into(),
            value: value.into(),
        })?;
        self.set(meta.name, v)?;
        Ok((meta.name, value))
    }

    /// The defaults with `(name, value)` overrides applied in order
    /// ([`NamedParams::set_named`]): Python's keywords.
    fn from_pairs<N: AsRef<str>>(
        pairs: impl IntoIterator<Item = (N, f64)>,
    ) -> Result<Self, ParamError> {
        let mut p = Self::default();
        for (name, value) in pairs {
            p.set_named(name.as_ref(), value)?;
        }
        Ok(p)
    }

    /// The defaults with `NAME=VALUE` overrides applied in order
    /// ([`NamedParams::apply_setting`]): the command line's `--param`.
    fn from_settings<S: AsRef<str>>(settings: &[S]) -> Result<Self, ParamError> {
        let mut p = Self::default();
        for item in settings {
            p.apply_setting(item.as_ref())?;
        }
        Ok(p)
    }
}

/// An error in a parameter override given by name ([`NamedParams::set_named`],
/// [`NamedParams::apply_setting`] and the parsers built on them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    /// A setting without `=`.
    #[error("{item}: expected NAME=VALUE")]
    Malformed {
        /// The setting as given.
        item: String,
    },
    /// A setting whose value is not a number.
    #[error("{item}: `{value}` is not a number")]
    NotANumber {
        /// The setting as given.
        item: String,
        /// Its value part.
        value: String,
    },
    /// No parameter has this name; the message names the closest one, if close, and every
    /// valid name by group.
    #[error("{}", unknown_message("parameter", name, groups))]
    Unknown {
        /// The name as given (trimmed).
        name: String,
        /// The parameters of the set it was looked up in.
        groups: &'static [ParamGroup],
    },
    /// The value is out of range (the set's own checks).
    #[error(transparent)]
    Invalid(#[from] ItdError),
}

impl ParamError {
    /// The message with an unknown name called an unknown `noun` instead of "parameter"
    /// (Python says "keyword or parameter": its parameters are keywords of the call); any
    /// other error as displayed.
    pub fn message_as(&self, noun: &str) -> String {
        match self {
            ParamError::Unknown { name, groups } => unknown_message(noun, name, groups),
            other => other.to_string(),
        }
    }
}

/// `unknown NOUN `name` (did you mean `x`?); LABEL: a, b; LABEL: c, d`.
fn unknown_message(noun: &str, name: &str, groups: &[ParamGroup]) -> String {
    let hint =
        closest_name(groups, name).map_or(String::new(), |n| format!(" (did you mean `{n}`?)"));
    let lists: Vec<String> = groups
        .iter()
        .map(|g| {
            let names: Vec<&str> = g.fields.iter().map(|f| f.name).collect();
            format!("{}: {}", g.label, names.join(", "))
        })
        .collect();
    format!("unknown {noun} `{name}`{hint}; {}", lists.join("; "))
}

/// The name of `groups` closest to `name` when it is close: edit distance at most
/// 2 + len/4 and below len.
fn closest_name(groups: &[ParamGroup], name: &str) -> Option<&'static str> {
    groups
        .iter()
        .flat_map(|g| g.fields)
        .map(|f| (edit_distance(name, f.name), f.name))
        .min()
        .filter(|(d, _)| *d <= 2 + name.len() / 4 && *d < name.chars().count())
        .map(|(_, n)| n)
}

/// Levenshtein distance between two short names.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ItdParams, RidgeStepOptions, details::RidgeStepParams};

    /// The complete step's constants are the ridging parameters and the thermodynamic
    /// constants, once each, and each name reaches its own field.
    #[test]
    fn ridge_step_constants_are_both_sets_and_route_by_name() {
        let names: Vec<&str> = RidgeStepOptions::fields().map(|f| f.name).collect();
        let want: Vec<&str> = ItdParams::NAMES
            .iter()
            .copied()
            .chain(RidgeStepParams::fields().map(|f| f.name))
            .collect();
        assert_eq!(names, want);
        let mut seen = std::collections::HashSet::new();
        assert!(names.iter().all(|n| seen.insert(*n)), "a name twice");
        let d = RidgeStepOptions::default();
        for f in RidgeStepOptions::fields() {
            let v = d.get(f.name).unwrap();
            let new = match f.name {
                "nitermax" => v + 1.0,
                "rhow" => v * 1.25, // stays above rhoi
                _ => v * 0.75,
            };
            let p = RidgeStepOptions::from_pairs([(f.name, new)]).unwrap();
            assert_eq!(p.get(f.name), Some(new), "{}", f.name);
            for g in RidgeStepOptions::fields().filter(|g| g.name != f.name) {
                assert_eq!(p.get(g.name), d.get(g.name), "{} moved {}", f.name, g.name);
            }
        }
        let p = RidgeStepOptions::from_settings(&[" rhos = 300", "cs=0.5"]).unwrap();
        assert_eq!((p.step.rhos, p.params.cs), (300.0, 0.5));
        let mut q = RidgeStepOptions::default();
        assert_eq!(q.apply_setting(" fsnowrdg = 0.3 "), Ok(("fsnowrdg", "0.3")));
    }

    /// An unknown name: the closest valid one and every valid name, by group, whichever
    /// way it was given; bad settings and values name the setting or the parameter.
    #[test]
    fn errors_name_the_parameter_and_the_closest_one() {
        let e = RidgeStepOptions::from_settings(&["fsnowrgd=0.3"]).unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.starts_with(
                "unknown parameter `fsnowrgd` (did you mean `fsnowrdg`?); ridging parameters: rhoi, rhow, "
            ),
            "{msg}"
        );
        assert!(
            msg.ends_with("; constants of the complete step: rhos, lfresh, cp_ice, fsnowrdg, ice_ref_salinity, itd_area_min, itd_mass_min, hs_min, tmin"),
            "{msg}"
        );
        assert_eq!(
            RidgeStepOptions::from_pairs([(" fsnowrgd ", 0.3)]).unwrap_err(),
            e
        );
        assert_eq!(
            e.message_as("keyword or parameter"),
            msg.replacen("unknown parameter", "unknown keyword or parameter", 1)
        );
        // An unknown name before a bad value.
        assert_eq!(
            RidgeStepOptions::from_settings(&["fsnowrgd=x"]).unwrap_err(),
            e
        );
        let e = RidgeStepParams::from_pairs([("cs", 0.5)])
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("unknown parameter `cs`; valid names: rhos, "),
            "{e}"
        );
        assert_eq!(
            RidgeStepOptions::from_settings(&["rhos"]).unwrap_err(),
            ParamError::Malformed {
                item: "rhos".into()
            }
        );
        assert_eq!(
            RidgeStepOptions::from_settings(&["rhos= x "])
                .unwrap_err()
                .to_string(),
            "rhos= x : `x` is not a number"
        );
        for (item, words) in [
            ("fsnowrdg=2", ["fsnowrdg", "[0, 1]"]),
            ("cp_ice=-1", ["cp_ice", "positive"]),
            ("mu_rdg=-1", ["mu_rdg", "positive"]),
        ] {
            let e = RidgeStepOptions::from_settings(&[item]).unwrap_err();
            assert!(matches!(e, ParamError::Invalid(_)), "{item}");
            let m = e.message_as("keyword or parameter");
            assert_eq!(m, e.to_string());
            assert!(words.iter().all(|w| m.contains(w)), "{m}");
        }
        assert_eq!(ItdParams::closest_name("zzzzzzzz"), None);
        assert_eq!(RidgeStepOptions::closest_name("Cs"), Some("cs"));
        // Not a name with every letter replaced.
        assert_eq!(ItdParams::closest_name("mu"), None);
    }
}
