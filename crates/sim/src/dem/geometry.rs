//! Plane geometry of convex polygons: intersection (overlap) polygons, area and centroid,
//! the points where two boundaries cross, and the part of a polygon below the water line.
//!
//! Everything here works on fixed-capacity, stack-allocated polygons so that the contact
//! loop never touches the heap. Why hand-written rather than `parry2d-f64`: see
//! `docs/model.md` ("Geometry") and `benches/dem.rs`; parry is kept as the test oracle.
//!
//! Lengths are in metres, areas in m² (per metre of depth these are volumes, m³/m).

use serde::{Deserialize, Serialize};
use std::ops::{Add, Mul, Neg, Sub};

/// A point or vector in the vertical plane: `x` horizontal (m), `y` up (m).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct V2 {
    /// Horizontal component (m).
    pub x: f64,
    /// Vertical component, positive up (m).
    pub y: f64,
}

impl V2 {
    /// The vector `(x, y)`.
    #[inline]
    pub const fn new(x: f64, y: f64) -> Self {
        Self { x, y }
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: V2) -> f64 {
        self.x * o.x + self.y * o.y
    }
    /// z-component of the cross product `self × o`.
    #[inline]
    pub fn cross(self, o: V2) -> f64 {
        self.x * o.y - self.y * o.x
    }
    /// Euclidean length (no overflow guard: coordinates here are metres).
    #[inline]
    pub fn norm(self) -> f64 {
        (self.x * self.x + self.y * self.y).sqrt()
    }
    /// The vector rotated by +90° (counter-clockwise).
    #[inline]
    pub fn perp(self) -> V2 {
        V2::new(-self.y, self.x)
    }
    /// The vector rotated by the angle whose cosine and sine are given.
    #[inline]
    pub fn rotate(self, c: f64, s: f64) -> V2 {
        V2::new(c * self.x - s * self.y, s * self.x + c * self.y)
    }
}

impl Add for V2 {
    type Output = V2;
    #[inline]
    fn add(self, o: V2) -> V2 {
        V2::new(self.x + o.x, self.y + o.y)
    }
}
impl Sub for V2 {
    type Output = V2;
    #[inline]
    fn sub(self, o: V2) -> V2 {
        V2::new(self.x - o.x, self.y - o.y)
    }
}
impl Mul<f64> for V2 {
    type Output = V2;
    #[inline]
    fn mul(self, k: f64) -> V2 {
        V2::new(self.x * k, self.y * k)
    }
}
impl Neg for V2 {
    type Output = V2;
    #[inline]
    fn neg(self) -> V2 {
        V2::new(-self.x, -self.y)
    }
}

/// Capacity of a body outline: a rectangle with all four corners bevelled has 8 vertices.
pub const MAX_VERTS: usize = 8;
/// Capacity of a clipping buffer: the intersection of two convex `MAX_VERTS`-gons has at
/// most `2 · MAX_VERTS` vertices; a few extra slots absorb duplicated points in degenerate
/// (touching, collinear) configurations.
pub(crate) const CLIP_VERTS: usize = 2 * MAX_VERTS + 4;

/// A convex polygon with at most `N` vertices in counter-clockwise order, stored inline.
#[derive(Clone, Copy, Debug)]
pub struct Poly<const N: usize> {
    n: usize,
    p: [V2; N],
    /// Source of the edge from vertex i to vertex i + 1: `k < MAX_VERTS` for edge k of the
    /// first polygon of an intersection, `MAX_VERTS + j` for edge j of the second.
    tag: [u8; N],
}

impl<const N: usize> Default for Poly<N> {
    fn default() -> Self {
        Self {
            n: 0,
            p: [V2::default(); N],
            tag: [0; N],
        }
    }
}

