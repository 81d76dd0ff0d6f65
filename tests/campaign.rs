//! Campaign specs and records through the library: bad specs named, the shipped specs plan
//! their sets, a campaign runs seed by seed, and the committed records and the shipped table
//! hold every run at its final volume. (The campaigns run by the command line are
//! crates/cli/tests/campaign.rs.)

use pressridge::campaign::{CampaignSpec, read_campaign, read_records};

mod common;
use common::TINY_CAMPAIGN as SPEC;

#[test]
fn bad_specs_are_named() {
    let e = CampaignSpec::from_toml("name = \"x\"\nseedz = 3")
        .unwrap_err()
        .to_string();
    assert!(e.contains("seedz"), "{e}");
    let spec = CampaignSpec::from_toml(
        "name = \"x\"\n[[axis]]\nkeys = [\"sheet.thickness\", \"sheet.block_width\"]\nvalues = [0.3]",
    )
    .unwrap();
    let e = spec
        .plan(std::path::Path::new("."))
        .unwrap_err()
        .to_string();
    assert!(e.contains("axis 0"), "{e}");
    let spec =
        CampaignSpec::from_toml("name = \"x\"\n[[axis]]\nkey = \"sheet.thicknes\"\nvalues = [0.3]")
            .unwrap();
    let e = spec
        .plan(std::path::Path::new("."))
        .unwrap_err()
        .to_string();
    assert!(e.contains("thicknes"), "{e}");
}

