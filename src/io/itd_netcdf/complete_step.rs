//! The complete ridging step on a file's columns ([`step_complete`]): the column mask, the
//! step of [`crate::itd::ridge_step_batch`] (snow, tracers, ocean fluxes), its checks and the
//! output file with the distribution, the tracers as they came (packed or one variable each),
//! the fluxes, the freezing temperature and the constants used. The read–step–write pipeline
//! of `pressridge ridge-step`; the command reads its arguments, the grid and the forcing and
//! calls this.

use std::path::Path;

use ndarray::{Array1, Array2, ArrayViewMut1, ArrayViewMut2, Axis};

use super::{
    CellField, DimField, FieldMeta, ItdGrid, NC_FILL_DOUBLE, NetcdfError, Output, SnowTracers,
    history_line, write_output,
};
use crate::itd::{
    RidgeStepOptions,
    details::{
        BatchClosing, BatchForcing, CATEGORY_OUTPUTS, CELL_OUTPUTS, OutputMeta, RidgeStepParams,
        SPECIES_OUTPUTS, StepBatchMut, StepBatchOutputs, TracerLayout, species_counts,
    },
    ridge_step_batch,
};

/// Closing and opening of the step per column.
pub enum FileClosing {
    /// CICE: the convergence and shear terms (1/s) of every column.
    Deformation {
        /// Convergence −div u (1/s), `ncol` values.
        convergence: Array1<f64>,
        /// The shear term ½(Δ − |div u|) (1/s), `ncol` values.
        shear: Array1<f64>,
    },
    /// SIS2: the host's net closing and opening rates (1/s), read from the file.
    Rates {
        /// The net closing rate's variable and values.
        closing: (String, CellField),
        /// The opening rate's variable and values.
        opening: (String, CellField),
    },
}

/// The freezing temperature of every column (°C).
pub struct FreezingTemperature {
    /// `ncol` values (°C).
    pub values: Array1<f64>,
    /// Columns where the input variable holds data (`None`: every column).
    pub valid: Option<Array1<bool>>,
    /// Where the values come from, for the output's `tf` attribute.
    pub description: String,
    /// The input variable they were read from, written back to the output under that name so
    /// that a chained step uses it again; `None` for a constant.
    pub variable: Option<String>,
}

/// What [`step_complete`] needs besides the file's distribution, snow and tracers.
pub struct CompleteStep<'a> {
    /// The input file (for messages).
    pub input: &'a Path,
    /// The output file (written atomically).
    pub output: &'a Path,
    /// Category bounds (m), `ncat + 1` values.
    pub hin_max: &'a [f64],
    /// Where the bounds come from, for the output's `category_bounds` attribute.
    pub bounds_source: &'a str,
    /// The closing and opening per column.
    pub closing: FileClosing,
    /// The freezing temperature per column.
    pub tf: FreezingTemperature,
    /// Time step (s).
    pub dt: f64,
    /// Dynamic subcycles per step (Icepack `ndtd`, ≥ 1).
    pub ndtd: u32,
    /// The step's options and constants.
    pub options: &'a RidgeStepOptions,
    /// The caller's global attributes (its options), written before the step's own.
    pub attributes: Vec<(String, String)>,
}

/// The snow, tracers and distribution of the file as [`step_complete`] takes them.
pub struct StepInput {
    /// The distribution (its mask is the input's land mask).
    pub grid: ItdGrid,
    /// Open water per column (1).
    pub aice0: Array1<f64>,
    /// Snow and tracers.
    pub snow: SnowTracers,
    /// Whether the file had snow or tracers to write back (else they are the zeros of the
    /// host's rates and are not written).
    pub write_tracers: bool,
}

