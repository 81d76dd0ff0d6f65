//! The batched step against the column routine.

use super::*;
use crate::details::CiceTracerFlags;
use ndarray::{Array1, Array2, Array3};

/// The batch equals the column routine bit for bit, in any column order and stride.
#[test]
fn batch_equals_column_calls() {
    let flags = CiceTracerFlags {
        snow: true,
        isotopes: 1,
        aerosols: 2,
        ..CiceTracerFlags::ALL
    };
    let layout = TracerLayout::cice(2, 1, flags).unwrap();
    let nt = layout.ntrcr();
    let (ncat, ncol) = (3, 4);
    let hin = [0.0, 0.6, 1.4, 2.4];
    let mut aicen = Array2::from_shape_fn((ncat, ncol), |(n, c)| 0.1 + 0.05 * (n + c) as f64);
    let mut vicen = Array2::from_shape_fn((ncat, ncol), |(n, c)| {
        aicen[[n, c]] * (0.4 + 0.8 * n as f64)
    });
    let mut vsnon = Array2::from_shape_fn((ncat, ncol), |(n, _)| 0.02 * (n + 1) as f64);
    let mut trcrn = Array3::from_shape_fn((ncat, nt, ncol), |(n, it, c)| {
        let (f, _) = layout.field_of(it).unwrap();
        match f.name.as_str() {
            "Tsfc" => -5.0,
            "qice" => -3.0e8,
            "qsno" => -1.1e8,
            "sice" => 4.0,
            "iage" => 1e6 * (c + 1) as f64,
            _ => 0.1 * (n + 1) as f64,
        }
    });
    let mut aice0 = Array1::from_shape_fn(ncol, |c| 1.0 - aicen.column(c).sum());
    let mut aice = Array1::from_shape_fn(ncol, |c| aicen.column(c).sum());
    let conv = Array1::from_elem(ncol, 2e-6);
    let shear = Array1::from_shape_fn(ncol, |c| 1e-6 * c as f64);
    let tf = Array1::from_elem(ncol, -1.8);
    let opts = RidgeStepOptions::default();
    // Expected: column calls on copies.
    let mut want = Vec::new();
    for c in 0..ncol {
        let mut a = aicen.column(c).to_vec();
        let mut v = vicen.column(c).to_vec();
        let mut s = vsnon.column(c).to_vec();
        let mut t: Vec<f64> = (0..ncat)
            .flat_map(|n| (0..nt).map(move |it| (n, it)))
            .map(|(n, it)| trcrn[[n, it, c]])
            .collect();
        let (mut a0, mut ai) = (aice0[c], aice[c]);
        let mut fl = OceanFluxes::default();
        let mut ws = StepWorkspace::new(ncat, nt);
        let d = ridge_step_column(
            &mut ColumnMut {
                aicen: &mut a,
                vicen: &mut v,
                vsnon: &mut s,
                trcrn: &mut t,
                aice0: &mut a0,
                aice: &mut ai,
            },
            &hin,
            StepForcing {
                closing: Closing::Deformation {
                    convergence: conv[c],
                    shear: shear[c],
                },
                dt: 3600.0,
                ndtd: 1,
                tf: -1.8,
            },
            &opts,
            &layout,
            &mut fl,
            &mut ws,
        )
        .unwrap();
        want.push((a, v, s, t, a0, ai, fl, d, ws.krdgn.clone()));
    }
    let mut cells: Vec<Array1<f64>> = (0..CELL_OUTPUTS.len())
        .map(|_| Array1::zeros(ncol))
        .collect();
    let mut cats: Vec<Array2<f64>> = (0..CATEGORY_OUTPUTS.len())
        .map(|_| Array2::zeros((ncat, ncol)))
        .collect();
    let mut sp = [
        Array2::zeros((2, ncol)),
        Array2::zeros((1, ncol)),
        Array2::zeros((0, ncol)),
    ];
    let mut cell_views: Vec<_> = cells.iter_mut().map(|x| x.view_mut()).collect();
    let mut cat_views: Vec<_> = cats.iter_mut().map(|x| x.view_mut()).collect();
    let mut sp_views: Vec<_> = sp.iter_mut().map(|x| x.view_mut()).collect();
    ridge_step_batch(
        StepBatchMut {
            aicen: aicen.view_mut(),
            vicen: vicen.view_mut(),
            vsnon: vsnon.view_mut(),
            trcrn: trcrn.view_mut(),
            aice0: aice0.view_mut(),
            aice: aice.view_mut(),
        },
        &hin,
        BatchForcing {
            closing: BatchClosing::Deformation {
                convergence: conv.view(),
                shear: shear.view(),
            },
            tf: tf.view(),
            dt: 3600.0,
            ndtd: 1,
            valid: None,
        },
        &opts,
        &layout,
        StepBatchOutputs {
            cell: &mut cell_views,
            category: Some(&mut cat_views),
            species: Some(&mut sp_views),
            fill: f64::NAN,
        },
    )
    .unwrap();
    for (c, (a, v, s, t, a0, ai, fl, d, krdgn)) in want.iter().enumerate() {
        assert_eq!(aicen.column(c).to_vec(), *a);
        assert_eq!(vicen.column(c).to_vec(), *v);
        assert_eq!(vsnon.column(c).to_vec(), *s);
        for n in 0..ncat {
            for it in 0..nt {
                assert_eq!(trcrn[[n, it, c]].to_bits(), t[n * nt + it].to_bits());
            }
        }
        assert_eq!(aice0[c], *a0);
        assert_eq!(aice[c], *ai);
        assert_eq!(cells[0][c], fl.fresh);
        assert_eq!(cells[2][c], fl.fhocn);
        assert_eq!(cells[7][c], d.dardg1dt);
        assert_eq!(cats[4].column(c).to_vec(), *krdgn);
        assert_eq!(sp[0].column(c).to_vec(), fl.faero_ocn[..2]);
        assert_eq!(sp[1][[0, c]], fl.fiso_ocn[0]);
        assert!(
            fl.faero_ocn[1] > 0.0 && fl.fiso_ocn[0] > 0.0,
            "snow went to the ocean"
        );
    }
}
