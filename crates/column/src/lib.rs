//! Ice thickness distribution (ITD) physics: category bounds, ridging participation,
//! redistribution of ridged ice, ice strength and the ridging step.
//!
//! This is the Thorndike et al. (1975) / Rothrock (1975) machinery of CICE/Icepack
//! (`icepack_mechred.F90`, `icepack_itd.F90`), rewritten in Rust so that the same options give
//! the same numbers to round-off, and extended where CICE leaves results undefined
//! (see `docs/strength.md`).
//!
//! Design: the core is a per-column function on plain slices (`aicen`, `vicen` of length
//! `ncat`, scalar `aice0`) that uses a reusable [`Workspace`] and never allocates; batched
//! drivers ([`strength_batch`], [`ridge_batch`]) loop over `ncol` columns
//! given as 2-D `ndarray` views of shape `(ncat, ncol)` with any strides (so Fortran
//! column-major `aicen(ncat, ncol)` and NetCDF `(ncat, y, x)` both pass without copies).
//! No module here knows about NetCDF, plotting or the command line: the crate depends on
//! `ndarray` and `thiserror` only, so a host model that wants the strength or the ridging step
//! links nothing else. The ridge simulator, its tables and NetCDF I/O are the `pressridge`
//! crate, which re-exports this one as `pressridge::itd`.
//!
//! ## Where to start
//!
//! - Ice strength P (N/m) of a column: [`strength_column`] (CICE's `icepack_ice_strength`);
//!   of many: [`strength_batch`].
//! - The ridging of areas and volumes: [`ridge_column`] / [`ridge_batch`]; the complete step
//!   with snow, tracers and ocean fluxes (Icepack's `icepack_step_ridge`):
//!   [`ridge_step_column`] / [`ridge_step_batch()`] / [`ridge_step_cells`].
//! - Category bounds: [`category_bounds`]; options: [`StrengthOptions`], [`RidgeOptions`],
//!   [`RidgeStepOptions`] (their defaults are CICE's).
//! - Everything else a host may need — participation and redistribution on their own, the
//!   complete step's batch and per-cell types, tracer layouts, C_f and μ_rdg tables, the
//!   parameter registry — is one level down, in [`details`].
//!
//! ```
//! use pressridge_column::{
//!     CategoryBounds, RidgeForcing, RidgeOptions, StrengthOptions, Workspace, category_bounds,
//!     ridge_column, strength_column,
//! };
//!
//! // Five categories with CICE's round-number bounds (m) and 90 % ice cover.
//! let hin_max = category_bounds(&CategoryBounds::RoundNumbers, 5)?;
//! let mut aicen = [0.30, 0.25, 0.20, 0.10, 0.05]; // area fractions (1)
//! let mut vicen = [0.15, 0.25, 0.40, 0.30, 0.25]; // volumes per unit area (m)
//! let mut aice0 = 0.10; // open water (1)
//! let mut ws = Workspace::new(5);
//!
//! // Rothrock's strength with CICE's defaults (C_f = 17, mu_rdg = 3 m^0.5).
//! let p = strength_column(&aicen, &vicen, Some(aice0), &StrengthOptions::default(), &mut ws)?;
//! assert!(p.strength > 0.0); // N/m
//!
//! // One hour of convergence: area ridges into thicker categories, volume is kept.
//! let v0: f64 = vicen.iter().sum();
//! let forcing = RidgeForcing { convergence: 1e-6, shear: 0.0, dt: 3600.0 }; // 1/s, 1/s, s
//! let d = ridge_column(
//!     &mut aicen, &mut vicen, &mut aice0, &hin_max, forcing, &RidgeOptions::default(), &mut ws,
//! )?;
//! assert!(d.dardg1dt > 0.0); // area lost by ridging ice (1/s)
//! assert!((vicen.iter().sum::<f64>() - v0).abs() < 1e-12 * v0);
//! assert!((aice0 + aicen.iter().sum::<f64>() - 1.0).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

pub mod interp;
pub mod limits;

