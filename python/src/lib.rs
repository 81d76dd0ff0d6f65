//! `pressridge._core`: the compiled half of the Python package `pressridge`.
//!
//! A thin face over the library, like the command line: it converts numpy arrays to
//! `ndarray` views (no copy for C- or F-ordered input), Python values to the library's
//! options, calls the library with the GIL released, and turns the library's errors into
//! `ValueError`/`OSError` with the library's message. No physics lives here. The Python
//! modules `pressridge/__init__.py` and `pressridge/xr.py` hold the documented API; the
//! functions here take already-normalised arguments.
//!
//! The modules, each owning one face of the library (see the header of each file):
//!
//! - `errors`: `BindError`, the library's errors as Python exceptions, and the guard
//!   (`guarded`, `detached`) that catches panics and releases the GIL around library calls;
//! - `arrays`: numpy `(ncat, spatial...)` arrays as `(ncat, ncol)` views, outputs in the
//!   input's layout, shape and alignment checks;
//! - `options`: option names, `ItdParams` overrides and C_f to the library's types, and the
//!   queries about them (category bounds, C_f presets and tables, parameter defaults);
//! - `strength`: `strength` and the thickness-distribution-only `ridge_step`;
//! - `tracers`: the `TracerLayout` class;
//! - `step`: the complete ridging step `ridge_step_full` (snow, tracers, ocean fluxes);
//! - `simulator`: scenes and `simulate`;
//! - `campaigns`: running campaigns and `tabulate`;
//! - `lookup`: the `RidgeLookup` class over a table file.
//!
//! This file registers them in the module `pressridge._core`.

#![warn(missing_docs)]

use pyo3::prelude::*;

mod arrays;
mod campaigns;
mod errors;
mod lookup;
mod options;
mod simulator;
mod step;
mod strength;
mod tracers;

/// The compiled core of the `pressridge` Python package.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    // Names of the category dimension looked for in datasets (one list, shared with the CLI).
    m.add(
        "CATEGORY_DIMS",
        pressridge::io::itd_netcdf::CATEGORY_DIM_NAMES.to_vec(),
    )?;
    // CF metadata of the strength output (units, long_name, standard_name), as the CLI's.
    let sm = pressridge::io::itd_netcdf::STRENGTH_META;
    m.add(
        "STRENGTH_META",
        (sm.units, sm.long_name, sm.standard_name.unwrap_or("")),
    )?;
    m.add_function(wrap_pyfunction!(strength::strength, m)?)?;
    m.add_function(wrap_pyfunction!(strength::layout, m)?)?;
    m.add_function(wrap_pyfunction!(strength::ridge_step, m)?)?;
    m.add_function(wrap_pyfunction!(step::ridge_step_full, m)?)?;
    m.add_function(wrap_pyfunction!(step::step_outputs, m)?)?;
    m.add_function(wrap_pyfunction!(step::step_parameters, m)?)?;
    m.add_class::<tracers::PyTracerLayout>()?;
    m.add_function(wrap_pyfunction!(options::category_bounds_py, m)?)?;
    m.add_function(wrap_pyfunction!(options::param_names, m)?)?;
    m.add_function(wrap_pyfunction!(options::check_param_name, m)?)?;
    m.add_function(wrap_pyfunction!(options::cf_presets, m)?)?;
    m.add_function(wrap_pyfunction!(options::read_cf_table_py, m)?)?;
    m.add_function(wrap_pyfunction!(options::read_cf_table_at_friction, m)?)?;
    m.add_function(wrap_pyfunction!(options::mu_rdg_table_nodes, m)?)?;
    m.add(
        "DEFAULT_FRICTION",
        pressridge::table::tabulate::DEFAULT_FRICTION,
    )?;
    m.add("RAFTING_REACH", pressridge::table::rafting::RAFTING_REACH)?;
    m.add(
        "CF_CLAMPED_MATERIAL_SHARE",
        pressridge::itd::details::CF_CLAMPED_MATERIAL_SHARE,
    )?;
    m.add_function(wrap_pyfunction!(options::default_params, m)?)?;
    m.add_function(wrap_pyfunction!(options::param_meta, m)?)?;
    m.add_function(wrap_pyfunction!(simulator::scene_toml, m)?)?;
    m.add_function(wrap_pyfunction!(simulator::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(simulator::series_units, m)?)?;
    m.add_function(wrap_pyfunction!(campaigns::campaign_local, m)?)?;
    m.add_function(wrap_pyfunction!(campaigns::campaign_prepare, m)?)?;
    m.add_function(wrap_pyfunction!(campaigns::campaign_adopt, m)?)?;
    m.add_function(wrap_pyfunction!(campaigns::campaign_run_planned, m)?)?;
    m.add_function(wrap_pyfunction!(campaigns::tabulate, m)?)?;
    m.add_function(wrap_pyfunction!(campaigns::redistribution, m)?)?;
    m.add_class::<lookup::PyRidgeLookup>()?;
    m.add_function(wrap_pyfunction!(errors::panic_for_test, m)?)?;
    Ok(())
}
