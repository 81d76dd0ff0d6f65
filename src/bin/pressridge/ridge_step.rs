//! `pressridge ridge-step`: one ridging step on a gridded thickness distribution: the
//! complete step (snow, tracers, ocean fluxes; `itd::ridge_step_batch`) when the input has
//! snow or tracers under their CICE restart names, else the area-volume step
//! (`itd::ridge_batch_masked`). Closing and opening are derived from the deformation (CICE,
//! `--rates deformation`) or read as the host's rates (SIS2, `--rates host`, always the
//! complete step); the freezing temperature comes from `--tf`, the file's `Tf` (degC), or
//! the default −1.8 °C.

use std::path::{Path, PathBuf};

use ndarray::{Array1, Array2, ArrayViewMut1, ArrayViewMut2};
use pressridge::io::itd_netcdf::{
    CellField, CellUnits, FieldMeta, ItdGrid, NC_FILL_DOUBLE, Output, ReadOptions, SnowTracers,
    history_line, read_cell_field, read_itd_with, read_snow_tracers, write_output,
};
use pressridge::io::refuse_output_over_input;
use pressridge::itd::{
    BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, CategoryBounds, CiceTracerFlags,
    RidgeOptions, RidgeRatesMut, RidgeStepOptions, StepBatchMut, TracerLayout, category_bounds,
    ridge_batch_masked, ridge_step_batch,
};

use crate::BoxError;
use crate::strength::{PartArg, RedistArg, check_finite};
use pressridge::itd::{ItdParams, RidgeStepParams, SaltFlux};

/// Where the closing and opening rates of `ridge-step` come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RatesArg {
    /// CICE: derived from the deformation (`divu`, `shear` or --convergence, --shear) as
    /// Icepack's `ridge_prep` does; the top category bound becomes 1e8 m.
    Deformation,
    /// SIS2: the host's net closing and opening rates (1/s), read from the variables named by
    /// --closing-var and --opening-var; the complete step, category bounds as given.
    Host,
}

/// Salt flux of the ice zapped by the clean-up (Icepack `saltflux_option`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum SaltFluxArg {
    /// The ice carries `ice_ref_salinity` (Icepack's default; salt not conserved).
    Constant,
    /// The ice carries its own mean layer salinity (conserving).
    Prognostic,
}

