//! The complete ridging step (snow, tracers, ocean fluxes).
//!
//! Owns `ridge_step_full` (`itd::ridge_step_batch` over numpy arrays; its constants by name
//! through the library's parser, `RidgeStepOptions::from_pairs`), the salt-flux option by
//! name, and the lists of its constants (`step_parameters`) and outputs (`step_outputs`).

use std::sync::Arc;

use ndarray::{ArrayViewMut1, ArrayViewMut2, ArrayViewMut3, CowArray, Ix3};
use numpy::{
    PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyReadwriteArrayDyn,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;

use pressridge::itd::{
    CategoryBounds, RidgeStepOptions, category_bounds,
    details::{
        BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, CiceTracerFlags, NamedParams,
        RidgeStepParams, SPECIES_OUTPUTS, SaltFlux, StepBatchMut, StepBatchOutputs, TracerLayout,
        species_counts,
    },
    ridge_step_batch,
};

use crate::arrays::{
    Order, category_shapes, check_array, choose_order, columns, columns_mut, flat, flat_bool,
    flat_mut, flatten, flatten_mut, itd_err, new_array,
};
use crate::errors::{BindError, detached, value_err};
use crate::options::{participation, redistribution};
use crate::tracers::PyTracerLayout;

/// The salt-flux option of the clean-up by name (`constant` or `prognostic`).
fn salt_flux_from(name: &str) -> PyResult<SaltFlux> {
    Ok(SaltFlux::from_name(name).ok_or_else(|| {
        value_err(format!(
            "salt_flux = {name:?}: must be \"constant\" or \"prognostic\""
        ))
    })?)
}

/// The complete step's thermodynamic constants (`RidgeStepParams::FIELDS`): (name, units,
/// description, Icepack default).
#[pyfunction]
pub(crate) fn step_parameters() -> Vec<(&'static str, &'static str, &'static str, f64)> {
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

/// Names, units and long names of the per-cell, per-category and per-species outputs of the
/// complete step (`pressridge::itd::details::CELL_OUTPUTS`, `CATEGORY_OUTPUTS`, `SPECIES_OUTPUTS`).
#[pyfunction]
#[allow(clippy::type_complexity)]
pub(crate) fn step_outputs() -> (
    Vec<(&'static str, &'static str, &'static str)>,
    Vec<(&'static str, &'static str, &'static str)>,
    Vec<(&'static str, &'static str, &'static str)>,
) {
    let f = |m: &pressridge::itd::details::OutputMeta| (m.name, m.units, m.long_name);
    (
        CELL_OUTPUTS.iter().map(f).collect(),
        CATEGORY_OUTPUTS.iter().map(f).collect(),
        SPECIES_OUTPUTS.iter().map(f).collect(),
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
    Vec<(&'static str, Bound<'py, PyArrayDyn<f64>>)>,
);

/// The complete ridging step (`itd::ridge_step_batch`); see `pressridge.ridge_step`. Every
/// spatial argument already has the spatial shape of `aicen` (the Python side broadcasts).
/// `rates`: `c1`, `c2` are the host's closing and opening rates, else Icepack's convergence
/// and shear terms. Without `trcrn` the column carries no tracers (zeros of a minimal layout,
/// not returned). Returns ([aicen, vicen, vsnon], trcrn, [aice0, aice], hin_max used,
/// [(cell output, array)], [(category output, array)], [(species output, array of shape
/// (n_aero or n_iso, spatial...))]); the inputs are not modified.
#[pyfunction]
#[pyo3(signature = (aicen, vicen, vsnon, trcrn, layout, aice0, aice, hin_max, c1, c2, rates, tf, dt, ndtd, valid, participation_name, redistribution_name, params, cleanup, rebin, salt_flux, mu_rdg_nodes = None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn ridge_step_full<'py>(
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
    salt_flux: &str,
    mu_rdg_nodes: Option<(Vec<f64>, Vec<f64>)>,
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
    let ndtd = step_timing(dt, ndtd)?;
    let layout = step_layout(trcrn.is_some(), layout.as_deref())?;
    let mut tshape = vec![ncat, layout.ntrcr()];
    tshape.extend_from_slice(&spatial);
    if let Some(t) = &trcrn {
        check_array("trcrn", t, &tshape, "(ncat, layout.ntrcr, spatial...) =")?;
    }
    let opts = step_options(
        participation_name,
        redistribution_name,
        mu_rdg_nodes,
        params,
        salt_flux,
        cleanup,
        rebin,
    )?;
    let hin_max = step_bounds(hin_max, ncat)?;
    let order = choose_order(&aicen.as_array());
    let out = StepArrays::new(py, &full, &tshape, &spatial, &layout, order);
    let inputs = StepInputs {
        state: [&aicen, &vicen, &vsnon],
        trcrn: trcrn.as_ref(),
        cell_state: [aice0.as_ref(), aice.as_ref()],
        forcing: [&c1, &c2, &tf],
        rates,
        dt,
        ndtd,
        valid: valid.as_ref(),
    };
    run_step(py, &inputs, &out, &hin_max, &opts, &layout)?;
    let mut h_used = hin_max;
    if !rates {
        h_used[ncat] = opts.params.big;
    }
    let StepArrays {
        state,
        trcrn: t_out,
        scal,
        cell,
        cats,
        species,
        ..
    } = out;
    Ok((
        state,
        trcrn.is_some().then_some(t_out),
        scal,
        PyArray1::from_vec(py, h_used),
        CELL_OUTPUTS.iter().map(|m| m.name).zip(cell).collect(),
        CATEGORY_OUTPUTS.iter().map(|m| m.name).zip(cats).collect(),
        SPECIES_OUTPUTS
            .iter()
            .map(|m| m.name)
            .zip(species)
            .collect(),
    ))
}

/// The step's time step (s, positive and finite) and its number of dynamic subcycles (≥ 1).
fn step_timing(dt: f64, ndtd: i64) -> PyResult<u32> {
    if !(dt > 0.0 && dt.is_finite()) {
        return Err(value_err(format!(
            "dt = {dt}: must be a positive, finite number of seconds"
        ))
        .into());
    }
    u32::try_from(ndtd)
        .ok()
        .filter(|&n| n >= 1)
        .ok_or_else(|| value_err(format!("ndtd = {ndtd}: must be at least 1")).into())
}

/// The tracer layout of the step: the caller's with `trcrn`, a minimal one without.
fn step_layout(has_trcrn: bool, layout: Option<&PyTracerLayout>) -> PyResult<Arc<TracerLayout>> {
    match (has_trcrn, layout) {
        (true, Some(l)) => Ok(l.inner.clone()),
        (true, None) => Err(value_err("trcrn needs its layout: pass layout=").into()),
        (false, Some(_)) => {
            Err(value_err("layout is given but trcrn is not: pass both or neither").into())
        }
        (false, None) => Ok(Arc::new(
            TracerLayout::cice(1, 1, CiceTracerFlags::default()).map_err(value_err)?,
        )),
    }
}

/// The participation and redistribution (by name, with the redistribution's μ_rdg nodes)
/// and every constant of the step by name, through the library's parser.
fn step_options(
    participation_name: &str,
    redistribution_name: &str,
    mu_rdg_nodes: Option<(Vec<f64>, Vec<f64>)>,
    params: Vec<(String, f64)>,
    salt_flux: &str,
    cleanup: bool,
    rebin: bool,
) -> PyResult<RidgeStepOptions> {
    let participation = participation(participation_name)?;
    let redistribution = redistribution(redistribution_name, mu_rdg_nodes)?;
    let constants = RidgeStepOptions::from_pairs(params).map_err(BindError::from)?;
    Ok(RidgeStepOptions {
        participation,
        redistribution,
        step: RidgeStepParams {
            salt_flux: salt_flux_from(salt_flux)?,
            ..constants.step
        },
        cleanup,
        rebin,
        ..constants
    })
}

/// The category bounds (m): the caller's `ncat + 1` values, or the round-number bounds.
fn step_bounds(hin_max: Option<Vec<f64>>, ncat: usize) -> PyResult<Vec<f64>> {
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
    Ok(hin_max)
}

/// The step's inputs, checked against the shapes of `aicen`.
struct StepInputs<'a, 'py> {
    /// aicen, vicen, vsnon: (ncat, spatial...).
    state: [&'a PyReadonlyArrayDyn<'py, f64>; 3],
    /// (ncat, ntrcr, spatial...), or none.
    trcrn: Option<&'a PyReadonlyArrayDyn<'py, f64>>,
    /// aice0, aice (spatial); where absent, derived from aicen.
    cell_state: [Option<&'a PyReadonlyArrayDyn<'py, f64>>; 2],
    /// The closing terms (`rates`: closing, opening; else convergence, shear, 1/s) and tf (°C).
    forcing: [&'a PyReadonlyArrayDyn<'py, f64>; 3],
    rates: bool,
    /// Time step (s).
    dt: f64,
    /// Dynamic subcycles.
    ndtd: u32,
    /// Which cells to step; the others are written as NaN.
    valid: Option<&'a PyReadonlyArrayDyn<'py, bool>>,
}

/// The arrays the step writes, new, in the memory order of the input.
struct StepArrays<'py> {
    state: [Bound<'py, PyArrayDyn<f64>>; 3],
    trcrn: Bound<'py, PyArrayDyn<f64>>,
    /// aice0, aice.
    scal: [Bound<'py, PyArrayDyn<f64>>; 2],
    cell: Vec<Bound<'py, PyArrayDyn<f64>>>,
    cats: Vec<Bound<'py, PyArrayDyn<f64>>>,
    species: Vec<Bound<'py, PyArrayDyn<f64>>>,
    spatial: Vec<usize>,
    order: Order,
}

impl<'py> StepArrays<'py> {
    fn new(
        py: Python<'py>,
        full: &[usize],
        tshape: &[usize],
        spatial: &[usize],
        layout: &TracerLayout,
        order: Order,
    ) -> Self {
        let cells = |n: usize| (0..n).map(|_| new_array(py, spatial, order)).collect();
        let cats = |n: usize| (0..n).map(|_| new_array(py, full, order)).collect();
        StepArrays {
            state: std::array::from_fn(|_| new_array(py, full, order)),
            trcrn: new_array(py, tshape, order),
            scal: std::array::from_fn(|_| new_array(py, spatial, order)),
            cell: cells(CELL_OUTPUTS.len()),
            cats: cats(CATEGORY_OUTPUTS.len()),
            species: species_counts(layout)
                .iter()
                .map(|&n| {
                    let mut shape = vec![n];
                    shape.extend_from_slice(spatial);
                    new_array(py, &shape, order)
                })
                .collect(),
            spatial: spatial.to_vec(),
            order,
        }
    }
}

/// Copies the inputs into the new arrays and steps them there with `ridge_step_batch`, the
/// Python thread detached.
fn run_step(
    py: Python<'_>,
    inputs: &StepInputs<'_, '_>,
    out: &StepArrays<'_>,
    hin_max: &[f64],
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
) -> PyResult<()> {
    let order = out.order;
    let mut s_rw: Vec<_> = out.state.iter().map(|x| x.readwrite()).collect();
    let mut s_cols: Vec<ArrayViewMut2<'_, f64>> = s_rw
        .iter_mut()
        .map(|x| columns_mut(x.as_array_mut(), order))
        .collect();
    let mut t_rw = out.trcrn.readwrite();
    let mut t_cols: ArrayViewMut3<'_, f64> = flatten_mut(t_rw.as_array_mut(), 2, order);
    let mut sc_rw: Vec<_> = out.scal.iter().map(|x| x.readwrite()).collect();
    let mut sc_flat: Vec<ArrayViewMut1<'_, f64>> = sc_rw
        .iter_mut()
        .map(|x| flat_mut(x.as_array_mut(), order))
        .collect();
    for (o, x) in s_cols.iter_mut().zip(inputs.state) {
        o.assign(&columns(x.as_array(), order));
    }
    if let Some(t) = inputs.trcrn {
        let tv: CowArray<'_, f64, Ix3> = flatten(t.as_array(), 2, order);
        t_cols.assign(&tv);
    }
    // aice0 = max(1 − Σ aicen, 0) and aice = Σ aicen where the caller gives neither.
    for (k, (o, x)) in sc_flat.iter_mut().zip(inputs.cell_state).enumerate() {
        match x {
            Some(x) => o.assign(&flat(x.as_array(), order)),
            None => {
                for (c, x) in o.iter_mut().enumerate() {
                    let area = s_cols[0].column(c).sum();
                    *x = if k == 0 {
                        f64::max(1.0 - area, 0.0)
                    } else {
                        area
                    };
                }
            }
        }
    }
    let [c1f, c2f, tff] = inputs.forcing.map(|x| flat(x.as_array(), order));
    let ok = inputs.valid.map(|x| flat_bool(x.as_array(), order));
    let mut cell_rw = readwrite_all(&out.cell);
    let mut cat_rw = readwrite_all(&out.cats);
    let mut sp_rw = readwrite_all(&out.species);
    let mut cell_views: Vec<ArrayViewMut1<'_, f64>> = cell_rw
        .iter_mut()
        .map(|x| flat_mut(x.as_array_mut(), order))
        .collect();
    let mut cat_views: Vec<ArrayViewMut2<'_, f64>> = cat_rw
        .iter_mut()
        .map(|x| columns_mut(x.as_array_mut(), order))
        .collect();
    let mut sp_views: Vec<ArrayViewMut2<'_, f64>> = sp_rw
        .iter_mut()
        .map(|x| columns_mut(x.as_array_mut(), order))
        .collect();
    let (rates, dt, ndtd) = (inputs.rates, inputs.dt, inputs.ndtd);
    let spatial = &out.spatial;
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
        let [mut a0, a1] = <[ArrayViewMut1<'_, f64>; 2]>::try_from(sc_flat)
            .map_err(|_| BindError::Internal("two cell state arrays".into()))?;
        ridge_step_batch(
            StepBatchMut {
                aicen: sa,
                vicen: sv,
                vsnon: ss,
                trcrn: t_cols,
                aice0: a0.view_mut(),
                aice: a1,
            },
            hin_max,
            BatchForcing {
                closing,
                tf: tff.view(),
                dt,
                ndtd,
                valid: ok.as_ref().map(|x| x.view()),
            },
            opts,
            layout,
            StepBatchOutputs {
                cell: &mut cell_views,
                category: Some(&mut cat_views),
                species: Some(&mut sp_views),
                fill: f64::NAN,
            },
        )
        .map_err(|e| itd_err(e, spatial, order))?;
        // Masked columns: their open water is missing, like their outputs.
        if let Some(ok) = &ok {
            for (x, &good) in a0.iter_mut().zip(ok.iter()) {
                if !good {
                    *x = f64::NAN;
                }
            }
        }
        Ok(())
    })?;
    Ok(())
}

/// Write access to each of `v`.
fn readwrite_all<'py>(v: &[Bound<'py, PyArrayDyn<f64>>]) -> Vec<PyReadwriteArrayDyn<'py, f64>> {
    v.iter().map(|x| x.readwrite()).collect()
}
