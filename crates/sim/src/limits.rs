//! The valid ranges of the parameters the library accepts from users, each a named constant
//! with its reason: physical where a physical bound exists (ice floats, sea ice has a known
//! range of thickness, stiffness and strength, drifts at most a few m/s), otherwise chosen so
//! that a run's memory and time stay finite. One place: the scene validation
//! ([`crate::scene::Scene::validate`]) and the campaign spec check against these, and their
//! messages quote them. The time step itself is bounded by the simulator's stability limit
//! ([`crate::dem`]), not here. The column physics' ranges (C_f, a category's thickness,
//! μ_rdg) and the [`Range`] type are [`pressridge_column::limits`].

use pressridge_column::limits::Range;

/// Ice density ρ_i: sea ice is 720–940 kg/m³ (brine pockets and air make it lighter than
/// pure ice, 917 kg/m³). It must also be below the water's density, or the ice sinks
/// ([`crate::scene::Scene::validate`] checks that too).
pub const ICE_DENSITY: Range = Range {
    min: 700.0,
    min_inclusive: true,
    max: 1000.0,
    unit: "kg/m³",
    why: "sea ice is 720–940 kg/m³, pure ice 917",
};
/// Water density ρ_w: fresh water (1000 kg/m³ at 0–4 °C, down to 990 when warm) to dense
/// brine.
pub const WATER_DENSITY: Range = Range {
    min: 990.0,
    min_inclusive: true,
    max: 1100.0,
    unit: "kg/m³",
    why: "fresh water to dense brine; sea water is 1020–1030",
};
/// Thickness of sheets, floes and pile blocks: from 1 cm (nilas) to 20 m (the thickest
/// deformed multi-year floes); room for lead ice of several metres with scaled
/// parameters. Below 1 cm a block's stiffness-to-mass ratio drives the stable time step
/// towards zero.
pub const THICKNESS: Range = Range {
    min: 0.01,
    min_inclusive: true,
    max: 20.0,
    unit: "m",
    why: "from 1 cm nilas to 20 m of deformed multi-year ice",
};
/// Width of a component block: as thin as the thinnest ice, at most 100 m.
pub const BLOCK_WIDTH: Range = Range {
    min: 0.01,
    min_inclusive: true,
    max: 100.0,
    unit: "m",
    why: "blocks from 1 cm to 100 m",
};
/// Length of a sheet or floe: at most 1 km (the default sheet is 25 m). Together with
/// [`MAX_BLOCKS`] this keeps the number of bodies, hence memory, finite.
pub const LENGTH: Range = Range {
    min: 0.0,
    min_inclusive: false,
    max: 1000.0,
    unit: "m",
    why: "at most 1 km, which keeps the number of blocks bounded",
};
/// Pushing speed U: sea ice drifts at up to about 1 m/s; 5 m/s leaves room for
/// accelerated experiments while keeping the sheet's displacement per step small.
pub const SPEED: Range = Range {
    min: 0.0,
    min_inclusive: false,
    max: 5.0,
    unit: "m/s",
    why: "sea ice drifts at up to about 1 m/s",
};
/// Young's modulus: effective moduli of sea ice are 0.1–10 GPa (Hopkins uses 0.067–1
/// GPa); pure ice is 9–10 GPa. The stable time step shrinks as 1/√E, so a modulus far
/// above ice's would make a run take for ever.
pub const YOUNGS_MODULUS: Range = Range {
    min: 1.0e6,
    min_inclusive: true,
    max: 2.0e10,
    unit: "Pa",
    why: "sea ice is 0.1–10 GPa, pure ice 9–10 GPa",
};
/// Tensile (flexural) strength: sea ice is 0.1–1 MPa, pure ice at most about 2 MPa; down
/// to 1 kPa for scenes that break on purpose.
pub const TENSILE_STRENGTH: Range = Range {
    min: 1.0e3,
    min_inclusive: true,
    max: 1.0e7,
    unit: "Pa",
    why: "sea ice is 0.1–1 MPa; 1 kPa allows scenes that break on purpose",
};
/// Simulated duration: positive (a run of no time takes no step), at most a day, which
/// at the default Δt is already some 10⁸ steps.
pub const DURATION: Range = Range {
    min: 0.0,
    min_inclusive: false,
    max: 86_400.0,
    unit: "s",
    why: "a run must take at least one step; a day is already ~1e8 steps",
};
/// Slope of a bevel, tan of its angle from the horizontal (dimensionless): about 6° to 84°.
/// Flatter, a ramp of any drop runs over several blocks; steeper, it is a vertical face.
pub const BEVEL_SLOPE: Range = Range {
    min: 0.1,
    min_inclusive: true,
    max: 10.0,
    unit: "",
    why: "tan of the bevel's angle from the horizontal, about 6° to 84°",
};
/// Smallest non-zero bevel leg (m): a shorter one makes a degenerate corner edge that the
/// polygon geometry cannot represent. A bevel is 0 (none) or at least this.
pub const MIN_BEVEL: f64 = 1.0e-3;
/// Most blocks a scene may start with (sheet, floe and pile together): memory and
/// contact search grow with it; the paper's runs have a few hundred.
pub const MAX_BLOCKS: usize = 100_000;
/// Most seeds per grid point of a campaign: the paper uses 7; every seed is a full run.
pub const MAX_SEEDS: u32 = 1000;
/// Most runs in a campaign (grid points × seeds): its plan and records are held in
/// memory, and each run takes minutes.
pub const MAX_RUNS: usize = 100_000;
