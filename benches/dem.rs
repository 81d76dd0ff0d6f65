//! Criterion benchmarks of the simulator core (results in docs/performance.md):
//! - contact geometry: our allocation-free clipper against parry2d-f64, ns per pair;
//! - one time step of a settled 500-block rubble pile, µs per step.

use criterion::{Criterion, criterion_group, criterion_main};
use parry2d_f64::mass_properties::details::convex_polygon_area_and_center_of_mass;
use parry2d_f64::na::Point2;
use parry2d_f64::transformation::convex_polygons_intersection_points;
use pressridge::dem::{Outline, V2, intersect, overlap};
use pressridge::dem::{Shape, World};
use pressridge::scene::Scene;
use std::hint::black_box;

/// Pairs of bevelled 0.25 m × 0.30 m blocks overlapping by a few millimetres at random
/// angles, as in a rubble pile.
fn pairs() -> Vec<(Outline, Outline, V2, V2)> {
    let shape = Shape::bevelled_rectangle(0.25, 0.30, [0.02; 4]).unwrap();
    let mut s: u64 = 99;
    let mut rnd = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let place = |th: f64, p: V2| {
        let (sn, c) = th.sin_cos();
        let v: Vec<V2> = shape
            .outline()
            .verts()
            .iter()
            .map(|q| q.rotate(c, sn) + p)
            .collect();
        Outline::from_slice(&v)
    };
    (0..1000)
        .map(|_| {
            let (t1, t2) = (rnd() * 0.4 - 0.2, rnd() * 0.4 - 0.2);
            let c1 = V2::new(0.0, 0.0);
            let c2 = V2::new(rnd() * 0.1 - 0.05, 0.295 - rnd() * 0.01);
            (place(t1, c1), place(t2, c2), c1, c2)
        })
        .collect()
}

fn geometry(c: &mut Criterion) {
    let ps = pairs();
    let mut g = c.benchmark_group("contact_geometry_1000_pairs");
    g.bench_function("pressridge_intersect_area", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for (a, q, _, _) in &ps {
                acc += intersect(black_box(a), black_box(q)).area_centroid().0;
            }
            acc
        })
    });
    g.bench_function("pressridge_overlap_full", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for (a, q, ca, cb) in &ps {
                if let Some(o) = overlap(black_box(a), black_box(q), *ca, *cb) {
                    acc += o.area + o.normal.x;
                }
            }
            acc
        })
    });
    type Pts = Vec<Point2<f64>>;
    let pp: Vec<(Pts, Pts)> = ps
        .iter()
        .map(|(a, q, _, _)| {
            let f = |o: &Outline| o.verts().iter().map(|p| Point2::new(p.x, p.y)).collect();
            (f(a), f(q))
        })
        .collect();
    g.bench_function("parry_intersection_area", |b| {
        let mut out = Vec::new();
        b.iter(|| {
            let mut acc = 0.0;
            for (a, q) in &pp {
                out.clear();
                convex_polygons_intersection_points(black_box(a), black_box(q), &mut out);
                if out.len() >= 3 {
                    acc += convex_polygon_area_and_center_of_mass(&out).0;
                }
            }
            acc
        })
    });
    g.finish();
}

/// A 500-block pile settled in water for 6 s.
fn settled_pile() -> World {
    let scene = Scene::default()
        .with_overrides(&["pile.blocks=500", "pile.columns=20", "pile.basin_width=7.5"])
        .unwrap();
    let mut w = scene.build().unwrap();
    while w.time() < 6.0 {
        w.step();
    }
    w
}

fn step(c: &mut Criterion) {
    let world = settled_pile();
    let mut g = c.benchmark_group("step");
    g.sample_size(30);
    g.bench_function("settled_pile_500_blocks", |b| {
        let mut w = world.clone();
        b.iter(|| w.step())
    });
    g.finish();
    eprintln!(
        "settled pile: {} bodies, {} contacts, dt = {:.3e} s",
        world.bodies().len(),
        world.contacts().len(),
        world.dt()
    );
}

criterion_group!(benches, geometry, step);
criterion_main!(benches);
