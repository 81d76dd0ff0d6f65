//! `pressridge plot-strength`: a map of ice strength on a 2-D grid (PNG or SVG).
//!
//! Either plots the `strength` variable of a file written by `pressridge strength`, or, with
//! one or more `--cf` (constant C_f) or `--cf-table` (C_f of the ridging ice's thickness from a
//! table), computes the strength of a thickness-distribution file for each and draws the
//! panels side by side on one colour scale, printing a summary table.

use std::path::PathBuf;

use ndarray::Array1;
use pressridge::io::itd_netcdf::{ReadOptions, has_variable, read_field, read_fill, read_itd_with};
use pressridge::io::refuse_output_over_input;
use pressridge::itd::details::strength_batch_masked;
use pressridge::plot::strength_map::{Panel, default_width, draw_strength_maps};

use crate::BoxError;
use crate::strength::{FormulaArg, RidgingArgs, options, redistribution};

/// Arguments of `pressridge plot-strength`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// A file with `strength` (from `pressridge strength`), or a thickness distribution with
    /// `--cf`.
    #[arg(long)]
    pub input: PathBuf,
    /// Output figure: PNG, or SVG when the name ends in `.svg`.
    #[arg(long)]
    pub output: PathBuf,
    /// Figure width (px); fonts scale with it. Default: 500 per panel + 160 for the colour
    /// bar.
    #[arg(long)]
    pub width: Option<u32>,
    /// Compute and draw the Rothrock strength for this C_f (repeatable: one panel each).
    #[arg(long)]
    pub cf: Vec<f64>,
    /// Compute and draw the Rothrock strength with the thickness-dependent C_f of this table
    /// (a `--cf-table` of `pressridge strength`, e.g. from `pressridge tabulate`; repeatable).
    #[arg(long)]
    pub cf_table: Vec<PathBuf>,
    /// The ridging options of the strengths of --cf and --cf-table.
    #[command(flatten)]
    pub ridging: RidgingArgs,
}

fn summary(label: &str, v: &[f64], ice: &[bool]) -> String {
    let mut s: Vec<f64> = v
        .iter()
        .zip(ice)
        .filter(|(_, i)| **i)
        .map(|(x, _)| *x)
        .collect();
    s.sort_by(f64::total_cmp);
    if s.is_empty() {
        return format!("| {label} | 0 | - | - | - | - |");
    }
    let mean = s.iter().sum::<f64>() / s.len() as f64;
    let med = s[s.len() / 2];
    format!(
        "| {label} | {} | {:.1} | {:.1} | {:.1} | {:.1} |",
        s.len(),
        s[0] / 1e3,
        med / 1e3,
        mean / 1e3,
        s[s.len() - 1] / 1e3
    )
}

/// Runs `pressridge plot-strength`.
pub fn run(args: Args) -> Result<(), BoxError> {
    let mut inputs = vec![("--input", args.input.as_path())];
    inputs.extend(args.cf_table.iter().map(|t| ("--cf-table", t.as_path())));
    if let Some(t) = &args.ridging.mu_rdg_table {
        inputs.push(("--mu-rdg-table", t.as_path()));
    }
    let redist = redistribution(
        args.ridging.redistribution,
        args.ridging.mu_rdg_table.as_deref(),
        None,
    )?;
    refuse_output_over_input(&args.output, "--output", &inputs)?;
    let mut titles = Vec::new();
    let mut fields = Vec::new();
    let (ny, nx, ice): (usize, usize, Vec<bool>);
    if args.cf.is_empty() && args.cf_table.is_empty() {
        if !has_variable(&args.input, "strength")? {
            return Err(format!(
                "{}: no `strength` variable; run `pressridge strength` first or pass --cf",
                args.input.display()
            )
            .into());
        }
        let (dims, mut v) = read_field(&args.input, "strength")?;
        // Masked (fill) cells are drawn grey.
        if let Some(f) = read_fill(&args.input, "strength")? {
            v.iter_mut()
                .filter(|x| **x == f)
                .for_each(|x| *x = f64::NAN);
        }
        if dims.len() != 2 {
            return Err(format!("`strength` must be 2-D, has dimensions {dims:?}").into());
        }
        (ny, nx) = (dims[0].1, dims[1].1);
        ice = v.iter().map(|x| x.is_finite() && *x > 0.0).collect();
        titles.push("strength".to_string());
        fields.push(v);
    } else {
        let grid = read_itd_with(
            &args.input,
            &ReadOptions {
                without_deformation: true,
                ..ReadOptions::default()
            },
        )?;
        // Dimensions of length 1 (e.g. the one time of a CICE history file) do not count.
        let map_dims: Vec<&(String, usize)> =
            grid.spatial_dims.iter().filter(|d| d.1 > 1).collect();
        if map_dims.len() != 2 {
            return Err(format!(
                "a map needs 2 spatial dimensions (besides those of length 1), the input has {:?}",
                grid.spatial_dims
            )
            .into());
        }
        (ny, nx) = (map_dims[0].1, map_dims[1].1);
        ice = (0..grid.ncol())
            .map(|c| grid.aicen.column(c).sum() > 0.0)
            .collect();
        let constants = args
            .cf
            .iter()
            .map(|&cf| (format!("C_f = {cf}"), Some(cf), None));
        let tables = args.cf_table.iter().map(|t| {
            let name = t.file_name().map_or_else(
                || t.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            );
            (format!("C_f from {name}"), None, Some(t.as_path()))
        });
        for (title, cf, table) in constants.chain(tables) {
            let o = options(
                args.ridging.participation,
                redist,
                FormulaArg::Rothrock,
                cf,
                None,
                table,
                None,
            )?;
            let mut p = Array1::zeros(grid.ncol());
            strength_batch_masked(
                grid.aicen.view(),
                grid.vicen.view(),
                grid.aice0.as_ref().map(|a| a.view()),
                grid.valid.as_ref().map(|v| v.view()),
                f64::NAN,
                &o,
                p.view_mut(),
            )
            .map_err(|e| grid.locate(&args.input, e))?;
            titles.push(title);
            fields.push(p.to_vec());
        }
    }
    let panels: Vec<Panel<'_>> = titles
        .iter()
        .zip(&fields)
        .map(|(t, v)| Panel {
            title: t,
            values: v,
        })
        .collect();
    let width = args.width.unwrap_or_else(|| default_width(panels.len()));
    draw_strength_maps(&args.output, &panels, ny, nx, width)?;
    println!("| field | ice cells | min (kN/m) | median (kN/m) | mean (kN/m) | max (kN/m) |");
    println!("|---|---|---|---|---|---|");
    for (t, v) in titles.iter().zip(&fields) {
        println!("{}", summary(t, v, &ice));
    }
    Ok(())
}
