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
//! of `aicen` (e.g. CICE's `TLON TLAT`) are copied to the outputs with their attributes, and
//! the output fields name the auxiliary ones in their own `coordinates` attribute.
//!
//! Units of `divu` and `shear`, from their `units` attribute: `s-1` (also `1/s`, `s^-1`, or no
//! attribute): `divu` is the divergence and `shear` the ridging shear term ½(Δ − |div u|),
//! both 1/s. `%/day` (CICE history files): `divu` and `shear` are CICE's divergence and shear
//! strain rate, converted to 1/s, and the shear term is formed as Icepack's ridging needs it
//! (`crate::itd::deformation_terms`, which needs `divu`). Any other unit is refused with a
//! message naming it, so that %/day is never taken for 1/s.
//!
//! Output: CF-1.8 attributes (`units`, `long_name`, `standard_name` where CF has one), the
//! options used and the package version as global attributes, and the input's `history`
//! with the command line appended ([`history_line`]).

use std::path::{Path, PathBuf};

use ndarray::{Array1, Array2, Array3};

use crate::itd::{CfTable, CiceTracerFlags, ItdError, TracerLayout};

mod cf_table;
mod output;

pub use cf_table::{read_cf_table, read_cf_table_at_friction, write_cf_table};
pub use output::{FieldMeta, NC_FILL_DOUBLE, Output, STRENGTH_META, history_line, write_output};

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

/// A coordinate variable copied from the input to the outputs: its values (as f64) and
/// attributes (`units`, `calendar`, `standard_name`...).
#[derive(Debug, Clone, PartialEq)]
pub struct CoordVar {
    /// Variable name (e.g. `time`, `TLON`).
    pub name: String,
    /// Its dimensions, in file order.
    pub dims: Vec<String>,
    /// Its values in C order.
    pub values: Vec<f64>,
    /// Its attributes, `_FillValue`/`missing_value` as f64 (the variable is written as f64).
    pub attrs: Vec<(String, netcdf::AttributeValue)>,
}

/// A gridded thickness distribution with its column dimensions (every dimension of `aicen`
/// but the category one) flattened to `ncol` columns (C order, last dimension fastest).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ItdGrid {
    /// Name of the category dimension (e.g. `ncat`).
    pub ncat_dim: String,
    /// Column dimensions (name, length) in file order, without the category dimension
    /// (e.g. `time`, `nj`, `ni`).
    pub spatial_dims: Vec<(String, usize)>,
    /// Position of the category dimension among the dimensions of `aicen` in the file (0:
    /// first); the category fields are written in that order again.
    pub cat_axis: usize,
    /// Coordinate variables to copy to the outputs.
    pub coords: Vec<CoordVar>,
    /// The auxiliary coordinates of `aicen` that were copied (its `coordinates` attribute),
    /// e.g. `TLON TLAT`.
    pub coordinates: Option<String>,
    /// The input's global `history` attribute.
    pub history: Option<String>,
    /// Where `hin_max` came from (`hin_max`, or `NCAT` of a CICE history file).
    pub hin_max_source: Option<String>,
    /// Category area fractions (dimensionless), shape (ncat, ncol).
    pub aicen: Array2<f64>,
    /// Category ice volume per unit area (m), shape (ncat, ncol).
    pub vicen: Array2<f64>,
    /// Open-water fraction (dimensionless), if present in the file.
    pub aice0: Option<Array1<f64>>,
    /// Category bounds (m), ncat + 1 values, if the file has them (`hin_max`, or `NCAT`
    /// with 0 m prepended; see `hin_max_source`).
    pub hin_max: Option<Vec<f64>>,
    /// Velocity divergence (1/s), if present.
    pub divu: Option<Array1<f64>>,
    /// Shear term of the ridging closing rate (1/s), if present.
    pub shear: Option<Array1<f64>>,
    /// Columns holding data (false where `aicen`, `vicen` or `aice0` equals its
    /// `_FillValue`/`missing_value`, e.g. land); `None` when no value is missing.
    pub valid: Option<Array1<bool>>,
    /// The fill value of `aicen` in the input (used for masked columns on output), if any.
    pub fill_value: Option<f64>,
}

