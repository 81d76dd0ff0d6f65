//! NetCDF reading and writing of gridded thickness distributions.
//!
//! Input: `aicen` and `vicen` with one category dimension, found **by name**
//! ([`CATEGORY_DIM_NAMES`]: CICE history `nc`, CICE restart and pressridge `ncat`, SIS2
//! diagnostics `ct`; or the name given in [`ReadOptions::category_dim`]), anywhere among
//! their dimensions. Every other dimension (`time`, `nj`, `ni`, an ensemble member...) is a
//! column dimension and is kept, in file order, in the outputs. A variable with none of the
//! names, or with more than one, is refused with a message listing its dimensions.
//! Optional: `aice0` (the column dimensions; else 1 − Σ aicen), the category bounds (m) from
//! `hin_max` (length ncat + 1) or CICE history's `NCAT` (on the category dimension: the upper
//! bound of each category, the lowest bound being 0 m), both checked against each other when
//! both are present; `divu` and `shear` (column dimensions) for the ridging step. A spatial
//! variable may lack a leading `time` dimension of length 1 that `aicen` has, or the reverse.
//! Any numeric type is read as `f64`.
//!
//! Land: a column is missing (written as the fill value, never computed) where `aicen`,
//! `vicen` or `aice0` holds its `_FillValue`/`missing_value`, or where CICE's ocean mask
//! `tmask` (1 ocean, 0 land) is 0 or fill. `tmask` may lack column dimensions (CICE writes
//! it without `time`); it then applies at every value of those.
//!
//! Coordinates: the coordinate variables of the column dimensions (e.g. `time` with its
//! `units` and `calendar`) and the auxiliary coordinates named in the `coordinates` attribute
//! of `aicen` (e.g. CICE's `TLON TLAT`) are copied to the outputs with their type and
//! attributes (an `int ni` stays `int`), and
//! the output fields name the auxiliary ones in their own `coordinates` attribute.
//!
//! Units of `divu` and `shear`, from their `units` attribute, which must be present: `s-1`
//! (also `1/s`, `s^-1`): `divu` is the divergence and `shear` the ridging shear term
//! ½(Δ − |div u|), both 1/s. `%/day` (CICE history files): `divu` and `shear` are CICE's divergence and shear
//! strain rate, converted to 1/s, and the shear term is formed as Icepack's ridging needs it
//! (`crate::itd::details::deformation_terms`, which needs `divu`). Any other unit, or none, is refused
//! with a message naming the variable, so that %/day is never taken for 1/s.
//!
//! Output: CF-1.8 attributes (`units`, `long_name`, `standard_name` where CF has one), the
//! options used and the package version as global attributes, and the input's `history`
//! with the command line appended ([`history_line`]).
//!
//! Files: this one holds the category dimension and the errors; `vars.rs` the reading of
//! single variables, `grid.rs` the grid type, `read.rs` the distribution's reader,
//! `forcing.rs` the per-cell forcing, `tracers.rs` snow and tracers, `output.rs` the
//! writer, `complete_step.rs` the complete ridging step from file to file, `cf_table.rs` the
//! C_f tables.

use std::path::{Path, PathBuf};

use crate::itd::ItdError;

mod cf_table;
mod complete_step;
mod forcing;
mod grid;
mod output;
mod read;
mod tracers;
mod vars;

pub use cf_table::{
    read_cf_table, read_cf_table_at_friction, read_mu_rdg_table_at_friction, write_cf_table,
};
pub use complete_step::{CompleteStep, FileClosing, FreezingTemperature, StepInput, step_complete};
pub use forcing::{CellField, CellUnits, read_cell_field};
pub use grid::{CoordValues, CoordVar, ItdGrid};
pub use output::{
    DimField, FieldMeta, NC_FILL_DOUBLE, Output, STRENGTH_META, history_line, write_output,
};
pub use read::{read_itd, read_itd_with};
pub use tracers::{PackedTracers, SnowTracers, read_packed_tracers, read_snow_tracers};
use vars::fmt_dims;
pub use vars::{has_variable, read_field, read_fill};

/// Dimensions of a variable: (name, length) in file order.
pub type Dims = Vec<(String, usize)>;

/// Names of the thickness-category dimension looked for when none is given, in this order:
/// CICE history files (`nc`), CICE restart files and pressridge's own files (`ncat`), SIS2
/// diagnostics (`ct`). Exactly one of a variable's dimensions may carry one of these names.
/// (SIS2 and MOM6 restart files use generic FMS axis names such as `zaxis_1`: name the
/// dimension with `--category-dim`.) Python's `pressridge.xr.CATEGORY_DIMS` is this list.
pub const CATEGORY_DIM_NAMES: &[&str] = &["nc", "ncat", "ct"];