/// The step's outputs before they are written: per cell, per category and per species.
struct StepOutputs {
    aice: Array1<f64>,
    cell: Vec<Array1<f64>>,
    cats: Vec<Array2<f64>>,
    species: Vec<Array2<f64>>,
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

/// The complete step (snow, tracers, ocean fluxes) on the file's columns, written to
/// `step.output`. A column is stepped where the distribution, snow, every tracer, the host's
/// rates and the freezing temperature have data; every other column is missing (the fill
/// value) in every output.
pub fn step_complete(input: StepInput, step: CompleteStep<'_>) -> Result<(), NetcdfError> {
    let StepInput {
        mut grid,
        mut aice0,
        mut snow,
        write_tracers,
    } = input;
    let mut valid = and_mask(grid.valid.clone(), snow.missing.as_ref());
    valid = and_mask(valid, step.tf.valid.as_ref());
    if let FileClosing::Rates { closing, opening } = &step.closing {
        valid = and_mask(valid, closing.1.valid.as_ref());
        valid = and_mask(valid, opening.1.valid.as_ref());
    }
    let fill = grid
        .fill_value
        .or(snow.fill_value)
        .unwrap_or(NC_FILL_DOUBLE);
    let mut out = run_step(
        &mut grid,
        &mut aice0,
        &mut snow,
        &step,
        valid.as_ref(),
        fill,
    )?;
    for (m, x) in CELL_OUTPUTS.iter().zip(&out.cell) {
        check_finite_masked(&grid, step.input, valid.as_ref(), m.name, x)?;
    }
    if let Some(v) = &valid {
        blank_masked(v, fill, &mut grid, &mut aice0, &mut out.aice, &mut snow);
    }
    grid.aice0 = Some(aice0);
    grid.valid = valid;
    write_step(&grid, &snow, write_tracers, &out, step, fill)
}

/// [`ridge_step_batch`] on the file's columns, its outputs allocated here.
fn run_step(
    grid: &mut ItdGrid,
    aice0: &mut Array1<f64>,
    snow: &mut SnowTracers,
    step: &CompleteStep<'_>,
    valid: Option<&Array1<bool>>,
    fill: f64,
) -> Result<StepOutputs, NetcdfError> {
    let (ncat, ncol) = (grid.ncat(), grid.ncol());
    let mut out = StepOutputs {
        aice: (0..ncol).map(|c| grid.aicen.column(c).sum()).collect(),
        cell: CELL_OUTPUTS.iter().map(|_| Array1::zeros(ncol)).collect(),
        cats: CATEGORY_OUTPUTS
            .iter()
            .map(|_| Array2::zeros((ncat, ncol)))
            .collect(),
        // Aerosol, isotope and bio fluxes, one row per species or bio tracer of the layout.
        species: species_counts(&snow.layout)
            .iter()
            .map(|&n| Array2::zeros((n, ncol)))
            .collect(),
    };
    let closing = match &step.closing {
        FileClosing::Rates { closing, opening } => BatchClosing::Rates {
            closing: closing.1.values.view(),
            opening: opening.1.values.view(),
        },
        FileClosing::Deformation { convergence, shear } => BatchClosing::Deformation {
            convergence: convergence.view(),
            shear: shear.view(),
        },
    };
    let mut cell_v: Vec<ArrayViewMut1<'_, f64>> =
        out.cell.iter_mut().map(|x| x.view_mut()).collect();
    let mut cat_v: Vec<ArrayViewMut2<'_, f64>> =
        out.cats.iter_mut().map(|x| x.view_mut()).collect();
    let mut sp_v: Vec<ArrayViewMut2<'_, f64>> =
        out.species.iter_mut().map(|x| x.view_mut()).collect();
    ridge_step_batch(
        StepBatchMut {
            aicen: grid.aicen.view_mut(),
            vicen: grid.vicen.view_mut(),
            vsnon: snow.vsnon.view_mut(),
            trcrn: snow.trcrn.view_mut(),
            aice0: aice0.view_mut(),
            aice: out.aice.view_mut(),
        },
        step.hin_max,
        BatchForcing {
            closing,
            tf: step.tf.values.view(),
            dt: step.dt,
            ndtd: step.ndtd,
            valid: valid.map(|v| v.view()),
        },
        step.options,
        &snow.layout,
        StepBatchOutputs {
            cell: &mut cell_v,
            category: Some(&mut cat_v),
            species: Some(&mut sp_v),
            fill,
        },
    )
    .map_err(|e| grid.locate(step.input, e))?;
    Ok(out)
}

/// Error for a non-finite output in a stepped column (the library refuses such columns
/// already; this guards the file).
fn check_finite_masked(
    grid: &ItdGrid,
    input: &Path,
    valid: Option<&Array1<bool>>,
    name: &str,
    values: &Array1<f64>,
) -> Result<(), NetcdfError> {
    for (c, &x) in values.iter().enumerate() {
        if valid.is_some_and(|v| !v[c]) {
            continue;
        }
        if !x.is_finite() {
            return Err(NetcdfError::Value {
                path: input.to_path_buf(),
                var: name.to_string(),
                msg: format!(
                    "column {c} at ({}): the computed `{name}` is {x}",
                    grid.spatial_index(c)
                ),
            });
        }
    }
    Ok(())
}

/// Masked columns are missing in every output: the fill value in the distribution, snow and
/// tracers.
fn blank_masked(
    valid: &Array1<bool>,
    fill: f64,
    grid: &mut ItdGrid,
    aice0: &mut Array1<f64>,
    aice: &mut Array1<f64>,
    snow: &mut SnowTracers,
) {
    for (c, ok) in valid.iter().enumerate() {
        if !ok {
            aice0[c] = fill;
            aice[c] = fill;
            grid.aicen.column_mut(c).fill(fill);
            grid.vicen.column_mut(c).fill(fill);
            snow.vsnon.column_mut(c).fill(fill);
            snow.trcrn
                .index_axis_mut(Axis(2), c)
                .iter_mut()
                .for_each(|x| *x = fill);
        }
    }
}

/// A field's metadata from its name, units and long name.
fn meta<'a>(name: &'a str, units: &'a str, long_name: &'a str) -> FieldMeta<'a> {
    FieldMeta {
        name,
        units,
        long_name,
        standard_name: None,
    }
}

