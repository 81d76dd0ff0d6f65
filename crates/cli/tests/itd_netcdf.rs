//! The command line on NetCDF distributions: small files written here, the sample and
//! CICE-history-like files (strength, ridge-step, plot-strength). (The library's NetCDF input
//! and output is tests/itd_netcdf.rs.)

use std::path::{Path, PathBuf};
#[path = "../../../tests/common/mod.rs"]
mod common;

use approx::assert_relative_eq;
use common::grid::{sample, small_grid, write_grid};
use pressridge::io::itd_netcdf::{read_field, read_itd, write_cf_table};
use pressridge::itd::details::CfTable;

/// Without `aice0`, open water is 1 − Σ aicen clamped at 0, as in the strength routine: the
/// sample file without its `aice0` ridges, although some fully covered columns sum to
/// 1 + 2e-16 (e.g. nj = 20, ni = 38).
#[test]
fn ridge_step_without_aice0_accepts_full_cover_round_off() {
    let dir = common::scratch("itd-ridge-step-without-aice0-accepts-full-cover-round-off");
    let g = read_itd(&sample()).unwrap();
    let (ncat, ncol) = (g.ncat(), g.ncol());
    let (ny, nx) = (g.spatial_dims[0].1, g.spatial_dims[1].1);
    assert!((0..ncol).any(|c| g.aicen.column(c).sum() > 1.0));
    let p = dir.join("noaice0.nc");
    let flat = |a: &ndarray::Array2<f64>| a.iter().copied().collect::<Vec<f64>>();
    let (_, divu) = read_field(&sample(), "divu").unwrap();
    let (_, shear) = read_field(&sample(), "shear").unwrap();
    let (cat, sp) = (
        [("nc", ncat), ("nj", ny), ("ni", nx)],
        [("nj", ny), ("ni", nx)],
    );
    common::write_nc(
        &p,
        &[
            common::Var::f64("aicen", &cat, flat(&g.aicen)),
            common::Var::f64("vicen", &cat, flat(&g.vicen)),
            common::Var::f64("divu", &sp, divu).with_units("s-1"),
            common::Var::f64("shear", &sp, shear).with_units("s-1"),
        ],
    );
    let out = dir.join("noaice0_out.nc");
    let o = cli(&[
        "ridge-step",
        "--input",
        p.to_str().unwrap(),
        "--output",
        out.to_str().unwrap(),
        "--dt",
        "3600",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (_, a0) = read_field(&out, "aice0").unwrap();
    assert!(a0.iter().all(|&a| a >= 0.0));
}

fn cli(args: &[&str]) -> std::process::Output {
    common::bin().args(args).output().unwrap()
}

#[test]
fn cli_strength_ridge_step_and_plot() {
    let dir = common::scratch("itd-cli-strength-ridge-step-and-plot");
    let s = sample();
    let s = s.to_str().unwrap();
    let out = dir.join("strength.nc");
    let o = cli(&[
        "strength",
        "--input",
        s,
        "--output",
        out.to_str().unwrap(),
        "--cf-preset",
        "flato1991",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (dims, p) = read_field(&out, "strength").unwrap();
    assert_eq!(dims, vec![("nj".to_string(), 60), ("ni".to_string(), 80)]);
    assert!(p.iter().all(|x| x.is_finite() && *x >= 0.0) && p.iter().any(|x| *x > 0.0));
    let f = netcdf::open(&out).unwrap();
    let cf: String = f
        .attribute("cf")
        .unwrap()
        .value()
        .unwrap()
        .try_into()
        .unwrap();
    assert_eq!(cf, "constant 15");

    // Parameter override and a C_f table (values clamped outside 0.5–2 m, and flagged).
    let out2 = dir.join("strength_mu.nc");
    let o = cli(&[
        "strength",
        "--input",
        s,
        "--output",
        out2.to_str().unwrap(),
        "--param",
        "mu_rdg=4",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (_, p4) = read_field(&out2, "strength").unwrap();
    let (_, p17) = {
        let o17 = dir.join("strength_17.nc");
        assert!(
            cli(&["strength", "--input", s, "--output", o17.to_str().unwrap()])
                .status
                .success()
        );
        read_field(&o17, "strength").unwrap()
    };
    assert!(p4.iter().zip(&p17).all(|(a, b)| a >= b) && p4.iter().zip(&p17).any(|(a, b)| a > b));
    let bad = cli(&[
        "strength",
        "--input",
        s,
        "--output",
        out2.to_str().unwrap(),
        "--param",
        "mu_rdg=-1",
    ]);
    assert!(!bad.status.success() && String::from_utf8_lossy(&bad.stderr).contains("mu_rdg"));
    let table = dir.join("cf_table.nc");
    write_cf_table(
        &table,
        &CfTable::new(vec![0.5, 2.0], vec![17.0, 17.0]).unwrap(),
    )
    .unwrap();
    let out3 = dir.join("strength_table.nc");
    let o = cli(&[
        "strength",
        "--input",
        s,
        "--output",
        out3.to_str().unwrap(),
        "--cf-table",
        table.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("clamped"));
    // How many columns were clamped, in how many the clamp is material (≥ 1 % of P), and
    // the largest share of P from clamped C_f.
    let attr = |name: &str| -> f64 {
        let f = netcdf::open(&out3).unwrap();
        let v: String = f
            .attribute(name)
            .unwrap()
            .value()
            .unwrap()
            .try_into()
            .unwrap();
        v.parse().unwrap()
    };
    let (all, material, share) = (
        attr("cf_clamped_columns"),
        attr("cf_clamped_material_columns"),
        attr("cf_clamped_share_max"),
    );
    assert!(all > 0.0 && material <= all && (0.0..=1.0).contains(&share));
    assert_eq!(material > 0.0, share >= 0.01);
    let (_, pt) = read_field(&out3, "strength").unwrap();
    for (a, b) in pt.iter().zip(&p17) {
        assert_relative_eq!(*a, *b, max_relative = 1e-12, epsilon = 1e-9);
    }

    let rs = dir.join("ridged.nc");
    let o = cli(&[
        "ridge-step",
        "--input",
        s,
        "--output",
        rs.to_str().unwrap(),
        "--dt",
        "3600",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let g = read_itd(&rs).unwrap();
    assert_eq!(g.ncat(), 5);
    assert!(read_field(&rs, "dardg1dt").is_ok());

    let png = dir.join("map.png");
    let o = cli(&[
        "plot-strength",
        "--input",
        out.to_str().unwrap(),
        "--output",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::metadata(&png).unwrap().len() > 1000);
    // A constant-17 table drawn beside C_f = 17 gives the same statistics row.
    let o = cli(&[
        "plot-strength",
        "--input",
        s,
        "--output",
        png.to_str().unwrap(),
        "--cf",
        "17",
        "--cf-table",
        table.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    let row = |label: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("| {label} |")))
            .unwrap_or_else(|| panic!("no row {label} in\n{text}"))
            .split_once(" | ")
            .unwrap()
            .1
            .to_string()
    };
    assert_eq!(row("C_f = 17"), row("C_f from cf_table.nc"));

    // Bad input: the error names the variable and the spatial index, exit status 1.
    let bad = dir.join("cli_bad.nc");
    write_grid(&bad, &small_grid(Some(f64::NAN)));
    let o = cli(&[
        "strength",
        "--input",
        bad.to_str().unwrap(),
        "--output",
        dir.join("x.nc").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("y=1, x=2") && err.contains("aicen"), "{err}");
}

/// A CICE-history-like file: `aicen(time, nc, nj, ni)` in single precision with
/// `_FillValue = 1e30` on a land cell. The length-1 time dimension is kept as a column
/// dimension, the land cell is masked (fill on output), the other cells are computed.
#[test]
fn cice_like_file_with_time_and_land_fill() {
    let dir = common::scratch("itd-cice-like-file-with-time-and-land-fill");
    let p = dir.join("cice_like.nc");
    {
        let mut f = netcdf::create_with(&p, netcdf::Options::_64BIT_OFFSET).unwrap();
        for (n, l) in [("time", 1), ("nc", 2), ("nj", 2), ("ni", 3)] {
            f.add_dimension(n, l).unwrap();
        }
        for n in ["aicen", "vicen"] {
            let mut v = f
                .add_variable::<f32>(n, &["time", "nc", "nj", "ni"])
                .unwrap();
            v.put_attribute("_FillValue", 1.0e30f32).unwrap();
        }
        f.enddef().unwrap();
        // Category-major, 6 columns; column 1 (nj=0, ni=1) is land.
        let mut a = vec![0.45f32; 12];
        let mut v = vec![0.9f32; 12];
        for k in [1usize, 7] {
            a[k] = 1.0e30;
            v[k] = 1.0e30;
        }
        f.variable_mut("aicen").unwrap().put_values(&a, ..).unwrap();
        f.variable_mut("vicen").unwrap().put_values(&v, ..).unwrap();
    }
    let g = read_itd(&p).unwrap();
    assert_eq!(g.ncat(), 2);
    assert_eq!(
        g.spatial_dims,
        vec![
            ("time".to_string(), 1),
            ("nj".to_string(), 2),
            ("ni".to_string(), 3)
        ]
    );
    let valid = g.valid.clone().unwrap();
    assert_eq!(valid.to_vec(), vec![true, false, true, true, true, true]);
    assert_relative_eq!(g.fill_value.unwrap(), 1.0e30f32 as f64);

    let out = dir.join("cice_like_strength.nc");
    let o = cli(&[
        "strength",
        "--input",
        p.to_str().unwrap(),
        "--output",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (_, s) = read_field(&out, "strength").unwrap();
    assert_eq!(s[1], 1.0e30f32 as f64);
    assert!(
        s.iter()
            .enumerate()
            .all(|(c, x)| c == 1 || (x.is_finite() && *x > 0.0))
    );
    assert!(s[0] == s[5], "identical columns give identical strength");
    let f = netcdf::open(&out).unwrap();
    let fv: f64 = f
        .variable("strength")
        .unwrap()
        .attribute_value("_FillValue")
        .unwrap()
        .unwrap()
        .try_into()
        .unwrap();
    assert_eq!(fv, 1.0e30f32 as f64);
}

/// A CICE-history-like file with `ntime` times: `time(time)` (days, noleap calendar),
/// `TLON`/`TLAT` (float, named by aicen's `coordinates`), `NCAT(nc)` upper bounds, and
/// `aicen`/`vicen(time, nc, nj, ni)` in single precision with a land cell (nj=0, ni=1) at
/// `_FillValue = 1e30`. Time `t` holds data that depends on `t`; `times` picks which.
fn cice_history(path: &Path, times: &[usize], ncat_bounds: &[f32]) {
    let mut f = netcdf::create_with(path, netcdf::Options::_64BIT_OFFSET).unwrap();
    f.add_unlimited_dimension("time").unwrap();
    for (n, l) in [("nc", 2), ("nj", 2), ("ni", 3)] {
        f.add_dimension(n, l).unwrap();
    }
    let mut t = f.add_variable::<f64>("time", &["time"]).unwrap();
    t.put_attribute("units", "days since 2000-01-01 00:00:00")
        .unwrap();
    t.put_attribute("calendar", "noleap").unwrap();
    for (n, u) in [("TLON", "degrees_east"), ("TLAT", "degrees_north")] {
        let mut v = f.add_variable::<f32>(n, &["nj", "ni"]).unwrap();
        v.put_attribute("units", u).unwrap();
        v.put_attribute("_FillValue", 1.0e30f32).unwrap();
    }
    let mut v = f.add_variable::<f32>("NCAT", &["nc"]).unwrap();
    v.put_attribute("units", "m").unwrap();
    // An integer index coordinate, as Icepack's column driver writes `ni`.
    f.add_variable::<i32>("ni", &["ni"]).unwrap();
    for n in ["aicen", "vicen"] {
        let mut v = f
            .add_variable::<f32>(n, &["time", "nc", "nj", "ni"])
            .unwrap();
        v.put_attribute("_FillValue", 1.0e30f32).unwrap();
        v.put_attribute("coordinates", "TLON TLAT time").unwrap();
    }
    f.add_attribute("history", "made by the test").unwrap();
    f.enddef().unwrap();
    let (mut a, mut v, mut tv) = (Vec::new(), Vec::new(), Vec::new());
    for &it in times {
        tv.push(31.0 * it as f64);
        for k in 0..2 {
            for c in 0..6 {
                let land = c == 1;
                let x = 0.3 + 0.05 * k as f32 + 0.02 * c as f32 + 0.05 * it as f32;
                a.push(if land { 1.0e30 } else { x });
                v.push(if land {
                    1.0e30
                } else {
                    x * (0.5 + 1.5 * k as f32 + 0.3 * it as f32)
                });
            }
        }
    }
    f.variable_mut("time")
        .unwrap()
        .put_values(&tv, (0..times.len(),))
        .unwrap();
    let lon: Vec<f32> = (0..6).map(|c| 10.0 + c as f32).collect();
    let lat: Vec<f32> = (0..6).map(|c| 70.0 + 0.5 * c as f32).collect();
    f.variable_mut("TLON")
        .unwrap()
        .put_values(&lon, ..)
        .unwrap();
    f.variable_mut("TLAT")
        .unwrap()
        .put_values(&lat, ..)
        .unwrap();
    f.variable_mut("NCAT")
        .unwrap()
        .put_values(ncat_bounds, ..)
        .unwrap();
    f.variable_mut("ni")
        .unwrap()
        .put_values(&[1i32, 2, 3], ..)
        .unwrap();
    let n = times.len();
    f.variable_mut("aicen")
        .unwrap()
        .put_values(&a, (0..n, .., .., ..))
        .unwrap();
    f.variable_mut("vicen")
        .unwrap()
        .put_values(&v, (0..n, .., .., ..))
        .unwrap();
}

fn str_attr(f: &netcdf::File, var: &str, name: &str) -> String {
    let v = f.variable(var).unwrap();
    let a = v.attributes().find(|a| a.name() == name);
    String::try_from(a.unwrap_or_else(|| panic!("{var}:{name}")).value().unwrap()).unwrap()
}

/// Strength and the ridging step of a CICE history file with two times: the category
/// dimension found by name, time kept, each time equal to the same file holding that time
/// alone; coordinates (time with its calendar, TLON/TLAT) and CF attributes carried over; land
/// stays missing; the bounds come from NCAT; coordinates keep their type (`int ni`, float
/// `TLAT`).
#[test]
fn cice_history_with_several_times_keeps_time_coordinates_and_land() {
    let dir =
        common::scratch("itd-cice-history-with-several-times-keeps-time-coordinates-and-land");
    let both = dir.join("hist2.nc");
    cice_history(&both, &[0, 1], &[1.0, 99.0]);
    let run = |cmd: &str, input: &Path, name: &str, extra: &[&str]| -> PathBuf {
        let out = dir.join(name);
        let mut a = vec![
            cmd,
            "--input",
            input.to_str().unwrap(),
            "--output",
            out.to_str().unwrap(),
        ];
        a.extend(extra);
        let o = cli(&a);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        out
    };
    let step = ["--dt", "3600", "--convergence", "2e-6", "--shear", "1e-6"];
    let p2 = run("strength", &both, "hist2_p.nc", &[]);
    let r2 = run("ridge-step", &both, "hist2_r.nc", &step);
    let (d, p) = read_field(&p2, "strength").unwrap();
    assert_eq!(
        d,
        vec![
            ("time".to_string(), 2),
            ("nj".to_string(), 2),
            ("ni".to_string(), 3)
        ]
    );
    let (da, a2) = read_field(&r2, "aicen").unwrap();
    assert_eq!(
        da.iter().map(|x| x.0.as_str()).collect::<Vec<_>>(),
        ["time", "nc", "nj", "ni"]
    );
    for it in 0..2 {
        let one = dir.join(format!("hist1_{it}.nc"));
        cice_history(&one, &[it], &[1.0, 99.0]);
        let (_, p1) = read_field(
            &run("strength", &one, &format!("h1p{it}.nc"), &[]),
            "strength",
        )
        .unwrap();
        assert_eq!(&p[6 * it..6 * it + 6], &p1[..], "time {it}");
        let (_, a1) = read_field(
            &run("ridge-step", &one, &format!("h1r{it}.nc"), &step),
            "aicen",
        )
        .unwrap();
        assert_eq!(&a2[12 * it..12 * it + 12], &a1[..], "time {it}");
    }
    // Land: fill in every output, never 0; the others computed.
    let fill = 1.0e30f32 as f64;
    for it in 0..2 {
        assert_eq!(p[6 * it + 1], fill);
        assert!(
            (0..6)
                .filter(|&c| c != 1)
                .all(|c| p[6 * it + c] > 0.0 && p[6 * it + c] < 1.0e6)
        );
        assert_eq!(a2[12 * it + 1], fill);
    }
    for out in [&p2, &r2] {
        let f = netcdf::open(out).unwrap();
        assert_eq!(
            String::try_from(f.attribute("Conventions").unwrap().value().unwrap()).unwrap(),
            "CF-1.8"
        );
        let h = String::try_from(f.attribute("history").unwrap().value().unwrap()).unwrap();
        assert!(h.starts_with("made by the test\n"), "{h}");
        assert!(h.contains("--input") && h.contains("hist2.nc"), "{h}");
        assert_eq!(str_attr(&f, "time", "calendar"), "noleap");
        assert_eq!(
            str_attr(&f, "time", "units"),
            "days since 2000-01-01 00:00:00"
        );
        assert_eq!(str_attr(&f, "TLAT", "units"), "degrees_north");
        let t: Vec<f64> = f.variable("time").unwrap().get_values(..).unwrap();
        assert_eq!(t, vec![0.0, 31.0]);
        // Coordinates keep their type: int stays int, float stays float, fill and all.
        use netcdf::types::{FloatType, IntType, NcVariableType as T};
        let ni = f.variable("ni").unwrap();
        assert_eq!(ni.vartype(), T::Int(IntType::I32));
        assert_eq!(ni.get_values::<i32, _>(..).unwrap(), vec![1, 2, 3]);
        let lat = f.variable("TLAT").unwrap();
        assert_eq!(lat.vartype(), T::Float(FloatType::F32));
        let fill = lat.attributes().find(|a| a.name() == "_FillValue").unwrap();
        assert_eq!(f32::try_from(fill.value().unwrap()).unwrap(), 1.0e30f32);
        assert_eq!(
            lat.get_values::<f32, _>(..).unwrap(),
            (0..6).map(|c| 70.0 + 0.5 * c as f32).collect::<Vec<_>>()
        );
    }
    let f = netcdf::open(&p2).unwrap();
    assert_eq!(str_attr(&f, "strength", "coordinates"), "TLON TLAT");
    assert_eq!(str_attr(&f, "strength", "units"), "N m-1");
    assert_eq!(
        str_attr(&f, "strength", "standard_name"),
        "compressive_strength_of_sea_ice"
    );
    let f = netcdf::open(&r2).unwrap();
    let h: Vec<f64> = f.variable("hin_max").unwrap().get_values(..).unwrap();
    assert_eq!(h, vec![0.0, 1.0, 99.0]);
    assert!(
        String::try_from(f.attribute("category_bounds").unwrap().value().unwrap())
            .unwrap()
            .starts_with("NCAT")
    );
}

/// The category dimension is found by name or refused with the dimensions listed; NCAT and
/// hin_max must agree.
#[test]
fn category_dimension_by_name_or_refused() {
    let dir = common::scratch("itd-category-dimension-by-name-or-refused");
    let data = vec![0.3; 6];
    // None of the names.
    let p = dir.join("noname.nc");
    common::write_f64(
        &p,
        &[("k", 2), ("x", 3)],
        &[
            ("aicen", &["k", "x"], data.clone()),
            ("vicen", &["k", "x"], data.clone()),
        ],
    );
    let e = read_itd(&p).unwrap_err().to_string();
    assert!(
        e.contains("(k=2, x=3)") && e.contains("--category-dim") && e.contains("nc, ncat, ct"),
        "{e}"
    );
    let out = dir.join("noname_p.nc");
    let o = cli(&[
        "strength",
        "--input",
        p.to_str().unwrap(),
        "--output",
        out.to_str().unwrap(),
        "--category-dim",
        "k",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = cli(&[
        "strength",
        "--input",
        p.to_str().unwrap(),
        "--output",
        out.to_str().unwrap(),
        "--category-dim",
        "nc",
    ]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && msg.contains("`nc` given"), "{msg}");
    // Two of the names: ambiguous.
    let p = dir.join("twonames.nc");
    common::write_f64(
        &p,
        &[("nc", 2), ("ncat", 3)],
        &[
            ("aicen", &["nc", "ncat"], data.clone()),
            ("vicen", &["nc", "ncat"], data.clone()),
        ],
    );
    let e = read_itd(&p).unwrap_err().to_string();
    assert!(
        e.contains("(nc=2, ncat=3)") && e.contains("more than one"),
        "{e}"
    );
    // The category dimension last.
    let p = dir.join("catlast.nc");
    let a: Vec<f64> = (0..6).map(|i| 0.1 + 0.05 * i as f64).collect();
    common::write_f64(
        &p,
        &[("x", 3), ("ncat", 2)],
        &[
            ("aicen", &["x", "ncat"], a.clone()),
            ("vicen", &["x", "ncat"], a.iter().map(|x| 2.0 * x).collect()),
        ],
    );
    let g = read_itd(&p).unwrap();
    assert_eq!(g.cat_axis, 1);
    assert_eq!(g.aicen.row(0).to_vec(), vec![a[0], a[2], a[4]]);
    assert_eq!(g.aicen.row(1).to_vec(), vec![a[1], a[3], a[5]]);
    // hin_max and NCAT disagree.
    let p = dir.join("ncat_vs_hin.nc");
    common::write_f64(
        &p,
        &[("ncat", 2), ("x", 3), ("nb", 3)],
        &[
            ("aicen", &["ncat", "x"], data.clone()),
            ("vicen", &["ncat", "x"], data.clone()),
            ("hin_max", &["nb"], vec![0.0, 1.0, 50.0]),
            ("NCAT", &["ncat"], vec![1.5, 50.0]),
        ],
    );
    let e = read_itd(&p).unwrap_err().to_string();
    assert!(e.contains("NCAT") && e.contains("disagree"), "{e}");
}

/// CICE's ocean mask `tmask` (1 ocean, 0 land; no time dimension) makes land missing in the
/// output even where the history file holds 0 there rather than a fill value. The sample
/// CICE history file with its land fill values replaced by 0 gives the strength of the
/// original on ocean and missing values exactly where tmask is 0, at both times.
#[test]
fn tmask_zero_is_land_like_fill() {
    let dir = common::scratch("itd-tmask-zero-is-land-like-fill");
    let src = common::repo().join("data/cice_history_sample.nc");
    let f = netcdf::open(&src).unwrap();
    let get = |n: &str| -> Vec<f64> {
        let v: Vec<f32> = f.variable(n).unwrap().get_values(..).unwrap();
        v.into_iter()
            .map(|x| if x >= 1e29 { 0.0 } else { x as f64 })
            .collect()
    };
    let (nt, nc, nj, ni) = (2, 5, 30, 40);
    let cat = [("time", nt), ("nc", nc), ("nj", nj), ("ni", ni)];
    let tmask = get("tmask");
    assert!(tmask.contains(&0.0) && tmask.contains(&1.0));
    let zeroed = dir.join("cice_tmask_zero_land.nc");
    common::write_nc(
        &zeroed,
        &[
            common::Var::f64("aicen", &cat, get("aicen")),
            common::Var::f64("vicen", &cat, get("vicen")),
            common::Var::f64("tmask", &[("nj", nj), ("ni", ni)], tmask.clone()),
            common::Var::f64("NCAT", &[("nc", nc)], get("NCAT")),
        ],
    );
    let g = read_itd(&zeroed).unwrap();
    let valid = g.valid.clone().expect("land from tmask");
    assert_eq!(valid.len(), nt * nj * ni);
    for (c, v) in valid.iter().enumerate() {
        assert_eq!(*v, tmask[c % (nj * ni)] != 0.0, "column {c}");
    }
    let run = |input: &Path, name: &str| -> Vec<f64> {
        let out = dir.join(name);
        let o = cli(&[
            "strength",
            "--input",
            input.to_str().unwrap(),
            "--output",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        read_field(&out, "strength").unwrap().1
    };
    let p = run(&zeroed, "cice_tmask_p.nc");
    let p_orig = run(&src, "cice_tmask_orig_p.nc");
    let fill = pressridge::io::itd_netcdf::NC_FILL_DOUBLE;
    for c in 0..p.len() {
        if tmask[c % (nj * ni)] == 0.0 {
            assert_eq!(p[c], fill, "land column {c} not missing");
        } else {
            assert!(
                p[c].is_finite() && p[c] != fill,
                "ocean column {c}: {}",
                p[c]
            );
            assert_relative_eq!(p[c], p_orig[c], max_relative = 1e-12);
        }
    }
    // A tmask over a dimension the fields do not have is refused by name.
    let bad = dir.join("cice_tmask_bad.nc");
    common::write_nc(
        &bad,
        &[
            common::Var::f64("aicen", &cat, get("aicen")),
            common::Var::f64("vicen", &cat, get("vicen")),
            common::Var::f64("tmask", &[("y", nj), ("ni", ni)], tmask),
            common::Var::f64("NCAT", &[("nc", nc)], get("NCAT")),
        ],
    );
    let e = read_itd(&bad).unwrap_err().to_string();
    assert!(e.contains("tmask"), "{e}");
}
