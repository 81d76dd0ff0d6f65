//! NetCDF reading and writing of gridded thickness distributions.
//!
//! Input: `aicen` and `vicen` whose first dimension is the category dimension (`ncat`)
//! followed by any number of spatial dimensions; optional `aice0` (spatial dims; else
//! 1 − Σ aicen), `hin_max` (length ncat + 1; else the CICE default bounds), `divu` and `shear`
//! (spatial dims) for the ridging step. Any numeric type is read as `f64`.
//!
//! Units of `divu` and `shear`, from their `units` attribute: `s-1` (also `1/s`, `s^-1`, or no
//! attribute): `divu` is the divergence and `shear` the ridging shear term ½(Δ − |div u|),
//! both 1/s. `%/day` (CICE history files): `divu` and `shear` are CICE's divergence and shear
//! strain rate, converted to 1/s, and the shear term is formed as Icepack's ridging needs it
//! (`crate::itd::deformation_terms`, which needs `divu`). Any other unit is refused with a
//! message naming it, so that %/day is never taken for 1/s.
//!
//! Output: CF-1.8 attributes (`units`, `long_name`, `standard_name` where CF has one), the
//! options used and the package version as global attributes.

use std::path::{Path, PathBuf};

use ndarray::{Array1, Array2, Array3};

use crate::itd::{CfTable, CiceTracerFlags, ItdError, TracerLayout};

/// Dimensions of a variable: (name, length) in file order.
pub type Dims = Vec<(String, usize)>;

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

/// A gridded thickness distribution with its spatial dimensions flattened to `ncol` columns
/// (C order, last dimension fastest).
#[derive(Debug, Clone, PartialEq)]
pub struct ItdGrid {
    /// Name of the category dimension (e.g. `ncat`).
    pub ncat_dim: String,
    /// Spatial dimensions (name, length) in file order.
    pub spatial_dims: Vec<(String, usize)>,
    /// Category area fractions (dimensionless), shape (ncat, ncol).
    pub aicen: Array2<f64>,
    /// Category ice volume per unit area (m), shape (ncat, ncol).
    pub vicen: Array2<f64>,
    /// Open-water fraction (dimensionless), if present in the file.
    pub aice0: Option<Array1<f64>>,
    /// Category bounds (m), if present in the file.
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
    let d = dims_of(&v);
    if d != spatial {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: name.into(),
            expected: fmt_dims(spatial),
            found: fmt_dims(&d),
        });
    }
    Ok(Some(Array1::from(read_f64(path, &v)?)))
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