mod bounds;
mod cf;
mod lanes;
mod mu_rdg;
mod named_params;
mod nodes;
mod params;
mod participation;
mod redistribution;
mod ridge_step;
mod strength;
mod tracers;
mod vexp;

pub use bounds::{CategoryBounds, category_bounds};
pub use cf::Cf;
pub use params::ItdParams;
pub use ridge_step::area_volume::{
    RidgeDiagnostics, RidgeForcing, RidgeOptions, ridge_batch, ridge_column,
};
pub use ridge_step::batch::ridge_step_batch;
pub use ridge_step::cells::ridge_step_cells;
pub use ridge_step::{
    ColumnMut, RidgeStepOptions, StepDiagnostics, StepForcing, StepWorkspace, ridge_step_column,
};
pub use strength::{ColumnStrength, StrengthOptions, strength_batch, strength_column};

/// The second tier: what a host needs beyond the entry points above — the strength's
/// variants and constants, participation and redistribution on their own, the complete
/// step's batch and per-cell types, its outputs' metadata and thermodynamic constants, the
/// tracer layouts, the C_f and μ_rdg tables, and the parameter registry (one path per name:
/// these are nowhere else).
pub mod details {
    pub use crate::bounds::validate_bounds;
    pub use crate::cf::{CfLookup, CfPreset, CfProvider, CfTable};
    pub use crate::mu_rdg::{MU_RDG_MAX_NODES, MuRdgLookup, MuRdgTable};
    pub use crate::named_params::{NamedParams, ParamError, ParamGroup, ParamMeta};
    pub use crate::params::{Participation, Redistribution, StrengthFormula};
    pub use crate::participation::participation;
    pub use crate::redistribution::{
        RidgeGeometry, category_fractions, category_fractions_all, mean_square_ridge_thickness,
        net_to_gross, ridge_geometry,
    };
    pub use crate::ridge_step::area_volume::{RidgeBatchForcing, RidgeRatesMut};
    pub use crate::ridge_step::batch::{
        BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, OutputMeta, SPECIES_OUTPUTS,
        StepBatchMut, StepBatchOutputs, species_counts,
    };
    pub use crate::ridge_step::cells::{CellForcing, CellOutputs, CellState};
    pub use crate::ridge_step::{
        Closing, OceanFluxes, RidgeStepParams, SECONDS_PER_DAY, SaltFlux, StepParamMeta,
        deformation_terms, percent_per_day_to_per_second,
    };
    pub use crate::strength::{
        BatchSummary, CF_CLAMPED_MATERIAL_SHARE, FAST_MAX_NCAT, StrengthConsts,
        strength_batch_masked, strength_column_constant_cf,
    };
    pub use crate::tracers::{
        BgcKind, BgcTracers, CiceLayoutSpec, CiceTracerFlags, IcedrvBgc, LAYOUT_PRESETS,
        LayoutDetectError, LayoutSpecError, MAX_AERO, MAX_ISO, MAX_NBTRCR, TracerBase, TracerField,
        TracerLayout, TracerRole,
    };
}

