//! The sections of a scene file (`[ice]`, `[water]`, `[numerics]`, `[sheet]`, `[floe]`,
//! `[wall]`, `[pile]`, `[joint]`, `[output]`): every key with its unit,
//! default and reason.
//! Re-exported by `scene`, their one public path.

use crate::dem::{ContactOnset, ContactParams, Dashpot, DragBodies, Drive, WaterParams};
use serde::{Deserialize, Serialize};

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
    /// Which bodies feel drag: `"rubble"` (free blocks and rubble; the default) or `"all"`
    /// (the sheet's and the floe's blocks too); see [`DragBodies`]. Left out of a written
    /// scene at its default, so that the records made before it keep their digests.
    #[serde(default, skip_serializing_if = "DragBodies::is_rubble")]
    pub drag_bodies: DragBodies,
    /// Shielding of packed rubble (count of submerged contacts, 0 for none, the default): a
    /// body with at least this many contacts below the water line feels no form drag; see
    /// [`WaterParams::shielding_contacts`]. Absent from a written scene at its default. Off:
    /// the paper gives drag no law and no shielding; at 2, on twelve seeds, the other sinks
    /// at the Figure 5 point move by −0.8 points of W [−3.6, +2.0] (docs/choices.md).
    #[serde(default, skip_serializing_if = "is_zero_u32")]
    pub shielding_contacts: u32,
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
            drag_bodies: w.drag_bodies,
            shielding_contacts: w.shielding_contacts,
        }
    }
}

/// Numerical choices.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NumericsSection {
    /// Safety factor on the stable time step (dimensionless, in (0, 1]). Default
    /// [`crate::dem::DEFAULT_TIME_STEP_SAFETY`], the full limit, refined around fracture and
    /// impacts by the `refine_*` options; see docs/speed-vs-error.md.
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
    /// Time discretisation of the joints' viscous stress of eq (1): "explicit" (default,
    /// the paper's form, at the half-step velocities) or "implicit" (centred in time per
    /// joint; raises the joints' stable limit 1.18× for 27 % more instructions per step and
    /// breaks as many joints: docs/model.md, "Joint dashpot in time"). Written only when
    /// set. See [`crate::dem::WorldParams::joint_dashpot`].
    #[serde(skip_serializing_if = "Dashpot::is_explicit")]
    pub joint_dashpot: Dashpot,
    /// How a new contact reads its first overlap rate in eq (3): "area" (default, the
    /// paper's Aⁿ/Δt) or "velocity" (the chord times the approach speed; restitution of a
    /// collision 0.8 % against 6.0 % too high at the default step, every trajectory changed:
    /// docs/model.md, "A new contact's first rate"). Written only when set. See
    /// [`crate::dem::ContactOnset`].
    #[serde(skip_serializing_if = "ContactOnset::is_area")]
    pub contact_onset: ContactOnset,
    /// Gauss–Seidel sweeps of the centred contact dashpot over the contacts (count, 0–50):
    /// 0 (default) solves each contact alone, n couples a block's contacts (a pressed block's
    /// viscous force to 2.5e-3 of the coupled solution after 3 sweeps; docs/model.md,
    /// "Several contacts on one block"). Written only when set. See
    /// [`crate::dem::WorldParams::contact_dashpot_sweeps`].
    #[serde(skip_serializing_if = "crate::dem::is_zero")]
    pub contact_dashpot_sweeps: u32,
    /// Test crack initiation on the mean elastic surface stress of the last two poses,
    /// (σⁿ⁻¹ + σⁿ)/2, instead of σⁿ (dimensionless switch). Default false: the stress of the
    /// pose, the paper's test. The leapfrog scheme makes a suddenly loaded mode of phase θ
    /// per step swing 1/cos(θ/2) times too far; the two-pose mean swings as far as the exact
    /// motion of the same energy. On the ensembles it does not take away the step's shift of
    /// fracture (docs/speed-vs-error.md). Not with `joint.incubation_time`. Written only
    /// when set.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub fracture_step_mean: bool,
    /// A step refined around fracture (s), or "off" (one step throughout). Default
    /// [`crate::dem::DEFAULT_REFINE_WINDOW`], 0.05 s. While a joint is cracking, and for this
    /// long after a joint severs (or an impact, `refine_impact`), the world steps by
    /// `refine_fraction` of its step, the leapfrog's kick the mean of the two steps where
    /// the step changes (docs/model.md, "A step refined around fracture"). A saved state
    /// carries the window's clock, so a run restarted inside a window repeats the bits of
    /// an unbroken run.
    #[serde(with = "crate::dem::numerics::off_or_number")]
    pub refine_window: Option<f64>,
    /// A step refined ahead of fracture (dimensionless, in (0, 1]), or "off". Default
    /// [`crate::dem::DEFAULT_REFINE_LOAD`], 0.9: while some intact joint's tested stress
    /// exceeds this fraction of its strength, the world steps by `refine_fraction` of its
    /// step (at the full limit 0.9 adds 2.7 % of the steps, 0.8 adds 17 %). With
    /// `refine_window` it refines the loading that leads to a crack as well as the cascade
    /// after it.
    #[serde(with = "crate::dem::numerics::off_or_number")]
    pub refine_load: Option<f64>,
    /// A step refined after impacts (m/s), or "off". Default
    /// [`crate::dem::DEFAULT_REFINE_IMPACT`], 0.6 m/s: with `refine_window`, a contact born
    /// approaching faster than this refines the step for that window, as a severed joint
    /// does, so that a block striking a rubble piece loads its joints in refined steps
    /// (without it the 0.45-m sheet's rubble breaks into more single blocks at the full
    /// limit; docs/speed-vs-error.md).
    #[serde(with = "crate::dem::numerics::off_or_number")]
    pub refine_impact: Option<f64>,
    /// The refined step as a fraction of the step (dimensionless, in (0, 1]), with
    /// `refine_window` or `refine_load`; none: a quarter. Written only when set.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refine_fraction: Option<f64>,
}

