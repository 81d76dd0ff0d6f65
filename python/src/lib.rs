//! `pressridge._core`: the compiled half of the Python package `pressridge`.
//!
//! A thin face over the library, like the command line: it converts numpy arrays to
//! `ndarray` views (no copy for C- or F-ordered input), Python values to the library's
//! options, calls the library with the GIL released, and turns the library's errors into
//! `ValueError`/`OSError` with the library's message. No physics lives here. The Python
//! modules `pressridge/__init__.py` and `pressridge/xr.py` hold the documented API; the
//! functions here take already-normalised arguments.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use ndarray::{
    ArrayBase, ArrayView, ArrayViewD, ArrayViewMut, ArrayViewMut1, ArrayViewMut2, ArrayViewMut3,
    ArrayViewMutD, CowArray, Dimension, Ix1, Ix2, Ix3, IxDyn, RawData,
};
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use pressridge::campaign::{
    CampaignError, CampaignSpec, PlannedRun, Progress, adopt_records, prepare_campaign,
    run_campaign, run_planned,
};
use pressridge::io::IoError;
use pressridge::io::itd_netcdf::{NetcdfError, read_cf_table};
use pressridge::io::table_netcdf::write_ridge_table;
use pressridge::itd::{
    BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, CategoryBounds, Cf, CfPreset,
    CfTable, CiceTracerFlags, ItdError, ItdParams, Participation, Redistribution, RidgeOptions,
    RidgeRatesMut, RidgeStepOptions, RidgeStepParams, SaltFlux, StepBatchMut, StrengthFormula,
    StrengthOptions, TracerBase, TracerField, TracerLayout, TracerRole, category_bounds,
    ridge_batch_masked, ridge_step_batch, strength_batch_masked,
};
use pressridge::scene::{Scene, SceneError, SceneLoadError};
use pressridge::simulation;
use pressridge::simulation::series_columns;
use pressridge::table::campaigns::{TabulateCampaignsError, TabulateOptions, tabulate_campaigns};
use pressridge::table::lookup::{LookupError, RidgeLookup};
use pressridge::table::tabulate::fit_warnings;

// ---------------------------------------------------------------------------------------
// Errors

/// An error on its way to Python; `Send`, so it can leave a GIL-free section.
#[derive(Debug)]
enum BindError {
    Value(String),
    Os(String),
    NotFound(String),
    Internal(String),
    Interrupted(PyErr),
}

impl From<BindError> for PyErr {
    fn from(e: BindError) -> PyErr {
        match e {
            BindError::Value(m) => PyValueError::new_err(m),
            BindError::Os(m) => PyOSError::new_err(m),
            BindError::NotFound(m) => PyFileNotFoundError::new_err(m),
            BindError::Internal(m) => PyRuntimeError::new_err(format!(
                "pressridge internal error (a bug: please report it): {m}"
            )),
            BindError::Interrupted(e) => e,
        }
    }
}

fn value_err(m: impl ToString) -> BindError {
    BindError::Value(m.to_string())
}

impl From<IoError> for BindError {
    fn from(e: IoError) -> Self {
        match &e {
            IoError::Os { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
                BindError::NotFound(e.to_string())
            }
            IoError::Os { .. } => BindError::Os(e.to_string()),
            IoError::Format { .. } => BindError::Value(e.to_string()),
        }
    }
}

impl From<NetcdfError> for BindError {
    fn from(e: NetcdfError) -> Self {
        match &e {
            NetcdfError::Netcdf { .. } => BindError::Os(e.to_string()),
            _ => BindError::Value(e.to_string()),
        }
    }
}

impl From<CampaignError> for BindError {
    fn from(e: CampaignError) -> Self {
        match e {
            CampaignError::Io(io) => io.into(),
            other => BindError::Value(other.to_string()),
        }
    }
}

impl From<SceneLoadError> for BindError {
    fn from(e: SceneLoadError) -> Self {
        match e {
            SceneLoadError::Read(io) => io.into(),
            other => BindError::Value(other.to_string()),
        }
    }
}

impl From<SceneError> for BindError {
    fn from(e: SceneError) -> Self {
        BindError::Value(e.to_string())
    }
}

/// Runs `f`, turning a panic into [`BindError::Internal`] so that none reaches Python.
fn guarded<T>(f: impl FnOnce() -> Result<T, BindError>) -> Result<T, BindError> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => {
            let msg = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "panic".into());
            Err(BindError::Internal(msg))
        }
    }
}

/// Runs `f` without the GIL and without letting a panic out.
fn detached<T: Send>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, BindError> + Send,
) -> PyResult<T> {
    py.detach(|| guarded(f)).map_err(PyErr::from)
}

fn file_missing(path: &Path) -> Result<(), BindError> {
    if path.exists() {
        Ok(())
    } else {
        Err(BindError::NotFound(format!(
            "{}: No such file or directory",
            path.display()
        )))
    }
}

/// Two 1-D arrays: node pairs, or lookup values with their clamp flags.
type Pair<'py, T> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<T>>);

// ---------------------------------------------------------------------------------------
// Arrays: (ncat, spatial...) numpy arrays as (ncat, ncol) views

/// How the spatial axes of an array are flattened into columns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Order {
    /// Last spatial axis fastest (C order).
    C,
    /// First spatial axis fastest (Fortran order): the spatial axes reversed, then C order.
    F,
}

/// Merges the axes `first..` of `a` into one, in row-major order (the last axis fastest),
/// without copying; `None` when the strides do not allow it. An array with no axis at
/// `first` gets one of length 1.
fn merge_tail<S: RawData>(a: ArrayBase<S, IxDyn>, first: usize) -> Option<ArrayBase<S, IxDyn>> {
    let n = a.ndim();
    if n <= first {
        return Some(a.insert_axis(ndarray::Axis(first)));
    }
    let mut a = a;
    for k in first..n - 1 {
        if !a.merge_axes(ndarray::Axis(k), ndarray::Axis(k + 1)) {
            return None;
        }
    }
    for _ in first..n - 1 {
        a = a.index_axis_move(ndarray::Axis(first), 0);
    }
    Some(a)
}

/// The axes of `a` (ndim axes, the first `lead` kept in place) in the order that flattens the
/// others in `order`.
fn flatten_perm(ndim: usize, lead: usize, order: Order) -> IxDyn {
    let mut p: Vec<usize> = (0..ndim).collect();
    if order == Order::F && ndim > lead {
        p[lead..].reverse();
    }
    IxDyn(&p)
}

/// `a` with the axes after the first `lead` flattened in `order`: a view when the layout
/// allows, else a copy.
fn flatten<'a, T: Clone, D: Dimension>(
    a: ArrayView<'a, T, IxDyn>,
    lead: usize,
    order: Order,
) -> CowArray<'a, T, D> {
    let perm = flatten_perm(a.ndim(), lead, order);
    let p = a.permuted_axes(perm);
    if let Some(m) = merge_tail(p.clone(), lead) {
        return CowArray::from(m.into_dimensionality::<D>().expect("merged rank"));
    }
    let mut shape: Vec<usize> = p.shape()[..lead].to_vec();
    shape.push(p.shape()[lead..].iter().product());
    let owned = p
        .to_shape((IxDyn(&shape), ndarray::Order::RowMajor))
        .expect("element count is unchanged")
        .into_owned();
    CowArray::from(owned.into_dimensionality::<D>().expect("merged rank"))
}

/// `a` (ncat, spatial...) as (ncat, ncol), the spatial axes flattened in `order`.
fn columns<'a>(a: ArrayViewD<'a, f64>, order: Order) -> CowArray<'a, f64, Ix2> {
    flatten(a, 1, order)
}

/// A spatial array (no category axis) flattened in `order`.
fn flat<'a>(a: ArrayViewD<'a, f64>, order: Order) -> CowArray<'a, f64, Ix1> {
    flatten(a, 0, order)
}

fn flat_bool<'a>(a: ArrayViewD<'a, bool>, order: Order) -> CowArray<'a, bool, Ix1> {
    flatten(a, 0, order)
}

/// The flattening order that makes `aicen` a view: C if its spatial axes merge in C order,
/// else F if they merge in Fortran order, else C (and a copy).
fn choose_order(a: &ArrayViewD<'_, f64>) -> Order {
    if a.ndim() <= 2 || columns(a.view(), Order::C).is_view() {
        Order::C
    } else if columns(a.view(), Order::F).is_view() {
        Order::F
    } else {
        Order::C
    }
}

/// A new numpy array of `shape` laid out so that flattening its spatial axes in `order` is a
/// view (C order for [`Order::C`], Fortran order for [`Order::F`]).
fn new_array<'py>(py: Python<'py>, shape: &[usize], order: Order) -> Bound<'py, PyArrayDyn<f64>> {
    PyArrayDyn::<f64>::zeros(py, IxDyn(shape), order == Order::F)
}

