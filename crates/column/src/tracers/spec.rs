//! A CICE/Icepack tracer layout named in words, for files that hold the tracers packed in one
//! array (Icepack column driver's history `trcrn(time, ncat, ntrcr, ni)`): the command line's
//! `--tracer-layout` and Python's `TracerLayout.from_spec` read the same text.
//!
//! The text is a comma-separated list of Icepack's own names, as a host's namelist
//! (`tracer_nml`) and settings (`NICELYR`, `NSNWLYR`, `NFSDCAT`, `NTRISO`, `NTRAERO`) give
//! them: the layer counts `nilyr=N`, `nslyr=N`; the switches `tr_iage`, `tr_FY`, `tr_lvl`,
//! `tr_pond_lvl`, `tr_pond_topo`, `tr_pond_sealvl`, `tr_snow`, `tr_fsd`, `tr_iso`, `tr_aero`,
//! `tr_brine` (alone: on; or `=true`/`=.false.`...); the counts `nfsd=N`, `n_iso=N`,
//! `n_aero=N`; the biogeochemical tracers of Icepack's column driver ([`IcedrvBgc`]: `zbgc_nml`'s
//! `z_tracers` with `nblyr=N`, or `skl_bgc`, and the switches `tr_bgc_N`, `tr_bgc_Nit`,
//! `tr_bgc_C`, `tr_bgc_chl`, `tr_bgc_Am`, `tr_bgc_Sil`, `tr_bgc_DMS`, `tr_bgc_PON`,
//! `tr_bgc_DON`, `tr_bgc_Fe`, `tr_bgc_hum`, `tr_zaero` with the counts `n_algae`, `n_doc`,
//! `n_dic`, `n_don`, `n_fed`, `n_fep`, `n_zaero`); and the preset [`PRESETS`] (`icedrv`).
//! Names are case-insensitive, as in a Fortran namelist; a later item overrides an earlier
//! one (`icedrv,tr_iage`). As in Icepack, a count is used only where its switch is on, and a
//! switch on with no count is an error. The packing order is Icepack's (`icedrv_init.F90`),
//! that of [`TracerLayout::cice`], with the biogeochemical tracers last.

use std::fmt;
use std::str::FromStr;

use super::{CiceTracerFlags, MAX_AERO, MAX_ISO, TracerLayout};
use crate::ItdError;

mod bgc;
pub use bgc::IcedrvBgc;

/// Named layouts: (name, the items it stands for, what it is).
pub const PRESETS: &[(&str, &str, &str)] = &[(
    "icedrv",
    "nilyr=7,nslyr=1,tr_lvl,tr_pond_lvl",
    "Icepack's column driver as configured out of the box (icepack_in, icepack.settings): \
     7 ice layers, 1 snow layer, level ice and level-ice ponds; 21 tracers",
)];

/// The switches, by Icepack name, and the flag each sets.
const SWITCHES: &[&str] = &[
    "tr_iage",
    "tr_FY",
    "tr_lvl",
    "tr_pond_lvl",
    "tr_pond_topo",
    "tr_pond_sealvl",
    "tr_snow",
    "tr_fsd",
    "tr_iso",
    "tr_aero",
    "tr_brine",
];

/// The counts, by Icepack name.
const COUNTS: &[&str] = &["nilyr", "nslyr", "nfsd", "n_iso", "n_aero"];

/// Why a layout text is refused: the item and the reason.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("tracer layout item `{item}`: {why}")]
pub struct LayoutSpecError {
    /// The item refused (or the key that is missing).
    pub item: String,
    /// Why.
    pub why: String,
}

/// A CICE/Icepack tracer layout given by Icepack's names: the layer counts, the optional
/// tracers ([`CiceTracerFlags`]) and any biogeochemical tracers as Icepack's column driver
/// sets them up ([`IcedrvBgc`]). `Display` writes the canonical text, which parses back to
/// the same value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CiceLayoutSpec {
    /// Ice layers (Icepack `nilyr`, ≥ 1).
    pub nilyr: usize,
    /// Snow layers (Icepack `nslyr`, ≥ 1).
    pub nslyr: usize,
    /// The optional tracers.
    pub flags: CiceTracerFlags,
    /// Biogeochemical tracers after all the others (`z_tracers` or `skl_bgc`), if any.
    pub bgc: Option<IcedrvBgc>,
}

impl CiceLayoutSpec {
    /// The layout, in Icepack's packing order ([`TracerLayout::cice`]), with the
    /// biogeochemical tracers appended and carried by the column driver's tables.
    pub fn layout(&self) -> Result<TracerLayout, ItdError> {
        let l = TracerLayout::cice(self.nilyr, self.nslyr, self.flags)?;
        match &self.bgc {
            Some(b) => b.apply(l),
            None => Ok(l),
        }
    }
}