/// Every shipped campaign spec parses and plans the paper's sets.
#[test]
fn shipped_specs_plan_the_papers_sets() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/campaigns");
    let count = |f: &str| {
        let spec = CampaignSpec::read(&dir.join(f)).unwrap();
        let plan = spec.plan(&dir).unwrap();
        assert!(
            plan.iter()
                .all(|p| p.scene.sheet.is_some() && p.scene.floe.is_some())
        );
        plan.len()
    };
    assert_eq!(count("thickness.toml"), 6 * 7);
    assert_eq!(count("default-table.toml"), 6 * 3);
    // Speed, modulus and floe list every point of the paper's set but the Figure 5 scene
    // itself, which is the thickness set's 0.30 m point (checked below); friction lists all
    // eight pairs, twelve seeds each (issue 30).
    assert_eq!(count("friction.toml"), 8 * 12);
    assert_eq!(count("speed.toml"), 7);
    assert_eq!(count("modulus.toml"), 2 * 7);
    assert_eq!(count("floe.toml"), 7);
    assert_eq!(count("floe-3seeds.toml"), 2 * 3);
    assert_eq!(count("thickness-thick.toml"), 3 * 7);
    assert_eq!(count("thickness-thin.toml"), 2 * 7);
    assert_eq!(count("sheet-length.toml"), 7);
    assert_eq!(count("thickness-thick-floe.toml"), 3 * 7);
    assert_eq!(count("friction-thickness.toml"), 7 * 2 * 7);
    assert_eq!(count("thickness-scaled.toml"), 8 * 7);
    assert_eq!(count("thickness-scaled-floe.toml"), 2 * 7);
    // thickness-scaled: the Figure 5 scene with its lengths in their ratio to the 0.30 m
    // sheet (rounded to 0.01 m), the block width 2h/3, the paper's 100 m of sheet pushed,
    // everything else as the thickness set's scene; the floe no thicker than a scene allows.
    let fig5 =
        pressridge::scene::Scene::load(Some(&dir.join("../scenes/figure5.toml")), &[] as &[&str])
            .unwrap();
    let spec = CampaignSpec::read(&dir.join("thickness-scaled.toml")).unwrap();
    for p in spec.plan(&dir).unwrap() {
        let (sh, f) = (
            p.scene.sheet.as_ref().unwrap(),
            p.scene.floe.as_ref().unwrap(),
        );
        let (sh0, f0) = (fig5.sheet.as_ref().unwrap(), fig5.floe.as_ref().unwrap());
        let r = sh.thickness / sh0.thickness;
        for (what, got, want) in [
            ("block width", sh.block_width, 2.0 * sh.thickness / 3.0),
            ("sheet length", sh.length, r * sh0.length),
            ("floe thickness", f.thickness, r * f0.thickness),
            ("floe length", f.length, r * f0.length),
            ("floe block width", f.block_width, r * f0.block_width),
            ("floe nose bevel", f.nose_bevel, r * f0.nose_bevel),
        ] {
            assert!(
                (got - want).abs() <= 0.005 + 1e-9,
                "{}: {what} {got} against {want}",
                p.id
            );
        }
        assert!(f.thickness <= pressridge::limits::THICKNESS.max);
        assert!((sh.speed * p.scene.duration - 100.0).abs() < 1e-9);
        let mut same = p.scene.clone();
        let (s, fl) = (same.sheet.as_mut().unwrap(), same.floe.as_mut().unwrap());
        (s.thickness, s.block_width, s.length) = (sh0.thickness, sh0.block_width, sh0.length);
        (fl.thickness, fl.length, fl.block_width, fl.nose_bevel) =
            (f0.thickness, f0.length, f0.block_width, f0.nose_bevel);
        (same.seed, same.name) = (fig5.seed, fig5.name.clone());
        same.numerics.sample_interval = fig5.numerics.sample_interval;
        same.output.snapshot_interval = fig5.output.snapshot_interval;
        assert_eq!(same, fig5, "{}: only the scaled lengths differ", p.id);
    }
    // thickness-scaled-floe: the same runs against a floe of half the ratio, nothing else.
    let scaled = CampaignSpec::read(&dir.join("thickness-scaled.toml"))
        .unwrap()
        .plan(&dir)
        .unwrap();
    for p in CampaignSpec::read(&dir.join("thickness-scaled-floe.toml"))
        .unwrap()
        .plan(&dir)
        .unwrap()
    {
        let h = p.scene.sheet.as_ref().unwrap().thickness;
        let mut q = scaled
            .iter()
            .find(|q| q.seed == p.seed && q.scene.sheet.as_ref().unwrap().thickness == h)
            .unwrap_or_else(|| panic!("{}: no thickness-scaled twin", p.id))
            .scene
            .clone();
        let f = q.floe.as_mut().unwrap();
        assert!((p.scene.floe.as_ref().unwrap().thickness - f.thickness / 2.0).abs() < 0.01);
        f.thickness = p.scene.floe.as_ref().unwrap().thickness;
        q.name.clone_from(&p.scene.name);
        assert_eq!(q, p.scene, "{}", p.id);
    }
    let plan = |f: &str| {
        CampaignSpec::read(&dir.join(f))
            .unwrap()
            .plan(&dir)
            .unwrap()
    };
    // The point those four sets leave out: the thickness set's 0.30 m runs are the Figure 5
    // scene (seeds 1-7) on which the four vary one thing each.
    let thickness = plan("thickness.toml");
    let figure5 = CampaignSpec::from_toml(
        "name = \"figure5\"\nseeds = 7\nsample_interval = 25.0\nscene = \"../scenes/figure5.toml\"\n",
    )
    .unwrap()
    .plan(&dir)
    .unwrap();
    for p in &figure5 {
        assert!(
            thickness
                .iter()
                .any(|q| q.seed == p.seed && q.scene == p.scene),
            "the Figure 5 scene, seed {}, is not a run of thickness.toml",
            p.seed
        );
    }
    // The three-seed copies run exactly the first seeds of the paper's sets.
    for (short, full) in [
        ("default-table.toml", vec!["thickness.toml"]),
        ("floe-3seeds.toml", vec!["floe.toml", "thickness.toml"]),
    ] {
        let all: Vec<_> = full.iter().flat_map(|f| plan(f)).collect();
        for p in plan(short) {
            assert!(
                all.iter().any(|q| q.seed == p.seed && q.scene == p.scene),
                "{short}: {}",
                p.id
            );
        }
    }
    // scripts/paper-campaign.sh runs every set of the paper and of the table's extension
    // and checks, and each set it names has a spec.
    let script = std::fs::read_to_string(dir.join("../../scripts/paper-campaign.sh")).unwrap();
    let line = script
        .lines()
        .find(|l| l.starts_with("sets=${PAPER_SETS:-"))
        .expect("the default set list");
    let named: Vec<&str> = line
        .trim_start_matches("sets=${PAPER_SETS:-")
        .trim_end_matches('}')
        .split_whitespace()
        .collect();
    for set in &named {
        assert!(dir.join(format!("{set}.toml")).is_file(), "{set}: no spec");
    }
    // Every spec in data/campaigns/ is run, but for the superseded three-seed sets and the
    // tool-trying one: a new set cannot be left out of the script.
    let not_paper = ["default-table", "floe-3seeds", "tiny"];
    let mut specs = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("toml") {
            continue;
        }
        let set = path.file_stem().unwrap().to_str().unwrap().to_owned();
        specs += 1;
        if !not_paper.contains(&set.as_str()) {
            assert!(
                named.contains(&set.as_str()),
                "paper-campaign.sh does not run {set}"
            );
        }
    }
    assert_eq!(named.len(), specs - not_paper.len(), "{named:?}");
    // 100 m of sheet in every run of the speed set.
    let spec = CampaignSpec::read(&dir.join("speed.toml")).unwrap();
    for p in spec.plan(&dir).unwrap() {
        let u = p.scene.sheet.as_ref().unwrap().speed;
        assert!((u * p.scene.duration - 100.0).abs() < 1e-9);
    }
}