/// The units and long name of each tracer of `layout`.
fn tracer_units(layout: &TracerLayout) -> Vec<(&'static str, &'static str)> {
    (0..layout.ntrcr())
        .map(|it| {
            let role = layout.field_of(it).expect("index in range").0.role;
            (role.units(), role.long_name())
        })
        .collect()
}

/// Writes the stepped distribution, snow, tracers, fluxes and the step's attributes.
fn write_step(
    grid: &ItdGrid,
    snow: &SnowTracers,
    write_tracers: bool,
    out: &StepOutputs,
    step: CompleteStep<'_>,
    fill: f64,
) -> Result<(), NetcdfError> {
    let layout = &snow.layout;
    let names = layout.cice_restart_names();
    let units = tracer_units(layout);
    // One variable per tracer, unless the tracers came packed (then one array) or the file
    // had none. Category fields in C order (category slowest, then the columns).
    let per_variable = write_tracers && snow.packed.is_none();
    let tracer_data: Vec<Vec<f64>> = (0..if per_variable { layout.ntrcr() } else { 0 })
        .map(|it| {
            let t = snow.trcrn.index_axis(Axis(1), it);
            t.as_standard_layout().iter().copied().collect()
        })
        .collect();
    let vsnon_c = snow.vsnon.as_standard_layout().into_owned();
    let mut category_fields: Vec<(FieldMeta<'_>, &[f64])> = Vec::new();
    if write_tracers {
        category_fields.push((
            meta(
                "vsnon",
                "m",
                "snow volume per unit grid-cell area in each thickness category",
            ),
            vsnon_c.as_slice().expect("standard layout"),
        ));
    }
    let packed_data = snow
        .packed
        .as_ref()
        .map(|p| p.to_file_order(grid, &snow.trcrn));
    let dim_fields: Vec<DimField<'_>> = match (&snow.packed, &packed_data) {
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
        category_fields.push((meta(name, u, ln), data));
    }
    let cat_c: Vec<Array2<f64>> = out
        .cats
        .iter()
        .map(|x| x.as_standard_layout().into_owned())
        .collect();
    for (m, x) in CATEGORY_OUTPUTS.iter().zip(&cat_c) {
        category_fields.push((
            meta(m.name, m.units, m.long_name),
            x.as_slice().expect("standard layout"),
        ));
    }
    let mut fields: Vec<(FieldMeta<'_>, &[f64])> = vec![(
        meta(
            "aice",
            "1",
            "total ice area fraction (recomputed by the clean-up)",
        ),
        out.aice.as_slice().expect("contiguous"),
    )];
    for (m, x) in CELL_OUTPUTS.iter().zip(&out.cell) {
        fields.push((
            meta(m.name, m.units, m.long_name),
            x.as_slice().expect("contiguous"),
        ));
    }
    // Per species a cell field, numbered as CICE numbers its species (`faero_ocn001`, ...).
    let species_rows: Vec<(String, &OutputMeta, Vec<f64>)> = SPECIES_OUTPUTS
        .iter()
        .zip(&out.species)
        .flat_map(|(m, x)| {
            x.outer_iter()
                .enumerate()
                .map(move |(k, row)| (format!("{}{:03}", m.name, k + 1), m, row.to_vec()))
        })
        .collect();
    for (name, m, x) in &species_rows {
        fields.push((meta(name, m.units, m.long_name), x));
    }
    // A per-column Tf read from the input goes to the output too (masked columns hold the
    // fill value).
    let mut tf_out = step.tf.values.clone();
    if let Some(tf_name) = &step.tf.variable {
        if let Some(v) = &grid.valid {
            for (x, ok) in tf_out.iter_mut().zip(v) {
                if !ok {
                    *x = fill;
                }
            }
        }
        fields.push((
            meta(
                tf_name,
                "degC",
                "freezing temperature (given to emptied categories' surface temperature)",
            ),
            tf_out.as_slice().expect("contiguous"),
        ));
    }
    let global = step_attributes(&step, snow, write_tracers, &names);
    write_output(
        step.output,
        &Output {
            grid,
            write_itd: true,
            hin_max: Some(step.hin_max),
            fields: &fields,
            category_fields: &category_fields,
            dim_fields: &dim_fields,
            global: &global,
            fill: grid.valid.as_ref().map(|_| fill),
            history: Some(&history_line()),
        },
    )
}

