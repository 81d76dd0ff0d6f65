//! `pressridge ridge-step` with snow and tracers (the complete step): a NetCDF file with
//! `vsnon` and the CICE restart tracer variables round-trips through the command line, equals
//! the library's `ridge_step_column` on the same columns bit for bit, conserves ice, snow
//! and enthalpy with the ocean fluxes, and keeps `_FillValue` land columns missing.

// Per-category, per-tracer and per-column tables are indexed by number, as in Icepack.
#![allow(
    clippy::needless_range_loop,
    clippy::type_complexity,
    clippy::field_reassign_with_default
)]

#[path = "../../../tests/common/mod.rs"]
mod common;

use std::path::Path;

use common::column::{Column, Stepped, step};
use common::{bin, fails_with, fill_value, global, read_values, scratch, succeeds};
use pressridge::itd::{
    RidgeStepOptions, StepForcing,
    details::{CATEGORY_OUTPUTS, CELL_OUTPUTS, CiceTracerFlags, Closing, TracerLayout},
};

const NCAT: usize = 3;
const NJ: usize = 2;
const NI: usize = 3;
const NCOL: usize = NJ * NI;
const FILL: f64 = 1e30;
/// The land column (flat C-order index of (nj = 1, ni = 2)).
const LAND: usize = 5;
const DT: f64 = 3600.0;

/// Every CICE tracer group, with two isotope and two aerosol species.
fn layout() -> TracerLayout {
    let flags = CiceTracerFlags {
        snow: true,
        isotopes: 2,
        aerosols: 2,
        ..CiceTracerFlags::ALL
    };
    TracerLayout::cice(2, 1, flags).unwrap()
}

/// Inputs: per variable, values in C order over (nc, nj, ni) or (nj, ni).
struct Input {
    aicen: Vec<f64>,
    vicen: Vec<f64>,
    vsnon: Vec<f64>,
    /// trcrn[it][n * NCOL + c]
    trcrn: Vec<Vec<f64>>,
    aice0: Vec<f64>,
    divu: Vec<f64>,
    shear: Vec<f64>,
    hin_max: Vec<f64>,
}

fn input() -> Input {
    let l = layout();
    let nt = l.ntrcr();
    let mut aicen = vec![0.0; NCAT * NCOL];
    let mut vicen = vec![0.0; NCAT * NCOL];
    let mut vsnon = vec![0.0; NCAT * NCOL];
    let mut trcrn = vec![vec![0.0; NCAT * NCOL]; nt];
    let mut aice0 = vec![0.0; NCOL];
    let h = [0.4, 1.0, 2.2];
    for c in 0..NCOL {
        let mut sum = 0.0;
        for n in 0..NCAT {
            let i = n * NCOL + c;
            let a = 0.1 + 0.07 * ((n + 2 * c) % 5) as f64;
            aicen[i] = a;
            sum += a;
            vicen[i] = a * h[n] * (1.0 + 0.05 * c as f64);
            vsnon[i] = a * 0.05 * (n + 1) as f64;
            for it in 0..nt {
                let (f, k) = l.field_of(it).unwrap();
                trcrn[it][i] = match f.name.as_str() {
                    "Tsfc" => -10.0 - c as f64,
                    "qice" => -3.0e8 - 1e7 * k as f64 - 1e6 * n as f64,
                    "qsno" => -1.15e8,
                    "sice" => 4.0 + k as f64,
                    "iage" => 1e7 * (n + 1) as f64,
                    "hpnd" | "ipnd" => 0.1,
                    _ => 0.3 + 0.1 * n as f64,
                };
            }
        }
        aice0[c] = 1.0 - sum;
    }
    let mut divu = (0..NCOL)
        .map(|c| -1e-6 * (c + 1) as f64)
        .collect::<Vec<_>>();
    let shear = (0..NCOL).map(|c| 5e-7 * c as f64).collect::<Vec<_>>();
    // Land: every value missing.
    for v in [&mut aicen, &mut vicen, &mut vsnon] {
        for n in 0..NCAT {
            v[n * NCOL + LAND] = FILL;
        }
    }
    for t in trcrn.iter_mut() {
        for n in 0..NCAT {
            t[n * NCOL + LAND] = FILL;
        }
    }
    aice0[LAND] = FILL;
    divu[LAND] = FILL;
    Input {
        aicen,
        vicen,
        vsnon,
        trcrn,
        aice0,
        divu,
        shear,
        hin_max: vec![0.0, 0.6, 1.4, 2.4],
    }
}

