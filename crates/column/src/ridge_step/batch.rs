//! The complete ridging step ([`ridge_step_column`]) over many columns held in `ndarray`
//! views, for the faces that hold gridded arrays (Python, the NetCDF command line): state
//! `(ncat, ncol)` and tracers `(ncat, ntrcr, ncol)`, any strides, with a per-column validity
//! mask. Each column is gathered into contiguous scratch, stepped, and written back; the
//! numbers are those of [`ridge_step_column`] bit for bit.
//!
//! The names, units and meanings of the outputs ([`CELL_OUTPUTS`], [`CATEGORY_OUTPUTS`]) are
//! defined here once; the faces take them from these tables.

use ndarray::{ArrayView1, ArrayViewMut1, ArrayViewMut2, ArrayViewMut3};

use super::{
    Closing, ColumnMut, OceanFluxes, RidgeStepOptions, StepDiagnostics, StepForcing, StepWorkspace,
    ridge_step_column,
};
use crate::tracers::TracerLayout;
use crate::{ItdError, check_len, check_shape};

/// Name, CF units and long name of one output of the batched step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OutputMeta {
    /// Name (Icepack's where Icepack has one).
    pub name: &'static str,
    /// CF `units`.
    pub units: &'static str,
    /// CF `long_name`.
    pub long_name: &'static str,
}

const fn meta(name: &'static str, units: &'static str, long_name: &'static str) -> OutputMeta {
    OutputMeta {
        name,
        units,
        long_name,
    }
}

/// The per-cell outputs of [`ridge_step_batch`], in the order of its `cell` argument. Fluxes
/// are one step's (not accumulated); the ocean fluxes are averaged over `ndtd·dt`.
pub const CELL_OUTPUTS: [OutputMeta; 13] = [
    meta(
        "fresh",
        "kg m-2 s-1",
        "fresh water flux to the ocean from ridging (snow) and clean-up (ice and snow)",
    ),
    meta(
        "fsalt",
        "kg m-2 s-1",
        "salt flux to the ocean from the clean-up",
    ),
    meta(
        "fhocn",
        "W m-2",
        "heat flux to the ocean from ridging and clean-up (negative: the ocean melts snow and ice)",
    ),
    meta(
        "fpond",
        "m",
        "pond water lost by ridging, with sign (-dpnd_ridge), per step",
    ),
    meta("dpnd_ridge", "m", "pond water drained by ridging, per step"),
    meta(
        "closing",
        "s-1",
        "net closing rate of the first ridging pass",
    ),
    meta("opening", "s-1", "opening rate of the last ridging pass"),
    meta("dardg1dt", "s-1", "rate of area loss by ridging ice"),
    meta("dardg2dt", "s-1", "rate of area gain by new ridges"),
    meta("dvirdgdt", "m s-1", "rate of ice volume ridged"),
    meta(
        "ice_to_ocean",
        "m",
        "ice volume per unit area put into the ocean by the clean-up, per step",
    ),
    meta(
        "snow_to_ocean",
        "m",
        "snow volume per unit area put into the ocean by ridging and clean-up, per step",
    ),
    meta("niter", "1", "number of ridging passes"),
];

/// The per-category outputs of [`ridge_step_batch`] (Icepack's names and units), in the
/// order of its `category` argument; `first_ice` is 1 for categories emptied by the clean-up
/// (Icepack sets `first_ice` there), else 0.
pub const CATEGORY_OUTPUTS: [OutputMeta; 10] = [
    meta(
        "dardg1ndt",
        "s-1",
        "rate of area loss by ridging ice, last pass the category ridged",
    ),
    meta(
        "dardg2ndt",
        "s-1",
        "rate of area gain by new ridges, last pass the category ridged",
    ),
    meta(
        "dvirdgndt",
        "m s-1",
        "rate of ice volume ridged, last pass the category ridged",
    ),
    meta("aparticn", "1", "participation function, last pass"),
    meta(
        "krdgn",
        "1",
        "mean ridge thickness over ridging-ice thickness, last pass",
    ),
    meta(
        "araftn",
        "1",
        "rafted new-ridge area, per step (exponential redistribution)",
    ),
    meta(
        "vraftn",
        "m",
        "rafting ice volume, per step (exponential redistribution)",
    ),
    meta(
        "aredistn",
        "1",
        "new-ridge area from category 1 landing in the category, per step (exponential redistribution)",
    ),
    meta(
        "vredistn",
        "m",
        "new-ridge volume from category 1 landing in the category, per step (exponential redistribution)",
    ),
    meta(
        "first_ice",
        "1",
        "1 where the clean-up emptied the category, else 0",
    ),
];

