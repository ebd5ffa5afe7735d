//! The scalar trait that closed forms are written against.

use super::Jet;
use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A real scalar: `f64` for values, any [`Jet`] for exact derivatives.
///
/// Write a closed form once as `fn f<T: Real>(u: T, v: T) -> T`; call it with
/// `f64` for the value or with `Jet::var_u(u0)`, `Jet::var_v(v0)` for all its
/// derivatives at `(u0, v0)`. Constants enter as `T::cst(2.0)` or through the
/// mixed operators with `f64` (`x * 2.0`, `x + 1.0`).
pub trait Real:
    Copy
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
    + Mul<f64, Output = Self>
    + Div<f64, Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + 'static
{
    /// A constant.
    fn cst(x: f64) -> Self;
    /// The value part (for `f64`, itself).
    fn value(&self) -> f64;
    fn sqrt(self) -> Self;
    fn powi(self, n: i32) -> Self;
    fn powf(self, p: f64) -> Self;
    fn exp(self) -> Self;
    fn ln(self) -> Self;
    fn sin(self) -> Self;
    fn cos(self) -> Self;
    /// `(sin, cos)`, the angle reduced once.
    fn sin_cos(self) -> (Self, Self) {
        (self.sin(), self.cos())
    }
    fn tan(self) -> Self;
    fn atan(self) -> Self;
    /// `atan2(self, x)`.
    fn atan2(self, x: Self) -> Self;
    fn sinh(self) -> Self;
    fn cosh(self) -> Self;
    fn recip(self) -> Self;
    /// `1`.
    fn one() -> Self {
        Self::cst(1.0)
    }
    /// `0`.
    fn zero() -> Self {
        Self::cst(0.0)
    }
}

impl Real for f64 {
    fn cst(x: f64) -> Self {
        x
    }
    fn value(&self) -> f64 {
        *self
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n)
    }
    fn powf(self, p: f64) -> Self {
        f64::powf(self, p)
    }
    fn exp(self) -> Self {
        f64::exp(self)
    }
    fn ln(self) -> Self {
        f64::ln(self)
    }
    fn sin(self) -> Self {
        f64::sin(self)
    }
    fn cos(self) -> Self {
        f64::cos(self)
    }
    fn sin_cos(self) -> (Self, Self) {
        f64::sin_cos(self)
    }
    fn tan(self) -> Self {
        f64::tan(self)
    }
    fn atan(self) -> Self {
        f64::atan(self)
    }
    fn atan2(self, x: Self) -> Self {
        f64::atan2(self, x)
    }
    fn sinh(self) -> Self {
        f64::sinh(self)
    }
    fn cosh(self) -> Self {
        f64::cosh(self)
    }
    fn recip(self) -> Self {
        f64::recip(self)
    }
}

impl<const U: usize, const V: usize> Real for Jet<U, V> {
    fn cst(x: f64) -> Self {
        Jet::constant(x)
    }
    fn value(&self) -> f64 {
        Jet::value(self)
    }
    fn sqrt(self) -> Self {
        Jet::sqrt(&self)
    }
    fn powi(self, n: i32) -> Self {
        Jet::powi(&self, n)
    }
    fn powf(self, p: f64) -> Self {
        Jet::powf(&self, p)
    }
    fn exp(self) -> Self {
        Jet::exp(&self)
    }
    fn ln(self) -> Self {
        Jet::ln(&self)
    }
    fn sin(self) -> Self {
        Jet::sin(&self)
    }
    fn cos(self) -> Self {
        Jet::cos(&self)
    }
    fn sin_cos(self) -> (Self, Self) {
        Jet::sin_cos(&self)
    }
    fn tan(self) -> Self {
        Jet::tan(&self)
    }
    fn atan(self) -> Self {
        Jet::atan(&self)
    }
    fn atan2(self, x: Self) -> Self {
        Jet::atan2(&self, &x)
    }
    fn sinh(self) -> Self {
        Jet::sinh(&self)
    }
    fn cosh(self) -> Self {
        Jet::cosh(&self)
    }
    fn recip(self) -> Self {
        Jet::recip(&self)
    }
}
