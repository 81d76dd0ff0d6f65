//! `pressridge ridge-step --rates host` (the SIS2 calling convention: the host's closing and
//! opening rates read from the file) on every Icepack reference case that passes `closing`:
//! each case is written as a one-column NetCDF file (with its tracers, `Tf`, `hin_max`,
//! options), run through the command line, and the output equals the library's
//! `ridge_step_column` (which the C ABI equals, `crates/capi/tests/ridge_step.rs`) bit for bit; where
//! the library refuses the column, the command line fails with the same message (or, for
//! out-of-order category bounds, already when reading `hin_max`). Also the
//! errors of the option: rates in %/day or without units, a missing variable, options of the
//! other convention.

// Per-category and per-tracer tables are indexed by number, as in Icepack.
#![allow(
    clippy::needless_range_loop,
    clippy::type_complexity,
    clippy::field_reassign_with_default
)]

#[path = "../../../tests/common/mod.rs"]
mod common;

use std::path::Path;

use common::column::{Column, step};
use common::icepack::{num, nums};
use common::{bin, fails_with, global, read_values as read, scratch, succeeds};
use pressridge::itd::{
    RidgeStepOptions, StepForcing,
    details::{CELL_OUTPUTS, Closing, TracerLayout},
};

/// One case's inputs, as the command line gets them.
struct Case {
    name: String,
    ncat: usize,
    hin_max: Vec<f64>,
    aicen: Vec<f64>,
    vicen: Vec<f64>,
    vsnon: Vec<f64>,
    /// `trcrn[n * ntrcr + it]`.
    trcrn: Vec<f64>,
    aice0: f64,
    closing: f64,
    opening: f64,
    tf: f64,
    dt: f64,
    ndtd: u32,
    opts: RidgeStepOptions,
}

fn cases() -> (TracerLayout, Vec<Case>) {
    let (params, all) = common::icepack::read();
    let layout = common::icepack::layout(&params);
    let mut out = Vec::new();
    for c in &all {
        let i = &c["inputs"];
        if i["closing_in"].is_null() {
            continue;
        }
        let ncat = i["ncat"].as_u64().unwrap() as usize;
        let t = common::icepack::tracers(&i["trcrn"], &layout, ncat);
        let opts = common::icepack::options(i);
        out.push(Case {
            name: c["case"].as_str().unwrap().to_string(),
            ncat,
            hin_max: nums(&i["hin_max"]),
            aicen: nums(&i["aicen"]),
            vicen: nums(&i["vicen"]),
            vsnon: nums(&i["vsnon"]),
            trcrn: t,
            aice0: num(&i["aice0"]),
            closing: num(&i["closing_in"]),
            opening: num(&i["opening_in"]),
            tf: num(&i["Tf"]),
            dt: num(&i["dt"]),
            ndtd: i["ndtd"].as_u64().unwrap() as u32,
            opts,
        });
    }
    (layout, out)
}

/// Writes a case as a one-column file `aicen(nc, nj=1, ni=1)`; `rate_units`: the `units` of
/// `closing` and `opening` (None: no attribute).
fn write_case(path: &Path, c: &Case, layout: &TracerLayout, rate_units: Option<&str>) {
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _guard = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let nt = layout.ntrcr();
    let mut f = netcdf::create_with(path, netcdf::Options::_64BIT_OFFSET).unwrap();
    f.add_dimension("nc", c.ncat).unwrap();
    f.add_dimension("nj", 1).unwrap();
    f.add_dimension("ni", 1).unwrap();
    f.add_dimension("nb", c.ncat + 1).unwrap();
    let cat = ["nc", "nj", "ni"];
    let sp = ["nj", "ni"];
    let mut vars: Vec<(String, &[&str], Vec<f64>, Option<&str>)> = vec![
        ("aicen".into(), &cat, c.aicen.clone(), None),
        ("vicen".into(), &cat, c.vicen.clone(), None),
        ("vsnon".into(), &cat, c.vsnon.clone(), None),
        ("aice0".into(), &sp, vec![c.aice0], None),
        ("closing".into(), &sp, vec![c.closing], rate_units),
        ("opening".into(), &sp, vec![c.opening], rate_units),
        ("Tf".into(), &sp, vec![c.tf], Some("degC")),
        ("hin_max".into(), &["nb"], c.hin_max.clone(), Some("m")),
    ];
    for (it, name) in layout.cice_restart_names().into_iter().enumerate() {
        let v = (0..c.ncat).map(|n| c.trcrn[n * nt + it]).collect();
        vars.push((name, &cat, v, None));
    }
    for (name, dims, _, units) in &vars {
        let mut v = f.add_variable::<f64>(name, dims).unwrap();
        if let Some(u) = units {
            v.put_attribute("units", *u).unwrap();
        }
    }
    f.enddef().unwrap();
    for (name, _, data, _) in &vars {
        f.variable_mut(name).unwrap().put_values(data, ..).unwrap();
    }
    f.close().unwrap();
}