/// Freezing temperature (°C) of the complete step when neither `--tf` nor a `Tf` variable
/// gives one: the command line's and Python's default.
const TF_DEFAULT: f64 = -1.8;

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
    /// Where closing and opening come from: `deformation` (CICE, from divu/shear) or `host`
    /// (SIS2: the host's rates from the file, 1/s).
    #[arg(long, value_enum, default_value = "deformation")]
    pub rates: RatesArg,
    /// --rates host: the variable holding the host's net closing rate (1/s, `units` "s-1"
    /// required; %/day is refused), on the column dimensions. Default `closing`.
    #[arg(long, value_name = "NAME")]
    pub closing_var: Option<String>,
    /// --rates host: the variable holding the host's opening rate (1/s, `units` "s-1"
    /// required), on the column dimensions. Default `opening`.
    #[arg(long, value_name = "NAME")]
    pub opening_var: Option<String>,
    /// Participation function.
    #[arg(long, value_enum, default_value = "exponential")]
    pub participation: PartArg,
    /// Ridged-ice redistribution.
    #[arg(long, value_enum, default_value = "exponential")]
    pub redistribution: RedistArg,
    /// Override a parameter, NAME=VALUE (repeatable), e.g. `--param cs=0.5`: the ridging
    /// parameters (`ItdParams`: rhoi, rhow, mu_rdg, cs, ...) and, for the complete step, its
    /// thermodynamic constants (`RidgeStepParams`: rhos, lfresh, cp_ice, fsnowrdg,
    /// ice_ref_salinity, itd_area_min, itd_mass_min, hs_min, tmin), in SI units as listed in
    /// docs/strength.md. Wins over --param-file.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    pub params: Vec<String>,
    /// A file of parameter overrides: one `NAME = VALUE` per line, the names of --param;
    /// `#` starts a comment.
    #[arg(long, value_name = "PATH")]
    pub param_file: Option<PathBuf>,
    /// Complete step only: salt flux of the ice the clean-up zaps (default constant).
    #[arg(long, value_enum)]
    pub salt_flux: Option<SaltFluxArg>,
    /// Complete step only: dynamics subcycles per thermodynamic step (>= 1, default 1); the
    /// ocean fluxes are averaged over ndtd·dt.
    #[arg(long)]
    pub ndtd: Option<u32>,
    /// Complete step only: freezing temperature (°C) for every column, given to the surface
    /// temperature of emptied categories; default: per column from the file's `Tf` variable
    /// (see --tf-var; `units` degC), else −1.8.
    #[arg(long, allow_negative_numbers = true)]
    pub tf: Option<f64>,
    /// Complete step only: the variable holding the freezing temperature per column (°C,
    /// `units` "degC" required), default `Tf` (used when present).
    #[arg(long, value_name = "NAME")]
    pub tf_var: Option<String>,
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
    let host = args.rates == RatesArg::Host;
    for (flag, given) in [
        ("--convergence", args.convergence.is_some() && host),
        ("--shear", args.shear.is_some() && host),
        ("--closing-var", args.closing_var.is_some() && !host),
        ("--opening-var", args.opening_var.is_some() && !host),
    ] {
        if given {
            let (other, what) = if host {
                ("deformation", "the host's rates are read from the file")
            } else {
                (
                    "host",
                    "closing and opening are derived from the deformation",
                )
            };
            return Err(format!(
                "{flag} belongs to --rates {other}; with --rates {}, {what}",
                if host { "host" } else { "deformation" }
            )
            .into());
        }
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
    let forcing = if host {
        let read = |flag: &str, given: &Option<String>, default: &str, what: &str| {
            let name = given.clone().unwrap_or_else(|| default.to_string());
            match read_cell_field(&args.input, &grid, &name, CellUnits::PerSecond)? {
                Some(f) => Ok::<_, BoxError>((name, f)),
                None => Err(format!(
                    "--rates host: {} has no variable `{name}` (the host's {what} rate, s-1); \
                     name it with {flag}",
                    args.input.display()
                )
                .into()),
            }
        };
        let closing = read("--closing-var", &args.closing_var, "closing", "net closing")?;
        let opening = read("--opening-var", &args.opening_var, "opening", "opening")?;
        Forcing::Host { closing, opening }
    } else {
        deformation(&args, &grid)?
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
    let all = parse_all_params(&args)?;
    let o = RidgeOptions {
        participation: args.participation.into(),
        redistribution: args.redistribution.into(),
        params: all.itd,
    };
    let (conv, shear) = match (snow, forcing) {
        (Some(st), forcing) => {
            return run_complete(
                &args,
                grid,
                (st, true),
                forcing,
                (hin_max, bounds_source),
                aice0,
                (o, all),
            );
        }
        // The host's rates need the complete step; without snow or tracers it runs on
        // empty ones (zero snow, zero tracers of the minimal CICE layout), not written out.
        (None, forcing @ Forcing::Host { .. }) => {
            let layout = TracerLayout::cice(1, 1, CiceTracerFlags::default())?;
            let nt = layout.ntrcr();
            let st = SnowTracers {
                layout,
                flags: CiceTracerFlags::default(),
                vsnon: Array2::zeros((ncat, ncol)),
                trcrn: ndarray::Array3::zeros((ncat, nt, ncol)),
                missing: None,
                fill_value: None,
            };
            return run_complete(
                &args,
                grid,
                (st, false),
                forcing,
                (hin_max, bounds_source),
                aice0,
                (o, all),
            );
        }
        (None, Forcing::Deformation { conv, shear }) => (conv, shear),
    };
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
    let mut global = global_attrs(&args, &o, None, &all.described);
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

/// The parameters of --param-file and --param.
struct AllParams {
    /// Ridging parameters.
    itd: ItdParams,
    /// Thermodynamic constants of the complete step (salt flux set later).
    step: RidgeStepParams,
    /// Names of the step constants overridden (they need the complete step).
    step_overrides: Vec<String>,
    /// The overrides as given, for the `parameter_overrides` attribute.
    described: String,
}

/// Reads --param-file, then --param (which wins): each NAME=VALUE names an `ItdParams` or a
/// `RidgeStepParams` constant.
fn parse_all_params(args: &Args) -> Result<AllParams, BoxError> {
    let mut items: Vec<(String, String)> = Vec::new();
    if let Some(path) = &args.param_file {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("--param-file {}: {e}", path.display()))?;
        for (k, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if !line.is_empty() {
                items.push((format!("{}:{}", path.display(), k + 1), line.to_string()));
            }
        }
    }
    for p in &args.params {
        items.push((format!("--param {p}"), p.clone()));
    }
    let mut out = AllParams {
        itd: ItdParams::default(),
        step: RidgeStepParams::default(),
        step_overrides: Vec::new(),
        described: String::new(),
    };
    let mut described = Vec::new();
    for (whence, item) in &items {
        let (name, value) = item
            .split_once('=')
            .ok_or_else(|| format!("{whence}: expected NAME=VALUE"))?;
        let (name, value) = (name.trim(), value.trim());
        let x: f64 = value
            .parse()
            .map_err(|_| format!("{whence}: `{value}` is not a number"))?;
        if ItdParams::NAMES.contains(&name) {
            out.itd.set(name, x).map_err(|e| format!("{whence}: {e}"))?;
        } else if RidgeStepParams::FIELDS.iter().any(|f| f.name == name) {
            out.step
                .set(name, x)
                .map_err(|e| format!("{whence}: {e}"))?;
            if !out.step_overrides.iter().any(|n| n == name) {
                out.step_overrides.push(name.to_string());
            }
        } else {
            let step: Vec<&str> = RidgeStepParams::FIELDS.iter().map(|f| f.name).collect();
            return Err(format!(
                "{whence}: unknown parameter `{name}`; ridging parameters: {}; constants of \
                 the complete step: {}",
                ItdParams::NAMES.join(", "),
                step.join(", ")
            )
            .into());
        }
        described.push(format!("{name}={value}"));
    }
    out.described = if described.is_empty() {
        "none".into()
    } else {
        described.join(", ")
    };
    Ok(out)
}

/// Closing and opening of the step, per column.
enum Forcing {
    /// CICE: convergence and shear terms (1/s).
    Deformation {
        conv: Array1<f64>,
        shear: Array1<f64>,
    },
    /// SIS2: the host's closing and opening rates (1/s), with their variable names.
    Host {
        closing: (String, CellField),
        opening: (String, CellField),
    },
}

/// Convergence and shear terms (1/s) per column from the options or the file (CICE).
fn deformation(args: &Args, grid: &ItdGrid) -> Result<Forcing, BoxError> {
    let ncol = grid.ncol();
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
    Ok(Forcing::Deformation { conv, shear })
}

/// The global attributes common to both steps; `host`: the variables of the host's rates.
fn global_attrs(
    args: &Args,
    o: &RidgeOptions,
    host: Option<(&str, &str)>,
    overrides: &str,
) -> Vec<(String, String)> {
    let mut g = vec![
        (
            "participation".to_string(),
            o.participation.name().to_string(),
        ),
        (
            "redistribution".to_string(),
            o.redistribution.name().to_string(),
        ),
        ("dt".to_string(), format!("{} s", args.dt)),
    ];
    match host {
        None => {
            g.push((
                "rates".into(),
                "deformation (CICE: closing and opening derived from convergence and shear)".into(),
            ));
            g.push((
                "convergence".to_string(),
                args.convergence
                    .map_or("max(-divu, 0) from input".into(), |c| format!("{c} s-1")),
            ));
            g.push((
                "shear".to_string(),
                args.shear
                    .map_or("from input (or 0)".into(), |s| format!("{s} s-1")),
            ));
        }
        Some((c, op)) => {
            g.push((
                "rates".into(),
                "host (SIS2: the host's closing and opening rates, category bounds as given)"
                    .into(),
            ));
            g.push(("closing_rate".into(), format!("input variable `{c}` (s-1)")));
            g.push((
                "opening_rate".into(),
                format!("input variable `{op}` (s-1)"),
            ));
        }
    }
    g.push(("input".to_string(), args.input.display().to_string()));
    g.push(("parameter_overrides".into(), overrides.to_string()));
    g
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

/// `a && b` of two optional column masks (`None`: every column valid).
fn and_mask(a: Option<Array1<bool>>, b: Option<&Array1<bool>>) -> Option<Array1<bool>> {
    match (a, b) {
        (None, None) => None,
        (Some(v), None) => Some(v),
        (None, Some(v)) => Some(v.clone()),
        (Some(a), Some(b)) => Some(a.iter().zip(b).map(|(x, y)| *x && *y).collect()),
    }
}

/// The complete step (snow, tracers, ocean fluxes) on the file's columns; `write_tracers`:
/// the file had snow or tracers (else they were zeros for the host's rates, not written).
fn run_complete(
    args: &Args,
    mut grid: ItdGrid,
    (st, write_tracers): (SnowTracers, bool),
    forcing: Forcing,
    (hin_max, bounds_source): (Vec<f64>, String),
    mut aice0: Array1<f64>,
    (o, all): (RidgeOptions, AllParams),
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
    if let Some(n) = args.ndtd
        && n < 1
    {
        return Err(format!("--ndtd must be at least 1, got {n}").into());
    }
    if args.tf.is_some() && args.tf_var.is_some() {
        return Err(
            "give --tf (one temperature for every column) or --tf-var (a variable \
                    of the input), not both"
                .into(),
        );
    }
    // The freezing temperature: --tf for every column, else the file's `Tf` per column,
    // else the default.
    let tf_name = args.tf_var.clone().unwrap_or_else(|| "Tf".to_string());
    let tf_field = match args.tf {
        Some(_) => None,
        None => read_cell_field(&args.input, &grid, &tf_name, CellUnits::DegC)?,
    };
    let tf_from_file = tf_field.is_some();
    let (tf, tf_valid, tf_desc): (Array1<f64>, Option<Array1<bool>>, String) = match args.tf {
        Some(t) if t.is_finite() => (Array1::from_elem(ncol, t), None, format!("{t} degC")),
        Some(t) => return Err(format!("--tf must be a finite temperature (°C), got {t}").into()),
        None => match tf_field {
            Some(f) => (
                f.values,
                f.valid,
                format!("input variable `{tf_name}` (degC)"),
            ),
            None if args.tf_var.is_some() => {
                return Err(format!(
                    "--tf-var {tf_name}: {} has no variable `{tf_name}` (freezing temperature, degC)",
                    args.input.display()
                )
                .into());
            }
            None => (
                Array1::from_elem(ncol, TF_DEFAULT),
                None,
                format!("{TF_DEFAULT} degC (default; no `{tf_name}` in the input)"),
            ),
        },
    };
    // A column is stepped when aicen, vicen, aice0, vsnon, every tracer, the host's rates
    // and Tf have data there.
    let mut valid = and_mask(grid.valid.clone(), missing.as_ref());
    valid = and_mask(valid, tf_valid.as_ref());
    let (c1, c2, host_names) = match forcing {
        Forcing::Deformation { conv, shear } => (conv, shear, None),
        Forcing::Host {
            closing: (cn, cf),
            opening: (on, of),
        } => {
            valid = and_mask(valid, cf.valid.as_ref());
            valid = and_mask(valid, of.valid.as_ref());
            (cf.values, of.values, Some((cn, on)))
        }
    };
    let fill = grid.fill_value.or(fill_value).unwrap_or(NC_FILL_DOUBLE);
    let opts = RidgeStepOptions {
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
                closing: if host_names.is_some() {
                    BatchClosing::Rates {
                        closing: c1.view(),
                        opening: c2.view(),
                    }
                } else {
                    BatchClosing::Deformation {
                        convergence: c1.view(),
                        shear: c2.view(),
                    }
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
    let mut category_fields: Vec<(FieldMeta<'_>, &[f64])> = Vec::new();
    if write_tracers {
        category_fields.push((
            FieldMeta {
                name: "vsnon",
                units: "m",
                long_name: "snow volume per unit grid-cell area in each thickness category",
                standard_name: None,
            },
            vsnon_c.as_slice().expect("standard layout"),
        ));
    }
    for ((name, (u, ln)), data) in names.iter().zip(&units).zip(&tracer_data) {
        if !write_tracers {
            break;
        }
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
    // A per-column Tf read from the input goes to the output too, so that a chained step
    // uses it again (masked columns hold the fill value).
    let mut tf_out = tf;
    if tf_from_file {
        if let Some(v) = &grid.valid {
            for (x, ok) in tf_out.iter_mut().zip(v) {
                if !ok {
                    *x = fill;
                }
            }
        }
        fields.push((
            FieldMeta {
                name: &tf_name,
                units: "degC",
                long_name: "freezing temperature (given to emptied categories' surface temperature)",
                standard_name: None,
            },
            tf_out.as_slice().expect("contiguous"),
        ));
    }
    let mut global = global_attrs(
        args,
        &o,
        host_names.as_ref().map(|(c, op)| (c.as_str(), op.as_str())),
        &all.described,
    );
    // The thermodynamic constants used, each with its units (the one list of
    // RidgeStepParams::FIELDS), and the ice density.
    global.push(("rhoi".into(), format!("{} kg m-3", opts.params.rhoi)));
    for f in RidgeStepParams::FIELDS {
        let v = opts.step.get(f.name).expect("a listed constant");
        global.push((f.name.into(), format!("{v} {}", f.units)));
    }
    global.push(("salt_flux".into(), opts.step.salt_flux.name().into()));
    global.push(("category_bounds".into(), bounds_source));
    global.push((
        "ridging_step".into(),
        "complete (Icepack icepack_step_ridge: snow, tracers, ocean fluxes)".into(),
    ));
    global.push(("ndtd".into(), args.ndtd.unwrap_or(1).to_string()));
    global.push(("tf".into(), tf_desc));
    global.push(("cleanup".into(), (!args.no_cleanup).to_string()));
    global.push(("rebin".into(), (!args.no_rebin).to_string()));
    global.push((
        "tracers".into(),
        if write_tracers {
            names.join(" ")
        } else {
            "none (no snow or tracers in the input: ridged as zeros, not written)".into()
        },
    ));
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
