//! `pressridge ridge-step`: one ridging step on a gridded thickness distribution: the
//! complete step (snow, tracers, ocean fluxes; `itd::ridge_step_batch`) when the input has
//! snow or tracers under their CICE restart names, else the area-volume step
//! (`itd::ridge_batch_masked`).

use std::path::{Path, PathBuf};

use ndarray::{Array1, Array2, ArrayViewMut1, ArrayViewMut2};
use pressridge::io::itd_netcdf::{
    FieldMeta, ItdGrid, NC_FILL_DOUBLE, Output, ReadOptions, SnowTracers, history_line,
    read_itd_with, read_snow_tracers, write_output,
};
use pressridge::io::refuse_output_over_input;
use pressridge::itd::{
    BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, CategoryBounds, RidgeOptions,
    RidgeRatesMut, RidgeStepOptions, StepBatchMut, category_bounds, ridge_batch_masked,
    ridge_step_batch,
};

use crate::BoxError;
use crate::strength::{PartArg, RedistArg, check_finite, describe_params, parse_params};

/// Arguments of `pressridge ridge-step`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input NetCDF with aicen, vicen (the category dimension found by name: nc, ncat or ct;
    /// every other dimension, e.g. time, nj, ni, is kept) and optionally aice0, hin_max (or
    /// CICE history's NCAT), divu, shear.
    #[arg(long)]
    pub input: PathBuf,
    /// Name of the category dimension of aicen/vicen, when it is none of nc, ncat, ct.
    #[arg(long, value_name = "NAME")]
    pub category_dim: Option<String>,
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
    /// Complete step only: dynamics subcycles per thermodynamic step (>= 1, default 1); the
    /// ocean fluxes are averaged over ndtd·dt.
    #[arg(long)]
    pub ndtd: Option<u32>,
    /// Complete step only: freezing temperature (°C, default −1.8) given to the surface
    /// temperature of emptied categories.
    #[arg(long, allow_negative_numbers = true)]
    pub tf: Option<f64>,
    /// Complete step only: skip Icepack's clean-up after ridging (`docleanup = false`).
    #[arg(long)]
    pub no_cleanup: bool,
    /// Complete step only: no rebinning in the clean-up (`dorebin = false`).
    #[arg(long)]
    pub no_rebin: bool,
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
    let mut grid = read_itd_with(
        &args.input,
        &ReadOptions {
            category_dim: args.category_dim.clone(),
        },
    )?;
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
    let bounds_source = grid
        .hin_max_source
        .clone()
        .unwrap_or_else(|| "CICE kcatbound = 1 (none in the input)".into());
    let aice0 = match &grid.aice0 {
        Some(a) => a.clone(),
        // As the strength routine: 1 − Σ aicen, never below 0 (full cover can sum to
        // 1 + 2e-16; a total above 1 is excess area that ridging removes).
        None => {
            Array1::from_iter((0..ncol).map(|c| f64::max(1.0 - grid.aicen.column(c).sum(), 0.0)))
        }
    };
    let snow = read_snow_tracers(&args.input, &grid)?;
    let o = RidgeOptions {
        participation: args.participation.into(),
        redistribution: args.redistribution.into(),
        params: parse_params(&args.params)?,
    };
    if let Some(st) = snow {
        return run_complete(
            &args,
            grid,
            st,
            conv,
            shear,
            (hin_max, bounds_source),
            aice0,
            o,
        );
    }
    for (flag, given) in [
        ("--ndtd", args.ndtd.is_some()),
        ("--tf", args.tf.is_some()),
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
    let mut global = global_attrs(&args, &o);
    global.push(("category_bounds".into(), bounds_source));
    write_output(
        &args.output,
        &Output {
            grid: &grid,
            write_itd: true,
            hin_max: Some(&hin_max),
            fields: &fields,
            category_fields: &[],
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
            history: Some(&history_line()),
        },
    )?;
    Ok(())
}

/// The global attributes common to both steps.
fn global_attrs(args: &Args, o: &RidgeOptions) -> Vec<(String, String)> {
    vec![
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
    ]
}

