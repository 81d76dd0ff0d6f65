//! The library's options and parameters from Python values, and the queries about them.
//!
//! Owns the parsing of the participation, redistribution and strength-law names, of the
//! `ItdParams` overrides (the library's parser) and of the C_f argument (number, nodes or
//! table file), gathered for `strength` in [`StrengthArgs`]; and the module functions that
//! list them: category bounds, C_f presets, C_f table files, parameter names, units and
//! CICE defaults.

use std::path::PathBuf;
use std::sync::Arc;

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use pressridge::io::itd_netcdf::read_cf_table;
use pressridge::itd::{
    CategoryBounds, Cf, ItdParams, RidgeStepOptions, StrengthOptions, category_bounds,
    details::{
        CfPreset, CfTable, MuRdgTable, NamedParams, Participation, Redistribution, StrengthFormula,
    },
};

use crate::arrays::Pair;
use crate::errors::{BindError, detached, file_missing, value_err};

/// `names` as `"a" or "b"` for messages.
fn quoted_names<T: Copy>(all: &[T], name: fn(T) -> &'static str) -> String {
    all.iter()
        .map(|&x| format!("\"{}\"", name(x)))
        .collect::<Vec<_>>()
        .join(" or ")
}

/// The option value called `name` (the library's `from_name`), or a `ValueError` naming
/// `what` and listing the valid names with `sources` (who each is from).
fn by_name<T: Copy>(
    what: &str,
    name: &str,
    from_name: fn(&str) -> Option<T>,
    all: &[T],
    names: fn(T) -> &'static str,
    sources: &str,
) -> PyResult<T> {
    from_name(name).ok_or_else(|| {
        value_err(format!(
            "unknown {what} `{name}`; use {} ({sources})",
            quoted_names(all, names)
        ))
        .into()
    })
}

pub(crate) fn participation(name: &str) -> PyResult<Participation> {
    by_name(
        "participation",
        name,
        Participation::from_name,
        &Participation::ALL,
        Participation::name,
        "exponential: Lipscomb et al. 2007, CICE default; thorndike: Thorndike et al. 1975",
    )
}

/// The redistribution called `name`; `"table"` is Lipscomb's exponential with μ_rdg per
/// category thickness from the nodes `mu_rdg` ((thickness m, μ_rdg m^½), as
/// `pressridge.ridge_step(mu_rdg_table=)` resolves them).
pub(crate) fn redistribution(
    name: &str,
    mu_rdg: Option<(Vec<f64>, Vec<f64>)>,
) -> PyResult<Redistribution> {
    match (name, mu_rdg) {
        ("table", Some((h, m))) => Ok(Redistribution::Table(
            MuRdgTable::new(&h, &m).map_err(value_err)?,
        )),
        ("table", None) => Err(value_err(
            "redistribution=\"table\" needs mu_rdg_table=: a ridging table file with `mu_rdg` \
             or (thickness_m, mu_rdg) node arrays",
        )
        .into()),
        (_, Some(_)) => {
            Err(value_err("mu_rdg_table is used with redistribution=\"table\" only").into())
        }
        (name, None) => by_name(
            "redistribution",
            name,
            Redistribution::from_name,
            &Redistribution::ALL,
            |r| r.name(),
            "exponential: Lipscomb et al. 2007, CICE default; uniform: Hibler 1980; table: \
             the exponential with mu_rdg from mu_rdg_table=",
        ),
    }
}

/// The μ_rdg nodes (thickness m, μ_rdg m^½) of a ridging table file at the friction pair
/// `friction` (default 1.0, 0.6), for `redistribution="table"`.
#[pyfunction]
#[pyo3(signature = (path, friction = None))]
pub(crate) fn mu_rdg_table_nodes(
    py: Python<'_>,
    path: PathBuf,
    friction: Option<(f64, f64)>,
) -> PyResult<(Vec<f64>, Vec<f64>)> {
    let t = detached(py, || {
        file_missing(&path)?;
        pressridge::io::itd_netcdf::read_mu_rdg_table_at_friction(&path, friction)
            .map_err(BindError::from)
    })?;
    Ok((t.thickness().to_vec(), t.values().to_vec()))
}

