//! NetCDF input and output of the library on small files written here and on the sample.
//! (The command line on such files is crates/cli/tests/itd_netcdf.rs.)

mod common;

use approx::assert_relative_eq;
use common::grid::{sample, small_grid, write_grid};
use ndarray::Array1;
use pressridge::io::itd_netcdf::{
    FieldMeta, NetcdfError, Output, read_cf_table, read_itd, write_cf_table, write_output,
};
use pressridge::itd::{ColumnError, details::CfTable};

#[test]
fn round_trip_keeps_values_and_dimensions() {
    let dir = common::scratch("itd-round-trip-keeps-values-and-dimensions");
    let p = dir.join("rt.nc");
    let g = small_grid(None);
    write_grid(&p, &g);
    let r = read_itd(&p).unwrap();
    assert_eq!(r.ncat_dim, "nc");
    assert_eq!(r.spatial_dims, g.spatial_dims);
    assert_eq!(r.aicen, g.aicen);
    assert_eq!(r.vicen, g.vicen);
    assert_eq!(r.aice0, g.aice0);
    assert_eq!(r.hin_max, Some(vec![0.0, 1.0, 3.0]));
    assert_eq!(r.spatial_index(5), "y=1, x=2");
}

#[test]
fn bad_column_is_located_by_spatial_index() {
    let dir = common::scratch("itd-bad-column-is-located-by-spatial-index");
    let p = dir.join("bad.nc");
    let g = small_grid(Some(-0.1));
    write_grid(&p, &g);
    let r = read_itd(&p).unwrap();
    let mut out = Array1::zeros(6);
    let e = pressridge::itd::strength_batch(
        r.aicen.view(),
        r.vicen.view(),
        r.aice0.as_ref().map(|a| a.view()),
        &Default::default(),
        out.view_mut(),
    )
    .map_err(|e| r.locate(&p, e))
    .unwrap_err();
    assert!(matches!(
        e,
        NetcdfError::Column {
            column: 5,
            source: ColumnError::Negative {
                var: "aicen",
                category: Some(1),
                ..
            },
            ..
        }
    ));
    let msg = e.to_string();
    assert!(
        msg.contains("y=1, x=2") && msg.contains("aicen[category 1]"),
        "{msg}"
    );
}

#[test]
fn missing_and_mismatched_variables_are_named() {
    let dir = common::scratch("itd-missing-and-mismatched-variables-are-named");
    // No vicen.
    let p = dir.join("novicen.nc");
    common::write_f64(
        &p,
        &[("ncat", 2), ("x", 3)],
        &[("aicen", &["ncat", "x"], vec![0.1; 6])],
    );
    let e = read_itd(&p).unwrap_err();
    assert!(
        matches!(&e, NetcdfError::MissingVariable { var, .. } if var == "vicen"),
        "{e}"
    );
    // vicen on other dimensions.
    let p = dir.join("shape.nc");
    common::write_f64(
        &p,
        &[("ncat", 2), ("x", 3), ("y", 2)],
        &[
            ("aicen", &["ncat", "x"], vec![0.1; 6]),
            ("vicen", &["ncat", "y"], vec![0.1; 4]),
        ],
    );
    let e = read_itd(&p).unwrap_err();
    assert!(
        matches!(&e, NetcdfError::Shape { var, .. } if var == "vicen"),
        "{e}"
    );
    // aice0 on the wrong dimensions.
    let p = dir.join("shape0.nc");
    common::write_f64(
        &p,
        &[("ncat", 2), ("x", 3)],
        &[
            ("aicen", &["ncat", "x"], vec![0.1; 6]),
            ("vicen", &["ncat", "x"], vec![0.1; 6]),
            ("aice0", &["ncat"], vec![0.1; 2]),
        ],
    );
    let e = read_itd(&p).unwrap_err();
    assert!(
        matches!(&e, NetcdfError::Shape { var, .. } if var == "aice0"),
        "{e}"
    );
    // hin_max of the wrong length.
    let p = dir.join("hin.nc");
    common::write_f64(
        &p,
        &[("ncat", 2), ("x", 3), ("nb", 2)],
        &[
            ("aicen", &["ncat", "x"], vec![0.1; 6]),
            ("vicen", &["ncat", "x"], vec![0.1; 6]),
            ("hin_max", &["nb"], vec![0.0, 1.0]),
        ],
    );
    let e = read_itd(&p).unwrap_err();
    assert!(
        matches!(&e, NetcdfError::Shape { var, .. } if var == "hin_max"),
        "{e}"
    );
}

#[test]
fn cf_table_round_trip() {
    let dir = common::scratch("itd-cf-table-round-trip");
    let p = dir.join("cf.nc");
    let t = CfTable::new(vec![0.2, 1.0, 3.0], vec![5.0, 12.0, 20.0]).unwrap();
    write_cf_table(&p, &t).unwrap();
    assert_eq!(read_cf_table(&p).unwrap(), t);
}

