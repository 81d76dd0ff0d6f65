//! The biogeochemical tracers of a layout named in Icepack's words (`zbgc_nml` and the
//! driver's sizes `NBGCLYR`, `TRALG`, `TRDOC`, `TRDIC`, `TRDON`, `TRFED`, `TRFEP`, `TRZAERO`),
//! laid out and carried as Icepack's column driver sets them up: `init_zbgc` and
//! `init_bgc_trcr` (`icedrv_init_column.F90`) append them after every other tracer, group by
//! group in a fixed order, and `init_state` (`icedrv_init.F90`) then resets the base of every
//! tracer whose `trcr_depend` is neither 0, 1 nor 2 to the ice area, with no strata.
//!
//! Written here rather than read from the host: a history file holds the tracers but not the
//! tables that say how each is carried, and the driver's tables follow from its switches.

use super::LayoutSpecError;
use crate::ItdError;
use crate::tracers::{BgcKind, BgcTracers, TracerLayout};

/// Icepack's skeletal layer thickness `sk_l` (m), which the column driver does not change.
const SK_L: f64 = 0.03;

/// The switches, by Icepack name, in the order of [`IcedrvBgc::switches`].
pub(super) const SWITCHES: &[&str] = &[
    "z_tracers",
    "skl_bgc",
    "tr_bgc_N",
    "tr_bgc_Nit",
    "tr_bgc_C",
    "tr_bgc_chl",
    "tr_bgc_Am",
    "tr_bgc_Sil",
    "tr_bgc_DMS",
    "tr_bgc_PON",
    "tr_bgc_DON",
    "tr_bgc_Fe",
    "tr_bgc_hum",
    "tr_zaero",
];

/// The counts, by Icepack name, with their largest value (`icepack_max_algae`, ...).
pub(super) const COUNTS: &[(&str, usize)] = &[
    ("nblyr", usize::MAX),
    ("n_algae", 3),
    ("n_doc", 3),
    ("n_dic", 1),
    ("n_don", 1),
    ("n_fed", 2),
    ("n_fep", 2),
    ("n_zaero", 6),
];

/// Per switch (after `z_tracers`, `skl_bgc`), the counts it uses, as indices into `COUNTS`
/// less `nblyr`: `tr_bgc_N` and `tr_bgc_chl` one tracer per alga, `tr_bgc_C` DOC and DIC,
/// `tr_bgc_Fe` dissolved and particulate iron; a switch with none is one bio tracer, or
/// three for `tr_bgc_DMS` (DMSPp, DMSPd, DMS).
const COUNTS_OF: [&[usize]; 12] = [
    &[0],
    &[],
    &[1, 2],
    &[0],
    &[],
    &[],
    &[],
    &[],
    &[3],
    &[4, 5],
    &[],
    &[6],
];

/// `tr_bgc_DMS` among the switches after `z_tracers`, `skl_bgc`.
const DMS: usize = 6;

/// Biogeochemical tracers as Icepack's column driver carries them: vertically resolved
/// (`z_tracers`: `nblyr + 1` levels on the brine grid and two in the snow per bio tracer, then
/// one mobile fraction `zbgc_frac` per bio tracer) or skeletal (`skl_bgc`: one value per bio
/// tracer). The bio tracers come in the driver's order: algal nitrogen (`n_algae`), nitrate,
/// DOC (`n_doc`) and DIC (`n_dic`) with `tr_bgc_C`, chlorophyll (`n_algae`), ammonium,
/// silicate, DMSPp, DMSPd and DMS with `tr_bgc_DMS`, PON, DON (`n_don`), dissolved and
/// particulate iron (`n_fed`, `n_fep`) with `tr_bgc_Fe`, humics, and z-aerosols (`n_zaero`,
/// `z_tracers` only). Give the switches as the driver ends up with them (its diagnostics
/// print them): `skl_bgc` and `solve_zbgc` turn on `tr_bgc_N` and `tr_bgc_Nit` there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IcedrvBgc {
    /// Bio grid layers in the ice (Icepack's `nblyr`) with `z_tracers`; `None`: `skl_bgc`.
    pub nblyr: Option<usize>,
    /// The switches, in the order `tr_bgc_N`, `tr_bgc_Nit`, `tr_bgc_C`, `tr_bgc_chl`,
    /// `tr_bgc_Am`, `tr_bgc_Sil`, `tr_bgc_DMS`, `tr_bgc_PON`, `tr_bgc_DON`, `tr_bgc_Fe`,
    /// `tr_bgc_hum`, `tr_zaero`.
    pub switches: [bool; 12],
    /// The counts `n_algae`, `n_doc`, `n_dic`, `n_don`, `n_fed`, `n_fep`, `n_zaero` (0 where
    /// no switch on uses it).
    pub counts: [usize; 7],
}