impl<const N: usize> Poly<N> {
    /// A polygon from vertices in counter-clockwise order. Extra vertices beyond `N` are
    /// an error of the caller and are dropped (debug builds panic).
    pub fn from_slice(v: &[V2]) -> Self {
        debug_assert!(v.len() <= N, "polygon has {} > {N} vertices", v.len());
        let mut out = Self::default();
        for (k, &q) in v.iter().take(N).enumerate() {
            out.push(q, k as u8);
        }
        out
    }
    /// The vertices.
    #[inline]
    pub fn verts(&self) -> &[V2] {
        &self.p[..self.n]
    }
    /// Overwrites this polygon with `src` rotated by the angle of cosine `c` and sine `s`
    /// and moved by `d`, in place (no temporary copies).
    #[inline]
    pub(crate) fn set_transformed(&mut self, src: &Poly<N>, c: f64, s: f64, d: V2) {
        self.n = src.n;
        for k in 0..src.n {
            self.p[k] = src.p[k].rotate(c, s) + d;
            self.tag[k] = k as u8;
        }
    }
    /// Number of vertices.
    #[inline]
    pub fn len(&self) -> usize {
        self.n
    }
    /// True when the polygon has no vertex.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }
    #[inline]
    fn push(&mut self, q: V2, tag: u8) {
        if self.n < N {
            self.p[self.n] = q;
            self.tag[self.n] = tag;
            self.n += 1;
        } else {
            debug_assert!(false, "polygon capacity {N} exceeded");
        }
    }
    #[inline]
    fn clear(&mut self) {
        self.n = 0;
    }
    /// The points where the boundaries of the two polygons `a` and `b` cross, for this
    /// polygon being their intersection (from [`intersect`]`(a, b)`): the vertices where
    /// its boundary passes from one input's boundary to the other's, plus the vertices
    /// that lie on both boundaries (within 1 nm). With flush, collinear edges both ends of
    /// the shared segment count, so the chord does not hang on round-off. Written to
    /// `out`; returns how many.
    pub(crate) fn crossings(&self, a: &Outline, b: &Outline, out: &mut [V2]) -> usize {
        let mut k = 0;
        let second = |t: u8| t as usize >= MAX_VERTS;
        for i in 0..self.n {
            let incoming = second(self.tag[(i + self.n - 1) % self.n]);
            let outgoing = second(self.tag[i]);
            let crossing = incoming != outgoing || {
                // On one boundary only by its tags: is it also on the other?
                let other = if incoming { a } else { b };
                on_boundary(other, self.p[i])
            };
            if crossing && k < out.len() {
                out[k] = self.p[i];
                k += 1;
            }
        }
        k
    }
    /// Area (m², positive for counter-clockwise order) and centroid (m), by the shoelace
    /// formula; a degenerate polygon (area below 1e-18 m²) has the mean of its vertices as
    /// centroid.
    pub fn area_centroid(&self) -> (f64, V2) {
        area_centroid(self.verts())
    }
}

/// A body outline in world or body coordinates.
pub type Outline = Poly<MAX_VERTS>;
/// A clipping result (intersection polygon, submerged part).
pub(crate) type ClipPoly = Poly<CLIP_VERTS>;

/// Area (m², positive for counter-clockwise order) and centroid (m) of a simple polygon, by
/// the shoelace formula. Degenerate polygons (area below 1e-18 m²) report their area as
/// computed and the mean of their vertices as centroid, so the result is always finite.
pub(crate) fn area_centroid(v: &[V2]) -> (f64, V2) {
    let n = v.len();
    if n == 0 {
        return (0.0, V2::default());
    }
    // Work relative to the first vertex: keeps round-off small far from the origin.
    let o = v[0];
    let mut a2 = 0.0;
    let mut cx = 0.0;
    let mut cy = 0.0;
    for i in 1..n.saturating_sub(1) {
        let p = v[i] - o;
        let q = v[i + 1] - o;
        let c = p.cross(q);
        a2 += c;
        cx += (p.x + q.x) * c;
        cy += (p.y + q.y) * c;
    }
    let area = 0.5 * a2;
    if area.abs() < 1e-18 {
        let mut m = V2::default();
        for &p in v {
            m = m + p;
        }
        return (area, m * (1.0 / n as f64));
    }
    let k = 1.0 / (3.0 * a2);
    (area, V2::new(o.x + cx * k, o.y + cy * k))
}

