//! Rafting instead of ridging: a per-run detector (issue 14).
//!
//! Hopkins (1994) pushes a lead sheet against a thick floe to grow a ridge. A sheet can
//! instead *raft*: slide intact over (or under) the floe instead of breaking against it. One
//! run of our first table did (h = 0.40 m: its sheet lay on the whole 20-m floe, and its
//! W/ΔPE came out a third above its siblings'), so a table mixes two processes unless the
//! rafted runs are found and counted.
//!
//! The diagnostic is [`crate::simulation::Summary::sheet_overrun_max`]: the largest
//! distance, over every step, by which the leading edge of the *intact* sheet passed the
//! floe's nose ([`crate::dem::World::sheet_overrun`]). A sheet that breaks against the floe
//! keeps it within a block or so of zero: the tip block may ride onto the nose before it
//! breaks off. A rafting sheet drives it up by the length it overrides. A run **rafted**
//! when that distance exceeds [`RAFTING_REACH`] in a scene of the paper's size, or that reach
//! scaled with the scene in a scene scaled with the sheet ([`reach_of`]); runs
//! recorded before the diagnostic existed are **unknown**, never counted as ridged.

use crate::record::RunRecord;
use crate::table::ensemble::{Stat, group_by_point};

/// The overrun beyond which a run counts as rafted (m). 2 m is several block widths
/// (0.20–0.30 m in the paper's sets) past the nose: more than a tip block riding up before
/// it breaks, and a tenth of the paper's 20-m floe. The paper gives no criterion; this one
/// is a definition, reported with every count and adjustable (`tabulate --rafting-reach`).
pub const RAFTING_REACH: f64 = 2.0;

/// The floe length the reach is given for (m): the 20-m floe of the paper's sets as first
/// run (`floe.length` is 40 m by default now).
pub const REACH_FLOE_LENGTH: f64 = 20.0;

/// The sheet thickness the reach is given for (m): the paper's Figure 5 sheet.
pub const REACH_THICKNESS: f64 = 0.30;

/// The floe thickness the reach is given for (m): the paper's 2-m floe.
pub const REACH_FLOE_THICKNESS: f64 = 2.0;

/// The reach (m) that classifies run `r`, given the reach `reach` (m) for the paper's scene
/// (a 0.30-m sheet, [`REACH_THICKNESS`], against a 2-m floe, [`REACH_FLOE_THICKNESS`], of
/// [`REACH_FLOE_LENGTH`]): multiplied by the scene's scale, the smallest of sheet thickness /
/// 0.30 m, floe thickness / 2 m and floe length / 20 m, and never below one. A scene scaled
/// with the sheet is larger in all three (`data/campaigns/thickness-scaled.toml`: blocks of
/// 2h/3, a floe 6.67h thick and 133h long), and so gets the same reach in block widths and
/// sheet thicknesses: a thick sheet's tip block riding up the floe's scaled nose bevel is not
/// taken for a raft. A scene larger in one or two only is not a larger scene: a longer floe
/// (the 40-m default) or a thicker sheet against the paper's floe keeps `reach`, as does a
/// scene without a floe.
pub fn reach_of(r: &RunRecord, reach: f64) -> f64 {
    reach_in(&r.scene, reach)
}

/// The reach (m) in `scene` given the reach `reach` (m) for the paper's scene
/// ([`reach_of`], for a scene rather than a run's record). It is counted from the top of
/// the floe's nose ramp: a longer ramp than the paper's scene's (a shallower `floe.nose_slope`)
/// adds its extra run, so that a sheet whose tip climbs the ramp and breaks there is not
/// taken for a raft (a 20° ramp runs 1.37 m where the 45° one runs 0.5 m).
pub fn reach_in(scene: &crate::scene::Scene, reach: f64) -> f64 {
    match (&scene.floe, &scene.sheet) {
        (Some(f), Some(s)) => {
            let scale = (s.thickness / REACH_THICKNESS)
                .min(f.thickness / REACH_FLOE_THICKNESS)
                .min(f.length / REACH_FLOE_LENGTH)
                .max(1.0);
            // The run beyond the drop: none at 45°, where `nose_run` is the drop exactly.
            reach * scale + (f.nose_run() - f.nose_bevel).max(0.0)
        }
        _ => reach,
    }
}

