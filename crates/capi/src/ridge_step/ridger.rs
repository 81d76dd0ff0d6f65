//! The ridging set-up of the C ABI: the tracer flags, the step's constants
//! ([`PressridgeStepParams`]) and the [`PressridgeRidger`] handle, made once at
//! initialisation, with the queries of its tracer layout.

// Per-category and per-tracer tables are indexed by number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use super::super::itd::PressridgeOptions;
use super::super::layout::check_ptr;
use super::super::{
    FfiError, FfiResult, PRESSRIDGE_ERR_BAD_SIZE, PRESSRIDGE_ERR_BAD_VALUE, guard, put,
};
use pressridge::itd::{
    RidgeStepOptions,
    details::{
        BgcKind, BgcTracers, CiceTracerFlags, MAX_NBTRCR, RidgeStepParams, SaltFlux, TracerLayout,
    },
};

/// Most tracers a host may carry after the flags' layout (`host_ntrcr` beyond its count):
/// CICE carries one.
const MAX_UNNAMED: usize = 8;

/// Tracer flag: ice age `iage` (s, on ice volume), Icepack `tr_iage`.
pub const PRESSRIDGE_TRACER_AGE: i32 = 1;
/// Tracer flag: first-year ice fraction `FY` (on area), Icepack `tr_FY`.
pub const PRESSRIDGE_TRACER_FIRST_YEAR: i32 = 2;
/// Tracer flag: level-ice area and volume fractions `alvl`, `vlvl`, Icepack `tr_lvl`.
pub const PRESSRIDGE_TRACER_LEVEL_ICE: i32 = 4;
/// Tracer flag: level-ice melt ponds `apnd`, `hpnd`, `ipnd`, Icepack `tr_pond_lvl` (needs
/// `PRESSRIDGE_TRACER_LEVEL_ICE`).
pub const PRESSRIDGE_TRACER_PONDS: i32 = 8;
/// Tracer flag: snow tracers `smice`, `smliq`, `rhos` (kg m⁻³), `rsnw` (m), one per snow
/// layer each, on snow volume, Icepack `tr_snow`.
pub const PRESSRIDGE_TRACER_SNOW: i32 = 16;
/// Tracer flag: topography melt ponds `apnd` (on area), `hpnd`, `ipnd` (on pond area), Icepack
/// `tr_pond_topo` (one pond scheme at a time).
pub const PRESSRIDGE_TRACER_POND_TOPO: i32 = 32;
/// Tracer flag: sea-level melt ponds, carried as the topography ponds, `tr_pond_sealvl`.
pub const PRESSRIDGE_TRACER_POND_SEALVL: i32 = 64;
/// Tracer flag: brine height fraction `fbri` (on ice volume; 1 where there is no ice),
/// Icepack `tr_brine`.
pub const PRESSRIDGE_TRACER_BRINE: i32 = 128;

/// `PressridgeTracers::bgc_kind`: no biogeochemical tracers.
pub const PRESSRIDGE_BGC_NONE: i32 = 0;
/// `PressridgeTracers::bgc_kind`: skeletal-layer bio tracers, one value each on ice area,
/// Icepack `skl_bgc`.
pub const PRESSRIDGE_BGC_SKELETAL: i32 = 1;
/// `PressridgeTracers::bgc_kind`: vertically resolved bio tracers, `nblyr + 1` values on the
/// brine grid and two in the snow each, Icepack `z_tracers` (needs
/// `PRESSRIDGE_TRACER_BRINE`).
pub const PRESSRIDGE_BGC_VERTICAL: i32 = 2;

