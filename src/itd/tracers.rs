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

mod field;
mod spec;
pub use field::{TracerBase, TracerField, TracerRole};
pub use spec::{CiceLayoutSpec, LayoutSpecError, PRESETS as LAYOUT_PRESETS};

/// Most aerosol species a layout may carry (Icepack's `icepack_max_aero`).
pub const MAX_AERO: usize = 6;
/// Most water-isotope species a layout may carry (Icepack's `icepack_max_iso`).
pub const MAX_ISO: usize = 3;

/// Which optional CICE tracers a column carries (Icepack's `tr_iage`, `tr_FY`, `tr_lvl`,
/// `tr_pond_lvl`, `tr_snow`, `tr_iso` with `n_iso`, `tr_aero` with `n_aero`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CiceTracerFlags {
    /// Ice age `iage`.
    pub age: bool,
    /// First-year ice fraction `FY`.
    pub first_year: bool,
    /// Level-ice area and volume fractions `alvl`, `vlvl`.
    pub level_ice: bool,
    /// Level-ice melt ponds `apnd`, `hpnd`, `ipnd` (needs `level_ice`).
    pub ponds: bool,
    /// Snow tracers `smice`, `smliq` (kg m⁻³), `rhos` (kg m⁻³), `rsnw` (m), one level per
    /// snow layer each, carried on snow volume (Icepack's `tr_snow`; emptied categories get
    /// 0, Icepack's value with its default `snwredist = 'none'`, `snwgrain = .false.`).
    pub snow: bool,
    /// Number of water-isotope species `isosno`, `isoice` (Icepack's `n_iso`; 0 to
    /// [`MAX_ISO`], 0: `tr_iso` off).
    pub isotopes: usize,
    /// Number of aerosol species, four tracers each (Icepack's `n_aero`; 0 to [`MAX_AERO`],
    /// 0: `tr_aero` off).
    pub aerosols: usize,
    /// Topography melt ponds `apnd` (on area), `hpnd`, `ipnd` (on pond area), Icepack's
    /// `tr_pond_topo`: the pond water of zapped ice is booked in `fpond`. At most one pond
    /// scheme.
    pub pond_topo: bool,
    /// Sea-level melt ponds, carried as the topography ponds (Icepack's `tr_pond_sealvl`).
    pub pond_sealvl: bool,
    /// Number of floe-size categories `fsd` (area tracers; Icepack's `nfsd` with `tr_fsd`;
    /// 0: off).
    pub fsd: usize,
    /// Brine height fraction `fbri` (Icepack's `tr_brine`), after the aerosols.
    pub brine: bool,
}

impl CiceTracerFlags {
    /// Every optional tracer on (the layout of the Icepack reference data: 23 tracers for 7
    /// ice layers and 1 snow layer).
    pub const ALL: CiceTracerFlags = CiceTracerFlags {
        age: true,
        first_year: true,
        level_ice: true,
        ponds: true,
        snow: false,
        isotopes: 0,
        aerosols: 0,
        pond_topo: false,
        pond_sealvl: false,
        fsd: 0,
        brine: false,
    };
}

/// Why [`TracerLayout::detect_cice`] cannot tell the layout: a variable is missing.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("missing: {why}")]
pub struct LayoutDetectError {
    /// The variable (CICE restart name) missing.
    pub var: String,
    /// Why it is needed.
    pub why: String,
}

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
    /// Per tracer: area tracer in Icepack's `trcr_depend = 0` sense (base area, no strata):
    /// recomputed only where the area exceeds `puny`.
    pub(crate) area_direct: Vec<bool>,
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
}