/// The per-species outputs of [`ridge_step_batch`], in the order of its `species` argument:
/// `(n_aero, ncol)`, `(n_iso, ncol)` and `(nbtrcr, ncol)` ([`species_counts`]), one step's
/// values averaged over `ndtd·dt`.
pub const SPECIES_OUTPUTS: [OutputMeta; 3] = [
    meta(
        "faero_ocn",
        "kg m-2 s-1",
        "aerosol flux to the ocean from ridging (snow) and clean-up (ice and snow), per species",
    ),
    meta(
        "fiso_ocn",
        "kg m-2 s-1",
        "water isotope flux to the ocean from ridging (snow) and clean-up (ice and snow), per species",
    ),
    meta(
        "flux_bio",
        "mmol m-2 s-1",
        "biogeochemical flux to the ocean from ridging (snow) and clean-up (ice and snow), per \
         bio tracer (the tracer's unit times m s-1: kg m-2 s-1 for zaerosols)",
    ),
];

/// Rows of each of the [`SPECIES_OUTPUTS`] for a layout: its aerosol species, isotope
/// species and bio tracers.
pub fn species_counts(layout: &TracerLayout) -> [usize; 3] {
    [layout.n_aero(), layout.n_iso(), layout.n_bio()]
}

/// Per-column closing and opening of [`ridge_step_batch`] (1/s, `ncol` values each): the two
/// calling conventions of [`Closing`].
#[derive(Debug, Clone, Copy)]
pub enum BatchClosing<'a> {
    /// CICE: Icepack's `rdg_conv` and `rdg_shear` ([`Closing::Deformation`]).
    Deformation {
        /// Convergence term (1/s, ≥ 0).
        convergence: ArrayView1<'a, f64>,
        /// Shear term (1/s, ≥ 0).
        shear: ArrayView1<'a, f64>,
    },
    /// SIS2: the host's net closing and opening rates ([`Closing::Rates`]).
    Rates {
        /// Net closing rate (1/s, ≥ 0).
        closing: ArrayView1<'a, f64>,
        /// Opening rate (1/s, ≥ 0).
        opening: ArrayView1<'a, f64>,
    },
}

/// The state of `ncol` columns, updated in place by [`ridge_step_batch`].
#[derive(Debug)]
pub struct StepBatchMut<'a> {
    /// Ice area per category (1), `(ncat, ncol)`.
    pub aicen: ArrayViewMut2<'a, f64>,
    /// Ice volume per unit cell area (m), `(ncat, ncol)`.
    pub vicen: ArrayViewMut2<'a, f64>,
    /// Snow volume per unit cell area (m), `(ncat, ncol)`.
    pub vsnon: ArrayViewMut2<'a, f64>,
    /// Tracers `(ncat, ntrcr, ncol)` (units per tracer, see [`TracerLayout`]).
    pub trcrn: ArrayViewMut3<'a, f64>,
    /// Open-water fraction (1), `ncol`.
    pub aice0: ArrayViewMut1<'a, f64>,
    /// Total ice area (1), `ncol`; recomputed only by the clean-up.
    pub aice: ArrayViewMut1<'a, f64>,
}

/// Forcing of [`ridge_step_batch`].
#[derive(Debug, Clone, Copy)]
pub struct BatchForcing<'a> {
    /// Closing and opening per column.
    pub closing: BatchClosing<'a>,
    /// Freezing temperature per column (°C), for emptied categories' surface temperature.
    pub tf: ArrayView1<'a, f64>,
    /// Dynamics time step (s, > 0).
    pub dt: f64,
    /// Dynamics subcycles per thermodynamic step (≥ 1); ocean fluxes are averaged over
    /// `ndtd·dt`.
    pub ndtd: u32,
    /// Columns to step (`ncol`); the others keep their state and get
    /// [`StepBatchOutputs::fill`] in every output. `None`: every column.
    pub valid: Option<ArrayView1<'a, bool>>,
}

