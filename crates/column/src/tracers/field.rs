//! One tracer field: what it is ([`TracerRole`]), what it is carried on ([`TracerBase`]) and
//! its place in a layout ([`TracerField`]).

/// What a tracer is carried on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TracerBase {
    /// Ice area `aicen` (Icepack `trcr_depend = 0`, or `2 + nt` through a stratum).
    Area,
    /// Ice volume `vicen` (Icepack `trcr_depend = 1`).
    IceVolume,
    /// Snow volume `vsnon` (Icepack `trcr_depend = 2`).
    SnowVolume,
}

/// The physical meaning of a tracer, where the ridging step or the clean-up treats it
/// specially (everything else is [`TracerRole::Other`] and just moves with its base).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TracerRole {
    /// Surface temperature `Tsfc` (°C), area tracer; set to the freezing temperature `Tf` in
    /// emptied categories.
    SurfaceTemperature,
    /// Ice enthalpy per layer `qice` (J m⁻³, negative), ice-volume tracer.
    IceEnthalpy,
    /// Snow enthalpy per layer `qsno` (J m⁻³, negative), snow-volume tracer.
    SnowEnthalpy,
    /// Ice salinity per layer `sice` (ppt), ice-volume tracer.
    IceSalinity,
    /// Ice age `iage` (s), ice-volume tracer.
    Age,
    /// First-year ice area fraction `FY` (1), area tracer.
    FirstYear,
    /// Level-ice area fraction `alvl` (1), area tracer; not given to new ridges.
    LevelArea,
    /// Level-ice volume fraction `vlvl` (1), ice-volume tracer; not given to new ridges.
    LevelVolume,
    /// Pond area fraction of the level ice `apnd` (1), on level-ice area.
    PondArea,
    /// Pond depth `hpnd` (m), on pond area.
    PondDepth,
    /// Refrozen pond-lid thickness `ipnd` (m), on pond area.
    PondLid,
    /// Mass of ice in snow per layer `smice` (kg m⁻³), snow-volume tracer (Icepack `tr_snow`).
    SnowIceMass,
    /// Mass of liquid water in snow per layer `smliq` (kg m⁻³), snow-volume tracer.
    SnowLiquidMass,
    /// Effective snow density per layer `rhos` (kg m⁻³), snow-volume tracer.
    SnowDensity,
    /// Snow grain radius per layer `rsnw` (m), snow-volume tracer.
    SnowGrainRadius,
    /// Floe size distribution `fsd` (1), area tracer, one level per floe-size category
    /// (Icepack `tr_fsd`).
    FloeSize,
    /// Brine height fraction `fbri` (1), ice-volume tracer; 1 where there is no ice (Icepack
    /// `tr_brine`). Tracers carried on it (strata `["fbri"]`) are given to new ridges.
    BrineFraction,
    /// Aerosol in snow (kg m⁻³), snow-volume tracer, single-level: one field for the
    /// surface scattering layer and one for the interior of each species, in that order
    /// (CICE's `aerosnossl00k`, `aerosnoint00k`). The share of snow on ridging ice that goes
    /// to the ocean, and zapped snow, take it into `faero_ocn`.
    AerosolSnow,
    /// Aerosol in ice (kg m⁻³), ice-volume tracer, single-level, as [`TracerRole::AerosolSnow`]
    /// (`aeroicessl00k`, `aeroiceint00k`); zapped ice puts it into `faero_ocn`.
    AerosolIce,
    /// Water isotopes in snow `isosno` (kg m⁻³), snow-volume tracer, one level per species;
    /// into `fiso_ocn` with the snow that leaves.
    IsotopeSnow,
    /// Water isotopes in ice `isoice` (kg m⁻³), ice-volume tracer, one level per species;
    /// into `fiso_ocn` with zapped ice and, as in Icepack, with the snow that ridging puts into
    /// the ocean.
    IsotopeIce,
    /// Any other tracer (units as the host defines them).
    Other,
}

impl TracerBase {
    /// Every base, in Icepack's `trcr_depend` order.
    pub const ALL: [TracerBase; 3] = [
        TracerBase::Area,
        TracerBase::IceVolume,
        TracerBase::SnowVolume,
    ];

    /// Lower-case name (`area`, `ice_volume`, `snow_volume`), as the Python face spells it.
    pub fn name(self) -> &'static str {
        match self {
            TracerBase::Area => "area",
            TracerBase::IceVolume => "ice_volume",
            TracerBase::SnowVolume => "snow_volume",
        }
    }

    /// The base called `name` ([`TracerBase::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|b| b.name() == name)
    }
}

