//! Exact derivatives by truncated Taylor arithmetic in two variables.
//!
//! A [`Jet<U, V>`] is an element of the truncated polynomial ring
//! $\mathbb{R}[\delta u, \delta v] / (\delta u^{U}, \delta v^{V})$: it stores the
//! Taylor coefficients
//!
//! $$ f(u_0 + \delta u, v_0 + \delta v) = \sum_{i < U} \sum_{j < V} c_{ij}\, \delta u^i\, \delta v^j $$
//!
//! so that $\partial_u^i \partial_v^j f(u_0, v_0) = i!\, j!\, c_{ij}$ for every
//! $i < U$, $j < V$, mixed orders included. Because the ring is a quotient of
//! the polynomial ring, sums and products are exact (no truncation error), and
//! every elementary function $f$ is applied through its univariate Taylor
//! series at the value part $x_0$:
//!
//! $$ f(x_0 + h) = \sum_{k=0}^{K} \frac{f^{(k)}(x_0)}{k!} h^k, \qquad K = (U-1) + (V-1), $$
//!
//! which is exact in the ring because $h^{K+1} = 0$ for a jet $h$ with zero
//! value part. Derivatives therefore agree with the analytic ones to rounding.
//!
//! Closed forms are written once, generically over [`Real`], which `f64` and
//! every `Jet` implement: the `f64` instance gives the value, a jet instance
//! gives all derivatives up to the chosen orders from the same code.
//!
//! Aliases: [`Jet6x6`] (orders up to 6 in u and in v, for sixth-order PDEs),
//! [`Jet4x4`], [`Jet2x2`], and univariate [`Jet6`] / [`Jet8`] (`V = 1`).

pub mod check;
mod elementary;
mod real;

pub use real::Real;

use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// Truncated bivariate Taylor polynomial: `U` coefficients in u, `V` in v
/// (orders `0..U` and `0..V`). See the module documentation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet<const U: usize, const V: usize> {
    /// Taylor coefficients `c[i][j]` of `du^i dv^j` (not derivatives).
    pub c: [[f64; V]; U],
}

/// Orders up to 6 in u and 6 in v (mixed included): sixth-order PDE residuals.
pub type Jet6x6 = Jet<7, 7>;
/// Orders up to 4 in u and 4 in v: fourth-order PDE residuals.
pub type Jet4x4 = Jet<5, 5>;
/// Orders up to 2 in u and 2 in v: curvature and C2 checks.
pub type Jet2x2 = Jet<3, 3>;
/// Univariate, orders up to 6.
pub type Jet6 = Jet<7, 1>;
/// Univariate, orders up to 8.
pub type Jet8 = Jet<9, 1>;

/// `n!` as `f64` (exact for the small n used here).
pub fn factorial(n: usize) -> f64 {
    (1..=n).fold(1.0, |acc, k| acc * k as f64)
}

impl<const U: usize, const V: usize> Jet<U, V> {
    /// The zero jet.
    pub const ZERO: Self = Self { c: [[0.0; V]; U] };

    /// A constant (all derivatives zero).
    pub fn constant(x: f64) -> Self {
        let mut j = Self::ZERO;
        j.c[0][0] = x;
        j
    }

    /// The independent variable u at `u0` (du/du = 1).
    ///
    /// # Panics
    /// If `U < 2` (a jet without first order in u cannot carry it).
    pub fn var_u(u0: f64) -> Self {
        assert!(U >= 2, "Jet::var_u needs U >= 2");
        let mut j = Self::constant(u0);
        j.c[1][0] = 1.0;
        j
    }

    /// The independent variable v at `v0` (dv/dv = 1).
    ///
    /// # Panics
    /// If `V < 2`.
    pub fn var_v(v0: f64) -> Self {
        assert!(V >= 2, "Jet::var_v needs V >= 2");
        let mut j = Self::constant(v0);
        j.c[0][1] = 1.0;
        j
    }

    /// Value part f(u0, v0).
    pub fn value(&self) -> f64 {
        self.c[0][0]
    }

    /// The mixed derivative d^(i+j) f / du^i dv^j at (u0, v0); zero beyond the
    /// stored orders is *not* implied: asking for `i >= U` or `j >= V` panics.
    pub fn deriv(&self, i: usize, j: usize) -> f64 {
        self.c[i][j] * factorial(i) * factorial(j)
    }