/// The optional tracers of a ridging set-up ([`pressridge_ridger_new`]); all zero and null:
/// none.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressridgeTracers {
    /// Sum of `PRESSRIDGE_TRACER_*` flags.
    pub flags: i32,
    /// Water-isotope species, 0–3 (Icepack `n_iso`).
    pub n_iso: i32,
    /// Aerosol species, 0–6 (Icepack `n_aero`).
    pub n_aero: i32,
    /// Floe-size categories `fsd` (area tracers), ≥ 0 (Icepack `nfsd` with `tr_fsd`).
    pub nfsd: i32,
    /// Snow tracers where there is no snow (kg m⁻³, kg m⁻³, m; with `PRESSRIDGE_TRACER_SNOW`):
    /// 0, or Icepack's refills, `rhos` = `rhosnew` with `snwredist = 'ITD'`, `smice` = `rhos`
    /// and `rsnw` = `rsnw_fall` with `snwgrain`.
    pub rhos_empty: f64,
    /// See `rhos_empty`.
    pub smice_empty: f64,
    /// See `rhos_empty`.
    pub rsnw_empty: f64,
    /// Null, or the host's Icepack tracer tables, `host_ntrcr` tracers (the layout's count, or
    /// up to 8 more: unnamed area tracers after the layout's, as CICE's extra slot):
    /// `trcr_depend(ntrcr)`, `trcr_base(ntrcr, 3)` and `nt_strata(ntrcr, 2)` in Fortran order
    /// (1-based tracer numbers), `n_trcr_strata(ntrcr)`; all four or none. Each tracer is then
    /// carried as they say, as Icepack moves every tracer through them (its roles stay the
    /// layout's).
    pub host_trcr_depend: *const i32,
    /// See `host_trcr_depend`.
    pub host_trcr_base: *const f64,
    /// See `host_trcr_depend`.
    pub host_n_trcr_strata: *const i32,
    /// See `host_trcr_depend`.
    pub host_nt_strata: *const i32,
    /// Number of tracers in the host's tables.
    pub host_ntrcr: i64,
    /// Biogeochemical tracers: `PRESSRIDGE_BGC_NONE` (0, the fields below unused),
    /// `PRESSRIDGE_BGC_SKELETAL` or `PRESSRIDGE_BGC_VERTICAL`.
    pub bgc_kind: i32,
    /// Tracers appended after every other for the biogeochemistry (Icepack's
    /// `ntrcr - ntrcr_o`, less the brine fraction where the host adds it after `ntrcr_o` as
    /// Icepack's column driver does: the bio tracers and what goes with them, e.g.
    /// `zbgc_frac`); they are carried on ice volume unless the host tables say otherwise.
    pub bgc_ntrcr: i32,
    /// Bio grid layers in the ice, Icepack `nblyr` (≥ 1; vertical tracers only).
    pub nblyr: i32,
    /// Skeletal layer thickness (m, > 0), Icepack `sk_l` (skeletal tracers only).
    pub sk_l: f64,
    /// Number of bio tracers, Icepack `nbtrcr` (1–29), the length of `bio_index`.
    pub nbtrcr: i32,
    /// Per bio tracer, its first tracer number (1-based, among all the tracers), Icepack
    /// `bio_index(1:nbtrcr)`; each lies among the `bgc_ntrcr` appended tracers.
    pub bio_index: *const i32,
}

impl Default for PressridgeTracers {
    fn default() -> Self {
        Self {
            flags: 0,
            n_iso: 0,
            n_aero: 0,
            nfsd: 0,
            rhos_empty: 0.0,
            smice_empty: 0.0,
            rsnw_empty: 0.0,
            host_trcr_depend: std::ptr::null(),
            host_trcr_base: std::ptr::null(),
            host_n_trcr_strata: std::ptr::null(),
            host_nt_strata: std::ptr::null(),
            host_ntrcr: 0,
            bgc_kind: PRESSRIDGE_BGC_NONE,
            bgc_ntrcr: 0,
            nblyr: 0,
            sk_l: 0.0,
            nbtrcr: 0,
            bio_index: std::ptr::null(),
        }
    }
}

/// Thermodynamic constants and clean-up thresholds of the ridging step (the fields of
/// `pressridge::itd::details::RidgeStepParams`; Icepack's defaults from
/// [`pressridge_step_params_default`]).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressridgeStepParams {
    /// Snow density (kg/m³), Icepack `rhos` = 330.
    pub rhos: f64,
    /// Latent heat of melting of fresh ice (J/kg), Icepack `Lfresh` = 3.34e5.
    pub lfresh: f64,
    /// Specific heat of fresh ice (J kg⁻¹ K⁻¹), Icepack `cp_ice` = 2106.
    pub cp_ice: f64,
    /// Fraction of the snow on ridging ice kept on the ridge (1), Icepack `fsnowrdg` = 0.5.
    pub fsnowrdg: f64,
    /// Salinity of zapped ice with the constant salt flux (ppt), Icepack 4.
    pub ice_ref_salinity: f64,
    /// 0: zapped ice carries `ice_ref_salinity` (Icepack `saltflux_option = "constant"`);
    /// 1: its own salinity (`"prognostic"`).
    pub salt_flux_prognostic: i32,
    /// Cell ice area below which all ice is zapped (1), Icepack `itd_area_min` = 1e-11.
    pub itd_area_min: f64,
    /// Cell ice mass below which all ice is zapped (kg/m²), Icepack `itd_mass_min` = 1e-10.
    pub itd_mass_min: f64,
    /// Snow thickness above which snow temperatures are checked (m), Icepack `hs_min` = 1e-4.
    pub hs_min: f64,
    /// Lowest physical snow temperature (°C), Icepack `Tmin` = −100.
    pub tmin: f64,
}