/// A freshly made `out` with the axes after the first `lead` flattened in `order`.
fn flatten_mut<'a, D: Dimension>(
    a: ArrayViewMutD<'a, f64>,
    lead: usize,
    order: Order,
) -> ArrayViewMut<'a, f64, D> {
    let perm = flatten_perm(a.ndim(), lead, order);
    let p = a.permuted_axes(perm);
    merge_tail(p, lead)
        .expect("a freshly made array in the chosen order flattens without a copy")
        .into_dimensionality::<D>()
        .expect("merged rank")
}

fn columns_mut<'a>(a: ArrayViewMutD<'a, f64>, order: Order) -> ArrayViewMut2<'a, f64> {
    flatten_mut(a, 1, order)
}

fn flat_mut<'a>(a: ArrayViewMutD<'a, f64>, order: Order) -> ArrayViewMut1<'a, f64> {
    flatten_mut(a, 0, order)
}

/// The spatial index of flat column `c` (flattened in `order`), as `(i, j, ...)`.
fn spatial_index(spatial: &[usize], order: Order, c: usize) -> String {
    let mut dims: Vec<usize> = spatial.to_vec();
    if order == Order::F {
        dims.reverse();
    }
    let mut idx = vec![0; dims.len()];
    let mut rem = c;
    for k in (0..dims.len()).rev() {
        idx[k] = rem % dims[k];
        rem /= dims[k];
    }
    if order == Order::F {
        idx.reverse();
    }
    let parts: Vec<String> = idx.iter().map(|i| i.to_string()).collect();
    if parts.len() == 1 {
        format!("({},)", parts[0])
    } else {
        format!("({})", parts.join(", "))
    }
}

/// A physics error with the column located by its index in the caller's spatial axes.
fn itd_err(e: ItdError, spatial: &[usize], order: Order) -> BindError {
    match e {
        ItdError::Column { column, source } => {
            if spatial.is_empty() {
                value_err(source)
            } else {
                value_err(format!(
                    "at spatial index {}: {source}",
                    spatial_index(spatial, order, column)
                ))
            }
        }
        other => value_err(other),
    }
}

/// Refuses an array whose data are not aligned for its element type (numpy allows such
/// views, e.g. arrays unpickled from a byte buffer by dask.distributed): reading it as an
/// ndarray view would be undefined behaviour. The Python wrappers pass aligned copies.
fn check_aligned<T: numpy::Element, D: ndarray::Dimension>(
    var: &str,
    x: &numpy::PyReadonlyArray<'_, T, D>,
) -> PyResult<()> {
    if (x.data() as usize) % std::mem::align_of::<T>() != 0 {
        return Err(value_err(format!(
            "{var}: the array's data are not aligned for its dtype; pass an aligned copy \
             (numpy.require(x, requirements=\"A\"))"
        ))
        .into());
    }
    Ok(())
}

/// [`check_aligned`], then [`check_shape`].
fn check_array<T: numpy::Element>(
    var: &str,
    x: &PyReadonlyArrayDyn<'_, T>,
    expected: &[usize],
    what: &str,
) -> PyResult<()> {
    check_aligned(var, x)?;
    check_shape(var, x.shape(), expected, what)
}

fn check_shape(var: &str, found: &[usize], expected: &[usize], what: &str) -> PyResult<()> {
    if found != expected {
        return Err(value_err(format!(
            "{var} has shape {}, expected {what} {}",
            shape_str(found),
            shape_str(expected)
        ))
        .into());
    }
    Ok(())
}

