//! A tiny campaign end to end: two thicknesses × two seeds of a short run, interrupted after
//! its first finished run and resumed without redoing anything; campaigns tabulated together
//! and the strength command on their table. (The campaign tests that need no binary are the
//! library's, tests/campaign.rs.)

use pressridge::campaign::{CampaignSpec, read_campaign, read_records};
use pressridge::energy::EnergyBudget;
use pressridge::record::RunSample;
use std::time::{Duration, Instant};

#[path = "../../../tests/common/mod.rs"]
mod common;
use common::TINY_CAMPAIGN as SPEC;
use common::bin;

#[test]
fn tiny_campaign_is_resumable_and_complete() {
    let dir = common::scratch("campaign");
    let spec = dir.join("tiny.toml");
    std::fs::write(&spec, SPEC).unwrap();
    let out = dir.join("out");

    // Start, wait for the first finished run, kill the process.
    let mut child = bin()
        .args(["campaign", "--threads", "1", "--spec"])
        .arg(&spec)
        .arg("--out")
        .arg(&out)
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    let first = out.join("runs/thickness=0.25__block_width=0.25/seed-01/run.json");
    while !first.is_file() {
        assert!(t0.elapsed() < Duration::from_secs(120), "no run finished");
        assert!(child.try_wait().unwrap().is_none(), "campaign ended early");
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let bytes = std::fs::read(&first).unwrap();
    let mtime = std::fs::metadata(&first).unwrap().modified().unwrap();
    // No half-written record is left behind by the kill: every record there is complete
    // and matches its files; an incomplete campaign is refused unless partial is allowed.
    assert!(
        read_records(&out).is_err(),
        "an interrupted campaign must not read as whole"
    );
    let c = read_campaign(&out, true).unwrap();
    assert!(c.inconsistent.is_empty(), "{:?}", c.inconsistent);
    let partial = c.records;
    assert!(!partial.is_empty() && partial.len() < 4);

    // Resume: the finished run is not redone, the others are made.
    let res = bin()
        .args(["campaign", "--threads", "2", "--spec"])
        .arg(&spec)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        res.status.success(),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );
    let msg = String::from_utf8_lossy(&res.stdout);
    assert!(
        msg.contains(&format!("{} already done", partial.len())),
        "{msg}"
    );
    assert_eq!(std::fs::read(&first).unwrap(), bytes);
    assert_eq!(
        std::fs::metadata(&first).unwrap().modified().unwrap(),
        mtime
    );

    // Everything is there, with samples every second and profiles.
    let (spec_back, records) = read_records(&out).unwrap();
    assert_eq!(spec_back, CampaignSpec::from_toml(SPEC).unwrap());
    assert_eq!(records.len(), 4);
    for r in &records {
        assert_eq!(r.samples.len(), 4, "{}", r.id);
        let last = r.samples.last().unwrap();
        let h = r.scene.sheet.as_ref().unwrap().thickness;
        assert!((last.volume - 0.25 * h * last.time).abs() < 1e-12);
        assert!((last.time - 3.0).abs() <= r.summary.dt);
        assert!(last.energy().work > 0.0);
        assert_eq!(r.profile.sail.len(), 32);
        // The ridge columns of the final profile, and the ridged ice at each sample: none at
        // the start, and at the end the final profile's.
        assert_eq!(r.profile.ridge_ice.len(), 32);
        assert_eq!(r.profile.ridge_envelope.len(), 32);
        assert_eq!(r.samples[0].ridge, None);
        assert!(r.samples[0].ridge_strips.is_empty());
        assert_eq!(
            last.ridge,
            pressridge::observe::RidgeSummary::of(&r.profile),
            "{}",
            r.id
        );
        // The ridged strips at each sample, to the millimetre: at the end the final
        // profile's, from which the summary follows within the rounding.
        assert_eq!(
            last.ridge_strips,
            RunSample::strips_of(&r.profile),
            "{}",
            r.id
        );
        let strips: Vec<(f64, f64)> = last.ridge_strips.iter().map(|s| (s[0], s[1])).collect();
        let from = pressridge::observe::RidgeSummary::of_strips(&strips, r.profile.dx).unwrap();
        let want = last.ridge.unwrap();
        assert_eq!(from.width, want.width);
        assert!((from.mean_thickness - want.mean_thickness).abs() <= 5e-4);
        let at_end =
            pressridge::table::redistribution::RidgedIce::at_sample(r, r.samples.len() - 1, h)
                .unwrap();
        assert_eq!(at_end.ice.len(), last.ridge_strips.len());
        assert!(
            pressridge::table::redistribution::RidgedIce::at_sample(r, 0, h).is_err(),
            "no rubble at the start"
        );
        for s in r.samples.iter().filter(|s| s.ridge.is_some()) {
            assert_eq!(
                s.ridge_strips.len() as f64 * r.profile.dx,
                s.ridge.unwrap().width
            );
            assert!(s.ridge_strips.iter().all(|[a, c]| 0.0 <= *a && a <= c));
        }
        assert!(out.join("runs").join(&r.id).join("state.json").is_file());
        // The rafting diagnostic: the largest overrun over the run bounds the final one, and
        // a sheet that breaks against the floe stays within the rafting reach.
        let over = r.summary.sheet_overrun_max.expect("sheet and floe present");
        let state =
            pressridge::io::state::load_state(&out.join("runs").join(&r.id).join("state.json"))
                .unwrap();
        let w = pressridge::dem::World::from_snapshot(&state).unwrap();
        let now = w.sheet_overrun().unwrap();
        assert!(now <= over && over < 2.0, "overrun {over}, final {now}");
        assert_eq!(
            pressridge::table::rafting::outcome(r, 2.0),
            pressridge::table::rafting::Outcome::Ridged
        );
        assert_eq!(
            pressridge::table::rafting::outcome(r, over - 1.0),
            pressridge::table::rafting::Outcome::Rafted(over)
        );
    }
    // A records-only archive (the run records without the states, as committed under
    // crates/lab/records/paper/) reads as the same campaign once marked; unmarked it is incomplete; a
    // campaign refuses to run into it.
    {
        use pressridge::campaign::RECORDS_ONLY;
        let archive = dir.join("archive");
        for r in &records {
            let to = archive.join("runs").join(&r.id);
            std::fs::create_dir_all(&to).unwrap();
            std::fs::copy(
                out.join("runs").join(&r.id).join("run.json"),
                to.join("run.json"),
            )
            .unwrap();
        }
        for f in ["campaign.json", "plan.json"] {
            std::fs::copy(out.join(f), archive.join(f)).unwrap();
        }
        let why = read_campaign(&archive, false).unwrap_err().to_string();
        assert!(why.contains("state.json is missing"), "{why}");
        std::fs::write(archive.join(RECORDS_ONLY), "records only\n").unwrap();
        assert_eq!(read_records(&archive).unwrap().1, records);
        let res = bin()
            .args(["campaign", "--threads", "1", "--spec"])
            .arg(&spec)
            .arg("--out")
            .arg(&archive)
            .output()
            .unwrap();
        assert!(!res.status.success());
        let err = String::from_utf8_lossy(&res.stderr);
        assert!(err.contains("records-only archive"), "{err}");

        // Resuming from the archive on another machine (a fresh directory): the archive's
        // runs are taken, not run again; only the run it lacks is made, and the result
        // reads as the same campaign.
        let lost = &records[3].id;
        std::fs::remove_dir_all(archive.join("runs").join(lost)).unwrap();
        let again = dir.join("again");
        let resume = |out: &std::path::Path| {
            bin()
                .args(["campaign", "--threads", "1", "--quiet", "--spec"])
                .arg(&spec)
                .arg("--out")
                .arg(out)
                .arg("--resume-from")
                .arg(&archive)
                .output()
                .unwrap()
        };
        let res = resume(&again);
        let msg = common::succeeds(&res);
        assert!(msg.contains("3 already done, 1 run now"), "{msg}");
        let err = String::from_utf8_lossy(&res.stderr);
        assert!(err.contains("3 finished runs taken from"), "{err}");
        assert!(again.join("runs").join(lost).join("state.json").is_file());
        assert!(
            !again
                .join("runs")
                .join(&records[0].id)
                .join("state.json")
                .exists()
        );
        let (_, back) = read_records(&again).unwrap();
        assert_eq!(back.len(), 4);
        for (a, b) in back.iter().zip(&records) {
            let (mut a, mut b) = (a.clone(), b.clone());
            (a.digest, b.digest) = (None, None);
            a.summary.wall_seconds = 0.0;
            b.summary.wall_seconds = 0.0;
            assert_eq!(a, b, "{}", a.id);
        }
        // An archive record of another scene under the same id is refused.
        let mut other = records[0].clone();
        other.seed += 10;
        std::fs::write(
            archive.join("runs").join(&other.id).join("run.json"),
            serde_json::to_string(&other).unwrap(),
        )
        .unwrap();
        common::fails_with(&resume(&dir.join("third")), &[&other.id]);
    }
    // Ensemble statistics per grid point: two points of two seeds, means over the records.
    let points = pressridge::table::ensemble::summarise(&records);
    assert_eq!(points.len(), 2);
    for (p, rs) in points.iter().zip(records.chunks(2)) {
        assert_eq!(p.seeds, vec![1, 2]);
        let w = p.get("work").unwrap();
        assert_eq!(w.n, 2);
        let mean = 0.5 * (rs[0].summary.energy().work + rs[1].summary.energy().work);
        assert!((w.mean - mean).abs() <= 1e-12 * mean.abs());
        let f = p.get("friction_fraction").unwrap();
        assert!(f.mean > 0.0 && f.mean < 1.0, "{f:?}");
        assert!(p.get("residual_fraction").unwrap().mean < 0.01);
    }
    // The physical-consistency gate: a negative dissipation (an energy source) leaves a run
    // out of the table; round-off does not.
    {
        use pressridge::table::ensemble::dissipation_violation;
        use pressridge::table::tabulate::tabulate;
        assert!(records.iter().all(|r| dissipation_violation(r).is_none()));
        let mut bad = records.clone();
        let mut e = bad[0].summary.energy();
        let w = e.work;
        e.viscous_dissipation = -0.01 * w;
        bad[0].summary.set_energy(&e);
        let why = dissipation_violation(&bad[0]).expect("negative Φ_i must be caught");
        assert!(why.contains("viscous_dissipation"), "{why}");
        let t = tabulate(&bad, 11).unwrap();
        assert_eq!(t.excluded.len(), 1);
        assert_eq!(t.excluded[0].0, records[0].id);
        assert_eq!(t.runs[[0, 0, 0]], 1, "one seed left at the first thickness");
        e.viscous_dissipation = -1e-9 * w;
        bad[0].summary.set_energy(&e);
        assert!(
            dissipation_violation(&bad[0]).is_none(),
            "round-off is tolerated"
        );
        let x = &mut bad[0].samples[2];
        x.set_energy(&EnergyBudget {
            friction_dissipation: -0.5 * w,
            ..x.energy()
        });
        assert!(dissipation_violation(&bad[0]).unwrap().contains("at t ="));
        assert!(tabulate(&records, 11).unwrap().excluded.is_empty());
    }
    // Tabulate: dimensions, units, fits, and a C_f table the strength routine reads.
    let table = dir.join("table.nc");
    let res = bin()
        .arg("tabulate")
        .arg("--campaign")
        .arg(&out)
        .arg("--out")
        .arg(&table)
        .args(["--points", "11"])
        .arg("--figures")
        .arg(dir.join("fig"))
        .arg("--report")
        .arg(dir.join("report.md"))
        .output()
        .unwrap();
    assert!(
        res.status.success(),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    for want in [
        "# Campaign `tiny`: 4 runs tabulated, 0 left out",
        "## Energy budget",
        "## Ridge metrics",
        "pooled",
        "## Rafting",
        "| sheet.thickness=0.25, sheet.block_width=0.25 | 2.0 | 0 / 2 | – |",
        "## Ridged ice",
        "| mu=1, mu_w=0.6 | 0.25 | 2 / 2 |",
    ] {
        assert!(report.contains(want), "report lacks {want}:\n{report}");
    }
    for f in ["work_set0", "force_set0", "cf", "profiles", "mu_rdg"] {
        for ext in ["png", "svg"] {
            let path = dir.join("fig").join(format!("{f}.{ext}"));
            assert!(path.is_file(), "missing figure {f}.{ext}");
        }
    }
    // C_f against thickness with each seed and the spread; profiles with the seed spread.
    let svg = |f: &str| std::fs::read_to_string(dir.join("fig").join(f)).unwrap();
    let cf_svg = svg("cf.svg");
    for want in [
        "C_f = W/ΔPE",
        "sheet thickness h (m)",
        "(2 seeds)",
        "CICE default",
    ] {
        assert!(cf_svg.contains(want), "cf.svg lacks {want}");
    }
    assert!(cf_svg.matches("<circle").count() >= 4, "a dot per run");
    // μ_rdg of the ridged ice against thickness, beside Icepack's values.
    let mu_svg = svg("mu_rdg.svg");
    for want in [
        "μ_rdg (m^½)",
        "Icepack default",
        "science guide",
        "(2 seeds)",
    ] {
        assert!(mu_svg.contains(want), "mu_rdg.svg lacks {want}");
    }
    let prof_svg = svg("profiles.svg");
    for want in [
        "h = 0.25 m (2 seeds)",
        "h = 0.35 m (2 seeds)",
        "mean ± 1 s.d.",
    ] {
        assert!(prof_svg.contains(want), "profiles.svg lacks {want}");
    }
    {
        use pressridge::table::tabulate::tabulate;
        let t = tabulate(&records, 11).unwrap();
        // The table in memory is the table its file reads back as (friction-grid layout
        // here): the same sets, axes and fields, to the bit.
        let mem = t.lookup().unwrap();
        let disk = pressridge::table::lookup::RidgeLookup::open(&table).unwrap();
        assert_eq!(
            (mem.sets(), mem.thickness(), mem.volume()),
            (disk.sets(), disk.thickness(), disk.volume())
        );
        assert_eq!(mem.friction(), disk.friction());
        let names: Vec<&str> = disk.variables().collect();
        assert_eq!(mem.variables().collect::<Vec<_>>(), names);
        // The ridged-ice fields: per thickness, the runs whose final profile holds rubble,
        // and μ_rdg from their ensemble (what `pressridge redistribution` reports).
        let (ens, without) = pressridge::table::redistribution::ensembles(&records);
        assert_eq!(without, 0);
        assert!(!ens.is_empty(), "the tiny runs break the sheet at the floe");
        for (k, e) in &ens {
            let hi = t.thickness.iter().position(|&h| h == k.thickness).unwrap();
            let got = t.ridged[[0, hi]].as_ref().unwrap();
            assert_eq!(got.mu_rdg, e.mu_rdg);
            // The table's μ_rdg is the ensemble's where positive, NaN where the ridged ice is
            // on average no thicker than H_min (as these short runs' thin rubble may be).
            let f = disk.field("mu_rdg").unwrap();
            match e.host_mu_rdg() {
                Some(m) => assert_eq!(f.data.iter().filter(|x| **x == m).count(), 1),
                None => assert!(e.mu_rdg.mean <= 0.0 && f.data.iter().any(|x| x.is_nan())),
            }
            let n = disk.field("ridged_runs").unwrap();
            assert!(n.data.iter().any(|x| *x == e.lambda.n as f64));
        }
        // The binned distribution, per bin of H/h: each thickness's fractions add to one.
        let file = netcdf::open(&table).unwrap();
        let v = file.variable("ridged_fraction").unwrap();
        let dims: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
        assert_eq!(dims, ["thickness", "mu", "mu_w", "ridged_bin"]);
        let x: Vec<f64> = v.get_values(..).unwrap();
        for (cell, k) in x.chunks(40).zip(0..) {
            let sum: f64 = cell.iter().sum();
            assert!((sum - 1.0).abs() < 1e-12, "cell {k}: {sum}");
        }
        assert_eq!(file.variable("ridged_bin_bounds").unwrap().len(), 80);
        for n in names {
            let (a, b) = (mem.field(n).unwrap(), disk.field(n).unwrap());
            assert_eq!(
                (a.axes, &a.units, &a.long_name),
                (b.axes, &b.units, &b.long_name)
            );
            let bits = |f: &pressridge::table::lookup::Field| -> Vec<u64> {
                f.data.iter().map(|x| x.to_bits()).collect()
            };
            assert_eq!(a.data.shape(), b.data.shape(), "{n}");
            assert_eq!(bits(a), bits(b), "{n}");
        }
        for (h, runs) in t.cf_finals.row(0).iter().enumerate() {
            assert_eq!(runs.len(), 2);
            let mean = runs.iter().sum::<f64>() / 2.0;
            assert!((mean - t.cf[[0, h]]).abs() <= 1e-12 * mean);
        }
        // An empty fit table and a NaN fit are warned about; one seed shows as "(1 seed)".
        use pressridge::table::tabulate::fit_warnings;
        assert!(fit_warnings(&t).is_empty(), "{:?}", fit_warnings(&t));
        let mut short = records[..1].to_vec();
        short[0].samples.truncate(2);
        let w = fit_warnings(&tabulate(&short, 11).unwrap());
        assert!(w[0].contains("fit table is empty"), "{w:?}");
        let mut nan = records[..1].to_vec();
        let x = &mut nan[0].samples[2];
        x.set_energy(&EnergyBudget {
            work: f64::NAN,
            ..x.energy()
        });
        assert!(!fit_warnings(&tabulate(&nan, 11).unwrap()).is_empty());
        let one = pressridge::table::ensemble::summarise(&records[..1]);
        let t1 = tabulate(&records[..1], 11).unwrap();
        let text = pressridge::io::report::campaign_report("one", &one, &t1, &[], 2.0);
        assert!(text.contains("(1 seed)"), "{text}");
        assert!(!text.contains("± 0.0 |"), "{text}");
        let ps: Vec<_> = records[..2].iter().map(|r| r.profile.clone()).collect();
        let m = pressridge::observe::mean_profile(&ps).unwrap();
        let sd = pressridge::observe::profile_spread(&ps).unwrap();
        for i in 0..m.sail.len() {
            let half = 0.5 * (ps[0].sail[i] - ps[1].sail[i]).abs();
            assert!((sd.sail[i] - half * 2f64.sqrt()).abs() <= 1e-12 + 1e-9 * half);
            assert!((m.sail[i] - 0.5 * (ps[0].sail[i] + ps[1].sail[i])).abs() <= 1e-12);
        }
    }
    // --exclude-rafted with a reach between the two largest overruns: the run that slid
    // farthest is left out of the table (named, with its reason), and still counted as
    // rafted.
    {
        let mut over: Vec<(f64, String)> = records
            .iter()
            .map(|r| (r.summary.sheet_overrun_max.unwrap(), r.id.clone()))
            .collect();
        over.sort_by(|a, b| b.0.total_cmp(&a.0));
        let reach = 0.5 * (over[0].0 + over[1].0);
        let t2 = dir.join("table-ridged.nc");
        let res = bin()
            .args(["tabulate", "--exclude-rafted", "--rafting-reach"])
            .arg(reach.to_string())
            .arg("--campaign")
            .arg(&out)
            .arg("--out")
            .arg(&t2)
            .args(["--points", "11"])
            .output()
            .unwrap();
        common::succeeds(&res);
        let stdout = String::from_utf8_lossy(&res.stdout);
        assert!(stdout.contains("3 runs (1 left out)"), "{stdout}");
        assert!(stdout.contains("rafting: 1 of 4 runs"), "{stdout}");
        let nc = netcdf::open(&t2).unwrap();
        let ex = match nc.attribute("excluded_runs").unwrap().value().unwrap() {
            netcdf::AttributeValue::Str(s) => s,
            other => panic!("{other:?}"),
        };
        assert!(ex.contains(&over[0].1) && ex.contains("rafted"), "{ex}");
        let runs: Vec<f64> = nc.variable("runs").unwrap().get_values(..).unwrap();
        assert_eq!(
            runs.iter().take(11).fold(0.0f64, |a, b| a.max(*b)) + runs[11],
            3.0
        );
    }
    let nc = netcdf::open(&table).unwrap();
    let dim = |n: &str| nc.dimension(n).unwrap().len();
    // One set told apart by its friction alone: the friction-grid layout.
    assert!(nc.dimension("set").is_none());
    assert_eq!(
        (dim("thickness"), dim("mu"), dim("mu_w"), dim("volume")),
        (2, 1, 1, 11)
    );
    let dims = |v: &str| -> Vec<String> {
        nc.variable(v)
            .unwrap()
            .dimensions()
            .iter()
            .map(|d| d.name())
            .collect()
    };
    assert_eq!(dims("work_mean"), ["thickness", "mu", "mu_w", "volume"]);
    assert_eq!(dims("cf_by_set"), ["thickness", "mu", "mu_w"]);
    assert_eq!(dims("work_fit"), ["mu", "mu_w", "volume"]);
    assert_eq!(dims("mu"), ["mu"]);
    let units = |v: &str| match nc
        .variable(v)
        .unwrap()
        .attribute_value("units")
        .unwrap()
        .unwrap()
    {
        netcdf::AttributeValue::Str(s) => s,
        other => panic!("{other:?}"),
    };
    assert_eq!(units("thickness"), "m");
    assert_eq!(units("volume"), "m3 m-1");
    assert_eq!(units("work_mean"), "J m-1");
    assert_eq!(units("force_fit"), "N m-1");
    assert_eq!(units("cf"), "1");
    let th: Vec<f64> = nc.variable("thickness").unwrap().get_values(..).unwrap();
    assert_eq!(th, vec![0.25, 0.35]);
    let cf: Vec<f64> = nc.variable("cf").unwrap().get_values(..).unwrap();
    assert!(cf.iter().all(|c| c.is_finite() && *c > 1.0), "{cf:?}");
    let runs: Vec<f64> = nc.variable("runs").unwrap().get_values(..).unwrap();
    assert_eq!(runs[0], 2.0, "both seeds behind V = 0");
    // Eq (15) is tabulated only where runs of that thickness reached (the thinner sheet
    // stops short of the grid's end): no extrapolation.
    let ffit: Vec<f64> = nc.variable("force_fit").unwrap().get_values(..).unwrap();
    assert!(
        runs.contains(&0.0),
        "the thin sheet should stop short: {runs:?}"
    );
    for (f, n) in ffit.iter().zip(&runs) {
        assert_eq!(f.is_finite(), *n > 0.0, "force_fit {f} with {n} runs");
    }
    for attr in [
        "campaign_spec",
        "scene",
        "history",
        "seeds",
        "pressridge_version",
    ] {
        assert!(nc.attribute(attr).is_some(), "missing provenance {attr}");
    }
    // Read back through the lookup API: nodes give the stored values, C_f matches `cf`,
    // outside the range is clamped and flagged.
    let work: Vec<f64> = nc.variable("work_mean").unwrap().get_values(..).unwrap();
    let vol: Vec<f64> = nc.variable("volume").unwrap().get_values(..).unwrap();
    drop(nc);
    let lut = pressridge::table::lookup::RidgeLookup::open(&table).unwrap();
    assert_eq!(lut.thickness(), th.as_slice());
    assert_eq!(lut.volume(), vol.as_slice());
    assert!(lut.attribute("campaign_spec").unwrap().contains("tiny"));
    for (ih, &h) in th.iter().enumerate() {
        for (iv, &v) in vol.iter().enumerate() {
            let got = lut.value("work_mean", 0, h, v).unwrap();
            let want = work[ih * vol.len() + iv];
            assert!(got.value.to_bits() == want.to_bits(), "{got:?} vs {want}");
            assert!(!got.clamped);
        }
        assert_eq!(lut.cf(0, h).unwrap().value, cf[ih]);
    }
    let out_of_range = lut.cf(0, 1.0).unwrap();
    assert!(out_of_range.clamped && out_of_range.value == cf[1]);
    assert_eq!(lut.cf_table(0).unwrap().values(), cf.as_slice());
    let sample = common::repo().join("data/sample_itd.nc");
    let res = bin()
        .arg("strength")
        .arg("--input")
        .arg(&sample)
        .arg("--output")
        .arg(dir.join("p.nc"))
        .arg("--cf-table")
        .arg(&table)
        .output()
        .unwrap();
    assert!(
        res.status.success(),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );

    // Runs are reproducible: a third invocation does nothing.
    let res = bin()
        .args(["campaign", "--spec"])
        .arg(&spec)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&res.stdout).contains("4 already done, 0 run now"));

    // Honest records: a deleted state file, a record copied from another run directory and
    // a missing record are named by tabulate (refused, or left out with --allow-partial
    // and counted in the table's attributes) and redone by the campaign, identically.
    for r in &records {
        assert!(r.digest.is_some(), "{} has no digest", r.id);
    }
    let ids: Vec<&str> = records.iter().map(|r| r.id.as_str()).collect();
    let run_dir = |id: &str| out.join("runs").join(id);
    std::fs::remove_file(run_dir(ids[1]).join("state.json")).unwrap();
    std::fs::copy(
        run_dir(ids[2]).join("run.json"),
        run_dir(ids[3]).join("run.json"),
    )
    .unwrap();
    std::fs::remove_file(run_dir(ids[0]).join("run.json")).unwrap();
    let c = read_campaign(&out, true).unwrap();
    assert_eq!(c.missing, vec![ids[0].to_string()]);
    let bad: Vec<&str> = c.inconsistent.iter().map(|(id, _)| id.as_str()).collect();
    assert_eq!(bad, vec![ids[1], ids[3]]);
    assert!(
        c.inconsistent[0].1.contains("state.json"),
        "{:?}",
        c.inconsistent
    );
    assert!(c.inconsistent[1].1.contains(ids[2]), "{:?}", c.inconsistent);
    let partial_table = dir.join("partial.nc");
    let tab = |extra: &[&str]| {
        bin()
            .arg("tabulate")
            .arg("--campaign")
            .arg(&out)
            .arg("--out")
            .arg(&partial_table)
            .args(["--points", "5"])
            .args(extra)
            .output()
            .unwrap()
    };
    let res = tab(&[]);
    assert_eq!(res.status.code(), Some(1));
    let err = String::from_utf8_lossy(&res.stderr);
    for id in [ids[0], ids[1], ids[3]] {
        assert!(err.contains(id), "tabulate does not name {id}: {err}");
    }
    assert!(err.contains("1 of 4 planned runs complete"), "{err}");
    assert!(!partial_table.exists());
    let res = tab(&["--allow-partial"]);
    assert!(
        res.status.success(),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );
    let nc = netcdf::open(&partial_table).unwrap();
    let int_attr = |n: &str| match nc.attribute(n).unwrap().value().unwrap() {
        netcdf::AttributeValue::Int(i) => i,
        other => panic!("{n}: {other:?}"),
    };
    assert_eq!(
        (int_attr("runs_planned"), int_attr("runs_tabulated")),
        (4, 1)
    );
    match nc.attribute("partial").unwrap().value().unwrap() {
        netcdf::AttributeValue::Str(s) => assert!(s.starts_with("yes") && s.contains(ids[0])),
        other => panic!("{other:?}"),
    }
    drop(nc);
    // Resuming redoes exactly the three runs, with the same results as before.
    let res = bin()
        .args(["campaign", "--threads", "2", "--spec"])
        .arg(&spec)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        String::from_utf8_lossy(&res.stdout).contains("1 already done, 3 run now"),
        "{}{}",
        String::from_utf8_lossy(&res.stdout),
        String::from_utf8_lossy(&res.stderr)
    );
    let (_, again) = read_records(&out).unwrap();
    let strip = |rs: &[pressridge::record::RunRecord]| {
        rs.iter()
            .cloned()
            .map(|mut r| {
                r.summary.wall_seconds = 0.0;
                r
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(strip(&again), strip(&records), "a resumed run differs");
    // The same scene and seed under another run's id (as a value given twice on an axis
    // made before such specs were refused), with consistent digests, counts once.
    let mut twin = again[0].clone();
    twin.id = ids[1].to_string();
    let d = twin.digest.as_mut().unwrap();
    d.scene = pressridge::campaign::scene_digest(&twin.id, twin.seed, &twin.scene);
    std::fs::copy(
        run_dir(ids[0]).join("state.json"),
        run_dir(ids[1]).join("state.json"),
    )
    .unwrap();
    pressridge::io::state::write_json(&run_dir(ids[1]).join("run.json"), &twin).unwrap();
    let c = read_campaign(&out, true).unwrap();
    assert_eq!(c.records.len(), 3);
    assert_eq!(c.inconsistent.len(), 1, "{:?}", c.inconsistent);
    assert!(
        c.inconsistent[0].1.contains("same scene and seed"),
        "{:?}",
        c.inconsistent
    );

    // A changed grid is refused in the same directory.
    std::fs::write(&spec, SPEC.replace("0.35", "0.40")).unwrap();
    let res = bin()
        .args(["campaign", "--spec"])
        .arg(&spec)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(!res.status.success());
    assert!(String::from_utf8_lossy(&res.stderr).contains("another grid"));
}

/// Two campaigns tabulated into one table (issue 14): a thickness set at the default
/// friction and a friction set at one thickness. Sets are found from the scenes, the run
/// both campaigns made is counted once, each set carries its friction pair as coordinates,
/// and the strength command takes C_f at the friction asked for — or refuses, naming the
/// pairs the table has.
/// Runs the campaign of `spec` into `out` on two threads, quietly, and checks it succeeded.
fn run_campaign(spec: &std::path::Path, out: &std::path::Path) {
    common::succeeds(
        &bin()
            .args(["campaign", "--threads", "2", "--quiet", "--spec"])
            .arg(spec)
            .arg("--out")
            .arg(out)
            .output()
            .unwrap(),
    );
}

#[test]
fn friction_is_chosen_by_its_value_across_campaigns() {
    let dir = common::scratch("friction-table");
    let thick = dir.join("thickness.toml");
    std::fs::write(&thick, SPEC.replace("seeds = 2", "seeds = 1")).unwrap();
    let fric = dir.join("friction.toml");
    std::fs::write(
        &fric,
        r#"
name = "tinyfriction"
seeds = 1
sample_interval = 1.0
set = ["duration=3.0", "sheet.length=8.0", "sheet.thickness=0.25", "sheet.block_width=0.25", "floe.nose_slope=1.0"]

[[axis]]
key = "contact.mu"
values = [0.6, 1.0]
"#,
    )
    .unwrap();
    for (spec, out) in [(&thick, "a"), (&fric, "b")] {
        run_campaign(spec, &dir.join(out));
    }
    let table = dir.join("t.nc");
    let res = bin()
        .arg("tabulate")
        .arg("--campaign")
        .arg(dir.join("a"))
        .arg("--campaign")
        .arg(dir.join("b"))
        .arg("--out")
        .arg(&table)
        .args(["--points", "5"])
        .arg("--figures")
        .arg(dir.join("fig"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&res.stderr).to_string();
    common::succeeds(&res);
    // Several sets: work and profiles per set, and at the thickness both sets have (0.25 m)
    // one curve per set (cf. Figures 8 and 9), legends in symbols.
    let fig = |f: &str| std::fs::read_to_string(dir.join("fig").join(f)).unwrap();
    for f in ["work_sets_h0.25.svg", "profiles_h0.25.svg"] {
        let svg = fig(f);
        for want in ["μ = 1, μ_w = 0.6", "μ = 0.6, μ_w = 0.6"] {
            assert!(svg.contains(want), "{f} lacks {want}");
        }
    }
    for f in [
        "profiles_set0.svg",
        "profiles_set1.png",
        "work_set1.png",
        "cf.png",
    ] {
        assert!(dir.join("fig").join(f).is_file(), "missing {f}");
    }
    assert!(fig("profiles_set0.svg").contains("h = 0.35 m (1 seed)"));
    assert!(
        !dir.join("fig/work_sets_h0.35.png").exists(),
        "one set at 0.35 m"
    );
    assert!(
        err.contains("1 runs were in more than one campaign"),
        "{err}"
    );

    let nc = netcdf::open(&table).unwrap();
    let get = |v: &str| -> Vec<f64> { nc.variable(v).unwrap().get_values(..).unwrap() };
    // Sets told apart by friction alone: a (thickness, mu, mu_w) grid, axes ascending.
    assert_eq!(get("mu"), vec![0.6, 1.0]);
    assert_eq!(get("mu_w"), vec![0.6]);
    assert_eq!(get("thickness"), vec![0.25, 0.35]);
    // Runs behind C_f: μ = 1.0 has both thicknesses (the shared 0.25 m run once), μ = 0.6
    // only 0.25 m; its C_f at 0.35 m is missing, not copied from the other set.
    assert_eq!(get("cf_runs"), vec![1.0, 1.0, 0.0, 1.0]);
    let cf_by_set = get("cf_by_set");
    assert!(cf_by_set[2].is_nan());
    assert_eq!(get("cf"), vec![cf_by_set[1], cf_by_set[3]]);
    let attr = |v: &str, a: &str| nc.variable(v).unwrap().attribute_value(a).unwrap().unwrap();
    assert_eq!(attr("cf", "mu"), netcdf::AttributeValue::Double(1.0));
    assert_eq!(
        nc.attribute("set_mu").unwrap().value().unwrap(),
        netcdf::AttributeValue::Doubles(vec![1.0, 0.6])
    );
    drop(nc);

    let lut = pressridge::table::lookup::RidgeLookup::open(&table).unwrap();
    assert_eq!(lut.friction_set(0.6, 0.6).unwrap(), 1);
    let low = lut.cf_table_at_friction(0.6, 0.6).unwrap();
    assert_eq!(
        (low.thickness(), low.values()),
        (&[0.25][..], &cf_by_set[0..1])
    );
    assert_eq!(low.friction(), Some((0.6, 0.6)));
    let e = lut.friction_set(0.4, 0.3).unwrap_err().to_string();
    assert!(
        e.contains("mu = 0.4, mu_w = 0.3") && e.contains("(1, 0.6), (0.6, 0.6)"),
        "{e}"
    );

    let sample = common::repo().join("data/sample_itd.nc");
    let strength = |extra: &[&str], out: &str| {
        bin()
            .arg("strength")
            .arg("--input")
            .arg(&sample)
            .arg("--output")
            .arg(dir.join(out))
            .arg("--cf-table")
            .arg(&table)
            .args(extra)
            .output()
            .unwrap()
    };
    for (extra, out, want) in [
        (&[][..], "p_default.nc", "mu = 1, mu_w = 0.6"),
        (
            &["--friction", "0.6,0.6"][..],
            "p_low.nc",
            "mu = 0.6, mu_w = 0.6",
        ),
    ] {
        common::succeeds(&strength(extra, out));
        let nc = netcdf::open(dir.join(out)).unwrap();
        let cf = match nc.attribute("cf").unwrap().value().unwrap() {
            netcdf::AttributeValue::Str(s) => s,
            other => panic!("{other:?}"),
        };
        assert!(cf.contains(want), "{out}: cf = {cf}");
    }
    common::fails_with(
        &strength(&["--friction", "0.4,0.3"], "p_none.nc"),
        &["mu = 0.4, mu_w = 0.3", "(1, 0.6), (0.6, 0.6)"],
    );
    assert!(!dir.join("p_none.nc").exists());
    let res = strength(&["--friction", "1.0"], "p_bad.nc");
    assert_eq!(
        res.status.code(),
        Some(2),
        "a malformed --friction is a usage error"
    );
    assert!(String::from_utf8_lossy(&res.stderr).contains("MU,MU_W"));
}

/// A thickness set whose floe is scaled with the sheet above the thicknesses of another
/// campaign (issue 14: the table's thick end, data/campaigns/thickness-scaled.toml) makes
/// one set only when tabulate is told which keys scale with the thickness; the table then
/// records their value per thickness, keeps its friction grid, and two campaigns whose runs
/// disagree at one thickness are refused rather than counted once.
#[test]
fn keys_scaled_with_the_thickness_join_two_campaigns_into_one_set() {
    let dir = common::scratch("scaled-keys");
    let plain = dir.join("plain.toml");
    std::fs::write(&plain, SPEC.replace("seeds = 2", "seeds = 1")).unwrap();
    let scaled_spec = |thickness: &str| {
        format!(
            r#"
name = "tinyscaled"
seeds = 1
sample_interval = 1.0
set = ["duration=3.0", "sheet.length=8.0", "floe.nose_slope=1.0"]

[[axis]]
keys = ["sheet.thickness", "sheet.block_width", "floe.thickness", "floe.length"]
values = [[{thickness}, 0.30, 3.0, 30.0]]
"#
        )
    };
    let scaled = dir.join("scaled.toml");
    std::fs::write(&scaled, scaled_spec("0.45")).unwrap();
    let clash = dir.join("clash.toml");
    std::fs::write(&clash, scaled_spec("0.35")).unwrap();
    for (spec, out) in [(&plain, "a"), (&scaled, "b"), (&clash, "c")] {
        run_campaign(spec, &dir.join(out));
    }
    let tabulate = |campaigns: &[&str], extra: &[&str], out: &str| {
        let mut c = bin();
        c.arg("tabulate");
        for k in campaigns {
            c.arg("--campaign").arg(dir.join(k));
        }
        c.arg("--out")
            .arg(dir.join(out))
            .args(["--points", "5"])
            .args(extra)
            .output()
            .unwrap()
    };
    let global = |nc: &netcdf::File, a: &str| match nc.attribute(a).map(|x| x.value().unwrap()) {
        Some(netcdf::AttributeValue::Str(s)) => Some(s),
        None => None,
        Some(other) => panic!("{a}: {other:?}"),
    };
    // Without the keys: the 3 m floe is another set (the set layout, two sets at one pair).
    common::succeeds(&tabulate(&["a", "b"], &[], "two.nc"));
    let nc = netcdf::open(dir.join("two.nc")).unwrap();
    assert!(
        nc.dimension("set").is_some(),
        "two sets at one friction pair"
    );
    assert!(global(&nc, "scaled_keys").is_none());
    drop(nc);
    // With them: one set over 0.25-0.45 m, a friction grid, the values per thickness.
    let report = dir.join("one.md");
    common::succeeds(&tabulate(
        &["a", "b"],
        &[
            "--scaled-with-thickness",
            "floe.thickness,floe.length",
            "--report",
            report.to_str().unwrap(),
        ],
        "one.nc",
    ));
    let nc = netcdf::open(dir.join("one.nc")).unwrap();
    assert!(nc.dimension("set").is_none(), "one set: the friction grid");
    let h: Vec<f64> = nc.variable("thickness").unwrap().get_values(..).unwrap();
    assert_eq!(h, vec![0.25, 0.35, 0.45]);
    let cf: Vec<f64> = nc.variable("cf").unwrap().get_values(..).unwrap();
    assert!(cf.iter().all(|c| c.is_finite()), "{cf:?}");
    assert_eq!(
        global(&nc, "scaled_keys").as_deref(),
        Some("floe.thickness floe.length")
    );
    let values = global(&nc, "scaled_values").unwrap();
    for want in [
        "at 0.25 m: floe.thickness=2.0, floe.length=40.0",
        "at 0.45 m: floe.thickness=3.0, floe.length=30.0",
    ] {
        assert!(values.contains(want), "{values}");
    }
    drop(nc);
    let text = std::fs::read_to_string(&report).unwrap();
    assert!(
        text.contains("## Scene keys scaled with the thickness"),
        "{text}"
    );
    assert!(
        text.contains("| mu=1, mu_w=0.6 | 0.45 | 3.0 | 30.0 |"),
        "{text}"
    );
    // Runs of one set and thickness must agree in the scaled keys: the 0.35 m runs of `a`
    // (2 m floe) and `c` (3 m floe) are refused together, naming both.
    common::fails_with(
        &tabulate(
            &["a", "c"],
            &["--scaled-with-thickness", "floe.thickness,floe.length"],
            "clash.nc",
        ),
        &["one set at one thickness", "thickness=0.35"],
    );
    // Keys that are not scene keys, or that may not vary within a set, are refused.
    for (key, want) in [
        ("floe.thicknes", "no run's scene has this key"),
        ("contact.mu", "may not vary within a set"),
    ] {
        common::fails_with(
            &tabulate(&["a"], &["--scaled-with-thickness", key], "bad.nc"),
            &[key, want],
        );
    }
}

/// A run is its scene and seed: resuming from an archive takes a run planned under another
/// id (a probe's axis setting a key to the value the spec now has anyway) and gives it this
/// campaign's id and settings; nothing is run again, and the records read as this campaign.
#[test]
fn resuming_takes_the_same_run_planned_under_another_id() {
    let dir = common::scratch("resume-by-scene");
    let spec_a = dir.join("a.toml");
    let spec_b = dir.join("b.toml");
    std::fs::write(
        &spec_a,
        SPEC.replace("name = \"tiny\"", "name = \"a\"")
            .replace("seeds = 2", "seeds = 1")
            + "\n[[axis]]\nkey = \"sheet.gap\"\nvalues = [0.05]\n",
    )
    .unwrap();
    std::fs::write(
        &spec_b,
        SPEC.replace("name = \"tiny\"", "name = \"b\"")
            .replace("seeds = 2", "seeds = 1"),
    )
    .unwrap();
    let run = |spec: &std::path::Path, out: &std::path::Path, from: Option<&std::path::Path>| {
        let mut c = bin();
        c.args(["campaign", "--threads", "1", "--quiet", "--spec"])
            .arg(spec)
            .arg("--out")
            .arg(out);
        if let Some(f) = from {
            c.arg("--resume-from").arg(f);
        }
        c.output().unwrap()
    };
    common::succeeds(&run(&spec_a, &dir.join("a"), None));
    let msg = common::succeeds(&run(&spec_b, &dir.join("b"), Some(&dir.join("a"))));
    assert!(msg.contains("2 already done, 0 run now"), "{msg}");
    let (_, a) = read_records(&dir.join("a")).unwrap();
    let (_, b) = read_records(&dir.join("b")).unwrap();
    for (x, y) in a.iter().zip(&b) {
        assert!(
            x.id.contains("gap=0.05") && !y.id.contains("gap"),
            "{} {}",
            x.id,
            y.id
        );
        assert_eq!(
            (&x.scene, x.seed, &x.summary.work_eq9),
            (&y.scene, y.seed, &y.summary.work_eq9)
        );
    }
}