impl TracerLayout {
    /// The CICE/Icepack layout for `nilyr` ice layers and `nslyr` snow layers (both ≥ 1):
    /// `Tsfc`, `qice(nilyr)`, `qsno(nslyr)`, `sice(nilyr)`, then `iage`, `FY`, `alvl`,
    /// `vlvl`, `apnd`, `hpnd`, `ipnd`, `smice(nslyr)`, `smliq(nslyr)`, `rhos(nslyr)`,
    /// `rsnw(nslyr)`, `isosno(n_iso)`, `isoice(n_iso)` and per aerosol species `k`
    /// `aerosnossl00k`, `aerosnoint00k`, `aeroicessl00k`, `aeroiceint00k` as the flags select,
    /// in the order of Icepack's driver (`icedrv_init.F90`).
    pub fn cice(nilyr: usize, nslyr: usize, flags: CiceTracerFlags) -> Result<Self, ItdError> {
        use TracerBase::*;
        use TracerRole::*;
        if flags.ponds && !flags.level_ice {
            return Err(ItdError::Parameter {
                name: "ponds",
                value: 1.0,
                reason: "melt ponds are carried on level ice: turn on level_ice too",
            });
        }
        if [flags.ponds, flags.pond_topo, flags.pond_sealvl]
            .iter()
            .filter(|x| **x)
            .count()
            > 1
        {
            return Err(ItdError::Parameter {
                name: "pond_topo",
                value: 1.0,
                reason: "one pond scheme at a time: ponds (level ice), pond_topo or pond_sealvl",
            });
        }
        let mut f = vec![
            TracerField::new("Tsfc", SurfaceTemperature, 1, Area, &[]),
            TracerField::new("qice", IceEnthalpy, nilyr, IceVolume, &[]),
            TracerField::new("qsno", SnowEnthalpy, nslyr, SnowVolume, &[]),
            TracerField::new("sice", IceSalinity, nilyr, IceVolume, &[]),
        ];
        if flags.age {
            f.push(TracerField::new("iage", Age, 1, IceVolume, &[]));
        }
        if flags.first_year {
            f.push(TracerField::new("FY", FirstYear, 1, Area, &[]));
        }
        if flags.level_ice {
            f.push(TracerField::new("alvl", LevelArea, 1, Area, &[]));
            f.push(TracerField::new("vlvl", LevelVolume, 1, IceVolume, &[]));
        }
        if flags.ponds {
            f.push(TracerField::new("apnd", PondArea, 1, Area, &["alvl"]));
            f.push(TracerField::new(
                "hpnd",
                PondDepth,
                1,
                Area,
                &["alvl", "apnd"],
            ));
            f.push(TracerField::new(
                "ipnd",
                PondLid,
                1,
                Area,
                &["alvl", "apnd"],
            ));
        }
        if flags.pond_topo || flags.pond_sealvl {
            f.push(TracerField::new("apnd", PondArea, 1, Area, &[]));
            f.push(TracerField::new("hpnd", PondDepth, 1, Area, &["apnd"]));
            f.push(TracerField::new("ipnd", PondLid, 1, Area, &["apnd"]));
        }
        if flags.snow {
            for role in [SnowIceMass, SnowLiquidMass, SnowDensity, SnowGrainRadius] {
                let name = role.icepack().expect("snow tracers have Icepack names").0;
                f.push(TracerField::new(name, role, nslyr, SnowVolume, &[]));
            }
        }
        if flags.fsd > 0 {
            f.push(TracerField::new("fsd", FloeSize, flags.fsd, Area, &[]));
        }
        if flags.isotopes > MAX_ISO {
            return Err(ItdError::Parameter {
                name: "isotopes",
                value: flags.isotopes as f64,
                reason: "at most 3 isotope species (Icepack's icepack_max_iso)",
            });
        }
        if flags.isotopes > 0 {
            f.push(TracerField::new(
                "isosno",
                IsotopeSnow,
                flags.isotopes,
                SnowVolume,
                &[],
            ));
            f.push(TracerField::new(
                "isoice",
                IsotopeIce,
                flags.isotopes,
                IceVolume,
                &[],
            ));
        }
        if flags.aerosols > MAX_AERO {
            return Err(ItdError::Parameter {
                name: "aerosols",
                value: flags.aerosols as f64,
                reason: "at most 6 aerosol species (Icepack's icepack_max_aero)",
            });
        }
        for k in 1..=flags.aerosols {
            for (part, role, base) in [
                ("snossl", AerosolSnow, SnowVolume),
                ("snoint", AerosolSnow, SnowVolume),
                ("icessl", AerosolIce, IceVolume),
                ("iceint", AerosolIce, IceVolume),
            ] {
                f.push(TracerField::new(
                    &format!("aero{part}{k:03}"),
                    role,
                    1,
                    base,
                    &[],
                ));
            }
        }
        if flags.brine {
            f.push(TracerField::new("fbri", BrineFraction, 1, IceVolume, &[]));
        }
        let mut l = Self::new(f)?;
        l.zap_pond_water = flags.pond_topo;
        Ok(l)
    }