/// What [`ridge_step_batch`] writes per column.
#[derive(Debug)]
pub struct StepBatchOutputs<'a, 'b> {
    /// The [`CELL_OUTPUTS`], `ncol` values each (one step's values).
    pub cell: &'a mut [ArrayViewMut1<'b, f64>],
    /// The [`CATEGORY_OUTPUTS`], `(ncat, ncol)` each, or `None`.
    pub category: Option<&'a mut [ArrayViewMut2<'b, f64>]>,
    /// The [`SPECIES_OUTPUTS`], `(n, ncol)` each for the layout's [`species_counts`], or
    /// `None`.
    pub species: Option<&'a mut [ArrayViewMut2<'b, f64>]>,
    /// The value of every output of a column [`BatchForcing::valid`] leaves out (NaN, a
    /// file's fill value).
    pub fill: f64,
}

/// The complete ridging step of `ncol` columns (Icepack `icepack_step_ridge` per column, see
/// [`ridge_step_column`]).
///
/// `hin_max`: `ncat + 1` category bounds (m), shared; with [`BatchClosing::Deformation`] the
/// top bound used is `opts.params.big`, as Icepack's. The outputs are written, not added to.
///
/// Stops at the first failing column with [`ItdError::Column`] (its flat index): earlier
/// columns are stepped, that one and later ones keep their state. Allocates only the scratch
/// of one column.
pub fn ridge_step_batch(
    state: StepBatchMut<'_>,
    hin_max: &[f64],
    forcing: BatchForcing<'_>,
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
    mut out: StepBatchOutputs<'_, '_>,
) -> Result<(), ItdError> {
    let StepBatchMut {
        mut aicen,
        mut vicen,
        mut vsnon,
        mut trcrn,
        mut aice0,
        mut aice,
    } = state;
    let (ncat, ncol) = aicen.dim();
    let nt = layout.ntrcr();
    if ncat == 0 {
        return Err(ItdError::Shape {
            var: "aicen",
            expected: vec![1, ncol],
            found: vec![0, ncol],
        });
    }
    check_shape("vicen", vicen.shape(), &[ncat, ncol])?;
    check_shape("vsnon", vsnon.shape(), &[ncat, ncol])?;
    check_shape("trcrn", trcrn.shape(), &[ncat, nt, ncol])?;
    check_len("hin_max", hin_max.len(), ncat + 1)?;
    check_len("aice0", aice0.len(), ncol)?;
    check_len("aice", aice.len(), ncol)?;
    check_len("tf", forcing.tf.len(), ncol)?;
    let (c1, c2) = match forcing.closing {
        BatchClosing::Deformation { convergence, shear } => {
            check_len("convergence", convergence.len(), ncol)?;
            check_len("shear", shear.len(), ncol)?;
            (convergence, shear)
        }
        BatchClosing::Rates { closing, opening } => {
            check_len("closing", closing.len(), ncol)?;
            check_len("opening", opening.len(), ncol)?;
            (closing, opening)
        }
    };
    let valid = forcing.valid;
    if let Some(m) = &valid {
        check_len("valid", m.len(), ncol)?;
    }
    check_len("cell outputs", out.cell.len(), CELL_OUTPUTS.len())?;
    for (m, o) in CELL_OUTPUTS.iter().zip(out.cell.iter()) {
        check_len(m.name, o.len(), ncol)?;
    }
    if let Some(cat) = out.category.as_deref() {
        check_len("category outputs", cat.len(), CATEGORY_OUTPUTS.len())?;
        for (m, o) in CATEGORY_OUTPUTS.iter().zip(cat.iter()) {
            check_shape(m.name, o.shape(), &[ncat, ncol])?;
        }
    }
    let nspecies = species_counts(layout);
    if let Some(sp) = out.species.as_deref() {
        check_len("species outputs", sp.len(), SPECIES_OUTPUTS.len())?;
        for ((m, o), n) in SPECIES_OUTPUTS.iter().zip(sp.iter()).zip(nspecies) {
            check_shape(m.name, o.shape(), &[n, ncol])?;
        }
    }

    let mut ws = StepWorkspace::new(ncat, nt);
    let mut a = vec![0.0; ncat];
    let mut v = vec![0.0; ncat];
    let mut s = vec![0.0; ncat];
    let mut t = vec![0.0; ncat * nt];
    for c in 0..ncol {
        if valid.as_ref().is_some_and(|m| !m[c]) {
            out.fill_column(c);
            continue;
        }
        for n in 0..ncat {
            a[n] = aicen[[n, c]];
            v[n] = vicen[[n, c]];
            s[n] = vsnon[[n, c]];
            for (it, x) in t[n * nt..(n + 1) * nt].iter_mut().enumerate() {
                *x = trcrn[[n, it, c]];
            }
        }
        let (mut a0, mut ai) = (aice0[c], aice[c]);
        let closing = match forcing.closing {
            BatchClosing::Deformation { .. } => Closing::Deformation {
                convergence: c1[c],
                shear: c2[c],
            },
            BatchClosing::Rates { .. } => Closing::Rates {
                closing: c1[c],
                opening: c2[c],
            },
        };
        let f = StepForcing {
            closing,
            dt: forcing.dt,
            ndtd: forcing.ndtd,
            tf: forcing.tf[c],
        };
        let mut fl = OceanFluxes::default();
        let mut col = ColumnMut {
            aicen: &mut a,
            vicen: &mut v,
            vsnon: &mut s,
            trcrn: &mut t,
            aice0: &mut a0,
            aice: &mut ai,
        };
        let d = ridge_step_column(&mut col, hin_max, f, opts, layout, &mut fl, &mut ws)
            .map_err(|source| ItdError::Column { column: c, source })?;
        for n in 0..ncat {
            aicen[[n, c]] = a[n];
            vicen[[n, c]] = v[n];
            vsnon[[n, c]] = s[n];
            for (it, x) in t[n * nt..(n + 1) * nt].iter().enumerate() {
                trcrn[[n, it, c]] = *x;
            }
        }
        aice0[c] = a0;
        aice[c] = ai;
        out.write_column(c, &fl, &d, &ws);
    }
    Ok(())
}