/// Reads a gridded thickness distribution (see the module documentation for the layout).
pub fn read_itd(path: &Path) -> Result<ItdGrid, NetcdfError> {
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
    let ad = dims_of(&av);
    let vd = dims_of(&vv);
    if ad.is_empty() {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "aicen".into(),
            expected: "(ncat, spatial dimensions...)".into(),
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
    if let Some(d0) = av.dimensions().first()
        && (d0.is_unlimited() || d0.name() == "time" || d0.name() == "t")
        && d0.len() > 1
    {
        return Err(NetcdfError::Shape {
            path: path.to_path_buf(),
            var: "aicen".into(),
            expected:
                "(ncat, spatial dimensions...), optionally after a time dimension of length 1"
                    .into(),
            found: format!(
                "a leading `{}` dimension of length {}: select one time first",
                d0.name(),
                d0.len()
            ),
        });
    }
    let ncat = ad[0].1;
    let spatial: Vec<(String, usize)> = ad[1..].to_vec();
    let ncol: usize = spatial.iter().map(|d| d.1).product();
    let aicen = Array2::from_shape_vec((ncat, ncol), read_f64(path, &av)?)
        .expect("length checked by the library");
    let vicen = Array2::from_shape_vec((ncat, ncol), read_f64(path, &vv)?)
        .expect("length checked by the library");
    let (afill, vfill) = (fill_of(&av), fill_of(&vv));
    let a0fill = file.variable("aice0").as_ref().and_then(fill_of);
    let hin_max = match file.variable("hin_max") {
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
            crate::itd::bounds::validate_bounds(&vals).map_err(|e| NetcdfError::Value {
                path: path.to_path_buf(),
                var: "hin_max".into(),
                msg: e.to_string(),
            })?;
            Some(vals)
        }
    };
    let aice0 = read_spatial(path, &file, "aice0", &spatial)?;
    let valid: Array1<bool> = (0..ncol)
        .map(|c| {
            !(aicen.column(c).iter().any(|&x| is_fill(x, afill))
                || vicen.column(c).iter().any(|&x| is_fill(x, vfill))
                || aice0.as_ref().is_some_and(|a| is_fill(a[c], a0fill)))
        })
        .collect();
    let (divu, shear) = read_deformation(path, &file, &spatial)?;
    let grid = ItdGrid {
        ncat_dim: ad[0].0.clone(),
        aice0,
        divu,
        shear,
        spatial_dims: spatial,
        aicen,
        vicen,
        hin_max,
        fill_value: afill.or(vfill).or(a0fill),
        valid: if valid.iter().all(|&v| v) {
            None
        } else {
            Some(valid)
        },
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

/// Number of consecutive variables `<prefix>001`, `<prefix>002`, ... in the file.
fn count_levels(file: &netcdf::File, prefix: &str) -> usize {
    (1..)
        .take_while(|k| file.variable(&format!("{prefix}{k:03}")).is_some())
        .count()
}

/// Reads the snow and tracers that go with `grid` (read from the same file by [`read_itd`]):
/// `Ok(None)` when the file has none of `vsnon`, `Tsfcn`, `qice001`, `sice001`, `qsno001`
/// (then only area and volume can be ridged). The numbers of ice and snow layers are those
/// of the `qice` and `qsno` variables found; each optional tracer group (`iage`; `FY`;
/// `alvl` with `vlvl`; `apnd`, `hpnd`, `ipnd`) is used when all its variables are present.
/// Errors name the missing or malformed variable.
pub fn read_snow_tracers(path: &Path, grid: &ItdGrid) -> Result<Option<SnowTracers>, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let has = |n: &str| file.variable(n).is_some();
    let nilyr = count_levels(&file, "qice");
    let nslyr = count_levels(&file, "qsno");
    let base_probe = TracerLayout::cice(1, 1, CiceTracerFlags::default())
        .expect("the minimal CICE layout is valid")
        .cice_restart_names();
    if !has("vsnon") && !base_probe.iter().any(|n| has(n)) {
        return Ok(None);
    }
    let missing_var = |var: String, why: &str| NetcdfError::Value {
        path: path.to_path_buf(),
        var,
        msg: format!("missing: {why}"),
    };
    if nilyr == 0 || nslyr == 0 {
        let var = if nilyr == 0 { "qice001" } else { "qsno001" };
        return Err(missing_var(
            var.into(),
            "the complete ridging step needs the ice enthalpy qice001.. and snow enthalpy \
             qsno001.. with vsnon and the other tracers (CICE restart names)",
        ));
    }
    let base = TracerLayout::cice(nilyr, nslyr, CiceTracerFlags::default())
        .map_err(|source| NetcdfError::Itd {
            path: path.to_path_buf(),
            source,
        })?
        .cice_restart_names();
    // Each optional group: the names it adds to the layout below it.
    let groups: [(CiceTracerFlags, CiceTracerFlags); 4] = {
        let f = |age, first_year, level_ice, ponds| CiceTracerFlags {
            age,
            first_year,
            level_ice,
            ponds,
        };
        [
            (f(true, false, false, false), f(false, false, false, false)),
            (f(false, true, false, false), f(false, false, false, false)),
            (f(false, false, true, false), f(false, false, false, false)),
            (f(false, false, true, true), f(false, false, true, false)),
        ]
    };
    let mut flags = CiceTracerFlags::default();
    for (k, (with, without)) in groups.iter().enumerate() {
        let names = |fl: CiceTracerFlags| {
            TracerLayout::cice(nilyr, nslyr, fl)
                .expect("CICE layouts with level ice are valid")
                .cice_restart_names()
        };
        let below = names(*without);
        let added: Vec<String> = names(*with)
            .into_iter()
            .filter(|n| !below.contains(n))
            .collect();
        let present: Vec<bool> = added.iter().map(|n| has(n)).collect();
        if present.iter().all(|p| *p) {
            match k {
                0 => flags.age = true,
                1 => flags.first_year = true,
                2 => flags.level_ice = true,
                _ => flags.ponds = true,
            }
        } else if present.iter().any(|p| *p) {
            let miss = added
                .iter()
                .zip(&present)
                .find(|(_, p)| !**p)
                .map(|(n, _)| n.clone())
                .unwrap_or_default();
            return Err(missing_var(
                miss,
                &format!("the tracers {} go together", added.join(", ")),
            ));
        }
    }
    if flags.ponds && !flags.level_ice {
        flags.ponds = false;
    }
    let layout = TracerLayout::cice(nilyr, nslyr, flags).map_err(|source| NetcdfError::Itd {
        path: path.to_path_buf(),
        source,
    })?;
    let names = layout.cice_restart_names();
    for n in base.iter().chain(&names) {
        if !has(n) {
            return Err(missing_var(
                n.clone(),
                &format!(
                    "the file has qice001..qice{nilyr:03} and qsno001..qsno{nslyr:03}, so the \
                     layout needs {n}"
                ),
            ));
        }
    }
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let mut dims = vec![(grid.ncat_dim.clone(), ncat)];
    dims.extend(grid.spatial_dims.iter().cloned());
    let mut fill_value = None;
    let mut missing = vec![false; ncol];
    let mut read_cat = |name: &str| -> Result<Array2<f64>, NetcdfError> {
        let v = file.variable(name).expect("presence checked");
        let d = dims_of(&v);
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
        let a = Array2::from_shape_vec((ncat, ncol), read_f64(path, &v)?)
            .expect("length checked by the library");
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

/// Reads a C_f table: 1-D variables `thickness` (m) and `cf` (dimensionless) of equal
/// length, thickness strictly increasing. See [`CfTable`] for interpolation and clamping.
pub fn read_cf_table(path: &Path) -> Result<CfTable, NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let mut cols = Vec::new();
    for name in ["thickness", "cf"] {
        let v = file
            .variable(name)
            .ok_or_else(|| NetcdfError::MissingVariable {
                path: path.to_path_buf(),
                var: name.into(),
            })?;
        if v.dimensions().len() != 1 {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: name.into(),
                expected: "one dimension".into(),
                found: fmt_dims(&dims_of(&v)),
            });
        }
        cols.push(read_f64(path, &v)?);
    }
    let cf = cols.pop().unwrap_or_default();
    let thickness = cols.pop().unwrap_or_default();
    CfTable::new(thickness, cf).map_err(|source| NetcdfError::Itd {
        path: path.to_path_buf(),
        source,
    })
}

