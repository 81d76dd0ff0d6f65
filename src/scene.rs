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
    Block, ContactOnset, ContactParams, Dashpot, Drive, JointMaterial, Role, Shape, V2,
    WaterParams, World, WorldError, WorldParams,
};
use rand_xoshiro::Xoshiro256PlusPlus;
use rand_xoshiro::rand_core::{Rng, SeedableRng};
use serde::{Deserialize, Serialize};

mod build;
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
    /// The file could not be read (the same message as [`crate::io::IoError::Os`]; the
    /// scene layer sits below `io`, so it keeps the path and the cause itself).
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

use crate::limits;
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
    /// Time discretisation of the joints' viscous stress of eq (1): "explicit" (default,
    /// the paper's form) or "implicit" (centred in time; experimental). See
    /// [`crate::dem::WorldParams::joint_dashpot`].
    #[serde(
        default = "Dashpot::explicit",
        skip_serializing_if = "Dashpot::is_explicit"
    )]
    pub joint_dashpot: Dashpot,
    /// How a new contact reads its first overlap rate in eq (3): "area" (default, the
    /// paper's) or "velocity" (experimental). See [`crate::dem::ContactOnset`].
    #[serde(default, skip_serializing_if = "ContactOnset::is_area")]
    pub contact_onset: ContactOnset,
    /// Gauss–Seidel sweeps of the implicit contact dashpot over the contacts (count, 0–50):
    /// 0 (default) solves each contact alone; experimental. See
    /// [`crate::dem::WorldParams::contact_dashpot_sweeps`].
    #[serde(default, skip_serializing_if = "crate::dem::world::is_zero")]
    pub contact_dashpot_sweeps: u32,
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
            joint_dashpot: Dashpot::Explicit,
            contact_onset: ContactOnset::Area,
            contact_dashpot_sweeps: 0,
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
    /// The length L_v (m) that turns eq (3)'s k_nv (kg/(m²·s)) into eq (8)'s coefficient
    /// k′ = k_nv·L_v·e^(−4(x_i − x_1)/(x_n − x_1)) (kg/(m·s)): eq (8) writes k′ = k_nv·e^(…)
    /// with no length. Unset (the default), the sheet thickness h, the height of the face a
    /// contact's dashpot acts on; 1 m reads eq (8) literally in the paper's 1-m depth
    /// (docs/choices.md). Absent from scenes and states when unset.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscous_length: Option<f64>,
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
            viscous_length: None,
        }
    }
}

impl SheetSection {
    /// The prescribed motion of the driven block.
    pub(crate) fn drive(&self) -> Drive {
        Drive {
            u: Some(self.speed),
            v: self.clamp_driven_end.then_some(0.0),
            omega: self.clamp_driven_end.then_some(0.0),
        }
    }

    /// Bevel leg under the sheet tip (m).
    pub(crate) fn tip_bevel(&self) -> f64 {
        self.tip_bevel_fraction * self.thickness
    }

    /// Skeletal layer (m): `skeletal_fraction·h`, at most `skeletal_max`.
    pub(crate) fn skeletal(&self) -> f64 {
        (self.skeletal_fraction * self.thickness).min(self.skeletal_max)
    }
}

/// The thick floe the sheet is pushed against (Table 1; Figure 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FloeSection {
    /// Thickness (m). Default 2.0 (Table 1).
    pub thickness: f64,
    /// Length (m). Default 40 m. The paper gives none: its floe is "a thick, multiyear floe",
    /// far longer than the ridge, and Figure 5's frames are 20 m wide. On a 20-m floe the
    /// intact sheet slid off the far end in about half the runs at μ = 0.4; on 40 m none did,
    /// and 80 m gives the same ensemble shifts (docs/choices.md, "floe length").
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
            length: 40.0,
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
    /// Incubation time τ of crack initiation (s), or none. Default none: the paper's test,
    /// a crack starts the first step the elastic surface stress exceeds the strength. With
    /// τ the stress compared is the elastic stress filtered by dσ_f/dt = (σ − σ_f)/τ, so a
    /// stress must last about τ to break ice: the dynamic-fracture "incubation time" idea,
    /// here to keep fracture from reading the leapfrog's high-frequency error
    /// (docs/speed-vs-error.md, "Fracture and the time step"). Experimental.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub incubation_time: Option<f64>,
}

