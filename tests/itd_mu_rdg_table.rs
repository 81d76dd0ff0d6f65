//! The exponential redistribution with μ_rdg per category thickness from a table
//! (`Redistribution::Table`, issue 34): a table of one value is the constant μ_rdg bit for
//! bit in the strength, the area-volume step and the complete step; each category's ridge
//! geometry takes μ_rdg at its own thickness (Lipscomb et al. 2007: k = (H_min + μ(h)√h)/h);
//! lookups outside the nodes are flagged. Conservation with a varying table is part of the
//! adversarial loop of `itd_ridge_step_conservation.rs`.

use pressridge::itd::{
    CategoryBounds, ColumnMut, ItdParams, RidgeForcing, RidgeOptions, RidgeStepOptions,
    StepForcing, StepWorkspace, StrengthOptions, Workspace, category_bounds,
    details::{CiceTracerFlags, Closing, MuRdgTable, OceanFluxes, Redistribution, TracerLayout},
    ridge_column, ridge_step_column, strength_batch, strength_column,
};

/// μ_rdg = `mu` at every thickness from 1 mm to 1 km (no lookup clamps).
fn flat(mu: f64) -> Redistribution {
    Redistribution::Table(MuRdgTable::new(&[1e-3, 1e3], &[mu, mu]).unwrap())
}

fn exponential(mu: f64) -> ItdParams {
    ItdParams {
        mu_rdg: mu,
        ..ItdParams::default()
    }
}

/// Columns of 5 categories with thicknesses across the bounds.
fn columns() -> Vec<([f64; 5], [f64; 5], f64)> {
    let mut out = Vec::new();
    for k in 0..40 {
        let x = f64::from(k);
        let a = [
            0.10 + 0.01 * (x % 7.0),
            0.20,
            0.15 + 0.005 * x,
            0.10,
            0.05 + 0.002 * x,
        ];
        let h = [0.3, 1.0, 1.9, 3.2, 5.0 + 0.1 * x];
        let v: Vec<f64> = a.iter().zip(h).map(|(a, h)| a * h).collect();
        let aice0 = 1.0 - a.iter().sum::<f64>();
        out.push((a, v.try_into().unwrap(), aice0));
    }
    out
}

#[test]
fn a_table_of_one_value_is_the_constant_mu_rdg_bit_for_bit() {
    let hin = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
    for mu in [1.5, 3.0] {
        let (table, constant) = (flat(mu), exponential(mu));
        // Strength, one column at a time and batched.
        let so = |r: Redistribution, p: ItdParams| StrengthOptions {
            redistribution: r,
            params: p,
            ..StrengthOptions::default()
        };
        let (st, sc) = (
            so(table, ItdParams::default()),
            so(Redistribution::Exponential, constant),
        );
        let mut ws = Workspace::new(5);
        let cols = columns();
        for (a, v, a0) in &cols {
            let x = strength_column(a, v, Some(*a0), &st, &mut ws).unwrap();
            let y = strength_column(a, v, Some(*a0), &sc, &mut ws).unwrap();
            assert_eq!(x.strength.to_bits(), y.strength.to_bits());
            assert!(x.strength > 0.0 && !x.mu_rdg_clamped);
        }
        let a = ndarray::Array2::from_shape_fn((5, cols.len()), |(n, c)| cols[c].0[n]);
        let v = ndarray::Array2::from_shape_fn((5, cols.len()), |(n, c)| cols[c].1[n]);
        let (mut pt, mut pc) = (
            ndarray::Array1::zeros(cols.len()),
            ndarray::Array1::zeros(cols.len()),
        );
        let s = strength_batch(a.view(), v.view(), None, &st, pt.view_mut()).unwrap();
        strength_batch(a.view(), v.view(), None, &sc, pc.view_mut()).unwrap();
        assert_eq!(pt, pc);
        assert_eq!(s.mu_rdg_clamped_columns, 0);
        // The area-volume step.
        let ro = |r: Redistribution, p: ItdParams| RidgeOptions {
            redistribution: r,
            params: p,
            ..RidgeOptions::default()
        };
        let forcing = RidgeForcing {
            convergence: 3e-6,
            shear: 1e-6,
            dt: 3600.0,
        };
        for (a, v, a0) in &cols {
            let run = |o: &RidgeOptions| {
                let (mut a, mut v, mut a0) = (*a, *v, *a0);
                let mut ws = Workspace::new(5);
                let d = ridge_column(&mut a, &mut v, &mut a0, &hin, forcing, o, &mut ws).unwrap();
                (a, v, a0, d.dardg2dt)
            };
            let x = run(&ro(table, ItdParams::default()));
            let y = run(&ro(Redistribution::Exponential, constant));
            assert_eq!(format!("{x:?}"), format!("{y:?}"));
        }
        // The complete step, tracers and fluxes included.
        let layout = TracerLayout::cice(4, 1, CiceTracerFlags::ALL).unwrap();
        let nt = layout.ntrcr();
        for (a, v, a0) in &cols {
            let run = |r: Redistribution, p: ItdParams| {
                let (mut a, mut v, mut a0) = (*a, *v, *a0);
                let mut s: Vec<f64> = a.iter().map(|x| 0.1 * x).collect();
                let mut t: Vec<f64> = (0..5 * nt)
                    .map(|i| match layout.field_of(i % nt).unwrap().0.name.as_str() {
                        "Tsfc" => -5.0,
                        "qice" => -3.0e8,
                        "qsno" => -1.2e8,
                        "sice" => 4.0,
                        _ => 0.3,
                    })
                    .collect();
                let mut aice: f64 = a.iter().sum();
                let mut fl = OceanFluxes::default();
                let mut ws = StepWorkspace::new(5, nt);
                let mut col = ColumnMut {
                    aicen: &mut a,
                    vicen: &mut v,
                    vsnon: &mut s,
                    trcrn: &mut t,
                    aice0: &mut a0,
                    aice: &mut aice,
                };
                let o = RidgeStepOptions {
                    redistribution: r,
                    params: p,
                    ..RidgeStepOptions::default()
                };
                let forcing = StepForcing {
                    closing: Closing::Deformation {
                        convergence: 3e-6,
                        shear: 1e-6,
                    },
                    dt: 3600.0,
                    ndtd: 1,
                    tf: -1.8,
                };
                let d = ridge_step_column(&mut col, &hin, forcing, &o, &layout, &mut fl, &mut ws)
                    .unwrap();
                assert!(!d.mu_rdg_clamped);
                format!("{a:?} {v:?} {s:?} {t:?} {a0:?} {fl:?} {:?}", d.dardg2dt)
            };
            assert_eq!(
                run(table, ItdParams::default()),
                run(Redistribution::Exponential, constant)
            );
        }
    }
}