impl From<&RidgeStepParams> for PressridgeStepParams {
    fn from(p: &RidgeStepParams) -> Self {
        Self {
            rhos: p.rhos,
            lfresh: p.lfresh,
            cp_ice: p.cp_ice,
            fsnowrdg: p.fsnowrdg,
            ice_ref_salinity: p.ice_ref_salinity,
            salt_flux_prognostic: i32::from(p.salt_flux == SaltFlux::Prognostic),
            itd_area_min: p.itd_area_min,
            itd_mass_min: p.itd_mass_min,
            hs_min: p.hs_min,
            tmin: p.tmin,
        }
    }
}

impl PressridgeStepParams {
    fn to_params(self) -> FfiResult<RidgeStepParams> {
        let p = RidgeStepParams {
            rhos: self.rhos,
            lfresh: self.lfresh,
            cp_ice: self.cp_ice,
            fsnowrdg: self.fsnowrdg,
            ice_ref_salinity: self.ice_ref_salinity,
            salt_flux: match self.salt_flux_prognostic {
                0 => SaltFlux::Constant,
                1 => SaltFlux::Prognostic,
                v => {
                    return Err(FfiError::new(
                        PRESSRIDGE_ERR_BAD_VALUE,
                        format!("salt_flux_prognostic = {v}: must be 0 or 1"),
                    ));
                }
            },
            itd_area_min: self.itd_area_min,
            itd_mass_min: self.itd_mass_min,
            hs_min: self.hs_min,
            tmin: self.tmin,
        };
        p.validate()?;
        Ok(p)
    }
}

/// Fills `*params` with Icepack's defaults.
///
/// # Safety
/// `params` must be valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_step_params_default(params: *mut PressridgeStepParams) -> i32 {
    // SAFETY: `put` checks the pointer; validity is the caller's promise.
    guard(|| unsafe {
        put(
            params,
            PressridgeStepParams::from(&RidgeStepParams::default()),
            "params",
        )
    })
}

/// A ridging set-up: number of categories, tracer layout and options. Immutable after
/// [`pressridge_ridger_new`]; one handle may be used by several threads at once.
#[derive(Debug)]
pub struct PressridgeRidger {
    pub(super) ncat: usize,
    pub(super) layout: TracerLayout,
    pub(super) opts: RidgeStepOptions,
}

pub(super) fn bad_value(msg: String) -> FfiError {
    FfiError::new(PRESSRIDGE_ERR_BAD_VALUE, msg)
}