/// The output's global attributes: the caller's, then the constants used (the one list of
/// [`RidgeStepParams::FIELDS`], each with its units), the ice density and the step's
/// settings.
fn step_attributes(
    step: &CompleteStep<'_>,
    snow: &SnowTracers,
    write_tracers: bool,
    names: &[String],
) -> Vec<(String, String)> {
    let opts = step.options;
    let mut global = step.attributes.clone();
    global.push(("rhoi".into(), format!("{} kg m-3", opts.params.rhoi)));
    for f in RidgeStepParams::FIELDS {
        let v = opts.step.get(f.name).expect("a listed constant");
        global.push((f.name.into(), format!("{v} {}", f.units)));
    }
    global.push(("salt_flux".into(), opts.step.salt_flux.name().into()));
    global.push(("category_bounds".into(), step.bounds_source.into()));
    global.push((
        "ridging_step".into(),
        "complete (Icepack icepack_step_ridge: snow, tracers, ocean fluxes)".into(),
    ));
    global.push(("ndtd".into(), step.ndtd.to_string()));
    global.push(("tf".into(), step.tf.description.clone()));
    global.push(("cleanup".into(), opts.cleanup.to_string()));
    global.push(("rebin".into(), opts.rebin.to_string()));
    if let Some(p) = &snow.packed {
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
    global
}
