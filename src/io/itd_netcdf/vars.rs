//! Reading NetCDF variables: numbers as `f64` whatever their type, dimensions (with or
//! without a leading unit `time`), fill values, string attributes, shape checks of fields
//! on the column dimensions, and the single-variable queries of the faces.

use std::path::Path;

use ndarray::Array1;

use super::{Dims, NetcdfError};

pub(super) fn nc_err(path: &Path) -> impl Fn(netcdf::Error) -> NetcdfError + '_ {
    move |source| NetcdfError::Netcdf {
        path: path.to_path_buf(),
        source,
    }
}

/// Dimensions of `v`, without a leading time dimension of length 1 (named `time` or `t`, or
/// unlimited), as in CICE history files `aicen(time, nc, nj, ni)`.
pub(super) fn dims_of(v: &netcdf::Variable<'_>) -> Vec<(String, usize)> {
    let d = v.dimensions();
    let skip = usize::from(
        d.len() > 1
            && d[0].len() == 1
            && (d[0].is_unlimited() || d[0].name() == "time" || d[0].name() == "t"),
    );
    d[skip..].iter().map(|d| (d.name(), d.len())).collect()
}

/// The `_FillValue` (else `missing_value`) attribute of `v`, as f64.
pub(super) fn fill_of(v: &netcdf::Variable<'_>) -> Option<f64> {
    // By listing: asking HDF5 for a missing attribute makes it print errors.
    ["_FillValue", "missing_value"].iter().find_map(|name| {
        v.attributes()
            .find(|a| a.name() == *name)
            .and_then(|a| a.value().ok())
            .and_then(|x| f64::try_from(x).ok())
    })
}

pub(super) fn is_fill(x: f64, fill: Option<f64>) -> bool {
    match fill {
        Some(f) => x == f || (f.is_nan() && x.is_nan()),
        None => false,
    }
}

pub(super) fn fmt_dims(d: &[(String, usize)]) -> String {
    let parts: Vec<String> = d.iter().map(|(n, l)| format!("{n}={l}")).collect();
    format!("({})", parts.join(", "))
}

/// Reads a numeric variable as f64; a variable of another type (text, compound, ...) is an
/// error naming it and its type.
pub(super) fn read_f64(path: &Path, v: &netcdf::Variable<'_>) -> Result<Vec<f64>, NetcdfError> {
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

pub(super) fn read_spatial(
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

/// All dimensions of `v` (name, length) in file order.
pub(super) fn all_dims(v: &netcdf::Variable<'_>) -> Vec<(String, usize)> {
    v.dimensions().iter().map(|d| (d.name(), d.len())).collect()
}

/// `d` without a leading `time`/`t`/`Time` dimension of length 1.
pub(super) fn without_unit_time(d: &[(String, usize)]) -> &[(String, usize)] {
    match d.first() {
        Some((n, 1)) if d.len() > 1 && matches!(n.as_str(), "time" | "t" | "Time") => &d[1..],
        _ => d,
    }
}

/// A string attribute of `v`, looked up by listing (asking HDF5 for a missing attribute makes
/// it print errors).
pub(super) fn str_attr(v: &netcdf::Variable<'_>, name: &str) -> Option<String> {
    v.attributes()
        .find(|a| a.name() == name)
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok())
}

/// The variable `name` of `file` (read from `path`); its absence is an error naming it.
pub(super) fn required<'f>(
    path: &Path,
    file: &'f netcdf::File,
    name: &str,
) -> Result<netcdf::Variable<'f>, NetcdfError> {
    file.variable(name)
        .ok_or_else(|| NetcdfError::MissingVariable {
            path: path.to_path_buf(),
            var: name.into(),
        })
}

/// Reads one variable as `f64` with its dimensions (name, length).
pub fn read_field(path: &Path, name: &str) -> Result<(Dims, Vec<f64>), NetcdfError> {
    let file = netcdf::open(path).map_err(nc_err(path))?;
    let v = required(path, &file, name)?;
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
    let v = required(path, &file, name)?;
    Ok(fill_of(&v))
}