/// Makes a ridging set-up for `ncat` categories and the CICE tracer layout with `nilyr` ice
/// and `nslyr` snow layers (both ≥ 1) and the optional tracers of `tracers` (null: none), in
/// the order of Icepack's driver: `Tsfc`, `qice(nilyr)`, `qsno(nslyr)`, `sice(nilyr)`,
/// `iage`, `FY`, `alvl`, `vlvl`, `apnd`, `hpnd`, `ipnd`, `smice(nslyr)`, `smliq(nslyr)`,
/// `rhos(nslyr)`, `rsnw(nslyr)`, `fsd(nfsd)`, `isosno(n_iso)`, `isoice(n_iso)`, four aerosol
/// tracers per species (snow surface layer and interior, ice surface layer and interior),
/// `fbri`, then `tracers.bgc_ntrcr` biogeochemical tracers (`bgc_kind`). `options` (null: CICE
/// defaults) gives the participation, redistribution and ridging parameters (its strength
/// fields are not used), `step_params` (null: Icepack defaults) the thermodynamic constants;
/// `cleanup` and `rebin` are Icepack's `docleanup`, `dorebin` (nonzero = true). Writes the
/// handle to `*ridger`; release it with [`pressridge_ridger_free`].
///
/// # Safety
/// `tracers`, `options` and `step_params` must be null or valid (with `tracers`' host tables
/// null or holding `host_ntrcr` values each, 3· and 2· for `trcr_base` and `nt_strata`, and
/// `bio_index` holding `nbtrcr` values when `bgc_kind` is not 0); `ridger` valid for one
/// write.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pressridge_ridger_new(
    ncat: i64,
    nilyr: i64,
    nslyr: i64,
    tracers: *const PressridgeTracers,
    options: *const PressridgeOptions,
    step_params: *const PressridgeStepParams,
    cleanup: i32,
    rebin: i32,
    ridger: *mut *mut PressridgeRidger,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        check_ptr(ridger, "ridger")?;
        for (name, v) in [("ncat", ncat), ("nilyr", nilyr), ("nslyr", nslyr)] {
            if !(1..=1 << 20).contains(&v) {
                return Err(FfiError::new(
                    PRESSRIDGE_ERR_BAD_SIZE,
                    format!("{name} = {v}: must be at least 1"),
                ));
            }
        }
        let t = if tracers.is_null() {
            PressridgeTracers::default()
        } else {
            *tracers
        };
        let tracer_flags = t.flags;
        if tracer_flags & !255 != 0 {
            return Err(bad_value(format!(
                "tracers.flags = {tracer_flags}: only PRESSRIDGE_TRACER_* (1, 2, 4, ..., 128) \
                 may be set"
            )));
        }
        for (name, v, max) in [
            ("tracers.n_iso", t.n_iso, 3),
            ("tracers.n_aero", t.n_aero, 6),
            ("tracers.nfsd", t.nfsd, 1 << 20),
        ] {
            if !(0..=max).contains(&v) {
                return Err(bad_value(format!("{name} = {v}: must be 0 to {max}")));
            }
        }
        let flags = CiceTracerFlags {
            age: tracer_flags & PRESSRIDGE_TRACER_AGE != 0,
            first_year: tracer_flags & PRESSRIDGE_TRACER_FIRST_YEAR != 0,
            level_ice: tracer_flags & PRESSRIDGE_TRACER_LEVEL_ICE != 0,
            ponds: tracer_flags & PRESSRIDGE_TRACER_PONDS != 0,
            snow: tracer_flags & PRESSRIDGE_TRACER_SNOW != 0,
            isotopes: t.n_iso as usize,
            aerosols: t.n_aero as usize,
            pond_topo: tracer_flags & PRESSRIDGE_TRACER_POND_TOPO != 0,
            pond_sealvl: tracer_flags & PRESSRIDGE_TRACER_POND_SEALVL != 0,
            fsd: t.nfsd as usize,
            brine: tracer_flags & PRESSRIDGE_TRACER_BRINE != 0,
        };
        let mut layout = TracerLayout::cice(nilyr as usize, nslyr as usize, flags)?;
        // SAFETY: bgc_layout reads `bio_index` only as the caller promised.
        layout = bgc_layout(layout, &t)?;
        for (name, v) in [
            ("rhos", t.rhos_empty),
            ("smice", t.smice_empty),
            ("rsnw", t.rsnw_empty),
        ] {
            if v != 0.0 {
                if !flags.snow {
                    return Err(bad_value(format!(
                        "tracers.{name}_empty = {v}: needs PRESSRIDGE_TRACER_SNOW"
                    )));
                }
                layout = layout.with_empty_value(name, v)?;
            }
        }
        let tables = [
            t.host_trcr_depend.is_null(),
            t.host_trcr_base.is_null(),
            t.host_n_trcr_strata.is_null(),
            t.host_nt_strata.is_null(),
        ];
        if tables.iter().any(|n| !n) {
            if tables.iter().any(|n| *n) {
                return Err(bad_value(
                    "tracers.host_*: give all four host tables or none".to_string(),
                ));
            }
            // A host array longer than the flags' layout (CICE's slot after its tracers)
            // carries the rest as unnamed area tracers, as its tables say.
            let named = layout.ntrcr();
            if t.host_ntrcr < named as i64 || t.host_ntrcr > (named + MAX_UNNAMED) as i64 {
                return Err(FfiError::new(
                    PRESSRIDGE_ERR_BAD_SIZE,
                    format!(
                        "tracers.host_ntrcr = {}: the layout of these flags has {named} tracers \
                         (a host may carry up to {MAX_UNNAMED} more, unnamed, after them)",
                        t.host_ntrcr
                    ),
                ));
            }
            layout = layout.with_unnamed_tracers(t.host_ntrcr as usize - named);
            let nt = layout.ntrcr();
            // SAFETY: non-null, and the caller's promise is that each holds host_ntrcr
            // (trcr_base 3·, nt_strata 2·) values, checked to be the layout's count above.
            let (dep, base, nst, st) = (
                std::slice::from_raw_parts(t.host_trcr_depend, nt),
                std::slice::from_raw_parts(t.host_trcr_base, 3 * nt),
                std::slice::from_raw_parts(t.host_n_trcr_strata, nt),
                std::slice::from_raw_parts(t.host_nt_strata, 2 * nt),
            );
            layout = layout.with_host_tables(dep, base, nst, st)?;
        }
        let o = PressridgeOptions::from_ptr(options)?;
        let ro = o.ridge_options()?;
        let step = if step_params.is_null() {
            RidgeStepParams::default()
        } else {
            check_ptr(step_params, "step_params")?;
            (*step_params).to_params()?
        };
        let opts = RidgeStepOptions {
            participation: ro.participation,
            redistribution: ro.redistribution,
            params: ro.params,
            step,
            cleanup: cleanup != 0,
            rebin: rebin != 0,
        };
        let h = Box::new(PressridgeRidger {
            ncat: ncat as usize,
            layout,
            opts,
        });
        ridger.write(Box::into_raw(h));
        Ok(())
    })
}

