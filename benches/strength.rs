//! ns per column of the strength routine (ncat = 5, 1e6 columns, each option pair) and of
//! the ridging step (CICE defaults). Single-threaded. Divide the reported time by 1e6 (or
//! read criterion's throughput in elements/s).

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use ndarray::{Array1, Array2, ShapeBuilder};
use pressridge::itd::{
    CategoryBounds, Participation, Redistribution, RidgeOptions, RidgeRatesMut, StrengthOptions,
    category_bounds, ridge_batch, strength_batch,
};

const NCAT: usize = 5;
const NCOL: usize = 1_000_000;

/// Deterministic pseudo-random columns: aicen, vicen in Fortran order (ncat fastest), aice0.
fn columns() -> (Array2<f64>, Array2<f64>, Array1<f64>) {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut rnd = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let h_mid = [0.3, 1.0, 1.9, 3.0, 4.5];
    let mut a = Array2::zeros((NCAT, NCOL).f());
    let mut v = Array2::zeros((NCAT, NCOL).f());
    let mut a0 = Array1::zeros(NCOL);
    for c in 0..NCOL {
        let w: [f64; NCAT + 1] = std::array::from_fn(|_| rnd());
        let s: f64 = w.iter().sum();
        let open = 0.2 * w[NCAT] / s;
        let ice = 1.0 - open;
        let si: f64 = w[..NCAT].iter().sum();
        for n in 0..NCAT {
            a[[n, c]] = ice * w[n] / si;
            v[[n, c]] = a[[n, c]] * h_mid[n] * (0.8 + 0.4 * rnd());
        }
        a0[c] = 1.0 - a.column(c).sum();
    }
    (a, v, a0)
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
                    conv.view(),
                    shear.view(),
                    3600.0,
                    &RidgeOptions::default(),
                    RidgeRatesMut {
                        closing: c.view_mut(),
                        opening: o.view_mut(),
                        dardg1dt: d1.view_mut(),
                        dardg2dt: d2.view_mut(),
                        dvirdgdt: dv.view_mut(),
                    },
                )
                .unwrap()
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