impl Default for NumericsSection {
    /// The world's defaults ([`crate::dem::WorldParams`]) where the world holds the choice.
    fn default() -> Self {
        let w = crate::dem::WorldParams::default();
        Self {
            time_step_safety: crate::dem::DEFAULT_TIME_STEP_SAFETY,
            time_step: 0.0,
            contact_dashpot: Dashpot::default(),
            sample_interval: 0.2,
            joint_dashpot: w.joint_dashpot,
            contact_onset: w.contact_onset,
            contact_dashpot_sweeps: w.contact_dashpot_sweeps,
            fracture_step_mean: w.fracture_step_mean,
            refine_window: w.refine_window,
            refine_load: w.refine_load,
            refine_impact: w.refine_impact,
            refine_fraction: w.refine_fraction,
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
    /// Eq (8)'s damping at the driven end as a fraction of the critical 2·sqrt(k_ne·h·ρ_i)
    /// (dimensionless): k′ = f·2·sqrt(k_ne·h·ρ_i)·L_v·e^(−4(x_i − x_1)/(x_n − x_1)). Default
    /// 0.5, the fraction the paper gives eq (3)'s k_nv, which eq (8) names; a key of its own
    /// so that the contacts' damping and the sheet's move apart. Absent from a written
    /// scene at its default.
    #[serde(default = "half", skip_serializing_if = "is_half")]
    pub boundary_damping_fraction: f64,
    /// Slope of the bevel under the sheet tip, tan of its angle from the horizontal
    /// (dimensionless): the bevel drops `tip_bevel_fraction`·h over a run of that divided by
    /// the slope. Default 1 (45°); absent from a written scene at its default.
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub tip_bevel_slope: f64,
}

fn half() -> f64 {
    0.5
}
fn is_half(x: &f64) -> bool {
    *x == 0.5
}
fn one() -> f64 {
    1.0
}
fn is_one(x: &f64) -> bool {
    *x == 1.0
}
fn is_zero_u32(x: &u32) -> bool {
    *x == 0
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
            boundary_damping_fraction: 0.5,
            tip_bevel_slope: 1.0,
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

    /// Bevel leg under the sheet tip (m): its drop up the tip's face.
    pub(crate) fn tip_bevel(&self) -> f64 {
        self.tip_bevel_fraction * self.thickness
    }

    /// The tip bevel's run along the sheet's bottom (m), or `None` at 45° (run = drop).
    pub(crate) fn tip_bevel_run(&self) -> Option<f64> {
        (self.tip_bevel_slope != 1.0).then(|| self.tip_bevel() / self.tip_bevel_slope)
    }

    /// Skeletal layer (m): `skeletal_fraction·h`, at most `skeletal_max`.
    pub(crate) fn skeletal(&self) -> f64 {
        (self.skeletal_fraction * self.thickness).min(self.skeletal_max)
    }

    /// k′ of eqs (7)–(8) at the driven end (kg/(m·s)): `boundary_damping_fraction` of the
    /// critical 2·sqrt(k_ne·h·ρ_i) for this sheet's thickness, the contacts' k_ne and ice
    /// density `rho_i` (kg/m³), times eq (8)'s length (`viscous_length`, default h;
    /// docs/choices.md).
    pub fn boundary_viscosity(&self, contact: &ContactParams, rho_i: f64) -> f64 {
        self.boundary_damping_fraction
            * 2.0
            * (contact.normal_stiffness * self.thickness * rho_i).sqrt()
            * self.viscous_length.unwrap_or(self.thickness)
    }
}

/// The floe nose ramp's slope of the built-in scene, tan 20° (dimensionless; the choice and
/// its measured effect: [`FloeSection::nose_slope`], docs/choices.md).
pub const NOSE_SLOPE: f64 = 0.36397;

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
    /// Bevel leg of the floe nose, its top corner facing the sheet (m): the ramp's drop from
    /// the floe top. Default 0.5: a ramp from the floe top (0.18 m above water) to 0.32 m
    /// below, spanning the waterline where the sheet arrives.
    pub nose_bevel: f64,
    /// Slope of the nose ramp, tan of its angle from the horizontal (dimensionless): the
    /// ramp drops `nose_bevel` over a run of `nose_bevel / nose_slope`. Default
    /// [`NOSE_SLOPE`] = 0.36397 (tan 20°, a run of 1.37 m). The paper gives no angle; it
    /// bevels the nose "to enable ride up". A block pushed horizontally up a ramp with
    /// friction μ locks once μ·tan α ≥ 1, so a 45° ramp (slope 1, the default of model
    /// revisions 1–2) lets nothing ride up it at the Figure 5 friction μ = 1; at 20° the lock
    /// is at μ = 2.75, above every friction of the paper. Measured on 12 seeds against 45°
    /// (docs/choices.md): runs that rafted 12/12 → 3/12 at μ = 0.4 and 6/12 → 2/12 at
    /// μ = 1.0, ΔPE +13 kJ/m and W/ΔPE −2.9 at μ = 1.0; 30° moved nothing. Where the run
    /// does not fit the first floe block, that block is made as many block widths wide as
    /// it needs (two at 20°). A scene file's `[floe]` table that omits the key gets 1 (45°):
    /// a file keeps the meaning it was written with; scenes with a 45° ramp omit it.
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub nose_slope: f64,
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
            nose_slope: NOSE_SLOPE,
            corner_bevel: 0.02,
            pin: true,
        }
    }
}

