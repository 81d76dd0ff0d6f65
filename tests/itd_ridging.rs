//! The ridging step: a case derived by hand from Icepack's `ridge_ice`/`ridge_shift`,
//! conservation, positivity, excess-area removal and bad input.

use approx::assert_relative_eq;
use ndarray::{Array1, Array2};
use pressridge::itd::{
    CategoryBounds, ColumnError, ItdError, RidgeForcing, RidgeOptions, Workspace, category_bounds,
    details::{Participation, Redistribution, RidgeBatchForcing, RidgeRatesMut},
    ridge_batch, ridge_column,
};
use proptest::prelude::*;

fn run(
    aicen: &mut [f64],
    vicen: &mut [f64],
    aice0: &mut f64,
    hin_max: &[f64],
    f: RidgeForcing,
    o: &RidgeOptions,
) -> Result<pressridge::itd::RidgeDiagnostics, ColumnError> {
    let mut ws = Workspace::new(aicen.len());
    ridge_column(aicen, vicen, aice0, hin_max, f, o, &mut ws)
}

/// Hand-derived step (Thorndike participation, exponential redistribution).
/// ncat = 2, hin_max = (0, 1, 5) m, aice0 = 0.1, aicen = (0.9, 0), vicen = (0.45, 0) m
/// (h = 0.5 m), convergence 1e-6 1/s, shear 0, dt = 3600 s.
/// - ridge_prep: total area 1, closing_net = 1e-6, opening = closing_net + 0 = 1e-6 1/s.
/// - ridge_itd: G = (0.1, 1, 1); a_P0 = (1/0.15)(0.1)(2 − 0.1/0.15) = 8/9,
///   a_P1 = (1/0.15)(0.05)(2 − 0.25/0.15) = 1/9, a_P2 = 0 (empty).
///   h_min = min(1, 1.5) = 1 m, λ = 3√0.5 = 2.1213203 m, k = 3.1213203/0.5 = 6.242640687119286,
///   aksum = 8/9 + (1/9)(1 − 1/k) = 0.9822012643879421.
/// - ridge_shift: closing_gross = 1e-6/aksum = 1.0181212713294044e-6 1/s (no cut needed),
///   aice0 = 0.1 − (8/9)·closing_gross·3600 + 1e-6·3600 = 0.10034201193174591,
///   ardg1 = (1/9)·closing_gross·3600 = 4.0724850853176176e-4, ardg2 = ardg1/k
///   = 6.52365767858553e-5, virdg = 0.45·ardg1/0.9 = ardg1/2.
///   Ridges start at h_min = 1 m = hin_max(1): none fall in category 1, all (area and volume
///   fractions 1) in category 2.
/// - Result: aicen = (0.9 − ardg1, ardg2), vicen = (0.45 − ardg1/2, ardg1/2), total area 1.
#[test]
fn one_step_by_hand() {
    let o = RidgeOptions {
        participation: Participation::Thorndike,
        redistribution: Redistribution::Exponential,
        ..Default::default()
    };
    let mut a = [0.9, 0.0];
    let mut v = [0.45, 0.0];
    let mut a0 = 0.1;
    let f = RidgeForcing {
        convergence: 1e-6,
        shear: 0.0,
        dt: 3600.0,
    };
    let d = run(&mut a, &mut v, &mut a0, &[0.0, 1.0, 5.0], f, &o).unwrap();
    let ardg1 = 4.072_485_085_317_617_6e-4;
    let ardg2 = 6.523_657_678_585_53e-5;
    assert_eq!(d.niter, 1);
    assert_relative_eq!(a0, 0.100_342_011_931_745_91, max_relative = 1e-13);
    assert_relative_eq!(a[0], 0.9 - ardg1, max_relative = 1e-13);
    assert_relative_eq!(a[1], ardg2, max_relative = 1e-12);
    assert_relative_eq!(v[0], 0.45 - ardg1 / 2.0, max_relative = 1e-13);
    assert_relative_eq!(v[1], ardg1 / 2.0, max_relative = 1e-12);
    assert_relative_eq!(d.dardg1dt, ardg1 / 3600.0, max_relative = 1e-12);
    assert_relative_eq!(d.dardg2dt, ardg2 / 3600.0, max_relative = 1e-12);
    assert_relative_eq!(d.dvirdgdt, ardg1 / 2.0 / 3600.0, max_relative = 1e-12);
    assert_relative_eq!(d.opening, 1e-6, max_relative = 1e-12);
    assert_relative_eq!(d.closing, 1e-6, max_relative = 1e-15);
}

