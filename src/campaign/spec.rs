//! A campaign's spec: its grid axes, seeds and base scene ([`CampaignSpec`]), and the runs
//! it plans ([`PlannedRun`]).

use super::CampaignError;
use crate::io::IoError;
use crate::scene::{Scene, SceneLoadError};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// A grid axis: one key, or several keys varied together.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Axis {
    /// A single scene key (dotted path).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub key: Option<String>,
    /// Several scene keys varied together.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub keys: Option<Vec<String>>,
    /// The values: scalars for `key`, arrays as long as `keys` for `keys`.
    pub values: Vec<toml::Value>,
}

/// Profile strips of a campaign.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ProfileSpec {
    /// Left edge of the first strip (m). Default −20 (the floe nose is at x = 0).
    pub x0: f64,
    /// Strip width (m). Default 1 (the paper's meter-wide strips).
    pub dx: f64,
    /// Number of strips. Default 32.
    pub strips: usize,
    /// Vertical lines sampled per strip. Default 10.
    pub lines_per_strip: usize,
}

impl Default for ProfileSpec {
    fn default() -> Self {
        Self {
            x0: -20.0,
            dx: 1.0,
            strips: 32,
            lines_per_strip: 10,
        }
    }
}

fn seven() -> u32 {
    7
}
fn one() -> u64 {
    1
}
fn twenty_five() -> f64 {
    25.0
}

/// A campaign spec.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CampaignSpec {
    /// Name for reports and tables.
    pub name: String,
    /// Seeds per grid point. Default 7 (the paper's sets of seven).
    #[serde(default = "seven")]
    pub seeds: u32,
    /// First seed. Default 1.
    #[serde(default = "one")]
    pub first_seed: u64,
    /// Sampling interval of the run records (s). Default 25 (the paper's).
    #[serde(default = "twenty_five")]
    pub sample_interval: f64,
    /// Base scene file, relative to the spec file; the built-in default when absent.
    #[serde(default)]
    pub scene: Option<String>,
    /// Overrides of the base scene, `key=value`.
    #[serde(default)]
    pub set: Vec<String>,
    /// Grid axes.
    #[serde(default)]
    pub axis: Vec<Axis>,
    /// Profile strips.
    #[serde(default)]
    pub profile: ProfileSpec,
}

/// One planned run. It serialises (JSON) so that a run can be sent to another process or
/// machine and run there with [`run_planned`](super::run_planned).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlannedRun {
    /// Directory below `runs/`, e.g. `thickness=0.3__block_width=0.25/seed-01`.
    pub id: String,
    /// Index of the grid point.
    pub point: usize,
    /// The axis settings of the point, `key=value`.
    pub settings: Vec<String>,
    /// The seed.
    pub seed: u64,
    /// The resolved scene.
    pub scene: Scene,
}

impl CampaignSpec {
    /// Parses a spec; unknown keys are an error naming them.
    pub fn from_toml(text: &str) -> Result<CampaignSpec, CampaignError> {
        let s: CampaignSpec =
            toml::from_str(text).map_err(|e| CampaignError::Spec(e.to_string()))?;
        let max_seeds = crate::limits::MAX_SEEDS;
        if s.seeds == 0 || s.seeds > max_seeds {
            return Err(CampaignError::Spec(format!(
                "`seeds` = {} is out of range: must lie in [1, {max_seeds}] (the paper uses 7 per grid point; every seed is a full run)",
                s.seeds
            )));
        }
        if s.first_seed.checked_add(u64::from(s.seeds)).is_none() {
            return Err(CampaignError::Spec(format!(
                "`first_seed` = {} is out of range: first_seed + seeds must stay below 2^64",
                s.first_seed
            )));
        }
        if !(s.sample_interval > 0.0 && s.sample_interval.is_finite()) {
            return Err(CampaignError::Spec(
                "`sample_interval` must be positive (s)".into(),
            ));
        }
        if s.profile.strips == 0 || s.profile.dx.is_nan() || s.profile.dx <= 0.0 {
            return Err(CampaignError::Spec(
                "`profile` needs strips ≥ 1 and dx > 0".into(),
            ));
        }
        Ok(s)
    }

    /// Reads a spec file.
    pub fn read(path: &Path) -> Result<CampaignSpec, CampaignError> {
        let text = std::fs::read_to_string(path).map_err(|e| IoError::Os {
            path: path.to_path_buf(),
            source: e,
        })?;
        Self::from_toml(&text).map_err(|e| match e {
            CampaignError::Spec(m) => CampaignError::Spec(format!("{}: {m}", path.display())),
            other => other,
        })
    }