#[test]
fn each_category_ridges_with_mu_rdg_at_its_own_thickness() {
    // μ_rdg 1 m^½ at 0.5 m rising to 4 m^½ at 2.5 m, linear between.
    let t = MuRdgTable::new(&[0.5, 2.5], &[1.0, 4.0]).unwrap();
    let o = StrengthOptions {
        redistribution: Redistribution::Table(t),
        ..StrengthOptions::default()
    };
    let a = [0.3, 0.3, 0.3];
    let h = [0.5, 1.5, 2.5];
    let v: Vec<f64> = a.iter().zip(h).map(|(a, h)| a * h).collect();
    let mut ws = Workspace::new(3);
    let r = strength_column(&a, &v, Some(0.1), &o, &mut ws).unwrap();
    assert!(r.strength > 0.0 && !r.mu_rdg_clamped);
    // Lipscomb et al. (2007): H_min = min(2h, h + 1 m), λ = μ(h)·√h, k = (H_min + λ)/h.
    for (n, (h, mu)) in h.iter().zip([1.0, 2.5, 4.0]).enumerate() {
        let hmin = f64::min(2.0 * h, h + 1.0);
        let k = (hmin + mu * h.sqrt()) / h;
        assert!(
            (ws.krdg()[n] - k).abs() <= 1e-14 * k,
            "category {n}: k {} against {k}",
            ws.krdg()[n]
        );
    }
    // Thinner ridged ice from the thin categories than with Icepack's μ_rdg = 3 gains less
    // potential energy: the strength lies between those of μ_rdg = 1 and 4 throughout.
    let mut at = |mu: f64| {
        let o = StrengthOptions {
            params: exponential(mu),
            ..StrengthOptions::default()
        };
        strength_column(&a, &v, Some(0.1), &o, &mut ws)
            .unwrap()
            .strength
    };
    let (lo, hi) = (at(1.0), at(4.0));
    assert!(lo < r.strength && r.strength < hi);
}

#[test]
fn lookups_outside_the_nodes_are_flagged_and_counted() {
    let t = MuRdgTable::new(&[0.2, 1.0], &[2.0, 3.0]).unwrap();
    let o = StrengthOptions {
        redistribution: Redistribution::Table(t),
        ..StrengthOptions::default()
    };
    let mut ws = Workspace::new(2);
    // Inside the nodes: not clamped; a category of 3 m is, and uses μ_rdg = 3 m^½.
    let inside = strength_column(&[0.4, 0.4], &[0.12, 0.32], Some(0.2), &o, &mut ws).unwrap();
    assert!(!inside.mu_rdg_clamped);
    let thick = strength_column(&[0.4, 0.4], &[0.12, 1.2], Some(0.2), &o, &mut ws).unwrap();
    assert!(thick.mu_rdg_clamped);
    let p3 = StrengthOptions {
        params: exponential(3.0),
        ..StrengthOptions::default()
    };
    let k3 = {
        let mut w = Workspace::new(2);
        strength_column(&[0.4, 0.4], &[0.12, 1.2], Some(0.2), &p3, &mut w).unwrap();
        w.krdg()[1]
    };
    strength_column(&[0.4, 0.4], &[0.12, 1.2], Some(0.2), &o, &mut ws).unwrap();
    assert_eq!(ws.krdg()[1], k3);
    // A clamped category with no area does not count.
    let empty = strength_column(&[0.4, 0.0], &[0.12, 0.0], Some(0.6), &o, &mut ws).unwrap();
    assert!(!empty.mu_rdg_clamped);
}
