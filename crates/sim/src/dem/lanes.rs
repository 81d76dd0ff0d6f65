//! Numbers and vectors for kernels written once for one body pair and evaluated for
//! several at a time: [`Real`] is `f64` or [`F4`] (four lanes), [`Vec2`] a vector of
//! either. Every operation is the IEEE operation of `f64` in each lane, so a kernel gives
//! the same bits per lane whatever the lane count; in a function compiled for AVX2 the
//! compiler turns an `F4` operation into one instruction on four lanes.
//!
//! Written here rather than with a SIMD crate: the kernels need only the four arithmetic
//! operations, negation and the square root, which plain arrays give once the compiler
//! vectorises them, and the instruction set is chosen at run time by the caller.

use super::geometry::V2;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

/// A real number, or four in lanes.
pub(crate) trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
{
    /// The number `x` (in every lane).
    fn splat(x: f64) -> Self;
    /// The square root (of each lane).
    fn sqrt(self) -> Self;
}

impl Real for f64 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
}

/// Four `f64` in lanes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct F4(pub(crate) [f64; 4]);

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for F4 {
            type Output = F4;
            #[inline(always)]
            fn $f(self, o: F4) -> F4 {
                let (a, b) = (self.0, o.0);
                F4([a[0] $op b[0], a[1] $op b[1], a[2] $op b[2], a[3] $op b[3]])
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);
lanewise!(Div, div, /);

impl Neg for F4 {
    type Output = F4;
    #[inline(always)]
    fn neg(self) -> F4 {
        F4(self.0.map(|x| -x))
    }
}
impl AddAssign for F4 {
    #[inline(always)]
    fn add_assign(&mut self, o: F4) {
        *self = *self + o;
    }
}
impl SubAssign for F4 {
    #[inline(always)]
    fn sub_assign(&mut self, o: F4) {
        *self = *self - o;
    }
}
impl Real for F4 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        F4([x; 4])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        F4(self.0.map(f64::sqrt))
    }
}

/// A vector of [`Real`]s, with the operations of [`V2`] in the same order.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Vec2<F> {
    pub(crate) x: F,
    pub(crate) y: F,
}

impl<F: Real> Vec2<F> {
    #[inline(always)]
    pub(crate) fn new(x: F, y: F) -> Self {
        Self { x, y }
    }
    /// As [`V2::dot`].
    #[inline(always)]
    pub(crate) fn dot(self, o: Self) -> F {
        self.x * o.x + self.y * o.y
    }
    /// As [`V2::cross`].
    #[inline(always)]
    pub(crate) fn cross(self, o: Self) -> F {
        self.x * o.y - self.y * o.x
    }
    /// As [`V2::norm`].
    #[inline(always)]
    pub(crate) fn norm(self) -> F {
        (self.x * self.x + self.y * self.y).sqrt()
    }
    /// As [`V2::perp`].
    #[inline(always)]
    pub(crate) fn perp(self) -> Self {
        Self::new(-self.y, self.x)
    }
    /// As [`V2::rotate`].
    #[inline(always)]
    pub(crate) fn rotate(self, c: F, s: F) -> Self {
        Self::new(c * self.x - s * self.y, s * self.x + c * self.y)
    }
}

impl<F: Real> Add for Vec2<F> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y)
    }
}
impl<F: Real> Sub for Vec2<F> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y)
    }
}
impl<F: Real> Mul<F> for Vec2<F> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, k: F) -> Self {
        Self::new(self.x * k, self.y * k)
    }
}

impl From<V2> for Vec2<f64> {
    #[inline(always)]
    fn from(v: V2) -> Self {
        Self::new(v.x, v.y)
    }
}
impl From<Vec2<f64>> for V2 {
    #[inline(always)]
    fn from(v: Vec2<f64>) -> Self {
        V2::new(v.x, v.y)
    }
}

impl Vec2<F4> {
    /// Lane `l`.
    #[inline(always)]
    pub(crate) fn lane(&self, l: usize) -> V2 {
        V2::new(self.x.0[l], self.y.0[l])
    }
    /// Sets lane `l` to `v`.
    #[inline(always)]
    pub(crate) fn set_lane(&mut self, l: usize, v: V2) {
        self.x.0[l] = v.x;
        self.y.0[l] = v.y;
    }
}