    /// Largest order of the elementary-function series that is not zero in
    /// the ring: `(U - 1) + (V - 1)`.
    pub const fn max_total_order() -> usize {
        (U - 1) + (V - 1)
    }

    /// Applies the univariate Taylor series `f(x0 + h) = sum_k a[k] h^k` with
    /// `x0 = self.value()`, `h = self - x0` (Horner in the ring). `a` must hold
    /// at least `max_total_order() + 1` coefficients; extra ones are ignored.
    pub fn compose_series(&self, a: &[f64]) -> Self {
        let k = Self::max_total_order();
        debug_assert!(a.len() > k);
        let mut h = *self;
        h.c[0][0] = 0.0;
        let mut acc = Self::constant(a[k]);
        for i in (0..k).rev() {
            acc *= h;
            acc.c[0][0] += a[i];
        }
        acc
    }

    /// True when every coefficient is finite.
    pub fn is_finite(&self) -> bool {
        self.c.iter().flatten().all(|x| x.is_finite())
    }
}

impl<const U: usize, const V: usize> Default for Jet<U, V> {
    fn default() -> Self {
        Self::ZERO
    }
}

impl<const U: usize, const V: usize> Add for Jet<U, V> {
    type Output = Self;
    fn add(mut self, rhs: Self) -> Self {
        for i in 0..U {
            for j in 0..V {
                self.c[i][j] += rhs.c[i][j];
            }
        }
        self
    }
}

impl<const U: usize, const V: usize> Sub for Jet<U, V> {
    type Output = Self;
    fn sub(mut self, rhs: Self) -> Self {
        for i in 0..U {
            for j in 0..V {
                self.c[i][j] -= rhs.c[i][j];
            }
        }
        self
    }
}

impl<const U: usize, const V: usize> Neg for Jet<U, V> {
    type Output = Self;
    fn neg(mut self) -> Self {
        for row in self.c.iter_mut() {
            for x in row.iter_mut() {
                *x = -*x;
            }
        }
        self
    }
}

impl<const U: usize, const V: usize> Mul for Jet<U, V> {
    type Output = Self;
    /// Cauchy product truncated to the ring (exact).
    fn mul(self, rhs: Self) -> Self {
        let mut out = Self::ZERO;
        for i in 0..U {
            for j in 0..V {
                let mut s = 0.0;
                for a in 0..=i {
                    for b in 0..=j {
                        s += self.c[a][b] * rhs.c[i - a][j - b];
                    }
                }
                out.c[i][j] = s;
            }
        }
        out
    }
}

impl<const U: usize, const V: usize> Div for Jet<U, V> {
    type Output = Self;
    #[allow(clippy::suspicious_arithmetic_impl)] // a / b = a * (1 / b)
    fn div(self, rhs: Self) -> Self {
        self * rhs.recip()
    }
}

impl<const U: usize, const V: usize> Add<f64> for Jet<U, V> {
    type Output = Self;
    fn add(mut self, rhs: f64) -> Self {
        self.c[0][0] += rhs;
        self
    }
}

impl<const U: usize, const V: usize> Sub<f64> for Jet<U, V> {
    type Output = Self;
    fn sub(mut self, rhs: f64) -> Self {
        self.c[0][0] -= rhs;
        self
    }
}

impl<const U: usize, const V: usize> Mul<f64> for Jet<U, V> {
    type Output = Self;
    fn mul(mut self, rhs: f64) -> Self {
        for row in self.c.iter_mut() {
            for x in row.iter_mut() {
                *x *= rhs;
            }
        }
        self
    }
}

impl<const U: usize, const V: usize> Div<f64> for Jet<U, V> {
    type Output = Self;
    fn div(self, rhs: f64) -> Self {
        self * (1.0 / rhs)
    }
}

macro_rules! assign_ops {
    ($($tr:ident $m:ident $op:tt),*) => {$(
        impl<const U: usize, const V: usize> $tr for Jet<U, V> {
            fn $m(&mut self, rhs: Self) { *self = *self $op rhs; }
        }
        impl<const U: usize, const V: usize> $tr<f64> for Jet<U, V> {
            fn $m(&mut self, rhs: f64) { *self = *self $op rhs; }
        }
    )*};
}
assign_ops!(AddAssign add_assign +, SubAssign sub_assign -, MulAssign mul_assign *, DivAssign div_assign /);

impl<const U: usize, const V: usize> std::iter::Sum for Jet<U, V> {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::ZERO, |a, b| a + b)
    }
}