pub(crate) fn law(name: &str) -> PyResult<StrengthFormula> {
    by_name(
        "strength law",
        name,
        StrengthFormula::from_name,
        &StrengthFormula::ALL,
        StrengthFormula::name,
        "rothrock: Rothrock 1975, CICE default; hibler: Hibler 1979",
    )
}

/// CICE's defaults with the `(name, value)` overrides (the library's parser,
/// [`NamedParams::from_pairs`]; an unknown name is answered with the closest valid one).
pub(crate) fn itd_params(params: Vec<(String, f64)>) -> PyResult<ItdParams> {
    Ok(ItdParams::from_pairs(params).map_err(BindError::from)?)
}

/// Raises the library's error ([`NamedParams::check_name`]: the closest valid name and all)
/// when `name` is not a parameter of `ItdParams`, or with `ridge_step` not a constant of the
/// complete step (`RidgeStepOptions`: the `ItdParams` and `RidgeStepParams` names).
/// `keyword`: the name was a keyword of the call, so the message says "unknown keyword or
/// parameter".
#[pyfunction]
#[pyo3(signature = (name, ridge_step = false, keyword = true))]
pub(crate) fn check_param_name(name: &str, ridge_step: bool, keyword: bool) -> PyResult<()> {
    let checked = if ridge_step {
        RidgeStepOptions::check_name(name)
    } else {
        ItdParams::check_name(name)
    };
    match checked {
        Ok(_) => Ok(()),
        Err(e) if keyword => Err(BindError::from(e).into()),
        Err(e) => Err(value_err(e).into()),
    }
}

/// The frictional factor from the normalised Python argument: a number, node arrays, a
/// C_f-table file, or a lookup table object's set.
pub(crate) fn cf_from(
    py: Python<'_>,
    cf_value: Option<f64>,
    cf_nodes: Option<(Vec<f64>, Vec<f64>)>,
    cf_file: Option<PathBuf>,
) -> PyResult<Cf> {
    match (cf_value, cf_nodes, cf_file) {
        (Some(v), None, None) => Ok(Cf::Constant(v)),
        (None, Some((h, c)), None) => {
            Ok(Cf::Table(Arc::new(CfTable::new(h, c).map_err(value_err)?)))
        }
        (None, None, Some(path)) => {
            let t = detached(py, || {
                file_missing(&path)?;
                read_cf_table(&path).map_err(BindError::from)
            })?;
            Ok(Cf::Table(Arc::new(t)))
        }
        (None, None, None) => Ok(Cf::default()),
        _ => Err(value_err("give C_f one way only").into()),
    }
}

/// The options of `strength` as `pressridge.strength` passes them: one dict with these
/// keys (the normalised `pressridge.StrengthOptions`), instead of seven positional
/// arguments.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub(crate) struct StrengthArgs {
    /// Participation function by name.
    participation: String,
    /// Redistribution by name.
    redistribution: String,
    /// With `"table"`: the μ_rdg nodes (thickness m, μ_rdg m^½).
    mu_rdg_nodes: Option<(Vec<f64>, Vec<f64>)>,
    /// Strength law by name.
    law: String,
    /// C_f, at most one of: a constant (dimensionless), (thickness m, C_f) nodes, a C_f
    /// table file; none: the default.
    cf_value: Option<f64>,
    cf_nodes: Option<(Vec<f64>, Vec<f64>)>,
    cf_file: Option<PathBuf>,
    /// `ItdParams` overrides as (name, value) pairs.
    params: Vec<(String, f64)>,
}

impl StrengthArgs {
    /// The library's options (reads a C_f table file, without the GIL).
    pub(crate) fn resolve(self, py: Python<'_>) -> PyResult<StrengthOptions> {
        Ok(StrengthOptions {
            participation: participation(&self.participation)?,
            redistribution: redistribution(&self.redistribution, self.mu_rdg_nodes)?,
            formula: law(&self.law)?,
            cf: cf_from(py, self.cf_value, self.cf_nodes, self.cf_file)?,
            params: itd_params(self.params)?,
        })
    }
}