impl ItdGrid {
    /// Number of categories.
    pub fn ncat(&self) -> usize {
        self.aicen.nrows()
    }
    /// Number of columns (product of the spatial lengths).
    pub fn ncol(&self) -> usize {
        self.aicen.ncols()
    }
    /// Numbers of columns before and after the category dimension in file order: the file
    /// holds (n_before, ncat, n_after) values.
    pub fn split(&self) -> (usize, usize) {
        let k = self.cat_axis.min(self.spatial_dims.len());
        let before = self.spatial_dims[..k].iter().map(|d| d.1).product();
        let after = self.spatial_dims[k..].iter().map(|d| d.1).product();
        (before, after)
    }
    /// The dimensions of a category variable in file order (the category dimension at
    /// `cat_axis` among the column dimensions).
    pub fn category_dims(&self) -> Vec<(String, usize)> {
        let mut d = self.spatial_dims.clone();
        d.insert(
            self.cat_axis.min(d.len()),
            (self.ncat_dim.clone(), self.ncat()),
        );
        d
    }
    /// Values of a category variable in file order, turned into (ncat, ncol).
    pub fn to_category_major(&self, data: Vec<f64>) -> Array2<f64> {
        let (ncat, (before, after)) = (self.aicen.nrows(), self.split());
        let a = Array3::from_shape_vec((before, ncat, after), data)
            .expect("length checked by the library");
        a.permuted_axes([1, 0, 2])
            .as_standard_layout()
            .into_owned()
            .into_shape_with_order((ncat, before * after))
            .expect("standard layout")
    }
    /// (ncat, ncol) values in C order turned into the file order of the category variables.
    pub fn to_file_order(&self, data: &[f64]) -> Vec<f64> {
        let (ncat, (before, after)) = (self.ncat(), self.split());
        if before == 1 {
            return data.to_vec();
        }
        let a = ndarray::ArrayView3::from_shape((ncat, before, after), data)
            .expect("length checked by the caller");
        a.permuted_axes([1, 0, 2]).iter().copied().collect()
    }
    /// The spatial index of flat column `column`, formatted as `name=i, ...`.
    pub fn spatial_index(&self, column: usize) -> String {
        let mut rem = column;
        let mut idx = vec![0; self.spatial_dims.len()];
        for (k, (_, len)) in self.spatial_dims.iter().enumerate().rev() {
            idx[k] = rem % len;
            rem /= len;
        }
        self.spatial_dims
            .iter()
            .zip(idx)
            .map(|((n, _), i)| format!("{n}={i}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
    /// Wraps a physics error with the file name and, for a column error, the spatial index.
    pub fn locate(&self, path: &Path, e: ItdError) -> NetcdfError {
        match e {
            ItdError::Column { column, source } => NetcdfError::Column {
                path: path.to_path_buf(),
                column,
                spatial: self.spatial_index(column),
                source,
            },
            other => NetcdfError::Itd {
                path: path.to_path_buf(),
                source: other,
            },
        }
    }
}

fn nc_err(path: &Path) -> impl Fn(netcdf::Error) -> NetcdfError + '_ {
    move |source| NetcdfError::Netcdf {
        path: path.to_path_buf(),
        source,
    }
}

/// Dimensions of `v`, without a leading time dimension of length 1 (named `time` or `t`, or
/// unlimited), as in CICE history files `aicen(time, nc, nj, ni)`.
fn dims_of(v: &netcdf::Variable<'_>) -> Vec<(String, usize)> {
    let d = v.dimensions();
    let skip = usize::from(
        d.len() > 1
            && d[0].len() == 1
            && (d[0].is_unlimited() || d[0].name() == "time" || d[0].name() == "t"),
    );
    d[skip..].iter().map(|d| (d.name(), d.len())).collect()
}

/// The `_FillValue` (else `missing_value`) attribute of `v`, as f64.
fn fill_of(v: &netcdf::Variable<'_>) -> Option<f64> {
    // By listing: asking HDF5 for a missing attribute makes it print errors.
    ["_FillValue", "missing_value"].iter().find_map(|name| {
        v.attributes()
            .find(|a| a.name() == *name)
            .and_then(|a| a.value().ok())
            .and_then(|x| f64::try_from(x).ok())
    })
}

fn is_fill(x: f64, fill: Option<f64>) -> bool {
    match fill {
        Some(f) => x == f || (f.is_nan() && x.is_nan()),
        None => false,
    }
}

fn fmt_dims(d: &[(String, usize)]) -> String {
    let parts: Vec<String> = d.iter().map(|(n, l)| format!("{n}={l}")).collect();
    format!("({})", parts.join(", "))
}

/// Reads a numeric variable as f64; a variable of another type (text, compound, ...) is an
/// error naming it and its type.
fn read_f64(path: &Path, v: &netcdf::Variable<'_>) -> Result<Vec<f64>, NetcdfError> {
    use netcdf::types::NcVariableType as T;
    // `vartype` panics on a type it does not know: that is "not numeric" too.
    let t = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| v.vartype())).ok();
    let kind = match &t {
        Some(T::Int(_) | T::Float(_)) => None,
        Some(T::Char) => Some("text (char)"),
        Some(T::String) => Some("text (string)"),
        Some(T::Compound(_)) => Some("compound"),
        Some(T::Opaque(_)) => Some("opaque"),
        Some(T::Enum(_)) => Some("enum"),
        Some(T::Vlen(_)) => Some("variable-length"),
        None => Some("an unknown type"),
    };
    if let Some(kind) = kind {
        return Err(NetcdfError::Value {
            path: path.to_path_buf(),
            var: v.name(),
            msg: format!("has type {kind}, expected a numeric type (double, float or integer)"),
        });
    }
    v.get_values::<f64, _>(..).map_err(nc_err(path))
}

