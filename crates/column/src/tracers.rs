//! Tracer layout of a thickness category: which tracers a column carries, where each sits in
//! the per-category tracer vector, and on what each is carried (its *base*: ice area, ice
//! volume or snow volume, times the product of its *strata* tracers).
//!
//! This is the one Rust definition of the layout; the C ABI, the Fortran module, Python and
//! the NetCDF reader all derive theirs from it. The CICE/Icepack layout
//! ([`TracerLayout::cice`]) follows `icepack_tracers.F90` (`icepack_init_tracer_indices`,
//! `icepack_init_tracer_flags`): surface temperature, ice enthalpy per layer, snow enthalpy per
//! layer, ice salinity per layer, then the optional age, first-year fraction, level-ice area
//! and volume fractions and the level-ice pond area, depth and lid. The conserved quantity of
//! tracer `t` in category `n` is `t · base_n · Π strata_n` (e.g. pond depth is conserved as
//! `aicen · alvl · apnd · hpnd`), exactly Icepack's `trcr_depend`, `trcr_base`,
//! `n_trcr_strata` and `nt_strata`.
//!
//! Storage: one column's tracers are a flat slice `trcrn[n * ntrcr + it]` — the memory order
//! of Icepack's `trcrn(ntrcr, ncat)` for one cell.

// Per-category and per-tracer tables are indexed by number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use super::ItdError;
use rules::{PerTracer, aerosols, check_bases, field_starts, isotopes, per_tracer};

mod bgc;
mod cice;
mod field;
mod host;
mod rules;
mod spec;
pub use bgc::{BgcKind, BgcTracers, MAX_NBTRCR};
pub use cice::{CiceTracerFlags, LayoutDetectError};
pub use field::{TracerBase, TracerField, TracerRole};
pub use spec::{CiceLayoutSpec, IcedrvBgc, LayoutSpecError, PRESETS as LAYOUT_PRESETS};

/// Most aerosol species a layout may carry (Icepack's `icepack_max_aero`).
pub const MAX_AERO: usize = 6;
/// Most water-isotope species a layout may carry (Icepack's `icepack_max_iso`).
pub const MAX_ISO: usize = 3;

/// A validated tracer layout with the per-tracer index tables the ridging step uses.
#[derive(Debug, Clone, PartialEq)]
pub struct TracerLayout {
    fields: Vec<TracerField>,
    /// First index of each field.
    starts: Vec<usize>,
    ntrcr: usize,
    /// Per tracer: base.
    pub(crate) base: Vec<TracerBase>,
    /// Per tracer: base as an index into (area, ice volume, snow volume).
    pub(crate) base_idx: Vec<u8>,
    /// Tracers given to new ridges, by base (area, ice volume, snow volume).
    pub(crate) ridge_lists: [Vec<usize>; 3],
    /// Per tracer: number of strata (0..=2) and their tracer indices.
    pub(crate) nstrata: Vec<u8>,
    pub(crate) strata: Vec<[usize; 2]>,
    /// Per tracer: area tracer in Icepack's `trcr_depend = 0` sense (base area, no strata,
    /// or a host's `trcr_depend` of 0): recomputed only where the area exceeds `puny`.
    pub(crate) area_direct: Vec<bool>,
    /// A host's own `trcr_depend` ([`TracerLayout::with_host_tables`]), kept as given: Icepack
    /// reads it only to choose the area branch of `icepack_compute_tracers` (`== 0`), and a
    /// host's may disagree with its bases and strata (Icepack's column driver resets those of
    /// its biogeochemical tracers to the area after setting their `trcr_depend`).
    pub(crate) host_depend: Option<Vec<i32>>,
    pub(crate) nt_tsfc: Option<usize>,
    pub(crate) nt_qice: usize,
    pub(crate) nt_sice: usize,
    pub(crate) nt_qsno: usize,
    pub(crate) nilyr: usize,
    pub(crate) nslyr: usize,
    pub(crate) nt_alvl: Option<usize>,
    pub(crate) nt_apnd: Option<usize>,
    pub(crate) nt_hpnd: Option<usize>,
    /// Per aerosol species: the tracers of snow surface layer, snow interior, ice surface
    /// layer, ice interior.
    pub(crate) aero: Vec<[usize; 4]>,
    /// Water isotopes: first tracer in snow, first in ice, number of species.
    pub(crate) iso: Option<(usize, usize, usize)>,
    /// Ponds carried on level ice (`apnd` on `alvl`), as Icepack's `tr_pond_lvl`; else on the
    /// ice area (topography and sea-level ponds).
    pub(crate) ponds_on_level_ice: bool,
    /// Whether the clean-up books the pond water of the ice it zaps in `fpond` (Icepack does
    /// for `tr_pond_topo` only).
    pub(crate) zap_pond_water: bool,
    /// Per tracer: its value where its base volume is zero ([`TracerField::empty`]).
    pub(crate) empty: Vec<f64>,
    /// Tracers with a nonzero [`TracerField::empty`].
    pub(crate) refilled: Vec<usize>,
    /// Per base (area, ice volume, snow volume): tracers carried on the brine fraction that
    /// new ridges get with it (Icepack gives ridges the tracers whose strata are `fbri` only).
    pub(crate) ridge_lists_brine: [Vec<usize>; 3],
    pub(crate) nt_fbri: Option<usize>,
    /// Biogeochemical tracers whose fluxes to the ocean the step books ([`BgcTracers`]).
    pub(crate) bgc: Option<BgcTracers>,
    /// The column driver's biogeochemistry this layout was made from
    /// ([`CiceLayoutSpec::layout`]), so that [`TracerLayout::cice_spec`] can name it.
    pub(crate) icedrv_bgc: Option<IcedrvBgc>,
}

