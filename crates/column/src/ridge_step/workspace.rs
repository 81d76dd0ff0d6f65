//! The scratch of the ridging step: [`StepWorkspace`] (per-category work arrays and
//! diagnostics, sized once) and the saved input that restores a column on error.

use super::ColumnMut;
use crate::Workspace;

/// Scratch and per-category diagnostics of the ridging step, sized once for `ncat`
/// categories and `ntrcr` tracers. One per thread gives allocation-free column calls.
#[derive(Debug, Clone)]
pub struct StepWorkspace {
    pub(crate) core: Workspace,
    pub(super) ntrcr: usize,
    pub(crate) vsnon_init: Vec<f64>,
    pub(crate) atrcrn: Vec<f64>,
    pub(crate) hicen: Vec<f64>,
    pub(super) mraft: Vec<f64>,
    pub(super) farea: Vec<f64>,
    pub(super) fvol: Vec<f64>,
    /// The input state, kept to restore the column on error.
    save: Vec<f64>,
    /// Participation of each category, last pass (1; Icepack `aparticn`).
    pub aparticn: Vec<f64>,
    /// Mean ridge thickness / ridging-ice thickness, last pass (1; `krdgn`).
    pub krdgn: Vec<f64>,
    /// Area of ridging ice per unit time, last pass in which the category ridged (1/s;
    /// `dardg1ndt`).
    pub dardg1ndt: Vec<f64>,
    /// Area of new ridges per unit time, same pass (1/s; `dardg2ndt`).
    pub dardg2ndt: Vec<f64>,
    /// Volume of ridging ice per unit time, same pass (m/s; `dvirdgndt`).
    pub dvirdgndt: Vec<f64>,
    /// Rafted new-ridge area per step (1; exponential redistribution only; `araftn`).
    pub araftn: Vec<f64>,
    /// Rafting ice volume per step (m; exponential redistribution only; `vraftn`).
    pub vraftn: Vec<f64>,
    /// New-ridge area from category 1 landing in each category, per step (1; exponential
    /// redistribution only; `aredistn`).
    pub aredistn: Vec<f64>,
    /// Same for volume (m; `vredistn`).
    pub vredistn: Vec<f64>,
    /// Categories emptied by the clean-up (Icepack sets `first_ice` for them).
    pub zapped: Vec<bool>,
    /// A category ridged this step with μ_rdg from a table queried outside its range.
    pub(super) mu_rdg_clamped: bool,
}

impl StepWorkspace {
    /// Scratch for `ncat` categories and `ntrcr` tracers (the only allocation).
    pub fn new(ncat: usize, ntrcr: usize) -> Self {
        let z = vec![0.0; ncat];
        Self {
            core: Workspace::new(ncat),
            ntrcr,
            vsnon_init: z.clone(),
            atrcrn: vec![0.0; ncat * ntrcr],
            hicen: z.clone(),
            mraft: z.clone(),
            farea: z.clone(),
            fvol: z.clone(),
            save: Vec::with_capacity(3 * ncat + ncat * ntrcr),
            aparticn: z.clone(),
            krdgn: z.clone(),
            dardg1ndt: z.clone(),
            dardg2ndt: z.clone(),
            dvirdgndt: z.clone(),
            araftn: z.clone(),
            vraftn: z.clone(),
            aredistn: z.clone(),
            vredistn: z,
            zapped: vec![false; ncat],
            mu_rdg_clamped: false,
        }
    }

    /// Number of categories.
    pub fn ncat(&self) -> usize {
        self.core.ncat()
    }

    /// Number of tracers per category.
    pub fn ntrcr(&self) -> usize {
        self.ntrcr
    }

    pub(super) fn reset_diagnostics(&mut self) {
        for v in [
            &mut self.aparticn,
            &mut self.krdgn,
            &mut self.dardg1ndt,
            &mut self.dardg2ndt,
            &mut self.dvirdgndt,
            &mut self.araftn,
            &mut self.vraftn,
            &mut self.aredistn,
            &mut self.vredistn,
            &mut self.mraft,
            &mut self.core.ardg1n,
            &mut self.core.ardg2n,
            &mut self.core.virdgn,
        ] {
            v.fill(0.0);
        }
        self.zapped.fill(false);
    }
}

/// The input scalars kept for restoring the column on error (the arrays go to `ws.save`).
pub(super) struct Saved {
    aice0: f64,
    aice: f64,
}

impl Saved {
    pub(super) fn take(col: &ColumnMut<'_>, ws: &mut StepWorkspace) -> Self {
        ws.save.clear();
        ws.save.extend_from_slice(col.aicen);
        ws.save.extend_from_slice(col.vicen);
        ws.save.extend_from_slice(col.vsnon);
        ws.save.extend_from_slice(col.trcrn);
        Saved {
            aice0: *col.aice0,
            aice: *col.aice,
        }
    }

    pub(super) fn restore(self, col: &mut ColumnMut<'_>, ws: &StepWorkspace) {
        let ncat = col.aicen.len();
        let s = &ws.save;
        col.aicen.copy_from_slice(&s[..ncat]);
        col.vicen.copy_from_slice(&s[ncat..2 * ncat]);
        col.vsnon.copy_from_slice(&s[2 * ncat..3 * ncat]);
        col.trcrn.copy_from_slice(&s[3 * ncat..]);
        *col.aice0 = self.aice0;
        *col.aice = self.aice;
    }
}
