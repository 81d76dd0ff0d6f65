//! `pressridge strength`: ice strength P (N/m) of a gridded thickness distribution.

use std::path::PathBuf;
use std::sync::Arc;

use clap::ValueEnum;
use ndarray::Array1;
use pressridge::io::itd_netcdf::{
    NC_FILL_DOUBLE, Output, ReadOptions, STRENGTH_META, history_line, read_cf_table_at_friction,
    read_itd_with, write_output,
};
use pressridge::io::refuse_output_over_input;
use pressridge::itd::{
    Cf, ItdParams, StrengthOptions,
    details::{
        CF_CLAMPED_MATERIAL_SHARE, CfPreset, Participation, Redistribution, StrengthFormula,
        strength_batch_masked,
    },
};

use crate::BoxError;

/// Participation function.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum PartArg {
    /// Thorndike et al. (1975), G* = 0.15.
    Thorndike,
    /// Lipscomb et al. (2007), a* = 0.05 (CICE default).
    Exponential,
}

/// Redistribution of ridged ice.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum RedistArg {
    /// Hibler (1980), H* = 25 m.
    Uniform,
    /// Lipscomb et al. (2007), mu = 3 m^0.5 (CICE default).
    Exponential,
    /// Lipscomb et al. (2007) with mu_rdg per category thickness from the simulated ridges
    /// of --mu-rdg-table (clamped at its ends, counted).
    Table,
}

/// The ridging options every thickness-distribution command takes (`ridge-step`, `strength`,
/// `plot-strength`): participation, redistribution and its μ_rdg table.
#[derive(clap::Args, Debug)]
pub struct RidgingArgs {
    /// Participation function.
    #[arg(long, value_enum, default_value = "exponential")]
    pub participation: PartArg,
    /// Ridged-ice redistribution.
    #[arg(long, value_enum, default_value = "exponential")]
    pub redistribution: RedistArg,
    /// With --redistribution table: the ridging table (`pressridge tabulate`) whose `mu_rdg`
    /// (m^0.5) against thickness sets each category's e-folding scale, at the command's
    /// friction pair (--friction where it has one; else 1.0,0.6).
    #[arg(long, value_name = "FILE")]
    pub mu_rdg_table: Option<PathBuf>,
}

/// Strength formula.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum FormulaArg {
    /// Rothrock (1975) with C_f (CICE default).
    Rothrock,
    /// Hibler (1979), P* = 2.75e4 N/m^2, C* = 20.
    Hibler,
}

/// Named C_f values.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum PresetArg {
    /// Hibler (1980): 2.
    Hibler1980,
    /// Flato (1991): 15.
    Flato1991,
    /// CICE/Icepack default: 17.
    Cice,
}

/// The library option named as the clap value `a` (the clap names are the library's
/// `from_name` spellings; `clap_names_are_the_library_names` checks every one).
fn by_name<T>(a: impl ValueEnum, from_name: fn(&str) -> Option<T>) -> T {
    let v = a.to_possible_value().expect("no value is hidden");
    from_name(v.get_name()).expect("every clap name is a library name")
}

impl From<PartArg> for Participation {
    fn from(a: PartArg) -> Self {
        by_name(a, Participation::from_name)
    }
}
/// The redistribution of `--redistribution` (`table`: μ_rdg of the ridging table `table`, at
/// the friction pair `friction`, default 1.0,0.6).
pub fn redistribution(
    a: RedistArg,
    table: Option<&std::path::Path>,
    friction: Option<(f64, f64)>,
) -> Result<Redistribution, BoxError> {
    match (a, table) {
        (RedistArg::Table, Some(t)) => Ok(Redistribution::Table(
            pressridge::io::itd_netcdf::read_mu_rdg_table_at_friction(t, friction)?,
        )),
        (RedistArg::Table, None) => Err("--redistribution table needs --mu-rdg-table FILE, a \
             ridging table of `pressridge tabulate` with `mu_rdg` (runs with ridge columns)"
            .into()),
        (_, Some(_)) => Err("--mu-rdg-table is used with --redistribution table only".into()),
        (a, None) => Ok(by_name(a, Redistribution::from_name)),
    }
}
impl From<FormulaArg> for StrengthFormula {
    fn from(a: FormulaArg) -> Self {
        by_name(a, StrengthFormula::from_name)
    }
}