fn read_spatial(
    path: &Path,
    file: &netcdf::File,
    name: &str,
    spatial: &[(String, usize)],
) -> Result<Option<Array1<f64>>, NetcdfError> {
    let Some(v) = file.variable(name) else {
        return Ok(None);
    };
    let d = all_dims(&v);
    if without_unit_time(&d) != without_unit_time(spatial) {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: name.into(),
            expected: fmt_dims(spatial),
            found: fmt_dims(&d),
        });
    }
    Ok(Some(Array1::from(read_f64(path, &v)?)))
}

/// The ocean mask of CICE history files, `tmask` (1 ocean, 0 land), over the column
/// dimensions: `None` without `tmask`; otherwise per column whether it is ocean. `tmask` may
/// lack column dimensions (it has no `time`): it is then the same at every value of those.
/// A zero or fill value is land. A `tmask` with a dimension that is not a column dimension
/// of the same length is refused.
fn read_ocean_mask(
    path: &Path,
    file: &netcdf::File,
    spatial: &[(String, usize)],
) -> Result<Option<Vec<bool>>, NetcdfError> {
    let Some(v) = file.variable("tmask") else {
        return Ok(None);
    };
    let d = all_dims(&v);
    let pos: Option<Vec<usize>> = d
        .iter()
        .map(|(n, l)| spatial.iter().position(|(m, k)| m == n && k == l))
        .collect();
    let Some(pos) = pos else {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "tmask".into(),
            expected: format!("column dimensions of aicen, {}", fmt_dims(spatial)),
            found: fmt_dims(&d),
        });
    };
    let vals = read_f64(path, &v)?;
    let fill = fill_of(&v);
    let ncol: usize = spatial.iter().map(|s| s.1).product();
    let mut idx = vec![0usize; spatial.len()];
    let mut out = Vec::with_capacity(ncol);
    for c in 0..ncol {
        let mut rem = c;
        for k in (0..spatial.len()).rev() {
            idx[k] = rem % spatial[k].1;
            rem /= spatial[k].1;
        }
        let j = pos
            .iter()
            .zip(&d)
            .fold(0usize, |j, (&p, (_, l))| j * l + idx[p]);
        let m = vals[j];
        out.push(!(is_fill(m, fill) || m == 0.0));
    }
    Ok(Some(out))
}

/// Units of a strain rate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum RateUnits {
    PerSecond,
    PercentPerDay,
}

