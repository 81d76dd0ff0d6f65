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
    Block, ContactParams, Dashpot, Drive, JointMaterial, Role, Shape, V2, WaterParams, World,
    WorldError, WorldParams,
};
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

pub use crate::limits;
use crate::limits::Range;

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
    /// Safety factor on the stable time step (dimensionless, in (0, 1]). Default
    /// [`crate::dem::world::DEFAULT_TIME_STEP_SAFETY`]; see docs/speed-vs-error.md.
    pub time_step_safety: f64,
    /// Fixed time step (s); 0 derives it from the stiffest element. Default 0. A value
    /// above the scene's stable limit is refused before the run, with the limit.
    pub time_step: f64,
    /// Time discretisation of the contact dashpot of eq (3): "implicit" (default) or
    /// "explicit" (the paper's form; needs a smaller step). See [`Dashpot`].
    pub contact_dashpot: Dashpot,
    /// Interval between samples of the energy budget and the ridging force (s).
    /// Default 0.2 s, the paper's force sampling interval (Figure 6).
    pub sample_interval: f64,
}

impl Default for NumericsSection {
    fn default() -> Self {
        Self {
            time_step_safety: crate::dem::world::DEFAULT_TIME_STEP_SAFETY,
            time_step: 0.0,
            contact_dashpot: Dashpot::default(),
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

/// The lead-ice sheet pushed into the ridge (Table 1; Figure 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SheetSection {
    /// Thickness h (m). Default 0.30.
    pub thickness: f64,
    /// Component block width W (m). Default 0.25 (Table 1: 0.20 for h = 0.20, 0.30 for
    /// h = 0.45).
    pub block_width: f64,
    /// Length of the sheet, kept constant as blocks break off (m). Default 25 m (100
    /// blocks): ten times the distance π/(4β) ≈ 2.5 m at which a 0.30 m sheet breaks, so
    /// the driven end is far from the failure zone. The paper does not give it.
    pub length: f64,
    /// Pushing speed U (m/s). Default 0.25 (Table 1).
    pub speed: f64,
    /// Young's modulus at the top (Pa). Default 1e8 (Table 1, lead top 0.1 GPa).
    pub e_top: f64,
    /// Young's modulus at the bottom (Pa). Default 6.7e7 (Table 1, 0.067 GPa).
    pub e_bottom: f64,
    /// Poisson's ratio (dimensionless). Default 0.3 (Table 1).
    pub poisson: f64,
    /// Tensile strength at the top surface (Pa). Default 750e3 (Table 1).
    pub strength_top: f64,
    /// Tensile strength at the bottom surface (Pa). Default 350e3 (Table 1).
    pub strength_bottom: f64,
    /// Skeletal layer as a fraction of h (dimensionless). Default 0.2 (Table 1).
    pub skeletal_fraction: f64,
    /// Largest skeletal layer (m). Default 0.06 (Table 1).
    pub skeletal_max: f64,
    /// Relative random variation of E at each sheet joint. Default 0.01 (±1 %).
    pub modulus_variation: f64,
    /// Bevel leg under the sheet tip, point B of Figure 1, as a fraction of h
    /// (dimensionless). Default 1/3 (0.10 m for h = 0.30 m): the paper shows the bevel but
    /// not its size; a third of h lets the tip ride onto a 45° slope and scales with the
    /// sheet.
    pub tip_bevel_fraction: f64,
    /// Bevel leg at the corners of broken faces (m). Default 0.02 ("beveled 2 cm at a 45°
    /// angle").
    pub corner_bevel: f64,
    /// Decay constant of eq (8) (dimensionless). Default 4.
    pub viscous_decay: f64,
    /// Gap between the sheet tip and the floe nose or wall at the start (m). Default 0.05.
    pub gap: f64,
    /// Hold the driven (leftmost) block at its floating height and orientation while it
    /// moves at U. Default true: the paper's "the first (leftmost) block of the sheet moves
    /// with constant speed U in the positive x direction" read as a prescribed motion, the
    /// far-field ice at the water line. With false only its x velocity is prescribed, and
    /// a long sheet under compression can tilt and sink its far end (a fully submerged
    /// block has only (ρ_w − ρ_i)·g·A of buoyancy left to pull it back).
    pub clamp_driven_end: bool,
}

impl Default for SheetSection {
    fn default() -> Self {
        Self {
            thickness: 0.30,
            block_width: 0.25,
            length: 25.0,
            speed: 0.25,
            e_top: 1.0e8,
            e_bottom: 6.7e7,
            poisson: 0.3,
            strength_top: 750e3,
            strength_bottom: 350e3,
            skeletal_fraction: 0.2,
            skeletal_max: 0.06,
            modulus_variation: 0.01,
            tip_bevel_fraction: 1.0 / 3.0,
            corner_bevel: 0.02,
            viscous_decay: 4.0,
            gap: 0.05,
            clamp_driven_end: true,
        }
    }
}

impl SheetSection {
    /// The prescribed motion of the driven block.
    pub fn drive(&self) -> Drive {
        Drive {
            u: Some(self.speed),
            v: self.clamp_driven_end.then_some(0.0),
            omega: self.clamp_driven_end.then_some(0.0),
        }
    }

    /// Bevel leg under the sheet tip (m).
    pub fn tip_bevel(&self) -> f64 {
        self.tip_bevel_fraction * self.thickness
    }

    /// Skeletal layer (m): `skeletal_fraction·h`, at most `skeletal_max`.
    pub fn skeletal(&self) -> f64 {
        (self.skeletal_fraction * self.thickness).min(self.skeletal_max)
    }
}

/// The thick floe the sheet is pushed against (Table 1; Figure 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FloeSection {
    /// Thickness (m). Default 2.0 (Table 1).
    pub thickness: f64,
    /// Length (m). Default 20 m, room for the sail; the paper does not give it.
    pub length: f64,
    /// Component block width (m). Default 1.0: the paper does not give it; 1 m keeps the
    /// floe's joints no stiffer (per unit mass) than the sheet's, so they do not set Δt.
    pub block_width: f64,
    /// Young's modulus at the top (Pa). Default 1e9 (Table 1).
    pub e_top: f64,
    /// Young's modulus at the bottom (Pa). Default 6.7e8 (Table 1).
    pub e_bottom: f64,
    /// Poisson's ratio. Default 0.3.
    pub poisson: f64,
    /// Tensile strength at the top (Pa). Default 750e3, the sheet's (the paper gives none
    /// for the floe).
    pub strength_top: f64,
    /// Tensile strength at the bottom (Pa). Default 350e3, the sheet's.
    pub strength_bottom: f64,
    /// Stiffness of the vertical support spring per metre of floe (N/m per m of depth,
    /// i.e. N/m²). Default 3e4: with buoyancy (ρ_w·g ≈ 1e4 N/m² while the 0.18 m
    /// freeboard lasts) a broken floe piece under a 2.4 m sail of rubble packed at 60 %
    /// (13 kN per metre of floe) subsides 0.37 m, inside the paper's "half a meter or less"
    /// (`tests/ridging.rs::broken_floe_piece_subsides_at_most_half_a_metre`).
    pub support_stiffness: f64,
    /// Damping of the support as a fraction of critical for spring plus buoyancy. Default
    /// 0.5.
    pub support_damping_fraction: f64,
    /// Bevel leg of the floe nose, its top corner facing the sheet (m). Default 0.5: a 45°
    /// ramp from the floe top (0.18 m above water) to 0.32 m below, spanning the waterline
    /// where the sheet arrives.
    pub nose_bevel: f64,
    /// Bevel leg at the corners of broken floe faces (m). Default 0.02.
    pub corner_bevel: f64,
    /// Pin the far (rightmost) floe block in x and y, point C of Figure 1. Default true.
    pub pin: bool,
}

impl Default for FloeSection {
    fn default() -> Self {
        Self {
            thickness: 2.0,
            length: 20.0,
            block_width: 1.0,
            e_top: 1.0e9,
            e_bottom: 6.7e8,
            poisson: 0.3,
            strength_top: 750e3,
            strength_bottom: 350e3,
            support_stiffness: 3.0e4,
            support_damping_fraction: 0.5,
            nose_bevel: 0.5,
            corner_bevel: 0.02,
            pin: true,
        }
    }
}

/// A fixed vertical wall in place of the floe.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WallSection {
    /// x of the wall face towards the sheet (m). Default 0.
    pub x: f64,
    /// Top of the wall (m). Default 5.
    pub top: f64,
    /// Bottom of the wall (m). Default −15.
    pub bottom: f64,
    /// Thickness of the wall (m). Default 1.
    pub thickness: f64,
}

