//! Scenes: every parameter of a run, read from TOML, with defaults and validation.
//!
//! A scene names the physics it contains and pays only for that: a scene without water has
//! no buoyancy or drag work, a scene without walls has no wall bodies. Unknown keys are
//! rejected with the key's name, so a misspelt parameter never silently takes its default.
//!
//! The built-in default scene ([`Scene::default`]) is the experiment of the paper's
//! Figure 5: a 0.30 m lead-ice sheet pushed at 0.25 m/s against a 2 m floe for 400 s, with
//! μ = 1.0 and μ_w = 0.6. Scenes compose: sheet against floe, sheet against a fixed wall
//! (`[wall]` instead of `[floe]`), a rubble pile alone (`[pile]`, see
//! [`Scene::rubble_pile`]). A section that is absent is not in the scene.

use crate::dem::boundary::{FloeSupport, SheetBoundary};
use crate::dem::{
    Block, ContactParams, Drive, JointMaterial, Role, Shape, V2, WaterParams, World, WorldError,
    WorldParams,
};
use rand_xoshiro::Xoshiro256PlusPlus;
use rand_xoshiro::rand_core::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};

use crate::limits;
use pressridge_column::limits::Range;

mod build;
mod sections;
pub use sections::{
    FloeSection, IceSection, JointSection, NOSE_SLOPE, NumericsSection, OutputSection, PileSection,
    SheetSection, WallSection, WaterSection,
};
mod step;
pub use step::StepScheme;
mod validate;

/// An error in a scene.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The TOML could not be parsed or named an unknown key (message from the parser).
    #[error("scene file: {0}")]
    Parse(String),
    /// A `--set key=value` override was malformed or named an unknown key.
    #[error("override `{0}`: {1}")]
    Override(String, String),
    /// A parameter is out of range.
    #[error("scene parameter `{0}`: {1}")]
    Invalid(String, String),
    /// The world rejected a parameter or a body.
    #[error(transparent)]
    World(#[from] WorldError),
}

/// An error loading a scene file with overrides ([`Scene::load`]).
#[derive(Debug, thiserror::Error)]
pub enum SceneLoadError {
    /// The file could not be read (the same message as `pressridge::io::IoError::Os`;
    /// the scene layer sits below `io`, so it keeps the path and the cause itself).
    #[error("{}: {source}", path.display())]
    Read {
        /// The file.
        path: std::path::PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The scene in the file is invalid; the message starts with the file's path.
    #[error("{}: {source}", path.display())]
    File {
        /// The file.
        path: std::path::PathBuf,
        /// The cause.
        source: SceneError,
    },
    /// An override was malformed, or the scene with the overrides is invalid.
    #[error(transparent)]
    Scene(#[from] SceneError),
}

/// A complete scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scene {
    /// A name for reports.
    pub name: String,
    /// Seed of every random choice in the scene.
    pub seed: u64,
    /// Simulated duration (s).
    pub duration: f64,
    /// Ice properties.
    pub ice: IceSection,
    /// Contact law, eqs (2)–(4).
    pub contact: ContactParams,
    /// Water.
    pub water: WaterSection,
    /// Numerics.
    pub numerics: NumericsSection,
    /// Joints and cracks.
    pub joint: JointSection,
    /// Outputs.
    pub output: OutputSection,
    /// The pushed sheet, if any.
    #[serde(default)]
    pub sheet: Option<SheetSection>,
    /// The floe, if any.
    #[serde(default)]
    pub floe: Option<FloeSection>,
    /// A fixed wall, if any.
    #[serde(default)]
    pub wall: Option<WallSection>,
    /// A rubble pile, if any.
    #[serde(default)]
    pub pile: Option<PileSection>,
}

impl Default for Scene {
    /// The Figure 5 experiment: h = 0.30 m, W = 0.25 m, 2 m floe, U = 0.25 m/s,
    /// E = 0.1 GPa top / 0.067 GPa bottom, μ = 1.0, μ_w = 0.6, 400 s (100 m of sheet).
    fn default() -> Self {
        Self {
            name: "figure5".into(),
            seed: 1,
            duration: 400.0,
            ice: IceSection::default(),
            contact: ContactParams::default(),
            water: WaterSection::default(),
            numerics: NumericsSection::default(),
            joint: JointSection::default(),
            output: OutputSection::default(),
            sheet: Some(SheetSection::default()),
            floe: Some(FloeSection::default()),
            wall: None,
            pile: None,
        }
    }
}

impl Scene {
    /// A pile of 200 blocks 0.25 m × 0.30 m dropped into water between two walls, 10 s:
    /// the verification scene of contacts, buoyancy and the ledger.
    pub fn rubble_pile() -> Scene {
        Scene {
            name: "rubble-pile".into(),
            duration: 10.0,
            sheet: None,
            floe: None,
            pile: Some(PileSection::default()),
            ..Scene::default()
        }
    }

