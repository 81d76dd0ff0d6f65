use super::*;

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Outline {
    Outline::from_slice(&[
        V2::new(x0, y0),
        V2::new(x1, y0),
        V2::new(x1, y1),
        V2::new(x0, y1),
    ])
}

#[test]
fn unit_square_area_and_centroid() {
    let (a, c) = rect(1.0, 2.0, 3.0, 3.0).area_centroid();
    assert!((a - 2.0).abs() < 1e-15);
    assert!((c.x - 2.0).abs() < 1e-15 && (c.y - 2.5).abs() < 1e-15);
}

#[test]
fn overlapping_rectangles() {
    let a = rect(0.0, 0.0, 2.0, 1.0);
    let b = rect(1.5, 0.9, 3.0, 2.0);
    let o = overlap(&a, &b, V2::new(1.0, 0.5), V2::new(2.25, 1.45)).unwrap();
    assert!((o.area - 0.5 * 0.1).abs() < 1e-14);
    assert!((o.centroid.x - 1.75).abs() < 1e-12 && (o.centroid.y - 0.95).abs() < 1e-12);
    // Crossings at (1.5, 1.0) and (2.0, 0.9): the chord is a diagonal of the overlap.
    let t = V2::new(0.5, -0.1);
    assert!(o.normal.dot(t).abs() < 1e-12);
    assert!(o.normal.dot(V2::new(1.25, 0.95)) > 0.0);
}

#[test]
fn contained_polygon_uses_centroid_direction() {
    let a = rect(0.0, 0.0, 4.0, 4.0);
    let b = rect(1.0, 2.0, 2.0, 3.0);
    let o = overlap(&a, &b, V2::new(2.0, 2.0), V2::new(1.5, 2.5)).unwrap();
    assert!((o.area - 1.0).abs() < 1e-14);
    let d = V2::new(-0.5, 0.5) * (1.0 / 0.5f64.hypot(0.5));
    assert!((o.normal - d).norm() < 1e-12);
}

#[test]
fn touching_and_separated_have_no_overlap() {
    let a = rect(0.0, 0.0, 1.0, 1.0);
    assert!(overlap(&a, &rect(1.0, 0.0, 2.0, 1.0), V2::default(), V2::default()).is_none());
    assert!(overlap(&a, &rect(1.0, 1.0, 2.0, 2.0), V2::default(), V2::default()).is_none());
    assert!(overlap(&a, &rect(3.0, 0.0, 4.0, 1.0), V2::default(), V2::default()).is_none());
}

#[test]
fn shared_collinear_edges_give_vertical_normal() {
    // b sits on a, sunk 1 mm, with both vertical edges flush (collinear edges).
    let a = rect(0.0, 0.0, 1.0, 1.0);
    let b = rect(0.0, 0.999, 1.0, 2.0);
    let o = overlap(&a, &b, V2::new(0.5, 0.5), V2::new(0.5, 1.5)).unwrap();
    assert!((o.area - 1e-3).abs() < 1e-12);
    assert!((o.normal.y - 1.0).abs() < 1e-9, "{:?}", o.normal);
    assert!(o.area.is_finite() && o.centroid.x.is_finite());
}

#[test]
fn flush_faces_give_a_normal_free_of_round_off() {
    // Side-by-side blocks whose top and bottom edges are collinear up to round-off:
    // the chord is the vertical shared face whichever corner round-off favours.
    for eps in [0.0, 3e-17, -3e-17, 1e-12, -1e-12] {
        let a = rect(-1.0, -0.15, 0.0005, 0.15);
        let b = rect(-0.0005, -0.15 + eps, 1.0, 0.15 - eps);
        let o = overlap(&a, &b, V2::new(-0.5, 0.0), V2::new(0.5, 0.0)).unwrap();
        assert!(o.normal.y.abs() < 1e-12, "eps {eps}: {:?}", o.normal);
        assert!((o.chord - 0.3).abs() < 1e-9);
    }
}

#[test]
fn submerged_part_of_a_tilted_square() {
    // A diamond with its lowest vertex at y = -1 and water line at y = 0.
    let d = Outline::from_slice(&[
        V2::new(0.0, -1.0),
        V2::new(1.0, 0.0),
        V2::new(0.0, 1.0),
        V2::new(-1.0, 0.0),
    ]);
    let (a, cen) = below_line(&d, 0.0);
    assert!((a - 1.0).abs() < 1e-14);
    assert!((cen.y + 1.0 / 3.0).abs() < 1e-14 && cen.x.abs() < 1e-14);
    assert_eq!(below_line(&d, -2.0).0, 0.0);
    assert!((below_line(&d, 5.0).0 - 2.0).abs() < 1e-14);
}

#[test]
fn rectangle_polar_moment() {
    let (w, h) = (0.25, 0.3);
    let r = rect(-w / 2.0, -h / 2.0, w / 2.0, h / 2.0);
    let j = polar_moment(r.verts());
    assert!((j - w * h * (w * w + h * h) / 12.0).abs() < 1e-15);
}
