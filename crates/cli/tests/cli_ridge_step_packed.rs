//! `pressridge ridge-step --tracer-layout` on tracers packed in one array as Icepack's column
//! driver writes its history, `trcrn(time, ncat, ntrcr, ni)` beside `aicen(time, ncat, ni)`:
//! the step equals, bit for bit, the same columns given one variable per tracer under CICE
//! restart names; the output holds `trcrn` again in the input's dimensions; the `ni`
//! coordinate stays `int`; bad layouts and shapes are refused by name; the column driver's
//! biogeochemical tracers ride along and book `flux_bio`.

// Per-category tables are indexed by number, as in Icepack.
#![allow(clippy::needless_range_loop)]

#[path = "../../../tests/common/mod.rs"]
mod common;

use std::path::Path;

use common::{Data, Var, bin, fails_with, global, read_values, scratch, succeeds, write_nc};
use pressridge::itd::details::{CiceLayoutSpec, TracerLayout};

const NCAT: usize = 3;
const NI: usize = 4;
const SPEC: &str = "nilyr=2,nslyr=1,tr_iage,tr_FY,tr_lvl,tr_pond_lvl,tr_snow,tr_iso,n_iso=1,\
                    tr_aero,n_aero=1";

fn layout() -> TracerLayout {
    SPEC.parse::<CiceLayoutSpec>().unwrap().layout().unwrap()
}

/// Per tracer `it`, category `n`, column `c`: a value its role allows.
fn tracer(l: &TracerLayout, it: usize, n: usize, c: usize) -> f64 {
    let (f, k) = l.field_of(it).unwrap();
    match f.name.as_str() {
        "Tsfc" => -8.0 - c as f64,
        "qice" => -3.1e8 - 1e7 * k as f64 - 1e6 * n as f64,
        "qsno" => -1.12e8,
        "sice" => 4.0 + k as f64,
        "iage" => 2e7 * (n + 1) as f64,
        "hpnd" | "ipnd" => 0.05 * (c + 1) as f64,
        "rhos" => 330.0,
        "rsnw" => 1e-4,
        _ => 0.2 + 0.1 * n as f64 + 0.01 * c as f64,
    }
}

/// The distribution on (time = 1, ncat, ni): aicen, vicen, vsnon in C order.
fn itd() -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let h = [0.3, 1.1, 2.5];
    let mut a = vec![0.0; NCAT * NI];
    let mut v = a.clone();
    let mut s = a.clone();
    for n in 0..NCAT {
        for c in 0..NI {
            let i = n * NI + c;
            a[i] = 0.15 + 0.08 * ((n + c) % 3) as f64;
            v[i] = a[i] * h[n] * (1.0 + 0.03 * c as f64);
            s[i] = a[i] * 0.04 * (n + 1) as f64;
        }
    }
    (a, v, s)
}

/// The common variables: the distribution, `ni` as int, divergence in CICE's %/day.
fn base_vars() -> Vec<Var> {
    let (a, v, s) = itd();
    let cat = [("time", 1), ("ncat", NCAT), ("ni", NI)];
    vec![
        Var::f64("aicen", &cat, a),
        Var::f64("vicen", &cat, v),
        Var::f64("vsnon", &cat, s),
        Var::f64(
            "divu",
            &[("time", 1), ("ni", NI)],
            vec![-5.0, -2.0, -9.0, 0.5],
        )
        .with_units("%/day"),
        Var {
            name: "ni".into(),
            dims: vec![("ni".into(), NI)],
            data: Data::I32((1..=NI as i32).collect()),
            units: None,
        },
    ]
}

/// Writes the packed file (icedrv's dimension order) and the one with restart names.
fn write_inputs(packed: &Path, named: &Path) {
    let l = write_packed(packed, SPEC);
    let mut vars = base_vars();
    for (it, name) in l.cice_restart_names().iter().enumerate() {
        let x: Vec<f64> = (0..NCAT)
            .flat_map(|n| (0..NI).map(move |c| (n, c)))
            .map(|(n, c)| tracer(&l, it, n, c))
            .collect();
        vars.push(Var::f64(
            name,
            &[("time", 1), ("ncat", NCAT), ("ni", NI)],
            x,
        ));
    }
    write_nc(named, &vars);
}

fn dims_of(path: &Path, name: &str) -> Vec<(String, usize)> {
    let f = netcdf::open(path).unwrap();
    let v = f.variable(name).unwrap();
    v.dimensions().iter().map(|d| (d.name(), d.len())).collect()
}