/// Second moment of area about the centroid (polar, m⁴) of a counter-clockwise polygon
/// whose vertices are given relative to its centroid. Multiply by density (kg/m³) for the
/// moment of inertia per metre of depth (kg·m²/m).
pub(crate) fn polar_moment(v: &[V2]) -> f64 {
    let n = v.len();
    let mut s = 0.0;
    for i in 0..n {
        let p = v[i];
        let q = v[(i + 1) % n];
        let c = p.cross(q);
        s += c * (p.dot(p) + p.dot(q) + q.dot(q));
    }
    s / 12.0
}

/// Distance (m) within which a vertex counts as lying on a polygon's boundary.
const ON_TOL: f64 = 1e-9;

/// Clips `subject` to the half-plane to the left of the directed line `a → b`
/// (Sutherland–Hodgman step), writing into `out`. The new edge along the clipping line
/// gets the tag `line`; every other edge keeps the tag of the edge it is part of.
#[inline]
fn clip_left<const N: usize, const M: usize>(
    subject: &Poly<N>,
    a: V2,
    b: V2,
    line: u8,
    out: &mut Poly<M>,
) {
    out.clear();
    let n = subject.n;
    if n == 0 {
        return;
    }
    let d = b - a;
    let mut s = subject.p[n - 1];
    let mut ts = subject.tag[n - 1];
    let mut ds = d.cross(s - a);
    for i in 0..n {
        let e = subject.p[i];
        let te = subject.tag[i];
        let de = d.cross(e - a);
        if de >= 0.0 {
            if ds < 0.0 {
                // Entering: the point starts the remainder of edge s → e.
                out.push(s + (e - s) * (ds / (ds - de)), ts);
            }
            out.push(e, te);
        } else if ds >= 0.0 {
            // Leaving: from here the boundary runs along the clipping line.
            out.push(s + (e - s) * (ds / (ds - de)), line);
        }
        s = e;
        ts = te;
        ds = de;
    }
}

/// True when some edge of `a` has every vertex of `b` strictly outside it: the two convex
/// polygons are then disjoint (a separating axis along that edge's normal).
#[inline]
fn separated_by_edge_of(a: &Outline, b: &Outline) -> bool {
    let n = a.n;
    let mut p0 = a.p[n - 1];
    for i in 0..n {
        let p1 = a.p[i];
        let d = p1 - p0;
        if b.verts().iter().all(|&q| d.cross(q - p0) < 0.0) {
            return true;
        }
        p0 = p1;
    }
    false
}

/// The intersection of two convex counter-clockwise polygons. Allocation-free.
/// Touching polygons give a degenerate (zero-area) result, never NaN.
///
/// `a` is clipped by the half-plane left of each edge of `b` (Sutherland–Hodgman). Two
/// short cuts keep the cost low where most candidate pairs of a ridge are: boxes that
/// overlap while the blocks do not (a separating edge of `a` is looked for first, and an
/// edge of `b` with every vertex outside ends the clipping at once), and small overlaps at
/// a corner (an edge of `b` with every vertex inside leaves the polygon as it is, with no
/// copy).
///
/// Public, and hidden from the docs, only for the clipper benchmark (`benches/dem.rs`, against
/// parry2d): the simulator clips through [`overlap`]'s crate-private form.
#[doc(hidden)]
pub fn intersect(a: &Outline, b: &Outline) -> ClipPoly {
    let mut bufs = [ClipPoly::default(), ClipPoly::default()];
    intersect_in(a, b, &mut bufs).copied().unwrap_or_default()
}