/// Error for a non-finite output in a stepped column (the library refuses such columns
/// already; this guards the file).
fn check_finite_masked(
    grid: &ItdGrid,
    input: &Path,
    valid: Option<&Array1<bool>>,
    name: &str,
    values: impl Iterator<Item = (usize, f64)>,
) -> Result<(), BoxError> {
    for (c, x) in values {
        if valid.is_some_and(|v| !v[c]) {
            continue;
        }
        if !x.is_finite() {
            return Err(format!(
                "{}: column {c} at ({}): the computed `{name}` is {x}",
                input.display(),
                grid.spatial_index(c)
            )
            .into());
        }
    }
    Ok(())
}

/// The complete step (snow, tracers, ocean fluxes) on the file's columns.
#[allow(clippy::too_many_arguments)]
fn run_complete(
    args: &Args,
    mut grid: ItdGrid,
    st: SnowTracers,
    conv: Array1<f64>,
    shear: Array1<f64>,
    (hin_max, bounds_source): (Vec<f64>, String),
    mut aice0: Array1<f64>,
    o: RidgeOptions,
) -> Result<(), BoxError> {
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let SnowTracers {
        layout,
        mut vsnon,
        mut trcrn,
        missing,
        fill_value,
        ..
    } = st;
    let nt = layout.ntrcr();
    // A column is stepped when aicen, vicen, aice0, vsnon and every tracer have data there.
    let valid: Option<Array1<bool>> = match (&grid.valid, &missing) {
        (None, None) => None,
        (Some(v), None) | (None, Some(v)) => Some(v.clone()),
        (Some(a), Some(b)) => Some(a.iter().zip(b).map(|(x, y)| *x && *y).collect()),
    };
    let fill = grid.fill_value.or(fill_value).unwrap_or(NC_FILL_DOUBLE);
    if let Some(n) = args.ndtd
        && n < 1
    {
        return Err(format!("--ndtd must be at least 1, got {n}").into());
    }
    let tf: Array1<f64> = match args.tf {
        Some(t) if t.is_finite() => Array1::from_elem(ncol, t),
        Some(t) => return Err(format!("--tf must be a finite temperature (°C), got {t}").into()),
        None => Array1::from_elem(ncol, -1.8),
    };
    let opts = RidgeStepOptions {
        participation: o.participation,
        redistribution: o.redistribution,
        params: o.params,
        cleanup: !args.no_cleanup,
        rebin: !args.no_rebin,
        ..Default::default()
    };
    let mut aice: Array1<f64> = (0..ncol).map(|c| grid.aicen.column(c).sum()).collect();
    let mut cell: Vec<Array1<f64>> = CELL_OUTPUTS.iter().map(|_| Array1::zeros(ncol)).collect();
    let mut cats: Vec<Array2<f64>> = CATEGORY_OUTPUTS
        .iter()
        .map(|_| Array2::zeros((ncat, ncol)))
        .collect();
    {
        let mut cell_v: Vec<ArrayViewMut1<'_, f64>> =
            cell.iter_mut().map(|x| x.view_mut()).collect();
        let mut cat_v: Vec<ArrayViewMut2<'_, f64>> =
            cats.iter_mut().map(|x| x.view_mut()).collect();
        ridge_step_batch(
            StepBatchMut {
                aicen: grid.aicen.view_mut(),
                vicen: grid.vicen.view_mut(),
                vsnon: vsnon.view_mut(),
                trcrn: trcrn.view_mut(),
                aice0: aice0.view_mut(),
                aice: aice.view_mut(),
            },
            &hin_max,
            BatchForcing {
                closing: BatchClosing::Deformation {
                    convergence: conv.view(),
                    shear: shear.view(),
                },
                tf: tf.view(),
                dt: args.dt,
                ndtd: args.ndtd.unwrap_or(1),
            },
            valid.as_ref().map(|v| v.view()),
            fill,
            &opts,
            &layout,
            &mut cell_v,
            Some(&mut cat_v),
        )
        .map_err(|e| grid.locate(&args.input, e))?;
    }
    for (m, x) in CELL_OUTPUTS.iter().zip(&cell) {
        check_finite_masked(
            &grid,
            &args.input,
            valid.as_ref(),
            m.name,
            x.iter().copied().enumerate(),
        )?;
    }
    // Masked columns are missing in every output.
    if let Some(v) = &valid {
        for (c, ok) in v.iter().enumerate() {
            if !ok {
                aice0[c] = fill;
                aice[c] = fill;
                grid.aicen.column_mut(c).fill(fill);
                grid.vicen.column_mut(c).fill(fill);
                vsnon.column_mut(c).fill(fill);
                for n in 0..ncat {
                    for it in 0..nt {
                        trcrn[[n, it, c]] = fill;
                    }
                }
            }
        }
    }
    grid.aice0 = Some(aice0);
    grid.valid = valid;
    // Category fields in C order (category slowest, then the columns).
    let names = layout.cice_restart_names();
    let tracer_data: Vec<Vec<f64>> = (0..nt)
        .map(|it| {
            trcrn
                .index_axis(ndarray::Axis(1), it)
                .as_standard_layout()
                .iter()
                .copied()
                .collect()
        })
        .collect();
    let units: Vec<(&'static str, &'static str)> = (0..nt)
        .map(|it| {
            let role = layout.field_of(it).expect("index in range").0.role;
            (role.units(), role.long_name())
        })
        .collect();
    let vsnon_c = vsnon.as_standard_layout().into_owned();
    let mut category_fields: Vec<(FieldMeta<'_>, &[f64])> = vec![(
        FieldMeta {
            name: "vsnon",
            units: "m",
            long_name: "snow volume per unit grid-cell area in each thickness category",
            standard_name: None,
        },
        vsnon_c.as_slice().expect("standard layout"),
    )];
    for ((name, (u, ln)), data) in names.iter().zip(&units).zip(&tracer_data) {
        category_fields.push((
            FieldMeta {
                name,
                units: u,
                long_name: ln,
                standard_name: None,
            },
            data,
        ));
    }
    let cat_c: Vec<Array2<f64>> = cats
        .iter()
        .map(|x| x.as_standard_layout().into_owned())
        .collect();
    for (m, x) in CATEGORY_OUTPUTS.iter().zip(&cat_c) {
        category_fields.push((
            FieldMeta {
                name: m.name,
                units: m.units,
                long_name: m.long_name,
                standard_name: None,
            },
            x.as_slice().expect("standard layout"),
        ));
    }
    let mut fields: Vec<(FieldMeta<'_>, &[f64])> = vec![(
        FieldMeta {
            name: "aice",
            units: "1",
            long_name: "total ice area fraction (recomputed by the clean-up)",
            standard_name: None,
        },
        aice.as_slice().expect("contiguous"),
    )];
    for (m, x) in CELL_OUTPUTS.iter().zip(&cell) {
        fields.push((
            FieldMeta {
                name: m.name,
                units: m.units,
                long_name: m.long_name,
                standard_name: None,
            },
            x.as_slice().expect("contiguous"),
        ));
    }
    let mut global = global_attrs(args, &o);
    global.push(("category_bounds".into(), bounds_source));
    global.push((
        "ridging_step".into(),
        "complete (Icepack icepack_step_ridge: snow, tracers, ocean fluxes)".into(),
    ));
    global.push(("ndtd".into(), args.ndtd.unwrap_or(1).to_string()));
    global.push(("tf".into(), format!("{} degC", args.tf.unwrap_or(-1.8))));
    global.push(("cleanup".into(), (!args.no_cleanup).to_string()));
    global.push(("rebin".into(), (!args.no_rebin).to_string()));
    global.push(("tracers".into(), names.join(" ")));
    write_output(
        &args.output,
        &Output {
            grid: &grid,
            write_itd: true,
            hin_max: Some(&hin_max),
            fields: &fields,
            category_fields: &category_fields,
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
            history: Some(&history_line()),
        },
    )?;
    Ok(())
}
