//! The natural cubic spline through values $y_i$ at increasing knots $t_i$:
//! cubic on each $[t_i, t_{i+1}]$, $C^2$ at the interior knots, zero second
//! derivative at both ends. With $M_i = s''(t_i)$ and $h_i = t_{i+1} - t_i$,
//! $$ s(t) = a\,y_i + b\,y_{i+1} + \big((a^3 - a) M_i + (b^3 - b) M_{i+1}\big)\frac{h_i^2}{6},
//! \quad a = \frac{t_{i+1} - t}{h_i},\ b = 1 - a, $$
//! and $C^1$ at the interior knots is the tridiagonal system
//! $\frac{h_{i-1}}{6} M_{i-1} + \frac{h_{i-1} + h_i}{3} M_i + \frac{h_i}{6} M_{i+1}
//! = \frac{y_{i+1} - y_i}{h_i} - \frac{y_i - y_{i-1}}{h_{i-1}}$, $M_0 = M_n = 0$
//! (solved by the Thomas algorithm: the matrix is diagonally dominant).
//!
//! Used by open polyline boundary curves ([`super::Curve::from_polyline`],
//! uniform knots in $v$) and by the natural-spline loft that the figures
//! compare with the ODE surfaces (knots at the curves' $u$).

use super::Ode6Error;
use crate::jet::Real;

/// A natural cubic spline in one variable.
#[derive(Clone, Debug, PartialEq)]
pub struct NaturalSpline {
    t: Vec<f64>,
    y: Vec<f64>,
    m2: Vec<f64>,
}

impl NaturalSpline {
    /// The spline through `y[i]` at `t[i]`; refuses fewer than two knots,
    /// lengths that differ, non-finite entries and knots that do not
    /// strictly increase.
    pub fn new(t: &[f64], y: &[f64]) -> Result<NaturalSpline, Ode6Error> {
        if t.len() < 2 || t.len() != y.len() {
            return Err(Ode6Error::SplineSize {
                knots: t.len(),
                values: y.len(),
            });
        }
        if let Some(&value) = t.iter().chain(y).find(|x| !x.is_finite()) {
            return Err(Ode6Error::NonFiniteValue {
                what: "spline knot or value",
                value,
            });
        }
        if let Some(i) = (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
            return Err(Ode6Error::KnotsNotIncreasing {
                index: i,
                previous: t[i - 1],
                knot: t[i],
            });
        }
        Ok(NaturalSpline {
            t: t.to_vec(),
            y: y.to_vec(),
            m2: second_derivatives(t, y),
        })
    }

    /// The second derivatives $M_i$ at the knots.
    pub fn second_derivatives(&self) -> &[f64] {
        &self.m2
    }

    /// `s(u)`; outside `[t_0, t_n]` the end cubic is extended.
    pub fn eval(&self, u: f64) -> f64 {
        // the last knot at or below `u` (binary search: the knots increase)
        let i = self
            .t
            .partition_point(|&t| t <= u)
            .saturating_sub(1)
            .min(self.t.len() - 2);
        segment(
            [self.t[i], self.t[i + 1]],
            [self.y[i], self.y[i + 1]],
            [self.m2[i], self.m2[i + 1]],
            u,
        )
    }
}

/// The cubic of one interval `[t0, t1]` with end values `y` and end second
/// derivatives `m2`, at `u` (generic: jets give its derivatives).
pub fn segment<T: Real>(t: [f64; 2], y: [f64; 2], m2: [f64; 2], u: T) -> T {
    let h = t[1] - t[0];
    let a = (T::cst(t[1]) - u) / h;
    let b = T::one() - a;
    a * y[0] + b * y[1] + ((a * a * a - a) * m2[0] + (b * b * b - b) * m2[1]) * (h * h / 6.0)
}

/// $M_0..M_n$ of the natural spline through `y` at `t` (strictly
/// increasing, as many as `y`; not checked here: [`NaturalSpline::new`]
/// checks them).
pub fn natural_second_derivatives(t: &[f64], y: &[f64]) -> Vec<f64> {
    second_derivatives(t, y)
}