impl Default for JointSection {
    fn default() -> Self {
        Self {
            damping_fraction: 0.1,
            crack_speed: 50.0,
            incubation_time: None,
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
    /// use pressridge::scene::Scene;
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
    /// # Ok::<(), pressridge::scene::SceneError>(())
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
    /// use pressridge::scene::Scene;
    /// use std::path::Path;
    ///
    /// // As `pressridge simulate --scene ridge.toml --set duration=20 --set contact.mu=0.4`.
    /// let scene = Scene::load(Some(Path::new("ridge.toml")), &["duration=20", "contact.mu=0.4"])?;
    /// // The built-in default, the paper's Figure 5 experiment, run for 20 s.
    /// let figure5 = Scene::load(None, &["duration=20"])?;
    /// # Ok::<(), pressridge::scene::SceneLoadError>(())
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
    pub(crate) fn value_at(&self, key: &str) -> Option<String> {
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
    pub(crate) fn toml_without(&self, keys: &[String]) -> String {
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
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dotted_keys_are_read_and_left_out() {
        let s = Scene::default()
            .with_overrides(&["contact.mu=0.4", "floe.thickness=3.5"])
            .unwrap();
        assert_eq!(s.value_at("contact.mu").as_deref(), Some("0.4"));
        assert_eq!(s.value_at("floe.thickness").as_deref(), Some("3.5"));
        assert_eq!(s.value_at("floe.nosuch"), None);
        assert_eq!(s.value_at("nosuch.key"), None);
        // Two scenes that differ only in the keys left out give the same text.
        let t = s.with_overrides(&["floe.thickness=7.0"]).unwrap();
        let keys = ["floe.thickness".to_string(), "absent.key".to_string()];
        assert_eq!(s.toml_without(&keys), t.toml_without(&keys));
        assert_ne!(s.toml_without(&keys[1..]), t.toml_without(&keys[1..]));
    }

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
        let e = Scene::default()
            .with_overrides(&["joint.incubation_time=0"])
            .unwrap_err()
            .to_string();
        assert!(e.contains("joint.incubation_time"), "{e}");
    }

    /// The incubation time is absent unless set, and then absent from the scene's TOML too,
    /// so that the scenes (and campaign digests) of earlier runs are unchanged.
    #[test]
    fn incubation_time_is_optional_and_not_written_when_absent() {
        let s = Scene::default();
        assert_eq!(s.joint.incubation_time, None);
        assert!(!s.to_toml().contains("incubation_time"));
        let s = s.with_overrides(&["joint.incubation_time=0.002"]).unwrap();
        assert_eq!(s.joint.incubation_time, Some(0.002));
        assert_eq!(s.world_params().incubation_time, Some(0.002));
        assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
    }

    /// An experimental scene option: absent from the default scene's TOML (`key` not in it);
    /// `key=value` set gives a scene that round-trips through TOML (returned), and each of
    /// `bad` values is refused, at parsing or at building, with a message naming `key`.
    fn option_absent_unless_set(key: &str, value: &str, bad: &[&str]) -> Scene {
        let name = key.rsplit('.').next().unwrap();
        assert!(!Scene::default().to_toml().contains(name));
        let s = Scene::default()
            .with_overrides(&[format!("{key}={value}")])
            .unwrap();
        assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
        for b in bad {
            let e = Scene::default()
                .with_overrides(&[format!("{key}={b}")])
                .and_then(|s| s.build().map(|_| ()))
                .unwrap_err()
                .to_string();
            assert!(e.contains(name), "{key}={b}: {e}");
        }
        s
    }

    /// The joint dashpot is explicit unless set and then absent from the scene's TOML;
    /// "implicit" reaches the world; a misspelt value is refused naming the key.
    #[test]
    fn joint_dashpot_is_explicit_unless_set_and_not_written_then() {
        assert_eq!(Scene::default().numerics.joint_dashpot, Dashpot::Explicit);
        let s = option_absent_unless_set("numerics.joint_dashpot", "implicit", &["centered"]);
        assert_eq!(s.world_params().joint_dashpot, Dashpot::Implicit);
    }

    /// The contact onset is eq (3)'s own unless set, and then absent from the scene's TOML;
    /// "velocity" reaches the world.
    #[test]
    fn contact_onset_is_the_area_rate_unless_set_and_not_written_then() {
        assert_eq!(Scene::default().numerics.contact_onset, ContactOnset::Area);
        let s = option_absent_unless_set("numerics.contact_onset", "velocity", &["speed"]);
        assert_eq!(s.world_params().contact_onset, ContactOnset::Velocity);
    }

    /// Eq (8)'s length is the sheet thickness unless set, and then absent from the scene's
    /// TOML; a set length reaches the sheet's k′, and a non-positive one is refused by name.
    #[test]
    fn eq8_length_is_the_thickness_unless_set() {
        let s = option_absent_unless_set("sheet.viscous_length", "1.0", &["0", "-1", "nan"]);
        assert_eq!(s.sheet.as_ref().unwrap().viscous_length, Some(1.0));
    }

    /// Eq (4)'s k_te has one reading, per contact (0.6·k_ne·L): the key that chose the
    /// withdrawn reading (k_ne·h) is refused by name, in a scene and in `--set`.
    #[test]
    fn the_withdrawn_tangential_reference_is_refused_by_name() {
        let e = Scene::default()
            .with_overrides(&["contact.tangential_reference=thickness".to_string()])
            .unwrap_err()
            .to_string();
        assert!(e.contains("tangential_reference"), "{e}");
        let e = Scene::from_toml("[contact]\ntangential_reference = \"chord\"\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("tangential_reference"), "{e}");
    }

    /// The contact dashpot's sweeps are 0 (each contact alone) unless set, and then absent
    /// from the scene's TOML; a count reaches the world, and too many are refused by name.
    #[test]
    fn contact_dashpot_sweeps_are_off_unless_set() {
        assert_eq!(Scene::default().numerics.contact_dashpot_sweeps, 0);
        let s = option_absent_unless_set("numerics.contact_dashpot_sweeps", "4", &["51", "-1"]);
        assert_eq!(s.world_params().contact_dashpot_sweeps, 4);
    }
}
