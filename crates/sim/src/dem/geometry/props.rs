//! Property tests of the contact geometry, with parry2d and a brute-force crossing search
//! as independent oracles (unit tests: most of what they check is crate-private).

use super::{Outline, V2, area_centroid, below_line, intersect, overlap};
use crate::dem::Shape;
use parry2d_f64::mass_properties::details::convex_polygon_area_and_center_of_mass;
use parry2d_f64::na::Point2;
use parry2d_f64::transformation::convex_polygons_intersection_points;
use proptest::prelude::*;

/// A block as the simulator makes them: a bevelled rectangle, rotated and placed.
fn block() -> impl Strategy<Value = Outline> {
    (
        0.1f64..3.0,
        0.1f64..2.0,
        prop::array::uniform4(0.0f64..0.5),
        -3.2f64..3.2,
        -1.5f64..1.5,
        -1.5f64..1.5,
    )
        .prop_map(|(w, h, bev, th, x, y)| {
            let m = 0.5 * w.min(h);
            let b = bev.map(|f| f * m);
            let s = Shape::bevelled_rectangle(w, h, b).unwrap();
            moved(s.outline(), th, V2::new(x, y))
        })
}

fn moved(o: &Outline, th: f64, d: V2) -> Outline {
    let (s, c) = th.sin_cos();
    let v: Vec<V2> = o.verts().iter().map(|p| p.rotate(c, s) + d).collect();
    Outline::from_slice(&v)
}

fn area(o: &Outline) -> f64 {
    area_centroid(o.verts()).0
}

/// Oracle of [`super::Poly::crossings`]: the points where the boundaries of two convex
/// polygons cross. For two overlapping convex polygons in general position there are
/// exactly two; vertex-on-edge contacts may report a point twice. Returns how many were
/// written to `out` (at most `out.len()`).
fn boundary_crossings(a: &Outline, b: &Outline, out: &mut [V2]) -> usize {
    let mut k = 0;
    let na = a.len();
    let nb = b.len();
    for i in 0..na {
        let p = a.verts()[i];
        let r = a.verts()[(i + 1) % na] - p;
        for j in 0..nb {
            let q = b.verts()[j];
            let s = b.verts()[(j + 1) % nb] - q;
            let den = r.cross(s);
            // Parallel (or collinear) edges have no isolated crossing point; the ends of a
            // collinear overlap are found where the neighbouring edges cross.
            if den.abs() <= 1e-12 * (r.norm() * s.norm()) {
                continue;
            }
            let qp = q - p;
            let t = qp.cross(s) / den;
            let u = qp.cross(r) / den;
            const TOL: f64 = 1e-12;
            if (-TOL..=1.0 + TOL).contains(&t) && (-TOL..=1.0 + TOL).contains(&u) {
                if k < out.len() {
                    out[k] = p + r * t;
                    k += 1;
                } else {
                    return k;
                }
            }
        }
    }
    k
}