impl TracerLayout {
    /// The layout with `value` as the tracer field `name`'s value where its base volume is
    /// zero and in emptied categories ([`TracerField::empty`]; units of the tracer): for
    /// Icepack's `snwredist = 'ITD'`, `rhos` = `rhosnew`; for `snwgrain`, `smice` = `rhos` and
    /// `rsnw` = `rsnw_fall`. Only for ice- and snow-volume tracers.
    pub fn with_empty_value(mut self, name: &str, value: f64) -> Result<Self, ItdError> {
        let i = self
            .fields
            .iter()
            .position(|f| f.name == name)
            .ok_or_else(|| ItdError::Layout(format!("no tracer field `{name}`")))?;
        if self.fields[i].base == TracerBase::Area || !value.is_finite() {
            return Err(ItdError::Layout(format!(
                "`{name}`: an empty value is for finite values of ice- and \
                 snow-volume tracers"
            )));
        }
        self.fields[i].empty = value;
        // Its tracers (those a host's tables put on the area stay 0), then the lists; the
        // layout's other settings and any host tables are kept.
        let start = self.starts[i];
        for it in start..start + self.fields[i].levels {
            if self.base_idx[it] != 0 {
                self.empty[it] = value;
            }
        }
        self.derive_lists();
        Ok(self)
    }