fn rate_units(path: &Path, v: &netcdf::Variable<'_>) -> Result<RateUnits, NetcdfError> {
    // Look the attribute up by listing (asking for a missing one makes HDF5 print errors).
    let Some(units) = v
        .attributes()
        .find(|a| a.name() == "units")
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok())
    else {
        return Ok(RateUnits::PerSecond);
    };
    let u: String = units.chars().filter(|c| !c.is_whitespace()).collect();
    match u.as_str() {
        "s-1" | "1/s" | "s^-1" | "/s" | "s**-1" => Ok(RateUnits::PerSecond),
        "%/day" | "%/d" | "%day-1" | "percent/day" => Ok(RateUnits::PercentPerDay),
        _ => Err(NetcdfError::Units {
            path: path.to_path_buf(),
            var: v.name(),
            units,
            extra: String::new(),
        }),
    }
}

/// An optional field on the spatial dimensions.
type SpatialField = Option<Array1<f64>>;

/// `divu` (1/s) and the ridging shear term (1/s) from the file, converted from CICE's %/day
/// where the units say so.
fn read_deformation(
    path: &Path,
    file: &netcdf::File,
    spatial: &[(String, usize)],
) -> Result<(SpatialField, SpatialField), NetcdfError> {
    use crate::itd::{deformation_terms, percent_per_day_to_per_second};
    let units = |name: &str| -> Result<Option<RateUnits>, NetcdfError> {
        file.variable(name)
            .map(|v| rate_units(path, &v))
            .transpose()
    };
    let (du, su) = (units("divu")?, units("shear")?);
    let mut divu = read_spatial(path, file, "divu", spatial)?;
    let mut shear = read_spatial(path, file, "shear", spatial)?;
    if du == Some(RateUnits::PercentPerDay)
        && let Some(d) = divu.as_mut()
    {
        d.mapv_inplace(percent_per_day_to_per_second);
    }
    if su == Some(RateUnits::PercentPerDay)
        && let Some(s) = shear.as_mut()
    {
        // CICE's history shear is the strain-rate magnitude: form the ridging term.
        let Some(d) = divu.as_ref() else {
            return Err(NetcdfError::Units {
                path: path.to_path_buf(),
                var: "shear".into(),
                units: "%/day".into(),
                extra: ": CICE's shear strain rate needs `divu` to form the ridging shear \
                        term"
                    .into(),
            });
        };
        for (x, &dv) in s.iter_mut().zip(d) {
            *x = deformation_terms(dv, percent_per_day_to_per_second(*x)).1;
        }
    }
    Ok((divu, shear))
}

/// The unit a per-cell field read by [`read_cell_field`] must carry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CellUnits {
    /// A rate in 1/s (`s-1`, `1/s`, `s^-1`, `/s`, `s**-1`): the host's closing and opening
    /// rates. CICE history's `%/day` is refused, never converted: SIS2 gives these rates in
    /// 1/s, and a %/day value taken for 1/s would be wrong by a factor 8.64e6.
    PerSecond,
    /// A temperature in °C (`degC`, `deg_C`, `degrees_C`, `degree_C`, `degree_Celsius`,
    /// `Celsius`, `C`): the freezing temperature. Kelvin and anything else is refused.
    DegC,
}

impl CellUnits {
    fn accepts(self, u: &str) -> bool {
        let u: String = u.chars().filter(|c| !c.is_whitespace()).collect();
        match self {
            CellUnits::PerSecond => matches!(u.as_str(), "s-1" | "1/s" | "s^-1" | "/s" | "s**-1"),
            CellUnits::DegC => matches!(
                u.to_ascii_lowercase().as_str(),
                "degc"
                    | "deg_c"
                    | "degrees_c"
                    | "degree_c"
                    | "degree_celsius"
                    | "degrees_celsius"
                    | "celsius"
                    | "c"
            ),
        }
    }

    fn expected(self) -> &'static str {
        match self {
            CellUnits::PerSecond => "\"s-1\" (1/s)",
            CellUnits::DegC => "\"degC\"",
        }
    }
}

/// A per-cell field of the column dimensions, read by [`read_cell_field`].
#[derive(Debug, Clone, PartialEq)]
pub struct CellField {
    /// Values per column (the variable's unit, which [`CellUnits`] checked).
    pub values: Array1<f64>,
    /// Columns holding data (false where the value equals the variable's `_FillValue` or
    /// `missing_value`); `None` when no value is missing.
    pub valid: Option<Array1<bool>>,
}

