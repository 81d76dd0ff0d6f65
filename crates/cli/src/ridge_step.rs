//! `pressridge ridge-step`: one ridging step on a gridded thickness distribution: the
//! complete step (snow, tracers, ocean fluxes; `itd::ridge_step_batch`) when the input has
//! snow or tracers under their CICE restart names, or packed in one array whose layout
//! `--tracer-layout` names (Icepack column driver's history), else the area-volume step
//! (`itd::ridge_batch`). Closing and opening are derived from the deformation (CICE,
//! `--rates deformation`) or read as the host's rates (SIS2, `--rates host`, always the
//! complete step); the freezing temperature comes from `--tf`, the file's `Tf` (degC), or
//! the default −1.8 °C.

//!
//! Files: this one holds the arguments and the reading and dispatch of the command;
//! `forcing.rs` the closing and opening per column, `settings.rs` the parameter overrides
//! and the global attributes, `area_volume.rs` the area-volume step, `complete.rs` the
//! complete step.

mod area_volume;
mod complete;
mod forcing;
mod settings;

use std::path::PathBuf;

use ndarray::{Array1, Array2};
use pressridge::io::itd_netcdf::{
    ReadOptions, SnowTracers, has_variable, read_itd_with, read_packed_tracers, read_snow_tracers,
};
use pressridge::io::refuse_output_over_input;
use pressridge::itd::{
    CategoryBounds, RidgeOptions, category_bounds,
    details::{CiceLayoutSpec, CiceTracerFlags, TracerLayout},
};

use crate::BoxError;
use crate::strength::RidgingArgs;
use forcing::{deformation, host_rates};
use pressridge::io::itd_netcdf::FileClosing;
use settings::parse_all_params;

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
    /// (`divu` in s-1, or CICE history %/day, converted; other units or none are refused).
    #[arg(long, allow_negative_numbers = true)]
    pub convergence: Option<f64>,
    /// Shear term (1/s, >= 0) for every column; default: from the file's `shear` (s-1: the
    /// term itself; CICE history %/day: the strain rate, converted, term formed with divu),
    /// else 0. With both --convergence and --shear the file's divu and shear are not read.
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
    #[command(flatten)]
    pub ridging: RidgingArgs,
    /// Friction pair MU,MU_W (dimensionless) of the set of --mu-rdg-table to use [default:
    /// 1.0,0.6].
    #[arg(long, value_name = "MU,MU_W", requires = "mu_rdg_table", value_parser = crate::strength::parse_friction)]
    pub friction: Option<(f64, f64)>,
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
    /// The tracers are packed in one array (--tracer-var, default `trcrn`: Icepack column
    /// driver's history `trcrn(time, ncat, ntrcr, ni)`) in this layout, given by Icepack's
    /// names: `nilyr=N,nslyr=N` and the switches that are on (`tr_iage`, `tr_FY`, `tr_lvl`,
    /// `tr_pond_lvl`, `tr_pond_topo`, `tr_pond_sealvl`, `tr_snow`, `tr_fsd,nfsd=N`,
    /// `tr_iso,n_iso=N`, `tr_aero,n_aero=N`, `tr_brine`), or the preset `icedrv` (the
    /// column driver's defaults: nilyr=7,nslyr=1,tr_lvl,tr_pond_lvl). The output holds the
    /// array again, in the same dimensions.
    #[arg(long, value_name = "SPEC")]
    pub tracer_layout: Option<String>,
    /// With --tracer-layout: the packed tracer variable (default `trcrn`).
    #[arg(long, value_name = "NAME")]
    pub tracer_var: Option<String>,
    /// Complete step only: skip Icepack's clean-up after ridging (`docleanup = false`).
    #[arg(long)]
    pub no_cleanup: bool,
    /// Complete step only: no rebinning in the clean-up (`dorebin = false`).
    #[arg(long)]
    pub no_rebin: bool,
}