/// The register's probe specs (`data/campaigns/choices*/`) all plan: on the decided model
/// (`choices40`) eight seeds at the two friction pairs each (the baseline twelve), on the
/// 40-m floe; the first look (`choices`) pins the 20-m floe it ran on (but its floe-length
/// probes).
#[test]
fn shipped_choice_probes_plan() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/campaigns");
    for (dir, floe) in [
        ("choices40", 40.0),
        ("choices", 20.0),
        ("choices-r2", 40.0),
        ("choices-r2-e1", 40.0),
    ] {
        let dir = root.join(dir);
        let mut n = 0;
        for e in std::fs::read_dir(&dir).unwrap() {
            let path = e.unwrap().path();
            if path.extension().is_none_or(|x| x != "toml") {
                continue;
            }
            let spec = CampaignSpec::read(&path).unwrap();
            let plan = spec.plan(&dir).unwrap();
            let name = path.file_stem().unwrap().to_string_lossy().into_owned();
            // The first look's floe-length probes move the floe themselves.
            if !name.starts_with("floe-length") {
                assert!(
                    plan.iter()
                        .all(|p| p.scene.floe.as_ref().unwrap().length == floe),
                    "{name}"
                );
            }
            if dir.ends_with("choices40") {
                let seeds = if name == "baseline" { 12 } else { 8 };
                assert_eq!(plan.len(), 2 * seeds, "{name}");
            }
            // Model revision 2's probes: one setting each, at both friction pairs (at μ = 1.0
            // only at the higher modulus).
            if dir.to_string_lossy().contains("choices-r2") {
                let pairs = if dir.ends_with("choices-r2-e1") { 1 } else { 2 };
                assert_eq!(plan.len(), pairs * spec.seeds as usize, "{name}");
            }
            n += 1;
        }
        assert!(n >= 3, "{}", dir.display());
    }
}