impl FloeSection {
    /// The floe's length in block widths, at least one (count): how many blocks of
    /// `block_width` it would be cut into were its nose block one width wide.
    pub(crate) fn block_count(&self) -> usize {
        (self.length / self.block_width).round().max(1.0) as usize
    }

    /// The nose ramp's run along the floe top (m): `nose_bevel / nose_slope`, exactly
    /// `nose_bevel` at 45°.
    pub fn nose_run(&self) -> f64 {
        if self.nose_slope == 1.0 {
            self.nose_bevel
        } else {
            self.nose_bevel / self.nose_slope
        }
    }

    /// How many block widths the nose block spans: the fewest that hold the ramp's run
    /// and a corner bevel at each end of its top (1 at the defaults).
    pub(crate) fn nose_block_widths(&self) -> usize {
        let need = self.nose_run() + 2.0 * self.corner_bevel;
        // Saturating: a nonsense bevel or width (refused by validation) must not overflow.
        ((need / self.block_width).floor() as usize).saturating_add(1)
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
    /// stress must last about τ to break ice: the dynamic-fracture "incubation time" idea.
    /// At 2 ms it took away the step dependence of fracture on the former model but moved
    /// the finest step's count of broken joints by +38 % (docs/model.md, "Incubation
    /// time"). Not with
    /// `numerics.fracture_step_mean`. Written only when set.
    #[serde(skip_serializing_if = "Option::is_none")]
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