/// Releases a handle of [`pressridge_ridger_new`] (null is allowed and does nothing).
///
/// # Safety
/// `ridger` must come from `pressridge_ridger_new`, not be in use, and not be freed twice.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridger_free(ridger: *mut PressridgeRidger) -> i32 {
    // SAFETY: ownership returns from the caller, as documented.
    guard(|| unsafe {
        if !ridger.is_null() {
            drop(Box::from_raw(ridger));
        }
        Ok(())
    })
}

/// `layout` with the biogeochemical tracers of `t` (none when `t.bgc_kind` is 0).
///
/// # Safety
/// With `t.bgc_kind` not 0, `t.bio_index` must be null or hold `t.nbtrcr` values.
unsafe fn bgc_layout(layout: TracerLayout, t: &PressridgeTracers) -> FfiResult<TracerLayout> {
    let kind = match t.bgc_kind {
        PRESSRIDGE_BGC_NONE => return Ok(layout),
        PRESSRIDGE_BGC_SKELETAL => BgcKind::Skeletal { sk_l: t.sk_l },
        PRESSRIDGE_BGC_VERTICAL => BgcKind::Vertical {
            nblyr: usize::try_from(t.nblyr)
                .map_err(|_| bad_value(format!("tracers.nblyr = {}: must be >= 1", t.nblyr)))?,
        },
        k => {
            return Err(bad_value(format!(
                "tracers.bgc_kind = {k}: must be PRESSRIDGE_BGC_NONE (0), _SKELETAL (1) or \
                 _VERTICAL (2)"
            )));
        }
    };
    if !(1..=MAX_NBTRCR as i32).contains(&t.nbtrcr) {
        return Err(bad_value(format!(
            "tracers.nbtrcr = {}: must be 1 to {MAX_NBTRCR} with bio tracers",
            t.nbtrcr
        )));
    }
    let extra = usize::try_from(t.bgc_ntrcr)
        .map_err(|_| bad_value(format!("tracers.bgc_ntrcr = {}: must be >= 0", t.bgc_ntrcr)))?;
    check_ptr(t.bio_index, "tracers.bio_index")?;
    // SAFETY: non-null, and holds nbtrcr (1..=29, checked) values by the caller's promise.
    let one_based = unsafe { std::slice::from_raw_parts(t.bio_index, t.nbtrcr as usize) };
    let bio_index = one_based
        .iter()
        .enumerate()
        .map(|(m, &b)| {
            usize::try_from(b)
                .ok()
                .and_then(|b| b.checked_sub(1))
                .ok_or_else(|| {
                    bad_value(format!(
                        "tracers.bio_index[{m}] = {b}: tracer numbers count from 1"
                    ))
                })
        })
        .collect::<FfiResult<Vec<_>>>()?;
    Ok(layout.with_bgc(extra, BgcTracers { kind, bio_index })?)
}