impl Default for WallSection {
    fn default() -> Self {
        Self {
            x: 0.0,
            top: 5.0,
            bottom: -15.0,
            thickness: 1.0,
        }
    }
}

/// Joint viscosity and crack growth, shared by the sheet, floe and rubble.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct JointSection {
    /// Joint viscosity as a fraction of critical, η = f·2·sqrt(ρ_i·E). Default 0.1 (the
    /// paper's 10 %).
    pub damping_fraction: f64,
    /// Crack speed across a joint (m/s). Default 50: the paper says only that a crack
    /// takes many steps; 50 m/s crosses a 0.24 m joint in 4.8 ms, about 40 steps of the
    /// default Δt, and is of the order of measured crack speeds in sea ice (tens to hundreds
    /// of m/s) while staying slow against the ~0.1 s flexural response of the sheet.
    pub crack_speed: f64,
}

impl Default for JointSection {
    fn default() -> Self {
        Self {
            damping_fraction: 0.1,
            crack_speed: 50.0,
        }
    }
}

/// What a run writes besides its summary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OutputSection {
    /// Interval between snapshots (s); 0 for none. Default 50.
    pub snapshot_interval: f64,
    /// Snapshot frame [x0, x1, y0, y1] (m). Default [−14, 6, −8, 4]: 20 m × 12 m as in
    /// Figure 5, the floe nose at x = 0. The least a snapshot shows: `simulate` grows it
    /// where needed to hold every rubble block and the sheet and floe within 3 m of the
    /// rubble (1 m margin), so that a sail or keel past it is not clipped.
    pub frame: [f64; 4],
}