/// Writes a C_f table file (`thickness` in m, `cf` dimensionless), 64-bit-offset format.
pub fn write_cf_table(path: &Path, table: &CfTable) -> Result<(), NetcdfError> {
    crate::io::write_atomic_with(path, |tmp| write_cf_table_at(tmp, path, table))
}

/// [`write_cf_table`] into the file `tmp`; errors name `path`.
fn write_cf_table_at(tmp: &Path, path: &Path, table: &CfTable) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    let mut f = netcdf::create_with(tmp, netcdf::Options::_64BIT_OFFSET).map_err(&e)?;
    f.add_dimension("node", table.thickness().len())
        .map_err(&e)?;
    let mut v = f.add_variable::<f64>("thickness", &["node"]).map_err(&e)?;
    v.put_attribute("units", "m").map_err(&e)?;
    v.put_attribute("long_name", "thickness of the ridging ice")
        .map_err(&e)?;
    let mut v = f.add_variable::<f64>("cf", &["node"]).map_err(&e)?;
    v.put_attribute("units", "1").map_err(&e)?;
    v.put_attribute(
        "long_name",
        "ratio of ridging work to potential energy change C_f",
    )
    .map_err(&e)?;
    f.add_attribute("Conventions", "CF-1.8").map_err(&e)?;
    f.enddef().map_err(&e)?;
    for (name, data) in [("thickness", table.thickness()), ("cf", table.values())] {
        let mut v = f.variable_mut(name).expect("just defined");
        v.put_values(data, ..).map_err(&e)?;
    }
    f.close().map_err(&e)?;
    Ok(())
}