/// Parses `true`/`false` as a Fortran namelist writes them, or the usual words.
fn parse_bool(v: &str) -> Option<bool> {
    match v.to_ascii_lowercase().trim_matches('.') {
        "true" | "t" | "1" | "yes" | "on" => Some(true),
        "false" | "f" | "0" | "no" | "off" => Some(false),
        _ => None,
    }
}

impl FromStr for CiceLayoutSpec {
    type Err = LayoutSpecError;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let err = |item: &str, why: String| LayoutSpecError {
            item: item.to_string(),
            why,
        };
        let mut sw = [false; 11];
        // nilyr, nslyr, nfsd, n_iso, n_aero as given.
        let mut counts: [Option<usize>; 5] = [None; 5];
        let mut bgc_sw = [false; 14];
        let mut bgc_counts: [Option<usize>; 8] = [None; 8];
        let mut items: Vec<String> = Vec::new();
        for item in text.split([',', ' ', '\t', '\n']).filter(|s| !s.is_empty()) {
            match PRESETS.iter().find(|p| p.0.eq_ignore_ascii_case(item)) {
                Some(p) => items.extend(p.1.split(',').map(str::to_string)),
                None => items.push(item.to_string()),
            }
        }
        if items.is_empty() {
            return Err(err(
                text,
                "empty; give Icepack's names, e.g. `nilyr=7,nslyr=1,tr_lvl,tr_pond_lvl` or \
                 the preset `icedrv`"
                    .into(),
            ));
        }
        for item in &items {
            let (key, value) = match item.split_once('=') {
                Some((k, v)) => (k.trim().to_ascii_lowercase(), Some(v.trim())),
                None => (item.trim().to_ascii_lowercase(), None),
            };
            let switch = |v: Option<&str>| match v {
                None => Ok(true),
                Some(v) => parse_bool(v).ok_or_else(|| {
                    err(
                        item,
                        format!("`{v}` is not true or false (.true., .false.)"),
                    )
                }),
            };
            let number = |v: Option<&str>| {
                let v = v.ok_or_else(|| err(item, format!("give a count: `{key}=N`")))?;
                v.parse::<usize>()
                    .map_err(|_| err(item, format!("`{v}` is not a whole number ≥ 0")))
            };
            if let Some(i) = SWITCHES.iter().position(|s| s.eq_ignore_ascii_case(&key)) {
                sw[i] = switch(value)?;
            } else if let Some(i) = COUNTS.iter().position(|s| *s == key) {
                counts[i] = Some(number(value)?);
            } else if let Some(i) = bgc::SWITCHES
                .iter()
                .position(|s| s.eq_ignore_ascii_case(&key))
            {
                bgc_sw[i] = switch(value)?;
            } else if let Some(i) = bgc::COUNTS.iter().position(|c| c.0 == key) {
                bgc_counts[i] = Some(number(value)?);
            } else {
                return Err(err(
                    item,
                    format!(
                        "unknown; the names are {}, {}, {} (each `=N`) and the preset(s) {}",
                        SWITCHES.join(", "),
                        bgc::SWITCHES.join(", "),
                        COUNTS
                            .iter()
                            .copied()
                            .chain(bgc::COUNTS.iter().map(|c| c.0))
                            .collect::<Vec<_>>()
                            .join(", "),
                        PRESETS.iter().map(|p| p.0).collect::<Vec<_>>().join(", ")
                    ),
                ));
            }
        }
        let [nilyr, nslyr, nfsd, n_iso, n_aero] = counts;
        let layers = |v: Option<usize>, key: &str| match v {
            Some(n) if n >= 1 => Ok(n),
            Some(_) => Err(err(&format!("{key}=0"), "at least one layer".into())),
            None => Err(err(
                key,
                format!("missing: give the number of layers, `{key}=N` (Icepack's {key})"),
            )),
        };
        let nilyr = layers(nilyr, "nilyr")?;
        let nslyr = layers(nslyr, "nslyr")?;
        // A switch on needs its count (≥ 1); a count without its switch is not used, as in
        // Icepack.
        let count = |on: bool, v: Option<usize>, key: &str, sw: &str, max: usize| {
            if !on {
                return Ok(0);
            }
            match v {
                Some(n) if (1..=max).contains(&n) => Ok(n),
                Some(n) => Err(err(
                    &format!("{key}={n}"),
                    format!("with {sw} on, from 1 to {max}"),
                )),
                None => Err(err(
                    sw,
                    format!("needs its count, `{key}=N` (Icepack's {key})"),
                )),
            }
        };
        let flags = CiceTracerFlags {
            age: sw[0],
            first_year: sw[1],
            level_ice: sw[2],
            ponds: sw[3],
            pond_topo: sw[4],
            pond_sealvl: sw[5],
            snow: sw[6],
            fsd: count(sw[7], nfsd, "nfsd", "tr_fsd", usize::MAX)?,
            isotopes: count(sw[8], n_iso, "n_iso", "tr_iso", MAX_ISO)?,
            aerosols: count(sw[9], n_aero, "n_aero", "tr_aero", MAX_AERO)?,
            brine: sw[10],
        };
        let bgc = IcedrvBgc::from_items(&bgc_sw, &bgc_counts, flags.brine)?;
        let spec = CiceLayoutSpec {
            nilyr,
            nslyr,
            flags,
            bgc,
        };
        spec.layout().map_err(|e| err(text, e.to_string()))?;
        Ok(spec)
    }
}