impl IcedrvBgc {
    /// Number of bio tracers (Icepack's `nbtrcr`).
    pub fn nbtrcr(&self) -> usize {
        (0..self.switches.len())
            .filter(|&s| self.switches[s])
            .map(|s| match COUNTS_OF[s] {
                [] if s == DMS => 3,
                [] => 1,
                cs => cs.iter().map(|&c| self.counts[c]).sum(),
            })
            .sum()
    }

    /// Tracers per bio tracer: `nblyr + 3` (vertical) or 1 (skeletal).
    fn levels(&self) -> usize {
        self.nblyr.map_or(1, |n| n + 3)
    }

    /// Tracers appended after the others: the bio tracers' and, vertically resolved, one
    /// `zbgc_frac` per bio tracer.
    pub fn extra(&self) -> usize {
        let nb = self.nbtrcr();
        nb * self.levels() + if self.nblyr.is_some() { nb } else { 0 }
    }

    /// `base` (the physical tracers, with `fbri` if vertical) with these tracers appended and
    /// every tracer carried by the driver's tables.
    pub(super) fn apply(&self, base: TracerLayout) -> Result<TracerLayout, ItdError> {
        let start = base.ntrcr();
        let levels = self.levels();
        let nb = self.nbtrcr();
        let kind = match self.nblyr {
            Some(nblyr) => BgcKind::Vertical { nblyr },
            None => BgcKind::Skeletal { sk_l: SK_L },
        };
        let bio_index = (0..nb).map(|i| start + i * levels).collect();
        let mut depend = base.trcr_depend();
        let codes = base.base_codes();
        let strata = base.strata_one_based();
        let nk = self.nblyr.map_or(1, |n| n + 1);
        let l = base.with_bgc(self.extra(), BgcTracers { kind, bio_index })?;
        let nt = l.ntrcr();
        // 0 area, 1 ice volume, 2 snow volume after `init_state`'s reset: every tracer with
        // a `trcr_depend` above 2 is on the area, with no strata.
        let mut code: Vec<i32> = codes;
        let mut strata = strata;
        let on_brine = match self.nblyr {
            Some(_) => {
                let (fbri, _) = l.field("fbri").expect("with_bgc checked fbri");
                2 + fbri as i32 + 1
            }
            None => 0,
        };
        for _ in 0..nb {
            for k in 0..levels {
                let snow = k >= nk;
                depend.push(if snow { 2 } else { on_brine });
                code.push(if snow { 2 } else { 0 });
                strata.push([0, 0]);
            }
        }
        if self.nblyr.is_some() {
            for _ in 0..nb {
                depend.push(on_brine);
                code.push(0);
                strata.push([0, 0]);
            }
        }
        debug_assert_eq!(depend.len(), nt);
        let mut trcr_base = vec![0.0; 3 * nt];
        for (it, &c) in code.iter().enumerate() {
            trcr_base[c as usize * nt + it] = 1.0;
        }
        let n_strata: Vec<i32> = strata
            .iter()
            .map(|s| s.iter().filter(|&&x| x > 0).count() as i32)
            .collect();
        let mut nt_strata = vec![0; 2 * nt];
        for (it, s) in strata.iter().enumerate() {
            nt_strata[it] = s[0];
            nt_strata[nt + it] = s[1];
        }
        let mut l = l.with_host_tables(&depend, &trcr_base, &n_strata, &nt_strata)?;
        l.icedrv_bgc = Some(*self);
        Ok(l)
    }