/// Runs `pressridge ridge-step`.
pub fn run(args: Args) -> Result<(), BoxError> {
    let mut inputs = vec![("--input", args.input.as_path())];
    if let Some(t) = &args.ridging.mu_rdg_table {
        inputs.push(("--mu-rdg-table", t.as_path()));
    }
    refuse_output_over_input(&args.output, "--output", &inputs)?;
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
    let grid = read_itd_with(
        &args.input,
        &ReadOptions {
            category_dim: args.category_dim.clone(),
            // The file's deformation is read only where it is used: not with the host's
            // rates, nor with both rates on the command line (a history whose `divu` has no
            // unit, as Icepack's column driver writes it, then runs).
            without_deformation: host || (args.convergence.is_some() && args.shear.is_some()),
        },
    )?;
    let ncol = grid.ncol();
    let ncat = grid.ncat();
    let snow = read_tracers(&args, &grid)?;
    let forcing = if host {
        host_rates(&args, &grid)?
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
    let all = parse_all_params(&args)?;
    let o = RidgeOptions {
        participation: args.ridging.participation.into(),
        redistribution: crate::strength::redistribution(
            args.ridging.redistribution,
            args.ridging.mu_rdg_table.as_deref(),
            args.friction,
        )?,
        params: all.itd,
    };
    match (snow, forcing) {
        (Some(st), forcing) => complete::run_complete(
            &args,
            grid,
            (st, true),
            forcing,
            (hin_max, bounds_source),
            aice0,
            (o, all),
        ),
        // The host's rates need the complete step; without snow or tracers it runs on
        // empty ones (zero snow, zero tracers of the minimal CICE layout), not written out.
        (None, forcing @ FileClosing::Rates { .. }) => {
            let layout = TracerLayout::cice(1, 1, CiceTracerFlags::default())?;
            let nt = layout.ntrcr();
            let st = SnowTracers {
                layout,
                vsnon: Array2::zeros((ncat, ncol)),
                trcrn: ndarray::Array3::zeros((ncat, nt, ncol)),
                missing: None,
                fill_value: None,
                packed: None,
            };
            complete::run_complete(
                &args,
                grid,
                (st, false),
                forcing,
                (hin_max, bounds_source),
                aice0,
                (o, all),
            )
        }
        (None, FileClosing::Deformation { convergence, shear }) => area_volume::run(
            &args,
            grid,
            (convergence, shear),
            (hin_max, bounds_source),
            aice0,
            (o, all),
        ),
    }
}

/// Packed tracer variable read when `--tracer-var` is not given.
const TRACER_VAR_DEFAULT: &str = "trcrn";

/// The snow and tracers of the input: packed in the layout of `--tracer-layout`, else under
/// CICE restart names (`None`: the file has neither). A packed `trcrn` with no
/// `--tracer-layout` is refused with the way to name its layout.
fn read_tracers(
    args: &Args,
    grid: &pressridge::io::itd_netcdf::ItdGrid,
) -> Result<Option<SnowTracers>, BoxError> {
    let var = args.tracer_var.as_deref().unwrap_or(TRACER_VAR_DEFAULT);
    match &args.tracer_layout {
        Some(text) => {
            let spec: CiceLayoutSpec = text.parse().map_err(|e| format!("--tracer-layout: {e}"))?;
            if !has_variable(&args.input, var)? {
                return Err(format!(
                    "--tracer-layout is given but {} has no packed tracer variable `{var}`{}",
                    args.input.display(),
                    if args.tracer_var.is_some() {
                        ""
                    } else {
                        " (name it with --tracer-var)"
                    }
                )
                .into());
            }
            Ok(Some(read_packed_tracers(&args.input, grid, var, &spec)?))
        }
        None => {
            if args.tracer_var.is_some() {
                return Err(
                    "--tracer-var needs --tracer-layout, the layout of the packed tracers".into(),
                );
            }
            if has_variable(&args.input, var)? && !has_variable(&args.input, "Tsfcn")? {
                return Err(format!(
                    "{} holds the packed tracer array `{var}`: name its layout with \
                     --tracer-layout in Icepack's names, e.g. `--tracer-layout icedrv` for the \
                     column driver's defaults or `--tracer-layout \
                     nilyr=7,nslyr=1,tr_iage,tr_FY,tr_lvl,tr_pond_lvl`",
                    args.input.display()
                )
                .into());
            }
            Ok(read_snow_tracers(&args.input, grid)?)
        }
    }
}
