//! The complete step over a block of a host's cells held in its own arrays
//! ([`ridge_step_cells`]): Fortran order, contiguous, one cell after the other
//! (`aicen(ncat, ncol)`, `trcrn(ntrcr, ncat, ncol)`, `faero_ocn(n_aero, ncol)`), fluxes added
//! to as Icepack adds to its arguments. The C ABI's block call (`pressridge_ridge_cells`) is
//! this loop; [`super::batch::ridge_step_batch`] is the same step on `ndarray` views of any
//! strides, with masked columns written as a fill value.

use super::{
    Closing, ColumnMut, OceanFluxes, RidgeStepOptions, StepForcing, StepWorkspace,
    ridge_step_column,
};
use crate::{
    ItdError,
    details::{TracerLayout, species_counts},
};

/// The state of `ncol` cells, stepped in place: `ncat·ncol` values per category field and
/// `ntrcr·ncat·ncol` tracers, cell by cell (column c at `c·ncat..`).
pub struct CellState<'a> {
    /// Category area fractions (1).
    pub aicen: &'a mut [f64],
    /// Category ice volumes per unit area (m).
    pub vicen: &'a mut [f64],
    /// Category snow volumes per unit area (m).
    pub vsnon: &'a mut [f64],
    /// Tracers in the layout's order and units, tracer fastest, then category, then cell.
    pub trcrn: &'a mut [f64],
    /// Open-water fraction (1), `ncol` values.
    pub aice0: &'a mut [f64],
    /// Total ice area (1), `ncol` values.
    pub aice: &'a mut [f64],
}

/// The forcing of `ncol` cells, `ncol` values each.
pub struct CellForcing<'a> {
    /// Icepack `rdg_conv` (1/s, ≥ 0), used without `closing`; `None`: 0.
    pub convergence: Option<&'a [f64]>,
    /// Icepack `rdg_shear` (1/s, ≥ 0), used without `closing`; `None`: 0.
    pub shear: Option<&'a [f64]>,
    /// The host's net closing rates (1/s); with them the opening rates are read from
    /// [`CellOutputs::opening`].
    pub closing: Option<&'a [f64]>,
    /// Freezing temperature (°C); `None`: −1.8 °C.
    pub tf: Option<&'a [f64]>,
    /// Time step (s).
    pub dt: f64,
    /// Dynamic subcycles (Icepack `ndtd`, ≥ 1).
    pub ndtd: u32,
    /// Which cells to step (the others are left as they are); `None`: every cell.
    pub step: Option<&'a dyn Fn(usize) -> bool>,
}

/// What the step returns per cell; `None` where the host does not want it.
#[derive(Default)]
pub struct CellOutputs<'a> {
    /// Opening rate (1/s): read with [`CellForcing::closing`], then the last pass's rate.
    pub opening: Option<&'a mut [f64]>,
    /// Fresh water, salt, heat and pond fluxes (`fresh`, `fsalt` kg m⁻² s⁻¹, `fhocn` W m⁻²,
    /// `fpond` m), added to.
    pub fluxes: [Option<&'a mut [f64]>; 4],
    /// `dardg1dt`, `dardg2dt` (1/s) and `dvirdgdt` (m/s), written.
    pub rates: [Option<&'a mut [f64]>; 3],
    /// Aerosol (kg m⁻² s⁻¹), isotope (kg m⁻² s⁻¹) and bio fluxes, species fastest
    /// (`n·ncol` values for the layout's `n` of each), added to.
    pub species: [Option<&'a mut [f64]>; 3],
}

/// The complete step ([`ridge_step_column`]) of every cell [`CellForcing::step`] selects,
/// cell by cell. Stops at the first failing cell with its
/// 0-based index in [`ItdError::Column`]: earlier cells are stepped, it and later ones
/// unchanged.
///
/// # Panics
/// If a slice is shorter than its documented length for `ncol = state.aice.len()` cells and
/// the layout (the C ABI checks every length first).
pub fn ridge_step_cells(
    state: CellState<'_>,
    forcing: CellForcing<'_>,
    out: CellOutputs<'_>,
    hin_max: &[f64],
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
    ws: &mut StepWorkspace,
) -> Result<(), ItdError> {
    let (ncat, nt) = (ws.ncat(), layout.ntrcr());
    let CellState {
        aicen: a,
        vicen: v,
        vsnon: s,
        trcrn: t,
        aice0: a0,
        aice: ai,
    } = state;
    let CellOutputs {
        mut opening,
        mut fluxes,
        mut rates,
        mut species,
    } = out;
    let counts = species_counts(layout);
    for i in 0..ai.len() {
        if forcing.step.is_some_and(|f| !f(i)) {
            continue;
        }
        let closing = match (forcing.closing, &opening) {
            (Some(cl), Some(op)) => Closing::Rates {
                closing: cl[i],
                opening: op[i],
            },
            _ => Closing::Deformation {
                convergence: forcing.convergence.map_or(0.0, |x| x[i]),
                shear: forcing.shear.map_or(0.0, |x| x[i]),
            },
        };
        let cell_forcing = StepForcing {
            closing,
            dt: forcing.dt,
            ndtd: forcing.ndtd,
            tf: forcing.tf.map_or(-1.8, |x| x[i]),
        };
        let at = |k: usize| fluxes[k].as_ref().map_or(0.0, |x| x[i]);
        let mut fl = OceanFluxes {
            fresh: at(0),
            fsalt: at(1),
            fhocn: at(2),
            fpond: at(3),
            dpnd_ridge: 0.0,
            ..OceanFluxes::default()
        };
        let mut rows = [
            &mut fl.faero_ocn[..],
            &mut fl.fiso_ocn[..],
            &mut fl.flux_bio[..],
        ];
        for ((row, x), &n) in rows.iter_mut().zip(&species).zip(&counts) {
            if let Some(x) = x {
                row[..n].copy_from_slice(&x[i * n..(i + 1) * n]);
            }
        }
        let mut col = ColumnMut {
            aicen: &mut a[i * ncat..(i + 1) * ncat],
            vicen: &mut v[i * ncat..(i + 1) * ncat],
            vsnon: &mut s[i * ncat..(i + 1) * ncat],
            trcrn: &mut t[i * ncat * nt..(i + 1) * ncat * nt],
            aice0: &mut a0[i],
            aice: &mut ai[i],
        };
        let d = ridge_step_column(&mut col, hin_max, cell_forcing, opts, layout, &mut fl, ws)
            .map_err(|source| ItdError::Column { column: i, source })?;
        if let Some(op) = opening.as_mut() {
            op[i] = d.opening;
        }
        for (o, x) in fluxes
            .iter_mut()
            .zip([fl.fresh, fl.fsalt, fl.fhocn, fl.fpond])
        {
            if let Some(o) = o {
                o[i] = x;
            }
        }
        for (o, x) in rates.iter_mut().zip([d.dardg1dt, d.dardg2dt, d.dvirdgdt]) {
            if let Some(o) = o {
                o[i] = x;
            }
        }
        let rows = [&fl.faero_ocn[..], &fl.fiso_ocn[..], &fl.flux_bio[..]];
        for ((x, row), &n) in species.iter_mut().zip(rows).zip(&counts) {
            if let Some(x) = x {
                x[i * n..(i + 1) * n].copy_from_slice(&row[..n]);
            }
        }
    }
    Ok(())
}