/// What is wrong with one column (no column index: see [`ItdError::Column`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ColumnError {
    /// A value is NaN or infinite.
    #[error("{var}{} is not finite ({value})", cat_suffix(*.category))]
    NotFinite {
        /// Variable name (`aicen`, `vicen`, `aice0`, ...).
        var: &'static str,
        /// Category index (0-based) for per-category variables.
        category: Option<usize>,
        /// The offending value.
        value: f64,
    },
    /// A value that must be non-negative is negative.
    #[error("{var}{} is negative ({value})", cat_suffix(*.category))]
    Negative {
        /// Variable name.
        var: &'static str,
        /// Category index (0-based) for per-category variables.
        category: Option<usize>,
        /// The offending value.
        value: f64,
    },
    /// A volume per unit area, or a category's thickness `vicen/aicen`, beyond
    /// [`crate::limits::CATEGORY_THICKNESS`] in a strength input: ice thicker than any, whose
    /// squares overflow or whose ridge thickness range rounds to nothing.
    #[error(
        "{var}{} = {value} m exceeds {max} m: thicker than any sea ice (the deepest ridge keels \
         reach ~50 m)",
        cat_suffix(*.category)
    )]
    TooThick {
        /// Variable name (`vicen`).
        var: &'static str,
        /// Category index (0-based).
        category: Option<usize>,
        /// The offending value (m).
        value: f64,
        /// The largest accepted value (m).
        max: f64,
    },
    /// A custom C_f provider ([`Cf::Custom`]) gave a value outside [`crate::limits::CF`]
    /// (tables are checked when built).
    #[error(
        "the C_f provider gave {value} for ridging ice {thickness} m thick (category {category}): \
         {}",
        crate::limits::CF.describe()
    )]
    CfOutOfRange {
        /// Category index (0-based) of the ridging ice.
        category: usize,
        /// Its thickness (m).
        thickness: f64,
        /// The value the provider gave (dimensionless).
        value: f64,
    },
    /// The total area differs from 1 by more than the tolerance (strength input).
    #[error(
        "total area aice0 + sum(aicen) = {total} differs from 1 by more than {tolerance}; \
         a ridging step always leaves exactly 1"
    )]
    AreaSum {
        /// aice0 + Σ aicen.
        total: f64,
        /// [`ItdParams::area_tolerance`].
        tolerance: f64,
    },
    /// `aice0` was not given and Σ aicen exceeds 1 by more than the tolerance.
    #[error(
        "aice0 not given and sum(aicen) = {total} exceeds 1 (by more than {tolerance}), \
         so 1 - sum(aicen) would be negative"
    )]
    IceAreaAboveOne {
        /// Σ aicen.
        total: f64,
        /// [`ItdParams::area_tolerance`].
        tolerance: f64,
    },
    /// The total area before ridging is larger than any advection step could leave.
    #[error(
        "total area aice0 + sum(aicen) = {total} before ridging exceeds the maximum {max} \
         (ItdParams::max_area_before_ridging)"
    )]
    AreaTooLarge {
        /// aice0 + Σ aicen.
        total: f64,
        /// [`ItdParams::max_area_before_ridging`].
        max: f64,
    },
    /// The ridging iteration did not bring the total area to 1.
    #[error("ridging did not converge after {niter} iterations (total area {total})")]
    NoConvergence {
        /// Iterations done.
        niter: usize,
        /// Total area left.
        total: f64,
    },
    /// A step of the ridging or clean-up found a state Icepack aborts on (named by the
    /// Icepack routine), e.g. more area to move than a category holds.
    #[error("{routine}: {what}{} ({value})", cat_suffix(*.category))]
    StepFailed {
        /// Icepack routine whose check failed (`ridge_shift`, `shift_ice`, ...).
        routine: &'static str,
        /// What failed.
        what: &'static str,
        /// Category index (0-based) where it applies.
        category: Option<usize>,
        /// The offending value.
        value: f64,
    },
    /// The step would leave a negative or non-finite area, volume, snow volume or flux
    /// (where Icepack returns it; pressridge refuses and leaves the column unchanged).
    #[error(
        "ridging would leave {var}{} = {value} (negative or not finite); column unchanged",
        cat_suffix(*.category)
    )]
    Unphysical {
        /// Variable name.
        var: &'static str,
        /// Category index (0-based) for per-category variables.
        category: Option<usize>,
        /// The value the step would have produced.
        value: f64,
    },
    /// A tracer value is NaN or infinite (input, or produced by the step).
    #[error("tracer {tracer} of category {category} is not finite ({value})")]
    TracerNotFinite {
        /// Tracer index (0-based) in the layout.
        tracer: usize,
        /// Category index (0-based).
        category: usize,
        /// The offending value.
        value: f64,
    },
    /// More open water was removed than existed (cannot happen for valid input; CICE aborts).
    #[error("ridging removed more open water than existed (aice0 = {aice0})")]
    OpenWaterExhausted {
        /// aice0 after the shift.
        aice0: f64,
    },
}

fn cat_suffix(category: Option<usize>) -> String {
    match category {
        Some(n) => format!("[category {n}]"),
        None => String::new(),
    }
}