fn shape_str(s: &[usize]) -> String {
    match s.len() {
        1 => format!("({},)", s[0]),
        _ => format!(
            "({})",
            s.iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Checks aicen/vicen and returns the spatial shape.
fn category_shapes(
    aicen: &PyReadonlyArrayDyn<'_, f64>,
    vicen: &PyReadonlyArrayDyn<'_, f64>,
) -> PyResult<Vec<usize>> {
    check_aligned("aicen", aicen)?;
    let shape = aicen.shape().to_vec();
    if shape.is_empty() || shape[0] == 0 {
        return Err(value_err(format!(
            "aicen has shape {}; it needs the category axis first, of length >= 1, then any spatial axes",
            shape_str(&shape)
        ))
        .into());
    }
    check_array("vicen", vicen, &shape, "the shape of aicen")?;
    Ok(shape[1..].to_vec())
}

// ---------------------------------------------------------------------------------------
// Options

/// `names` as `"a" or "b"` for messages.
fn quoted_names<T: Copy>(all: &[T], name: fn(T) -> &'static str) -> String {
    all.iter()
        .map(|&x| format!("\"{}\"", name(x)))
        .collect::<Vec<_>>()
        .join(" or ")
}

fn participation(name: &str) -> PyResult<Participation> {
    Participation::from_name(name).ok_or_else(|| {
        value_err(format!(
            "unknown participation `{name}`; use {} (exponential: Lipscomb et al. 2007, CICE default; thorndike: Thorndike et al. 1975)",
            quoted_names(&Participation::ALL, Participation::name)
        ))
        .into()
    })
}

fn redistribution(name: &str) -> PyResult<Redistribution> {
    Redistribution::from_name(name).ok_or_else(|| {
        value_err(format!(
            "unknown redistribution `{name}`; use {} (exponential: Lipscomb et al. 2007, CICE default; uniform: Hibler 1980)",
            quoted_names(&Redistribution::ALL, Redistribution::name)
        ))
        .into()
    })
}

fn law(name: &str) -> PyResult<StrengthFormula> {
    StrengthFormula::from_name(name).ok_or_else(|| {
        value_err(format!(
            "unknown strength law `{name}`; use {} (rothrock: Rothrock 1975, CICE default; hibler: Hibler 1979)",
            quoted_names(&StrengthFormula::ALL, StrengthFormula::name)
        ))
        .into()
    })
}

/// CICE's defaults with the `(name, value)` overrides ([`ItdParams::from_pairs`]; an
/// unknown name is answered with the closest valid one).
fn itd_params(params: Vec<(String, f64)>) -> PyResult<ItdParams> {
    Ok(ItdParams::from_pairs(params).map_err(value_err)?)
}

/// The frictional factor from the normalised Python argument: a number, node arrays, a
/// C_f-table file, or a lookup table object's set.
fn cf_from(
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

// ---------------------------------------------------------------------------------------
// Strength and ridging

/// Ice strength P (N/m); see `pressridge.strength`. Returns (P, columns with a clamped C_f).
#[pyfunction]
#[pyo3(signature = (aicen, vicen, aice0, valid, participation_name, redistribution_name, law_name, cf_value, cf_nodes, cf_file, params))]
#[allow(clippy::too_many_arguments)]
fn strength<'py>(
    py: Python<'py>,
    aicen: PyReadonlyArrayDyn<'py, f64>,
    vicen: PyReadonlyArrayDyn<'py, f64>,
    aice0: Option<PyReadonlyArrayDyn<'py, f64>>,
    valid: Option<PyReadonlyArrayDyn<'py, bool>>,
    participation_name: &str,
    redistribution_name: &str,
    law_name: &str,
    cf_value: Option<f64>,
    cf_nodes: Option<(Vec<f64>, Vec<f64>)>,
    cf_file: Option<PathBuf>,
    params: Vec<(String, f64)>,
) -> PyResult<(Bound<'py, PyArrayDyn<f64>>, usize)> {
    let spatial = category_shapes(&aicen, &vicen)?;
    if let Some(a0) = &aice0 {
        check_array("aice0", a0, &spatial, "the spatial shape of aicen")?;
    }
    if let Some(v) = &valid {
        check_array("valid", v, &spatial, "the spatial shape of aicen")?;
    }
    let opts = StrengthOptions {
        participation: participation(participation_name)?,
        redistribution: redistribution(redistribution_name)?,
        formula: law(law_name)?,
        cf: cf_from(py, cf_value, cf_nodes, cf_file)?,
        params: itd_params(params)?,
    };
    let a = aicen.as_array();
    let order = choose_order(&a);
    let out = new_array(py, &spatial, order);
    let mut out_rw = out.readwrite();
    let out_view = flat_mut(out_rw.as_array_mut(), order);
    let a2 = columns(a, order);
    let v2 = columns(vicen.as_array(), order);
    let a0 = aice0.as_ref().map(|x| flat(x.as_array(), order));
    let ok = valid.as_ref().map(|x| flat_bool(x.as_array(), order));
    let summary = detached(py, || {
        strength_batch_masked(
            a2.view(),
            v2.view(),
            a0.as_ref().map(|x| x.view()),
            ok.as_ref().map(|x| x.view()),
            f64::NAN,
            &opts,
            out_view,
        )
        .map_err(|e| itd_err(e, &spatial, order))
    })?;
    drop(out_rw);
    Ok((out, summary.cf_clamped_columns))
}

/// Whether `aicen` passes to the batch routines as a view ("view") or is copied ("copy"),
/// and the flattening order; for tests of the no-copy promise.
#[pyfunction]
#[pyo3(name = "_layout")]
fn layout(aicen: PyReadonlyArrayDyn<'_, f64>) -> PyResult<(String, String)> {
    check_aligned("aicen", &aicen)?;
    let a = aicen.as_array();
    let order = choose_order(&a);
    let kind = if a.ndim() == 0 || columns(a.view(), order).is_view() {
        "view"
    } else {
        "copy"
    };
    Ok((kind.into(), format!("{order:?}")))
}

type RidgeOut<'py> = (
    Bound<'py, PyArrayDyn<f64>>,
    Bound<'py, PyArrayDyn<f64>>,
    Bound<'py, PyArrayDyn<f64>>,
    [Bound<'py, PyArrayDyn<f64>>; 5],
);

/// One ridging step; see `pressridge.ridge_step`. Returns new arrays (aicen, vicen, aice0,
/// [closing, opening, dardg1dt, dardg2dt, dvirdgdt]); the inputs are not modified.
#[pyfunction]
#[pyo3(signature = (aicen, vicen, aice0, hin_max, convergence, shear, dt, valid, participation_name, redistribution_name, params))]
#[allow(clippy::too_many_arguments)]
fn ridge_step<'py>(
    py: Python<'py>,
    aicen: PyReadonlyArrayDyn<'py, f64>,
    vicen: PyReadonlyArrayDyn<'py, f64>,
    aice0: Option<PyReadonlyArrayDyn<'py, f64>>,
    hin_max: Option<Vec<f64>>,
    convergence: PyReadonlyArrayDyn<'py, f64>,
    shear: PyReadonlyArrayDyn<'py, f64>,
    dt: f64,
    valid: Option<PyReadonlyArrayDyn<'py, bool>>,
    participation_name: &str,
    redistribution_name: &str,
    params: Vec<(String, f64)>,
) -> PyResult<RidgeOut<'py>> {
    let spatial = category_shapes(&aicen, &vicen)?;
    let full = aicen.shape().to_vec();
    let ncat = full[0];
    for (var, x) in [("convergence", &convergence), ("shear", &shear)] {
        check_array(var, x, &spatial, "the spatial shape of aicen")?;
    }
    if let Some(a0) = &aice0 {
        check_array("aice0", a0, &spatial, "the spatial shape of aicen")?;
    }
    if let Some(v) = &valid {
        check_array("valid", v, &spatial, "the spatial shape of aicen")?;
    }
    let opts = RidgeOptions {
        participation: participation(participation_name)?,
        redistribution: redistribution(redistribution_name)?,
        params: itd_params(params)?,
    };
    let hin_max = match hin_max {
        Some(h) => h,
        None => category_bounds(&CategoryBounds::RoundNumbers, ncat).map_err(value_err)?,
    };
    let a = aicen.as_array();
    let order = choose_order(&a);
    // Outputs in the input's layout; the step works on them in place.
    let a_out = new_array(py, &full, order);
    let v_out = new_array(py, &full, order);
    let a0_out = new_array(py, &spatial, order);
    let rates: [Bound<'py, PyArrayDyn<f64>>; 5] =
        std::array::from_fn(|_| new_array(py, &spatial, order));
    {
        let mut a_rw = a_out.readwrite();
        let mut v_rw = v_out.readwrite();
        let mut a0_rw = a0_out.readwrite();
        let mut a_cols = columns_mut(a_rw.as_array_mut(), order);
        let mut v_cols = columns_mut(v_rw.as_array_mut(), order);
        let mut a0_flat = flat_mut(a0_rw.as_array_mut(), order);
        a_cols.assign(&columns(a, order));
        v_cols.assign(&columns(vicen.as_array(), order));
        match &aice0 {
            Some(x) => a0_flat.assign(&flat(x.as_array(), order)),
            // The open water the categories leave, none when they fill the cell (round-off
            // or advection), as the strength routine's default.
            None => {
                for (c, x) in a0_flat.iter_mut().enumerate() {
                    *x = f64::max(1.0 - a_cols.column(c).sum(), 0.0);
                }
            }
        }
        let conv = flat(convergence.as_array(), order);
        let shr = flat(shear.as_array(), order);
        let ok = valid.as_ref().map(|x| flat_bool(x.as_array(), order));
        let mut r_rw: Vec<_> = rates.iter().map(|r| r.readwrite()).collect();
        let mut r_views: Vec<ArrayViewMut1<'_, f64>> = r_rw
            .iter_mut()
            .map(|r| flat_mut(r.as_array_mut(), order))
            .collect();
        let dvirdgdt = r_views.pop().expect("five rates");
        let dardg2dt = r_views.pop().expect("five rates");
        let dardg1dt = r_views.pop().expect("five rates");
        let opening = r_views.pop().expect("five rates");
        let closing = r_views.pop().expect("five rates");
        detached(py, || {
            ridge_batch_masked(
                a_cols,
                v_cols,
                a0_flat.view_mut(),
                &hin_max,
                conv.view(),
                shr.view(),
                ok.as_ref().map(|x| x.view()),
                f64::NAN,
                dt,
                &opts,
                RidgeRatesMut {
                    closing,
                    opening,
                    dardg1dt,
                    dardg2dt,
                    dvirdgdt,
                },
            )
            .map_err(|e| itd_err(e, &spatial, order))?;
            // Masked columns keep their (missing) values, like their rates.
            if let Some(ok) = &ok {
                for (x, &good) in a0_flat.iter_mut().zip(ok.iter()) {
                    if !good {
                        *x = f64::NAN;
                    }
                }
            }
            Ok(())
        })?;
    }
    Ok((a_out, v_out, a0_out, rates))
}

// ---------------------------------------------------------------------------------------
// The complete ridging step (snow, tracers, ocean fluxes)

/// A tracer layout: which tracers each thickness category carries, in what order and on
/// what base (the Rust ``pressridge::itd::TracerLayout``, not a copy of it).
///
/// Make one with ``TracerLayout.cice(nilyr, nslyr, *, age=False, first_year=False,
/// level_ice=False, ponds=False)``: CICE/Icepack's order ``Tsfc``, ``qice(nilyr)``,
/// ``qsno(nslyr)``, ``sice(nilyr)``, then ``iage``, ``FY``, ``alvl``, ``vlvl``, ``apnd``,
/// ``hpnd``, ``ipnd`` as the flags (Icepack's ``tr_iage``, ``tr_FY``, ``tr_lvl``,
/// ``tr_pond_lvl``) select; ``ponds`` needs ``level_ice``. Or with
/// ``TracerLayout.from_fields(fields)`` for any layout the Rust ``TracerLayout::new``
/// accepts, or ``TracerLayout.detect(names)`` from CICE restart variable names. Units:
/// ``Tsfc`` degC, enthalpies J m-3 (negative), salinity ppt, age s, fractions 1, pond depth
/// and lid m.
///
/// Attributes and methods: ``ntrcr``, ``nilyr``, ``nslyr``, ``flags``, ``fields()`` (name,
/// first index, levels, base, strata, units, long name), ``spec()`` (the fields as
/// ``from_fields`` takes them), ``field(name)`` (first index, levels), ``names`` (per tracer,
/// the CICE restart variable name: ``Tsfcn``, ``qice001``...), ``units``, ``long_names``,
/// ``trcr_depend()`` (Icepack's).
#[pyclass(frozen, name = "TracerLayout", module = "pressridge._core")]
struct PyTracerLayout {
    inner: Arc<TracerLayout>,
}

/// The optional CICE tracers a layout carries, from its fields' roles.
fn flags_of(l: &TracerLayout) -> CiceTracerFlags {
    let has = |r: TracerRole| l.fields().iter().any(|f| f.role == r);
    CiceTracerFlags {
        age: has(TracerRole::Age),
        first_year: has(TracerRole::FirstYear),
        level_ice: has(TracerRole::LevelArea),
        ponds: has(TracerRole::PondArea),
    }
}

/// One field of `from_fields`: a dict (`name`, `levels`, `base`, `strata`, `role`) or a
/// sequence in that order; missing items default to Icepack's for the role, the role to the
/// one whose Icepack name is `name` (else `other`).
fn field_from_py(i: usize, item: &Bound<'_, PyAny>) -> Result<TracerField, BindError> {
    const KEYS: [&str; 5] = ["name", "levels", "base", "strata", "role"];
    let mut got: [Option<Bound<'_, PyAny>>; 5] = Default::default();
    let at = |what: &str| format!("fields[{i}]{what}");
    if let Ok(d) = item.cast::<PyDict>() {
        for (k, v) in d.iter() {
            let k: String = k
                .extract()
                .map_err(|_| value_err(at(": keys must be strings")))?;
            let Some(pos) = KEYS.iter().position(|x| *x == k) else {
                return Err(value_err(format!(
                    "{}: unknown key `{k}`; the keys are {}",
                    at(""),
                    KEYS.join(", ")
                )));
            };
            got[pos] = Some(v);
        }
    } else if let Ok(seq) = item.extract::<Vec<Bound<'_, PyAny>>>()
        && !item.is_instance_of::<pyo3::types::PyString>()
    {
        if seq.is_empty() || seq.len() > 5 {
            return Err(value_err(at(&format!(
                ": a sequence of 1 to 5 items ({}), got {}",
                KEYS.join(", "),
                seq.len()
            ))));
        }
        for (k, v) in seq.into_iter().enumerate() {
            got[k] = Some(v);
        }
    } else {
        return Err(value_err(at(&format!(
            ": a dict with keys {} or a sequence in that order, got {}",
            KEYS.join(", "),
            item.get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_default()
        ))));
    }
    let name: String = match &got[0] {
        Some(v) => v
            .extract()
            .map_err(|_| value_err(at(": `name` must be a string")))?,
        None => return Err(value_err(at(": `name` is missing"))),
    };
    let at = |what: &str| format!("fields[{i}] (`{name}`): {what}");
    let role = match &got[4] {
        Some(v) if !v.is_none() => {
            let r: String = v
                .extract()
                .map_err(|_| value_err(at("`role` must be a string")))?;
            TracerRole::from_name(&r).ok_or_else(|| {
                let all: Vec<&str> = TracerRole::ALL.iter().map(|r| r.name()).collect();
                value_err(at(&format!(
                    "unknown role `{r}`; one of {}",
                    all.join(", ")
                )))
            })?
        }
        _ => TracerRole::ALL
            .into_iter()
            .find(|r| r.icepack().is_some_and(|(n, _, _)| n == name))
            .unwrap_or(TracerRole::Other),
    };
    let levels: usize = match &got[1] {
        Some(v) if !v.is_none() => {
            let n: i64 = v
                .extract()
                .map_err(|_| value_err(at("`levels` must be an integer")))?;
            if !(1..=1 << 20).contains(&n) {
                return Err(value_err(at(&format!("levels = {n}: must be at least 1"))));
            }
            n as usize
        }
        _ => 1,
    };
    let base = match &got[2] {
        Some(v) if !v.is_none() => {
            let b: String = v
                .extract()
                .map_err(|_| value_err(at("`base` must be a string")))?;
            TracerBase::from_name(&b).ok_or_else(|| {
                let all: Vec<&str> = TracerBase::ALL.iter().map(|b| b.name()).collect();
                value_err(at(&format!(
                    "unknown base `{b}`; one of {}",
                    all.join(", ")
                )))
            })?
        }
        _ => match role.icepack() {
            Some((_, b, _)) => b,
            None => {
                return Err(value_err(at(
                    "`base` is needed (area, ice_volume or snow_volume) for a tracer of role other",
                )));
            }
        },
    };
    let strata: Vec<String> = match &got[3] {
        Some(v) if !v.is_none() => {
            if v.is_instance_of::<pyo3::types::PyString>() {
                return Err(value_err(at(
                    "`strata` must be a list of field names, not a string",
                )));
            }
            v.extract()
                .map_err(|_| value_err(at("`strata` must be a list of field names")))?
        }
        _ => role
            .icepack()
            .map(|(_, _, s)| s.iter().map(|x| x.to_string()).collect())
            .unwrap_or_default(),
    };
    Ok(TracerField {
        name,
        role,
        levels,
        base,
        strata,
    })
}

impl PyTracerLayout {
    /// `f` of the role of every tracer, in tracer order.
    fn per_tracer(&self, f: impl Fn(&TracerRole) -> &'static str) -> Vec<&'static str> {
        (0..self.inner.ntrcr())
            .map(|it| f(&self.inner.field_of(it).expect("index in range").0.role))
            .collect()
    }
}

#[pymethods]
impl PyTracerLayout {
    /// The CICE/Icepack layout (`TracerLayout::cice`) for `nilyr` ice and `nslyr` snow layers
    /// (both >= 1) with the optional tracers of `CiceTracerFlags` by keyword.
    #[staticmethod]
    #[pyo3(signature = (nilyr, nslyr, *, age = false, first_year = false, level_ice = false, ponds = false))]
    fn cice(
        nilyr: i64,
        nslyr: i64,
        age: bool,
        first_year: bool,
        level_ice: bool,
        ponds: bool,
    ) -> PyResult<Self> {
        for (name, v) in [("nilyr", nilyr), ("nslyr", nslyr)] {
            if !(1..=1 << 20).contains(&v) {
                return Err(value_err(format!("{name} = {v}: must be at least 1")).into());
            }
        }
        let flags = CiceTracerFlags {
            age,
            first_year,
            level_ice,
            ponds,
        };
        let l = TracerLayout::cice(nilyr as usize, nslyr as usize, flags).map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// Any layout (`TracerLayout::new`): `fields` in storage order, each a dict with keys
    /// `name` (str), `levels` (int >= 1, default 1), `base` (`area`, `ice_volume`,
    /// `snow_volume`), `strata` (names of earlier single-level fields it is also carried on),
    /// `role` (`surface_temperature`, `ice_enthalpy`, `snow_enthalpy`, `ice_salinity`, `age`,
    /// `first_year`, `level_area`, `level_volume`, `pond_area`, `pond_depth`, `pond_lid`,
    /// `other`), or a sequence in that order. The role defaults to the one whose Icepack name
    /// is `name` (`Tsfc`, `qice`, `qsno`, `sice`, `iage`, `FY`, `alvl`, `vlvl`, `apnd`,
    /// `hpnd`, `ipnd`), else `other`; base and strata default to Icepack's for the role.
    /// Errors name the field and what is wrong.
    #[staticmethod]
    fn from_fields(fields: Vec<Bound<'_, PyAny>>) -> PyResult<Self> {
        let f: Vec<TracerField> = fields
            .iter()
            .enumerate()
            .map(|(i, x)| field_from_py(i, x))
            .collect::<Result<_, _>>()?;
        let l = TracerLayout::new(f).map_err(value_err)?;
        Ok(Self { inner: Arc::new(l) })
    }

    /// The CICE layout of a dataset or file holding these variable names (CICE restart names:
    /// `vsnon`, `Tsfcn`, `qice001`.., `qsno001`.., `sice001`.., `iage`, `FY`, `alvl`, `vlvl`,
    /// `apnd`, `hpnd`, `ipnd`), as the command line tells it (`TracerLayout::detect_cice`):
    /// None when there is no snow and no tracer; a missing member of a group is a ValueError
    /// naming the variable.
    #[staticmethod]
    fn detect(names: Vec<String>) -> PyResult<Option<Self>> {
        let has = |n: &str| names.iter().any(|m| m == n);
        match TracerLayout::detect_cice(&has) {
            Ok(Some((l, _))) => Ok(Some(Self { inner: Arc::new(l) })),
            Ok(None) => Ok(None),
            Err(e) => Err(value_err(format!("tracer variable `{}` {e}", e.var)).into()),
        }
    }

    /// Tracers per category (Icepack `ntrcr`).
    #[getter]
    fn ntrcr(&self) -> usize {
        self.inner.ntrcr()
    }

    /// Ice layers.
    #[getter]
    fn nilyr(&self) -> usize {
        self.inner.nilyr()
    }

    /// Snow layers.
    #[getter]
    fn nslyr(&self) -> usize {
        self.inner.nslyr()
    }

    /// The optional CICE tracers carried, as a dict of `CiceTracerFlags` field names.
    #[getter]
    fn flags<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let f = flags_of(&self.inner);
        for (k, v) in [
            ("age", f.age),
            ("first_year", f.first_year),
            ("level_ice", f.level_ice),
            ("ponds", f.ponds),
        ] {
            d.set_item(k, v)?;
        }
        Ok(d)
    }

    /// Fields in storage order: (name, first index, levels, base, strata, units, long_name).
    #[allow(clippy::type_complexity)]
    fn fields(
        &self,
    ) -> Vec<(
        String,
        usize,
        usize,
        &'static str,
        Vec<String>,
        &'static str,
        &'static str,
    )> {
        self.inner
            .fields()
            .iter()
            .map(|f| {
                let (start, _) = self.inner.field(&f.name).expect("own field");
                (
                    f.name.clone(),
                    start,
                    f.levels,
                    f.base.name(),
                    f.strata.clone(),
                    f.role.units(),
                    f.role.long_name(),
                )
            })
            .collect()
    }

    /// The fields as `from_fields` takes them: a list of dicts `name`, `levels`, `base`,
    /// `strata`, `role`.
    fn spec<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        self.inner
            .fields()
            .iter()
            .map(|f| {
                let d = PyDict::new(py);
                d.set_item("name", &f.name)?;
                d.set_item("levels", f.levels)?;
                d.set_item("base", f.base.name())?;
                d.set_item("strata", f.strata.clone())?;
                d.set_item("role", f.role.name())?;
                Ok(d)
            })
            .collect()
    }

    /// (first index, levels) of the field `name`.
    fn field(&self, name: &str) -> PyResult<(usize, usize)> {
        self.inner.field(name).ok_or_else(|| {
            let known: Vec<&str> = self
                .inner
                .fields()
                .iter()
                .map(|f| f.name.as_str())
                .collect();
            value_err(format!(
                "no tracer field `{name}` in this layout (it has: {})",
                known.join(", ")
            ))
            .into()
        })
    }

    /// Per tracer, the variable name of a CICE restart file (`Tsfcn`, `qice001`, ...).
    #[getter]
    fn names(&self) -> Vec<String> {
        self.inner.cice_restart_names()
    }

    /// Per tracer, its CF units.
    #[getter]
    fn units(&self) -> Vec<&'static str> {
        self.per_tracer(|r| r.units())
    }

    /// Per tracer, its long name.
    #[getter]
    fn long_names(&self) -> Vec<&'static str> {
        self.per_tracer(|r| r.long_name())
    }

    /// Icepack's `trcr_depend` per tracer (0 area, 1 ice volume, 2 snow volume, 2 + nt).
    fn trcr_depend(&self) -> Vec<i32> {
        self.inner.trcr_depend()
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyTracerLayout>()
            .is_ok_and(|o| *o.get().inner == *self.inner)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        for f in self.inner.fields() {
            f.name.hash(&mut h);
            f.levels.hash(&mut h);
            f.base.name().hash(&mut h);
            f.role.name().hash(&mut h);
            f.strata.hash(&mut h);
        }
        h.finish()
    }

    fn __repr__(&self) -> String {
        let l = &*self.inner;
        let f = flags_of(l);
        if TracerLayout::cice(l.nilyr(), l.nslyr(), f).is_ok_and(|c| c == *l) {
            return format!(
                "TracerLayout.cice(nilyr={}, nslyr={}, age={}, first_year={}, level_ice={}, ponds={}) with {} tracers",
                l.nilyr(),
                l.nslyr(),
                py_bool(f.age),
                py_bool(f.first_year),
                py_bool(f.level_ice),
                py_bool(f.ponds),
                l.ntrcr()
            );
        }
        let parts: Vec<String> = l
            .fields()
            .iter()
            .map(|f| {
                let strata = if f.strata.is_empty() {
                    String::new()
                } else {
                    format!(" on {}", f.strata.join("*"))
                };
                format!(
                    "{}[{}] {} {}{strata}",
                    f.name,
                    f.levels,
                    f.role.name(),
                    f.base.name()
                )
            })
            .collect();
        format!(
            "TracerLayout.from_fields({}) with {} tracers",
            parts.join(", "),
            l.ntrcr()
        )
    }

    /// Pickling (dask workers): rebuilt from its fields.
    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, (Vec<Bound<'py, PyDict>>,))> {
        let make = slf.getattr("from_fields")?;
        Ok((make, (slf.get().spec(slf.py())?,)))
    }
}

fn py_bool(b: bool) -> &'static str {
    if b { "True" } else { "False" }
}