/// Arguments of `pressridge strength`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input NetCDF with aicen, vicen (the category dimension found by name: nc, ncat or ct;
    /// every other dimension, e.g. time, nj, ni, is kept) and optionally aice0.
    #[arg(long)]
    pub input: PathBuf,
    /// Output NetCDF; gets `strength` (N/m) on the input's other dimensions, with their
    /// coordinates.
    #[arg(long)]
    pub output: PathBuf,
    /// Name of the category dimension of aicen/vicen, when it is none of nc, ncat, ct.
    #[arg(long, value_name = "NAME")]
    pub category_dim: Option<String>,
    #[command(flatten)]
    pub ridging: RidgingArgs,
    /// Strength formula.
    #[arg(long, value_enum, default_value = "rothrock")]
    pub strength: FormulaArg,
    /// Constant C_f (dimensionless); default 17 (CICE).
    #[arg(long, allow_negative_numbers = true, conflicts_with_all = ["cf_preset", "cf_table"])]
    pub cf: Option<f64>,
    /// Named constant C_f.
    #[arg(long, value_enum, conflicts_with = "cf_table")]
    pub cf_preset: Option<PresetArg>,
    /// NetCDF table of C_f (`cf`) against ridging-ice thickness (`thickness`, m): a ridging
    /// table of `pressridge tabulate` (C_f at the `--friction` pair) or a plain C_f table.
    #[arg(long)]
    pub cf_table: Option<PathBuf>,
    /// Friction pair MU,MU_W (dimensionless: between blocks above and below the water line)
    /// of the simulations whose C_f a `--cf-table` (and whose mu_rdg a `--mu-rdg-table`)
    /// gives [default: 1.0,0.6, Hopkins 1994's thickness set]. The table must hold that
    /// pair; the choice is written to the output.
    #[arg(long, value_name = "MU,MU_W", value_parser = parse_friction)]
    pub friction: Option<(f64, f64)>,
    /// Override a parameter, NAME=VALUE (repeatable), e.g. `--param mu_rdg=4`; names as the
    /// fields of `pressridge::itd::ItdParams`.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    pub params: Vec<String>,
}

/// CICE's default parameters with the `NAME=VALUE` overrides of --param (the library's
/// parser, which names the closest valid name of a misspelt one).
pub fn parse_params(list: &[String]) -> Result<ItdParams, BoxError> {
    let mut p = ItdParams::default();
    crate::params::apply(&mut p, &crate::params::settings(None, list)?)?;
    Ok(p)
}

/// Global attributes listing the parameters that differ from CICE's defaults.
pub fn describe_params(list: &[String]) -> (String, String) {
    (
        "parameter_overrides".into(),
        if list.is_empty() {
            "none".into()
        } else {
            list.join(", ")
        },
    )
}

/// Parses `--friction MU,MU_W` (two finite non-negative numbers).
pub fn parse_friction(s: &str) -> Result<(f64, f64), String> {
    let bad = || format!("`{s}`: expected MU,MU_W, two finite non-negative numbers, e.g. 1.0,0.6");
    let (a, b) = s.split_once(',').ok_or_else(bad)?;
    let (mu, mu_w): (f64, f64) = (
        a.trim().parse().map_err(|_| bad())?,
        b.trim().parse().map_err(|_| bad())?,
    );
    if !(mu.is_finite() && mu_w.is_finite() && mu >= 0.0 && mu_w >= 0.0) {
        return Err(bad());
    }
    Ok((mu, mu_w))
}