    /// The layout with each tracer carried as a host's tables say (Icepack's `trcr_depend`,
    /// `trcr_base(ntrcr, 3)` in Fortran order, `n_trcr_strata`, `nt_strata(ntrcr, 2)` in
    /// Fortran order, 1-based tracer numbers), as Icepack moves every tracer through them:
    /// the base and strata of each tracer are the host's, the roles (which tracer is an
    /// enthalpy, a pond, an aerosol...) stay the layout's. For a host whose tables differ from
    /// those the layout derives (e.g. Icepack's column driver gives only the first isotope
    /// species its dependency; the others are area tracers there). Each `trcr_base` row must
    /// hold one 1 and two 0; a stratum must be an earlier single tracer.
    pub fn with_host_tables(
        mut self,
        trcr_depend: &[i32],
        trcr_base: &[f64],
        n_trcr_strata: &[i32],
        nt_strata: &[i32],
    ) -> Result<Self, ItdError> {
        let nt = self.ntrcr;
        let bad = |msg: String| ItdError::Layout(format!("host tracer tables: {msg}"));
        if trcr_depend.len() != nt
            || trcr_base.len() != 3 * nt
            || n_trcr_strata.len() != nt
            || nt_strata.len() != 2 * nt
        {
            return Err(bad(format!(
                "need trcr_depend({nt}), trcr_base({nt}, 3), n_trcr_strata({nt}), \
                 nt_strata({nt}, 2)"
            )));
        }
        for it in 0..nt {
            let row = [trcr_base[it], trcr_base[nt + it], trcr_base[2 * nt + it]];
            let k = match row {
                [1.0, 0.0, 0.0] => 0u8,
                [0.0, 1.0, 0.0] => 1,
                [0.0, 0.0, 1.0] => 2,
                _ => {
                    return Err(bad(format!(
                        "tracer {}: trcr_base {row:?} is not one of area, ice volume, snow volume",
                        it + 1
                    )));
                }
            };
            let n = n_trcr_strata[it];
            if !(0..=2).contains(&n) {
                return Err(bad(format!("tracer {}: n_trcr_strata = {n}", it + 1)));
            }
            let mut st = [0usize; 2];
            for j in 0..n as usize {
                let s1 = nt_strata[j * nt + it];
                if !(1..=it as i32).contains(&s1) {
                    return Err(bad(format!(
                        "tracer {}: stratum {s1} must be an earlier tracer (1-based)",
                        it + 1
                    )));
                }
                st[j] = s1 as usize - 1;
            }
            let d = trcr_depend[it];
            let expect = if n > 0 {
                2 + st[n as usize - 1] as i32 + 1
            } else {
                k as i32
            };
            if d != expect {
                return Err(bad(format!(
                    "tracer {}: trcr_depend = {d} but its base and strata make {expect}",
                    it + 1
                )));
            }
            self.base_idx[it] = k;
            self.base[it] = TracerBase::ALL[k as usize];
            self.nstrata[it] = n as u8;
            self.strata[it] = st;
            if k == 0 {
                self.empty[it] = 0.0;
            }
        }
        self.derive_lists();
        Ok(self)
    }

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
        let mut starts = Vec::with_capacity(fields.len());
        let mut ntrcr = 0;
        for (i, f) in fields.iter().enumerate() {
            if f.levels == 0 {
                return Err(bad(format!("field {} has 0 levels", f.name)));
            }
            if fields[..i].iter().any(|g| g.name == f.name) {
                return Err(bad(format!("field name {} used twice", f.name)));
            }
            if !f.role.repeats() && fields[..i].iter().any(|g| g.role == f.role) {
                return Err(bad(format!("two fields with role {:?}", f.role)));
            }
            if f.strata.len() > 2 {
                return Err(bad(format!("field {} has more than 2 strata", f.name)));
            }
            starts.push(ntrcr);
            ntrcr += f.levels;
        }
        let find = |role: TracerRole| fields.iter().position(|f| f.role == role);
        let qice = find(TracerRole::IceEnthalpy).ok_or_else(|| bad("no qice field".into()))?;
        let sice = find(TracerRole::IceSalinity).ok_or_else(|| bad("no sice field".into()))?;
        let qsno = find(TracerRole::SnowEnthalpy).ok_or_else(|| bad("no qsno field".into()))?;
        if fields[qice].levels != fields[sice].levels {
            return Err(bad("qice and sice need the same number of levels".into()));
        }
        for (role, base) in [
            (TracerRole::SurfaceTemperature, TracerBase::Area),
            (TracerRole::IceEnthalpy, TracerBase::IceVolume),
            (TracerRole::IceSalinity, TracerBase::IceVolume),
            (TracerRole::SnowEnthalpy, TracerBase::SnowVolume),
            (TracerRole::LevelArea, TracerBase::Area),
            (TracerRole::LevelVolume, TracerBase::IceVolume),
            (TracerRole::PondArea, TracerBase::Area),
            (TracerRole::PondDepth, TracerBase::Area),
            (TracerRole::PondLid, TracerBase::Area),
            (TracerRole::AerosolSnow, TracerBase::SnowVolume),
            (TracerRole::AerosolIce, TracerBase::IceVolume),
        ] {
            if let Some(i) = find(role)
                && (fields[i].base != base || fields[i].levels != 1 && base == TracerBase::Area)
            {
                return Err(bad(format!(
                    "field {} must be a single-level {:?} tracer",
                    fields[i].name, base
                )));
            }
        }
        for (i, f) in fields.iter().enumerate() {
            let base = match f.role {
                TracerRole::AerosolSnow
                | TracerRole::IsotopeSnow
                | TracerRole::SnowIceMass
                | TracerRole::SnowLiquidMass
                | TracerRole::SnowDensity
                | TracerRole::SnowGrainRadius => TracerBase::SnowVolume,
                TracerRole::AerosolIce | TracerRole::IsotopeIce => TracerBase::IceVolume,
                _ => continue,
            };
            let single = !matches!(f.role, TracerRole::AerosolSnow | TracerRole::AerosolIce);
            if f.base != base || !f.strata.is_empty() || (!single && f.levels != 1) {
                return Err(bad(format!(
                    "field {} must be a{} {:?} tracer without strata",
                    fields[i].name,
                    if single { "" } else { " single-level" },
                    base
                )));
            }
        }
        // Aerosols: per species a surface-layer and an interior field in snow and in ice, the
        // k-th pair of each role making species k.
        let of = |role: TracerRole| -> Vec<usize> {
            fields
                .iter()
                .enumerate()
                .filter(|(_, f)| f.role == role)
                .map(|(i, _)| starts[i])
                .collect()
        };
        let (asno, aice) = (of(TracerRole::AerosolSnow), of(TracerRole::AerosolIce));
        if asno.len() != aice.len() || asno.len() % 2 != 0 || asno.len() > 2 * MAX_AERO {
            return Err(bad(format!(
                "aerosols need two snow and two ice fields (surface layer, interior) per \
                 species, at most {MAX_AERO} species: {} snow and {} ice fields",
                asno.len(),
                aice.len()
            )));
        }
        let aero = (0..asno.len() / 2)
            .map(|k| [asno[2 * k], asno[2 * k + 1], aice[2 * k], aice[2 * k + 1]])
            .collect();
        let iso = match (find(TracerRole::IsotopeSnow), find(TracerRole::IsotopeIce)) {
            (None, None) => None,
            (Some(s), Some(i)) if fields[s].levels == fields[i].levels => {
                if fields[s].levels > MAX_ISO {
                    return Err(bad(format!("at most {MAX_ISO} isotope species")));
                }
                Some((starts[s], starts[i], fields[s].levels))
            }
            _ => {
                return Err(bad(
                    "isotopes need isosno and isoice fields with one level per species each".into(),
                ));
            }
        };
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
        let mut base = Vec::with_capacity(ntrcr);
        let mut nstrata = Vec::with_capacity(ntrcr);
        let mut strata = Vec::with_capacity(ntrcr);
        let mut empty = Vec::with_capacity(ntrcr);
        for (i, f) in fields.iter().enumerate() {
            let mut s = [0usize; 2];
            for (k, name) in f.strata.iter().enumerate() {
                let j = fields[..i]
                    .iter()
                    .position(|g| &g.name == name)
                    .ok_or_else(|| {
                        bad(format!(
                            "stratum {name} of {} must be an earlier field",
                            f.name
                        ))
                    })?;
                if fields[j].levels != 1 {
                    return Err(bad(format!("stratum {name} must have one level")));
                }
                s[k] = starts[j];
            }
            // Icepack's ponds: on level ice apnd on [alvl], hpnd and ipnd on [alvl, apnd];
            // topography and sea-level ponds apnd on the area, hpnd and ipnd on [apnd].
            let expected: &[TracerRole] = match (f.role, on_level) {
                (TracerRole::PondArea, true) => &[TracerRole::LevelArea],
                (TracerRole::PondDepth | TracerRole::PondLid, true) => {
                    &[TracerRole::LevelArea, TracerRole::PondArea]
                }
                (TracerRole::PondDepth | TracerRole::PondLid, false) => &[TracerRole::PondArea],
                _ => &[],
            };
            if !expected.is_empty()
                && (f.strata.len() != expected.len()
                    || f.strata.iter().zip(expected).any(|(n, r)| {
                        fields.iter().find(|g| &g.name == n).map(|g| g.role) != Some(*r)
                    }))
            {
                return Err(bad(format!(
                    "field {} must be carried on {:?}",
                    f.name, expected
                )));
            }
            for _ in 0..f.levels {
                empty.push(if f.base == TracerBase::Area {
                    0.0
                } else {
                    f.empty
                });
                base.push(f.base);
                nstrata.push(f.strata.len() as u8);
                strata.push(s);
            }
        }
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
            fields,
            starts,
            ntrcr,
            base,
            nstrata,
            strata,
            area_direct: Vec::new(),
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
        self.area_direct = (0..nt)
            .map(|it| self.base_idx[it] == 0 && self.nstrata[it] == 0)
            .collect();
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
    /// [`OceanFluxes::faero_ocn`](super::OceanFluxes::faero_ocn) the step fills.
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