/// The thermodynamic constants of the complete step from (name, value) pairs of
/// `RidgeStepParams::FIELDS` names, and the salt-flux option by name.
fn step_params_from(list: Vec<(String, f64)>, salt_flux: &str) -> PyResult<RidgeStepParams> {
    let mut p = RidgeStepParams::default();
    for (name, value) in list {
        if !RidgeStepParams::FIELDS.iter().any(|f| f.name == name) {
            let all: Vec<&str> = RidgeStepParams::FIELDS.iter().map(|f| f.name).collect();
            return Err(value_err(format!(
                "unknown constant `{name}`; the complete step's constants: {}",
                all.join(", ")
            ))
            .into());
        }
        p.set(&name, value).map_err(value_err)?;
    }
    p.salt_flux = SaltFlux::from_name(salt_flux).ok_or_else(|| {
        value_err(format!(
            "salt_flux = {salt_flux:?}: must be \"constant\" or \"prognostic\""
        ))
    })?;
    Ok(p)
}

/// The complete step's thermodynamic constants (`RidgeStepParams::FIELDS`): (name, units,
/// description, Icepack default).
#[pyfunction]
fn step_parameters() -> Vec<(&'static str, &'static str, &'static str, f64)> {
    let d = RidgeStepParams::default();
    RidgeStepParams::FIELDS
        .iter()
        .map(|f| {
            (
                f.name,
                f.units,
                f.description,
                d.get(f.name).expect("a listed constant"),
            )
        })
        .collect()
}

