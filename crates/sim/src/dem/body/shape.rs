//! A body's outline and its mass properties (area, centroid, polar moment), made from a
//! convex polygon or a rectangle with bevelled corners.

use super::super::geometry::{MAX_VERTS, Outline, V2, area_centroid, polar_moment};
use serde::{Deserialize, Serialize};

/// An error in a body's definition.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum ShapeError {
    /// Fewer than 3 or more than [`MAX_VERTS`] vertices.
    #[error("a block outline needs 3 to {MAX_VERTS} vertices, got {0}")]
    VertexCount(usize),
    /// A coordinate is NaN or infinite.
    #[error("a block outline has a non-finite coordinate")]
    NonFinite,
    /// The outline is not convex and counter-clockwise with positive area.
    #[error("a block outline must be convex, counter-clockwise and of positive area")]
    NotConvex,
    /// A dimension is not positive, or a bevel does not fit.
    #[error("invalid block dimensions: {0}")]
    Dimensions(String),
}

/// The outline of a block relative to its centroid, with its geometric properties.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(try_from = "ShapeDef", into = "ShapeDef")]
pub struct Shape {
    outline: Outline,
    area: f64,
    polar: f64,
    radius: f64,
}

/// Serialised form of a [`Shape`]: its vertices (m, relative to the centroid).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct ShapeDef {
    /// Counter-clockwise vertices (m).
    pub(crate) vertices: Vec<[f64; 2]>,
}

impl TryFrom<ShapeDef> for Shape {
    type Error = ShapeError;
    fn try_from(d: ShapeDef) -> Result<Self, ShapeError> {
        let v: Vec<V2> = d.vertices.iter().map(|p| V2::new(p[0], p[1])).collect();
        Shape::convex(&v)
    }
}

impl From<Shape> for ShapeDef {
    fn from(s: Shape) -> Self {
        ShapeDef {
            vertices: s.outline.verts().iter().map(|p| [p.x, p.y]).collect(),
        }
    }
}

impl Shape {
    /// A convex polygon from counter-clockwise vertices (m) in any frame; it is recentred on
    /// its centroid (the offset is lost: place the body with its centroid).
    pub fn convex(v: &[V2]) -> Result<Shape, ShapeError> {
        if v.len() < 3 || v.len() > MAX_VERTS {
            return Err(ShapeError::VertexCount(v.len()));
        }
        if v.iter().any(|p| !p.x.is_finite() || !p.y.is_finite()) {
            return Err(ShapeError::NonFinite);
        }
        let n = v.len();
        for i in 0..n {
            let e0 = v[(i + 1) % n] - v[i];
            let e1 = v[(i + 2) % n] - v[(i + 1) % n];
            if e0.cross(e1) < -1e-12 * e0.norm() * e1.norm() || e0.norm() == 0.0 {
                return Err(ShapeError::NotConvex);
            }
        }
        let (area, c) = area_centroid(v);
        if area <= 0.0 {
            return Err(ShapeError::NotConvex);
        }
        let local: Vec<V2> = v.iter().map(|&p| p - c).collect();
        let outline = Outline::from_slice(&local);
        let polar = polar_moment(outline.verts());
        let radius = local.iter().map(|p| p.norm()).fold(0.0, f64::max);
        Ok(Shape {
            outline,
            area,
            polar,
            radius,
        })
    }

    /// A rectangle `width × thickness` (m), sides parallel to the body axes.
    pub fn rectangle(width: f64, thickness: f64) -> Result<Shape, ShapeError> {
        Self::bevelled_rectangle(width, thickness, [0.0; 4])
    }

    /// A rectangle `width × thickness` (m) whose corners are cut at 45° with legs
    /// `bevel[k]` (m), corners ordered bottom-left, bottom-right, top-right, top-left
    /// (Hopkins 1994, Figure 1: the sheet tip, the floe nose, and 2 cm on the corners of a
    /// block broken from the sheet). A leg of 0 leaves the corner square.
    pub fn bevelled_rectangle(
        width: f64,
        thickness: f64,
        bevel: [f64; 4],
    ) -> Result<Shape, ShapeError> {
        Self::bevelled_rectangle_legs(width, thickness, bevel, bevel)
    }