/// [`intersect`] in two buffers of the caller's: a reference to the one holding the
/// result, `None` when the polygons do not overlap (the result is never copied).
fn intersect_in<'s>(a: &Outline, b: &Outline, bufs: &'s mut [ClipPoly; 2]) -> Option<&'s ClipPoly> {
    if a.n == 0 || b.n == 0 || separated_by_edge_of(a, b) {
        return None;
    }
    let [first, second] = bufs;
    let (mut cur, mut next) = (first, second);
    cur.clear();
    for (k, &q) in a.verts().iter().enumerate() {
        cur.push(q, k as u8);
    }
    let m = b.n;
    for i in 0..m {
        let p0 = b.p[i];
        let p1 = b.p[(i + 1) % m];
        let d = p1 - p0;
        let (mut inside, mut outside) = (0, 0);
        for &q in cur.verts() {
            if d.cross(q - p0) >= 0.0 {
                inside += 1;
            } else {
                outside += 1;
            }
        }
        if outside == 0 {
            continue;
        }
        if inside == 0 {
            return None;
        }
        clip_left(cur, p0, p1, (MAX_VERTS + i) as u8, next);
        std::mem::swap(&mut cur, &mut next);
        if cur.n == 0 {
            return None;
        }
    }
    Some(cur)
}

/// The part of a polygon below the horizontal line `y = level` (m), as a polygon.
pub(crate) fn clip_below(poly: &Outline, level: f64) -> ClipPoly {
    let mut out = ClipPoly::default();
    clip_below_into(poly, level, &mut out);
    out
}

/// [`clip_below`] into a buffer the caller keeps.
pub(crate) fn clip_below_into(poly: &Outline, level: f64, out: &mut ClipPoly) {
    // Left of the directed line from (1, level) to (0, level) is the half-plane below it.
    clip_left(
        poly,
        V2::new(1.0, level),
        V2::new(0.0, level),
        MAX_VERTS as u8,
        out,
    );
}

/// The part of a polygon below the horizontal line `y = level` (m): its area (m²) and
/// centroid (m). Returns zero area when the polygon is entirely above.
pub(crate) fn below_line(poly: &Outline, level: f64) -> (f64, V2) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for &p in poly.verts() {
        lo = lo.min(p.y);
        hi = hi.max(p.y);
    }
    if lo >= level {
        return (0.0, V2::default());
    }
    if hi <= level {
        return area_centroid(poly.verts());
    }
    clip_below(poly, level).area_centroid()
}

/// The geometry of a contact between two convex polygons `a` and `b`. Public, and hidden
/// from the docs, only as the result of [`overlap`].
#[doc(hidden)]
#[derive(Clone, Copy, Debug, Default)]
pub struct Overlap {
    /// Area of the intersection polygon (m²).
    pub area: f64,
    /// Centroid of the intersection polygon (m): the point where contact forces act.
    pub centroid: V2,
    /// Unit normal pointing from `a` towards `b`, perpendicular to the line through the
    /// two boundary crossing points (Hopkins 1994, "Dynamic Ridge Model").
    pub normal: V2,
    /// Distance between the two crossing points (m): the length of the contact surface.
    pub chord: f64,
}

/// Overlap of two convex polygons whose centroids are `ca` and `cb` (m). `None` when they
/// do not overlap with positive area.
///
/// The normal is perpendicular to the chord through the two boundary crossing points.
/// When there are more than two (flush, collinear edges give four; vertex-on-edge contacts
/// repeat a point) the chord is the principal axis of the crossing points, which is the
/// line through them when there are two. Its sign is chosen
/// so that it points from `a`'s centroid side to `b`'s. When the chord is undefined
/// (one polygon inside the other, or a touch of zero length) the normal falls back to the
/// direction between the centroids, and to `+y` if those coincide.
///
/// Public, and hidden from the docs, only for the contact-geometry benchmark
/// (`benches/dem.rs`): the simulator calls the crate-private `overlap_with`.
#[doc(hidden)]
pub fn overlap(a: &Outline, b: &Outline, ca: V2, cb: V2) -> Option<Overlap> {
    overlap_with(a, b, ca, cb, &mut OverlapScratch::default())
}

/// Working space of [`overlap_with`], kept by the caller so that no buffer is cleared per
/// pair.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct OverlapScratch {
    bufs: [ClipPoly; 2],
    pts: [V2; CLIP_VERTS],
}