/// Reads the per-cell variable `name` (the column dimensions of `grid`, a leading `time` of
/// length 1 allowed on one side) from `path`: `Ok(None)` when the file has no such variable.
/// Its `units` attribute must be present and name `units`; a missing or other unit is an
/// error naming the variable, the unit found and the one expected.
pub fn read_cell_field(
    path: &Path,
    grid: &ItdGrid,
    name: &str,
    units: CellUnits,
) -> Result<Option<CellField>, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let Some(v) = file.variable(name) else {
        return Ok(None);
    };
    let found = v
        .attributes()
        .find(|a| a.name() == "units")
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok());
    match found {
        None => {
            return Err(NetcdfError::Value {
                path: path.to_path_buf(),
                var: name.into(),
                msg: format!(
                    "has no `units` attribute; it must be in {} (say so with units = {})",
                    units.expected(),
                    units.expected()
                ),
            });
        }
        Some(u) if !units.accepts(&u) => {
            let hint = if units == CellUnits::PerSecond && rate_is_percent_per_day(&u) {
                " (CICE history's %/day is not converted here: give the host's rates in 1/s)"
            } else {
                ""
            };
            return Err(NetcdfError::Value {
                path: path.to_path_buf(),
                var: name.into(),
                msg: format!("has units \"{u}\"; expected {}{hint}", units.expected()),
            });
        }
        Some(_) => {}
    }
    let fill = fill_of(&v);
    let values = read_spatial(path, &file, name, &grid.spatial_dims)?.expect("the variable exists");
    let valid: Array1<bool> = values.iter().map(|&x| !is_fill(x, fill)).collect();
    Ok(Some(CellField {
        values,
        valid: (!valid.iter().all(|&v| v)).then_some(valid),
    }))
}

fn rate_is_percent_per_day(u: &str) -> bool {
    let u: String = u.chars().filter(|c| !c.is_whitespace()).collect();
    matches!(u.as_str(), "%/day" | "%/d" | "%day-1" | "percent/day")
}

/// Reads a gridded thickness distribution (see the module documentation for the layout),
/// the category dimension found by name.
pub fn read_itd(path: &Path) -> Result<ItdGrid, NetcdfError> {
    read_itd_with(path, &ReadOptions::default())
}

/// All dimensions of `v` (name, length) in file order.
fn all_dims(v: &netcdf::Variable<'_>) -> Vec<(String, usize)> {
    v.dimensions().iter().map(|d| (d.name(), d.len())).collect()
}

/// `d` without a leading `time`/`t`/`Time` dimension of length 1.
fn without_unit_time(d: &[(String, usize)]) -> &[(String, usize)] {
    match d.first() {
        Some((n, 1)) if d.len() > 1 && matches!(n.as_str(), "time" | "t" | "Time") => &d[1..],
        _ => d,
    }
}

/// A string attribute of `v`, looked up by listing (asking HDF5 for a missing attribute makes
/// it print errors).
fn str_attr(v: &netcdf::Variable<'_>, name: &str) -> Option<String> {
    v.attributes()
        .find(|a| a.name() == name)
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok())
}

/// A coordinate variable of `file` to copy, if it is numeric and lies on `allowed` dims.
fn coord_var(
    path: &Path,
    file: &netcdf::File,
    name: &str,
    allowed: &[&str],
) -> Result<Option<CoordVar>, NetcdfError> {
    let Some(v) = file.variable(name) else {
        return Ok(None);
    };
    let dims: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
    if dims.is_empty() || !dims.iter().all(|d| allowed.contains(&d.as_str())) {
        return Ok(None);
    }
    let Ok(values) = read_f64(path, &v) else {
        return Ok(None); // a text coordinate: not copied
    };
    let mut attrs = Vec::new();
    for a in v.attributes() {
        let n = a.name().to_string();
        // Bounds variables are not copied; fill values are rewritten as f64.
        if matches!(
            n.as_str(),
            "bounds" | "_FillValue" | "missing_value" | "coordinates"
        ) {
            continue;
        }
        if let Ok(x) = a.value() {
            attrs.push((n, x));
        }
    }
    if let Some(f) = fill_of(&v) {
        attrs.push(("_FillValue".into(), f.into()));
    }
    Ok(Some(CoordVar {
        name: name.into(),
        dims,
        values,
        attrs,
    }))
}