impl fmt::Display for CiceLayoutSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let fl = &self.flags;
        write!(f, "nilyr={},nslyr={}", self.nilyr, self.nslyr)?;
        for (on, name) in [
            (fl.age, "tr_iage"),
            (fl.first_year, "tr_FY"),
            (fl.level_ice, "tr_lvl"),
            (fl.ponds, "tr_pond_lvl"),
            (fl.pond_topo, "tr_pond_topo"),
            (fl.pond_sealvl, "tr_pond_sealvl"),
            (fl.snow, "tr_snow"),
        ] {
            if on {
                write!(f, ",{name}")?;
            }
        }
        for (n, sw, key) in [
            (fl.fsd, "tr_fsd", "nfsd"),
            (fl.isotopes, "tr_iso", "n_iso"),
            (fl.aerosols, "tr_aero", "n_aero"),
        ] {
            if n > 0 {
                write!(f, ",{sw},{key}={n}")?;
            }
        }
        if fl.brine {
            write!(f, ",tr_brine")?;
        }
        match &self.bgc {
            Some(b) => b.write(f),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(s: &str) -> Result<CiceLayoutSpec, LayoutSpecError> {
        s.parse()
    }

    #[test]
    fn the_icedrv_preset_is_icepacks_default_column_driver() {
        let s = parse("icedrv").unwrap();
        let l = s.layout().unwrap();
        // 1 + 7 + 1 + 7 + alvl, vlvl + apnd, hpnd, ipnd (icedrv_init.F90).
        assert_eq!(l.ntrcr(), 21);
        assert_eq!(s.to_string(), "nilyr=7,nslyr=1,tr_lvl,tr_pond_lvl");
        assert_eq!(l.cice_restart_names()[16], "alvl");
    }

    #[test]
    fn names_are_icepacks_case_insensitive_and_round_trip() {
        let s = parse(
            "NILYR=4, nslyr=2, tr_iage, tr_fy=.true., tr_lvl=T, tr_snow, tr_fsd, nfsd=3, \
             tr_iso, n_iso=2, tr_aero, n_aero=1, tr_brine, tr_pond_topo",
        )
        .unwrap();
        assert_eq!((s.nilyr, s.nslyr), (4, 2));
        let f = s.flags;
        assert!(f.age && f.first_year && f.level_ice && f.snow && f.brine && f.pond_topo);
        assert_eq!((f.fsd, f.isotopes, f.aerosols), (3, 2, 1));
        let text = s.to_string();
        assert_eq!(parse(&text).unwrap(), s);
        // 1 + 4 + 2 + 4 + iage, FY, alvl, vlvl + 3 ponds + 4·2 snow + 3 fsd + 2·2 iso
        // + 4 aero + fbri.
        assert_eq!(s.layout().unwrap().ntrcr(), 11 + 4 + 3 + 8 + 3 + 4 + 4 + 1);
        // A later item wins; a count without its switch is unused, as in Icepack.
        let s = parse("icedrv,tr_pond_lvl=.false.,n_aero=2").unwrap();
        assert!(!s.flags.ponds && s.flags.aerosols == 0);
    }

    #[test]
    fn bad_items_are_named() {
        let why = |s: &str| parse(s).unwrap_err();
        assert_eq!(why("nslyr=1").item, "nilyr");
        assert_eq!(why("nilyr=7").item, "nslyr");
        assert_eq!(why("nilyr=0,nslyr=1").item, "nilyr=0");
        assert_eq!(why("icedrv,tr_aero").item, "tr_aero");
        assert_eq!(why("icedrv,tr_iso,n_iso=4").item, "n_iso=4");
        assert_eq!(why("icedrv,tr_lvl=maybe").item, "tr_lvl=maybe");
        assert_eq!(why("icedrv,nilyr=x").item, "nilyr=x");
        assert_eq!(why("icedrv,nilyr").item, "nilyr");
        let e = why("icedrv,tr_ages");
        assert!(
            e.why.contains("unknown") && e.why.contains("tr_iage"),
            "{e}"
        );
        assert!(why("icedrv,tr_bgc_N").why.contains("biogeochemistry"));
        assert!(why("").why.contains("empty"));
        // Two pond schemes, or level-ice ponds without level ice.
        assert!(why("icedrv,tr_pond_topo").why.contains("one pond scheme"));
        assert!(why("nilyr=7,nslyr=1,tr_pond_lvl").why.contains("level"));
    }
}
