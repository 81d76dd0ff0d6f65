//! ns per column of the strength routine (ncat = 5, 1e6 columns, each option pair) and of
//! the ridging step (CICE defaults). Single-threaded. Divide the reported time by 1e6 (or
//! read criterion's throughput in elements/s).

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use ndarray::{Array1, Array2, ShapeBuilder};
use pressridge::itd::{
    CategoryBounds, ColumnMut, RidgeOptions, RidgeStepOptions, StepForcing, StepWorkspace,
    StrengthOptions, category_bounds,
    details::{
        CiceTracerFlags, Closing, OceanFluxes, Participation, Redistribution, RidgeBatchForcing,
        RidgeRatesMut, TracerLayout,
    },
    ridge_batch, ridge_step_column, strength_batch,
};

const NCAT: usize = 5;
const NCOL: usize = 1_000_000;

/// Icepack-like pseudo-random number in [0, 1): the generator of
/// `fortran-bridge/bench/bench_strength.f90` (`lcg`), so both benchmarks draw the same columns.
fn lcg(x: f64) -> f64 {
    (x * 9301.0 + 0.49297).rem_euclid(1.0)
}

/// The benchmark workload, column for column the Fortran benchmark's: 5–20 % open water,
/// category weights 0.2 + U(0, 1), thicknesses within ±20 % of 0.3, 1, 1.9, 3, 4.5 m.
/// aicen, vicen in Fortran order (ncat fastest), aice0.
fn columns_n(ncol: usize) -> (Array2<f64>, Array2<f64>, Array1<f64>) {
    let h_mid = [0.3, 1.0, 1.9, 3.0, 4.5];
    let mut a = Array2::zeros((NCAT, ncol).f());
    let mut v = Array2::zeros((NCAT, ncol).f());
    let mut a0 = Array1::zeros(ncol);
    let mut r = 0.5;
    for c in 0..ncol {
        r = lcg(r);
        let open = 0.05 + 0.15 * r;
        let mut w = [0.0; NCAT];
        for wn in w.iter_mut() {
            r = lcg(r);
            *wn = 0.2 + r;
        }
        let s: f64 = w.iter().sum();
        for n in 0..NCAT {
            a[[n, c]] = (1.0 - open) * w[n] / s;
            r = lcg(r);
            v[[n, c]] = a[[n, c]] * h_mid[n] * (0.8 + 0.4 * r);
        }
        // Sequential, as Fortran's sum(a(:, c)).
        let mut total = 0.0;
        for n in 0..NCAT {
            total += a[[n, c]];
        }
        a0[c] = 1.0 - total;
    }
    (a, v, a0)
}

fn columns() -> (Array2<f64>, Array2<f64>, Array1<f64>) {
    columns_n(NCOL)
}

/// Snow (10 % of the ice volume) and the 23 CICE tracers (7 ice layers, 1 snow layer, age,
/// first-year ice, level ice, ponds) of the complete step's benchmark, as the Fortran one.
fn snow_and_tracers(v: &Array2<f64>, ntrcr: usize) -> (Vec<f64>, Vec<f64>) {
    let ncol = v.ncols();
    let s: Vec<f64> = v.t().iter().map(|x| 0.1 * x).collect();
    let mut t = vec![0.0; ntrcr * NCAT * ncol];
    for cell in t.chunks_mut(ntrcr) {
        cell[0] = -20.0;
        for k in 0..7 {
            cell[1 + k] = -3.0e8 - 1.0e6 * k as f64;
            cell[9 + k] = 4.0 + 0.2 * k as f64;
        }
        cell[8] = -1.15e8;
        cell[16..23].copy_from_slice(&[2.0e7, 0.4, 0.8, 0.8, 0.2, 0.1, 0.01]);
    }
    (s, t)
}

