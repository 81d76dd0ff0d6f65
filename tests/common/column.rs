//! The library's complete step on one column, as the reference of the tests that compare a
//! face (the command line, gridded files) with `ridge_step_column`.

use pressridge::itd::{
    ColumnError, ColumnMut, RidgeStepOptions, StepDiagnostics, StepForcing, StepWorkspace,
    details::{OceanFluxes, TracerLayout},
    ridge_step_column,
};

/// The state of one column, owned, in `ridge_step_column`'s layout.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    pub aicen: Vec<f64>,
    pub vicen: Vec<f64>,
    pub vsnon: Vec<f64>,
    /// `trcrn[n * ntrcr + it]`.
    pub trcrn: Vec<f64>,
    pub aice0: f64,
    pub aice: f64,
}

impl Column {
    /// A column whose total ice area `aice` is the sum of `aicen`.
    pub fn new(
        aicen: Vec<f64>,
        vicen: Vec<f64>,
        vsnon: Vec<f64>,
        trcrn: Vec<f64>,
        aice0: f64,
    ) -> Column {
        let aice = aicen.iter().sum();
        Column {
            aicen,
            vicen,
            vsnon,
            trcrn,
            aice0,
            aice,
        }
    }

    /// Column `c` of `ncol` gridded columns in C order: category variables `x[n * ncol + c]`
    /// over (nc, nj, ni), one vector per tracer (`trcrn[it][n * ncol + c]`), `aice0[c]`;
    /// `aice` is the sum of the column's `aicen`.
    pub fn gather(
        ncol: usize,
        c: usize,
        aicen: &[f64],
        vicen: &[f64],
        vsnon: &[f64],
        trcrn: &[Vec<f64>],
        aice0: &[f64],
    ) -> Column {
        let ncat = aicen.len() / ncol;
        let per_cat = |x: &[f64]| -> Vec<f64> { (0..ncat).map(|n| x[n * ncol + c]).collect() };
        let nt = trcrn.len();
        let t = (0..ncat)
            .flat_map(|n| (0..nt).map(move |it| (n, it)))
            .map(|(n, it)| trcrn[it][n * ncol + c])
            .collect();
        Column::new(per_cat(aicen), per_cat(vicen), per_cat(vsnon), t, aice0[c])
    }
}

/// What [`step`] gives: the column after the step (as the library leaves it, also on an
/// error), the ocean fluxes of this one step, the workspace's per-category diagnostics and
/// the library's result.
pub struct Stepped {
    pub col: Column,
    pub fluxes: OceanFluxes,
    pub ws: StepWorkspace,
    pub result: Result<StepDiagnostics, ColumnError>,
}

/// `ridge_step_column` on a copy of `col` with zeroed ocean fluxes and a fresh workspace.
pub fn step(
    col: &Column,
    hin_max: &[f64],
    forcing: StepForcing,
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
) -> Stepped {
    let mut out = col.clone();
    let mut fluxes = OceanFluxes::default();
    let mut ws = StepWorkspace::new(col.aicen.len(), layout.ntrcr());
    let Column {
        aicen,
        vicen,
        vsnon,
        trcrn,
        aice0,
        aice,
    } = &mut out;
    let mut view = ColumnMut {
        aicen,
        vicen,
        vsnon,
        trcrn,
        aice0,
        aice,
    };
    let result = ridge_step_column(
        &mut view,
        hin_max,
        forcing,
        opts,
        layout,
        &mut fluxes,
        &mut ws,
    );
    Stepped {
        col: out,
        fluxes,
        ws,
        result,
    }
}