/// Category bounds (m) from `hin_max` (ncat + 1 values) or CICE history's `NCAT` (the ncat
/// upper bounds, on the category dimension; the lowest bound is 0 m), checked against each
/// other when both are present, and validated. Returns the bounds and their source.
fn read_bounds(
    path: &Path,
    file: &netcdf::File,
    cat_dim: &str,
    ncat: usize,
) -> Result<Option<(Vec<f64>, String)>, NetcdfError> {
    let from_hin_max = match file.variable("hin_max") {
        None => None,
        Some(h) => {
            let vals = read_f64(path, &h)?;
            if h.dimensions().len() != 1 || vals.len() != ncat + 1 {
                return Err(NetcdfError::Shape {
                    path: path.to_path_buf(),
                    var: "hin_max".into(),
                    expected: format!("one dimension of length ncat + 1 = {}", ncat + 1),
                    found: fmt_dims(&dims_of(&h)),
                });
            }
            Some(vals)
        }
    };
    let from_ncat = match file.variable("NCAT") {
        None => None,
        Some(v) => {
            let d = all_dims(&v);
            if d != [(cat_dim.to_string(), ncat)] {
                return Err(NetcdfError::Shape {
                    path: path.to_path_buf(),
                    var: "NCAT".into(),
                    expected: format!(
                        "({cat_dim}={ncat}): the upper bound of each category (CICE history)"
                    ),
                    found: fmt_dims(&d),
                });
            }
            let mut b = vec![0.0];
            b.extend(read_f64(path, &v)?);
            Some(b)
        }
    };
    let (vals, source) = match (from_hin_max, from_ncat) {
        (None, None) => return Ok(None),
        (Some(h), None) => (h, "hin_max from the input".to_string()),
        (None, Some(n)) => (
            n,
            "NCAT from the input (CICE history: upper bounds; lowest bound 0 m)".to_string(),
        ),
        (Some(h), Some(n)) => {
            // NCAT is often single precision: agree to its precision.
            let agree = h
                .iter()
                .zip(&n)
                .all(|(a, b)| (a - b).abs() <= 1e-6 * a.abs().max(1.0));
            if !agree {
                return Err(NetcdfError::Value {
                    path: path.to_path_buf(),
                    var: "NCAT".into(),
                    msg: format!(
                        "the category bounds disagree: hin_max is {h:?} m, NCAT (upper bounds, \
                         from 0 m) gives {n:?} m"
                    ),
                });
            }
            (h, "hin_max from the input (agrees with NCAT)".to_string())
        }
    };
    let var = if source.starts_with("NCAT") {
        "NCAT"
    } else {
        "hin_max"
    };
    crate::itd::bounds::validate_bounds(&vals).map_err(|e| NetcdfError::Value {
        path: path.to_path_buf(),
        var: var.into(),
        msg: e.to_string(),
    })?;
    Ok(Some((vals, source)))
}