/// Errors of the ITD physics.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ItdError {
    /// Bad values in one column; `column` is the flat column index (0-based).
    #[error("column {column}: {source}")]
    Column {
        /// Flat column index.
        column: usize,
        /// What is wrong.
        source: ColumnError,
    },
    /// Arrays do not have the shapes they must have.
    #[error("shape mismatch: {var} has shape {found:?}, expected {expected:?}")]
    Shape {
        /// Variable name.
        var: &'static str,
        /// Expected shape.
        expected: Vec<usize>,
        /// Actual shape.
        found: Vec<usize>,
    },
    /// Category bounds are unusable.
    #[error("invalid category bounds hin_max: {0}")]
    Bounds(String),
    /// A parameter or option value is unusable.
    #[error("invalid parameter {name} = {value}: {reason}")]
    Parameter {
        /// Parameter name.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Why it is rejected.
        reason: std::borrow::Cow<'static, str>,
    },
    /// A C_f table is unusable.
    #[error("invalid C_f table: {0}")]
    CfTable(String),
    /// A μ_rdg table is unusable.
    #[error("invalid mu_rdg table: {0}")]
    MuRdgTable(String),
    /// A tracer layout (its fields, a host's tracer tables, a refill value) is unusable.
    #[error("invalid tracer layout: {0}")]
    Layout(String),
}

/// Reusable scratch space for the per-column routines, sized once for `ncat` categories.
/// Holding one per thread gives allocation-free, thread-safe column calls.
#[derive(Debug, Clone)]
pub struct Workspace {
    ncat: usize,
    /// Participation a_Pn, n = 0 (open water) ..= ncat.
    pub(crate) apartic: Vec<f64>,
    /// Cumulative area G(n), stored shifted: gsum[k + 1] = G(k), k = −1 ..= ncat.
    pub(crate) gsum: Vec<f64>,
    /// Constants of the exponential participation (1/a*, 1/(1 − e^{−1/a*}), …), computed once.
    pub(crate) exp_cache: participation::ExpCache,
    pub(crate) hi: Vec<f64>,
    pub(crate) hrmin: Vec<f64>,
    pub(crate) hrmax: Vec<f64>,
    pub(crate) hrexp: Vec<f64>,
    pub(crate) krdg: Vec<f64>,
    /// Per category: μ_rdg came from a table queried outside its range (the end value).
    pub(crate) mu_clamped: Vec<bool>,
    pub(crate) aicen_init: Vec<f64>,
    pub(crate) vicen_init: Vec<f64>,
    /// Area ridged out of each category during the last ridging step (dimensionless).
    pub ardg1n: Vec<f64>,
    /// Area of new ridges formed from each category during the last ridging step.
    pub ardg2n: Vec<f64>,
    /// Volume per unit area ridged out of each category during the last ridging step (m).
    pub virdgn: Vec<f64>,
}

impl Workspace {
    /// Allocates scratch space for `ncat` categories (the only allocation).
    pub fn new(ncat: usize) -> Self {
        Self {
            ncat,
            apartic: vec![0.0; ncat + 1],
            gsum: vec![0.0; ncat + 2],
            exp_cache: participation::ExpCache::EMPTY,
            hi: vec![0.0; ncat],
            hrmin: vec![0.0; ncat],
            hrmax: vec![0.0; ncat],
            hrexp: vec![0.0; ncat],
            krdg: vec![1.0; ncat],
            mu_clamped: vec![false; ncat],
            aicen_init: vec![0.0; ncat],
            vicen_init: vec![0.0; ncat],
            ardg1n: vec![0.0; ncat],
            ardg2n: vec![0.0; ncat],
            virdgn: vec![0.0; ncat],
        }
    }

    /// Number of categories this workspace was made for.
    pub fn ncat(&self) -> usize {
        self.ncat
    }