#[test]
fn sample_file_is_valid_and_ridging_conserves_it() {
    let g = read_itd(&sample()).unwrap();
    assert_eq!(g.ncat(), 5);
    assert_eq!(
        g.spatial_dims,
        vec![("nj".to_string(), 60), ("ni".to_string(), 80)]
    );
    let a0 = g.aice0.clone().unwrap();
    assert!(
        a0.iter().any(|&x| x == 1.0),
        "sample needs open-water cells"
    );
    assert!(
        a0.iter().any(|&x| x == 0.0),
        "sample needs full-cover cells"
    );
    let vol0 = g.vicen.sum();
    let mut aicen = g.aicen.clone();
    let mut vicen = g.vicen.clone();
    let mut aice0 = a0.clone();
    let conv = g.divu.clone().unwrap().mapv(|d| f64::max(-d, 0.0));
    let shear = g.shear.clone().unwrap();
    let mut r: [Array1<f64>; 5] = std::array::from_fn(|_| Array1::zeros(g.ncol()));
    let [c, o, d1, d2, dv] = &mut r;
    pressridge::itd::ridge_batch(
        aicen.view_mut(),
        vicen.view_mut(),
        aice0.view_mut(),
        g.hin_max.as_ref().unwrap(),
        pressridge::itd::details::RidgeBatchForcing {
            convergence: conv.view(),
            shear: shear.view(),
            dt: 86_400.0,
            valid: None,
        },
        &Default::default(),
        pressridge::itd::details::RidgeRatesMut {
            closing: c.view_mut(),
            opening: o.view_mut(),
            dardg1dt: d1.view_mut(),
            dardg2dt: d2.view_mut(),
            dvirdgdt: dv.view_mut(),
            fill: f64::NAN,
        },
    )
    .unwrap();
    assert_relative_eq!(vicen.sum(), vol0, max_relative = 1e-13);
    for col in 0..g.ncol() {
        assert!((aice0[col] + aicen.column(col).sum() - 1.0).abs() < 1e-10);
    }
    assert!(r[2].iter().any(|&x| x > 0.0), "some ice must ridge");
}

#[test]
fn write_output_rejects_wrong_field_length() {
    let dir = common::scratch("itd-write-output-rejects-wrong-field-length");
    let g = small_grid(None);
    let meta = FieldMeta {
        name: "strength",
        units: "N m-1",
        long_name: "P",
        standard_name: None,
    };
    let data = [0.0; 5];
    let e = write_output(
        &dir.join("len.nc"),
        &Output {
            grid: &g,
            write_itd: false,
            hin_max: None,
            fields: &[(meta, &data)],
            category_fields: &[],
            dim_fields: &[],
            global: &[],
            fill: None,
            history: None,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NetcdfError::Shape { .. }));
}

/// CICE history strain rates (`divu`, `shear` in %/day) are converted to 1/s and the shear
/// term is formed as Icepack's ridging needs it; an unknown unit, or none, is refused by name.
#[test]
fn cice_history_rates_in_percent_per_day_are_converted_or_refused() {
    use pressridge::itd::details::deformation_terms;
    let dir = common::scratch("units");
    let write = |name: &str, units: &str| -> std::path::PathBuf {
        let p = dir.join(name);
        let mut f = netcdf::create(&p).unwrap();
        f.add_dimension("nc", 1).unwrap();
        f.add_dimension("ni", 2).unwrap();
        let mut a = f.add_variable::<f64>("aicen", &["nc", "ni"]).unwrap();
        a.put_values(&[0.9, 0.8], ..).unwrap();
        let mut v = f.add_variable::<f64>("vicen", &["nc", "ni"]).unwrap();
        v.put_values(&[0.9, 1.6], ..).unwrap();
        let mut d = f.add_variable::<f64>("divu", &["ni"]).unwrap();
        d.put_values(&[-8.64, 4.32], ..).unwrap();
        let mut s = f.add_variable::<f64>("shear", &["ni"]).unwrap();
        s.put_values(&[17.28, 0.0], ..).unwrap();
        // "" writes no attribute at all.
        if !units.is_empty() {
            for n in ["divu", "shear"] {
                f.variable_mut(n)
                    .unwrap()
                    .put_attribute("units", units)
                    .unwrap();
            }
        }
        p
    };
    let g = read_itd(&write("pct.nc", "%/day")).unwrap();
    let divu = g.divu.unwrap();
    assert!((divu[0] - -1e-6).abs() < 1e-20 && (divu[1] - 5e-7).abs() < 1e-20);
    let term = deformation_terms(-1e-6, 2e-6).1;
    assert!((g.shear.unwrap()[0] - term).abs() < 1e-20);
    let err = read_itd(&write("bad.nc", "m/s")).unwrap_err().to_string();
    assert!(
        err.contains("divu") && err.contains("m/s") && err.contains("%/day"),
        "{err}"
    );
    let g = read_itd(&write("s.nc", "s-1")).unwrap();
    assert_eq!(g.divu.unwrap()[0], -8.64, "1/s taken as given");
    // No `units` at all: refused, naming the variable, never taken for 1/s.
    let err = read_itd(&write("none.nc", "")).unwrap_err().to_string();
    assert!(err.contains("divu") && err.contains("no `units`"), "{err}");
}

#[test]
fn deformation_terms_are_icepacks() {
    use pressridge::itd::details::{deformation_terms, percent_per_day_to_per_second};
    // Pure convergence: all of it closes, no shear term.
    assert_eq!(deformation_terms(-2e-6, 0.0), (2e-6, 0.0));
    // Pure shear: Delta = shear/2 (e = 2), shear term = Delta/2.
    let (c, s) = deformation_terms(0.0, 4e-6);
    assert_eq!(c, 0.0);
    assert!((s - 1e-6).abs() < 1e-22);
    assert!((percent_per_day_to_per_second(8.64) - 1e-6).abs() < 1e-22);
}