/// Shear contributes C_s = 0.25 of its rate to the net closing.
#[test]
fn shear_closes_at_cs_times_rate() {
    let o = RidgeOptions::default();
    let f = RidgeForcing {
        convergence: 0.0,
        shear: 4e-6,
        dt: 1800.0,
    };
    let mut a = [0.2, 0.5, 0.25];
    let mut v = [0.1, 0.75, 0.75];
    let mut a0 = 0.05;
    let d = run(&mut a, &mut v, &mut a0, &[0.0, 0.6, 1.6, 5.0], f, &o).unwrap();
    assert_relative_eq!(d.closing, 1e-6, max_relative = 1e-15);
    // Net closing = ice area lost net of new ridges + open water closed:
    // (ardg1 − ardg2)/dt + (aice0_before + opening·dt − aice0_after)/dt = C_s · shear.
    let water_closed = (0.05 + d.opening * 1800.0 - a0) / 1800.0;
    assert_relative_eq!(
        d.dardg1dt - d.dardg2dt + water_closed,
        1e-6,
        max_relative = 1e-9
    );
    assert!(d.dardg1dt > 0.0);
    assert_relative_eq!(d.opening, 1e-6, max_relative = 1e-9);
}

/// Advection left total area 1.06: ridging removes the excess without any deformation.
#[test]
fn removes_excess_area_left_by_advection() {
    for p in [Participation::Thorndike, Participation::Exponential] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            let o = RidgeOptions {
                participation: p,
                redistribution: r,
                ..Default::default()
            };
            let mut a = [0.3, 0.4, 0.3, 0.06, 0.0];
            let mut v = [0.15, 0.6, 0.75, 0.2, 0.0];
            let vol0: f64 = v.iter().sum();
            let mut a0 = 0.0;
            let f = RidgeForcing {
                convergence: 0.0,
                shear: 0.0,
                dt: 3600.0,
            };
            let h = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
            let d = run(&mut a, &mut v, &mut a0, &h, f, &o).unwrap();
            assert_relative_eq!(a0 + a.iter().sum::<f64>(), 1.0, max_relative = 1e-11);
            assert_relative_eq!(v.iter().sum::<f64>(), vol0, max_relative = 1e-14);
            assert_relative_eq!(d.closing, 0.06 / 3600.0, max_relative = 1e-12);
            assert!(a.iter().chain(&v).all(|x| *x >= 0.0) && a0 >= 0.0);
        }
    }
}

#[test]
fn divergence_opens_water_and_empty_column_becomes_open_water() {
    let o = RidgeOptions::default();
    let f = RidgeForcing {
        convergence: 0.0,
        shear: 0.0,
        dt: 600.0,
    };
    let mut a = [0.3, 0.5];
    let mut v = [0.3, 1.0];
    let mut a0 = 0.1; // total 0.9: advection spread the ice
    run(&mut a, &mut v, &mut a0, &[0.0, 1.0, 3.0], f, &o).unwrap();
    assert_relative_eq!(a0, 0.2, max_relative = 1e-12);
    assert_eq!((a, v), ([0.3, 0.5], [0.3, 1.0]));

    // Empty column: CICE divides by aksum = 0; here it becomes open water.
    let mut a = [0.0, 0.0];
    let mut v = [0.0, 0.0];
    let mut a0 = 0.0;
    let f = RidgeForcing {
        convergence: 1e-5,
        shear: 1e-5,
        dt: 600.0,
    };
    run(&mut a, &mut v, &mut a0, &[0.0, 1.0, 3.0], f, &o).unwrap();
    assert_eq!(a0, 1.0);
    assert_eq!(a, [0.0, 0.0]);
}

/// Strong convergence on thin ice cuts the rates (no category overdrawn) and iterates.
#[test]
fn strong_convergence_never_overdraws_a_category() {
    for p in [Participation::Thorndike, Participation::Exponential] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            let o = RidgeOptions {
                participation: p,
                redistribution: r,
                ..Default::default()
            };
            let mut a = [0.6, 0.3, 0.0];
            let mut v = [0.06, 0.3, 0.0];
            let mut a0 = 0.3;
            let f = RidgeForcing {
                convergence: 1e-3,
                shear: 0.0,
                dt: 3600.0,
            };
            let vol0: f64 = v.iter().sum();
            let h = [0.0, 0.5, 2.0, 10.0];
            run(&mut a, &mut v, &mut a0, &h, f, &o).unwrap();
            assert!(
                a.iter().chain(&v).all(|x| *x >= 0.0) && a0 >= 0.0,
                "{a:?} {v:?} {a0}"
            );
            assert_relative_eq!(a0 + a.iter().sum::<f64>(), 1.0, max_relative = 1e-11);
            assert_relative_eq!(v.iter().sum::<f64>(), vol0, max_relative = 1e-13);
        }
    }
}