impl TracerRole {
    /// Every role.
    pub const ALL: [TracerRole; 22] = [
        TracerRole::SurfaceTemperature,
        TracerRole::IceEnthalpy,
        TracerRole::SnowEnthalpy,
        TracerRole::IceSalinity,
        TracerRole::Age,
        TracerRole::FirstYear,
        TracerRole::LevelArea,
        TracerRole::LevelVolume,
        TracerRole::PondArea,
        TracerRole::PondDepth,
        TracerRole::PondLid,
        TracerRole::SnowIceMass,
        TracerRole::SnowLiquidMass,
        TracerRole::SnowDensity,
        TracerRole::SnowGrainRadius,
        TracerRole::FloeSize,
        TracerRole::BrineFraction,
        TracerRole::AerosolSnow,
        TracerRole::AerosolIce,
        TracerRole::IsotopeSnow,
        TracerRole::IsotopeIce,
        TracerRole::Other,
    ];

    /// Lower-case name (`surface_temperature`, `ice_enthalpy`, ..., `other`), as the Python
    /// face spells it.
    pub fn name(self) -> &'static str {
        use TracerRole::*;
        match self {
            SurfaceTemperature => "surface_temperature",
            IceEnthalpy => "ice_enthalpy",
            SnowEnthalpy => "snow_enthalpy",
            IceSalinity => "ice_salinity",
            Age => "age",
            FirstYear => "first_year",
            LevelArea => "level_area",
            LevelVolume => "level_volume",
            PondArea => "pond_area",
            PondDepth => "pond_depth",
            PondLid => "pond_lid",
            SnowIceMass => "snow_ice_mass",
            SnowLiquidMass => "snow_liquid_mass",
            SnowDensity => "snow_density",
            SnowGrainRadius => "snow_grain_radius",
            FloeSize => "floe_size",
            BrineFraction => "brine_fraction",
            AerosolSnow => "aerosol_snow",
            AerosolIce => "aerosol_ice",
            IsotopeSnow => "isotope_snow",
            IsotopeIce => "isotope_ice",
            Other => "other",
        }
    }

    /// The role called `name` ([`TracerRole::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|r| r.name() == name)
    }

    /// Icepack's field name of this role (`Tsfc`, `qice`, `qsno`, `sice`, `iage`, `FY`,
    /// `alvl`, `vlvl`, `apnd`, `hpnd`, `ipnd`, `smice`, `smliq`, `rhos`, `rsnw`, `isosno`,
    /// `isoice`; none for the aerosols,
    /// whose names carry the species, and for [`TracerRole::Other`]), and its base and strata
    /// as [`TracerLayout::cice`](super::TracerLayout::cice) carries it.
    pub fn icepack(self) -> Option<(&'static str, TracerBase, &'static [&'static str])> {
        use TracerBase::*;
        use TracerRole::*;
        Some(match self {
            SurfaceTemperature => ("Tsfc", Area, &[]),
            IceEnthalpy => ("qice", IceVolume, &[]),
            SnowEnthalpy => ("qsno", SnowVolume, &[]),
            IceSalinity => ("sice", IceVolume, &[]),
            Age => ("iage", IceVolume, &[]),
            FirstYear => ("FY", Area, &[]),
            LevelArea => ("alvl", Area, &[]),
            LevelVolume => ("vlvl", IceVolume, &[]),
            PondArea => ("apnd", Area, &["alvl"]),
            PondDepth => ("hpnd", Area, &["alvl", "apnd"]),
            PondLid => ("ipnd", Area, &["alvl", "apnd"]),
            SnowIceMass => ("smice", SnowVolume, &[]),
            SnowLiquidMass => ("smliq", SnowVolume, &[]),
            SnowDensity => ("rhos", SnowVolume, &[]),
            SnowGrainRadius => ("rsnw", SnowVolume, &[]),
            FloeSize => ("fsd", Area, &[]),
            BrineFraction => ("fbri", IceVolume, &[]),
            IsotopeSnow => ("isosno", SnowVolume, &[]),
            IsotopeIce => ("isoice", IceVolume, &[]),
            AerosolSnow | AerosolIce | Other => return None,
        })
    }

    /// CF `units` of a tracer of this role (CICE's units: °C, J m⁻³, ppt, s, m; `""` for
    /// [`TracerRole::Other`], whose units the host defines).
    pub fn units(self) -> &'static str {
        use TracerRole::*;
        match self {
            SurfaceTemperature => "degC",
            IceEnthalpy | SnowEnthalpy => "J m-3",
            IceSalinity => "ppt",
            Age => "s",
            FirstYear | LevelArea | LevelVolume | PondArea | FloeSize | BrineFraction => "1",
            PondDepth | PondLid => "m",
            SnowIceMass | SnowLiquidMass | SnowDensity => "kg m-3",
            SnowGrainRadius => "m",
            AerosolSnow | AerosolIce | IsotopeSnow | IsotopeIce => "kg m-3",
            Other => "",
        }
    }

    /// A CF `long_name` of a tracer of this role.
    pub fn long_name(self) -> &'static str {
        use TracerRole::*;
        match self {
            SurfaceTemperature => "ice/snow surface temperature",
            IceEnthalpy => "ice enthalpy of a layer (negative)",
            SnowEnthalpy => "snow enthalpy of a layer (negative)",
            IceSalinity => "ice salinity of a layer",
            Age => "ice age",
            FirstYear => "first-year ice area fraction",
            LevelArea => "level ice area fraction",
            LevelVolume => "level ice volume fraction",
            PondArea => "melt pond area fraction of the level ice",
            PondDepth => "melt pond depth",
            PondLid => "refrozen melt pond lid thickness",
            SnowIceMass => "mass of ice in a snow layer",
            SnowLiquidMass => "mass of liquid water in a snow layer",
            SnowDensity => "effective density of a snow layer",
            SnowGrainRadius => "snow grain radius of a layer",
            FloeSize => "floe size distribution (area fraction per floe-size category)",
            BrineFraction => "brine height over ice thickness",
            AerosolSnow => "aerosol in snow (surface layer or interior)",
            AerosolIce => "aerosol in ice (surface layer or interior)",
            IsotopeSnow => "water isotope in snow",
            IsotopeIce => "water isotope in ice",
            Other => "tracer",
        }
    }

    /// Whether a layout may hold several fields of this role (the aerosol fields, one per
    /// species and part, and [`TracerRole::Other`]).
    pub(super) fn repeats(self) -> bool {
        matches!(
            self,
            TracerRole::AerosolSnow | TracerRole::AerosolIce | TracerRole::Other
        )
    }

    /// Whether CICE numbers this role's variables per layer (`qice001`, ...) even with one
    /// layer.
    pub(super) fn layered(self) -> bool {
        matches!(
            self,
            TracerRole::IceEnthalpy
                | TracerRole::SnowEnthalpy
                | TracerRole::IceSalinity
                | TracerRole::SnowIceMass
                | TracerRole::SnowLiquidMass
                | TracerRole::SnowDensity
                | TracerRole::SnowGrainRadius
                | TracerRole::FloeSize
                | TracerRole::IsotopeSnow
                | TracerRole::IsotopeIce
        )
    }
}

