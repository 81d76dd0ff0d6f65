//! Scenes: every parameter of a run, read from TOML, with defaults and validation.
//!
//! A scene names the physics it contains and pays only for that: a scene without water has
//! no buoyancy or drag work, a scene without walls has no wall bodies. Unknown keys are
//! rejected with the key's name, so a misspelt parameter never silently takes its default.
//!
//! The built-in default scene ([`Scene::default`]) is a rubble pile of 200 blocks dropped
//! into water between two walls: the verification scene of the contact, buoyancy and
//! ledger mechanics.

use crate::dem::{ContactParams, Drive, Shape, V2, WaterParams, World, WorldError, WorldParams};
use rand_xoshiro::Xoshiro256PlusPlus;
use rand_xoshiro::rand_core::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};

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

/// Ice properties.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct IceSection {
    /// Ice density ρ_i (kg/m³). Default 920 (Hopkins 1994, Table 1).
    pub density: f64,
    /// Acceleration of gravity g (m/s²). Default 9.81.
    pub gravity: f64,
}

impl Default for IceSection {
    fn default() -> Self {
        Self {
            density: 920.0,
            gravity: 9.81,
        }
    }
}

/// The water, if any.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WaterSection {
    /// Whether the scene has water at all. Default true.
    pub enabled: bool,
    /// Still-water level (m). Default 0.
    pub level: f64,
    /// Sea-water density ρ_w (kg/m³). Default 1010 (Table 1).
    pub density: f64,
    /// Form-drag coefficient C_d (dimensionless). Default 1.0; see [`WaterParams`].
    pub drag_coefficient: f64,
    /// Linear drag coefficient (kg/(m³·s)). Default 0.
    pub linear_drag: f64,
}

impl Default for WaterSection {
    fn default() -> Self {
        let w = WaterParams::default();
        Self {
            enabled: true,
            level: w.level,
            density: w.density,
            drag_coefficient: w.drag_coefficient,
            linear_drag: w.linear_drag,
        }
    }
}

/// Numerical choices.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NumericsSection {
    /// Safety factor on the critical time step (dimensionless). Default 0.5.
    pub time_step_safety: f64,
    /// Fixed time step (s); 0 derives it from the stiffest element. Default 0.
    pub time_step: f64,
    /// Interval between samples of the energy budget and the ridging force (s).
    /// Default 0.2 s, the paper's force sampling interval (Figure 6).
    pub sample_interval: f64,
}

impl Default for NumericsSection {
    fn default() -> Self {
        Self {
            time_step_safety: 0.5,
            time_step: 0.0,
            sample_interval: 0.2,
        }
    }
}

/// A pile of identical blocks dropped into the scene, optionally between two walls.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PileSection {
    /// Number of blocks. Default 200.
    pub blocks: usize,
    /// Number of columns the blocks are stacked in. Default 10.
    pub columns: usize,
    /// Block width W (m). Default 0.25 (Table 1).
    pub width: f64,
    /// Block thickness h (m). Default 0.30 (the Figure 5 sheet).
    pub thickness: f64,
    /// Gap between neighbouring blocks in the initial stack (m). Default 0.05.
    pub gap: f64,
    /// Height of the bottom of the lowest row above the water level (m). Default 0.5.
    pub base: f64,
    /// Amplitude of the seeded random horizontal offset of each block (m). Default 0.02.
    pub jitter: f64,
    /// Amplitude of the seeded random tilt of each block (rad). Default 0.05.
    pub tilt: f64,
    /// Put a fixed wall on each side. Default true.
    pub walls: bool,
    /// Clear width between the walls (m). Default 4.0.
    pub basin_width: f64,
}

impl Default for PileSection {
    fn default() -> Self {
        Self {
            blocks: 200,
            columns: 10,
            width: 0.25,
            thickness: 0.30,
            gap: 0.05,
            base: 0.5,
            jitter: 0.02,
            tilt: 0.05,
            walls: true,
            basin_width: 4.0,
        }
    }
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
    /// A rubble pile, if any.
    pub pile: Option<PileSection>,
}