/// Names, units and long names of the per-cell and per-category outputs of the complete step
/// (`pressridge::itd::CELL_OUTPUTS`, `CATEGORY_OUTPUTS`).
#[pyfunction]
#[allow(clippy::type_complexity)]
fn step_outputs() -> (
    Vec<(&'static str, &'static str, &'static str)>,
    Vec<(&'static str, &'static str, &'static str)>,
) {
    let f = |m: &pressridge::itd::OutputMeta| (m.name, m.units, m.long_name);
    (
        CELL_OUTPUTS.iter().map(f).collect(),
        CATEGORY_OUTPUTS.iter().map(f).collect(),
    )
}

/// Arrays returned by `ridge_step_full`.
type FullOut<'py> = (
    [Bound<'py, PyArrayDyn<f64>>; 3],
    Option<Bound<'py, PyArrayDyn<f64>>>,
    [Bound<'py, PyArrayDyn<f64>>; 2],
    Bound<'py, PyArray1<f64>>,
    Vec<(&'static str, Bound<'py, PyArrayDyn<f64>>)>,
    Vec<(&'static str, Bound<'py, PyArrayDyn<f64>>)>,
);

/// The complete ridging step (`itd::ridge_step_batch`); see `pressridge.ridge_step`. Every
/// spatial argument already has the spatial shape of `aicen` (the Python side broadcasts).
/// `rates`: `c1`, `c2` are the host's closing and opening rates, else Icepack's convergence
/// and shear terms. Without `trcrn` the column carries no tracers (zeros of a minimal layout,
/// not returned). Returns ([aicen, vicen, vsnon], trcrn, [aice0, aice], hin_max used,
/// [(cell output, array)], [(category output, array)]); the inputs are not modified.
#[pyfunction]
#[pyo3(signature = (aicen, vicen, vsnon, trcrn, layout, aice0, aice, hin_max, c1, c2, rates, tf, dt, ndtd, valid, participation_name, redistribution_name, params, cleanup, rebin, step_params, salt_flux))]
#[allow(clippy::too_many_arguments)]
fn ridge_step_full<'py>(
    py: Python<'py>,
    aicen: PyReadonlyArrayDyn<'py, f64>,
    vicen: PyReadonlyArrayDyn<'py, f64>,
    vsnon: PyReadonlyArrayDyn<'py, f64>,
    trcrn: Option<PyReadonlyArrayDyn<'py, f64>>,
    layout: Option<PyRef<'py, PyTracerLayout>>,
    aice0: Option<PyReadonlyArrayDyn<'py, f64>>,
    aice: Option<PyReadonlyArrayDyn<'py, f64>>,
    hin_max: Option<Vec<f64>>,
    c1: PyReadonlyArrayDyn<'py, f64>,
    c2: PyReadonlyArrayDyn<'py, f64>,
    rates: bool,
    tf: PyReadonlyArrayDyn<'py, f64>,
    dt: f64,
    ndtd: i64,
    valid: Option<PyReadonlyArrayDyn<'py, bool>>,
    participation_name: &str,
    redistribution_name: &str,
    params: Vec<(String, f64)>,
    cleanup: bool,
    rebin: bool,
    step_params: Vec<(String, f64)>,
    salt_flux: &str,
) -> PyResult<FullOut<'py>> {
    let spatial = category_shapes(&aicen, &vicen)?;
    let full = aicen.shape().to_vec();
    let ncat = full[0];
    check_array("vsnon", &vsnon, &full, "the shape of aicen")?;
    let (n1, n2) = if rates {
        ("closing", "opening")
    } else {
        ("convergence", "shear")
    };
    for (var, x) in [(n1, &c1), (n2, &c2), ("tf", &tf)] {
        check_array(var, x, &spatial, "the spatial shape of aicen")?;
    }
    for (var, x) in [("aice0", &aice0), ("aice", &aice)] {
        if let Some(x) = x {
            check_array(var, x, &spatial, "the spatial shape of aicen")?;
        }
    }
    if let Some(v) = &valid {
        check_array("valid", v, &spatial, "the spatial shape of aicen")?;
    }
    if !(dt > 0.0 && dt.is_finite()) {
        return Err(value_err(format!(
            "dt = {dt}: must be a positive, finite number of seconds"
        ))
        .into());
    }
    if !(1..=i64::from(u32::MAX)).contains(&ndtd) {
        return Err(value_err(format!("ndtd = {ndtd}: must be at least 1")).into());
    }
    let layout: Arc<TracerLayout> = match (&trcrn, &layout) {
        (Some(_), Some(l)) => l.inner.clone(),
        (Some(_), None) => return Err(value_err("trcrn needs its layout: pass layout=").into()),
        (None, Some(_)) => {
            return Err(value_err("layout is given but trcrn is not: pass both or neither").into());
        }
        (None, None) => {
            Arc::new(TracerLayout::cice(1, 1, CiceTracerFlags::default()).map_err(value_err)?)
        }
    };
    let nt = layout.ntrcr();
    let mut tshape = vec![ncat, nt];
    tshape.extend_from_slice(&spatial);
    if let Some(t) = &trcrn {
        check_array("trcrn", t, &tshape, "(ncat, layout.ntrcr, spatial...) =")?;
    }
    let ro = RidgeOptions {
        participation: participation(participation_name)?,
        redistribution: redistribution(redistribution_name)?,
        params: itd_params(params)?,
    };
    let opts = RidgeStepOptions {
        participation: ro.participation,
        redistribution: ro.redistribution,
        params: ro.params,
        step: step_params_from(step_params, salt_flux)?,
        cleanup,
        rebin,
    };
    let hin_max = match hin_max {
        Some(h) => h,
        None => category_bounds(&CategoryBounds::RoundNumbers, ncat).map_err(value_err)?,
    };
    if hin_max.len() != ncat + 1 {
        return Err(value_err(format!(
            "hin_max has {} values, expected ncat + 1 = {}",
            hin_max.len(),
            ncat + 1
        ))
        .into());
    }
    let a = aicen.as_array();
    let order = choose_order(&a);
    let state: [Bound<'py, PyArrayDyn<f64>>; 3] =
        std::array::from_fn(|_| new_array(py, &full, order));
    let t_out = new_array(py, &tshape, order);
    let scal: [Bound<'py, PyArrayDyn<f64>>; 2] =
        std::array::from_fn(|_| new_array(py, &spatial, order));
    let cell: Vec<Bound<'py, PyArrayDyn<f64>>> = CELL_OUTPUTS
        .iter()
        .map(|_| new_array(py, &spatial, order))
        .collect();
    let cats: Vec<Bound<'py, PyArrayDyn<f64>>> = CATEGORY_OUTPUTS
        .iter()
        .map(|_| new_array(py, &full, order))
        .collect();
    {
        let mut s_rw: Vec<_> = state.iter().map(|x| x.readwrite()).collect();
        let mut s_cols: Vec<ArrayViewMut2<'_, f64>> = s_rw
            .iter_mut()
            .map(|x| columns_mut(x.as_array_mut(), order))
            .collect();
        let mut t_rw = t_out.readwrite();
        let mut t_cols: ArrayViewMut3<'_, f64> = flatten_mut(t_rw.as_array_mut(), 2, order);
        let mut sc_rw: Vec<_> = scal.iter().map(|x| x.readwrite()).collect();
        let mut sc_flat: Vec<ArrayViewMut1<'_, f64>> = sc_rw
            .iter_mut()
            .map(|x| flat_mut(x.as_array_mut(), order))
            .collect();
        s_cols[0].assign(&columns(a, order));
        s_cols[1].assign(&columns(vicen.as_array(), order));
        s_cols[2].assign(&columns(vsnon.as_array(), order));
        if let Some(t) = &trcrn {
            let tv: CowArray<'_, f64, Ix3> = flatten(t.as_array(), 2, order);
            t_cols.assign(&tv);
        }
        match &aice0 {
            Some(x) => sc_flat[0].assign(&flat(x.as_array(), order)),
            None => {
                for (c, x) in sc_flat[0].iter_mut().enumerate() {
                    *x = f64::max(1.0 - s_cols[0].column(c).sum(), 0.0);
                }
            }
        }
        match &aice {
            Some(x) => sc_flat[1].assign(&flat(x.as_array(), order)),
            None => {
                for (c, x) in sc_flat[1].iter_mut().enumerate() {
                    *x = s_cols[0].column(c).sum();
                }
            }
        }
        let c1f = flat(c1.as_array(), order);
        let c2f = flat(c2.as_array(), order);
        let tff = flat(tf.as_array(), order);
        let ok = valid.as_ref().map(|x| flat_bool(x.as_array(), order));
        let mut cell_rw: Vec<_> = cell.iter().map(|x| x.readwrite()).collect();
        let mut cell_views: Vec<ArrayViewMut1<'_, f64>> = cell_rw
            .iter_mut()
            .map(|x| flat_mut(x.as_array_mut(), order))
            .collect();
        let mut cat_rw: Vec<_> = cats.iter().map(|x| x.readwrite()).collect();
        let mut cat_views: Vec<ArrayViewMut2<'_, f64>> = cat_rw
            .iter_mut()
            .map(|x| columns_mut(x.as_array_mut(), order))
            .collect();
        let layout_ref = &*layout;
        detached(py, || {
            let closing = if rates {
                BatchClosing::Rates {
                    closing: c1f.view(),
                    opening: c2f.view(),
                }
            } else {
                BatchClosing::Deformation {
                    convergence: c1f.view(),
                    shear: c2f.view(),
                }
            };
            let [sa, sv, ss] = <[ArrayViewMut2<'_, f64>; 3]>::try_from(s_cols)
                .map_err(|_| BindError::Internal("three state arrays".into()))?;
            let [s0, s1] = <[ArrayViewMut1<'_, f64>; 2]>::try_from(sc_flat)
                .map_err(|_| BindError::Internal("two cell state arrays".into()))?;
            let mut a0_keep = s0;
            ridge_step_batch(
                StepBatchMut {
                    aicen: sa,
                    vicen: sv,
                    vsnon: ss,
                    trcrn: t_cols,
                    aice0: a0_keep.view_mut(),
                    aice: s1,
                },
                &hin_max,
                BatchForcing {
                    closing,
                    tf: tff.view(),
                    dt,
                    ndtd: ndtd as u32,
                },
                ok.as_ref().map(|x| x.view()),
                f64::NAN,
                &opts,
                layout_ref,
                &mut cell_views,
                Some(&mut cat_views),
            )
            .map_err(|e| itd_err(e, &spatial, order))?;
            // Masked columns: their open water is missing, like their outputs.
            if let Some(ok) = &ok {
                for (x, &good) in a0_keep.iter_mut().zip(ok.iter()) {
                    if !good {
                        *x = f64::NAN;
                    }
                }
            }
            Ok(())
        })?;
    }
    let mut h_used = hin_max.clone();
    if !rates {
        h_used[ncat] = opts.params.big;
    }
    let [aicen_o, vicen_o, vsnon_o] = state;
    Ok((
        [aicen_o, vicen_o, vsnon_o],
        trcrn.is_some().then_some(t_out),
        scal,
        PyArray1::from_vec(py, h_used),
        CELL_OUTPUTS.iter().map(|m| m.name).zip(cell).collect(),
        CATEGORY_OUTPUTS.iter().map(|m| m.name).zip(cats).collect(),
    ))
}

/// The `ncat + 1` category bounds hin_max (m) of a CICE `kcatbound` option.
#[pyfunction]
#[pyo3(name = "category_bounds", signature = (ncat, scheme = "round_numbers"))]
fn category_bounds_py<'py>(
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
fn cf_presets() -> Vec<(&'static str, f64)> {
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
fn read_cf_table_py<'py>(py: Python<'py>, path: PathBuf) -> PyResult<Pair<'py, f64>> {
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
fn read_cf_table_at_friction<'py>(
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
fn param_names() -> Vec<&'static str> {
    ItdParams::NAMES.to_vec()
}

/// CICE's default value of every parameter (`ItdParams::FIELDS`, in order), as a dict.
#[pyfunction]
fn default_params<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
    let p = ItdParams::default();
    let d = PyDict::new(py);
    for f in ItdParams::FIELDS {
        d.set_item(f.name, p.get(f.name).expect("a listed parameter"))?;
    }
    Ok(d)
}

// ---------------------------------------------------------------------------------------
// The simulator

/// The resolved scene: a TOML file (or the built-in default) with `key=value` overrides
/// ([`Scene::load`]).
fn load_scene(path: Option<&Path>, sets: &[String]) -> Result<Scene, BindError> {
    Ok(Scene::load(path, sets)?)
}

/// The resolved scene as TOML text.
#[pyfunction]
#[pyo3(signature = (scene, sets))]
fn scene_toml(scene: Option<PathBuf>, sets: Vec<String>) -> PyResult<String> {
    Ok(guarded(|| load_scene(scene.as_deref(), &sets))?.to_toml())
}

type SimOut<'py> = (String, String, Vec<(String, Bound<'py, PyArray1<f64>>)>);

/// Runs a scene; returns (summary JSON, resolved scene TOML, [(column, samples)]).
/// Ctrl-C stops the run at the next sample with `KeyboardInterrupt`.
#[pyfunction]
#[pyo3(signature = (scene, sets, progress=None))]
fn simulate<'py>(
    py: Python<'py>,
    scene: Option<PathBuf>,
    sets: Vec<String>,
    progress: Option<Py<PyAny>>,
) -> PyResult<SimOut<'py>> {
    let sc = guarded(|| load_scene(scene.as_deref(), &sets))?;
    let duration = sc.duration;
    let out = detached(py, || {
        let mut interrupted: Option<PyErr> = None;
        // `progress(time, duration)` (s) at most every 0.2 s of wall time, and at the end.
        let mut last = std::time::Instant::now();
        let out = simulation::run(&sc, &mut |w| {
            let t = w.time();
            let due = last.elapsed().as_secs_f64() >= 0.2 || t >= duration - 0.5 * w.dt();
            let r = Python::attach(|py| {
                py.check_signals()?;
                if let (Some(cb), true) = (&progress, due) {
                    cb.call1(py, (t, duration))?;
                }
                Ok::<(), PyErr>(())
            });
            if due {
                last = std::time::Instant::now();
            }
            match r {
                Ok(()) => true,
                Err(e) => {
                    interrupted = Some(e);
                    false
                }
            }
        })?;
        match interrupted {
            Some(e) => Err(BindError::Interrupted(e)),
            None => Ok(out),
        }
    })?;
    let summary = serde_json::to_string(&out.summary).map_err(value_err)?;
    let mut cols: Vec<Vec<f64>> =
        vec![Vec::with_capacity(out.series.len()); series_columns().len()];
    for s in &out.series {
        let row = s.row();
        for (c, x) in cols.iter_mut().zip(row) {
            c.push(x);
        }
    }
    let series = series_columns()
        .iter()
        .zip(cols)
        .map(|((name, _), c)| (name.to_string(), PyArray1::from_vec(py, c)))
        .collect();
    Ok((summary, sc.to_toml(), series))
}

