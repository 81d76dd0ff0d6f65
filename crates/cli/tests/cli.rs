//! The command line end to end: simulate a short scene, render its state, reject bad input.

#[path = "../../../tests/common/mod.rs"]
mod common;
use common::bin;

#[test]
fn simulate_then_render() {
    let dir = common::simulate(
        "cli",
        &[
            "--set",
            "duration=0.5",
            "--set",
            "output.snapshot_interval=0.25",
        ],
    );
    for f in [
        "summary.json",
        "series.csv",
        "state.json",
        "scene.toml",
        "final.png",
        "energy.png",
        "force.png",
        "snapshots/t00000.png",
        "snapshots/t00000.json",
    ] {
        assert!(dir.join(f).is_file(), "missing {f}");
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    // Every ledger term of the table is a key of the summary and, with its unit, a column
    // of the series between the time and the two forces.
    let terms = &pressridge::energy::LEDGER_TERMS;
    for t in terms {
        assert!(summary[t.name].is_number(), "summary lacks {}", t.name);
    }
    for key in [
        "work_eq9",
        "ratio_work_to_pe",
        "ridged_volume",
        "steps",
        "dt",
        "wall_seconds",
        "seed",
        "blocks_broken",
        "rubble_block_lengths",
    ] {
        assert!(summary.get(key).is_some(), "summary lacks {key}");
    }
    let v = summary["ridged_volume"].as_f64().unwrap();
    assert!((v - 0.25 * 0.30 * 0.5).abs() < 1e-3, "ridged volume {v}");
    let csv = std::fs::read_to_string(dir.join("series.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    let columns: Vec<String> = std::iter::once("time [s]".to_string())
        .chain(terms.iter().map(|t| format!("{} [{}]", t.name, t.unit)))
        .chain(["ridging_force [N/m]".into(), "mean_force [N/m]".into()])
        .collect();
    assert_eq!(header, columns.join(","));
    // 0.5 s at 0.2 s intervals: t = 0, 0.2, 0.4 and the end.
    assert_eq!(csv.lines().count(), 1 + 4);
    let png = dir.join("again.png");
    let out = bin()
        .arg("render")
        .arg(dir.join("state.json"))
        .arg("--out")
        .arg(&png)
        .args(["--window", "-3,3,-2,3"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
}

#[test]
fn bad_input_gives_a_clear_error_and_nonzero_exit() {
    let out = bin()
        .args(["simulate", "--set", "contact.muu=1", "--out", "/tmp/never"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("muu"), "{err}");
    let out = bin()
        .args([
            "simulate",
            "--set",
            "sheet.thickness=-0.3",
            "--out",
            "/tmp/never",
        ])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("sheet.thickness"));
    let out = bin()
        .args(["render", "/nonexistent/state.json"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/state.json"));
}

/// The run summary says whether the intact sheet broke at the floe or rode over it
/// (`rafting::verdict`, whose words for a ride-over are tested beside it).
#[test]
fn the_summary_says_whether_the_sheet_rode_over_the_floe() {
    let dir = common::scratch("rideover");
    let run = |extra: &[&str]| {
        let o = bin()
            .args([
                "simulate",
                "--no-figures",
                "--overwrite",
                "--set",
                "duration=2",
            ])
            .args(extra)
            .arg("--out")
            .arg(&dir)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let broke = run(&[]);
    assert!(
        broke.contains("it broke at the floe (within the 2.87 m rafting reach)"),
        "{broke}"
    );
}

#[test]
fn simulate_svg_writes_svg_figures_beside_the_pngs() {
    let dir = common::simulate("cli-svg", &["--svg", "-q", "--set", "duration=0.5"]);
    for f in ["final", "energy", "force"] {
        assert!(dir.join(format!("{f}.png")).is_file(), "missing {f}.png");
        let svg = std::fs::read_to_string(dir.join(format!("{f}.svg"))).unwrap();
        assert!(
            svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
            "{f}.svg"
        );
    }
}