#[test]
fn bad_input_names_variable_and_column() {
    let ncat = 3;
    let ncol = 4;
    let h = [0.0, 0.6, 1.4, 2.4];
    let mut aicen = Array2::from_elem((ncat, ncol), 0.3);
    let mut vicen = Array2::from_elem((ncat, ncol), 0.3);
    let mut aice0 = Array1::from_elem(ncol, 0.1);
    let conv = Array1::from_elem(ncol, 1e-6);
    let mut shear = Array1::from_elem(ncol, 0.0);
    let mut r: [Array1<f64>; 5] = std::array::from_fn(|_| Array1::zeros(ncol));
    let o = RidgeOptions::default();
    macro_rules! go {
        () => {{
            let [c, op, d1, d2, dv] = r.each_mut();
            ridge_batch(
                aicen.view_mut(),
                vicen.view_mut(),
                aice0.view_mut(),
                &h,
                RidgeBatchForcing {
                    convergence: conv.view(),
                    shear: shear.view(),
                    dt: 3600.0,
                    valid: None,
                },
                &o,
                RidgeRatesMut {
                    closing: c.view_mut(),
                    opening: op.view_mut(),
                    dardg1dt: d1.view_mut(),
                    dardg2dt: d2.view_mut(),
                    dvirdgdt: dv.view_mut(),
                    fill: f64::NAN,
                },
            )
        }};
    }
    go!().unwrap();
    aicen[[2, 3]] = f64::NAN;
    let e = go!().unwrap_err();
    assert!(
        matches!(
            e,
            ItdError::Column {
                column: 3,
                source: ColumnError::NotFinite {
                    var: "aicen",
                    category: Some(2),
                    ..
                }
            }
        ),
        "{e}"
    );
    aicen[[2, 3]] = 0.3;
    shear[1] = -1e-6;
    let e = go!().unwrap_err();
    assert!(
        matches!(
            e,
            ItdError::Column {
                column: 1,
                source: ColumnError::Negative { var: "shear", .. }
            }
        ),
        "{e}"
    );
    shear[1] = 0.0;
    aice0[2] = 1.5; // total 2.4: no advection step leaves that much
    let e = go!().unwrap_err();
    assert!(
        matches!(
            e,
            ItdError::Column {
                column: 2,
                source: ColumnError::AreaTooLarge { .. }
            }
        ),
        "{e}"
    );
    aice0[2] = 0.1;
    vicen[[0, 0]] = -0.2;
    let e = go!().unwrap_err();
    assert!(
        matches!(
            e,
            ItdError::Column {
                column: 0,
                source: ColumnError::Negative {
                    var: "vicen",
                    category: Some(0),
                    ..
                }
            }
        ),
        "{e}"
    );
    // hin_max of the wrong length.
    let mut ws = Workspace::new(3);
    let mut a = [0.3; 3];
    let mut v = [0.3; 3];
    let mut a0 = 0.1;
    let f = RidgeForcing {
        convergence: 0.0,
        shear: 0.0,
        dt: 0.0,
    };
    assert!(matches!(
        ridge_column(&mut a, &mut v, &mut a0, &h, f, &o, &mut ws),
        Err(ColumnError::Negative { var: "dt", .. })
    ));
}