/// Reads a gridded thickness distribution (see the module documentation for the layout).
pub fn read_itd_with(path: &Path, opts: &ReadOptions) -> Result<ItdGrid, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let get = |name: &str| {
        file.variable(name)
            .ok_or_else(|| NetcdfError::MissingVariable {
                path: path.to_path_buf(),
                var: name.into(),
            })
    };
    let av = get("aicen")?;
    let vv = get("vicen")?;
    let ad = all_dims(&av);
    let vd = all_dims(&vv);
    if ad.is_empty() {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "aicen".into(),
            expected: "(a category dimension, column dimensions...)".into(),
            found: "a scalar".into(),
        });
    }
    if vd != ad {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "vicen".into(),
            expected: fmt_dims(&ad),
            found: fmt_dims(&vd),
        });
    }
    let cat_axis = category_axis(path, "aicen", &ad, opts.category_dim.as_deref())?;
    let (ncat_dim, ncat) = ad[cat_axis].clone();
    let mut spatial: Vec<(String, usize)> = ad.clone();
    spatial.remove(cat_axis);
    let ncol: usize = spatial.iter().map(|d| d.1).product();
    let mut grid = ItdGrid {
        ncat_dim: ncat_dim.clone(),
        spatial_dims: spatial.clone(),
        cat_axis,
        aicen: Array2::zeros((ncat, ncol)),
        ..Default::default()
    };
    let aicen = grid.to_category_major(read_f64(path, &av)?);
    let vicen = grid.to_category_major(read_f64(path, &vv)?);
    let (afill, vfill) = (fill_of(&av), fill_of(&vv));
    let a0fill = file.variable("aice0").as_ref().and_then(fill_of);
    let bounds = read_bounds(path, &file, &ncat_dim, ncat)?;
    let aice0 = read_spatial(path, &file, "aice0", &spatial)?;
    let ocean = read_ocean_mask(path, &file, &spatial)?;
    let valid: Array1<bool> = (0..ncol)
        .map(|c| {
            ocean.as_ref().is_none_or(|o| o[c])
                && !(aicen.column(c).iter().any(|&x| is_fill(x, afill))
                    || vicen.column(c).iter().any(|&x| is_fill(x, vfill))
                    || aice0.as_ref().is_some_and(|a| is_fill(a[c], a0fill)))
        })
        .collect();
    let (divu, shear) = read_deformation(path, &file, &spatial)?;
    // Coordinates: those of the column dimensions, and aicen's auxiliary ones.
    let names: Vec<&str> = spatial.iter().map(|d| d.0.as_str()).collect();
    let mut coords = Vec::new();
    for n in &names {
        if let Some(c) = coord_var(path, &file, n, &names)? {
            coords.push(c);
        }
    }
    let mut aux = Vec::new();
    if let Some(list) = str_attr(&av, "coordinates") {
        for n in list.split_whitespace() {
            if coords.iter().any(|c| c.name == n) {
                continue;
            }
            if let Some(c) = coord_var(path, &file, n, &names)? {
                coords.push(c);
                aux.push(n.to_string());
            }
        }
    }
    let history = file
        .attribute("history")
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok());
    let (hin_max, hin_max_source) = match bounds {
        Some((b, s)) => (Some(b), Some(s)),
        None => (None, None),
    };
    grid.aicen = aicen;
    grid.vicen = vicen;
    grid.aice0 = aice0;
    grid.divu = divu;
    grid.shear = shear;
    grid.hin_max = hin_max;
    grid.hin_max_source = hin_max_source;
    grid.coords = coords;
    grid.coordinates = (!aux.is_empty()).then(|| aux.join(" "));
    grid.history = history;
    grid.fill_value = afill.or(vfill).or(a0fill);
    grid.valid = if valid.iter().all(|&v| v) {
        None
    } else {
        Some(valid)
    };
    check_volume_range(path, &grid)?;
    Ok(grid)
}

/// Snow and tracers of a gridded distribution, for the complete ridging step. Variable names
/// are CICE restart names ([`TracerLayout::cice_restart_names`]): `vsnon` (m), `Tsfcn`,
/// `qice001`.., `sice001`.., `qsno001`.., and `iage`, `FY`, `alvl`, `vlvl`, `apnd`, `hpnd`,
/// `ipnd` where present, each with the dimensions of `aicen`.
#[derive(Debug, Clone, PartialEq)]
pub struct SnowTracers {
    /// The CICE layout found in the file.
    pub layout: TracerLayout,
    /// The optional tracers found.
    pub flags: CiceTracerFlags,
    /// Snow volume per unit area (m), `(ncat, ncol)`; zeros when the file has no `vsnon`.
    pub vsnon: Array2<f64>,
    /// Tracers `(ncat, ntrcr, ncol)` in the layout's order and units.
    pub trcrn: Array3<f64>,
    /// Columns with a fill value in `vsnon` or a tracer (false), if any.
    pub missing: Option<Array1<bool>>,
    /// The fill value of those variables, if any has one.
    pub fill_value: Option<f64>,
}

