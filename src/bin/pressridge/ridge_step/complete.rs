//! The complete step of `ridge-step` (`itd::ridge_step_batch`: snow, tracers, ocean
//! fluxes): the freezing temperature, the column mask, the step and its output file with
//! the tracers, the fluxes and the constants used.

use std::path::Path;

use ndarray::{Array1, Array2, ArrayViewMut1, ArrayViewMut2};
use pressridge::io::itd_netcdf::{
    CellUnits, DimField, FieldMeta, ItdGrid, NC_FILL_DOUBLE, Output, SnowTracers, history_line,
    read_cell_field, write_output,
};
use pressridge::itd::{
    BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, OutputMeta, RidgeOptions,
    RidgeStepOptions, RidgeStepParams, SPECIES_OUTPUTS, SaltFlux, StepBatchMut, ridge_step_batch,
    species_counts,
};

use super::forcing::Forcing;
use super::settings::{AllParams, global_attrs};
use super::{Args, SaltFluxArg, TF_DEFAULT};
use crate::BoxError;

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
pub(super) fn run_complete(
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
        packed,
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
    // Aerosol, isotope and bio fluxes, one row per species or bio tracer of the layout.
    let mut species: Vec<Array2<f64>> = species_counts(&layout)
        .iter()
        .map(|&n| Array2::zeros((n, ncol)))
        .collect();
    {
        let mut cell_v: Vec<ArrayViewMut1<'_, f64>> =
            cell.iter_mut().map(|x| x.view_mut()).collect();
        let mut cat_v: Vec<ArrayViewMut2<'_, f64>> =
            cats.iter_mut().map(|x| x.view_mut()).collect();
        let mut sp_v: Vec<ArrayViewMut2<'_, f64>> =
            species.iter_mut().map(|x| x.view_mut()).collect();
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
            Some(&mut sp_v),
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
    // One variable per tracer, unless the tracers came packed (then one array, below) or
    // the file had none.
    let per_variable = write_tracers && packed.is_none();
    let tracer_data: Vec<Vec<f64>> = (0..if per_variable { nt } else { 0 })
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
    // Tracers as they came: packed in one array, or one variable each.
    let packed_data = packed.as_ref().map(|p| p.to_file_order(&grid, &trcrn));
    let dim_fields: Vec<DimField<'_>> = match (&packed, &packed_data) {
        (Some(p), Some(data)) => vec![DimField {
            name: &p.var,
            dims: p.dims.clone(),
            data,
            attrs: vec![
                (
                    "long_name",
                    "tracers of each thickness category, packed (Icepack trcrn)".into(),
                ),
                ("tracer_layout", p.spec.to_string()),
                ("tracers", names.join(" ")),
                (
                    "tracer_units",
                    units.iter().map(|u| u.0).collect::<Vec<_>>().join(", "),
                ),
            ],
        }],
        _ => Vec::new(),
    };
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
    // Per species a cell field, numbered as CICE numbers its species (`faero_ocn001`, ...).
    let species_rows: Vec<(String, &OutputMeta, Vec<f64>)> = SPECIES_OUTPUTS
        .iter()
        .zip(&species)
        .flat_map(|(m, x)| {
            x.outer_iter()
                .enumerate()
                .map(move |(k, row)| (format!("{}{:03}", m.name, k + 1), m, row.to_vec()))
        })
        .collect();
    for (name, m, x) in &species_rows {
        fields.push((
            FieldMeta {
                name,
                units: m.units,
                long_name: m.long_name,
                standard_name: None,
            },
            x,
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
    if let Some(p) = &packed {
        global.push((
            "tracer_layout".into(),
            format!("{} (packed in `{}`)", p.spec, p.var),
        ));
    }
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
            dim_fields: &dim_fields,
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
            history: Some(&history_line()),
        },
    )?;
    Ok(())
}
