//! Elementary functions on jets through their univariate Taylor series.
//!
//! Each function computes the coefficients `a_k = f^(k)(x0) / k!` for
//! `k = 0..=K` and composes them with the nilpotent part of the argument
//! ([`Jet::compose_series`]). The closed forms of the coefficients are the
//! textbook ones; `jet::check` verifies them against SymPy goldens.

use super::{factorial, Jet};

impl<const U: usize, const V: usize> Jet<U, V> {
    fn series_len() -> usize {
        Self::max_total_order() + 1
    }

    /// `1 / self`: `a_k = (-1)^k / x0^(k+1)`.
    pub fn recip(&self) -> Self {
        let x0 = self.value();
        let n = Self::series_len();
        let mut a = vec![0.0; n];
        let inv = 1.0 / x0;
        let mut p = inv;
        for (k, ak) in a.iter_mut().enumerate() {
            *ak = if k % 2 == 0 { p } else { -p };
            p *= inv;
        }
        self.compose_series(&a)
    }

    /// `self^p` for real `p` (value part must be positive unless `p` is a
    /// non-negative integer): `a_k = binom(p, k) x0^(p-k)`.
    pub fn powf(&self, p: f64) -> Self {
        if p >= 0.0 && p.fract() == 0.0 && p <= i32::MAX as f64 {
            return self.powi(p as i32);
        }
        let x0 = self.value();
        let n = Self::series_len();
        let mut a = vec![0.0; n];
        let mut binom = 1.0;
        for (k, ak) in a.iter_mut().enumerate() {
            if k > 0 {
                binom *= (p - (k as f64 - 1.0)) / k as f64;
            }
            *ak = binom * x0.powf(p - k as f64);
        }
        self.compose_series(&a)
    }

    /// `self^n` for integer `n` (exact binomial expansion for `n >= 0`, also
    /// at `x0 = 0`).
    pub fn powi(&self, n: i32) -> Self {
        if n < 0 {
            return self.recip().powi(-n);
        }
        let x0 = self.value();
        let len = Self::series_len();
        let mut a = vec![0.0; len];
        let mut binom = 1.0;
        for (k, ak) in a.iter_mut().enumerate() {
            if k as i64 > n as i64 {
                break;
            }
            if k > 0 {
                binom *= (n as f64 - (k as f64 - 1.0)) / k as f64;
            }
            *ak = binom * x0.powi(n - k as i32);
        }
        self.compose_series(&a)
    }

    /// Square root (`powf(0.5)`).
    pub fn sqrt(&self) -> Self {
        self.powf(0.5)
    }

    /// `exp`: `a_k = e^x0 / k!`.
    pub fn exp(&self) -> Self {
        let e = self.value().exp();
        let a: Vec<f64> = (0..Self::series_len()).map(|k| e / factorial(k)).collect();
        self.compose_series(&a)
    }

    /// Natural logarithm: `a_0 = ln x0`, `a_k = (-1)^(k+1) / (k x0^k)`.
    pub fn ln(&self) -> Self {
        let x0 = self.value();
        let mut a = vec![0.0; Self::series_len()];
        a[0] = x0.ln();
        let mut p = 1.0;
        for (k, ak) in a.iter_mut().enumerate().skip(1) {
            p /= x0;
            let s = if k % 2 == 1 { 1.0 } else { -1.0 };
            *ak = s * p / k as f64;
        }
        self.compose_series(&a)
    }

    fn cyclic(&self, cycle: [f64; 4]) -> Self {
        let a: Vec<f64> = (0..Self::series_len())
            .map(|k| cycle[k % 4] / factorial(k))
            .collect();
        self.compose_series(&a)
    }

    /// Sine.
    pub fn sin(&self) -> Self {
        let (s, c) = self.value().sin_cos();
        self.cyclic([s, c, -s, -c])
    }

    /// Cosine.
    pub fn cos(&self) -> Self {
        let (s, c) = self.value().sin_cos();
        self.cyclic([c, -s, -c, s])
    }

    /// `(sin, cos)` from one `sin_cos` of the value.
    pub fn sin_cos(&self) -> (Self, Self) {
        let (s, c) = self.value().sin_cos();
        (self.cyclic([s, c, -s, -c]), self.cyclic([c, -s, -c, s]))
    }

    /// Tangent (`sin / cos`).
    pub fn tan(&self) -> Self {
        self.sin() / self.cos()
    }

    /// Hyperbolic sine.
    pub fn sinh(&self) -> Self {
        let (s, c) = (self.value().sinh(), self.value().cosh());
        self.cyclic([s, c, s, c])
    }

    /// Hyperbolic cosine.
    pub fn cosh(&self) -> Self {
        let (s, c) = (self.value().sinh(), self.value().cosh());
        self.cyclic([c, s, c, s])
    }

    /// Arc tangent: `atan(x0 + h) = atan(x0) + int_0^h dt / (1 + (x0 + t)^2)`,
    /// the integrand expanded by the reciprocal recurrence of
    /// `p(t) = (1 + x0^2) + 2 x0 t + t^2`.
    pub fn atan(&self) -> Self {
        let x0 = self.value();
        let n = Self::series_len();
        let (p0, p1, p2) = (1.0 + x0 * x0, 2.0 * x0, 1.0);
        let mut r = vec![0.0; n];
        r[0] = 1.0 / p0;
        for k in 1..n {
            let mut s = p1 * r[k - 1];
            if k >= 2 {
                s += p2 * r[k - 2];
            }
            r[k] = -s / p0;
        }
        let mut a = vec![0.0; n];
        a[0] = x0.atan();
        for k in 1..n {
            a[k] = r[k - 1] / k as f64;
        }
        self.compose_series(&a)
    }