pub(super) unsafe fn ridger_ref<'a>(r: *const PressridgeRidger) -> FfiResult<&'a PressridgeRidger> {
    check_ptr(r, "ridger")?;
    // SAFETY: non-null, aligned; validity is the caller's promise.
    Ok(unsafe { &*r })
}

/// The tracer layout of a set-up, as Icepack's arrays: `*ntrcr` (tracers per category), and
/// where not null, for each tracer (arrays of `ntrcr_len` ≥ ntrcr elements; the two 2-D ones
/// Fortran-ordered `(ntrcr_len, 3)` and `(ntrcr_len, 2)`): `trcr_depend` (0 area, 1 ice volume,
/// 2 snow volume, 2 + nt for tracer nt, 1-based), `trcr_base` (1 in the column of its base),
/// `n_trcr_strata` and `nt_strata` (1-based tracer indices, 0 = none).
///
/// # Safety
/// Non-null pointers must be valid for the writes described.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridger_tracers(
    ridger: *const PressridgeRidger,
    ntrcr: *mut i64,
    ntrcr_len: i64,
    trcr_depend: *mut i32,
    trcr_base: *mut f64,
    n_trcr_strata: *mut i32,
    nt_strata: *mut i32,
) -> i32 {
    // SAFETY: pointers checked; validity is the caller's promise.
    guard(|| unsafe {
        let r = ridger_ref(ridger)?;
        let l = &r.layout;
        let nt = l.ntrcr();
        put(ntrcr, nt as i64, "ntrcr")?;
        let any = [
            trcr_depend.is_null(),
            trcr_base.is_null(),
            n_trcr_strata.is_null(),
            nt_strata.is_null(),
        ]
        .iter()
        .any(|n| !n);
        if !any {
            return Ok(());
        }
        if ntrcr_len < nt as i64 {
            return Err(FfiError::new(
                PRESSRIDGE_ERR_BAD_SIZE,
                format!("ntrcr_len = {ntrcr_len}: the layout has {nt} tracers"),
            ));
        }
        let len = ntrcr_len as usize;
        let dep = l.trcr_depend();
        let base = l.base_codes();
        let strata = l.strata_one_based();
        for it in 0..nt {
            if !trcr_depend.is_null() {
                put(trcr_depend.add(it), dep[it], "trcr_depend")?;
            }
            if !trcr_base.is_null() {
                for k in 0..3 {
                    let v = if base[it] == k as i32 { 1.0 } else { 0.0 };
                    put(trcr_base.add(it + k * len), v, "trcr_base")?;
                }
            }
            if !n_trcr_strata.is_null() {
                let n = strata[it].iter().filter(|s| **s > 0).count() as i32;
                put(n_trcr_strata.add(it), n, "n_trcr_strata")?;
            }
            if !nt_strata.is_null() {
                for k in 0..2 {
                    put(nt_strata.add(it + k * len), strata[it][k], "nt_strata")?;
                }
            }
        }
        Ok(())
    })
}

/// First tracer index (0-based) and number of levels of the tracer field `name` (`len`
/// bytes of UTF-8: `Tsfc`, `qice`, `qsno`, `sice`, `iage`, `FY`, `alvl`, `vlvl`, `apnd`,
/// `hpnd`, `ipnd`); `PRESSRIDGE_ERR_NOT_FOUND` when the layout has no such field.
///
/// # Safety
/// `name` valid for `len` bytes; `start`, `levels` valid for one write each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_ridger_tracer_field(
    ridger: *const PressridgeRidger,
    name: *const u8,
    len: i64,
    start: *mut i64,
    levels: *mut i64,
) -> i32 {
    // SAFETY: pointers checked; validity is the caller's promise.
    guard(|| unsafe {
        let r = ridger_ref(ridger)?;
        check_ptr(name, "name")?;
        if len < 0 {
            return Err(FfiError::new(PRESSRIDGE_ERR_BAD_SIZE, "len < 0"));
        }
        let s = std::str::from_utf8(std::slice::from_raw_parts(name, len as usize))
            .map_err(|e| FfiError::new(super::super::PRESSRIDGE_ERR_PARSE, e.to_string()))?;
        let (a, b) = r.layout.field(s).ok_or_else(|| {
            FfiError::new(
                super::super::PRESSRIDGE_ERR_NOT_FOUND,
                format!("no tracer field {s} in this layout"),
            )
        })?;
        put(start, a as i64, "start")?;
        put(levels, b as i64, "levels")
    })
}