/// The rule of [`reach_in`] in words, for reach `reach` (m) in the paper's scene: the one
/// wording of the report and the command line.
pub fn reach_rule(reach: f64) -> String {
    format!(
        "{reach} m in a scene of the paper's size, and that times the scene's scale in a scene \
         larger in all of sheet thickness, floe thickness and floe length (the smallest of \
         h/0.30 m, floe thickness/2 m and floe length/20 m), plus the run a nose ramp \
         shallower than 45° has beyond its drop"
    )
}

/// In words, what a run whose intact sheet passed the floe's nose by at most `overrun` (m)
/// did against rafting reach `reach` (m): it rode over the floe, or it broke at it.
pub fn verdict(overrun: f64, reach: f64) -> String {
    // The reach to the centimetre, without trailing zeros ("2 m", "2.87 m").
    let text = format!("{reach:.2}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    let what = if overrun > reach {
        format!("it rode over the floe (more than the {text} m rafting reach)")
    } else {
        format!("it broke at the floe (within the {text} m rafting reach)")
    };
    format!("the intact sheet passed the floe's nose by at most {overrun:.2} m: {what}")
}

/// What a run did at the floe.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Outcome {
    /// The intact sheet never passed the nose by more than the reach.
    Ridged,
    /// It did, by this much (m).
    Rafted(f64),
    /// The record predates the diagnostic, or the scene has no sheet or no floe.
    Unknown,
}

/// Classifies one run with rafting reach `reach` (m, for a 20-m floe; [`reach_of`]).
pub fn outcome(r: &RunRecord, reach: f64) -> Outcome {
    match r.summary.sheet_overrun_max {
        Some(x) if x > reach_of(r, reach) => Outcome::Rafted(x),
        Some(_) => Outcome::Ridged,
        None => Outcome::Unknown,
    }
}

/// Rafting at one grid point of a campaign.
#[derive(Clone, Debug, PartialEq)]
pub struct PointRafting {
    /// The grid point's label ([`group_by_point`]).
    pub label: String,
    /// The rafting reach of its runs (m; [`reach_of`]: the reach given for a 20-m floe, in
    /// proportion to the floe's length), the largest if they differ.
    pub reach: f64,
    /// Runs with a known outcome.
    pub known: usize,
    /// Rafted runs: (run id, overrun (m), final W/ΔPE).
    pub rafted: Vec<(String, f64, f64)>,
    /// Largest overrun of the runs that ridged, over the runs (m).
    pub ridged_overrun: Stat,
    /// Final W/ΔPE of the runs that ridged (dimensionless).
    pub ridged_ratio: Stat,
}