/// Units of the time-series columns, as (name, unit) pairs.
#[pyfunction]
fn series_units() -> Vec<(&'static str, &'static str)> {
    series_columns().to_vec()
}

// ---------------------------------------------------------------------------------------
// Campaigns and tables

fn read_spec(spec: &Path) -> Result<(CampaignSpec, PathBuf), BindError> {
    let s = CampaignSpec::read(spec)?;
    let base = spec.parent().map(|p| p.to_path_buf()).unwrap_or_default();
    Ok((s, base))
}

/// Runs a campaign on `threads` threads in this process (`run_campaign`); returns
/// (skipped, done). Ctrl-C ends it after the runs in flight, with `KeyboardInterrupt`.
/// `progress`, if given, is called about once a second with a dict (skipped, done, total,
/// simulated seconds).
#[pyfunction]
#[pyo3(signature = (spec, out, threads, progress))]
fn campaign_local(
    py: Python<'_>,
    spec: PathBuf,
    out: PathBuf,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<(usize, usize)> {
    let (spec_v, base) = guarded(|| read_spec(&spec))?;
    let stop = AtomicBool::new(false);
    let latest = std::sync::Mutex::new(None::<Progress>);
    let mut interrupted: Option<PyErr> = None;
    let mut callback_err: Option<PyErr> = None;
    let result = py.detach(|| {
        std::thread::scope(|s| {
            let worker = s.spawn(|| {
                guarded(|| {
                    run_campaign(
                        &spec_v,
                        &base,
                        &out,
                        threads,
                        &|p| *latest.lock().expect("progress lock") = Some(p),
                        &stop,
                    )
                    .map_err(BindError::from)
                })
            });
            let mut ticks = 0u32;
            while !worker.is_finished() {
                std::thread::sleep(Duration::from_millis(50));
                ticks += 1;
                Python::attach(|py| {
                    if interrupted.is_none()
                        && let Err(e) = py.check_signals()
                    {
                        interrupted = Some(e);
                        stop.store(true, Ordering::Relaxed);
                    }
                    if ticks % 20 == 0
                        && callback_err.is_none()
                        && let Some(cb) = &progress
                        && let Some(p) = *latest.lock().expect("progress lock")
                    {
                        let d = PyDict::new(py);
                        let r = d
                            .set_item("skipped", p.skipped)
                            .and_then(|_| d.set_item("done", p.done))
                            .and_then(|_| d.set_item("total", p.total))
                            .and_then(|_| d.set_item("simulated", p.simulated))
                            .and_then(|_| cb.call1(py, (d,)).map(|_| ()));
                        if let Err(e) = r {
                            callback_err = Some(e);
                            stop.store(true, Ordering::Relaxed);
                        }
                    }
                });
            }
            worker
                .join()
                .unwrap_or_else(|_| Err(BindError::Internal("campaign thread panicked".into())))
        })
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    if let Some(e) = callback_err {
        return Err(e);
    }
    Ok(result?)
}

/// Takes the finished runs of a campaign from an earlier result directory or records-only
/// archive into `out` (`campaign::adopt_records`); returns the number taken.
#[pyfunction]
fn campaign_adopt(
    py: Python<'_>,
    spec: PathBuf,
    out: PathBuf,
    archive: PathBuf,
) -> PyResult<usize> {
    detached(py, || {
        let (s, base) = read_spec(&spec)?;
        Ok(adopt_records(&s, &base, &out, &archive)?)
    })
}

/// Prepares a campaign directory (`prepare_campaign`); returns (spec JSON, [planned run
/// JSON] still to do, skipped, total).
#[pyfunction]
fn campaign_prepare(
    py: Python<'_>,
    spec: PathBuf,
    out: PathBuf,
) -> PyResult<(String, Vec<String>, usize, usize)> {
    detached(py, || {
        let (s, base) = read_spec(&spec)?;
        let prepared = prepare_campaign(&s, &base, &out)?;
        let todo = prepared
            .todo
            .iter()
            .map(|p| serde_json::to_string(p).map_err(value_err))
            .collect::<Result<Vec<_>, _>>()?;
        Ok((
            serde_json::to_string(&s).map_err(value_err)?,
            todo,
            prepared.skipped,
            prepared.plan.len(),
        ))
    })
}

/// Runs one planned run (JSON from `campaign_prepare`) and writes it into `out`
/// (`run_planned`); returns the run id. Meant to run on a dask worker.
#[pyfunction]
fn campaign_run_planned(
    py: Python<'_>,
    spec_json: &str,
    run_json: &str,
    out: PathBuf,
) -> PyResult<String> {
    let spec: CampaignSpec = serde_json::from_str(spec_json)
        .map_err(|e| value_err(format!("campaign spec JSON: {e}")))?;
    let run: PlannedRun =
        serde_json::from_str(run_json).map_err(|e| value_err(format!("planned run JSON: {e}")))?;
    detached(py, || {
        run_planned(&run, &spec, &out, &|_| {})?;
        Ok(run.id.clone())
    })
}

/// What a Python tabulation returns besides the table file: ([(set, thickness, C_f)],
/// [warning]).
type TabulateOut = (Vec<(String, f64, f64)>, Vec<String>);

/// Tabulates campaign directories into a NetCDF lookup table, as `pressridge tabulate`
/// (`table::campaigns::tabulate_campaigns`); returns one line per set and thickness with
/// its C_f, and the warnings and notes the command line prints.
#[pyfunction]
#[pyo3(signature = (campaign_dirs, out, points, command, date, allow_partial=false, rafting_reach=pressridge::table::rafting::RAFTING_REACH, exclude_rafted=false))]
#[allow(clippy::too_many_arguments)]
fn tabulate(
    py: Python<'_>,
    campaign_dirs: Vec<PathBuf>,
    out: PathBuf,
    points: usize,
    command: String,
    date: String,
    allow_partial: bool,
    rafting_reach: f64,
    exclude_rafted: bool,
) -> PyResult<TabulateOut> {
    detached(py, || {
        for d in &campaign_dirs {
            file_missing(d)?;
        }
        let opts = TabulateOptions {
            points,
            allow_partial,
            rafting_reach,
            exclude_rafted,
        };
        let t =
            tabulate_campaigns(&campaign_dirs, &opts, &command, &date).map_err(|e| match e {
                TabulateCampaignsError::Campaign(c) => c.into(),
                other => value_err(other),
            })?;
        write_ridge_table(&out, &t.table, &t.provenance)?;
        let mut warnings: Vec<String> = t
            .partial
            .iter()
            .map(|(d, g)| format!("partial campaign {} (allow_partial): {g}", d.display()))
            .collect();
        warnings.extend(fit_warnings(&t.table));
        for (id, why) in &t.gate_excluded {
            warnings.push(format!(
                "run {id} left out: its {why}; a dissipation cannot be negative, so the run went numerically unstable"
            ));
        }
        for (id, why) in &t.rafted_out {
            warnings.push(format!("run {id} left out: its {why}"));
        }
        let table = t.table;
        let mut lines = Vec::new();
        for (si, set) in table.sets.iter().enumerate() {
            for (hi, &h) in table.thickness.iter().enumerate() {
                lines.push((set.clone(), h, table.cf[si][hi]));
            }
        }
        Ok((lines, warnings))
    })
}

/// Test hook: panics inside the library-call guard, with (`detach = true`) or without the
/// GIL released; must raise `RuntimeError`, never abort the interpreter.
#[pyfunction]
#[pyo3(name = "_panic_for_test")]
fn panic_for_test(py: Python<'_>, detach: bool) -> PyResult<()> {
    let boom = || -> Result<(), BindError> { panic!("deliberate test panic") };
    if detach {
        detached(py, boom)
    } else {
        guarded(boom).map_err(PyErr::from)
    }
}

// ---------------------------------------------------------------------------------------
// Lookup tables

fn lookup_err(e: LookupError) -> BindError {
    value_err(e)
}

/// `lookup(i)` (value, clamped) for every i in 0..n, off the interpreter lock; returns
/// (values, clamped).
fn lookup_each<'py>(
    py: Python<'py>,
    n: usize,
    lookup: impl Fn(usize) -> Result<(f64, bool), LookupError> + Send,
) -> PyResult<Pair<'py, bool>> {
    let (vals, clamped): (Vec<f64>, Vec<bool>) = detached(py, move || {
        (0..n)
            .map(|i| lookup(i).map_err(lookup_err))
            .collect::<Result<_, _>>()
    })?;
    Ok((
        PyArray1::from_vec(py, vals),
        PyArray1::from_vec(py, clamped),
    ))
}

/// A ridging lookup table (`pressridge::table::lookup::RidgeLookup`) opened from the NetCDF
/// file that `pressridge tabulate` writes. Wrapped by `pressridge.Table`.
#[pyclass(frozen, name = "RidgeLookup", module = "pressridge._core")]
struct PyRidgeLookup {
    inner: Arc<RidgeLookup>,
}

#[pymethods]
impl PyRidgeLookup {
    /// Reads a table file.
    #[staticmethod]
    fn open(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let t = detached(py, || {
            file_missing(&path)?;
            RidgeLookup::open(&path).map_err(BindError::from)
        })?;
        Ok(Self { inner: Arc::new(t) })
    }

    /// Set labels.
    fn sets(&self) -> Vec<String> {
        self.inner.sets().to_vec()
    }

    /// The friction pair (μ, μ_w) of each set (dimensionless), or None for a table made
    /// before friction coordinates were written.
    fn friction(&self) -> Option<Vec<(f64, f64)>> {
        self.inner.friction()
    }

    /// The set at friction (`mu`, `mu_w`); ValueError listing the pairs the table has.
    fn friction_set(&self, mu: f64, mu_w: f64) -> PyResult<usize> {
        Ok(self.inner.friction_set(mu, mu_w).map_err(lookup_err)?)
    }

    /// Thickness axis (m).
    fn thickness<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.inner.thickness())
    }

    /// Volume axis (m³/m).
    fn volume<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.inner.volume())
    }

    /// Field names, sorted.
    fn variables(&self) -> Vec<String> {
        self.inner.variables().map(str::to_string).collect()
    }

    /// A global attribute, or None.
    fn attribute(&self, name: &str) -> Option<String> {
        self.inner.attribute(name).map(str::to_string)
    }

    /// (axis names, units, long_name, values with the field's shape) of a field.
    #[allow(clippy::type_complexity)]
    fn field<'py>(
        &self,
        py: Python<'py>,
        name: &str,
    ) -> PyResult<(
        Vec<&'static str>,
        String,
        String,
        Bound<'py, PyArrayDyn<f64>>,
    )> {
        let f = self.inner.field(name).ok_or_else(|| {
            value_err(format!(
                "the table has no field `{name}` (it has: {})",
                self.inner.variables().collect::<Vec<_>>().join(", ")
            ))
        })?;
        let t = &self.inner;
        let mut shape = Vec::new();
        if f.axes.set {
            shape.push(t.sets().len());
        }
        if f.axes.thickness {
            shape.push(t.thickness().len());
        }
        if f.axes.volume {
            shape.push(t.volume().len());
        }
        let data = ndarray::ArrayD::from_shape_vec(IxDyn(&shape), f.data.clone())
            .map_err(|e| BindError::Internal(e.to_string()))?;
        Ok((
            f.axes.names(),
            f.units.clone(),
            f.long_name.clone(),
            PyArrayDyn::from_owned_array(py, data),
        ))
    }

    /// Field `name` of set `set` interpolated at every (thickness, volume) pair of two
    /// equally long 1-D arrays; returns (values, clamped).
    fn value<'py>(
        &self,
        py: Python<'py>,
        name: &str,
        set: usize,
        thickness: numpy::PyReadonlyArray1<'py, f64>,
        volume: numpy::PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Pair<'py, bool>> {
        check_aligned("thickness", &thickness)?;
        check_aligned("volume", &volume)?;
        let h = thickness.as_array();
        let v = volume.as_array();
        if h.len() != v.len() {
            return Err(value_err("thickness and volume differ in length").into());
        }
        let t = &self.inner;
        lookup_each(py, h.len(), |i| {
            t.value(name, set, h[i], v[i]).map(|l| (l.value, l.clamped))
        })
    }

    /// C_f of set `set` at every thickness (m) of a 1-D array; returns (values, clamped).
    fn cf<'py>(
        &self,
        py: Python<'py>,
        set: usize,
        thickness: numpy::PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Pair<'py, bool>> {
        check_aligned("thickness", &thickness)?;
        let h = thickness.as_array();
        let t = &self.inner;
        lookup_each(py, h.len(), |i| {
            t.cf(set, h[i]).map(|l| (l.value, l.clamped))
        })
    }

    /// The nodes (thickness in m, C_f) of set `set`'s C_f table for the strength routine.
    fn cf_nodes<'py>(&self, py: Python<'py>, set: usize) -> PyResult<Pair<'py, f64>> {
        let c = self.inner.cf_table(set).map_err(lookup_err)?;
        Ok((
            PyArray1::from_slice(py, c.thickness()),
            PyArray1::from_slice(py, c.values()),
        ))
    }
}