    /// Icepack `ridge_itd` without the rafting mask: the participation a_Pn of every
    /// category and of open water, each category's ridge geometry (h_i, H_min, H_max, λ,
    /// k_n) into this workspace, and the net-to-gross ratio `aksum` = Σ a_Pn·(1 − 1/k_n)
    /// (dimensionless), returned. The one kernel behind the strength, the area-and-volume
    /// step and the complete step.
    pub(crate) fn prepare_ridging(
        &mut self,
        participation: params::Participation,
        redistribution: &params::Redistribution,
        p: &params::ItdParams,
        aice0: f64,
        aicen: &[f64],
        vicen: &[f64],
    ) -> f64 {
        participation::participation_cached(
            participation,
            p,
            aice0,
            aicen,
            &mut self.gsum,
            &mut self.apartic,
            &mut self.exp_cache,
        );
        for n in 0..aicen.len() {
            let g = redistribution::ridge_geometry(redistribution, p, aicen[n], vicen[n]);
            self.hi[n] = g.hi;
            self.hrmin[n] = g.hrmin;
            self.hrmax[n] = g.hrmax;
            self.hrexp[n] = g.hrexp;
            self.krdg[n] = g.krdg;
            self.mu_clamped[n] = g.mu_clamped;
        }
        redistribution::net_to_gross(&self.apartic, &self.krdg)
    }

    /// Participation function a_Pn of the last call (index 0 is open water), dimensionless.
    pub fn apartic(&self) -> &[f64] {
        &self.apartic
    }

    /// Mean ridge thickness over ridging-ice thickness k_n of the last call (dimensionless).
    pub fn krdg(&self) -> &[f64] {
        &self.krdg
    }
}

/// Refuses a volume per unit area or a thickness (m), `var` naming which, beyond
/// [`crate::limits::CATEGORY_THICKNESS`].
#[inline]
pub(crate) fn too_thick(var: &'static str, n: usize, v: f64) -> Result<(), ColumnError> {
    let max = crate::limits::CATEGORY_THICKNESS.max;
    if v > max {
        return Err(ColumnError::TooThick {
            var,
            category: Some(n),
            value: v,
            max,
        });
    }
    Ok(())
}

/// Checks one column's raw values: finite and non-negative `aicen`, `vicen` (and `aice0` when
/// given), and matching lengths. Returns Σ aicen.
pub(crate) fn check_column(
    aicen: &[f64],
    vicen: &[f64],
    aice0: Option<f64>,
) -> Result<f64, ColumnError> {
    let mut sum = 0.0;
    for (n, (&a, &v)) in aicen.iter().zip(vicen).enumerate() {
        if !a.is_finite() {
            return Err(ColumnError::NotFinite {
                var: "aicen",
                category: Some(n),
                value: a,
            });
        }
        if a < 0.0 {
            return Err(ColumnError::Negative {
                var: "aicen",
                category: Some(n),
                value: a,
            });
        }
        if !v.is_finite() {
            return Err(ColumnError::NotFinite {
                var: "vicen",
                category: Some(n),
                value: v,
            });
        }
        if v < 0.0 {
            return Err(ColumnError::Negative {
                var: "vicen",
                category: Some(n),
                value: v,
            });
        }
        sum += a;
    }
    if let Some(a0) = aice0 {
        if !a0.is_finite() {
            return Err(ColumnError::NotFinite {
                var: "aice0",
                category: None,
                value: a0,
            });
        }
        if a0 < 0.0 {
            return Err(ColumnError::Negative {
                var: "aice0",
                category: None,
                value: a0,
            });
        }
    }
    Ok(sum)
}

/// Checks that the 1-D array `var` has length `n` (an [`ItdError::Shape`] naming it if not).
pub(crate) fn check_len(var: &'static str, found: usize, n: usize) -> Result<(), ItdError> {
    check_shape(var, &[found], &[n])
}

/// Checks that the array `var` has the shape `expected` (an [`ItdError::Shape`] naming it and
/// giving both shapes if not).
pub(crate) fn check_shape(
    var: &'static str,
    found: &[usize],
    expected: &[usize],
) -> Result<(), ItdError> {
    if found != expected {
        return Err(ItdError::Shape {
            var,
            expected: expected.to_vec(),
            found: found.to_vec(),
        });
    }
    Ok(())
}