impl StepBatchOutputs<'_, '_> {
    /// Fills column `c` of every output with [`Self::fill`] (a column the mask leaves out).
    fn fill_column(&mut self, c: usize) {
        let fill = self.fill;
        for o in self.cell.iter_mut() {
            o[c] = fill;
        }
        for o in self.category.iter_mut().flat_map(|x| x.iter_mut()) {
            o.column_mut(c).fill(fill);
        }
        for o in self.species.iter_mut().flat_map(|x| x.iter_mut()) {
            o.column_mut(c).fill(fill);
        }
    }

    /// Writes column `c`'s diagnostics: the cell outputs from its fluxes `fl` and step `d`,
    /// and, where given, the category outputs from the workspace `ws` and the species outputs.
    fn write_column(
        &mut self,
        c: usize,
        fl: &OceanFluxes,
        d: &StepDiagnostics,
        ws: &StepWorkspace,
    ) {
        let values = [
            fl.fresh,
            fl.fsalt,
            fl.fhocn,
            fl.fpond,
            fl.dpnd_ridge,
            d.closing,
            d.opening,
            d.dardg1dt,
            d.dardg2dt,
            d.dvirdgdt,
            d.ice_to_ocean,
            d.snow_to_ocean,
            d.niter as f64,
        ];
        for (o, x) in self.cell.iter_mut().zip(values) {
            o[c] = x;
        }
        if let Some(cat) = self.category.as_deref_mut() {
            let per = [
                &ws.dardg1ndt,
                &ws.dardg2ndt,
                &ws.dvirdgndt,
                &ws.aparticn,
                &ws.krdgn,
                &ws.araftn,
                &ws.vraftn,
                &ws.aredistn,
                &ws.vredistn,
            ];
            for (o, xs) in cat.iter_mut().zip(per) {
                for (n, x) in xs.iter().enumerate() {
                    o[[n, c]] = *x;
                }
            }
            let first_ice = cat.last_mut().expect("ten category outputs");
            for (n, z) in ws.zapped.iter().enumerate() {
                first_ice[[n, c]] = if *z { 1.0 } else { 0.0 };
            }
        }
        if let Some(sp) = self.species.as_deref_mut() {
            let rows = [&fl.faero_ocn[..], &fl.fiso_ocn[..], &fl.flux_bio[..]];
            for (o, xs) in sp.iter_mut().zip(rows) {
                for k in 0..o.nrows() {
                    o[[k, c]] = xs[k];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;
