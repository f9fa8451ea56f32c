//! 2-D vectors over any scalar.

use crate::scalar::{Rational, Scalar};

/// A planar point or vector with coordinates in `S`.
///
/// # Examples
/// ```
/// use lncert::curve::V2;
/// let a = V2::new(1.0, 2.0);
/// let b = V2::new(3.0, -1.0);
/// assert_eq!(a.cross(&b), -7.0);
/// assert_eq!(a.rot90(), V2::new(-2.0, 1.0));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct V2<S> {
    /// The first coordinate.
    pub x: S,
    /// The second coordinate.
    pub y: S,
}

impl<S: Scalar> V2<S> {
    /// The vector `(x, y)`.
    pub fn new(x: S, y: S) -> Self {
        V2 { x, y }
    }
    /// The zero vector `(0, 0)`.
    pub fn zero() -> Self {
        V2 {
            x: S::zero(),
            y: S::zero(),
        }
    }
    /// Converts exact coordinates into `S`.
    pub fn from_rational(p: &V2<Rational>) -> Self {
        V2 {
            x: S::from_rational(&p.x),
            y: S::from_rational(&p.y),
        }
    }
    /// `self + o`.
    pub fn add(&self, o: &Self) -> Self {
        V2 {
            x: self.x.clone() + o.x.clone(),
            y: self.y.clone() + o.y.clone(),
        }
    }
    /// `self - o`.
    pub fn sub(&self, o: &Self) -> Self {
        V2 {
            x: self.x.clone() - o.x.clone(),
            y: self.y.clone() - o.y.clone(),
        }
    }
    /// `-self`.
    pub fn neg(&self) -> Self {
        V2 {
            x: -self.x.clone(),
            y: -self.y.clone(),
        }
    }
    /// `k * self`.
    pub fn scale(&self, k: &S) -> Self {
        V2 {
            x: self.x.clone() * k.clone(),
            y: self.y.clone() * k.clone(),
        }
    }
    /// `(1-t) self + t o`.
    pub fn lerp(&self, o: &Self, t: &S) -> Self {
        self.add(&o.sub(self).scale(t))
    }
    /// `self.x * o.x + self.y * o.y`.
    pub fn dot(&self, o: &Self) -> S {
        self.x.clone() * o.x.clone() + self.y.clone() * o.y.clone()
    }
    /// `self.x * o.y - self.y * o.x`.
    pub fn cross(&self, o: &Self) -> S {
        self.x.clone() * o.y.clone() - self.y.clone() * o.x.clone()
    }
    /// Squared length.
    pub fn norm2(&self) -> S {
        self.dot(self)
    }
    /// Rotation by +pi/2: `R (x, y) = (-y, x)` (seed 000's `R`).
    pub fn rot90(&self) -> Self {
        V2 {
            x: -self.y.clone(),
            y: self.x.clone(),
        }
    }
    /// Maps both coordinates.
    pub fn map<T: Scalar>(&self, f: impl Fn(&S) -> T) -> V2<T> {
        V2 {
            x: f(&self.x),
            y: f(&self.y),
        }
    }
}

impl V2<f64> {
    /// As a glam vector (the f64 fast path).
    pub fn to_dvec2(&self) -> glam::DVec2 {
        glam::DVec2::new(self.x, self.y)
    }
}