/// Builds the strength options from the shared flags (`redistribution` as
/// [`redistribution`] gives it).
pub fn options(
    participation: PartArg,
    redistribution: Redistribution,
    formula: FormulaArg,
    cf: Option<f64>,
    cf_preset: Option<PresetArg>,
    cf_table: Option<&std::path::Path>,
    friction: Option<(f64, f64)>,
) -> Result<StrengthOptions, BoxError> {
    let cf = if let Some(t) = cf_table {
        Cf::Table(Arc::new(read_cf_table_at_friction(t, friction)?))
    } else if let Some(p) = cf_preset {
        match p {
            PresetArg::Hibler1980 => CfPreset::Hibler1980.into(),
            PresetArg::Flato1991 => CfPreset::Flato1991.into(),
            PresetArg::Cice => CfPreset::Cice.into(),
        }
    } else {
        let value = cf.unwrap_or(CfPreset::Cice.value());
        if let Some(why) = pressridge::itd::limits::CF.violation(value) {
            return Err(format!("--cf: {why}").into());
        }
        Cf::Constant(value)
    };
    Ok(StrengthOptions {
        participation: participation.into(),
        redistribution,
        formula: formula.into(),
        cf,
        ..Default::default()
    })
}

/// Global attributes describing the strength options.
pub fn describe(o: &StrengthOptions) -> Vec<(String, String)> {
    let mut v = vec![
        ("participation".into(), o.participation.name().into()),
        ("redistribution".into(), o.redistribution.name().into()),
        ("strength_formula".into(), o.formula.name().into()),
        ("cf".into(), o.cf.describe()),
    ];
    v.extend(describe_mu_rdg(&o.redistribution));
    v
}

/// The attribute `mu_rdg_table` (its nodes, thickness m: mu_rdg m^0.5) of a table
/// redistribution; none otherwise.
pub fn describe_mu_rdg(r: &Redistribution) -> Option<(String, String)> {
    r.mu_rdg_table().map(|t| {
        let nodes: Vec<String> = t
            .thickness()
            .iter()
            .zip(t.values())
            .map(|(h, m)| format!("{h}: {m}"))
            .collect();
        (
            "mu_rdg_table".into(),
            format!(
                "thickness (m): mu_rdg (m^0.5), linear, held at the ends: {}",
                nodes.join(", ")
            ),
        )
    })
}

/// Refuses an output field with a non-finite value in a column holding data: the inputs
/// there overflowed the formulas, and NaN or inf must not be written as a result.
pub fn check_finite(
    grid: &pressridge::io::itd_netcdf::ItdGrid,
    input: &std::path::Path,
    name: &str,
    values: &[f64],
) -> Result<(), BoxError> {
    for (c, x) in values.iter().enumerate() {
        let masked = grid.valid.as_ref().is_some_and(|v| !v[c]);
        if !masked && !x.is_finite() {
            return Err(format!(
                "{}: column {c} at ({}): the computed `{name}` is {x}: aicen/vicen there are beyond what the formulas can represent",
                input.display(),
                grid.spatial_index(c)
            )
            .into());
        }
    }
    Ok(())
}