    /// Parses a scene from TOML text; missing keys take their defaults, unknown keys are
    /// an error naming them. Lengths are in m, speeds in m/s, times in s (SI throughout;
    /// `pressridge simulate --print-scene` prints every key with its default).
    ///
    /// ```
    /// use pressridge_sim::scene::Scene;
    ///
    /// // A 2 m sheet, 0.30 m thick, pushed against a fixed wall for 1 s.
    /// let scene = Scene::from_toml(
    ///     r#"
    ///     name = "sheet-on-wall"
    ///     duration = 1.0
    ///     [sheet]
    ///     thickness = 0.30
    ///     length = 2.0
    ///     [wall]
    ///     "#,
    /// )?;
    /// assert_eq!(scene.sheet.as_ref().unwrap().speed, 0.25); // m/s, the default
    /// assert_eq!(Scene::from_toml(&scene.to_toml())?, scene); // TOML round trip
    /// let faster = scene.with_overrides(&["sheet.speed=0.5"])?; // as `--set sheet.speed=0.5`
    /// assert_eq!(faster.sheet.unwrap().speed, 0.5);
    /// assert!(Scene::from_toml("[sheet]\nthikness = 0.3").is_err()); // unknown key
    /// let world = scene.build()?; // the world at time zero, its time step derived
    /// assert!(world.dt() > 0.0); // s
    /// # Ok::<(), pressridge_sim::scene::SceneError>(())
    /// ```
    pub fn from_toml(text: &str) -> Result<Scene, SceneError> {
        let s: Scene = toml::from_str(text).map_err(|e| SceneError::Parse(e.to_string()))?;
        s.validate()?;
        Ok(s)
    }

    /// The scene of a run: the TOML file at `path` (the built-in default when `None`) with
    /// the `key=value` overrides `sets` applied ([`Scene::with_overrides`]) and validated.
    /// The one loader of the command line, Python and campaigns.
    ///
    /// ```no_run
    /// use pressridge_sim::scene::Scene;
    /// use std::path::Path;
    ///
    /// // As `pressridge simulate --scene ridge.toml --set duration=20 --set contact.mu=0.4`.
    /// let scene = Scene::load(Some(Path::new("ridge.toml")), &["duration=20", "contact.mu=0.4"])?;
    /// // The built-in default, the paper's Figure 5 experiment, run for 20 s.
    /// let figure5 = Scene::load(None, &["duration=20"])?;
    /// # Ok::<(), pressridge_sim::scene::SceneLoadError>(())
    /// ```
    pub fn load<S: AsRef<str>>(
        path: Option<&std::path::Path>,
        sets: &[S],
    ) -> Result<Scene, SceneLoadError> {
        let base = match path {
            Some(p) => {
                let text = std::fs::read_to_string(p).map_err(|source| SceneLoadError::Read {
                    path: p.to_path_buf(),
                    source,
                })?;
                Scene::from_toml(&text).map_err(|source| SceneLoadError::File {
                    path: p.to_path_buf(),
                    source,
                })?
            }
            None => Scene::default(),
        };
        if sets.is_empty() {
            return Ok(base);
        }
        Ok(base.with_overrides(sets)?)
    }

