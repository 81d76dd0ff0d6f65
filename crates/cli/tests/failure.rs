//! Failure behaviour (issue 16, docs/failure.md): no input is destroyed, no output is left
//! half-written, no input the program cannot honour is accepted, and every refusal is one
//! line naming the parameter or variable. Each test fails on the behaviour before issue 16.

#[path = "../../../tests/common/mod.rs"]
mod common;

use common::*;
use pressridge::scene::Scene;
use std::path::Path;

fn strength(input: &Path, output: &Path, extra: &[&str]) -> std::process::Output {
    bin()
        .arg("strength")
        .arg("--input")
        .arg(input)
        .arg("--output")
        .arg(output)
        .args(extra)
        .output()
        .unwrap()
}

fn ridge_step(input: &Path, output: &Path, extra: &[&str]) -> std::process::Output {
    bin()
        .arg("ridge-step")
        .arg("--input")
        .arg(input)
        .arg("--output")
        .arg(output)
        .args(extra)
        .output()
        .unwrap()
}

// ---------------------------------------------------------------------------------------
// Data loss

#[test]
fn an_output_resolving_to_the_input_is_refused_and_the_input_kept() {
    let d = scratch("alias");
    let input = d.join("in.nc");
    write_nc(&input, &good_itd());
    let before = std::fs::read(&input).unwrap();
    let link = d.join("link.nc");
    std::os::unix::fs::symlink(&input, &link).unwrap();
    let dotted = d.join("sub/../in.nc");
    std::fs::create_dir_all(d.join("sub")).unwrap();
    for out in [&input, &link, &dotted] {
        fails_with(&strength(&input, out, &[]), &["--output", "in.nc"]);
        fails_with(
            &ridge_step(&input, out, &["--dt", "3600"]),
            &["--output", "in.nc"],
        );
        assert_eq!(std::fs::read(&input).unwrap(), before, "input changed");
    }
    // Through the symlink as input too.
    fails_with(&strength(&link, &input, &[]), &["--output"]);
    assert_eq!(std::fs::read(&input).unwrap(), before);
    // A distinct output is fine.
    succeeds(&strength(&input, &d.join("p.nc"), &[]));
    // render: the image may not replace the state it draws.
    let state = d.join("state.json");
    std::fs::write(&state, b"{}").unwrap();
    let res = bin()
        .arg("render")
        .arg(&state)
        .arg("--out")
        .arg(&state)
        .output()
        .unwrap();
    fails_with(&res, &["--out", "state.json"]);
    assert_eq!(std::fs::read(&state).unwrap(), b"{}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_failed_netcdf_write_leaves_the_old_file_and_no_partial_one() {
    let d = scratch("ncfail");
    // The spatial dimension is named as the output's bounds dimension `ncat_bounds`:
    // readable, but the output cannot define that dimension twice, so writing fails after
    // the file was created.
    let input = d.join("in.nc");
    write_nc(
        &input,
        &[
            Var::f64(
                "aicen",
                &[("ncat", 2), ("ncat_bounds", 2)],
                vec![0.3, 0.3, 0.3, 0.3],
            ),
            Var::f64(
                "vicen",
                &[("ncat", 2), ("ncat_bounds", 2)],
                vec![0.3, 0.3, 0.6, 0.6],
            ),
        ],
    );
    let out = d.join("out.nc");
    std::fs::write(&out, b"old").unwrap();
    let res = ridge_step(&input, &out, &["--dt", "3600", "--convergence", "1e-6"]);
    assert_eq!(res.status.code(), Some(1), "{res:?}");
    assert_eq!(std::fs::read(&out).unwrap(), b"old", "old output damaged");
    assert_eq!(
        names_in(&d),
        vec!["in.nc", "out.nc"],
        "temporary left behind"
    );
    std::fs::remove_file(&out).unwrap();
    let res = ridge_step(&input, &out, &["--dt", "3600", "--convergence", "1e-6"]);
    assert_eq!(res.status.code(), Some(1));
    assert!(!out.exists(), "a header-only file was left at the target");
    assert_eq!(names_in(&d), vec!["in.nc"]);
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn simulate_refuses_a_used_directory_and_overwrite_replaces_only_its_files() {
    let d = scratch("simdir");
    let out = d.join("run");
    let sim = |extra: &[&str]| {
        bin()
            .args(["simulate", "--no-figures", "--scene"])
            .arg(common::repo().join("data/scenes/rubble-pile.toml"))
            .args([
                "--set",
                "pile.blocks=6",
                "--set",
                "pile.columns=3",
                "--set",
                "duration=0.05",
            ])
            .arg("--out")
            .arg(&out)
            .args(extra)
            .output()
            .unwrap()
    };
    succeeds(&sim(&["--set", "output.snapshot_interval=0.02"]));
    assert!(out.join("snapshots").is_dir());
    let summary = std::fs::read(out.join("summary.json")).unwrap();
    std::fs::write(out.join("notes.txt"), b"mine").unwrap();
    // Refused without --overwrite: nothing touched.
    fails_with(
        &sim(&["--set", "output.snapshot_interval=0"]),
        &["--overwrite", "not empty"],
    );
    assert_eq!(std::fs::read(out.join("summary.json")).unwrap(), summary);
    // --overwrite: the old run's files go (the snapshots of the first run too), others stay.
    succeeds(&sim(&[
        "--set",
        "output.snapshot_interval=0",
        "--set",
        "seed=2",
        "--overwrite",
    ]));
    assert!(!out.join("snapshots").exists(), "stale snapshots left");
    assert_eq!(std::fs::read(out.join("notes.txt")).unwrap(), b"mine");
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["seed"], 2);
    // A file as --out is refused.
    let file = d.join("file");
    std::fs::write(&file, b"x").unwrap();
    let res = bin()
        .args(["simulate", "--out"])
        .arg(&file)
        .output()
        .unwrap();
    fails_with(&res, &["--out", "not a directory"]);
    let _ = std::fs::remove_dir_all(&d);
}

// ---------------------------------------------------------------------------------------
// Inputs it cannot honour

#[test]
fn scene_parameters_out_of_range_are_refused_naming_key_and_range() {
    let cases: &[(&str, &str, &str)] = &[
        ("ice.density=1020", "ice.density", "[700, 1000] kg/m³"),
        ("ice.density=1e5", "ice.density", "must lie in"),
        ("water.density=1e9", "water.density", "must lie in"),
        ("sheet.speed=1e6", "sheet.speed", "(0, 5] m/s"),
        ("sheet.e_top=1e30", "sheet.e_top", "Pa"),
        ("sheet.thickness=1e-9", "sheet.thickness", "[0.01, 20] m"),
        ("sheet.length=1e7", "sheet.length", "must lie in"),
        ("floe.thickness=1e4", "floe.thickness", "must lie in"),
        ("floe.e_bottom=1", "floe.e_bottom", "must lie in"),
        (
            "sheet.strength_top=1e20",
            "sheet.strength_top",
            "must lie in",
        ),
        ("duration=1e12", "duration", "must lie in"),
        ("duration=0", "duration", "must lie in"),
    ];
    for (set, key, frag) in cases {
        let e = Scene::default()
            .with_overrides(&[*set])
            .unwrap_err()
            .to_string();
        assert!(e.contains(key) && e.contains(frag), "{set}: {e}");
        assert!(!e.contains('\n'), "{e}");
    }
    let e = Scene::default()
        .with_overrides(&["ice.density=1000", "water.density=995"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("ice.density") && e.contains("sinks"), "{e}");
    let e = Scene::rubble_pile()
        .with_overrides(&["pile.blocks=100000000"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("pile.blocks") && e.contains("100000"), "{e}");
    // Through the command line and a scene file alike.
    let d = scratch("ranges");
    let f = d.join("s.toml");
    std::fs::write(&f, "[ice]\ndensity = 1000.0\n[water]\ndensity = 995.0\n").unwrap();
    let res = bin()
        .args(["simulate", "--scene"])
        .arg(&f)
        .arg("--out")
        .arg(d.join("o"))
        .output()
        .unwrap();
    fails_with(&res, &["ice.density", "water.density"]);
    assert!(!d.join("o").exists(), "a refused scene must write nothing");
    let res = bin()
        .args(["simulate", "--set", "sheet.speed=1e6", "--out"])
        .arg(d.join("o"))
        .output()
        .unwrap();
    fails_with(&res, &["sheet.speed", "m/s"]);
    // Thick lead ice stays possible with wider blocks (scaled scenes).
    Scene::default()
        .with_overrides(&["sheet.thickness=2.5", "sheet.block_width=1.0"])
        .unwrap();
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn runs_of_no_step_are_errors() {
    let d = scratch("nostep");
    // The derived stable step of the default scene is ~1e-4 s.
    let res = bin()
        .args(["simulate", "--set", "duration=1e-7", "--out"])
        .arg(d.join("a"))
        .output()
        .unwrap();
    fails_with(&res, &["duration", "no step"]);
    assert!(!String::from_utf8_lossy(&res.stdout).contains("wrote"));
    assert!(!d.join("a").exists(), "a refused run must write nothing");
    let res = bin()
        .args([
            "simulate",
            "--set",
            "duration=0.1",
            "--set",
            "numerics.time_step=0.5",
            "--out",
        ])
        .arg(d.join("b"))
        .output()
        .unwrap();
    fails_with(&res, &["numerics.time_step", "no step"]);
    let e = Scene::default()
        .with_overrides(&["duration=1e-7"])
        .and_then(|s| pressridge::simulation::run(&s, &mut |_| true).map(|_| ()))
        .unwrap_err()
        .to_string();
    assert!(e.contains("no step"), "{e}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn strength_and_ridge_step_refuse_values_they_cannot_honour() {
    let d = scratch("itdvals");
    let p = d.join("p.nc");
    let mut vars = good_itd();
    if let Data::F64(v) = &mut vars[1].data {
        v[3] = 1e160;
    }
    let f = d.join("huge.nc");
    write_nc(&f, &vars);
    fails_with(&strength(&f, &p, &[]), &["vicen", "must lie in"]);
    fails_with(&ridge_step(&f, &p, &["--dt", "3600"]), &["vicen"]);
    let good = d.join("good.nc");
    write_nc(&good, &good_itd());
    fails_with(
        &strength(&good, &p, &["--cf", "1e308"]),
        &["--cf", "must lie in"],
    );
    fails_with(
        &strength(&good, &p, &["--cf", "-3"]),
        &["--cf", "must lie in"],
    );
    for (bad, what) in [(f64::NAN, "not finite"), (0.5, "increasing")] {
        let mut vars = good_itd();
        if let Data::F64(v) = &mut vars[3].data {
            v[2] = bad;
        }
        let f = d.join("bounds.nc");
        write_nc(&f, &vars);
        fails_with(&strength(&f, &p, &[]), &["hin_max", what]);
        fails_with(&ridge_step(&f, &p, &["--dt", "3600"]), &["hin_max", what]);
    }
    let mut vars = good_itd();
    if let Data::F64(v) = &mut vars[4].data {
        v[4] = f64::NAN;
    }
    let f = d.join("divu.nc");
    write_nc(&f, &vars);
    fails_with(
        &ridge_step(&f, &p, &["--dt", "3600"]),
        &["divu", "y=1, x=1"],
    );
    assert!(!p.exists(), "nothing may be written on refusal");
    // A strain rate without `units` is refused by the ridge step, naming it (a %/day field
    // taken for 1/s would be 8.64e6 times too large); the strength, which does not use it,
    // is not stopped by it.
    for k in [4, 5] {
        let mut vars = good_itd();
        vars[k].units = None;
        let f = d.join("nounits.nc");
        write_nc(&f, &vars);
        fails_with(
            &ridge_step(&f, &p, &["--dt", "3600"]),
            &[vars[k].name.as_str(), "no `units`"],
        );
        assert!(!p.exists(), "nothing may be written on refusal");
        assert!(strength(&f, &p, &[]).status.success());
        std::fs::remove_file(&p).unwrap();
        // Nor is the ridge step when both rates are given and the file's are not read (as
        // on the history of Icepack's column driver, which writes no units).
        let given = ["--dt", "3600", "--convergence", "1e-6", "--shear", "0"];
        assert!(ridge_step(&f, &p, &given).status.success());
        std::fs::remove_file(&p).unwrap();
        fails_with(
            &ridge_step(&f, &p, &given[..4]),
            &[vars[k].name.as_str(), "no `units`", "--shear"],
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

// ---------------------------------------------------------------------------------------
// Messages that mislead

#[test]
fn messages_name_the_real_constraint() {
    let e = Scene::default()
        .with_overrides(&["sheet.thickness=2.5"])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("sheet.block_width") && e.contains("0.833") && e.contains("tip_bevel_fraction"),
        "{e}"
    );
    let d = scratch("messages");
    let good = d.join("good.nc");
    write_nc(&good, &good_itd());
    let p = d.join("p.nc");
    let res = strength(&good, &p, &["--param", "foo=1"]);
    fails_with(&res, &["`foo`", "mu_rdg", "cstar"]);
    let res = strength(&good, &p, &["--param", "mu_rgd=4"]);
    fails_with(&res, &["`mu_rgd`", "did you mean `mu_rdg`"]);
    fails_with(
        &ridge_step(&good, &p, &["--dt", "0"]),
        &["--dt", "positive", "0"],
    );
    // Negative numbers need no `=`: the value reaches the check.
    fails_with(&ridge_step(&good, &p, &["--dt", "-5"]), &["--dt", "-5"]);
    fails_with(
        &ridge_step(&good, &p, &["--dt", "60", "--convergence", "-1"]),
        &["--convergence", "-1"],
    );
    // A text variable: named, with the expected type.
    let mut vars = good_itd();
    vars[1].data = Data::Text;
    let f = d.join("text.nc");
    write_nc(&f, &vars);
    fails_with(&strength(&f, &p, &[]), &["vicen", "numeric"]);
    // plot-strength into a directory that does not exist yet: made, and the PNG written.
    succeeds(&strength(&good, &p, &[]));
    let png = d.join("new/dir/map.png");
    let res = bin()
        .arg("plot-strength")
        .arg("--input")
        .arg(&p)
        .arg("--output")
        .arg(&png)
        .output()
        .unwrap();
    succeeds(&res);
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
    let _ = std::fs::remove_dir_all(&d);
}

// ---------------------------------------------------------------------------------------
// Fuzzing

/// Malformed NetCDF inputs for `strength` and `ridge-step`: wrong shapes and types, missing
/// variables, NaN/Inf/negative/huge values, empty dimensions. Each gives success or a
/// one-line error naming the variable concerned; never a panic or a signal.
#[test]
fn fuzz_malformed_netcdf_inputs() {
    let d = scratch("fuzz-nc");
    let mut rng = Rng(0x16);
    let names = ["aicen", "vicen", "aice0", "hin_max", "divu", "shear"];
    let out = d.join("o.nc");
    for case in 0..60 {
        let mut vars = good_itd();
        let k = rng.below(vars.len());
        let target = names[k].to_string();
        let kind = rng.below(7);
        match kind {
            0 => {
                vars.remove(k);
            }
            1 => {
                // Wrong shape: one dimension longer, values to match.
                let v = &mut vars[k];
                let j = rng.below(v.dims.len());
                v.dims[j].0 = format!("{}_wrong", v.dims[j].0);
                v.dims[j].1 += 1;
                let n: usize = v.dims.iter().map(|d| d.1).product();
                v.data = Data::F64(vec![0.1; n]);
            }
            2 => vars[k].data = Data::Text,
            3 => {
                let n: usize = vars[k].dims.iter().map(|d| d.1).product();
                vars[k].data = Data::I32(vec![1; n]);
            }
            4 => {
                // Empty dimension: every variable using it becomes empty.
                let dim = vars[k].dims[0].0.clone();
                for v in vars.iter_mut() {
                    for dd in v.dims.iter_mut() {
                        if dd.0 == dim {
                            dd.1 = 0;
                        }
                    }
                    v.data = Data::F64(vec![]);
                }
            }
            _ => {
                let bad = [f64::NAN, f64::INFINITY, -1.0, 1e300, -0.0, 9.969e36][rng.below(6)];
                if let Data::F64(v) = &mut vars[k].data {
                    let i = rng.below(v.len());
                    v[i] = bad;
                }
            }
        }
        let f = d.join(format!("case{case}.nc"));
        write_nc(&f, &vars);
        for res in [
            strength(&f, &out, &[]),
            ridge_step(&f, &out, &["--dt", "3600"]),
        ] {
            let err = String::from_utf8_lossy(&res.stderr);
            let ctx = format!(
                "case {case} (kind {kind} on {target}): {:?} {err}",
                res.status
            );
            assert!(res.status.code().is_some(), "signal: {ctx}");
            assert!(!err.contains("panicked"), "panic: {ctx}");
            if !res.status.success() {
                assert_eq!(err.trim().lines().count(), 1, "not one line: {ctx}");
                // Names a variable (the mutated one, or the one a missing or empty
                // dimension made inconsistent) or the option concerned.
                assert!(
                    names.iter().any(|n| err.contains(n)) || err.contains("--"),
                    "names nothing: {ctx}"
                );
            }
        }
    }
    let _ = std::fs::remove_dir_all(&d);
}