fn step(input: &Path, output: &Path, extra: &[&str]) -> std::process::Output {
    bin()
        .args(["ridge-step", "--input"])
        .arg(input)
        .arg("--output")
        .arg(output)
        .args(["--dt", "3600"])
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn packed_tracers_step_as_the_named_ones_and_come_back_packed() {
    let dir = scratch("ridge-step-packed");
    let (packed, named) = (dir.join("packed.nc"), dir.join("named.nc"));
    write_inputs(&packed, &named);
    let (out_p, out_n) = (dir.join("out_packed.nc"), dir.join("out_named.nc"));
    succeeds(&step(&packed, &out_p, &["--tracer-layout", SPEC]));
    succeeds(&step(&named, &out_n, &[]));
    let l = layout();
    let nt = l.ntrcr();
    // Every field the step writes, but the tracers, is the same bits.
    for name in [
        "aicen",
        "vicen",
        "vsnon",
        "aice0",
        "aice",
        "fresh",
        "fhocn",
        "fsalt",
        "fpond",
        "dardg1dt",
        "faero_ocn001",
        "fiso_ocn001",
    ] {
        let (p, n) = (read_values(&out_p, name), read_values(&out_n, name));
        assert_eq!(p.len(), n.len(), "{name}");
        for (x, y) in p.iter().zip(&n) {
            assert_eq!(x.to_bits(), y.to_bits(), "{name}");
        }
    }
    assert!(
        read_values(&out_n, "dardg1dt").iter().any(|x| *x > 0.0),
        "the columns ridge"
    );
    // The packed tracers, in the input's dimensions, equal the named ones.
    assert_eq!(
        dims_of(&out_p, "trcrn"),
        dims_of(&packed, "trcrn"),
        "trcrn keeps its dimensions"
    );
    let t = read_values(&out_p, "trcrn");
    for (it, name) in l.cice_restart_names().iter().enumerate() {
        let want = read_values(&out_n, name);
        for n in 0..NCAT {
            for c in 0..NI {
                let got = t[(n * nt + it) * NI + c];
                assert_eq!(
                    got.to_bits(),
                    want[n * NI + c].to_bits(),
                    "{name} cat {n} col {c}"
                );
            }
        }
    }
    // No restart-name variables in the packed output; the layout is said.
    let f = netcdf::open(&out_p).unwrap();
    assert!(f.variable("qice001").is_none());
    assert!(
        global(&out_p, "tracer_layout").starts_with(SPEC),
        "the canonical text"
    );
    let ni = f.variable("ni").unwrap();
    assert_eq!(
        ni.vartype(),
        netcdf::types::NcVariableType::Int(netcdf::types::IntType::I32)
    );
    drop(f);
    // The output is an input again (chained steps).
    let out2 = dir.join("out2.nc");
    succeeds(&step(
        &out_p,
        &out2,
        &["--tracer-layout", SPEC, "--convergence", "1e-6"],
    ));
    // The preset of Icepack's column driver reads its 21 tracers.
    let mut vars = base_vars();
    vars.push(Var::f64(
        "trcrn",
        &[("time", 1), ("ncat", NCAT), ("ntrcr", 21), ("ni", NI)],
        (0..NCAT * 21 * NI)
            .map(|i| {
                let it = (i / NI) % 21;
                let l = "icedrv"
                    .parse::<CiceLayoutSpec>()
                    .unwrap()
                    .layout()
                    .unwrap();
                tracer(&l, it, i / (21 * NI), i % NI)
            })
            .collect(),
    ));
    let icedrv = dir.join("icedrv.nc");
    write_nc(&icedrv, &vars);
    succeeds(&step(
        &icedrv,
        &dir.join("icedrv_out.nc"),
        &["--tracer-layout", "icedrv"],
    ));
}

#[test]
fn bad_layouts_and_shapes_are_named() {
    let dir = scratch("ridge-step-packed-bad");
    let (packed, named) = (dir.join("packed.nc"), dir.join("named.nc"));
    write_inputs(&packed, &named);
    let out = dir.join("out.nc");
    // A packed array with no layout: the way to name it.
    fails_with(
        &step(&packed, &out, &[]),
        &["trcrn", "--tracer-layout", "icedrv"],
    );
    // A layout of another tracer count: both counts and the layout's names.
    fails_with(
        &step(&packed, &out, &["--tracer-layout", "icedrv"]),
        &["trcrn", "ntrcr", "21", "holds", "Tsfcn"],
    );
    fails_with(
        &step(&packed, &out, &["--tracer-layout", "nilyr=2,tr_iage"]),
        &["--tracer-layout", "nslyr"],
    );
    fails_with(
        &step(&packed, &out, &["--tracer-layout", "icedrv,tr_aero"]),
        &["tr_aero", "n_aero"],
    );
    fails_with(
        &step(&named, &out, &["--tracer-layout", SPEC]),
        &["no packed tracer variable `trcrn`"],
    );
    fails_with(
        &step(&named, &out, &["--tracer-var", "trcrn"]),
        &["--tracer-var needs --tracer-layout"],
    );
    fails_with(
        &step(
            &packed,
            &out,
            &["--tracer-layout", SPEC, "--tracer-var", "vsnon"],
        ),
        &["vsnon", "one tracer dimension"],
    );
    assert!(!out.exists(), "no output from a refused step");
}

/// A layout with the column driver's vertical biogeochemistry (nitrate and one z-aerosol on
/// `nblyr = 2`) after the physical tracers of `PHYSICAL`.
const PHYSICAL: &str = "nilyr=2,nslyr=1,tr_lvl,tr_pond_lvl,tr_brine";
const WITH_BGC: &str = "nilyr=2,nslyr=1,tr_lvl,tr_pond_lvl,tr_brine,z_tracers,nblyr=2,\
                        tr_bgc_Nit,tr_zaero,n_zaero=1";

/// The packed file of `spec`'s layout.
fn write_packed(path: &Path, spec: &str) -> TracerLayout {
    let l = spec.parse::<CiceLayoutSpec>().unwrap().layout().unwrap();
    let nt = l.ntrcr();
    let mut t = vec![0.0; NCAT * nt * NI];
    for n in 0..NCAT {
        for it in 0..nt {
            for c in 0..NI {
                t[(n * nt + it) * NI + c] = tracer(&l, it, n, c);
            }
        }
    }
    let mut vars = base_vars();
    vars.push(Var::f64(
        "trcrn",
        &[("time", 1), ("ncat", NCAT), ("ntrcr", nt), ("ni", NI)],
        t,
    ));
    write_nc(path, &vars);
    l
}

#[test]
fn biogeochemical_tracers_ride_along_and_book_their_flux() {
    let dir = scratch("ridge-step-packed-bgc");
    let (phys, bgc) = (dir.join("phys.nc"), dir.join("bgc.nc"));
    let lp = write_packed(&phys, PHYSICAL);
    let lb = write_packed(&bgc, WITH_BGC);
    // 12 physical tracers with fbri; 2 bio tracers of 5 levels and their 2 zbgc_frac.
    assert_eq!((lp.ntrcr(), lb.ntrcr(), lb.n_bio()), (12, 24, 2));
    let (out_p, out_b) = (dir.join("out_phys.nc"), dir.join("out_bgc.nc"));
    succeeds(&step(&phys, &out_p, &["--tracer-layout", PHYSICAL]));
    succeeds(&step(&bgc, &out_b, &["--tracer-layout", WITH_BGC]));
    // The bio tracers do not act on the ice: the state and fluxes are the same bits.
    for name in [
        "aicen", "vicen", "vsnon", "aice0", "fresh", "fhocn", "fsalt", "dardg1dt",
    ] {
        let (p, b) = (read_values(&out_p, name), read_values(&out_b, name));
        assert!(
            p.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()),
            "{name}"
        );
    }
    let (tp, tb) = (read_values(&out_p, "trcrn"), read_values(&out_b, "trcrn"));
    let (np, nb) = (lp.ntrcr(), lb.ntrcr());
    for n in 0..NCAT {
        for it in 0..np {
            for c in 0..NI {
                assert_eq!(
                    tp[(n * np + it) * NI + c].to_bits(),
                    tb[(n * nb + it) * NI + c].to_bits(),
                    "tracer {it} cat {n} col {c}"
                );
            }
        }
    }
    // One flux per bio tracer, in the tracer's unit times m/s: ridging puts snow, and the
    // bio tracers in it, into the ocean.
    for k in 1..=2 {
        let f = read_values(&out_b, &format!("flux_bio{k:03}"));
        assert_eq!(f.len(), NI);
        assert!(f.iter().all(|x| x.is_finite() && *x >= 0.0), "{f:?}");
        assert!(f.iter().any(|x| *x > 0.0), "flux_bio{k:03}: {f:?}");
    }
    assert!(
        netcdf::open(&out_p)
            .unwrap()
            .variable("flux_bio001")
            .is_none()
    );
    assert!(global(&out_b, "tracer_layout").starts_with(WITH_BGC));
    // Without the bio switches, the count says what is missing.
    fails_with(
        &step(&bgc, &dir.join("no.nc"), &["--tracer-layout", PHYSICAL]),
        &["holds 24 tracers", "has 12", "z_tracers"],
    );
}