    /// The validated tracers from the switches and counts as given (`None`: not given), or
    /// `Ok(None)` when no biogeochemical switch is on. `brine`: the layout has `tr_brine`.
    pub(super) fn from_items(
        sw: &[bool; 14],
        counts: &[Option<usize>; 8],
        brine: bool,
    ) -> Result<Option<Self>, LayoutSpecError> {
        let err = |item: &str, why: String| LayoutSpecError {
            item: item.to_string(),
            why,
        };
        let (z, skl) = (sw[0], sw[1]);
        let mut switches = [false; 12];
        switches.copy_from_slice(&sw[2..]);
        let any = switches.iter().position(|&s| s);
        if !z && !skl {
            return match any {
                Some(i) => Err(err(
                    SWITCHES[i + 2],
                    "needs the kind of biogeochemistry: z_tracers (vertical) or skl_bgc \
                     (skeletal)"
                        .into(),
                )),
                None => Ok(None),
            };
        }
        if z && skl {
            return Err(err(
                "skl_bgc",
                "one of z_tracers and skl_bgc, as in Icepack".into(),
            ));
        }
        let kind = if z { "z_tracers" } else { "skl_bgc" };
        if any.is_none() {
            return Err(err(
                kind,
                "no bio tracer is on: give the driver's switches (tr_bgc_N, tr_bgc_Nit, ..., \
                 tr_zaero)"
                    .into(),
            ));
        }
        if skl && switches[11] {
            return Err(err(
                "tr_zaero",
                "z-aerosols are vertically resolved: they need z_tracers, not skl_bgc".into(),
            ));
        }
        if z && !brine {
            return Err(err(
                "z_tracers",
                "the vertical bio grid is carried on the brine fraction: turn on tr_brine".into(),
            ));
        }
        let nblyr = if z {
            match counts[0] {
                Some(n) if n >= 1 => Some(n),
                Some(_) => return Err(err("nblyr=0", "at least one bio layer".into())),
                None => {
                    return Err(err(
                        "z_tracers",
                        "needs its bio layers, `nblyr=N` (Icepack's nblyr, NBGCLYR)".into(),
                    ));
                }
            }
        } else {
            None
        };
        let mut used = [0usize; 7];
        for (s, cs) in COUNTS_OF.iter().enumerate() {
            if !switches[s] {
                continue;
            }
            for &c in *cs {
                let (key, max) = COUNTS[c + 1];
                used[c] = match counts[c + 1] {
                    Some(n) if n <= max => n,
                    Some(n) => return Err(err(&format!("{key}={n}"), format!("from 0 to {max}"))),
                    None => {
                        return Err(err(
                            SWITCHES[s + 2],
                            format!("needs its count, `{key}=N` (Icepack's {key})"),
                        ));
                    }
                };
            }
        }
        let bgc = IcedrvBgc {
            nblyr,
            switches,
            counts: used,
        };
        let nb = bgc.nbtrcr();
        if nb == 0 || nb > crate::tracers::MAX_NBTRCR {
            return Err(err(
                kind,
                format!(
                    "{nb} bio tracers from the switches and counts given: Icepack carries 1 to \
                     {}",
                    crate::tracers::MAX_NBTRCR
                ),
            ));
        }
        Ok(Some(bgc))
    }