    /// A layout from explicit fields. Rules: exactly one field each of roles `IceEnthalpy`,
    /// `IceSalinity` (same number of levels, ≥ 1) and `SnowEnthalpy` (≥ 1 level); at most one
    /// of every other role except `Other`; `Tsfc` (if present) first; strata name earlier
    /// single-level fields; field names unique; level-ice and pond roles as in
    /// [`TracerLayout::cice`].
    pub fn new(fields: Vec<TracerField>) -> Result<Self, ItdError> {
        let bad = ItdError::Layout;
        let (starts, ntrcr) = field_starts(&fields)?;
        let find = |role: TracerRole| fields.iter().position(|f| f.role == role);
        let qice = find(TracerRole::IceEnthalpy).ok_or_else(|| bad("no qice field".into()))?;
        let sice = find(TracerRole::IceSalinity).ok_or_else(|| bad("no sice field".into()))?;
        let qsno = find(TracerRole::SnowEnthalpy).ok_or_else(|| bad("no qsno field".into()))?;
        if fields[qice].levels != fields[sice].levels {
            return Err(bad("qice and sice need the same number of levels".into()));
        }
        check_bases(&fields)?;
        let aero = aerosols(&fields, &starts)?;
        let iso = isotopes(&fields, &starts)?;
        if let Some(i) = find(TracerRole::SurfaceTemperature)
            && i != 0
        {
            return Err(bad("Tsfc must be the first field".into()));
        }
        let nt_alvl = find(TracerRole::LevelArea).map(|i| starts[i]);
        let nt_apnd = find(TracerRole::PondArea).map(|i| starts[i]);
        let nt_hpnd = find(TracerRole::PondDepth).map(|i| starts[i]);
        if nt_apnd.is_some() != nt_hpnd.is_some() {
            return Err(bad("ponds need apnd and hpnd".into()));
        }
        // Level-ice ponds when apnd is carried on a stratum (alvl), else on the area.
        let on_level = find(TracerRole::PondArea).is_some_and(|i| !fields[i].strata.is_empty());
        let brine = find(TracerRole::BrineFraction);
        let PerTracer {
            base,
            nstrata,
            strata,
            empty,
        } = per_tracer(&fields, &starts, ntrcr, on_level)?;
        let base_idx: Vec<u8> = base
            .iter()
            .map(|b| match b {
                TracerBase::Area => 0,
                TracerBase::IceVolume => 1,
                TracerBase::SnowVolume => 2,
            })
            .collect();
        let mut l = Self {
            base_idx,
            ridge_lists: Default::default(),
            nt_tsfc: find(TracerRole::SurfaceTemperature).map(|i| starts[i]),
            nt_qice: starts[qice],
            nt_sice: starts[sice],
            nt_qsno: starts[qsno],
            nilyr: fields[qice].levels,
            nslyr: fields[qsno].levels,
            nt_alvl,
            nt_apnd,
            nt_hpnd,
            aero,
            iso,
            ponds_on_level_ice: on_level,
            zap_pond_water: false,
            empty,
            refilled: Vec::new(),
            ridge_lists_brine: Default::default(),
            nt_fbri: brine.map(|i| starts[i]),
            bgc: None,
            icedrv_bgc: None,
            fields,
            starts,
            ntrcr,
            base,
            nstrata,
            strata,
            area_direct: Vec::new(),
            host_depend: None,
        };
        l.derive_lists();
        Ok(l)
    }

    /// The per-tracer lists the step uses, from each tracer's base, strata and empty value
    /// (written once here for a new layout and after a host's tables or an empty value):
    /// Icepack's area tracers (`trcr_depend = 0`), the tracers new ridges get — those without
    /// strata but for the level-ice ones, and those carried on the brine fraction alone — and
    /// those refilled where their base is zero.
    fn derive_lists(&mut self) {
        let nt = self.ntrcr;
        self.area_direct = match &self.host_depend {
            Some(d) => d.iter().map(|&d| d == 0).collect(),
            None => (0..nt)
                .map(|it| self.base_idx[it] == 0 && self.nstrata[it] == 0)
                .collect(),
        };
        let level: Vec<bool> = (0..nt)
            .map(|it| {
                self.field_of(it).is_some_and(|(f, _)| {
                    matches!(f.role, TracerRole::LevelArea | TracerRole::LevelVolume)
                })
            })
            .collect();
        self.ridge_lists = std::array::from_fn(|k| {
            (0..nt)
                .filter(|&it| {
                    !level[it] && self.nstrata[it] == 0 && self.base_idx[it] as usize == k
                })
                .collect()
        });
        let fbri = self.nt_fbri;
        self.ridge_lists_brine = std::array::from_fn(|k| {
            (0..nt)
                .filter(|&it| {
                    self.nstrata[it] > 0
                        && self.base_idx[it] as usize == k
                        && (0..self.nstrata[it] as usize).all(|j| Some(self.strata[it][j]) == fbri)
                })
                .collect()
        });
        self.refilled = (0..nt).filter(|&it| self.empty[it] != 0.0).collect();
    }

    /// Number of tracers per category (Icepack `ntrcr`).
    pub fn ntrcr(&self) -> usize {
        self.ntrcr
    }

    /// Number of aerosol species (Icepack `n_aero`): the length of
    /// [`OceanFluxes::faero_ocn`](crate::details::OceanFluxes::faero_ocn) the step fills.
    pub fn n_aero(&self) -> usize {
        self.aero.len()
    }

    /// Number of water-isotope species (Icepack `n_iso`).
    pub fn n_iso(&self) -> usize {
        self.iso.map_or(0, |(_, _, n)| n)
    }

    /// Number of ice layers (Icepack `nilyr`).
    pub fn nilyr(&self) -> usize {
        self.nilyr
    }

    /// Number of snow layers (Icepack `nslyr`).
    pub fn nslyr(&self) -> usize {
        self.nslyr
    }