/// The command line of a case.
fn command(c: &Case, input: &Path, output: &Path) -> std::process::Command {
    let mut cmd = bin();
    cmd.args(["ridge-step", "--rates", "host", "--input"])
        .arg(input)
        .arg("--output")
        .arg(output)
        .args(["--dt", &format!("{:e}", c.dt)])
        .args(["--ndtd", &c.ndtd.to_string()])
        .args(["--participation", c.opts.participation.name()])
        .args(["--redistribution", c.opts.redistribution.name()])
        .args(["--param", &format!("mu_rdg={:e}", c.opts.params.mu_rdg)]);
    if !c.opts.cleanup {
        cmd.arg("--no-cleanup");
    }
    if !c.opts.rebin {
        cmd.arg("--no-rebin");
    }
    cmd
}

#[test]
fn host_rates_on_the_reference_cases_equal_the_library_bit_for_bit() {
    let dir = scratch("ridge-step-host-rates");
    let (layout, cases) = cases();
    assert!(cases.len() >= 4, "the reference file has SIS2 cases");
    let nt = layout.ntrcr();
    let names = layout.cice_restart_names();
    let (mut stepped, mut refused) = (0, 0);
    for c in &cases {
        let (inp, out) = (
            dir.join(format!("{}.nc", c.name)),
            dir.join(format!("{}-out.nc", c.name)),
        );
        write_case(&inp, c, &layout, Some("s-1"));
        let r = command(c, &inp, &out).output().unwrap();
        // The library on the same column.
        let col = Column::new(
            c.aicen.clone(),
            c.vicen.clone(),
            c.vsnon.clone(),
            c.trcrn.clone(),
            c.aice0,
        );
        let forcing = StepForcing {
            closing: Closing::Rates {
                closing: c.closing,
                opening: c.opening,
            },
            dt: c.dt,
            ndtd: c.ndtd,
            tf: c.tf,
        };
        let lib = step(&col, &c.hin_max, forcing, &c.opts, &layout);
        let (a, v, s, t, a0) = (
            lib.col.aicen,
            lib.col.vicen,
            lib.col.vsnon,
            lib.col.trcrn,
            lib.col.aice0,
        );
        let (fl, ws) = (lib.fluxes, lib.ws);
        let d = match lib.result {
            Ok(d) => d,
            Err(e) => {
                // The command line refuses the column with the library's message, or
                // earlier, the file's out-of-order category bounds (its reader checks them).
                let msg = e.to_string();
                if c.hin_max.windows(2).all(|w| w[0] < w[1]) {
                    fails_with(&r, &[&msg, "column 0"]);
                } else {
                    fails_with(&r, &["hin_max", "not strictly increasing"]);
                }
                refused += 1;
                continue;
            }
        };
        succeeds(&r);
        stepped += 1;
        let bits = |x: &[f64]| x.iter().map(|y| y.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&read(&out, "aicen")), bits(&a), "{}: aicen", c.name);
        assert_eq!(bits(&read(&out, "vicen")), bits(&v), "{}: vicen", c.name);
        assert_eq!(bits(&read(&out, "vsnon")), bits(&s), "{}: vsnon", c.name);
        for (it, name) in names.iter().enumerate() {
            let want: Vec<f64> = (0..c.ncat).map(|n| t[n * nt + it]).collect();
            assert_eq!(bits(&read(&out, name)), bits(&want), "{}: {name}", c.name);
        }
        assert_eq!(read(&out, "aice0")[0].to_bits(), a0.to_bits(), "{}", c.name);
        for (name, want) in [
            ("fresh", fl.fresh),
            ("fsalt", fl.fsalt),
            ("fhocn", fl.fhocn),
            ("fpond", fl.fpond),
            ("dpnd_ridge", fl.dpnd_ridge),
            ("closing", d.closing),
            ("opening", d.opening),
            ("dardg1dt", d.dardg1dt),
            ("dardg2dt", d.dardg2dt),
            ("dvirdgdt", d.dvirdgdt),
        ] {
            assert!(CELL_OUTPUTS.iter().any(|m| m.name == name));
            assert_eq!(
                read(&out, name)[0].to_bits(),
                want.to_bits(),
                "{}: {name}",
                c.name
            );
        }
        assert_eq!(bits(&read(&out, "krdgn")), bits(&ws.krdgn), "{}", c.name);
        // The category bounds are the host's, written as given.
        assert_eq!(bits(&read(&out, "hin_max")), bits(&c.hin_max), "{}", c.name);
        assert!(global(&out, "rates").starts_with("host"));
        assert_eq!(
            global(&out, "closing_rate"),
            "input variable `closing` (s-1)"
        );
        assert_eq!(global(&out, "tf"), "input variable `Tf` (degC)");
        assert_eq!(read(&out, "Tf"), vec![c.tf]);
    }
    assert!(stepped >= 2, "{stepped} cases stepped, {refused} refused");
}