/// Description of one output field.
#[derive(Debug, Clone, Copy)]
pub struct FieldMeta<'a> {
    /// Variable name.
    pub name: &'a str,
    /// CF `units`.
    pub units: &'a str,
    /// CF `long_name`.
    pub long_name: &'a str,
    /// CF `standard_name`, where CF defines one.
    pub standard_name: Option<&'a str>,
}

/// What to write: an optional distribution (with bounds) and any number of 2-D fields.
#[derive(Debug, Clone, Copy)]
pub struct Output<'a> {
    /// Category and spatial layout (only the dimension names and lengths are used, plus
    /// `aicen`/`vicen`/`aice0` when `write_itd` is true).
    pub grid: &'a ItdGrid,
    /// Also write `aicen`, `vicen`, `aice0` (from `grid.aice0`, else 1 − Σ aicen) and
    /// `hin_max` from `hin_max`.
    pub write_itd: bool,
    /// Category bounds to write with the distribution (m).
    pub hin_max: Option<&'a [f64]>,
    /// Extra fields on the spatial dimensions, `ncol` values each.
    pub fields: &'a [(FieldMeta<'a>, &'a [f64])],
    /// Extra fields on the category and spatial dimensions (as `aicen`), `ncat·ncol` values
    /// each in C order (category slowest); written after `fields`.
    pub category_fields: &'a [(FieldMeta<'a>, &'a [f64])],
    /// Global attributes (name, value): options used.
    pub global: &'a [(String, String)],
    /// Fill value for masked columns (`grid.valid` false): written as `_FillValue` of every
    /// gridded variable and into the computed `aice0` of masked columns.
    pub fill: Option<f64>,
}

/// Writes `out` to a new file at `path` in the NetCDF 64-bit-offset format (readable by
/// every NetCDF tool; netCDF-C 4.9.0 with HDF5 1.10 prints spurious `HDF5-DIAG` messages
/// when NetCDF-4 files are read from a non-main thread), with CF attributes,
/// `Conventions = CF-1.8`, `source`/`pressridge_version` and the given global attributes.
///
/// The file is written atomically ([`crate::io::write_atomic_with`]): a writer killed or
/// failing at any moment leaves the previous file at `path` (or none), never a partial one.
pub fn write_output(path: &Path, out: &Output<'_>) -> Result<(), NetcdfError> {
    crate::io::write_atomic_with(path, |tmp| write_output_at(tmp, path, out))
}