/// Reads the snow and tracers that go with `grid` (read from the same file by [`read_itd`]):
/// `Ok(None)` when the file has none of `vsnon`, `Tsfcn`, `qice001`, `sice001`, `qsno001`
/// (then only area and volume can be ridged). The layout is told from the variable names by
/// [`TracerLayout::detect_cice`] (the one detection, which Python's `xr.ridge_step` uses
/// too). Errors name the missing or malformed variable.
pub fn read_snow_tracers(path: &Path, grid: &ItdGrid) -> Result<Option<SnowTracers>, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let has = |n: &str| file.variable(n).is_some();
    let Some((layout, flags)) =
        TracerLayout::detect_cice(&has).map_err(|e| NetcdfError::Value {
            path: path.to_path_buf(),
            var: e.var.clone(),
            msg: e.to_string(),
        })?
    else {
        return Ok(None);
    };
    let names = layout.cice_restart_names();
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let dims = grid.category_dims();
    let mut fill_value = None;
    let mut missing = vec![false; ncol];
    let mut read_cat = |name: &str| -> Result<Array2<f64>, NetcdfError> {
        let v = file.variable(name).expect("presence checked");
        let d = all_dims(&v);
        if d != dims {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: name.into(),
                expected: fmt_dims(&dims),
                found: fmt_dims(&d),
            });
        }
        let fill = fill_of(&v);
        fill_value = fill_value.or(fill);
        let a = grid.to_category_major(read_f64(path, &v)?);
        for (c, m) in missing.iter_mut().enumerate() {
            if a.column(c).iter().any(|&x| is_fill(x, fill)) {
                *m = true;
            }
        }
        Ok(a)
    };
    let vsnon = if has("vsnon") {
        read_cat("vsnon")?
    } else {
        Array2::zeros((ncat, ncol))
    };
    let nt = layout.ntrcr();
    let mut trcrn = Array3::zeros((ncat, nt, ncol));
    for (it, name) in names.iter().enumerate() {
        let a = read_cat(name)?;
        trcrn.index_axis_mut(ndarray::Axis(1), it).assign(&a);
    }
    let any_missing = missing.iter().any(|m| *m);
    Ok(Some(SnowTracers {
        layout,
        flags,
        vsnon,
        trcrn,
        missing: any_missing.then(|| missing.into_iter().map(|m| !m).collect()),
        fill_value,
    }))
}

/// Refuses a category volume beyond [`crate::limits::CATEGORY_THICKNESS`] (vicen ≤ vicen /
/// aicen, so a larger vicen means thicker ice than any), which would overflow the squares
/// and exponentials of the strength and ridging formulas into inf or NaN. Masked columns are
/// not checked; NaN, infinite and negative values are the physics' to name.
fn check_volume_range(path: &Path, g: &ItdGrid) -> Result<(), NetcdfError> {
    let range = crate::limits::CATEGORY_THICKNESS;
    for c in 0..g.ncol() {
        if g.valid.as_ref().is_some_and(|v| !v[c]) {
            continue;
        }
        for (k, &x) in g.vicen.column(c).iter().enumerate() {
            if x.is_finite()
                && x > range.max
                && let Some(why) = range.violation(x)
            {
                return Err(NetcdfError::Value {
                    path: path.to_path_buf(),
                    var: "vicen".into(),
                    msg: format!(
                        "column {c} at ({}), category {k}: {why}",
                        g.spatial_index(c)
                    ),
                });
            }
        }
    }
    Ok(())
}

/// Reads one variable as `f64` with its dimensions (name, length).
pub fn read_field(path: &Path, name: &str) -> Result<(Dims, Vec<f64>), NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let v = file
        .variable(name)
        .ok_or_else(|| NetcdfError::MissingVariable {
            path: path.to_path_buf(),
            var: name.into(),
        })?;
    Ok((dims_of(&v), read_f64(path, &v)?))
}

/// True when the file has a variable called `name`.
pub fn has_variable(path: &Path, name: &str) -> Result<bool, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    Ok(file.variable(name).is_some())
}

/// The `_FillValue` (else `missing_value`) of variable `name`, if it has one.
pub fn read_fill(path: &Path, name: &str) -> Result<Option<f64>, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let v = file
        .variable(name)
        .ok_or_else(|| NetcdfError::MissingVariable {
            path: path.to_path_buf(),
            var: name.into(),
        })?;
    Ok(fill_of(&v))
}