impl Default for Scene {
    fn default() -> Self {
        Self {
            name: "rubble-pile".into(),
            seed: 1,
            duration: 10.0,
            ice: IceSection::default(),
            contact: ContactParams::default(),
            water: WaterSection::default(),
            numerics: NumericsSection::default(),
            pile: Some(PileSection::default()),
        }
    }
}

impl Scene {
    /// Parses a scene from TOML text; missing keys take their defaults, unknown keys are
    /// an error naming them.
    pub fn from_toml(text: &str) -> Result<Scene, SceneError> {
        let s: Scene = toml::from_str(text).map_err(|e| SceneError::Parse(e.to_string()))?;
        s.validate()?;
        Ok(s)
    }

    /// The scene as TOML text.
    pub fn to_toml(&self) -> String {
        toml::to_string_pretty(self).expect("a scene always serialises")
    }

    /// Applies `key=value` overrides with dotted keys (`contact.mu=0.4`, `pile.blocks=50`,
    /// `duration=20`). The value is parsed as a TOML value.
    pub fn with_overrides<S: AsRef<str>>(&self, sets: &[S]) -> Result<Scene, SceneError> {
        let mut doc: toml::Table =
            toml::from_str(&self.to_toml()).map_err(|e| SceneError::Parse(e.to_string()))?;
        for set in sets {
            let set = set.as_ref();
            let (key, value) = set
                .split_once('=')
                .ok_or_else(|| SceneError::Override(set.into(), "expected key=value".into()))?;
            let value: toml::Value = toml::from_str::<toml::Table>(&format!("v = {value}"))
                .or_else(|_| toml::from_str::<toml::Table>(&format!("v = \"{value}\"")))
                .map_err(|e| SceneError::Override(set.into(), e.to_string()))?
                .remove("v")
                .expect("parsed table has v");
            let parts: Vec<&str> = key.trim().split('.').collect();
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

    /// Checks the scene-level parameters (the world checks its own).
    pub fn validate(&self) -> Result<(), SceneError> {
        let bad = |k: &str, why: &str| Err(SceneError::Invalid(k.into(), why.into()));
        if !(self.duration >= 0.0 && self.duration.is_finite()) {
            return bad("duration", "must be a non-negative number of seconds");
        }
        if !(self.numerics.sample_interval > 0.0 && self.numerics.sample_interval.is_finite()) {
            return bad("numerics.sample_interval", "must be positive (s)");
        }
        if !(self.numerics.time_step >= 0.0 && self.numerics.time_step.is_finite()) {
            return bad("numerics.time_step", "must be 0 (derived) or positive (s)");
        }
        if let Some(p) = &self.pile {
            if p.columns == 0 {
                return bad("pile.columns", "must be at least 1");
            }
            for (k, v) in [
                ("pile.width", p.width),
                ("pile.thickness", p.thickness),
                ("pile.basin_width", p.basin_width),
            ] {
                if !(v > 0.0 && v.is_finite()) {
                    return bad(k, "must be positive (m)");
                }
            }
            for (k, v) in [
                ("pile.gap", p.gap),
                ("pile.jitter", p.jitter),
                ("pile.tilt", p.tilt),
            ] {
                if !(v >= 0.0 && v.is_finite()) {
                    return bad(k, "must be non-negative");
                }
            }
            if !p.base.is_finite() {
                return bad("pile.base", "must be finite (m)");
            }
            let need = p.columns as f64 * (p.width + p.gap) + p.gap;
            if p.walls && need > p.basin_width {
                return bad(
                    "pile.basin_width",
                    "is narrower than the columns of the initial stack",
                );
            }
        }
        Ok(())
    }

    /// The world parameters of this scene.
    pub fn world_params(&self) -> WorldParams {
        WorldParams {
            gravity: self.ice.gravity,
            ice_density: self.ice.density,
            contact: self.contact.clone(),
            water: self.water.enabled.then_some(WaterParams {
                level: self.water.level,
                density: self.water.density,
                drag_coefficient: self.water.drag_coefficient,
                linear_drag: self.water.linear_drag,
            }),
            time_step_safety: self.numerics.time_step_safety,
            time_step: (self.numerics.time_step > 0.0).then_some(self.numerics.time_step),
        }
    }

    /// Builds the world at time zero.
    pub fn build(&self) -> Result<World, SceneError> {
        self.validate()?;
        let mut world = World::new(self.world_params())?;
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(self.seed);
        let level = self.water.level;
        if let Some(p) = &self.pile {
            build_pile(&mut world, p, level, &mut rng)?;
        }
        Ok(world)
    }
}

/// A uniform random number in [−1, 1).
fn symmetric(rng: &mut Xoshiro256PlusPlus) -> f64 {
    (rng.next_u64() >> 11) as f64 * (2.0 / (1u64 << 53) as f64) - 1.0
}

fn build_pile(
    world: &mut World,
    p: &PileSection,
    level: f64,
    rng: &mut Xoshiro256PlusPlus,
) -> Result<(), SceneError> {
    let shape = Shape::rectangle(p.width, p.thickness)
        .map_err(|e| SceneError::Invalid("pile".into(), e.to_string()))?;
    let pitch_x = p.width + p.gap;
    let pitch_y = p.thickness + p.gap;
    let x0 = -0.5 * (p.columns as f64 * pitch_x - p.gap) + 0.5 * p.width;
    for k in 0..p.blocks {
        let (row, col) = (k / p.columns, k % p.columns);
        let x = x0 + col as f64 * pitch_x + p.jitter.min(0.45 * p.gap) * symmetric(rng);
        let y = level + p.base + 0.5 * p.thickness + row as f64 * pitch_y;
        let tilt = p.tilt * symmetric(rng);
        world.add_block(shape, V2::new(x, y), tilt, Drive::FREE);
    }
    if p.walls {
        let rows = p.blocks.div_ceil(p.columns) as f64;
        let top = level + p.base + rows * pitch_y + 1.0;
        let bottom = level - 2.0 * rows * p.thickness - 2.0;
        let t = 0.5;
        let wall = Shape::rectangle(t, top - bottom)
            .map_err(|e| SceneError::Invalid("pile walls".into(), e.to_string()))?;
        let yc = 0.5 * (top + bottom);
        let xw = 0.5 * p.basin_width + 0.5 * t;
        world.add_block(wall, V2::new(-xw, yc), 0.0, Drive::FIXED);
        world.add_block(wall, V2::new(xw, yc), 0.0, Drive::FIXED);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_scene_round_trips_through_toml() {
        let s = Scene::default();
        assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
    }

    #[test]
    fn unknown_keys_are_rejected_by_name() {
        let e = Scene::from_toml("duraton = 3.0").unwrap_err().to_string();
        assert!(e.contains("duraton"), "{e}");
        let e = Scene::from_toml("[contact]\nmuu = 0.3")
            .unwrap_err()
            .to_string();
        assert!(e.contains("muu"), "{e}");
        let e = Scene::default()
            .with_overrides(&["contact.mew=1"])
            .unwrap_err()
            .to_string();
        assert!(e.contains("mew"), "{e}");
    }

    #[test]
    fn overrides_set_nested_values() {
        let s = Scene::default()
            .with_overrides(&[
                "contact.mu=0.4",
                "pile.blocks=12",
                "water.enabled=false",
                "name=x",
            ])
            .unwrap();
        assert_eq!(s.contact.mu, 0.4);
        assert_eq!(s.pile.as_ref().unwrap().blocks, 12);
        assert!(!s.water.enabled);
        assert_eq!(s.name, "x");
        assert!(s.world_params().water.is_none());
    }

    #[test]
    fn invalid_values_are_named() {
        let e = Scene::default()
            .with_overrides(&["duration=-1"])
            .unwrap_err()
            .to_string();
        assert!(e.contains("duration"), "{e}");
        let e = Scene::default()
            .with_overrides(&["contact.normal_stiffness=-5"])
            .unwrap()
            .build()
            .unwrap_err()
            .to_string();
        assert!(e.contains("normal_stiffness"), "{e}");
        let e = Scene::from_toml("duration = nan").unwrap_err().to_string();
        assert!(e.contains("duration"), "{e}");
    }
}