/// Runs `pressridge strength`.
pub fn run(args: Args) -> Result<(), BoxError> {
    if args.friction.is_some() && args.cf_table.is_none() && args.ridging.mu_rdg_table.is_none() {
        return Err(
            "--friction chooses the set of a --cf-table or --mu-rdg-table: give one".into(),
        );
    }
    let mut o = options(
        args.ridging.participation,
        redistribution(
            args.ridging.redistribution,
            args.ridging.mu_rdg_table.as_deref(),
            args.friction,
        )?,
        args.strength,
        args.cf,
        args.cf_preset,
        args.cf_table.as_deref(),
        args.friction,
    )?;
    o.params = parse_params(&args.params)?;
    let mut inputs = vec![("--input", args.input.as_path())];
    if let Some(t) = &args.cf_table {
        inputs.push(("--cf-table", t.as_path()));
    }
    if let Some(t) = &args.ridging.mu_rdg_table {
        inputs.push(("--mu-rdg-table", t.as_path()));
    }
    refuse_output_over_input(&args.output, "--output", &inputs)?;
    let grid = read_itd_with(
        &args.input,
        &ReadOptions {
            category_dim: args.category_dim.clone(),
            without_deformation: true,
        },
    )?;
    let mut p = Array1::zeros(grid.ncol());
    let fill = grid.fill_value.unwrap_or(NC_FILL_DOUBLE);
    let summary = strength_batch_masked(
        grid.aicen.view(),
        grid.vicen.view(),
        grid.aice0.as_ref().map(|a| a.view()),
        grid.valid.as_ref().map(|v| v.view()),
        fill,
        &o,
        p.view_mut(),
    )
    .map_err(|e| grid.locate(&args.input, e))?;
    check_finite(
        &grid,
        &args.input,
        "strength",
        p.as_slice().expect("contiguous"),
    )?;
    if summary.cf_clamped_columns > 0 {
        eprintln!(
            "pressridge: note: {} of {} columns had ridging-ice thicknesses outside the C_f table; \
             values were clamped; the clamped ice carries >= {} % of the strength in {} of them \
             (at most {:.1} %)",
            summary.cf_clamped_columns,
            summary.columns,
            CF_CLAMPED_MATERIAL_SHARE * 100.0,
            summary.cf_clamped_material_columns,
            summary.cf_clamped_share_max * 100.0
        );
    }
    if summary.mu_rdg_clamped_columns > 0 {
        eprintln!(
            "pressridge: note: {} of {} columns had ridging-ice thicknesses outside the mu_rdg \
             table; its end values were used",
            summary.mu_rdg_clamped_columns, summary.columns
        );
    }
    let mut global = describe(&o);
    global.push(describe_params(&args.params));
    if o.redistribution.mu_rdg_table().is_some() {
        global.push((
            "mu_rdg_clamped_columns".into(),
            summary.mu_rdg_clamped_columns.to_string(),
        ));
    }
    global.push(("input".into(), args.input.display().to_string()));
    global.push(("category_dimension".into(), grid.ncat_dim.clone()));
    global.push((
        "cf_clamped_columns".into(),
        summary.cf_clamped_columns.to_string(),
    ));
    global.push((
        "cf_clamped_material_columns".into(),
        summary.cf_clamped_material_columns.to_string(),
    ));
    global.push((
        "cf_clamped_share_max".into(),
        format!("{}", summary.cf_clamped_share_max),
    ));
    write_output(
        &args.output,
        &Output {
            grid: &grid,
            write_itd: false,
            hin_max: None,
            fields: &[(STRENGTH_META, p.as_slice().expect("contiguous"))],
            category_fields: &[],
            dim_fields: &[],
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
            history: Some(&history_line()),
        },
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every clap value of the option enums is a library name, and every library option
    /// has a clap value.
    #[test]
    fn clap_names_are_the_library_names() {
        for a in PartArg::value_variants() {
            let _: Participation = (*a).into();
        }
        for a in RedistArg::value_variants() {
            let r = redistribution(*a, None, None);
            // `table` needs its file; every other is a library name.
            assert_eq!(r.is_err(), matches!(a, RedistArg::Table));
        }
        for a in FormulaArg::value_variants() {
            let _: StrengthFormula = (*a).into();
        }
        assert_eq!(PartArg::value_variants().len(), Participation::ALL.len());
        assert_eq!(
            RedistArg::value_variants().len(),
            Redistribution::ALL.len() + 1
        );
        assert_eq!(
            FormulaArg::value_variants().len(),
            StrengthFormula::ALL.len()
        );
    }
}
