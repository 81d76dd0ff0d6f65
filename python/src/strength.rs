//! Ice strength and the ridging step of the thickness distribution alone.
//!
//! Owns `strength` (P, N/m, and the columns with a clamped C_f), `ridge_step` (areas,
//! volumes and ridging rates, no snow or tracers) and the `_layout` probe of the no-copy
//! promise. The complete step with snow, tracers and ocean fluxes is in `step.rs`.

use ndarray::ArrayViewMut1;
use numpy::{PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

use pressridge::itd::{
    CategoryBounds, RidgeOptions, category_bounds,
    details::{RidgeBatchForcing, RidgeRatesMut, strength_batch_masked},
    ridge_batch,
};

use crate::arrays::{
    category_shapes, check_aligned, check_array, choose_order, columns, columns_mut, flat,
    flat_bool, flat_mut, itd_err, new_array,
};
use crate::errors::{detached, value_err};
use crate::options::{StrengthArgs, itd_params, participation, redistribution};

/// Ice strength P (N/m); see `pressridge.strength`. `options` is a dict (`StrengthArgs`).
/// Returns (P, columns with a clamped C_f, of these the columns where the clamp carries ≥ 1 %
/// of P, the largest share of a column's P from clamped C_f).
#[pyfunction]
#[pyo3(signature = (aicen, vicen, aice0, valid, options))]
pub(crate) fn strength<'py>(
    py: Python<'py>,
    aicen: PyReadonlyArrayDyn<'py, f64>,
    vicen: PyReadonlyArrayDyn<'py, f64>,
    aice0: Option<PyReadonlyArrayDyn<'py, f64>>,
    valid: Option<PyReadonlyArrayDyn<'py, bool>>,
    options: StrengthArgs,
) -> PyResult<(Bound<'py, PyArrayDyn<f64>>, usize, usize, f64)> {
    let spatial = category_shapes(&aicen, &vicen)?;
    if let Some(a0) = &aice0 {
        check_array("aice0", a0, &spatial, "the spatial shape of aicen")?;
    }
    if let Some(v) = &valid {
        check_array("valid", v, &spatial, "the spatial shape of aicen")?;
    }
    let opts = options.resolve(py)?;
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
    Ok((
        out,
        summary.cf_clamped_columns,
        summary.cf_clamped_material_columns,
        summary.cf_clamped_share_max,
    ))
}

/// Whether `aicen` passes to the batch routines as a view ("view") or is copied ("copy"),
/// and the flattening order; for tests of the no-copy promise.
#[pyfunction]
#[pyo3(name = "_layout")]
pub(crate) fn layout(aicen: PyReadonlyArrayDyn<'_, f64>) -> PyResult<(String, String)> {
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
#[pyo3(signature = (aicen, vicen, aice0, hin_max, convergence, shear, dt, valid, participation_name, redistribution_name, params, mu_rdg_nodes = None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn ridge_step<'py>(
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
    mu_rdg_nodes: Option<(Vec<f64>, Vec<f64>)>,
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
        redistribution: redistribution(redistribution_name, mu_rdg_nodes)?,
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
            ridge_batch(
                a_cols,
                v_cols,
                a0_flat.view_mut(),
                &hin_max,
                RidgeBatchForcing {
                    convergence: conv.view(),
                    shear: shr.view(),
                    dt,
                    valid: ok.as_ref().map(|x| x.view()),
                },
                &opts,
                RidgeRatesMut {
                    closing,
                    opening,
                    dardg1dt,
                    dardg2dt,
                    dvirdgdt,
                    fill: f64::NAN,
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