    /// The fields, in storage order.
    pub fn fields(&self) -> &[TracerField] {
        &self.fields
    }

    /// First tracer index (0-based) and number of levels of the field called `name`.
    pub fn field(&self, name: &str) -> Option<(usize, usize)> {
        self.fields
            .iter()
            .position(|f| f.name == name)
            .map(|i| (self.starts[i], self.fields[i].levels))
    }

    /// The field of tracer `it` (index order) and the tracer's level in it (0-based).
    pub fn field_of(&self, it: usize) -> Option<(&TracerField, usize)> {
        let i = self.starts.iter().rposition(|&s| s <= it)?;
        (it < self.ntrcr).then(|| (&self.fields[i], it - self.starts[i]))
    }

    /// Icepack's `trcr_depend` per tracer: 0 area, 1 ice volume, 2 snow volume, `2 + nt`
    /// (1-based `nt`) for a tracer carried on tracer `nt` (its innermost stratum); a host's
    /// own where it gave its tables ([`TracerLayout::with_host_tables`]).
    pub fn trcr_depend(&self) -> Vec<i32> {
        if let Some(d) = &self.host_depend {
            return d.clone();
        }
        (0..self.ntrcr)
            .map(|it| match (self.nstrata[it], self.base[it]) {
                (0, TracerBase::Area) => 0,
                (0, TracerBase::IceVolume) => 1,
                (0, TracerBase::SnowVolume) => 2,
                (k, _) => 2 + self.strata[it][k as usize - 1] as i32 + 1,
            })
            .collect()
    }

    /// Per tracer, its base as a code 0 (area), 1 (ice volume), 2 (snow volume).
    pub fn base_codes(&self) -> Vec<i32> {
        self.base
            .iter()
            .map(|b| match b {
                TracerBase::Area => 0,
                TracerBase::IceVolume => 1,
                TracerBase::SnowVolume => 2,
            })
            .collect()
    }

    /// Per tracer, its strata as 1-based tracer indices (0 = none), Icepack's `nt_strata`.
    pub fn strata_one_based(&self) -> Vec<[i32; 2]> {
        (0..self.ntrcr)
            .map(|it| {
                let mut s = [0; 2];
                for k in 0..self.nstrata[it] as usize {
                    s[k] = self.strata[it][k] as i32 + 1;
                }
                s
            })
            .collect()
    }

    /// Conserved amount of tracer `it` of one category: tracer × base × strata, in Icepack's
    /// order of operations (`ridge_shift`, `shift_ice`).
    #[inline(always)]
    pub(crate) fn amount(&self, it: usize, trc: &[f64], a: f64, v: f64, s: f64) -> f64 {
        let b = [a, v, s][self.base_idx[it] as usize];
        let mut x = trc[it] * b;
        for k in 0..self.nstrata[it] as usize {
            x *= trc[self.strata[it][k]];
        }
        x
    }

    /// Icepack `icepack_compute_tracers` for one category: tracers from the conserved amounts
    /// `atrc` and the new area `a`, ice volume `v`, snow volume `s`. Area tracers without strata
    /// are set where `a > puny` (else 0, `Tsfc = tf`); the others wherever their base is
    /// positive, then divided by each positive stratum (else 0), strata first.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn compute(
        &self,
        atrc: &[f64],
        a: f64,
        v: f64,
        s: f64,
        puny: f64,
        tf: f64,
        trc: &mut [f64],
    ) {
        for it in 0..self.ntrcr {
            if self.area_direct[it] {
                trc[it] = if a > puny {
                    atrc[it] / a
                } else if Some(it) == self.nt_tsfc {
                    tf
                } else {
                    0.0
                };
            } else {
                let d = [a, v, s][self.base_idx[it] as usize];
                let mut w = if d > 0.0 { atrc[it] / d } else { 0.0 };
                for k in 0..self.nstrata[it] as usize {
                    let st = trc[self.strata[it][k]];
                    w = if st > 0.0 { w / st } else { 0.0 };
                }
                trc[it] = w;
            }
        }
        // Icepack's refills where the base volume is zero (fbri; the snow tracers).
        for &it in &self.refilled {
            if [a, v, s][self.base_idx[it] as usize] <= 0.0 {
                trc[it] = self.empty[it];
            }
        }
    }
}

#[cfg(test)]
mod tests;