    /// The scene as TOML text.
    pub fn to_toml(&self) -> String {
        toml::to_string_pretty(self).expect("a scene always serialises")
    }

    /// The value of the dotted key `key` (e.g. `floe.thickness`), as TOML text; `None` when
    /// the scene has no such key (e.g. no floe).
    pub fn value_at(&self, key: &str) -> Option<String> {
        let doc: toml::Table = toml::from_str(&self.to_toml()).expect("a scene's own TOML");
        let mut parts = key.split('.');
        let mut v = doc.get(parts.next()?)?;
        for p in parts {
            v = v.as_table()?.get(p)?;
        }
        Some(v.to_string())
    }

    /// The scene as TOML without the dotted keys `keys` (those it lacks are ignored): what
    /// two scenes must share when they may differ in these keys.
    pub fn toml_without(&self, keys: &[String]) -> String {
        fn remove(doc: &mut toml::Table, key: &str) {
            match key.split_once('.') {
                None => {
                    doc.remove(key);
                }
                Some((head, rest)) => {
                    if let Some(toml::Value::Table(t)) = doc.get_mut(head) {
                        remove(t, rest);
                    }
                }
            }
        }
        let mut doc: toml::Table = toml::from_str(&self.to_toml()).expect("a scene's own TOML");
        for k in keys {
            remove(&mut doc, k);
        }
        doc.to_string()
    }

    /// Applies `key=value` overrides with dotted keys (`contact.mu=0.4`, `pile.blocks=50`,
    /// `duration=20`). The value is parsed as a TOML value.
    pub fn with_overrides<S: AsRef<str>>(&self, sets: &[S]) -> Result<Scene, SceneError> {
        let mut doc: toml::Table =
            toml::from_str(&self.to_toml()).map_err(|e| SceneError::Parse(e.to_string()))?;
        for set in sets {
            let set = set.as_ref();
            let (key, value) = split_override(set)
                .ok_or_else(|| SceneError::Override(set.into(), "expected key=value".into()))?;
            let value: toml::Value = toml::from_str::<toml::Table>(&format!("v = {value}"))
                .or_else(|_| toml::from_str::<toml::Table>(&format!("v = \"{value}\"")))
                .map_err(|e| SceneError::Override(set.into(), e.to_string()))?
                .remove("v")
                .expect("parsed table has v");
            let parts: Vec<&str> = key.split('.').collect();
            let mut table = &mut doc;
            for p in &parts[..parts.len() - 1] {
                table = table
                    .entry(p.to_string())
                    .or_insert_with(|| toml::Value::Table(toml::Table::new()))
                    .as_table_mut()
                    .ok_or_else(|| {
                        SceneError::Override(set.into(), format!("`{p}` is not a section"))
                    })?;
            }
            table.insert(parts[parts.len() - 1].to_string(), value);
        }
        let text = toml::to_string(&doc).map_err(|e| SceneError::Parse(e.to_string()))?;
        Scene::from_toml(&text).map_err(|e| match e {
            SceneError::Parse(m) => SceneError::Override(
                sets.iter()
                    .map(|s| s.as_ref())
                    .collect::<Vec<_>>()
                    .join(" "),
                m,
            ),
            other => other,
        })
    }
}

/// The key an override `key=value` (as `--set` takes it) names, trimmed, with its untrimmed
/// value; `None` when there is no `=`. One parser for [`Scene::with_overrides`] and every
/// caller that asks which key a `--set` names.
pub fn split_override(set: &str) -> Option<(&str, &str)> {
    set.split_once('=').map(|(k, v)| (k.trim(), v))
}

#[cfg(test)]
mod tests;