    /// The axes as lists of `key=value` settings per value.
    fn settings(&self) -> Result<Vec<Vec<Vec<String>>>, CampaignError> {
        let mut out = Vec::new();
        let mut seen_keys: Vec<String> = Vec::new();
        for (k, a) in self.axis.iter().enumerate() {
            let keys: Vec<String> = match (&a.key, &a.keys) {
                (Some(key), None) => vec![key.clone()],
                (None, Some(keys)) if !keys.is_empty() => keys.clone(),
                _ => {
                    return Err(CampaignError::Spec(format!(
                        "axis {k}: give either `key` or a non-empty `keys`"
                    )));
                }
            };
            if a.values.is_empty() {
                return Err(CampaignError::Spec(format!("axis {k}: no values")));
            }
            for key in &keys {
                if seen_keys.contains(key) {
                    return Err(CampaignError::Spec(format!(
                        "axis {k}: key `{key}` is varied by an earlier axis too; each key may appear on one axis"
                    )));
                }
                seen_keys.push(key.clone());
            }
            let mut vals: Vec<Vec<String>> = Vec::new();
            for v in &a.values {
                let items: Vec<toml::Value> = match (keys.len(), v) {
                    (1, toml::Value::Array(x)) if x.len() == 1 => x.clone(),
                    (1, x) => vec![x.clone()],
                    (n, toml::Value::Array(x)) if x.len() == n => x.clone(),
                    (n, x) => {
                        return Err(CampaignError::Spec(format!(
                            "axis {k}: value {x} must be an array of {n} values, one per key"
                        )));
                    }
                };
                let setting: Vec<String> = keys
                    .iter()
                    .zip(items)
                    .map(|(key, x)| format!("{key}={x}"))
                    .collect();
                if vals.contains(&setting) {
                    return Err(CampaignError::Spec(format!(
                        "axis {k}: value {v} appears twice; each value is one grid point (use more `seeds` for more runs)"
                    )));
                }
                vals.push(setting);
            }
            out.push(vals);
        }
        Ok(out)
    }

    /// The planned runs: the grid points in axis order (the first axis slowest), each with
    /// its seeds. `base_dir` resolves a relative `scene` path.
    pub fn plan(&self, base_dir: &Path) -> Result<Vec<PlannedRun>, CampaignError> {
        let path = self.scene.as_ref().map(|p| base_dir.join(p));
        let base = Scene::load::<&str>(path.as_deref(), &[]).map_err(|e| match e {
            SceneLoadError::Read { path, source } => CampaignError::Io(IoError::os(&path, source)),
            SceneLoadError::File { path, source } => CampaignError::Scene {
                run: path.display().to_string(),
                source,
            },
            SceneLoadError::Scene(source) => CampaignError::Scene {
                run: path
                    .as_deref()
                    .unwrap_or(Path::new(""))
                    .display()
                    .to_string(),
                source,
            },
        })?;
        let axes = self.settings()?;
        let mut points: Vec<Vec<String>> = vec![Vec::new()];
        for axis in &axes {
            let mut next = Vec::new();
            for p in &points {
                for v in axis {
                    let mut q = p.clone();
                    q.extend(v.iter().cloned());
                    next.push(q);
                }
            }
            points = next;
        }
        let max_runs = crate::limits::MAX_RUNS;
        let total = points.len().saturating_mul(self.seeds as usize);
        if total > max_runs {
            return Err(CampaignError::Spec(format!(
                "the grid has {} points × {} seeds = {total} runs; at most {max_runs} are allowed",
                points.len(),
                self.seeds
            )));
        }
        let mut runs = Vec::new();
        for (pi, settings) in points.iter().enumerate() {
            let label = if settings.is_empty() {
                "base".to_string()
            } else {
                settings
                    .iter()
                    .map(|s| {
                        let (k, v) = s.split_once('=').expect("key=value");
                        format!("{}={}", k.rsplit('.').next().unwrap_or(k), v)
                    })
                    .collect::<Vec<_>>()
                    .join("__")
            };
            for s in 0..self.seeds as u64 {
                let seed = self.first_seed + s;
                let id = format!("{label}/seed-{seed:02}");
                let mut sets = self.set.clone();
                sets.extend(settings.iter().cloned());
                sets.push(format!("seed={seed}"));
                sets.push(format!("numerics.sample_interval={}", self.sample_interval));
                sets.push("output.snapshot_interval=0".into());
                let scene = base
                    .with_overrides(&sets)
                    .and_then(|sc| sc.validate().map(|_| sc))
                    .map_err(|e| CampaignError::Scene {
                        run: id.clone(),
                        source: e,
                    })?;
                runs.push(PlannedRun {
                    id,
                    point: pi,
                    settings: settings.clone(),
                    seed,
                    scene,
                });
            }
        }
        Ok(runs)
    }
}