/// Writes the input file; `skip` names tracer variables to leave out.
fn write_input(path: &Path, inp: &Input, skip: &[&str]) {
    write_input_with(path, inp, skip, &[]);
}

/// A variable on the column dimensions (nj, ni): name, values, units.
type CellVar<'a> = (&'a str, &'a [f64], Option<&'a str>);

/// [`write_input`] with `extra` variables on the column dimensions.
fn write_input_with(path: &Path, inp: &Input, skip: &[&str], extra: &[CellVar<'_>]) {
    // One writer at a time: the tests run on several threads, the NetCDF library is not
    // thread-safe.
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _guard = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let l = layout();
    let mut f = netcdf::create_with(path, netcdf::Options::_64BIT_OFFSET).unwrap();
    f.add_dimension("nc", NCAT).unwrap();
    f.add_dimension("nj", NJ).unwrap();
    f.add_dimension("ni", NI).unwrap();
    f.add_dimension("nb", NCAT + 1).unwrap();
    let cat = ["nc", "nj", "ni"];
    let sp = ["nj", "ni"];
    let names = l.cice_restart_names();
    let mut vars: Vec<(String, Vec<&str>, &[f64], Option<&str>)> = vec![
        ("aicen".into(), cat.to_vec(), &inp.aicen, None),
        ("vicen".into(), cat.to_vec(), &inp.vicen, None),
        ("vsnon".into(), cat.to_vec(), &inp.vsnon, None),
        ("aice0".into(), sp.to_vec(), &inp.aice0, None),
        ("divu".into(), sp.to_vec(), &inp.divu, Some("s-1")),
        ("shear".into(), sp.to_vec(), &inp.shear, Some("s-1")),
    ];
    for (name, data, units) in extra {
        vars.push((name.to_string(), sp.to_vec(), data, *units));
    }
    for (name, t) in names.iter().zip(&inp.trcrn) {
        if !skip.contains(&name.as_str()) {
            vars.push((name.clone(), cat.to_vec(), t, None));
        }
    }
    for (name, dims, _, units) in &vars {
        let mut v = f.add_variable::<f64>(name, dims).unwrap();
        v.put_attribute("_FillValue", FILL).unwrap();
        if let Some(u) = units {
            v.put_attribute("units", *u).unwrap();
        }
    }
    f.add_variable::<f64>("hin_max", &["nb"]).unwrap();
    f.enddef().unwrap();
    for (name, _, data, _) in &vars {
        f.variable_mut(name).unwrap().put_values(data, ..).unwrap();
    }
    f.variable_mut("hin_max")
        .unwrap()
        .put_values(&inp.hin_max, ..)
        .unwrap();
    f.close().unwrap();
}

fn read(path: &Path, name: &str) -> Vec<f64> {
    assert_eq!(fill_value(path, name), Some(FILL), "{name}: _FillValue");
    read_values(path, name)
}

/// The library's step of column `c` of the input, closing by its divergence and shear, with
/// `ndtd` subcycles and freezing temperature `tf`: the column before the step, and the step.
fn library(
    inp: &Input,
    c: usize,
    ndtd: u32,
    tf: f64,
    opts: &RidgeStepOptions,
) -> (Column, Stepped) {
    let col = Column::gather(
        NCOL, c, &inp.aicen, &inp.vicen, &inp.vsnon, &inp.trcrn, &inp.aice0,
    );
    let forcing = StepForcing {
        closing: Closing::Deformation {
            convergence: f64::max(-inp.divu[c], 0.0),
            shear: inp.shear[c],
        },
        dt: DT,
        ndtd,
        tf,
    };
    let r = step(&col, &inp.hin_max, forcing, opts, &layout());
    (col, r)
}

fn units(path: &Path, name: &str) -> String {
    let f = netcdf::open(path).unwrap();
    let v = f.variable(name).unwrap();
    v.attributes()
        .find(|a| a.name() == "units")
        .and_then(|a| a.value().ok())
        .and_then(|x| String::try_from(x).ok())
        .unwrap_or_default()
}

#[test]
fn snow_and_tracers_round_trip_equal_the_library_and_conserve() {
    let dir = scratch("ridge-step-complete");
    let (inp_path, out) = (dir.join("in.nc"), dir.join("out.nc"));
    let inp = input();
    write_input(&inp_path, &inp, &[]);
    succeeds(
        &bin()
            .args(["ridge-step", "--input"])
            .arg(&inp_path)
            .arg("--output")
            .arg(&out)
            .args(["--dt", "3600", "--ndtd", "2"])
            .output()
            .unwrap(),
    );
    let l = layout();
    let nt = l.ntrcr();
    let names = l.cice_restart_names();
    let got_a = read(&out, "aicen");
    let got_v = read(&out, "vicen");
    let got_s = read(&out, "vsnon");
    let got_t: Vec<Vec<f64>> = names.iter().map(|n| read(&out, n)).collect();
    let got_a0 = read(&out, "aice0");
    let cell: Vec<Vec<f64>> = CELL_OUTPUTS.iter().map(|m| read(&out, m.name)).collect();
    let cats: Vec<Vec<f64>> = CATEGORY_OUTPUTS
        .iter()
        .map(|m| read(&out, m.name))
        .collect();
    let cell_of =
        |name: &str, c: usize| cell[CELL_OUTPUTS.iter().position(|m| m.name == name).unwrap()][c];
    assert_eq!(units(&out, "fhocn"), "W m-2");
    assert_eq!(units(&out, "fresh"), "kg m-2 s-1");
    assert_eq!(units(&out, "qice001"), "J m-3");
    assert_eq!(units(&out, "Tsfcn"), "degC");
    let opts = RidgeStepOptions::default();
    let rhoi = opts.params.rhoi;
    let rhos = opts.step.rhos;
    for c in 0..NCOL {
        if c == LAND {
            // Land stays missing in every gridded output.
            for n in 0..NCAT {
                let i = n * NCOL + c;
                assert_eq!(got_a[i], FILL);
                assert_eq!(got_s[i], FILL);
                assert!(got_t.iter().all(|t| t[i] == FILL));
                assert!(cats.iter().all(|x| x[i] == FILL));
            }
            assert_eq!(got_a0[c], FILL);
            assert!(cell.iter().all(|x| x[c] == FILL));
            continue;
        }
        // The library on the same column.
        let (col, r) = library(&inp, c, 2, -1.8, &opts);
        let d = r.result.unwrap();
        let (a, v, s, t, a0) = (
            r.col.aicen,
            r.col.vicen,
            r.col.vsnon,
            r.col.trcrn,
            r.col.aice0,
        );
        let (fl, ws) = (r.fluxes, r.ws);
        let (v_in, s_in, t_in) = (col.vicen, col.vsnon, col.trcrn);
        assert!(d.dardg1dt > 0.0, "column {c} ridges");
        for n in 0..NCAT {
            let i = n * NCOL + c;
            assert_eq!(got_a[i].to_bits(), a[n].to_bits(), "aicen col {c} cat {n}");
            assert_eq!(got_v[i].to_bits(), v[n].to_bits(), "vicen col {c} cat {n}");
            assert_eq!(got_s[i].to_bits(), s[n].to_bits(), "vsnon col {c} cat {n}");
            for it in 0..nt {
                assert_eq!(
                    got_t[it][i].to_bits(),
                    t[n * nt + it].to_bits(),
                    "{} col {c} cat {n}",
                    names[it]
                );
            }
            assert_eq!(cats[0][i], ws.dardg1ndt[n]);
            assert_eq!(cats[4][i], ws.krdgn[n]);
        }
        assert_eq!(got_a0[c].to_bits(), a0.to_bits());
        // Aerosol and isotope fluxes, one variable per species.
        for (name, want) in [
            ("faero_ocn001", fl.faero_ocn[0]),
            ("faero_ocn002", fl.faero_ocn[1]),
            ("fiso_ocn001", fl.fiso_ocn[0]),
            ("fiso_ocn002", fl.fiso_ocn[1]),
        ] {
            assert_eq!(
                read(&out, name)[c].to_bits(),
                want.to_bits(),
                "{name} col {c}"
            );
            assert!(want > 0.0, "{name}: ridged snow takes some into the ocean");
        }
        for (name, want) in [
            ("fresh", fl.fresh),
            ("fsalt", fl.fsalt),
            ("fhocn", fl.fhocn),
            ("fpond", fl.fpond),
            ("dpnd_ridge", fl.dpnd_ridge),
            ("dardg1dt", d.dardg1dt),
            ("opening", d.opening),
        ] {
            assert_eq!(cell_of(name, c).to_bits(), want.to_bits(), "{name} col {c}");
        }
        // Conservation with the fluxes (fluxes averaged over ndtd·dt).
        let rel = |x: f64, y: f64| (x - y).abs() / y.abs().max(1e-300);
        let sum = |x: &[f64]| x.iter().sum::<f64>();
        let ice_out = cell_of("ice_to_ocean", c);
        let snow_out = cell_of("snow_to_ocean", c);
        assert!(rel(sum(&v) + ice_out, sum(&v_in)) < 1e-12);
        assert!(rel(sum(&s) + snow_out, sum(&s_in)) < 1e-12);
        assert!((a0 + sum(&a) - 1.0).abs() < 1e-12);
        let water = (rhoi * ice_out + rhos * snow_out) / (2.0 * DT);
        assert!(rel(cell_of("fresh", c), water) < 1e-12 || water == 0.0);
        let (qi, li) = l.field("qice").unwrap();
        let (qs, ls) = l.field("qsno").unwrap();
        let enthalpy = |v: &[f64], s: &[f64], t: &[f64]| -> f64 {
            (0..NCAT)
                .map(|n| {
                    let tr = &t[n * nt..(n + 1) * nt];
                    v[n] * tr[qi..qi + li].iter().sum::<f64>() / li as f64
                        + s[n] * tr[qs..qs + ls].iter().sum::<f64>() / ls as f64
                })
                .sum()
        };
        let e0 = enthalpy(&v_in, &s_in, &t_in);
        let e1 = enthalpy(&v, &s, &t) + cell_of("fhocn", c) * 2.0 * DT;
        assert!(rel(e1, e0) < 1e-12, "enthalpy col {c}: {e1} vs {e0}");
    }
    // The output is a valid input again (chained steps).
    let out2 = dir.join("out2.nc");
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(&out)
        .arg("--output")
        .arg(&out2)
        .args(["--dt", "3600", "--convergence", "1e-6"])
        .output()
        .unwrap();
    succeeds(&r);
    // Output over input is refused.
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(&inp_path)
        .arg("--output")
        .arg(&inp_path)
        .args(["--dt", "3600"])
        .output()
        .unwrap();
    assert_eq!(r.status.code(), Some(1));
}

#[test]
fn incomplete_tracer_groups_and_misplaced_options_are_named() {
    let dir = scratch("ridge-step-complete-errors");
    let inp = input();
    let out = dir.join("out.nc");
    // alvl without vlvl.
    let p = dir.join("no_vlvl.nc");
    write_input(&p, &inp, &["vlvl"]);
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(&p)
        .arg("--output")
        .arg(&out)
        .args(["--dt", "3600"])
        .output()
        .unwrap();
    fails_with(&r, &["vlvl", "alvl"]);
    // The surface temperature is needed with the other tracers.
    let p = dir.join("no_tsfc.nc");
    write_input(&p, &inp, &["Tsfcn"]);
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(&p)
        .arg("--output")
        .arg(&out)
        .args(["--dt", "3600"])
        .output()
        .unwrap();
    fails_with(&r, &["Tsfcn"]);
    // No enthalpies at all: vsnon alone is refused.
    let l = layout();
    let all: Vec<String> = l.cice_restart_names();
    let refs: Vec<&str> = all.iter().map(|s| s.as_str()).collect();
    let p = dir.join("snow_only.nc");
    write_input(&p, &inp, &refs);
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(&p)
        .arg("--output")
        .arg(&out)
        .args(["--dt", "3600"])
        .output()
        .unwrap();
    fails_with(&r, &["qice001"]);
    // Options of the complete step on an area-volume file.
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(common::repo().join("data/sample_itd.nc"))
        .arg("--output")
        .arg(&out)
        .args(["--dt", "3600", "--ndtd", "2"])
        .output()
        .unwrap();
    fails_with(&r, &["--ndtd", "complete step"]);
}

/// The freezing temperature per column from the file's `Tf` (degC): the step equals the
/// library with that `Tf` column by column (an emptied category takes it as its surface
/// temperature), the output carries `Tf` for the next step, `--tf` overrides it, and other
/// units or a missing `--tf-var` are refused by name.
#[test]
fn freezing_temperature_per_column_from_the_file() {
    let dir = scratch("ridge-step-complete-tf");
    let mut inp = input();
    // Column 0, category 0: a residue the clean-up zaps, so its Tsfcn becomes Tf.
    let a_old = inp.aicen[0];
    inp.aicen[0] = 1e-13;
    inp.vicen[0] = 1e-13 * 0.4;
    inp.vsnon[0] = 0.0;
    inp.aice0[0] += a_old - 1e-13;
    let tf: Vec<f64> = (0..NCOL)
        .map(|c| {
            if c == LAND {
                FILL
            } else {
                -1.8 - 0.05 * c as f64
            }
        })
        .collect();
    let p = dir.join("in.nc");
    write_input_with(&p, &inp, &[], &[("Tf", &tf, Some("degC"))]);
    let out = dir.join("out.nc");
    succeeds(
        &bin()
            .args(["ridge-step", "--input"])
            .arg(&p)
            .arg("--output")
            .arg(&out)
            .args(["--dt", "3600"])
            .output()
            .unwrap(),
    );
    let l = layout();
    let nt = l.ntrcr();
    let names = l.cice_restart_names();
    let got_t: Vec<Vec<f64>> = names.iter().map(|n| read(&out, n)).collect();
    let got_a = read(&out, "aicen");
    let opts = RidgeStepOptions::default();
    for c in 0..NCOL {
        if c == LAND {
            continue;
        }
        let (_, r) = library(&inp, c, 1, tf[c], &opts);
        r.result.unwrap();
        let (a, t) = (r.col.aicen, r.col.trcrn);
        for n in 0..NCAT {
            let i = n * NCOL + c;
            assert_eq!(got_a[i].to_bits(), a[n].to_bits(), "aicen col {c} cat {n}");
            for it in 0..nt {
                assert_eq!(
                    got_t[it][i].to_bits(),
                    t[n * nt + it].to_bits(),
                    "{} col {c} cat {n}",
                    names[it]
                );
            }
        }
    }
    // The zapped category took this column's Tf.
    assert_eq!(got_a[0], 0.0);
    assert_eq!(got_t[0][0], tf[0]);
    assert_eq!(read(&out, "Tf"), tf);
    assert_eq!(units(&out, "Tf"), "degC");
    // --tf overrides the file for every column.
    let out2 = dir.join("out2.nc");
    succeeds(
        &bin()
            .args(["ridge-step", "--input"])
            .arg(&p)
            .arg("--output")
            .arg(&out2)
            .args(["--dt", "3600", "--tf", "-1.5"])
            .output()
            .unwrap(),
    );
    assert_eq!(read(&out2, "Tsfcn")[0], -1.5);
    // Kelvin, or no units, is refused naming the variable and the unit.
    let k = dir.join("kelvin.nc");
    write_input_with(&k, &inp, &[], &[("Tfrz", &tf, Some("K"))]);
    let run = |extra: &[&str]| {
        bin()
            .args(["ridge-step", "--input"])
            .arg(&k)
            .arg("--output")
            .arg(dir.join("out3.nc"))
            .args(["--dt", "3600"])
            .args(extra)
            .output()
            .unwrap()
    };
    fails_with(&run(&["--tf-var", "Tfrz"]), &["Tfrz", "\"K\"", "degC"]);
    fails_with(&run(&["--tf-var", "Tf"]), &["--tf-var", "`Tf`"]);
    fails_with(
        &run(&["--tf-var", "Tfrz", "--tf", "-1.8"]),
        &["--tf", "--tf-var", "not both"],
    );
    let n = dir.join("nounits.nc");
    write_input_with(&n, &inp, &[], &[("Tf", &tf, None)]);
    fails_with(
        &bin()
            .args(["ridge-step", "--input"])
            .arg(&n)
            .arg("--output")
            .arg(dir.join("out4.nc"))
            .args(["--dt", "3600"])
            .output()
            .unwrap(),
        &["Tf", "no `units`", "degC"],
    );
}

/// The thermodynamic constants of the complete step from --param and --param-file (one list,
/// `RidgeStepParams::FIELDS`), and the salt-flux option: the step equals the library with
/// them bit for bit, every constant used is written as a global attribute with its units,
/// and bad names, values or misplaced constants are refused by name.
#[test]
fn thermodynamic_constants_from_options_and_file() {
    let dir = scratch("ridge-step-complete-constants");
    let inp = input();
    let p = dir.join("in.nc");
    write_input(&p, &inp, &[]);
    let pf = dir.join("constants.txt");
    std::fs::write(
        &pf,
        "# thermodynamics\nfsnowrdg = 0.3\nice_ref_salinity = 5  # ppt\nrhos = 250\n",
    )
    .unwrap();
    let out = dir.join("out.nc");
    succeeds(
        &bin()
            .args(["ridge-step", "--input"])
            .arg(&p)
            .arg("--output")
            .arg(&out)
            .args(["--dt", "3600", "--param", "rhos=300", "--param", "rhoi=900"])
            .arg("--param-file")
            .arg(&pf)
            .args(["--salt-flux", "prognostic"])
            .output()
            .unwrap(),
    );
    let mut opts = RidgeStepOptions::default();
    opts.step.rhos = 300.0; // --param wins over the file
    opts.step.fsnowrdg = 0.3;
    opts.step.ice_ref_salinity = 5.0;
    opts.step.salt_flux = pressridge::itd::details::SaltFlux::Prognostic;
    opts.params.rhoi = 900.0;
    let got_s = read(&out, "vsnon");
    let fresh = read(&out, "fresh");
    let fhocn = read(&out, "fhocn");
    for c in (0..NCOL).filter(|&c| c != LAND) {
        let (_, r) = library(&inp, c, 1, -1.8, &opts);
        r.result.unwrap();
        let (s, fl) = (r.col.vsnon, r.fluxes);
        for n in 0..NCAT {
            assert_eq!(got_s[n * NCOL + c].to_bits(), s[n].to_bits(), "col {c}");
        }
        assert_eq!(fresh[c].to_bits(), fl.fresh.to_bits(), "fresh col {c}");
        assert_eq!(fhocn[c].to_bits(), fl.fhocn.to_bits(), "fhocn col {c}");
        // Snow on ridging ice reaches the ocean (70 % of it with fsnowrdg = 0.3).
        assert!(fl.fresh > 0.0);
    }
    assert_eq!(global(&out, "rhos"), "300 kg m-3");
    assert_eq!(global(&out, "fsnowrdg"), "0.3 1");
    assert_eq!(global(&out, "ice_ref_salinity"), "5 ppt");
    assert_eq!(global(&out, "rhoi"), "900 kg m-3");
    assert_eq!(global(&out, "lfresh"), "334000 J kg-1");
    assert_eq!(global(&out, "salt_flux"), "prognostic");
    for f in pressridge::itd::details::RidgeStepParams::FIELDS {
        assert!(global(&out, f.name).ends_with(f.units), "{}", f.name);
    }
    assert!(global(&out, "parameter_overrides").contains("fsnowrdg=0.3"));
    // The docs' table and the command line's help list every constant with its units.
    let docs = std::fs::read_to_string(common::repo().join("docs/strength.md")).unwrap();
    let help = bin().args(["ridge-step", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    for f in pressridge::itd::details::RidgeStepParams::FIELDS {
        let row = format!("| `{}` | {} |", f.name, f.units);
        assert!(docs.contains(&row), "docs/strength.md lacks the row {row}");
        assert!(help.contains(f.name), "--help lacks {}", f.name);
    }
    // Errors, by name.
    let run = |extra: &[&str]| {
        bin()
            .args(["ridge-step", "--input"])
            .arg(&p)
            .arg("--output")
            .arg(dir.join("bad.nc"))
            .args(["--dt", "3600"])
            .args(extra)
            .output()
            .unwrap()
    };
    fails_with(&run(&["--param", "rhoz=300"]), &["rhoz", "rhos", "mu_rdg"]);
    fails_with(&run(&["--param", "fsnowrdg=2"]), &["fsnowrdg", "[0, 1]"]);
    fails_with(&run(&["--param", "cp_ice=-1"]), &["cp_ice", "positive"]);
    std::fs::write(&pf, "rhos 300\n").unwrap();
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(&p)
        .arg("--output")
        .arg(dir.join("bad.nc"))
        .args(["--dt", "3600", "--param-file"])
        .arg(&pf)
        .output()
        .unwrap();
    fails_with(&r, &["constants.txt:1", "NAME=VALUE"]);
    // Constants of the complete step on an area-volume file.
    let r = bin()
        .args(["ridge-step", "--input"])
        .arg(common::repo().join("data/sample_itd.nc"))
        .arg("--output")
        .arg(dir.join("bad.nc"))
        .args(["--dt", "3600", "--param", "rhos=300"])
        .output()
        .unwrap();
    fails_with(&r, &["rhos", "complete step"]);
}
