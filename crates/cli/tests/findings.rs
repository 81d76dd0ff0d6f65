//! The statement table of the paper's findings (issue 30, `pressridge findings`) on the
//! committed records: it runs in seconds, names every item, and fails when the runs an item
//! needs are missing.

#[path = "../../../tests/common/mod.rs"]
mod common;

fn findings(args: &[&str]) -> std::process::Output {
    common::bin().arg("findings").args(args).output().unwrap()
}

/// The decided model's table: `pressridge findings` on the built-in Figure 5 scene. Until
/// its sets are run it stops naming the first point it lacks, and `docs/findings.md` says
/// the table does not exist yet; once they are, the page holds the command's output.
#[test]
fn the_decided_models_table_is_the_page_or_the_page_says_it_is_not_run() {
    let o = findings(&[]);
    if o.status.success() {
        check_table(&[], "docs/findings.md");
    } else {
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(
            e.contains("the Figure 5 scene at") && e.contains("runs,"),
            "{e}"
        );
        let page = std::fs::read_to_string(common::repo().join("docs/findings.md")).unwrap();
        assert!(page.contains("does not exist yet"), "docs/findings.md");
    }
}

/// The committed records of the paper campaign (`crates/lab/records/paper3`, model revision 1, all with
/// the 45° nose) give a row for every item of the paper's statements (a–g), each with a
/// verdict, and the count of verdicts; the table kept as a notes page is what the command
/// prints for that model.
#[test]
fn the_statement_table_is_made_from_the_committed_records() {
    check_table(
        &[
            "--records",
            "crates/lab/records/paper3",
            "--set",
            "floe.nose_slope=1",
            "--register",
            "crates/lab/records/choices40",
        ],
        "docs/notes/findings-revision1.md",
    );
}

/// The former model's table (k_te per thickness, the 20-m floe; crates/lab/records/paper) is kept as a
/// notes page and stays the command's output.
#[test]
fn the_former_models_table_is_made_from_its_records() {
    check_table(
        &[
            "--records",
            "crates/lab/records/paper",
            "--set",
            "floe.length=20",
            "--set",
            "floe.nose_slope=1",
        ],
        "docs/notes/findings-former-model.md",
    );
}

/// The table of the same model at the former default step, 0.8 of the stable limit
/// (`crates/lab/records/paper2`), is kept as a notes page and stays the command's output.
#[test]
fn the_table_at_the_former_step_is_made_from_its_records() {
    check_table(
        &[
            "--records",
            "crates/lab/records/paper2",
            "--set",
            "floe.nose_slope=1",
            "--register",
            "crates/lab/records/choices40",
        ],
        "docs/notes/findings-step08.md",
    );
}

/// The statement table with `args` has a row for every item with a verdict, and `page`
/// holds it.
fn check_table(args: &[&str], page: &str) {
    let o = findings(args);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for item in ["a", "b", "c1", "c2", "c3", "d1", "d2", "d3", "e", "f", "g"] {
        assert!(
            text.contains(&format!("\n| {item} |")),
            "item {item}:\n{text}"
        );
    }
    // The statement table ends with the line naming its runs; the evidence follows it.
    let table = text.split("\nFrom ").next().unwrap();
    let rows = table
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| item"))
        .count();
    let verdicts = ["| agree |", "| disagree |", "| unresolved |"];
    let judged = table
        .lines()
        .filter(|l| verdicts.iter().any(|v| l.ends_with(v)))
        .count();
    assert_eq!(rows, judged, "every row has a verdict");
    assert!(
        text.contains(" agree, ") && text.contains(" unresolved."),
        "{text}"
    );
    let committed = std::fs::read_to_string(common::repo().join(page)).unwrap();
    assert!(
        committed.contains(text.trim()),
        "{page} is not the output of `pressridge findings {}`: regenerate it",
        args.join(" ")
    );
}

/// Without the runs an item needs, the command fails and names the scene it looked for; a
/// bad `--set` fails naming the key.
#[test]
fn missing_records_fail_naming_the_scene() {
    let o = findings(&["--records", "crates/lab/records/paper/friction"]);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("μ = 1, μ_w = 0.6") && e.contains("0 runs, 7 needed"),
        "{e}"
    );
    let o = findings(&["--records", "data/no-such-dir"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--records data/no-such-dir"));
    // A variant of the model with a bad key or value is refused, naming it.
    for (set, says) in [
        ("floe.lenght=20", "unknown field `lenght`"),
        ("floe.length=-1", "`floe.length`: must be positive"),
    ] {
        let o = findings(&["--set", set]);
        assert!(!o.status.success());
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(e.contains("--set") && e.contains(says), "{set}: {e}");
    }
}

/// The table is read at the step its records were made with: runs of the Figure 5 point at
/// two steps (the step study's 0.5 and 0.8 of the stable limit) are refused, naming both and
/// the key that chooses one; with the key, the table looks for that step's runs.
#[test]
fn records_of_two_steps_are_refused_naming_them() {
    let (half, default) = (
        "crates/lab/records/speed-vs-error/decided-half",
        "crates/lab/records/speed-vs-error/decided-default",
    );
    // The 45° nose of their records.
    let both = [
        "--records",
        half,
        "--records",
        default,
        "--set",
        "floe.nose_slope=1",
    ];
    let o = findings(&both);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("2 steps (0.5 of the stable limit; 0.8 of the stable limit)")
            && e.contains("--set numerics.time_step_safety="),
        "{e}"
    );
    // One step chosen: its Figure 5 runs are found, and the friction points are missing.
    let step = [
        "--set",
        "numerics.time_step_safety=0.8",
        "--set",
        "numerics.refine_window=off",
        "--set",
        "numerics.refine_load=off",
        "--set",
        "numerics.refine_impact=off",
    ];
    let o = findings(&[&both[..], &step[..]].concat());
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("μ = 0.4") && e.contains("0 runs, 7 needed"),
        "{e}"
    );
}