#[test]
fn host_rates_in_other_units_or_missing_are_refused_by_name() {
    let dir = scratch("ridge-step-host-rates-errors");
    let (layout, cases) = cases();
    let c = &cases[0];
    let out = dir.join("out.nc");
    // %/day is never taken for 1/s.
    let p = dir.join("pct.nc");
    write_case(&p, c, &layout, Some("%/day"));
    fails_with(
        &command(c, &p, &out).output().unwrap(),
        &["closing", "%/day", "s-1"],
    );
    // No units: refused, not assumed.
    let p = dir.join("nounits.nc");
    write_case(&p, c, &layout, None);
    fails_with(
        &command(c, &p, &out).output().unwrap(),
        &["closing", "no `units`", "s-1"],
    );
    // A variable that is not there, named with its option.
    let p = dir.join("ok.nc");
    write_case(&p, c, &layout, Some("1/s"));
    fails_with(
        &command(c, &p, &out)
            .args(["--closing-var", "host_closing"])
            .output()
            .unwrap(),
        &["host_closing", "--closing-var"],
    );
    // The deformation options belong to the other convention, and the reverse.
    fails_with(
        &command(c, &p, &out)
            .args(["--convergence", "1e-6"])
            .output()
            .unwrap(),
        &["--convergence", "--rates deformation"],
    );
    fails_with(
        &bin()
            .args(["ridge-step", "--input"])
            .arg(&p)
            .arg("--output")
            .arg(&out)
            .args(["--dt", "3600", "--opening-var", "opening"])
            .output()
            .unwrap(),
        &["--opening-var", "--rates host"],
    );
    assert!(!out.exists(), "no output after an error");
}

/// Without snow or tracers in the file, the host's rates still ridge area and volume (the
/// complete step on zero snow and tracers, as Python's `ridge_step(closing=...)`), and the
/// output holds no snow or tracer variables, so that it is a valid input again.
#[test]
fn host_rates_without_tracers_ridge_area_and_volume() {
    let dir = scratch("ridge-step-host-rates-no-tracers");
    let (layout, cases) = cases();
    let c = cases.iter().find(|c| c.opts.cleanup).unwrap();
    let p = dir.join("in.nc");
    write_case(&p, c, &layout, Some("s-1"));
    // Drop snow and tracers: rewrite only area, volume and the forcing.
    let q = dir.join("bare.nc");
    {
        let src = netcdf::open(&p).unwrap();
        let mut f = netcdf::create_with(&q, netcdf::Options::_64BIT_OFFSET).unwrap();
        for d in src.dimensions() {
            f.add_dimension(&d.name(), d.len()).unwrap();
        }
        let keep = ["aicen", "vicen", "aice0", "closing", "opening", "hin_max"];
        for name in keep {
            let v = src.variable(name).unwrap();
            let dims: Vec<String> = v.dimensions().iter().map(|d| d.name()).collect();
            let dims: Vec<&str> = dims.iter().map(|s| s.as_str()).collect();
            let mut w = f.add_variable::<f64>(name, &dims).unwrap();
            if matches!(name, "closing" | "opening") {
                w.put_attribute("units", "s-1").unwrap();
            }
        }
        f.enddef().unwrap();
        for name in keep {
            let data = src
                .variable(name)
                .unwrap()
                .get_values::<f64, _>(..)
                .unwrap();
            f.variable_mut(name).unwrap().put_values(&data, ..).unwrap();
        }
        f.close().unwrap();
    }
    let out = dir.join("out.nc");
    let r = bin()
        .args(["ridge-step", "--rates", "host", "--input"])
        .arg(&q)
        .arg("--output")
        .arg(&out)
        .args(["--dt", &format!("{:e}", c.dt)])
        .output()
        .unwrap();
    succeeds(&r);
    let a = read(&out, "aicen");
    let a0 = read(&out, "aice0")[0];
    assert!((a.iter().sum::<f64>() + a0 - 1.0).abs() < 1e-12);
    assert!(read(&out, "dardg1dt")[0] > 0.0);
    let f = netcdf::open(&out).unwrap();
    assert!(f.variable("vsnon").is_none() && f.variable("Tsfcn").is_none());
    assert!(global(&out, "tf").contains("default"));
}