/// How [`read_itd_with`] reads a file.
#[derive(Debug, Clone, Default)]
pub struct ReadOptions {
    /// Name of the category dimension; `None`: the one dimension of `aicen` named as in
    /// [`CATEGORY_DIM_NAMES`].
    pub category_dim: Option<String>,
    /// Leave `divu` and `shear` unread ([`ItdGrid::divu`] and `shear` stay `None`), their
    /// units unchecked: for the strength, which does not use them.
    pub without_deformation: bool,
}

/// The position of the category dimension among `dims` (the dimensions of `var`): the
/// dimension called `chosen` if given, else the one dimension named as in
/// [`CATEGORY_DIM_NAMES`]. Errors list the dimensions seen.
pub fn category_axis(
    path: &Path,
    var: &str,
    dims: &[(String, usize)],
    chosen: Option<&str>,
) -> Result<usize, NetcdfError> {
    let err = |why: String| NetcdfError::CategoryDim {
        path: path.to_path_buf(),
        var: var.into(),
        dims: fmt_dims(dims),
        why,
    };
    if let Some(name) = chosen {
        let at: Vec<usize> = (0..dims.len()).filter(|&i| dims[i].0 == name).collect();
        return match at.as_slice() {
            [i] => Ok(*i),
            [] => Err(err(format!(
                "the category dimension `{name}` given is not among them"
            ))),
            _ => Err(err(format!("`{name}` occurs more than once"))),
        };
    }
    let at: Vec<usize> = (0..dims.len())
        .filter(|&i| CATEGORY_DIM_NAMES.contains(&dims[i].0.as_str()))
        .collect();
    match at.as_slice() {
        [i] => Ok(*i),
        [] => Err(err(format!(
            "none is named {}; name it with --category-dim",
            CATEGORY_DIM_NAMES.join(", ")
        ))),
        _ => Err(err(format!(
            "more than one is named as a category dimension ({}); name the right one with \
             --category-dim",
            CATEGORY_DIM_NAMES.join(", ")
        ))),
    }
}

/// Errors of NetCDF input and output.
#[derive(Debug, thiserror::Error)]
pub enum NetcdfError {
    /// The NetCDF library reported an error.
    #[error("{path}: {source}")]
    Netcdf {
        /// File concerned.
        path: PathBuf,
        /// Library error.
        source: netcdf::Error,
    },
    /// A required variable is missing.
    #[error("{path}: missing variable `{var}`")]
    MissingVariable {
        /// File concerned.
        path: PathBuf,
        /// Variable name.
        var: String,
    },
    /// A variable's dimensions do not match what is required.
    #[error("{path}: variable `{var}` has dimensions {found}, expected {expected}")]
    Shape {
        /// File concerned.
        path: PathBuf,
        /// Variable name.
        var: String,
        /// What was expected.
        expected: String,
        /// What was found.
        found: String,
    },
    /// A rate has units that are not understood.
    #[error(
        "{path}: variable `{var}` has units \"{units}\"; expected \"%/day\" (CICE history) \
         or \"s-1\"{extra}"
    )]
    Units {
        /// File concerned.
        path: PathBuf,
        /// Variable name.
        var: String,
        /// The units found.
        units: String,
        /// More explanation.
        extra: String,
    },
    /// Bad values in one grid column, located by flat and spatial index.
    #[error("{path}: column {column} at ({spatial}): {source}")]
    Column {
        /// File concerned.
        path: PathBuf,
        /// Flat column index (C order over the spatial dimensions).
        column: usize,
        /// Spatial index, e.g. `nj=3, ni=17`.
        spatial: String,
        /// What is wrong.
        source: crate::itd::ColumnError,
    },
    /// A variable has a value the format does not allow (e.g. a non-finite `hin_max`) or a
    /// type that is not numeric.
    #[error("{path}: variable `{var}`: {msg}")]
    Value {
        /// File concerned.
        path: PathBuf,
        /// Variable name.
        var: String,
        /// What is wrong.
        msg: String,
    },
    /// The category dimension cannot be told (none or several of the known names, or the
    /// name given is absent).
    #[error("{path}: variable `{var}` has dimensions {dims}: {why}")]
    CategoryDim {
        /// File concerned.
        path: PathBuf,
        /// Variable name.
        var: String,
        /// The dimensions seen.
        dims: String,
        /// What is wrong.
        why: String,
    },
    /// Writing the file failed (the path could not be created, synced or renamed).
    #[error(transparent)]
    Io(#[from] crate::io::IoError),
    /// Any other physics error (bounds, shapes, parameters, C_f table).
    #[error("{path}: {source}")]
    Itd {
        /// File concerned.
        path: PathBuf,
        /// The error.
        source: ItdError,
    },
}