fn column() -> impl Strategy<Value = (Vec<f64>, Vec<f64>, f64)> {
    (
        prop::collection::vec((0.0f64..1.0, 0.02f64..6.0, prop::bool::weighted(0.2)), 5),
        0.0f64..0.3,
        0.9f64..1.15,
    )
        .prop_map(|(cats, a0w, total)| {
            let w: f64 = cats
                .iter()
                .map(|c| if c.2 { 0.0 } else { c.0 })
                .sum::<f64>()
                + a0w
                + 1e-9;
            let a: Vec<f64> = cats
                .iter()
                .map(|c| if c.2 { 0.0 } else { c.0 / w * total })
                .collect();
            let v: Vec<f64> = a.iter().zip(&cats).map(|(a, c)| a * c.1).collect();
            (a, v, a0w / w * total)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    /// Area comes out at 1, volume is conserved to round-off, nothing goes negative, no NaN,
    /// for every option pair.
    #[test]
    fn ridging_conserves_and_stays_positive(
        (a, v, a0) in column(),
        conv in 0.0f64..2e-5,
        shear in 0.0f64..2e-5,
        dt in 60.0f64..7200.0,
        pi in 0usize..2,
        ri in 0usize..2,
    ) {
        let o = RidgeOptions {
            participation: [Participation::Thorndike, Participation::Exponential][pi],
            redistribution: [Redistribution::Uniform, Redistribution::Exponential][ri],
            ..Default::default()
        };
        let h = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
        let (mut a, mut v, mut a0) = (a, v, a0);
        let vol0: f64 = v.iter().sum();
        let d = run(&mut a, &mut v, &mut a0, &h, RidgeForcing { convergence: conv, shear, dt }, &o).unwrap();
        let total = a0 + a.iter().sum::<f64>();
        prop_assert!((total - 1.0).abs() < 1e-10, "total {}", total);
        prop_assert!((v.iter().sum::<f64>() - vol0).abs() <= 1e-13 * vol0.max(1.0));
        prop_assert!(a.iter().chain(&v).all(|x| x.is_finite() && *x >= 0.0) && a0 >= 0.0);
        prop_assert!(d.dardg1dt >= d.dardg2dt && d.dardg2dt >= 0.0 && d.opening >= 0.0);
    }
}

/// The area-only step and the complete step (no snow, no cleanup) sum the areas in Icepack's
/// order (`asum_ridging`: open water first), so they agree to the bit on the benchmark
/// workload (5–20 % open water, thicknesses near 0.3, 1, 1.9, 3, 4.5 m) and on cells with an
/// area excess such as a total of 1.2, which both ridge to 1.
#[test]
fn area_only_step_is_bitwise_the_complete_step() {
    use pressridge::itd::{
        ColumnMut, RidgeStepOptions, StepForcing, StepWorkspace,
        details::{CiceTracerFlags, Closing, OceanFluxes, TracerLayout},
        ridge_step_column,
    };
    let layout = TracerLayout::cice(1, 1, CiceTracerFlags::default()).unwrap();
    let hin = category_bounds(&CategoryBounds::RoundNumbers, 5).unwrap();
    let h_mid = [0.3, 1.0, 1.9, 3.0, 4.5];
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut rnd = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut ws = Workspace::new(5);
    let mut sws = StepWorkspace::new(5, layout.ntrcr());
    for c in 0..20_000 {
        let excess = if c % 4 == 0 { 0.2 * rnd() } else { 0.0 };
        let mut a0 = if excess > 0.0 {
            0.0
        } else {
            0.05 + 0.15 * rnd()
        };
        let w: [f64; 5] = std::array::from_fn(|_| 0.2 + rnd());
        let s: f64 = w.iter().sum();
        let mut a: [f64; 5] = std::array::from_fn(|n| (1.0 - a0 + excess) * w[n] / s);
        let mut v: [f64; 5] = std::array::from_fn(|n| a[n] * h_mid[n] * (0.8 + 0.4 * rnd()));
        if excess == 0.0 {
            a0 = 1.0 - a.iter().sum::<f64>();
        }
        let (conv, shear, dt) = (2e-6 * rnd(), 4e-6 * rnd(), 3600.0);
        let (mut a2, mut v2, mut s2, mut a02) = (a, v, [0.0; 5], a0);
        let mut t2 = vec![-1.8; 5 * layout.ntrcr()];
        let o = RidgeOptions::default();
        let d = ridge_column(
            &mut a,
            &mut v,
            &mut a0,
            &hin,
            RidgeForcing {
                convergence: conv,
                shear,
                dt,
            },
            &o,
            &mut ws,
        )
        .unwrap();
        let so = RidgeStepOptions {
            cleanup: false,
            ..Default::default()
        };
        let mut aice = 0.0;
        let d2 = ridge_step_column(
            &mut ColumnMut {
                aicen: &mut a2,
                vicen: &mut v2,
                vsnon: &mut s2,
                trcrn: &mut t2,
                aice0: &mut a02,
                aice: &mut aice,
            },
            &hin,
            StepForcing {
                closing: Closing::Deformation {
                    convergence: conv,
                    shear,
                },
                dt,
                ndtd: 1,
                tf: -1.8,
            },
            &so,
            &layout,
            &mut OceanFluxes::default(),
            &mut sws,
        )
        .unwrap();
        assert_eq!(a, a2, "column {c}");
        assert_eq!(v, v2, "column {c}");
        assert_eq!(a0.to_bits(), a02.to_bits(), "column {c}");
        assert_eq!(d.dardg1dt.to_bits(), d2.dardg1dt.to_bits(), "column {c}");
        assert_eq!(d.niter, d2.niter);
        // The area-only step reports the opening summed over passes, Icepack (and the
        // complete step) that of the last pass: equal when one pass suffices.
        if d.niter == 1 {
            assert_eq!(d.opening.to_bits(), d2.opening.to_bits(), "column {c}");
        }
    }
}