    /// A rectangle `width × thickness` (m) whose corners are cut by straight bevels that
    /// drop `drop[k]` (m) along the vertical faces and run `run[k]` (m) along the horizontal
    /// faces (a bevel of slope drop/run, 45° when they are equal), corners ordered
    /// bottom-left, bottom-right, top-right, top-left. A corner with a zero leg stays square.
    pub fn bevelled_rectangle_legs(
        width: f64,
        thickness: f64,
        drop: [f64; 4],
        run: [f64; 4],
    ) -> Result<Shape, ShapeError> {
        if !(width > 0.0 && thickness > 0.0 && width.is_finite() && thickness.is_finite()) {
            return Err(ShapeError::Dimensions(format!(
                "width {width} m and thickness {thickness} m must be positive"
            )));
        }
        for k in 0..4 {
            let (d, r) = (drop[k], run[k]);
            if !(d >= 0.0 && d < thickness && r >= 0.0 && r < width) {
                return Err(ShapeError::Dimensions(format!(
                    "bevel {k} of drop {d} m and run {r} m must lie in [0, {thickness}) m and \
                     [0, {width}) m",
                )));
            }
            if (d > 0.0) != (r > 0.0) {
                return Err(ShapeError::Dimensions(format!(
                    "bevel {k} has a drop of {d} m and a run of {r} m: both or neither"
                )));
            }
        }
        // Neighbouring bevels must not meet: bottom, right, top and left sides in turn
        // (runs on the horizontal sides, drops on the vertical ones).
        for (k, side) in [width, thickness, width, thickness].iter().enumerate() {
            let legs = if k % 2 == 0 { &run } else { &drop };
            if legs[k] + legs[(k + 1) % 4] >= *side {
                return Err(ShapeError::Dimensions(format!(
                    "bevels {k} and {} ({} m, {} m) overlap on a side of {side} m",
                    (k + 1) % 4,
                    legs[k],
                    legs[(k + 1) % 4]
                )));
            }
        }
        let (w, h) = (0.5 * width, 0.5 * thickness);
        let corners = [
            (V2::new(-w, -h), V2::new(0.0, 1.0), V2::new(1.0, 0.0)),
            (V2::new(w, -h), V2::new(-1.0, 0.0), V2::new(0.0, 1.0)),
            (V2::new(w, h), V2::new(0.0, -1.0), V2::new(-1.0, 0.0)),
            (V2::new(-w, h), V2::new(1.0, 0.0), V2::new(0.0, -1.0)),
        ];
        let mut v = Vec::with_capacity(8);
        for (k, &(c, into_prev, into_next)) in corners.iter().enumerate() {
            if drop[k] > 0.0 {
                // The edge before a corner is vertical at even corners, horizontal at odd.
                let (before, after) = if k % 2 == 0 {
                    (drop[k], run[k])
                } else {
                    (run[k], drop[k])
                };
                v.push(c + into_prev * before);
                v.push(c + into_next * after);
            } else {
                v.push(c);
            }
        }
        Self::convex(&v)
    }

    /// Centroid of a bevelled rectangle relative to the rectangle's centre (m), for the
    /// bevels' drops `drop` and runs `run` (m) (see [`Shape::bevelled_rectangle_legs`]).
    pub(crate) fn bevel_centroid(width: f64, thickness: f64, drop: [f64; 4], run: [f64; 4]) -> V2 {
        // Each cut removes a right triangle of legs d (vertical) and r (horizontal) at a
        // corner; its centroid lies r/3 in from the corner along the horizontal side and
        // d/3 along the vertical one.
        let (w, h) = (0.5 * width, 0.5 * thickness);
        let corners = [
            V2::new(-w, -h),
            V2::new(w, -h),
            V2::new(w, h),
            V2::new(-w, h),
        ];
        let mut m = V2::default();
        let mut a = width * thickness;
        for (k, c) in corners.iter().enumerate() {
            let (d, r) = (drop[k], run[k]);
            if d > 0.0 {
                let tri = 0.5 * d * r;
                let inward = V2::new(-c.x.signum() * (r / 3.0), -c.y.signum() * (d / 3.0));
                m = m - (*c + inward) * tri;
                a -= tri;
            }
        }
        m * (1.0 / a)
    }