// ---------------------------------------------------------------------------------------

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
    m.add_function(wrap_pyfunction!(strength, m)?)?;
    m.add_function(wrap_pyfunction!(layout, m)?)?;
    m.add_function(wrap_pyfunction!(ridge_step, m)?)?;
    m.add_function(wrap_pyfunction!(ridge_step_full, m)?)?;
    m.add_function(wrap_pyfunction!(step_outputs, m)?)?;
    m.add_function(wrap_pyfunction!(step_parameters, m)?)?;
    m.add_class::<PyTracerLayout>()?;
    m.add_function(wrap_pyfunction!(category_bounds_py, m)?)?;
    m.add_function(wrap_pyfunction!(param_names, m)?)?;
    m.add_function(wrap_pyfunction!(cf_presets, m)?)?;
    m.add_function(wrap_pyfunction!(read_cf_table_py, m)?)?;
    m.add_function(wrap_pyfunction!(read_cf_table_at_friction, m)?)?;
    m.add(
        "DEFAULT_FRICTION",
        pressridge::table::tabulate::DEFAULT_FRICTION,
    )?;
    m.add("RAFTING_REACH", pressridge::table::rafting::RAFTING_REACH)?;
    m.add_function(wrap_pyfunction!(default_params, m)?)?;
    m.add_function(wrap_pyfunction!(scene_toml, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(series_units, m)?)?;
    m.add_function(wrap_pyfunction!(campaign_local, m)?)?;
    m.add_function(wrap_pyfunction!(campaign_prepare, m)?)?;
    m.add_function(wrap_pyfunction!(campaign_adopt, m)?)?;
    m.add_function(wrap_pyfunction!(campaign_run_planned, m)?)?;
    m.add_function(wrap_pyfunction!(tabulate, m)?)?;
    m.add_class::<PyRidgeLookup>()?;
    m.add_function(wrap_pyfunction!(panic_for_test, m)?)?;
    Ok(())
}