/// A campaign runs seed by seed over its grid: stopped after two runs on one thread, it has
/// the first seed of both points, not two seeds of the first point, so a partial campaign is
/// an ensemble that can be compared point with point.
#[test]
fn a_campaign_runs_seed_by_seed_over_the_grid() {
    let dir = common::scratch("order");
    let spec = CampaignSpec::from_toml(SPEC).unwrap();
    let out = dir.join("out");
    let stop = std::sync::atomic::AtomicBool::new(false);
    let progress = |p: pressridge::campaign::Progress| {
        if p.done >= 2 {
            stop.store(true, std::sync::atomic::Ordering::Relaxed);
        }
    };
    let (_, done) =
        pressridge::campaign::run_campaign(&spec, &dir, &out, 1, &progress, &stop).unwrap();
    assert_eq!(done, 2);
    let mut got: Vec<(f64, u64)> = read_campaign(&out, true)
        .unwrap()
        .records
        .iter()
        .map(|r| (r.scene.sheet.as_ref().unwrap().thickness, r.seed))
        .collect();
    got.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(got, [(0.25, 1), (0.35, 1)]);
}

/// The volume grid ends at the volume the runs were set to reach, U·h·T, so its points are
/// round (k·2.5 m³/m over the paper's six thicknesses in 19 points), and every run counts at
/// its own final volume 100·h: a run stops within half a step of T, and its last sample stands
/// for its end. Made from the committed records of the thickness set: all 7 runs of each
/// thickness at 100·h, where the grid up to the largest sample's volume (45.000004 m³/m)
/// held 0–3 of them.
#[test]
fn every_run_counts_at_its_final_volume() {
    use pressridge::table::tabulate::tabulate;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("crates/lab/records/paper3/thickness");
    let (_, records) = read_records(&dir).unwrap();
    let t = tabulate(&records, 19).unwrap();
    assert!(
        t.volume
            .iter()
            .enumerate()
            .all(|(k, &v)| v == 2.5 * k as f64),
        "{:?}",
        t.volume
    );
    for (hi, &h) in t.thickness.iter().enumerate() {
        let n = records
            .iter()
            .filter(|r| r.scene.sheet.as_ref().unwrap().thickness == h)
            .count();
        let k = (100.0 * h / 2.5f64).round() as usize;
        assert_eq!(
            t.runs[[0, hi, k]] as usize,
            n,
            "h = {h} m at {} m³/m",
            t.volume[k]
        );
        assert!(t.work_mean[[0, hi, k]].is_finite());
    }
}

/// The shipped table (`data/ridging_table.nc`) as a host reads it: at each of its 40
/// settings (friction pair and thickness) the final ridged volume 100·h m³/m (400 s at
/// 0.25 m/s) is a point of the volume axis and holds every run of that setting, as many as
/// the volume 0 and C_f have, and the work there is a number. Until 2026-12-01 the axis ran
/// to the largest sample's volume, 600.0001 m³/m, and its points held 0–3 of the 7–12 runs.
#[test]
fn the_shipped_table_holds_every_run_at_each_final_volume() {
    let path = common::repo().join("data/ridging_table.nc");
    let lut = pressridge::table::lookup::RidgeLookup::open(&path).unwrap();
    let at = |name: &str, si: usize, h: f64, v: f64| lut.value(name, si, h, v).unwrap().value;
    let mut settings = 0;
    for si in 0..lut.sets().len() {
        // Every set's μ_rdg is one a host can redistribute with (positive at each node that
        // has one: a tabulated mean at or below zero is written NaN, not refused at the host).
        if let Err(e) = lut.mu_rdg_table(si) {
            panic!("{}: {e}", lut.sets()[si]);
        }
        for &h in lut.thickness() {
            let n = at("cf_runs", si, h, 0.0);
            if n == 0.0 {
                continue;
            }
            let end = 100.0 * h;
            assert!(lut.volume().contains(&end), "{end} m³/m");
            let what = format!("{} at {h} m", lut.sets()[si]);
            assert_eq!(at("runs", si, h, 0.0), n, "{what}");
            assert_eq!(at("runs", si, h, end), n, "{what} at {end} m³/m");
            assert!(at("work_mean", si, h, end).is_finite(), "{what}");
            settings += 1;
        }
    }
    assert_eq!(settings, 40);
}