    /// Two-argument arc tangent `atan2(self, x)`, valid wherever
    /// `(x0, y0) != (0, 0)`: the derivatives come from `atan(y/x)` or
    /// `-atan(x/y)`, whichever quotient is bounded, and the value from
    /// `f64::atan2`.
    pub fn atan2(&self, x: &Self) -> Self {
        let (y0, x0) = (self.value(), x.value());
        let mut out = if x0.abs() >= y0.abs() {
            (*self / *x).atan()
        } else {
            -(*x / *self).atan()
        };
        out.c[0][0] = y0.atan2(x0);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::Jet;
    use crate::check::tol;

    /// A jet in one variable (`V = 1`) carries its derivatives through an
    /// elementary function: sin's are cos, -sin, -cos. The series' length
    /// is `max_total_order() + 1` with the order `(U - 1) + (V - 1)`; a
    /// product in place of the sum is 0 here and keeps only the value.
    #[test]
    fn one_variable_jets_carry_derivatives_through_sin() {
        let x = 0.7f64;
        let s = Jet::<4, 1>::var_u(x).sin();
        let want = [x.sin(), x.cos(), -x.sin(), -x.cos()];
        for (k, w) in want.iter().enumerate() {
            let got = s.deriv(k, 0);
            assert!(
                (got - w).abs() <= tol::ROUNDING,
                "d^{k}/du^{k}: {got} against {w}"
            );
        }
    }

    /// `powf` at a non-negative integer power is `powi`'s exact expansion,
    /// also at `x0 = 0`, where the general series' `x0^(p - k)` is
    /// infinite for `k > p` (and `0 * inf` is NaN): `(u + v)^2` at 0 has
    /// every second derivative 2 and nothing else.
    #[test]
    fn powf_at_an_integer_power_is_exact_at_zero() {
        let p = (Jet::<4, 4>::var_u(0.0) + Jet::var_v(0.0)).powf(2.0);
        for i in 0..4 {
            for j in 0..4 {
                let want = if i + j == 2 { 2.0 } else { 0.0 };
                let got = p.deriv(i, j);
                assert!((got - want).abs() <= tol::ROUNDING, "d^({i},{j}): {got}");
            }
        }
    }

    /// `x^0` is the constant 1 (every derivative 0), at `x0 = 0` too (the
    /// expansion's `0^0 = 1`), and `x^-2` is `1 / x^2`.
    #[test]
    fn the_zeroth_power_is_one_and_a_negative_power_a_reciprocal() {
        for x0 in [0.0f64, 0.7] {
            let p = (Jet::<3, 3>::var_u(x0) + Jet::var_v(x0)).powi(0);
            for i in 0..3 {
                for j in 0..3 {
                    let want = if (i, j) == (0, 0) { 1.0 } else { 0.0 };
                    assert_eq!(p.deriv(i, j), want, "x0 = {x0}, d^({i},{j})");
                }
            }
        }
        let x = Jet::<3, 3>::var_u(0.7) + Jet::var_v(0.3);
        let (neg, recip) = (x.powi(-2), x.powi(2).recip());
        for i in 0..3 {
            for j in 0..3 {
                let (a, b) = (neg.deriv(i, j), recip.deriv(i, j));
                assert!(
                    (a - b).abs() <= tol::ROUNDING * b.abs().max(1.0),
                    "d^({i},{j}): {a} against {b}"
                );
            }
        }
    }

    /// Subtracting a constant moves the value and nothing else: `x - c`
    /// at `x0` has the value `x0 - c`, the first derivative 1, the rest 0
    /// (as `x + (-c)`).
    #[test]
    fn subtracting_a_constant_moves_only_the_value() {
        let (x0, c) = (0.7f64, 2.5f64);
        let d = Jet::<3, 3>::var_u(x0) - c;
        let e = Jet::<3, 3>::var_u(x0) + (-c);
        for i in 0..3 {
            for j in 0..3 {
                let want = match (i, j) {
                    (0, 0) => x0 - c,
                    (1, 0) => 1.0,
                    _ => 0.0,
                };
                let (got, sum) = (d.deriv(i, j), e.deriv(i, j));
                assert!((got - want).abs() <= tol::ROUNDING, "d^({i},{j}): {got}");
                assert!(
                    (got - sum).abs() <= tol::ROUNDING,
                    "d^({i},{j}): {got} against {sum}"
                );
            }
        }
    }

    /// The f64 side of `Real` reads its value as itself (code generic over
    /// `Real` picks a chain's piece by it: `pde6::Chain::eval`).
    #[test]
    fn an_f64_is_its_own_value() {
        use super::super::Real;
        for x in [-3.25f64, 0.0, 1e-300, 7.5e12] {
            assert_eq!(Real::value(&x), x);
        }
        assert!(Real::value(&f64::NAN).is_nan());
    }

    /// Through the `Real` trait a jet's value is its value part, as an
    /// `f64`'s is itself: closed forms written against `Real` branch on it.
    #[test]
    fn a_jets_real_value_is_its_value_part() {
        use super::super::Real;
        for x0 in [-3.25f64, 0.7, 7.5e12] {
            let x = Jet::<2, 2>::var_u(x0) * 2.0 + Jet::var_v(1.0);
            assert_eq!(Real::value(&x), 2.0 * x0 + 1.0);
            assert_eq!(Real::value(&<Jet<2, 2> as Real>::cst(x0)), x0);
        }
    }
}