fn bench(c: &mut Criterion) {
    let (a, v, a0) = columns();
    let mut out = Array1::zeros(NCOL);
    let mut g = c.benchmark_group("strength_ncat5_1e6_columns");
    g.throughput(Throughput::Elements(NCOL as u64));
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(8));
    for p in [Participation::Thorndike, Participation::Exponential] {
        for r in [Redistribution::Uniform, Redistribution::Exponential] {
            let o = StrengthOptions {
                participation: p,
                redistribution: r,
                ..Default::default()
            };
            g.bench_function(format!("{}_{}", p.name(), r.name()), |b| {
                b.iter(|| {
                    strength_batch(
                        a.view(),
                        v.view(),
                        Some(a0.view()),
                        black_box(&o),
                        out.view_mut(),
                    )
                    .unwrap()
                })
            });
        }
    }
    // Same default options on C-order (ncat, ncol) arrays: each column is gathered.
    let ac = a.as_standard_layout().into_owned();
    let vc = v.as_standard_layout().into_owned();
    let o = StrengthOptions::default();
    g.bench_function("exponential_exponential_c_order", |b| {
        b.iter(|| {
            strength_batch(ac.view(), vc.view(), Some(a0.view()), &o, out.view_mut()).unwrap()
        })
    });
    g.finish();

    let mut g = c.benchmark_group("ridge_step_ncat5_1e6_columns");
    g.throughput(Throughput::Elements(NCOL as u64));
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(8));
    let h = category_bounds(&CategoryBounds::RoundNumbers, NCAT).unwrap();
    let conv = Array1::from_elem(NCOL, 2e-6);
    let shear = Array1::from_elem(NCOL, 4e-6);
    let mut rates: [Array1<f64>; 5] = std::array::from_fn(|_| Array1::zeros(NCOL));
    g.bench_function("exponential_exponential", |b| {
        b.iter_batched_ref(
            || (a.clone(), v.clone(), a0.clone()),
            |(a, v, a0)| {
                let [c, o, d1, d2, dv] = &mut rates;
                ridge_batch(
                    a.view_mut(),
                    v.view_mut(),
                    a0.view_mut(),
                    &h,
                    RidgeBatchForcing {
                        convergence: conv.view(),
                        shear: shear.view(),
                        dt: 3600.0,
                        valid: None,
                    },
                    &RidgeOptions::default(),
                    RidgeRatesMut {
                        closing: c.view_mut(),
                        opening: o.view_mut(),
                        dardg1dt: d1.view_mut(),
                        dardg2dt: d2.view_mut(),
                        dvirdgdt: dv.view_mut(),
                        fill: f64::NAN,
                    },
                )
                .unwrap()
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.finish();
}

/// The complete ridging step (snow, 23 tracers, fluxes, clean-up; CICE defaults, rdg_conv
/// 2e-6 + rdg_shear 4e-6 1/s, dt 3600 s) per cell over 1e5 cells, one workspace.
fn bench_full_step(c: &mut Criterion) {
    const N: usize = 100_000;
    let layout = TracerLayout::cice(7, 1, CiceTracerFlags::ALL).unwrap();
    let nt = layout.ntrcr();
    let (a, v, a0) = columns_n(N);
    let a: Vec<f64> = a.t().iter().copied().collect();
    let vv: Vec<f64> = v.t().iter().copied().collect();
    let (s, t) = snow_and_tracers(&v, nt);
    let h = category_bounds(&CategoryBounds::RoundNumbers, NCAT).unwrap();
    let opts = RidgeStepOptions::default();
    let mut g = c.benchmark_group("ridge_step_full_ncat5_ntrcr23_1e5_cells");
    g.throughput(Throughput::Elements(N as u64));
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(8));
    let mut ws = StepWorkspace::new(NCAT, nt);
    g.bench_function("exponential_exponential", |b| {
        b.iter_batched_ref(
            || (a.clone(), vv.clone(), s.clone(), t.clone(), a0.to_vec()),
            |(a, v, s, t, a0)| {
                let mut fl = OceanFluxes::default();
                for c in 0..N {
                    let mut aice = 0.0;
                    let mut col = ColumnMut {
                        aicen: &mut a[c * NCAT..(c + 1) * NCAT],
                        vicen: &mut v[c * NCAT..(c + 1) * NCAT],
                        vsnon: &mut s[c * NCAT..(c + 1) * NCAT],
                        trcrn: &mut t[c * NCAT * nt..(c + 1) * NCAT * nt],
                        aice0: &mut a0[c],
                        aice: &mut aice,
                    };
                    let f = StepForcing {
                        closing: Closing::Deformation {
                            convergence: 2e-6,
                            shear: 4e-6,
                        },
                        dt: 3600.0,
                        ndtd: 1,
                        tf: -1.8,
                    };
                    ridge_step_column(&mut col, &h, f, &opts, &layout, &mut fl, &mut ws).unwrap();
                }
                black_box(fl)
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.finish();
}

criterion_group!(benches, bench, bench_full_step);
criterion_main!(benches);