/// [`write_output`] into the file `tmp`; errors name `path`.
fn write_output_at(tmp: &Path, path: &Path, out: &Output<'_>) -> Result<(), NetcdfError> {
    let e = nc_err(path);
    let g = out.grid;
    let ncol = g.ncol();
    for (meta, data) in out.category_fields {
        if data.len() != ncol * g.ncat() {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: meta.name.into(),
                expected: format!("{} values", ncol * g.ncat()),
                found: format!("{} values", data.len()),
            });
        }
    }
    for (meta, data) in out.fields {
        if data.len() != ncol {
            return Err(NetcdfError::Shape {
                path: path.to_path_buf(),
                var: meta.name.into(),
                expected: format!("{ncol} values"),
                found: format!("{} values", data.len()),
            });
        }
    }
    let spatial: Vec<&str> = g.spatial_dims.iter().map(|d| d.0.as_str()).collect();
    let mut cat_dims: Vec<&str> = vec![g.ncat_dim.as_str()];
    cat_dims.extend(&spatial);
    let bdim = format!("{}_bounds", g.ncat_dim);

    // Everything to write: (metadata, dimensions, values). Owned copies of the distribution
    // in C order (the classic format wants all definitions before any data).
    let a = g.aicen.as_standard_layout().into_owned();
    let v = g.vicen.as_standard_layout().into_owned();
    let aice0: Vec<f64> = match &g.aice0 {
        Some(a0) => a0.to_vec(),
        None => (0..ncol)
            .map(|c| match (&g.valid, out.fill) {
                (Some(v), Some(f)) if !v[c] => f,
                _ => 1.0 - g.aicen.column(c).sum(),
            })
            .collect(),
    };
    let mut items: Vec<(FieldMeta<'_>, Vec<&str>, &[f64])> = Vec::new();
    if out.write_itd {
        items.push((
            FieldMeta {
                name: "aicen",
                units: "1",
                long_name: "sea ice area fraction in each thickness category",
                standard_name: Some("sea_ice_area_fraction"),
            },
            cat_dims.clone(),
            a.as_slice().expect("standard layout"),
        ));
        items.push((
            FieldMeta {
                name: "vicen",
                units: "m",
                long_name: "sea ice volume per unit grid-cell area in each thickness category",
                standard_name: None,
            },
            cat_dims.clone(),
            v.as_slice().expect("standard layout"),
        ));
        items.push((
            FieldMeta {
                name: "aice0",
                units: "1",
                long_name: "open water fraction",
                standard_name: None,
            },
            spatial.clone(),
            &aice0,
        ));
        if let Some(h) = out.hin_max {
            items.push((
                FieldMeta {
                    name: "hin_max",
                    units: "m",
                    long_name: "thickness category bounds",
                    standard_name: None,
                },
                vec![bdim.as_str()],
                h,
            ));
        }
    }
    for (meta, data) in out.fields {
        items.push((*meta, spatial.clone(), data));
    }
    for (meta, data) in out.category_fields {
        items.push((*meta, cat_dims.clone(), data));
    }

    let mut f = netcdf::create_with(tmp, netcdf::Options::_64BIT_OFFSET).map_err(&e)?;
    for (n, l) in &g.spatial_dims {
        f.add_dimension(n, *l).map_err(&e)?;
    }
    if out.write_itd || !out.category_fields.is_empty() {
        f.add_dimension(&g.ncat_dim, g.ncat()).map_err(&e)?;
    }
    if out.write_itd {
        if let Some(h) = out.hin_max {
            f.add_dimension(&bdim, h.len()).map_err(&e)?;
        }
    }
    for (meta, dims, _) in &items {
        let mut var = f.add_variable::<f64>(meta.name, dims).map_err(&e)?;
        var.put_attribute("units", meta.units).map_err(&e)?;
        var.put_attribute("long_name", meta.long_name).map_err(&e)?;
        if let Some(s) = meta.standard_name {
            var.put_attribute("standard_name", s).map_err(&e)?;
        }
        if let Some(fill) = out.fill
            && meta.name != "hin_max"
        {
            var.put_attribute("_FillValue", fill).map_err(&e)?;
        }
    }
    f.add_attribute("Conventions", "CF-1.8").map_err(&e)?;
    f.add_attribute(
        "source",
        format!("pressridge {}", env!("CARGO_PKG_VERSION")),
    )
    .map_err(&e)?;
    f.add_attribute("pressridge_version", env!("CARGO_PKG_VERSION"))
        .map_err(&e)?;
    for (k, val) in out.global {
        f.add_attribute(k, val.as_str()).map_err(&e)?;
    }
    f.enddef().map_err(&e)?;
    for (meta, _, data) in &items {
        let mut var = f.variable_mut(meta.name).expect("just defined");
        var.put_values(data, ..).map_err(&e)?;
    }
    f.close().map_err(&e)?;
    Ok(())
}

/// NetCDF's default fill value for doubles (`NC_FILL_DOUBLE`).
pub const NC_FILL_DOUBLE: f64 = 9.969_209_968_386_869e36;

/// Metadata of the `strength` output field (N/m).
pub const STRENGTH_META: FieldMeta<'static> = FieldMeta {
    name: "strength",
    units: "N m-1",
    long_name: "compressive ice strength P",
    standard_name: None,
};

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
