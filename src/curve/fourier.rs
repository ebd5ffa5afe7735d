//! Closed curves in space as finite Fourier series: the common currency
//! between generalized elliptic curves and the surface families.
//!
//! $$ \mathbf{P}(\theta) = \mathbf{c}_0 + \sum_{n=1}^{N} \left( \mathbf{c}_n \cos n\theta + \mathbf{s}_n \sin n\theta \right), \qquad \theta \in [0, 2\pi), $$
//!
//! with $\mathbf{c}_0, \mathbf{c}_n, \mathbf{s}_n \in \mathbb{R}^3$. A planar
//! generalized elliptic curve (paper 000 eq 16, paper 002 eq 1) placed in
//! space by a frame is such a series; the sixth-order PDE and ODE families
//! interpolate these coefficients harmonic by harmonic.

use crate::jet::Real;

/// A closed space curve as a finite Fourier series in `theta`.
///
/// Read from JSON as `{"c0": [x, y, z], "cos": [[...], ...], "sin": [[...], ...]}`:
/// unknown keys are refused, and so are `cos` and `sin` lists of different
/// lengths (pad the shorter with `[0, 0, 0]`), which would otherwise be read
/// silently as missing harmonics.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(try_from = "Fourier3Json")]
pub struct Fourier3 {
    /// Constant term (the centre).
    pub c0: [f64; 3],
    /// `cos[n - 1]` multiplies `cos(n theta)`, n = 1..=N.
    pub cos: Vec<[f64; 3]>,
    /// `sin[n - 1]` multiplies `sin(n theta)`, n = 1..=N.
    pub sin: Vec<[f64; 3]>,
}

/// The JSON form of [`Fourier3`], checked by `TryFrom`.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Fourier3Json {
    c0: [f64; 3],
    #[serde(default)]
    cos: Vec<[f64; 3]>,
    #[serde(default)]
    sin: Vec<[f64; 3]>,
}

impl TryFrom<Fourier3Json> for Fourier3 {
    type Error = String;
    fn try_from(j: Fourier3Json) -> Result<Self, String> {
        if j.cos.len() != j.sin.len() {
            return Err(format!(
                "a Fourier curve has {} cos terms but {} sin terms: give both lists the same length (pad with [0, 0, 0])",
                j.cos.len(),
                j.sin.len()
            ));
        }
        Ok(Fourier3 {
            c0: j.c0,
            cos: j.cos,
            sin: j.sin,
        })
    }
}

impl Fourier3 {
    /// Number of harmonics N.
    pub fn harmonics(&self) -> usize {
        self.cos.len().max(self.sin.len())
    }

    /// The point at `theta` (generic: jets give exact derivatives).
    pub fn eval<T: Real>(&self, theta: T) -> [T; 3] {
        let mut p = [T::cst(self.c0[0]), T::cst(self.c0[1]), T::cst(self.c0[2])];
        for n in 1..=self.harmonics() {
            let a = theta * n as f64;
            let (c, s) = (a.cos(), a.sin());
            let cn = self.cos.get(n - 1).copied().unwrap_or([0.0; 3]);
            let sn = self.sin.get(n - 1).copied().unwrap_or([0.0; 3]);
            for k in 0..3 {
                p[k] += c * cn[k] + s * sn[k];
            }
        }
        p
    }

    /// Coefficient vector of harmonic `n` for coordinate `k`: `(a, b)` with
    /// the term `a cos n theta + b sin n theta` (`(c0[k], 0)` for n = 0).
    pub fn harmonic(&self, n: usize, k: usize) -> (f64, f64) {
        if n == 0 {
            return (self.c0[k], 0.0);
        }
        (
            self.cos.get(n - 1).map_or(0.0, |c| c[k]),
            self.sin.get(n - 1).map_or(0.0, |s| s[k]),
        )
    }

    /// The same curve with `N` harmonics (zero-padded or truncated).
    pub fn with_harmonics(&self, n: usize) -> Fourier3 {
        let pad = |v: &Vec<[f64; 3]>| {
            let mut v = v.clone();
            v.resize(n, [0.0; 3]);
            v
        };
        Fourier3 {
            c0: self.c0,
            cos: pad(&self.cos),
            sin: pad(&self.sin),
        }
    }

    /// `sum w_i c_i` of the curves `c_i` (each zero-padded to the most
    /// harmonics among them): Fourier curves form a vector space, so the
    /// result evaluates to the same weighted sum of points.
    pub fn weighted_sum(terms: &[(f64, &Fourier3)]) -> Fourier3 {
        let n = terms.iter().map(|t| t.1.harmonics()).max().unwrap_or(0);
        let mut out = Fourier3 {
            c0: [0.0; 3],
            cos: vec![[0.0; 3]; n],
            sin: vec![[0.0; 3]; n],
        };
        for (w, f) in terms {
            let f = f.with_harmonics(n);
            for k in 0..3 {
                out.c0[k] += w * f.c0[k];
                for h in 0..n {
                    out.cos[h][k] += w * f.cos[h][k];
                    out.sin[h][k] += w * f.sin[h][k];
                }
            }
        }
        out
    }

    /// `m` points at `theta = 2 pi k / m`.
    pub fn sample(&self, m: usize) -> Vec<[f64; 3]> {
        (0..m)
            .map(|k| self.eval(2.0 * std::f64::consts::PI * k as f64 / m as f64))
            .collect()
    }

    /// The largest absolute value of any coefficient (0 for the zero
    /// curve); NaN if any coefficient is NaN.
    pub fn max_abs_coef(&self) -> f64 {
        self.c0
            .iter()
            .chain(self.cos.iter().flatten())
            .chain(self.sin.iter().flatten())
            .fold(0.0, |m: f64, x| {
                if m.is_nan() || x.abs() <= m {
                    m
                } else {
                    x.abs()
                }
            })
    }

    /// All coefficients finite.
    pub fn is_finite(&self) -> bool {
        self.c0
            .iter()
            .chain(self.cos.iter().flatten())
            .chain(self.sin.iter().flatten())
            .all(|x| x.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::Fourier3;

    #[test]
    fn the_largest_coefficient_is_found_and_nan_is_kept() {
        let mut f = Fourier3 {
            c0: [0.5, -0.25, 0.0],
            cos: vec![[0.0, -2.0, 1.0]],
            sin: vec![[0.0, 0.0, 1.5]],
        };
        assert_eq!(f.max_abs_coef(), 2.0);
        f.c0[2] = f64::NAN;
        assert!(f.max_abs_coef().is_nan());
    }
}