/// The register's effect table (`--choices`) from the committed probe records: the
/// baseline's row and a row per probe setting at each friction pair, every probe difference
/// with its interval, and the paper's friction statements per setting (a probe's later seeds
/// pooled with its first), as `crates/lab/records/choices/register.md` holds it.
#[test]
fn the_register_is_made_from_the_committed_probe_records() {
    let text = committed_register("crates/lab/records/choices");
    for f in ["**μ = 0.4, μ_w = 0.6**", "**μ = 1, μ_w = 0.6**"] {
        assert!(text.contains(f), "{f}:\n{text}");
    }
    // The baseline's row at each friction pair, and in the table of the friction statements.
    assert_eq!(text.matches("| baseline (n = ").count(), 5, "{text}");
    assert!(text.contains("friction statements at μ_w = 0.6"), "{text}");
    assert!(text.contains("| floe.length=40.0 (n = 8, 8) |"), "{text}");
    for probe in ["tip_bevel_fraction=", "nose_bevel=", "viscous_length="] {
        assert!(text.contains(probe), "{probe}:\n{text}");
    }
}

/// `pressridge findings --choices DIR`'s table, checked to be what `DIR/register.md` holds.
fn committed_register(dir: &str) -> String {
    let o = findings(&["--choices", dir]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let committed =
        std::fs::read_to_string(common::repo().join(format!("{dir}/register.md"))).unwrap();
    assert!(
        committed.contains(text.trim()),
        "{dir}/register.md is not the command's output: regenerate it with \
         `pressridge findings --choices {dir} --out {dir}/register.md`"
    );
    text
}

/// The register's follow-up on the decided model (`crates/lab/records/choices40/`: eight seeds per probe
/// on the 40-m floe, the baseline taken from the friction set of `crates/lab/records/paper2/`) is the
/// command's output too.
#[test]
fn the_decided_models_register_is_made_from_its_committed_records() {
    let text = committed_register("crates/lab/records/choices40");
    assert_eq!(text.matches("| baseline (n = 12) |").count(), 4, "{text}");
    for probe in ["viscous_length=1.0 (n = 8)", "drag_coefficient=0.3 (n = 8)"] {
        assert!(text.contains(probe), "{probe}:\n{text}");
    }
}

/// The register of model revision 2 (`crates/lab/records/choices-r2/`: the drag moment on the body's own
/// outline; its baseline twelve seeds per friction pair) is the command's output, with a row
/// for each of its open options.
#[test]
fn the_revision_2_register_is_made_from_its_committed_records() {
    let text = committed_register("crates/lab/records/choices-r2");
    assert_eq!(text.matches("| baseline (n = 12) |").count(), 4, "{text}");
    for probe in [
        "crushing_pressure=1000000.0",
        "damping_law=\"contact\"",
        "nose_slope=0.36397",
        "nose_slope=0.57735",
        "shielding_contacts=2",
    ] {
        assert!(text.contains(probe), "{probe}:\n{text}");
    }
}

/// Under the table, each statement the model disagrees with gets the register's evidence: the
/// closest any open choice comes, from the committed probe records (`crates/lab/records/choices40`, read at
/// the step they were made with). A register of another model (`crates/lab/records/choices`, the 20-m
/// floe) gives no such section, and a missing one fails naming the option.
#[test]
fn the_disagreements_carry_the_registers_evidence() {
    // The register's model: revision 1 with the 45° nose, as its records and crates/lab/records/paper3's.
    let nose45 = [
        "--records",
        "crates/lab/records/paper3",
        "--set",
        "floe.nose_slope=1",
    ];
    let with_register = |dir: &str| findings(&[&nose45[..], &["--register", dir]].concat());
    let o = with_register("crates/lab/records/choices40");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    let (_, evidence) = text
        .split_once("the closest any open choice comes")
        .expect("an evidence section");
    for item in ["| a |", "| c1 |", "| e |"] {
        assert!(evidence.contains(item), "{item}:\n{evidence}");
    }
    assert!(evidence.contains("no choice meets it"), "{evidence}");
    // The register (made at 0.8 of the stable limit) is read at its own step under a table
    // of runs at half the limit, and the section says so.
    assert!(
        text.contains("were made at 0.8 of the stable limit, the table's above at 0.5"),
        "{text}"
    );
    assert!(!evidence.contains("floe.pin=false`:"), "{evidence}");
    let o = with_register("crates/lab/records/choices");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!String::from_utf8_lossy(&o.stdout).contains("closest any open choice"));
    let o = with_register("data/no-such-dir");
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--register"));
}
