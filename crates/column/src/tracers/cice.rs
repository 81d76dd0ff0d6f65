//! The CICE/Icepack tracer layout: which optional tracers a column carries
//! ([`CiceTracerFlags`]), the layout in the order of Icepack's driver
//! ([`TracerLayout::cice`]), its CICE restart variable names, and the layout told from
//! those names ([`TracerLayout::detect_cice`]).

use super::{CiceLayoutSpec, MAX_AERO, MAX_ISO, TracerBase, TracerField, TracerLayout, TracerRole};
use crate::ItdError;

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
                reason: "melt ponds are carried on level ice: turn on level_ice too".into(),
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
                reason: "one pond scheme at a time: ponds (level ice), pond_topo or pond_sealvl"
                    .into(),
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
                reason: "at most 3 isotope species (Icepack's icepack_max_iso)".into(),
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
                reason: "at most 6 aerosol species (Icepack's icepack_max_aero)".into(),
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
    /// ([`TracerLayout::cice`], or one made from a [`CiceLayoutSpec`] with biogeochemistry),
    /// else `None` (other fields, host tables, refill values).
    pub fn cice_spec(&self) -> Option<CiceLayoutSpec> {
        let spec = CiceLayoutSpec {
            nilyr: self.nilyr,
            nslyr: self.nslyr,
            flags: self.cice_flags(),
            bgc: self.icedrv_bgc,
        };
        spec.layout().is_ok_and(|l| l == *self).then_some(spec)
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
}
