//! `pressridge ridge-step`: one ridging step on a gridded thickness distribution.

use std::path::PathBuf;

use ndarray::Array1;
use pressridge::io::itd_netcdf::{FieldMeta, NC_FILL_DOUBLE, Output, read_itd, write_output};
use pressridge::io::refuse_output_over_input;
use pressridge::itd::{
    CategoryBounds, RidgeOptions, RidgeRatesMut, category_bounds, ridge_batch_masked,
};

use crate::BoxError;
use crate::strength::{PartArg, RedistArg, check_finite, describe_params, parse_params};

/// Arguments of `pressridge ridge-step`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input NetCDF with aicen, vicen and optionally aice0, hin_max, divu, shear.
    #[arg(long)]
    pub input: PathBuf,
    /// Output NetCDF: updated aicen, vicen, aice0, hin_max and the ridging rates.
    #[arg(long)]
    pub output: PathBuf,
    /// Time step (s, > 0).
    #[arg(long, allow_negative_numbers = true)]
    pub dt: f64,
    /// Convergence rate (1/s, >= 0) for every column; default: max(-divu, 0) from the file
    /// (`divu` in s-1, or CICE history %/day, converted; other units are refused).
    #[arg(long, allow_negative_numbers = true)]
    pub convergence: Option<f64>,
    /// Shear term (1/s, >= 0) for every column; default: from the file's `shear` (s-1: the
    /// term itself; CICE history %/day: the strain rate, converted, term formed with divu),
    /// else 0.
    #[arg(long, allow_negative_numbers = true)]
    pub shear: Option<f64>,
    /// Participation function.
    #[arg(long, value_enum, default_value = "exponential")]
    pub participation: PartArg,
    /// Ridged-ice redistribution.
    #[arg(long, value_enum, default_value = "exponential")]
    pub redistribution: RedistArg,
    /// Override a parameter, NAME=VALUE (repeatable), e.g. `--param cs=0.5`.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    pub params: Vec<String>,
}

/// Runs `pressridge ridge-step`.
pub fn run(args: Args) -> Result<(), BoxError> {
    refuse_output_over_input(&args.output, "--output", &[("--input", &args.input)])?;
    if !(args.dt > 0.0 && args.dt.is_finite()) {
        return Err(format!(
            "--dt must be a positive, finite number of seconds, got {}",
            args.dt
        )
        .into());
    }
    for (flag, v) in [("--convergence", args.convergence), ("--shear", args.shear)] {
        if let Some(x) = v
            && !(x >= 0.0 && x.is_finite())
        {
            return Err(
                format!("{flag} must be a non-negative, finite rate (1/s), got {x}").into(),
            );
        }
    }
    let mut grid = read_itd(&args.input)?;
    let ncol = grid.ncol();
    let ncat = grid.ncat();
    let conv: Array1<f64> = match (args.convergence, &grid.divu) {
        (Some(c), _) => Array1::from_elem(ncol, c),
        (None, Some(d)) => {
            // A NaN or infinite divergence in a column with data is an error, not "no
            // convergence" (f64::max would turn NaN into 0).
            for (c, x) in d.iter().enumerate() {
                let masked = grid.valid.as_ref().is_some_and(|v| !v[c]);
                if !masked && !x.is_finite() {
                    return Err(format!(
                        "{}: variable `divu`: column {c} at ({}) is {x}: the divergence must be finite (1/s)",
                        args.input.display(),
                        grid.spatial_index(c)
                    )
                    .into());
                }
            }
            d.mapv(|x| f64::max(-x, 0.0))
        }
        (None, None) => {
            return Err("no convergence: pass --convergence or put `divu` in the input".into());
        }
    };
    let shear: Array1<f64> = match (args.shear, &grid.shear) {
        (Some(s), _) => Array1::from_elem(ncol, s),
        (None, Some(s)) => {
            for (c, x) in s.iter().enumerate() {
                let masked = grid.valid.as_ref().is_some_and(|v| !v[c]);
                if !(masked || x.is_finite() && *x >= 0.0) {
                    return Err(format!(
                        "{}: variable `shear`: column {c} at ({}) is {x}: the shear term must be finite and non-negative (1/s)",
                        args.input.display(),
                        grid.spatial_index(c)
                    )
                    .into());
                }
            }
            s.clone()
        }
        (None, None) => {
            eprintln!("pressridge: note: no --shear and no `shear` in the input; using 0");
            Array1::zeros(ncol)
        }
    };
    let hin_max = match &grid.hin_max {
        Some(h) => h.clone(),
        None => category_bounds(&CategoryBounds::RoundNumbers, ncat)?,
    };
    let mut aice0 = match &grid.aice0 {
        Some(a) => a.clone(),
        // As the strength routine: 1 − Σ aicen, never below 0 (full cover can sum to
        // 1 + 2e-16; a total above 1 is excess area that ridging removes).
        None => {
            Array1::from_iter((0..ncol).map(|c| f64::max(1.0 - grid.aicen.column(c).sum(), 0.0)))
        }
    };
    let fill = grid.fill_value.unwrap_or(NC_FILL_DOUBLE);
    let o = RidgeOptions {
        participation: args.participation.into(),
        redistribution: args.redistribution.into(),
        params: parse_params(&args.params)?,
    };
    let mut rates: [Array1<f64>; 5] = std::array::from_fn(|_| Array1::zeros(ncol));
    {
        let [c, op, d1, d2, dv] = &mut rates;
        ridge_batch_masked(
            grid.aicen.view_mut(),
            grid.vicen.view_mut(),
            aice0.view_mut(),
            &hin_max,
            conv.view(),
            shear.view(),
            grid.valid.as_ref().map(|v| v.view()),
            fill,
            args.dt,
            &o,
            RidgeRatesMut {
                closing: c.view_mut(),
                opening: op.view_mut(),
                dardg1dt: d1.view_mut(),
                dardg2dt: d2.view_mut(),
                dvirdgdt: dv.view_mut(),
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
    let global = vec![
        (
            "participation".to_string(),
            o.participation.name().to_string(),
        ),
        (
            "redistribution".to_string(),
            o.redistribution.name().to_string(),
        ),
        ("dt".to_string(), format!("{} s", args.dt)),
        (
            "convergence".to_string(),
            args.convergence
                .map_or("max(-divu, 0) from input".into(), |c| format!("{c} s-1")),
        ),
        (
            "shear".to_string(),
            args.shear
                .map_or("from input (or 0)".into(), |s| format!("{s} s-1")),
        ),
        ("input".to_string(), args.input.display().to_string()),
        describe_params(&args.params),
    ];
    write_output(
        &args.output,
        &Output {
            grid: &grid,
            write_itd: true,
            hin_max: Some(&hin_max),
            fields: &fields,
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
        },
    )?;
    Ok(())
}