    /// Vertices relative to the centroid (m).
    #[inline]
    pub fn outline(&self) -> &Outline {
        &self.outline
    }
    /// Area (m², i.e. volume per metre of depth, m³/m).
    #[inline]
    pub fn area(&self) -> f64 {
        self.area
    }
    /// Polar second moment of area about the centroid (m⁴).
    #[inline]
    pub(crate) fn polar_moment(&self) -> f64 {
        self.polar
    }
    /// Largest distance from the centroid to a vertex (m).
    #[inline]
    pub(crate) fn radius(&self) -> f64 {
        self.radius
    }
    /// Largest distance between two vertices (m).
    pub(crate) fn diameter(&self) -> f64 {
        let v = self.outline.verts();
        let mut d: f64 = 0.0;
        for i in 0..v.len() {
            for j in i + 1..v.len() {
                d = d.max((v[i] - v[j]).norm());
            }
        }
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bevelled_rectangle_area_and_vertices() {
        let b = 0.02;
        let s = Shape::bevelled_rectangle(0.25, 0.3, [b; 4]).unwrap();
        assert_eq!(s.outline().len(), 8);
        assert!((s.area() - (0.25 * 0.3 - 4.0 * 0.5 * b * b)).abs() < 1e-15);
        let r = Shape::rectangle(0.25, 0.3).unwrap();
        assert!((r.polar_moment() - 0.075 * (0.0625 + 0.09) / 12.0).abs() < 1e-15);
        assert!((r.diameter() - 0.25f64.hypot(0.3)).abs() < 1e-15);
    }

    #[test]
    fn bevel_centroid_matches_the_polygon() {
        let bev = [0.05, 0.0, 0.12, 0.02];
        let c = Shape::bevel_centroid(0.25, 0.3, bev, bev);
        let (w, h) = (0.125, 0.15);
        let mut v = vec![];
        let corners = [(-w, -h), (w, -h), (w, h), (-w, h)];
        let (ip, inx) = (
            [(0., 1.), (-1., 0.), (0., -1.), (1., 0.)],
            [(1., 0.), (0., 1.), (-1., 0.), (0., -1.)],
        );
        for k in 0..4 {
            let (x, y) = corners[k];
            if bev[k] > 0.0 {
                v.push(V2::new(x + ip[k].0 * bev[k], y + ip[k].1 * bev[k]));
                v.push(V2::new(x + inx[k].0 * bev[k], y + inx[k].1 * bev[k]));
            } else {
                v.push(V2::new(x, y));
            }
        }
        let (_, want) = area_centroid(&v);
        assert!((c - want).norm() < 1e-15, "{c:?} {want:?}");
    }

    #[test]
    fn bad_shapes_are_rejected() {
        assert!(Shape::rectangle(0.0, 1.0).is_err());
        assert!(Shape::rectangle(f64::NAN, 1.0).is_err());
        assert!(Shape::bevelled_rectangle(1.0, 1.0, [0.6, 0.5, 0.0, 0.0]).is_err());
        assert!(Shape::bevelled_rectangle(1.0, 1.0, [0.6, 0.0, 0.0, 0.0]).is_ok());
        let cw = [V2::new(0.0, 0.0), V2::new(0.0, 1.0), V2::new(1.0, 0.0)];
        assert_eq!(Shape::convex(&cw).unwrap_err(), ShapeError::NotConvex);
        let dart = [
            V2::new(0.0, 0.0),
            V2::new(2.0, 0.0),
            V2::new(1.0, 0.2),
            V2::new(1.0, 1.0),
        ];
        assert_eq!(Shape::convex(&dart).unwrap_err(), ShapeError::NotConvex);
    }
}