impl Default for OutputSection {
    fn default() -> Self {
        Self {
            snapshot_interval: 50.0,
            frame: [-14.0, 6.0, -8.0, 4.0],
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

/// Checks scene parameter `key` against its range ([`limits`]).
fn check(range: Range, key: &str, value: f64) -> Result<(), SceneError> {
    match range.violation(value) {
        None => Ok(()),
        Some(why) => Err(SceneError::Invalid(key.into(), why)),
    }
}

/// Checks a bevel leg (m): 0 or at least [`limits::MIN_BEVEL`].
fn check_bevel(key: &str, leg: f64) -> Result<(), SceneError> {
    if leg == 0.0 || leg >= limits::MIN_BEVEL {
        Ok(())
    } else {
        Err(SceneError::Invalid(
            key.into(),
            format!(
                "makes a bevel leg of {leg:e} m: a bevel is 0 (none) or at least {} m, as a shorter one is a degenerate edge",
                limits::MIN_BEVEL
            ),
        ))
    }
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

    /// Checks the scene-level parameters (the world checks its own): each bounded parameter
    /// against its range in [`limits`], the ice lighter than the water, the block geometry,
    /// and the number of blocks. The message names the parameter and its valid range.
    pub fn validate(&self) -> Result<(), SceneError> {
        use limits::*;
        let bad = |k: &str, why: &str| Err(SceneError::Invalid(k.into(), why.into()));
        if !self.duration.is_finite() {
            return bad("duration", "must be a finite number of seconds");
        }
        check(DURATION, "duration", self.duration)?;
        check(ICE_DENSITY, "ice.density", self.ice.density)?;
        if self.water.enabled {
            check(WATER_DENSITY, "water.density", self.water.density)?;
            if self.ice.density >= self.water.density {
                return Err(SceneError::Invalid(
                    "ice.density".into(),
                    format!(
                        "{} kg/m³ is not below water.density = {} kg/m³: ice denser than water sinks",
                        self.ice.density, self.water.density
                    ),
                ));
            }
        }
        if self.numerics.time_step > 0.0 && self.numerics.time_step > self.duration {
            return Err(SceneError::Invalid(
                "numerics.time_step".into(),
                format!(
                    "{} s is longer than duration = {} s: the run would take no step",
                    self.numerics.time_step, self.duration
                ),
            ));
        }
        let mut blocks = 0.0f64;
        if !(self.numerics.sample_interval > 0.0 && self.numerics.sample_interval.is_finite()) {
            return bad("numerics.sample_interval", "must be positive (s)");
        }
        if !(self.numerics.time_step >= 0.0 && self.numerics.time_step.is_finite()) {
            return bad("numerics.time_step", "must be 0 (derived) or positive (s)");
        }
        if let Some(sh) = &self.sheet {
            for (k, v) in [
                ("sheet.thickness", sh.thickness),
                ("sheet.block_width", sh.block_width),
                ("sheet.length", sh.length),
                ("sheet.speed", sh.speed),
                ("sheet.e_top", sh.e_top),
                ("sheet.e_bottom", sh.e_bottom),
                ("sheet.strength_top", sh.strength_top),
                ("sheet.strength_bottom", sh.strength_bottom),
            ] {
                if !(v > 0.0 && v.is_finite()) {
                    return bad(k, "must be positive");
                }
            }
            check(THICKNESS, "sheet.thickness", sh.thickness)?;
            check(BLOCK_WIDTH, "sheet.block_width", sh.block_width)?;
            check(LENGTH, "sheet.length", sh.length)?;
            check(SPEED, "sheet.speed", sh.speed)?;
            check(YOUNGS_MODULUS, "sheet.e_top", sh.e_top)?;
            check(YOUNGS_MODULUS, "sheet.e_bottom", sh.e_bottom)?;
            check(TENSILE_STRENGTH, "sheet.strength_top", sh.strength_top)?;
            check(
                TENSILE_STRENGTH,
                "sheet.strength_bottom",
                sh.strength_bottom,
            )?;
            blocks += (sh.length / sh.block_width).round().max(2.0);
            for (k, v) in [
                ("sheet.skeletal_fraction", sh.skeletal_fraction),
                ("sheet.skeletal_max", sh.skeletal_max),
                ("sheet.modulus_variation", sh.modulus_variation),
                ("sheet.tip_bevel_fraction", sh.tip_bevel_fraction),
                ("sheet.corner_bevel", sh.corner_bevel),
                ("sheet.viscous_decay", sh.viscous_decay),
                ("sheet.gap", sh.gap),
            ] {
                if !(v >= 0.0 && v.is_finite()) {
                    return bad(k, "must be non-negative");
                }
            }
            if !(0.0..0.5).contains(&sh.poisson) {
                return bad("sheet.poisson", "must lie in [0, 0.5)");
            }
            if sh.skeletal() >= sh.thickness {
                return bad("sheet.skeletal_fraction", "leaves no joint");
            }
            for (k, v) in [
                ("sheet.tip_bevel_fraction", sh.tip_bevel()),
                ("sheet.corner_bevel", sh.corner_bevel),
            ] {
                check_bevel(k, v)?;
            }
            if sh.tip_bevel_fraction >= 1.0 {
                return bad(
                    "sheet.tip_bevel_fraction",
                    "must be below 1: the bevel under the tip is a fraction of the thickness",
                );
            }
            if sh.tip_bevel() >= sh.block_width {
                // The bevel leg scales with the thickness: a thick sheet needs wide blocks.
                return Err(SceneError::Invalid(
                    "sheet.block_width".into(),
                    format!(
                        "{} m is not wider than the bevel under the sheet tip, tip_bevel_fraction × thickness = {} × {} m = {:.3} m: use blocks wider than that (the paper uses about the thickness) or a smaller sheet.tip_bevel_fraction",
                        sh.block_width,
                        sh.tip_bevel_fraction,
                        sh.thickness,
                        sh.tip_bevel()
                    ),
                ));
            }
            let side = sh.block_width.min(sh.thickness);
            if 2.0 * sh.corner_bevel >= side {
                return Err(SceneError::Invalid(
                    "sheet.corner_bevel".into(),
                    format!(
                        "{} m must be shorter than half the sheet block's smaller side, min(sheet.block_width, sheet.thickness) / 2 = {} m",
                        sh.corner_bevel,
                        0.5 * side
                    ),
                ));
            }
            if sh.modulus_variation >= 1.0 {
                return bad("sheet.modulus_variation", "must be below 1");
            }
            if sh.length < 2.0 * sh.block_width {
                return bad("sheet.length", "must hold at least two blocks");
            }
        }
        if let Some(f) = &self.floe {
            for (k, v) in [
                ("floe.thickness", f.thickness),
                ("floe.length", f.length),
                ("floe.block_width", f.block_width),
                ("floe.e_top", f.e_top),
                ("floe.e_bottom", f.e_bottom),
                ("floe.strength_top", f.strength_top),
                ("floe.strength_bottom", f.strength_bottom),
            ] {
                if !(v > 0.0 && v.is_finite()) {
                    return bad(k, "must be positive");
                }
            }
            check(THICKNESS, "floe.thickness", f.thickness)?;
            check(BLOCK_WIDTH, "floe.block_width", f.block_width)?;
            check(LENGTH, "floe.length", f.length)?;
            check(YOUNGS_MODULUS, "floe.e_top", f.e_top)?;
            check(YOUNGS_MODULUS, "floe.e_bottom", f.e_bottom)?;
            check(TENSILE_STRENGTH, "floe.strength_top", f.strength_top)?;
            check(TENSILE_STRENGTH, "floe.strength_bottom", f.strength_bottom)?;
            blocks += (f.length / f.block_width).round().max(1.0);
            for (k, v) in [
                ("floe.support_stiffness", f.support_stiffness),
                ("floe.support_damping_fraction", f.support_damping_fraction),
                ("floe.nose_bevel", f.nose_bevel),
                ("floe.corner_bevel", f.corner_bevel),
            ] {
                if !(v >= 0.0 && v.is_finite()) {
                    return bad(k, "must be non-negative");
                }
            }
            if !(0.0..0.5).contains(&f.poisson) {
                return bad("floe.poisson", "must lie in [0, 0.5)");
            }
            check_bevel("floe.nose_bevel", f.nose_bevel)?;
            check_bevel("floe.corner_bevel", f.corner_bevel)?;
            let side = f.block_width.min(f.thickness);
            if f.nose_bevel >= side {
                return Err(SceneError::Invalid(
                    "floe.nose_bevel".into(),
                    format!(
                        "{} m must be shorter than the floe block's smaller side, min(floe.block_width, floe.thickness) = {side} m",
                        f.nose_bevel
                    ),
                ));
            }
            if 2.0 * f.corner_bevel >= side {
                return Err(SceneError::Invalid(
                    "floe.corner_bevel".into(),
                    format!(
                        "{} m must be shorter than half the floe block's smaller side, min(floe.block_width, floe.thickness) / 2 = {} m",
                        f.corner_bevel,
                        0.5 * side
                    ),
                ));
            }
        }
        if self.floe.is_some() && self.wall.is_some() {
            return bad("wall", "a scene has a floe or a wall, not both");
        }
        if let Some(w) = &self.wall
            && !(w.top > w.bottom && w.thickness > 0.0 && w.x.is_finite())
        {
            return bad("wall", "needs top > bottom and a positive thickness");
        }
        if !(self.joint.damping_fraction >= 0.0 && self.joint.damping_fraction.is_finite()) {
            return bad("joint.damping_fraction", "must be non-negative");
        }
        if !(self.joint.crack_speed > 0.0 && self.joint.crack_speed.is_finite()) {
            return bad("joint.crack_speed", "must be positive (m/s)");
        }
        if self.output.snapshot_interval.is_nan() || self.output.snapshot_interval < 0.0 {
            return bad("output.snapshot_interval", "must be non-negative (s)");
        }
        let f = self.output.frame;
        if !(f[1] > f[0] && f[3] > f[2]) {
            return bad(
                "output.frame",
                "must be [x0, x1, y0, y1] with x1 > x0 and y1 > y0",
            );
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
            check(THICKNESS, "pile.thickness", p.thickness)?;
            check(BLOCK_WIDTH, "pile.width", p.width)?;
            if p.blocks > MAX_BLOCKS {
                return Err(SceneError::Invalid(
                    "pile.blocks".into(),
                    format!(
                        "{} is out of range: must lie in [0, {MAX_BLOCKS}] (memory and contact search grow with the number of blocks)",
                        p.blocks
                    ),
                ));
            }
            blocks += p.blocks as f64;
            let need = p.columns as f64 * (p.width + p.gap) + p.gap;
            if p.walls && need > p.basin_width {
                return bad(
                    "pile.basin_width",
                    "is narrower than the columns of the initial stack",
                );
            }
        }
        if blocks > MAX_BLOCKS as f64 {
            return Err(SceneError::Invalid(
                "sheet.length, floe.length, pile.blocks".into(),
                format!(
                    "the scene would start with {blocks} blocks (sheet.length / sheet.block_width + floe.length / floe.block_width + pile.blocks); at most {MAX_BLOCKS} are allowed, as memory and contact search grow with them"
                ),
            ));
        }
        Ok(())
    }

    /// Checks that a run of this scene with time step `dt` (s), e.g. the stable step its
    /// world derived, takes at least one step: `dt` must be positive, finite and no longer
    /// than the duration. [`crate::simulation::run`] calls it, so every face (command line,
    /// scene file, Python, C) refuses such a run before it starts.
    pub fn check_run_length(&self, dt: f64) -> Result<(), SceneError> {
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(SceneError::Invalid(
                "numerics.time_step".into(),
                format!(
                    "the time step is {dt} s: the scene has nothing that sets a stable step (no free blocks?); set numerics.time_step to a positive value below duration = {} s",
                    self.duration
                ),
            ));
        }
        if dt > self.duration {
            return Err(SceneError::Invalid(
                "duration".into(),
                format!(
                    "{} s is shorter than the time step {dt:.3e} s: the run would take no step; use a longer duration",
                    self.duration
                ),
            ));
        }
        Ok(())
    }

    /// The world parameters of this scene.
    pub fn world_params(&self) -> WorldParams {
        let mut contact = self.contact.clone();
        if contact.reference_thickness.is_none()
            && let Some(sh) = &self.sheet
        {
            contact.reference_thickness = Some(sh.thickness);
        }
        WorldParams {
            gravity: self.ice.gravity,
            ice_density: self.ice.density,
            contact,
            crack_speed: self.joint.crack_speed,
            water: self.water.enabled.then_some(WaterParams {
                level: self.water.level,
                density: self.water.density,
                drag_coefficient: self.water.drag_coefficient,
                linear_drag: self.water.linear_drag,
            }),
            time_step_safety: self.numerics.time_step_safety,
            time_step: (self.numerics.time_step > 0.0).then_some(self.numerics.time_step),
            contact_dashpot: self.numerics.contact_dashpot,
            ..WorldParams::default()
        }
    }

    /// Builds the world at time zero.
    pub fn build(&self) -> Result<World, SceneError> {
        self.validate()?;
        let mut world = World::new(self.world_params())?;
        // Δt is derived once, from the complete world (not after every block and joint).
        world.defer_time_step();
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(self.seed);
        let level = self.water.level;
        if let Some(p) = &self.pile {
            build_pile(&mut world, p, level, &mut rng)?;
        }
        if let Some(f) = &self.floe {
            self.build_floe(&mut world, f)?;
        }
        if let Some(w) = &self.wall {
            let shape = Shape::rectangle(w.thickness, w.top - w.bottom)
                .map_err(|e| SceneError::Invalid("wall".into(), e.to_string()))?;
            let id = world.add_block(
                shape,
                V2::new(w.x + 0.5 * w.thickness, 0.5 * (w.top + w.bottom)),
                0.0,
                Drive::FIXED,
            );
            world.bodies.role[id as usize] = Role::Wall;
        }
        if let Some(sh) = &self.sheet {
            self.build_sheet(&mut world, sh)?;
        }
        world.finish_time_step()?;
        Ok(world)
    }

    /// Height of the centre of a floating slab of thickness `h` (m) at rest.
    fn floating_centre(&self, h: f64) -> f64 {
        let level = self.water.level;
        if self.water.enabled {
            level + 0.5 * h - h * self.ice.density / self.water.density
        } else {
            level + 0.5 * h
        }
    }

    fn build_sheet(&self, world: &mut World, sh: &SheetSection) -> Result<(), SceneError> {
        let n = (sh.length / sh.block_width).round().max(2.0) as usize;
        let yc = self.floating_centre(sh.thickness);
        let mat = JointMaterial {
            e_top: sh.e_top,
            e_bottom: sh.e_bottom,
            poisson: sh.poisson,
            damping_fraction: self.joint.damping_fraction,
            strength_top: sh.strength_top,
            strength_bottom: sh.strength_bottom,
        };
        let front = self
            .floe
            .as_ref()
            .map(|_| 0.0)
            .or(self.wall.as_ref().map(|w| w.x))
            .unwrap_or(0.0)
            - sh.gap;
        let mut boundary = SheetBoundary {
            speed: sh.speed,
            clamp: sh.clamp_driven_end,
            width: sh.block_width,
            thickness: sh.thickness,
            skeletal: sh.skeletal(),
            material: mat,
            modulus_variation: sh.modulus_variation,
            seed: self.seed,
            joints_made: 0,
            tip_bevel: sh.tip_bevel(),
            corner_bevel: sh.corner_bevel,
            decay: sh.viscous_decay,
            viscosity: self
                .contact
                .viscous_coefficient_for(sh.thickness, self.ice.density)
                * sh.thickness,
            blocks: Vec::with_capacity(n),
        };
        for k in 0..n {
            let bevel = if k + 1 == n {
                [0.0, sh.tip_bevel(), 0.0, 0.0]
            } else {
                [0.0; 4]
            };
            let block = Block {
                width: sh.block_width,
                thickness: sh.thickness,
                bevel,
            };
            let drive = if k == 0 { sh.drive() } else { Drive::FREE };
            let x = front - (n - k) as f64 * sh.block_width + 0.5 * sh.block_width;
            let id = world.add_rect(block, V2::new(x, yc), 0.0, drive, Role::Sheet)?;
            if let Some(&prev) = boundary.blocks.last() {
                let f = boundary.modulus_factor(boundary.joints_made);
                let m = JointMaterial {
                    e_top: mat.e_top * f,
                    e_bottom: mat.e_bottom * f,
                    ..mat
                };
                world.join(prev, id, sh.skeletal(), m)?;
                boundary.joints_made += 1;
            }
            boundary.blocks.push(id);
        }
        world.boundary.sheet = Some(boundary);
        Ok(())
    }

    fn build_floe(&self, world: &mut World, f: &FloeSection) -> Result<(), SceneError> {
        let n = (f.length / f.block_width).round().max(1.0) as usize;
        let yc = self.floating_centre(f.thickness);
        let skeletal = f.thickness.min(0.3) * 0.2;
        let skeletal = skeletal.min(0.06);
        let mat = JointMaterial {
            e_top: f.e_top,
            e_bottom: f.e_bottom,
            poisson: f.poisson,
            damping_fraction: self.joint.damping_fraction,
            strength_top: f.strength_top,
            strength_bottom: f.strength_bottom,
        };
        let g = self.ice.gravity;
        let rho_w = if self.water.enabled {
            self.water.density
        } else {
            0.0
        };
        let mut support = FloeSupport {
            blocks: Vec::with_capacity(n),
            stiffness: Vec::with_capacity(n),
            damping: Vec::with_capacity(n),
            corner_bevel: f.corner_bevel,
        };
        let mut prev = None;
        for k in 0..n {
            let bevel = if k == 0 {
                [0.0, 0.0, 0.0, f.nose_bevel]
            } else {
                [0.0; 4]
            };
            let block = Block {
                width: f.block_width,
                thickness: f.thickness,
                bevel,
            };
            let drive = if f.pin && k + 1 == n {
                Drive {
                    u: Some(0.0),
                    v: Some(0.0),
                    omega: None,
                }
            } else {
                Drive::FREE
            };
            let x = (k as f64 + 0.5) * f.block_width;
            let id = world.add_rect(block, V2::new(x, yc), 0.0, drive, Role::Floe)?;
            if let Some(p) = prev {
                world.join(p, id, skeletal, mat)?;
            }
            prev = Some(id);
            let i = id as usize;
            let k_s = f.support_stiffness * f.block_width;
            let m = world.bodies.mass[i];
            let k_total = k_s + rho_w * g * f.block_width;
            support.blocks.push((id, world.bodies.pos[i].y));
            support.stiffness.push(k_s);
            support
                .damping
                .push(f.support_damping_fraction * 2.0 * (k_total * m).sqrt());
        }
        world.boundary.floe = Some(support);
        Ok(())
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