    /// The optional CICE tracers this layout carries, told from its fields' roles (sea-level
    /// ponds from topography ponds by the clean-up's pond-water booking).
    pub fn cice_flags(&self) -> CiceTracerFlags {
        use TracerRole::*;
        let find = |r: TracerRole| self.fields.iter().find(|f| f.role == r);
        let pond_on_area = self
            .fields
            .iter()
            .any(|f| f.role == PondArea && f.strata.is_empty());
        CiceTracerFlags {
            age: find(Age).is_some(),
            first_year: find(FirstYear).is_some(),
            level_ice: find(LevelArea).is_some(),
            ponds: self
                .fields
                .iter()
                .any(|f| f.role == PondArea && !f.strata.is_empty()),
            snow: [SnowIceMass, SnowLiquidMass, SnowDensity, SnowGrainRadius]
                .iter()
                .all(|r| find(*r).is_some()),
            isotopes: find(IsotopeSnow).map_or(0, |f| f.levels),
            aerosols: self.aero.len(),
            pond_topo: pond_on_area && self.zap_pond_water,
            pond_sealvl: pond_on_area && !self.zap_pond_water,
            fsd: find(FloeSize).map_or(0, |f| f.levels),
            brine: find(BrineFraction).is_some(),
        }
    }

    /// The layout in Icepack's names ([`CiceLayoutSpec`]) when it is exactly a CICE layout
    /// ([`TracerLayout::cice`]), else `None` (other fields, host tables, refill values).
    pub fn cice_spec(&self) -> Option<CiceLayoutSpec> {
        let spec = CiceLayoutSpec {
            nilyr: self.nilyr,
            nslyr: self.nslyr,
            flags: self.cice_flags(),
        };
        spec.layout().is_ok_and(|l| l == *self).then_some(spec)
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

    /// The name of every tracer (index order) as a CICE restart file names its variable:
    /// `Tsfcn` for the surface temperature, `<field>NNN` (level 1-based, three digits:
    /// `qice001`, `sice007`, `qsno001`) for the per-layer fields and for any field with more
    /// than one level, else the field name (`iage`, `FY`, `alvl`, `vlvl`, `apnd`, `hpnd`,
    /// `ipnd`). The NetCDF face of the ridging step reads and writes these names.
    pub fn cice_restart_names(&self) -> Vec<String> {
        let mut names = Vec::with_capacity(self.ntrcr);
        for f in &self.fields {
            if f.role == TracerRole::SurfaceTemperature && f.levels == 1 {
                names.push(format!("{}n", f.name));
            } else if f.role.layered() || f.levels > 1 {
                names.extend((1..=f.levels).map(|k| format!("{}{k:03}", f.name)));
            } else {
                names.push(f.name.clone());
            }
        }
        names
    }

    /// The CICE layout of a file or dataset holding snow and tracers under their CICE restart
    /// names ([`TracerLayout::cice_restart_names`]), told from which variable names it has
    /// (`has`): `Ok(None)` when it has none of `vsnon`, `Tsfcn`, `qice001`, `sice001`,
    /// `qsno001` (no snow, no tracers); the numbers of ice and snow layers are those of the
    /// consecutive `qice001..` and `qsno001..` found; each optional group (`iage`; `FY`;
    /// `alvl` with `vlvl`; `apnd`, `hpnd`, `ipnd`) is used when all its variables are there;
    /// the snow tracers (`smice001`.., `smliq001`.., `rhos001`.., `rsnw001`..) when any is,
    /// and as many isotope (`isosno001`.., `isoice001`..) and aerosol species
    /// (`aerosnossl001`, `aerosnoint001`, `aeroicessl001`, `aeroiceint001`, ...) as are numbered.
    /// A missing member of a group, or a base tracer missing for the layers found, is an
    /// error naming the variable. The NetCDF reader and Python's `xr.ridge_step` both use it.
    pub fn detect_cice(
        has: &dyn Fn(&str) -> bool,
    ) -> Result<Option<(TracerLayout, CiceTracerFlags)>, LayoutDetectError> {
        let count = |prefix: &str| {
            (1..)
                .take_while(|k| has(&format!("{prefix}{k:03}")))
                .count()
        };
        let nilyr = count("qice");
        let nslyr = count("qsno");
        let probe = TracerLayout::cice(1, 1, CiceTracerFlags::default())
            .expect("the minimal CICE layout is valid")
            .cice_restart_names();
        if !has("vsnon") && !probe.iter().any(|n| has(n)) {
            return Ok(None);
        }
        let missing = |var: String, why: String| LayoutDetectError { var, why };
        if nilyr == 0 || nslyr == 0 {
            let var = if nilyr == 0 { "qice001" } else { "qsno001" };
            return Err(missing(
                var.into(),
                "the complete ridging step needs the ice enthalpy qice001.. and snow enthalpy \
                 qsno001.. with vsnon and the other tracers (CICE restart names)"
                    .into(),
            ));
        }
        let names = |fl: CiceTracerFlags| {
            TracerLayout::cice(nilyr, nslyr, fl)
                .expect("CICE layouts with level ice are valid")
                .cice_restart_names()
        };
        let f = |age, first_year, level_ice, ponds| CiceTracerFlags {
            age,
            first_year,
            level_ice,
            ponds,
            ..CiceTracerFlags::default()
        };
        // Each optional group: the names it adds to the layout below it.
        let groups: [(CiceTracerFlags, CiceTracerFlags); 4] = [
            (f(true, false, false, false), f(false, false, false, false)),
            (f(false, true, false, false), f(false, false, false, false)),
            (f(false, false, true, false), f(false, false, false, false)),
            (f(false, false, true, true), f(false, false, true, false)),
        ];
        let mut flags = CiceTracerFlags::default();
        for (k, (with, without)) in groups.iter().enumerate() {
            let below = names(*without);
            let added: Vec<String> = names(*with)
                .into_iter()
                .filter(|n| !below.contains(n))
                .collect();
            let present: Vec<bool> = added.iter().map(|n| has(n)).collect();
            if present.iter().all(|p| *p) {
                match k {
                    0 => flags.age = true,
                    1 => flags.first_year = true,
                    2 => flags.level_ice = true,
                    _ => flags.ponds = true,
                }
            } else if present.iter().any(|p| *p) {
                let miss = added
                    .iter()
                    .zip(&present)
                    .find(|(_, p)| !**p)
                    .map(|(n, _)| n.clone())
                    .unwrap_or_default();
                return Err(missing(
                    miss,
                    format!("the tracers {} go together", added.join(", ")),
                ));
            }
        }
        if flags.ponds && !flags.level_ice {
            flags.ponds = false;
        }
        // Snow tracers (all four or none), isotope and aerosol species by count; a partial
        // species is caught by the check of every name below.
        flags.snow = ["smice001", "smliq001", "rhos001", "rsnw001"]
            .iter()
            .any(|n| has(n));
        flags.isotopes = count("isosno").max(count("isoice")).min(MAX_ISO);
        flags.aerosols = ["aerosnossl", "aerosnoint", "aeroicessl", "aeroiceint"]
            .iter()
            .map(|p| count(p))
            .max()
            .unwrap_or(0)
            .min(MAX_AERO);
        let layout = TracerLayout::cice(nilyr, nslyr, flags).map_err(|e| LayoutDetectError {
            var: "qice001".into(),
            why: e.to_string(),
        })?;
        for n in layout.cice_restart_names() {
            if !has(&n) {
                return Err(missing(
                    n.clone(),
                    format!(
                        "there are qice001..qice{nilyr:03} and qsno001..qsno{nslyr:03}, so the \
                         layout needs {n}"
                    ),
                ));
            }
        }
        Ok(Some((layout, flags)))
    }

    /// The field of tracer `it` (index order) and the tracer's level in it (0-based).
    pub fn field_of(&self, it: usize) -> Option<(&TracerField, usize)> {
        let i = self.starts.iter().rposition(|&s| s <= it)?;
        (it < self.ntrcr).then(|| (&self.fields[i], it - self.starts[i]))
    }

    /// Icepack's `trcr_depend` per tracer: 0 area, 1 ice volume, 2 snow volume, `2 + nt`
    /// (1-based `nt`) for a tracer carried on tracer `nt` (its innermost stratum).
    pub fn trcr_depend(&self) -> Vec<i32> {
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
    pub(crate) fn base_codes(&self) -> Vec<i32> {
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
    pub(crate) fn strata_one_based(&self) -> Vec<[i32; 2]> {
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