/// $M_0..M_{n-1}$ of the **periodic** cubic spline through `y[0..n]` at
/// `t[0..n]`, closed by the knot `t[n]` where the values repeat (`y[n] =
/// y[0]`, `y` has `n + 1` entries). The C1 condition of the module doc at
/// every knot, indices modulo `n`, is a cyclic tridiagonal system, solved
/// in O(n) by the Thomas algorithm with a Sherman-Morrison correction for
/// the two corner entries (diagonally dominant, as the natural system).
/// With `n = 1` the spline is the constant `y[0]`.
pub fn periodic_second_derivatives(t: &[f64], y: &[f64]) -> Vec<f64> {
    let n = t.len().saturating_sub(1);
    if n < 2 {
        return vec![0.0; n.max(1)];
    }
    let h = |i: usize| t[i + 1] - t[i];
    let (mut sub, mut diag, mut sup, mut rhs) =
        (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for i in 0..n {
        let (ip, hm) = ((i + n - 1) % n, h((i + n - 1) % n));
        let hp = h(i);
        sub[i] = hm / 6.0;
        diag[i] = (hm + hp) / 3.0;
        sup[i] = hp / 6.0;
        rhs[i] = (y[i + 1] - y[i]) / hp - (y[i] - y[ip]) / hm;
    }
    if n == 2 {
        // both off-diagonal entries of a row land on the one other unknown
        let (a00, a01, a10, a11) = (diag[0], sub[0] + sup[0], sub[1] + sup[1], diag[1]);
        let det = a00 * a11 - a01 * a10;
        return vec![
            (rhs[0] * a11 - a01 * rhs[1]) / det,
            (a00 * rhs[1] - a10 * rhs[0]) / det,
        ];
    }
    // corners: row 0 names x[n-1] (sub[0]), row n-1 names x[0] (sup[n-1])
    let (beta, alpha) = (sub[0], sup[n - 1]);
    let gamma = -diag[0];
    diag[0] -= gamma;
    diag[n - 1] -= alpha * beta / gamma;
    let x = thomas(&sub, &diag, &sup, &rhs);
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = alpha;
    let z = thomas(&sub, &diag, &sup, &u);
    let fact = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
    x.iter().zip(&z).map(|(x, z)| x - fact * z).collect()
}

/// Solves the tridiagonal system `sub[i] x[i-1] + diag[i] x[i] + sup[i]
/// x[i+1] = rhs[i]` (`sub[0]` and `sup[n-1]` unused) by the Thomas
/// algorithm (no pivoting: the callers' systems are diagonally dominant).
fn thomas(sub: &[f64], diag: &[f64], sup: &[f64], rhs: &[f64]) -> Vec<f64> {
    let k = diag.len();
    let (mut d, mut r) = (diag.to_vec(), rhs.to_vec());
    for i in 1..k {
        let w = sub[i] / d[i - 1];
        d[i] -= w * sup[i - 1];
        r[i] -= w * r[i - 1];
    }
    let mut x = vec![0.0; k];
    x[k - 1] = r[k - 1] / d[k - 1];
    for i in (0..k - 1).rev() {
        x[i] = (r[i] - sup[i] * x[i + 1]) / d[i];
    }
    x
}

/// $M_0..M_n$ of the module doc (Thomas algorithm); `t` strictly increasing.
fn second_derivatives(t: &[f64], y: &[f64]) -> Vec<f64> {
    let n = t.len();
    let mut m2 = vec![0.0; n];
    if n < 3 {
        return m2;
    }
    let k = n - 2;
    let (mut sub, mut diag, mut sup, mut rhs) =
        (vec![0.0; k], vec![0.0; k], vec![0.0; k], vec![0.0; k]);
    for i in 1..n - 1 {
        let (h0, h1) = (t[i] - t[i - 1], t[i + 1] - t[i]);
        sub[i - 1] = h0 / 6.0;
        diag[i - 1] = (h0 + h1) / 3.0;
        sup[i - 1] = h1 / 6.0;
        rhs[i - 1] = (y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0;
    }
    let x = thomas(&sub, &diag, &sup, &rhs);
    m2[1..=k].copy_from_slice(&x);
    m2
}

#[cfg(test)]
mod tests {
    use super::periodic_second_derivatives;

    /// The cyclic system of [`periodic_second_derivatives`] solved densely
    /// (nalgebra LU, the reference the O(n) solve replaced).
    fn dense(t: &[f64], y: &[f64]) -> Vec<f64> {
        let n = t.len() - 1;
        let h = |i: usize| t[i + 1] - t[i];
        let mut a = nalgebra::DMatrix::<f64>::zeros(n, n);
        let mut rhs = nalgebra::DVector::<f64>::zeros(n);
        for i in 0..n {
            let (ip, hm) = ((i + n - 1) % n, h((i + n - 1) % n));
            let hp = h(i);
            a[(i, ip)] += hm / 6.0;
            a[(i, i)] += (hm + hp) / 3.0;
            a[(i, (i + 1) % n)] += hp / 6.0;
            rhs[i] = (y[i + 1] - y[i]) / hp - (y[i] - y[ip]) / hm;
        }
        a.lu()
            .solve(&rhs)
            .expect("regular")
            .iter()
            .copied()
            .collect()
    }

    /// Relative agreement of the O(n) and the dense solve (rounding of a
    /// well-conditioned system of size up to 60).
    const AGREE: f64 = 1e-11;

    #[test]
    fn the_cyclic_thomas_solve_matches_a_dense_lu() {
        for n in 2..60usize {
            // uneven knots and values from a fixed sequence
            let mut t = vec![0.0];
            for i in 0..n {
                t.push(t[i] + 0.3 + ((i * 37 + n) % 11) as f64 / 7.0);
            }
            let mut y: Vec<f64> = (0..n)
                .map(|i| ((i * i * 13 + n) % 17) as f64 - 8.0)
                .collect();
            y.push(y[0]);
            let fast = periodic_second_derivatives(&t, &y);
            let slow = dense(&t, &y);
            let scale = slow.iter().fold(1.0f64, |m, x| m.max(x.abs()));
            for (a, b) in fast.iter().zip(&slow) {
                assert!((a - b).abs() <= AGREE * scale, "n = {n}: {a} vs {b}");
            }
        }
    }
}
