//! Per-cell forcing read from a file: the deformation (`divu`, `shear`; 1/s or CICE
//! history's %/day, converted; a missing `units` refused) for the CICE closing, and the unit-checked per-cell fields
//! ([`read_cell_field`]: the host's closing and opening rates in 1/s, the freezing
//! temperature in °C).

use std::path::Path;

use ndarray::Array1;

use super::vars::{fill_of, is_fill, nc_err, read_spatial};
use super::{ItdGrid, NetcdfError};

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
        // Refused, as the host's rates are (`read_cell_field`): a %/day history field
        // without its attribute taken for 1/s would be wrong by a factor 8.64e6.
        return Err(NetcdfError::Value {
            path: path.to_path_buf(),
            var: v.name(),
            msg: "has no `units` attribute; a strain rate must say its unit: \"s-1\" (1/s) \
                  or CICE history's \"%/day\" (set it, e.g. `ncatted -a units,VAR,c,c,s-1`, \
                  or give the rates instead: --convergence and --shear)"
                .into(),
        });
    };
    if CellUnits::PerSecond.accepts(&units) {
        Ok(RateUnits::PerSecond)
    } else if rate_is_percent_per_day(&units) {
        Ok(RateUnits::PercentPerDay)
    } else {
        Err(NetcdfError::Units {
            path: path.to_path_buf(),
            var: v.name(),
            units,
            extra: String::new(),
        })
    }
}

/// An optional field on the spatial dimensions.
type SpatialField = Option<Array1<f64>>;

/// `divu` (1/s) and the ridging shear term (1/s) from the file, converted from CICE's %/day
/// where the units say so.
pub(super) fn read_deformation(
    path: &Path,
    file: &netcdf::File,
    spatial: &[(String, usize)],
) -> Result<(SpatialField, SpatialField), NetcdfError> {
    use crate::itd::details::{deformation_terms, percent_per_day_to_per_second};
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