    /// The canonical text (after the physical part), which parses back to the same value.
    pub(super) fn write(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.nblyr {
            Some(n) => write!(f, ",z_tracers,nblyr={n}")?,
            None => write!(f, ",skl_bgc")?,
        }
        // Each count once, after the first switch that uses it (`n_algae` serves both
        // `tr_bgc_N` and `tr_bgc_chl`).
        let mut written = [false; COUNTS.len() - 1];
        for (s, on) in self.switches.iter().enumerate() {
            if *on {
                write!(f, ",{}", SWITCHES[s + 2])?;
                for &c in COUNTS_OF[s] {
                    if !std::mem::replace(&mut written[c], true) {
                        write!(f, ",{}={}", COUNTS[c + 1].0, self.counts[c])?;
                    }
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::details::CiceLayoutSpec;

    /// The layout of `text` and its tables: `trcr_depend`, base codes, strata (1-based).
    struct Tables {
        nt: usize,
        depend: Vec<i32>,
        base: Vec<i32>,
        strata: Vec<[i32; 2]>,
        bio: Vec<usize>,
    }

    fn tables(text: &str) -> Tables {
        let l = text.parse::<CiceLayoutSpec>().unwrap().layout().unwrap();
        Tables {
            nt: l.ntrcr(),
            depend: l.trcr_depend(),
            base: l.base_codes(),
            strata: l.strata_one_based(),
            bio: l.bgc().unwrap().bio_index.clone(),
        }
    }

    /// The tables of `init_zbgc` and `init_bgc_trcr` (`icedrv_init_column.F90`) after
    /// `init_state`'s reset (`icedrv_init.F90`), written out by hand for a small layout.
    #[test]
    fn vertical_tracers_are_laid_out_and_carried_as_the_column_driver_does() {
        // Tsfc, qice ×2, qsno, sice ×2, fbri: 7 tracers, fbri the 7th (1-based).
        let Tables {
            nt,
            depend,
            base,
            strata,
            bio,
        } = tables(
            "nilyr=2,nslyr=1,tr_brine,z_tracers,nblyr=2,tr_bgc_N,n_algae=1,tr_zaero,n_zaero=1",
        );
        // Two bio tracers (algal N, then the aerosol) of nblyr + 1 = 3 ice levels and 2 snow
        // levels each, then one zbgc_frac per bio tracer.
        assert_eq!(nt, 7 + 2 * 5 + 2);
        assert_eq!(bio, [7, 12]);
        let on_fbri = 2 + 7;
        let per_bio = [on_fbri, on_fbri, on_fbri, 2, 2];
        let want: Vec<i32> = [0, 1, 1, 2, 1, 1, 1]
            .into_iter()
            .chain(per_bio)
            .chain(per_bio)
            .chain([on_fbri, on_fbri])
            .collect();
        assert_eq!(depend, want);
        // Reset to the area where trcr_depend is above 2; snow levels on snow volume.
        let want: Vec<i32> = [0, 1, 1, 2, 1, 1, 1]
            .into_iter()
            .chain([0, 0, 0, 2, 2])
            .chain([0, 0, 0, 2, 2])
            .chain([0, 0])
            .collect();
        assert_eq!(base, want);
        assert!(strata.iter().all(|s| *s == [0, 0]), "{strata:?}");
    }

    #[test]
    fn skeletal_tracers_are_one_area_tracer_each_in_the_drivers_order() {
        // N ×3, Nit, DOC ×2, DIC, chl ×3, Am, Sil, DMSPp, DMSPd, DMS, PON, DON, Fed, Fep, hum:
        // the bgcsklnice case's sizes (TRALG 3, TRDOC 2, TRDIC 1, TRDON 1, TRFED 1, TRFEP 1).
        let text = "icedrv,tr_brine,skl_bgc,tr_bgc_N,n_algae=3,tr_bgc_Nit,tr_bgc_C,n_doc=2,\
                    n_dic=1,tr_bgc_chl,tr_bgc_Am,tr_bgc_Sil,tr_bgc_DMS,tr_bgc_PON,tr_bgc_DON,\
                    n_don=1,tr_bgc_Fe,n_fed=1,n_fep=1,tr_bgc_hum";
        let Tables {
            nt,
            depend,
            base,
            bio,
            ..
        } = tables(text);
        let nb = 3 + 1 + 3 + 3 + 2 + 3 + 1 + 1 + 2 + 1;
        assert_eq!(nt, 22 + nb);
        assert_eq!(bio, (22..22 + nb).collect::<Vec<_>>());
        assert!(depend[22..].iter().all(|&d| d == 0));
        assert!(base[22..].iter().all(|&b| b == 0));
        // The canonical text names each count once and parses back to the same spec.
        let s: CiceLayoutSpec = text.parse().unwrap();
        let canon = s.to_string();
        assert_eq!(canon.matches("n_algae=").count(), 1, "{canon}");
        assert_eq!(canon.parse::<CiceLayoutSpec>().unwrap(), s);
    }

    /// Icepack's `zaero` test case (`set_env.zaero`, `set_nml.zaero` over the driver's
    /// defaults): 55 tracers, as its history holds them.
    #[test]
    fn the_zaero_case_has_the_drivers_55_tracers_and_round_trips() {
        let s: CiceLayoutSpec = "icedrv,tr_brine,z_tracers,nblyr=7,tr_zaero,n_zaero=3"
            .parse()
            .unwrap();
        let l = s.layout().unwrap();
        assert_eq!((l.ntrcr(), l.n_bio()), (55, 3));
        let text = s.to_string();
        assert_eq!(
            text,
            "nilyr=7,nslyr=1,tr_lvl,tr_pond_lvl,tr_brine,z_tracers,nblyr=7,tr_zaero,n_zaero=3"
        );
        assert_eq!(text.parse::<CiceLayoutSpec>().unwrap(), s);
        assert_eq!(l.cice_spec(), Some(s), "the layout names its spec");
        // A count without its switch is unused, as in Icepack.
        let t: CiceLayoutSpec = format!("{text},n_algae=2,tr_bgc_Fe=.false.")
            .parse()
            .unwrap();
        assert_eq!(t, s);
    }

    #[test]
    fn bad_biogeochemistry_is_named() {
        let why = |s: &str| s.parse::<CiceLayoutSpec>().unwrap_err();
        let e = why("icedrv,tr_bgc_N,n_algae=1");
        assert_eq!(e.item, "tr_bgc_N");
        assert!(e.why.contains("z_tracers"), "{e}");
        assert_eq!(
            why("icedrv,tr_brine,z_tracers,skl_bgc,tr_bgc_Nit").item,
            "skl_bgc"
        );
        assert!(
            why("icedrv,z_tracers,nblyr=2,tr_bgc_Nit")
                .why
                .contains("tr_brine")
        );
        assert!(
            why("icedrv,tr_brine,z_tracers,tr_bgc_Nit")
                .why
                .contains("nblyr=N")
        );
        assert_eq!(
            why("icedrv,tr_brine,z_tracers,nblyr=0,tr_bgc_Nit").item,
            "nblyr=0"
        );
        assert!(
            why("icedrv,tr_brine,z_tracers,nblyr=2")
                .why
                .contains("no bio tracer")
        );
        assert!(
            why("icedrv,skl_bgc,tr_zaero,n_zaero=1")
                .why
                .contains("z_tracers")
        );
        let e = why("icedrv,skl_bgc,tr_bgc_N");
        assert!(e.item == "tr_bgc_N" && e.why.contains("n_algae"), "{e}");
        assert_eq!(why("icedrv,skl_bgc,tr_bgc_N,n_algae=4").item, "n_algae=4");
        // Switches that turn on no tracer (counts of 0).
        assert!(
            why("icedrv,skl_bgc,tr_bgc_N,n_algae=0")
                .why
                .contains("0 bio tracers")
        );
    }
}
