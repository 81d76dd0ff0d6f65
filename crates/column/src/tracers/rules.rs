//! The rules a tracer layout's fields must keep ([`super::TracerLayout::new`]): levels,
//! names, roles and bases, aerosol and isotope species, strata and Icepack's ponds; and the
//! per-tracer tables they give.

use super::{MAX_AERO, MAX_ISO, TracerBase, TracerField, TracerRole};
use crate::ItdError;

/// The first tracer index of each field, and the number of tracers; refuses fields of no
/// level, names used twice, two fields of a role that does not repeat, and more than two
/// strata.
pub(super) fn field_starts(fields: &[TracerField]) -> Result<(Vec<usize>, usize), ItdError> {
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
    Ok((starts, ntrcr))
}

/// Refuses a field whose base (area, ice or snow volume) or number of levels its role does
/// not allow.
pub(super) fn check_bases(fields: &[TracerField]) -> Result<(), ItdError> {
    let bad = ItdError::Layout;
    let find = |role: TracerRole| fields.iter().position(|f| f.role == role);
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
    Ok(())
}

/// The aerosol species' first tracers: per species a surface-layer and an interior field in
/// snow and in ice, the k-th pair of each role making species k.
pub(super) fn aerosols(
    fields: &[TracerField],
    starts: &[usize],
) -> Result<Vec<[usize; 4]>, ItdError> {
    let bad = ItdError::Layout;
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
    Ok(aero)
}

/// The water isotopes' first tracer in snow and in ice and their number of species, if any.
pub(super) fn isotopes(
    fields: &[TracerField],
    starts: &[usize],
) -> Result<Option<(usize, usize, usize)>, ItdError> {
    let bad = ItdError::Layout;
    let find = |role: TracerRole| fields.iter().position(|f| f.role == role);
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
    Ok(iso)
}

/// Per tracer: its base, its number of strata and their tracer indices, and its value where
/// its base volume is zero; refuses strata that are not earlier single-level fields and
/// ponds not carried as Icepack carries them (`on_level`: ponds on level ice).
pub(super) fn per_tracer(
    fields: &[TracerField],
    starts: &[usize],
    ntrcr: usize,
    on_level: bool,
) -> Result<PerTracer, ItdError> {
    let bad = ItdError::Layout;
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
                || f.strata
                    .iter()
                    .zip(expected)
                    .any(|(n, r)| fields.iter().find(|g| &g.name == n).map(|g| g.role) != Some(*r)))
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
    Ok(PerTracer {
        base,
        nstrata,
        strata,
        empty,
    })
}

/// The per-tracer tables of [`per_tracer`].
pub(super) struct PerTracer {
    pub base: Vec<TracerBase>,
    pub nstrata: Vec<u8>,
    pub strata: Vec<[usize; 2]>,
    pub empty: Vec<f64>,
}