/// [`overlap`] in the caller's working space.
pub(crate) fn overlap_with(
    a: &Outline,
    b: &Outline,
    ca: V2,
    cb: V2,
    scratch: &mut OverlapScratch,
) -> Option<Overlap> {
    let poly = intersect_in(a, b, &mut scratch.bufs)?;
    if poly.n < 3 {
        return None;
    }
    let (area, centroid) = poly.area_centroid();
    if area <= 0.0 {
        return None;
    }
    let pts = &mut scratch.pts;
    let k = poly.crossings(a, b, pts);
    let ab = cb - ca;
    let scale = a_scale(a).max(a_scale(b));
    let (dir, chord) = chord_direction(&pts[..k]);
    let normal = if chord > 1e-9 * scale {
        let n = dir.perp();
        if n.dot(ab) < 0.0 { -n } else { n }
    } else {
        let d = ab.norm();
        if d > 0.0 {
            ab * (1.0 / d)
        } else {
            V2::new(0.0, 1.0)
        }
    };
    Some(Overlap {
        area,
        centroid,
        normal,
        chord,
    })
}

/// True when `p`, a point inside or on the convex polygon, lies within 1 nm of its boundary.
#[inline]
fn on_boundary(poly: &Outline, p: V2) -> bool {
    let v = poly.verts();
    let n = v.len();
    (0..n).any(|j| {
        let d = v[(j + 1) % n] - v[j];
        let c = d.cross(p - v[j]);
        c * c <= ON_TOL * ON_TOL * d.dot(d)
    })
}

/// Unit direction and length (m) of the line through a set of crossing points: their
/// principal axis and their extent along it. The length is 0 when the direction is
/// undefined (fewer than two distinct points, or points spread evenly in all directions,
/// as when two squares overlap in an octagon).
fn chord_direction(pts: &[V2]) -> (V2, f64) {
    let k = pts.len();
    if k < 2 {
        return (V2::new(1.0, 0.0), 0.0);
    }
    if k == 2 {
        // The general case: the line through the two crossings.
        let d = pts[1] - pts[0];
        let len = d.norm();
        return if len > 0.0 {
            (d * (1.0 / len), len)
        } else {
            (V2::new(1.0, 0.0), 0.0)
        };
    }
    let mut m = V2::default();
    for &p in pts {
        m = m + p;
    }
    m = m * (1.0 / k as f64);
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for &p in pts {
        let d = p - m;
        sxx += d.x * d.x;
        sxy += d.x * d.y;
        syy += d.y * d.y;
    }
    let tr = sxx + syy;
    let disc = ((sxx - syy).powi(2) + 4.0 * sxy * sxy).sqrt();
    // Eigenvalues (tr ± disc)/2: insist on a clearly dominant axis.
    if tr <= 0.0 || disc < 0.5 * tr {
        return (V2::new(1.0, 0.0), 0.0);
    }
    let phi = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let dir = V2::new(phi.cos(), phi.sin());
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &p in pts {
        let s = (p - m).dot(dir);
        lo = lo.min(s);
        hi = hi.max(s);
    }
    (dir, hi - lo)
}

#[inline]
fn a_scale(p: &Outline) -> f64 {
    let mut s: f64 = 0.0;
    for &q in p.verts() {
        s = s.max(q.x.abs()).max(q.y.abs());
    }
    s.max(1.0)
}

/// Axis-aligned bounding box (m).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Aabb {
    /// Lower-left corner (m).
    pub(crate) min: V2,
    /// Upper-right corner (m).
    pub(crate) max: V2,
}

impl Aabb {
    /// The bounding box of a set of points.
    pub(crate) fn of(v: &[V2]) -> Aabb {
        let mut min = V2::new(f64::INFINITY, f64::INFINITY);
        let mut max = V2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        for &p in v {
            min.x = min.x.min(p.x);
            min.y = min.y.min(p.y);
            max.x = max.x.max(p.x);
            max.y = max.y.max(p.y);
        }
        Aabb { min, max }
    }
    /// True when the boxes overlap (touching counts).
    #[inline]
    pub(crate) fn overlaps(&self, o: &Aabb) -> bool {
        self.min.x <= o.max.x
            && o.min.x <= self.max.x
            && self.min.y <= o.max.y
            && o.min.y <= self.max.y
    }
}

#[cfg(test)]
mod props;

#[cfg(test)]
mod tests;