/// One named tracer field (one or more levels, consecutive in the tracer vector).
#[derive(Debug, Clone, PartialEq)]
pub struct TracerField {
    /// Name (Icepack's: `Tsfc`, `qice`, `qsno`, `sice`, `iage`, `FY`, `alvl`, `vlvl`, `apnd`,
    /// `hpnd`, `ipnd`).
    pub name: String,
    /// Physical meaning.
    pub role: TracerRole,
    /// Number of levels (layers), ≥ 1.
    pub levels: usize,
    /// What the tracer is carried on (before its strata).
    pub base: TracerBase,
    /// Names of the single-level fields it is additionally carried on, outermost first
    /// (e.g. `["alvl", "apnd"]` for pond depth). At most two.
    pub strata: Vec<String>,
    /// The value where its base volume is zero, and in categories the clean-up empties
    /// (units of the tracer): 0 but for Icepack's refills — `fbri` = 1, and with Icepack's
    /// `snwredist = 'ITD'` `rhos` = `rhosnew`, with `snwgrain` `smice` = `rhos` and `rsnw` =
    /// `rsnw_fall` (set with [`TracerLayout::with_empty_value`](super::TracerLayout::with_empty_value)).
    /// Used for ice- and snow-volume tracers only.
    pub empty: f64,
}

impl TracerField {
    pub(super) fn new(
        name: &str,
        role: TracerRole,
        levels: usize,
        base: TracerBase,
        strata: &[&str],
    ) -> Self {
        Self {
            name: name.to_string(),
            role,
            levels,
            base,
            strata: strata.iter().map(|s| s.to_string()).collect(),
            empty: if role == TracerRole::BrineFraction {
                1.0
            } else {
                0.0
            },
        }
    }
}