/// The `ncat + 1` category bounds hin_max (m) of a CICE `kcatbound` option.
#[pyfunction]
#[pyo3(name = "category_bounds", signature = (ncat, scheme = "round_numbers"))]
pub(crate) fn category_bounds_py<'py>(
    py: Python<'py>,
    ncat: usize,
    scheme: &str,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let b = match scheme {
        "original" => CategoryBounds::Original,
        "round_numbers" => CategoryBounds::RoundNumbers,
        "wmo" => CategoryBounds::Wmo,
        "asymptotic" => CategoryBounds::Asymptotic,
        "single" => CategoryBounds::SingleCategory,
        _ => {
            return Err(value_err(format!(
                "unknown category-bounds scheme `{scheme}`; use \"round_numbers\" (CICE kcatbound = 1, default), \"original\" (0), \"wmo\" (2), \"asymptotic\" (3) or \"single\" (-1)"
            ))
            .into());
        }
    };
    let h = category_bounds(&b, ncat).map_err(value_err)?;
    Ok(PyArray1::from_vec(py, h))
}

/// The named constant values of C_f (dimensionless): (name, value) pairs.
#[pyfunction]
pub(crate) fn cf_presets() -> Vec<(&'static str, f64)> {
    vec![
        ("hibler1980", CfPreset::Hibler1980.value()),
        ("flato1991", CfPreset::Flato1991.value()),
        ("cice", CfPreset::Cice.value()),
    ]
}

/// Reads a C_f table file (1-D `thickness` in m and `cf`, as `--cf-table` of the command
/// line); returns its nodes (thickness, cf), validated.
#[pyfunction]
#[pyo3(name = "read_cf_table")]
pub(crate) fn read_cf_table_py<'py>(py: Python<'py>, path: PathBuf) -> PyResult<Pair<'py, f64>> {
    let t = detached(py, || {
        file_missing(&path)?;
        read_cf_table(&path).map_err(BindError::from)
    })?;
    Ok((
        PyArray1::from_slice(py, t.thickness()),
        PyArray1::from_slice(py, t.values()),
    ))
}

/// The C_f of a table file at friction `friction` = (μ, μ_w) (dimensionless; None: the
/// default 1.0, 0.6 for a ridging table, the one curve of a plain table), as
/// `--cf-table FILE --friction MU,MU_W`: returns (thickness, cf, friction of the curve or
/// None when the file does not say).
#[pyfunction]
#[pyo3(signature = (path, friction=None))]
#[allow(clippy::type_complexity)]
pub(crate) fn read_cf_table_at_friction<'py>(
    py: Python<'py>,
    path: PathBuf,
    friction: Option<(f64, f64)>,
) -> PyResult<(
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    Option<(f64, f64)>,
)> {
    let t = detached(py, || {
        file_missing(&path)?;
        pressridge::io::itd_netcdf::read_cf_table_at_friction(&path, friction)
            .map_err(BindError::from)
    })?;
    Ok((
        PyArray1::from_slice(py, t.thickness()),
        PyArray1::from_slice(py, t.values()),
        t.friction(),
    ))
}

/// Names of the parameters that `strength` and `ridge_step` accept as keywords
/// (`ItdParams::NAMES`, the names of `ItdParams::FIELDS`).
#[pyfunction]
pub(crate) fn param_names() -> Vec<&'static str> {
    ItdParams::NAMES.to_vec()
}

/// Every parameter (`ItdParams::FIELDS`, in order): (name, units, description, CICE
/// default).
#[pyfunction]
pub(crate) fn param_meta() -> Vec<(&'static str, &'static str, &'static str, f64)> {
    let d = ItdParams::default();
    ItdParams::FIELDS
        .iter()
        .map(|f| {
            (
                f.name,
                f.units,
                f.description,
                d.get(f.name).expect("a listed parameter"),
            )
        })
        .collect()
}

/// CICE's default value of every parameter (`ItdParams::FIELDS`, in order), as a dict.
#[pyfunction]
pub(crate) fn default_params<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
    let p = ItdParams::default();
    let d = PyDict::new(py);
    for f in ItdParams::FIELDS {
        d.set_item(f.name, p.get(f.name).expect("a listed parameter"))?;
    }
    Ok(d)
}