fn to_parry(o: &Outline) -> Vec<Point2<f64>> {
    o.verts().iter().map(|p| Point2::new(p.x, p.y)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn overlap_area_is_bounded_and_symmetric(a in block(), b in block()) {
        let ab = intersect(&a, &b).area_centroid();
        let ba = intersect(&b, &a).area_centroid();
        let small = area(&a).min(area(&b));
        prop_assert!(ab.0 >= -1e-12 && ab.0 <= small * (1.0 + 1e-12) + 1e-12);
        prop_assert!((ab.0 - ba.0).abs() <= 1e-10 * small.max(1e-3));
        if ab.0 > 1e-9 {
            prop_assert!((ab.1 - ba.1).norm() < 1e-7);
        }
    }

    #[test]
    fn clipper_crossings_are_true_boundary_crossings(a in block(), b in block()) {
        let poly = intersect(&a, &b);
        let mut tagged = [V2::default(); 24];
        let k = poly.crossings(&a, &b, &mut tagged);
        let mut brute = [V2::default(); 128];
        let m = boundary_crossings(&a, &b, &mut brute);
        for p in &tagged[..k] {
            prop_assert!(brute[..m].iter().any(|q| (*p - *q).norm() < 1e-7),
                "{:?} is not a crossing of the two boundaries", p);
        }
        if poly.area_centroid().0 > 1e-6 {
            prop_assert!(k >= 2 || m < 2, "{} crossings found of {}", k, m);
        }
    }

    #[test]
    fn overlap_matches_parry(a in block(), b in block()) {
        let ours = intersect(&a, &b).area_centroid().0.max(0.0);
        let mut pts = Vec::new();
        convex_polygons_intersection_points(&to_parry(&a), &to_parry(&b), &mut pts);
        let theirs = if pts.len() >= 3 {
            convex_polygon_area_and_center_of_mass(&pts).0
        } else {
            0.0
        };
        prop_assert!((ours - theirs).abs() <= 1e-8 * area(&a).max(area(&b)),
            "ours {} parry {}", ours, theirs);
    }

    #[test]
    fn overlap_is_invariant_under_rigid_motion(
        a in block(), b in block(), th in -3.2f64..3.2, dx in -50.0f64..50.0, dy in -50.0f64..50.0
    ) {
        let d = V2::new(dx, dy);
        let (s, c) = th.sin_cos();
        let ca = area_centroid(a.verts()).1;
        let cb = area_centroid(b.verts()).1;
        let o1 = overlap(&a, &b, ca, cb);
        let (ma, mb) = (moved(&a, th, d), moved(&b, th, d));
        let o2 = overlap(&ma, &mb, ca.rotate(c, s) + d, cb.rotate(c, s) + d);
        match (o1, o2) {
            (Some(p), Some(q)) => {
                let scale = area(&a).max(area(&b));
                prop_assert!((p.area - q.area).abs() <= 1e-9 * scale);
                prop_assert!((p.centroid.rotate(c, s) + d - q.centroid).norm() < 1e-6);
                if p.area > 1e-6 * scale {
                    prop_assert!((p.normal.rotate(c, s) - q.normal).norm() < 1e-6,
                        "{:?} {:?}", p.normal.rotate(c, s), q.normal);
                }
                prop_assert!((q.normal.norm() - 1.0).abs() < 1e-12);
            }
            (None, None) => {}
            (p, q) => {
                // Only a vanishing overlap may appear on one side and not the other.
                let a = p.or(q).unwrap().area;
                prop_assert!(a < 1e-9, "one-sided overlap of {} m²", a);
            }
        }
    }

    #[test]
    fn normal_points_from_a_to_b_and_centroid_is_inside_both(a in block(), b in block()) {
        let ca = area_centroid(a.verts()).1;
        let cb = area_centroid(b.verts()).1;
        if let Some(o) = overlap(&a, &b, ca, cb) {
            prop_assert!(o.area.is_finite() && o.centroid.x.is_finite() && o.normal.x.is_finite());
            prop_assert!(o.normal.dot(cb - ca) >= -1e-12);
            for p in [&a, &b] {
                let v = p.verts();
                for k in 0..v.len() {
                    let e = v[(k + 1) % v.len()] - v[k];
                    prop_assert!(e.cross(o.centroid - v[k]) >= -1e-9 * e.norm());
                }
            }
        }
    }

    #[test]
    fn submerged_area_lies_between_zero_and_the_area(a in block(), level in -3.0f64..3.0) {
        let (s, c) = below_line(&a, level);
        let total = area(&a);
        prop_assert!(s >= 0.0 && s <= total * (1.0 + 1e-12));
        if s > 1e-12 {
            prop_assert!(c.y <= level + 1e-12);
        }
        // Above and below add up to the whole.
        let flipped: Vec<V2> = a.verts().iter().map(|p| V2::new(-p.x, 2.0 * level - p.y)).collect();
        let (above, _) = below_line(&Outline::from_slice(&flipped), level);
        prop_assert!((s + above - total).abs() < 1e-10 * total.max(1.0));
    }
}
