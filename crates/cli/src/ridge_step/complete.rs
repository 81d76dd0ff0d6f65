//! The complete step of `ridge-step` (snow, tracers, ocean fluxes): the command's checks, the
//! freezing temperature from `--tf`/`--tf-var` and the call to the library's file-to-file
//! step (`io::itd_netcdf::step_complete`).

use ndarray::Array1;
use pressridge::io::itd_netcdf::{
    CellUnits, CompleteStep, FileClosing, FreezingTemperature, ItdGrid, SnowTracers, StepInput,
    read_cell_field, step_complete,
};
use pressridge::itd::{
    RidgeOptions, RidgeStepOptions,
    details::{RidgeStepParams, SaltFlux},
};

use super::settings::{AllParams, global_attrs};
use super::{Args, SaltFluxArg, TF_DEFAULT};
use crate::BoxError;

/// The freezing temperature (°C): `--tf` for every column, else the file's `Tf` (or the
/// variable of `--tf-var`) per column, else the default.
fn freezing_temperature(args: &Args, grid: &ItdGrid) -> Result<FreezingTemperature, BoxError> {
    if args.tf.is_some() && args.tf_var.is_some() {
        return Err(
            "give --tf (one temperature for every column) or --tf-var (a variable \
                    of the input), not both"
                .into(),
        );
    }
    let ncol = grid.ncol();
    let name = args.tf_var.clone().unwrap_or_else(|| "Tf".to_string());
    let constant = |t: f64, description: String| FreezingTemperature {
        values: Array1::from_elem(ncol, t),
        valid: None,
        description,
        variable: None,
    };
    match args.tf {
        Some(t) if t.is_finite() => return Ok(constant(t, format!("{t} degC"))),
        Some(t) => return Err(format!("--tf must be a finite temperature (°C), got {t}").into()),
        None => {}
    }
    match read_cell_field(&args.input, grid, &name, CellUnits::DegC)? {
        Some(f) => Ok(FreezingTemperature {
            values: f.values,
            valid: f.valid,
            description: format!("input variable `{name}` (degC)"),
            variable: Some(name),
        }),
        None if args.tf_var.is_some() => Err(format!(
            "--tf-var {name}: {} has no variable `{name}` (freezing temperature, degC)",
            args.input.display()
        )
        .into()),
        None => Ok(constant(
            TF_DEFAULT,
            format!("{TF_DEFAULT} degC (default; no `{name}` in the input)"),
        )),
    }
}

/// The complete step (snow, tracers, ocean fluxes) on the file's columns; `write_tracers`:
/// the file had snow or tracers (else they were zeros for the host's rates, not written).
pub(super) fn run_complete(
    args: &Args,
    grid: ItdGrid,
    (snow, write_tracers): (SnowTracers, bool),
    closing: FileClosing,
    (hin_max, bounds_source): (Vec<f64>, String),
    aice0: Array1<f64>,
    (o, all): (RidgeOptions, AllParams),
) -> Result<(), BoxError> {
    if let Some(n) = args.ndtd
        && n < 1
    {
        return Err(format!("--ndtd must be at least 1, got {n}").into());
    }
    let tf = freezing_temperature(args, &grid)?;
    let host_names = match &closing {
        FileClosing::Rates { closing, opening } => Some((closing.0.clone(), opening.0.clone())),
        FileClosing::Deformation { .. } => None,
    };
    let options = RidgeStepOptions {
        participation: o.participation,
        redistribution: o.redistribution,
        params: o.params,
        step: RidgeStepParams {
            salt_flux: match args.salt_flux {
                Some(SaltFluxArg::Prognostic) => SaltFlux::Prognostic,
                Some(SaltFluxArg::Constant) | None => SaltFlux::Constant,
            },
            ..all.step
        },
        cleanup: !args.no_cleanup,
        rebin: !args.no_rebin,
    };
    let attributes = global_attrs(
        args,
        &o,
        host_names.as_ref().map(|(c, op)| (c.as_str(), op.as_str())),
        &all.described,
    );
    step_complete(
        StepInput {
            grid,
            aice0,
            snow,
            write_tracers,
        },
        CompleteStep {
            input: &args.input,
            output: &args.output,
            hin_max: &hin_max,
            bounds_source: &bounds_source,
            closing,
            tf,
            dt: args.dt,
            ndtd: args.ndtd.unwrap_or(1),
            options: &options,
            attributes,
        },
    )?;
    Ok(())
}