/// Rafting per grid point of `records` with reach `reach` (m, for a 20-m floe;
/// [`reach_of`]).
pub fn by_point(records: &[RunRecord], reach: f64) -> Vec<PointRafting> {
    group_by_point(records)
        .into_iter()
        .map(|(label, rs)| {
            let mut p = PointRafting {
                label,
                reach: rs.iter().map(|r| reach_of(r, reach)).fold(0.0, f64::max),
                known: 0,
                rafted: Vec::new(),
                ridged_overrun: Stat::of(&[]),
                ridged_ratio: Stat::of(&[]),
            };
            let (mut over, mut ratio) = (Vec::new(), Vec::new());
            for r in rs {
                match outcome(r, reach) {
                    Outcome::Rafted(x) => {
                        p.known += 1;
                        p.rafted.push((r.id.clone(), x, r.summary.ratio_work_to_pe));
                    }
                    Outcome::Ridged => {
                        p.known += 1;
                        over.extend(r.summary.sheet_overrun_max);
                        ratio.push(r.summary.ratio_work_to_pe);
                    }
                    Outcome::Unknown => {}
                }
            }
            p.ridged_overrun = Stat::of(&over);
            p.ridged_ratio = Stat::of(&ratio);
            p
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A record of the default scene with the floe `floe_length` m long (none if `None`),
    /// the sheet `thickness` m thick and the floe 6.67 times that (at least 2 m), that overran
    /// the floe by `overrun` m.
    fn record(floe_length: Option<f64>, thickness: f64, overrun: f64) -> RunRecord {
        let floe_thickness = (thickness * 20.0 / 3.0).max(2.0);
        let mut json = crate::table::summary_without_ledger();
        for t in crate::energy::LEDGER_TERMS {
            json[t.name] = 0.0.into();
        }
        json["sheet_overrun_max"] = overrun.into();
        let mut scene = crate::scene::Scene::default();
        scene.sheet.as_mut().expect("a sheet").thickness = thickness;
        scene.floe.as_mut().expect("a floe").nose_slope = 1.0;
        match floe_length {
            Some(l) => {
                let f = scene.floe.as_mut().expect("a floe");
                (f.length, f.thickness) = (l, floe_thickness);
            }
            None => scene.floe = None,
        }
        RunRecord {
            id: "x".into(),
            settings: vec![],
            seed: 1,
            scene,
            summary: serde_json::from_value(json).unwrap(),
            samples: vec![],
            profile: Default::default(),
            metrics: Default::default(),
            digest: None,
        }
    }

    /// The run summary's words follow the reach.
    #[test]
    fn the_verdict_names_a_ride_over() {
        let v = verdict(20.46, 2.0);
        assert!(
            v.ends_with("it rode over the floe (more than the 2 m rafting reach)"),
            "{v}"
        );
        assert!(v.contains("by at most 20.46 m"), "{v}");
        assert!(verdict(2.0, 2.0).ends_with("it broke at the floe (within the 2 m rafting reach)"));
        assert!(verdict(1.33, 2.873739593922576).ends_with("(within the 2.87 m rafting reach)"));
    }

    /// The reach is the given one in a scene of the paper's size (a 0.30-m sheet on a 20-m
    /// or longer floe, and without a floe), and scaled with a scene scaled with the sheet.
    #[test]
    fn the_reach_scales_with_the_scene() {
        let r = RAFTING_REACH;
        assert_eq!(reach_of(&record(Some(20.0), 0.30, 0.0), r), 2.0);
        assert_eq!(reach_of(&record(None, 0.30, 0.0), r), 2.0);
        // A longer floe alone is not a larger scene (the 40-m default, an 80-m probe) ...
        assert_eq!(reach_of(&record(Some(40.0), 0.30, 0.0), r), 2.0);
        assert_eq!(reach_of(&record(Some(80.0), 0.30, 0.0), 3.0), 3.0);
        // ... nor a thicker sheet on the paper's floe length, nor a thinner one on any floe.
        assert_eq!(reach_of(&record(Some(20.0), 0.45, 0.0), r), 2.0);
        assert_eq!(reach_of(&record(Some(40.0), 0.10, 0.0), r), 2.0);
        // The scaled scenes: a 3 m sheet against a 20 m thick floe 400 m (133h) or 200 m
        // (66.7h, the former ratio) long; a 4 m sheet against a floe 133.3 m long.
        assert_eq!(reach_of(&record(Some(400.0), 3.0, 0.0), r), 20.0);
        assert_eq!(reach_of(&record(Some(200.0), 3.0, 0.0), r), 20.0);
        let q = reach_of(&record(Some(133.3), 4.0, 0.0), r);
        assert!((q - 13.33).abs() < 1e-9, "{q}");
        // A 0.45 m sheet against the 2 m floe, 40 m long: the paper's scene, the same reach.
        let mut thick = record(Some(40.0), 0.45, 0.0);
        thick.scene.floe.as_mut().unwrap().thickness = 2.0;
        assert_eq!(reach_of(&thick, r), 2.0);
        // A 3.8 m overrun (a 3 m sheet's 2-m tip block riding up the 5-m nose bevel of its
        // 200-m floe) is no raft there, but would be at the paper's size.
        assert_eq!(outcome(&record(Some(200.0), 3.0, 3.8), r), Outcome::Ridged);
        assert_eq!(
            outcome(&record(Some(40.0), 0.30, 3.8), r),
            Outcome::Rafted(3.8)
        );
    }

    /// A nose ramp shallower than 45° adds its extra run to the reach: at 20° the 0.5-m drop
    /// runs 1.37 m, 0.87 m more than at 45°, so the reach is 2.87 m; a tip that stopped
    /// 2.6 m past the ramp's foot broke at the floe, one 3.0 m past it rode over.
    #[test]
    fn a_longer_nose_ramp_lengthens_the_reach() {
        let at = |overrun: f64| {
            let mut r = record(Some(40.0), 0.30, overrun);
            r.scene.floe.as_mut().unwrap().nose_slope = 0.36397;
            r
        };
        let reach = reach_of(&at(0.0), RAFTING_REACH);
        assert!(
            (reach - (2.0 + 0.5 / 0.36397 - 0.5)).abs() < 1e-12,
            "{reach}"
        );
        assert_eq!(outcome(&at(2.6), RAFTING_REACH), Outcome::Ridged);
        assert_eq!(outcome(&at(3.0), RAFTING_REACH), Outcome::Rafted(3.0));
    }
}
