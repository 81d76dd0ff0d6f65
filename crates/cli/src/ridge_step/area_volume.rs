//! The area-volume step of `ridge-step` (`itd::ridge_batch`): an input without snow
//! or tracers, closing and opening from the deformation (CICE); its output file with the
//! ridging rates.

use ndarray::Array1;
use pressridge::io::itd_netcdf::{
    FieldMeta, ItdGrid, NC_FILL_DOUBLE, Output, history_line, write_output,
};
use pressridge::itd::{
    RidgeOptions,
    details::{RidgeBatchForcing, RidgeRatesMut},
    ridge_batch,
};

use super::Args;
use super::settings::{AllParams, global_attrs};
use crate::BoxError;
use crate::strength::check_finite;

/// The area-volume step on the file's columns, written to `--output`; the options of the
/// complete step are refused.
pub(super) fn run(
    args: &Args,
    mut grid: ItdGrid,
    (conv, shear): (Array1<f64>, Array1<f64>),
    (hin_max, bounds_source): (Vec<f64>, String),
    aice0: Array1<f64>,
    (o, all): (RidgeOptions, AllParams),
) -> Result<(), BoxError> {
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let step_names: Vec<&str> = all.step_overrides.iter().map(|s| s.as_str()).collect();
    for (flag, given) in [
        ("--ndtd", args.ndtd.is_some()),
        ("--tf", args.tf.is_some()),
        ("--tf-var", args.tf_var.is_some()),
        ("--salt-flux", args.salt_flux.is_some()),
        (
            &*format!("--param {}", step_names.join(", ")),
            !step_names.is_empty(),
        ),
        ("--no-cleanup", args.no_cleanup),
        ("--no-rebin", args.no_rebin),
    ] {
        if given {
            return Err(format!(
                "{flag} belongs to the complete step, but {} has no snow or tracers (vsnon, \
                 Tsfcn, qice001.., sice001.., qsno001..): only area and volume are ridged",
                args.input.display()
            )
            .into());
        }
    }
    let fill = grid.fill_value.unwrap_or(NC_FILL_DOUBLE);
    let mut aice0 = aice0;
    let mut rates: [Array1<f64>; 5] = std::array::from_fn(|_| Array1::zeros(ncol));
    {
        let [c, op, d1, d2, dv] = &mut rates;
        ridge_batch(
            grid.aicen.view_mut(),
            grid.vicen.view_mut(),
            aice0.view_mut(),
            &hin_max,
            RidgeBatchForcing {
                convergence: conv.view(),
                shear: shear.view(),
                dt: args.dt,
                valid: grid.valid.as_ref().map(|v| v.view()),
            },
            &o,
            RidgeRatesMut {
                closing: c.view_mut(),
                opening: op.view_mut(),
                dardg1dt: d1.view_mut(),
                dardg2dt: d2.view_mut(),
                dvirdgdt: dv.view_mut(),
                fill,
            },
        )
        .map_err(|e| grid.locate(&args.input, e))?;
    }
    for (name, r) in ["closing", "opening", "dardg1dt", "dardg2dt", "dvirdgdt"]
        .iter()
        .zip(&rates)
    {
        check_finite(&grid, &args.input, name, r.as_slice().expect("contiguous"))?;
    }
    for k in 0..ncat {
        check_finite(&grid, &args.input, "aicen", &grid.aicen.row(k).to_vec())?;
        check_finite(&grid, &args.input, "vicen", &grid.vicen.row(k).to_vec())?;
    }
    if let Some(v) = &grid.valid {
        for (a, ok) in aice0.iter_mut().zip(v) {
            if !ok {
                *a = fill;
            }
        }
    }
    grid.aice0 = Some(aice0);
    let meta = [
        ("closing", "s-1", "net closing rate"),
        ("opening", "s-1", "opening rate"),
        ("dardg1dt", "s-1", "rate of area loss by ridging ice"),
        ("dardg2dt", "s-1", "rate of area gain by new ridges"),
        ("dvirdgdt", "m s-1", "rate of ice volume ridged"),
    ];
    let fields: Vec<(FieldMeta<'_>, &[f64])> = meta
        .iter()
        .zip(&rates)
        .map(|(&(name, units, long_name), r)| {
            (
                FieldMeta {
                    name,
                    units,
                    long_name,
                    standard_name: None,
                },
                r.as_slice().expect("contiguous"),
            )
        })
        .collect();
    let mut global = global_attrs(args, &o, None, &all.described);
    global.push(("category_bounds".into(), bounds_source));
    write_output(
        &args.output,
        &Output {
            grid: &grid,
            write_itd: true,
            hin_max: Some(&hin_max),
            fields: &fields,
            category_fields: &[],
            dim_fields: &[],
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
            history: Some(&history_line()),
        },
    )?;
    Ok(())
}
