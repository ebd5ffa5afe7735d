//! The ode6 part surface (paper 004): one sixth-order ODE patch (eq 19)
//! between each pair of consecutive key sections, joined C2 (eqs 23-25).
//!
//! Eq 1 asks each patch for its two boundary curves and their first and
//! second u-derivative curves. A part gives only its sections, so the
//! derivative curves are those of the natural cubic spline through the
//! sections in u, coefficient by coefficient (Fourier curves form a vector
//! space). The spline is C2, so the six constraints of a join are the same
//! on both of its sides and the chain is C2 by construction, whatever rho,
//! eta and lambda are. Between the sections the ODE, not the spline, shapes
//! the part: the shape parameters act there as in 004's Fig 6. The
//! spline is natural, so S_uu = 0 at the two end sections.

use super::PartGeometry;
use crate::curve::Fourier3;
use crate::jet::{Jet, Real};
use crate::ode6::spline::natural_second_derivatives;
use crate::ode6::{Basis, BoundaryCurves, Curve, Ode6Error, Ode6Surface, Params};
use crate::surface::{Domain, Surface};
use std::f64::consts::PI;

/// A part's ODE6 chain over global `u` in `[knots[0], knots[n]]`, `v` the
/// section angle `theta` in `[0, 2 pi)` (patch `i` covers `[knots[i],
/// knots[i + 1]]` in its own `t = (u - knots[i]) / h_i` and `v = theta / 2
/// pi`).
#[derive(Clone, Debug)]
pub struct Ode6Part {
    knots: Vec<f64>,
    basis: Basis,
    /// Per patch, the six constraint curves `c_1..c_6` of eq 1 in `t`.
    curves: Vec<[Fourier3; 6]>,
    patches: Vec<Ode6Surface>,
}

/// A curve's coefficients as one vector (`c0`, then the cosine and sine
/// rows), all curves with `n` harmonics.
fn flatten(c: &Fourier3) -> Vec<f64> {
    let mut out = c.c0.to_vec();
    out.extend(c.cos.iter().flatten());
    out.extend(c.sin.iter().flatten());
    out
}

fn unflatten(x: &[f64], n: usize) -> Fourier3 {
    let rows = |from: usize| {
        (0..n)
            .map(|h| std::array::from_fn(|k| x[from + 3 * h + k]))
            .collect()
    };
    Fourier3 {
        c0: [x[0], x[1], x[2]],
        cos: rows(3),
        sin: rows(3 + 3 * n),
    }
}

/// `[S, S_u, S_uu]` at every knot of the natural cubic spline through
/// `curves` at `knots` (strictly increasing, at least two).
fn spline_derivatives(knots: &[f64], curves: &[Fourier3]) -> Vec<[Fourier3; 3]> {
    let n = curves[0].harmonics();
    let flat: Vec<Vec<f64>> = curves.iter().map(flatten).collect();
    let len = flat[0].len();
    let last = knots.len() - 1;
    let mut d1 = vec![vec![0.0; len]; knots.len()];
    let mut d2 = vec![vec![0.0; len]; knots.len()];
    for c in 0..len {
        let y: Vec<f64> = flat.iter().map(|f| f[c]).collect();
        let m = natural_second_derivatives(knots, &y);
        for i in 0..=last {
            // s'(t_i) from the segment to the right, the last from the left
            d1[i][c] = if i < last {
                let h = knots[i + 1] - knots[i];
                (y[i + 1] - y[i]) / h - h * (2.0 * m[i] + m[i + 1]) / 6.0
            } else {
                let h = knots[i] - knots[i - 1];
                (y[i] - y[i - 1]) / h + h * (m[i - 1] + 2.0 * m[i]) / 6.0
            };
            d2[i][c] = m[i];
        }
    }
    (0..knots.len())
        .map(|i| {
            [
                curves[i].clone(),
                unflatten(&d1[i], n),
                unflatten(&d2[i], n),
            ]
        })
        .collect()
}

/// Builds the chain through `sections` (`(u, curve)`, `u` strictly
/// increasing, curves with the same number of harmonics).
pub(super) fn build(params: Params, sections: &[(f64, Fourier3)]) -> Result<Ode6Part, Ode6Error> {
    let basis = Basis::new(params)?;
    let knots: Vec<f64> = sections.iter().map(|s| s.0).collect();
    if knots.len() < 2 {
        return Err(Ode6Error::ChainShape {
            sections: knots.len(),
            params: 1,
        });
    }
    let curves: Vec<Fourier3> = sections.iter().map(|s| s.1.clone()).collect();
    let at = spline_derivatives(&knots, &curves);
    let scaled = |c: &Fourier3, s: f64| Fourier3::weighted_sum(&[(s, c)]);
    let mut six = Vec::with_capacity(knots.len() - 1);
    let mut patches = Vec::with_capacity(knots.len() - 1);
    for i in 0..knots.len() - 1 {
        let h = knots[i + 1] - knots[i];
        // derivatives in the patch's own t = (u - u_i) / h
        let (a, b) = (&at[i], &at[i + 1]);
        let c = [
            a[0].clone(),
            scaled(&a[1], h),
            scaled(&a[2], h * h),
            b[0].clone(),
            scaled(&b[1], h),
            scaled(&b[2], h * h),
        ];
        let keys = c.clone().map(Curve::Fourier);
        patches.push(Ode6Surface::new(
            basis.clone(),
            BoundaryCurves::direct(keys)?,
        ));
        six.push(c);
    }
    Ok(Ode6Part {
        knots,
        basis,
        curves: six,
        patches,
    })
}

impl Ode6Part {
    /// The patch owning global `u` (clamped to the ends) and its length.
    fn patch_at(&self, u: f64) -> (usize, f64) {
        let n = self.patches.len();
        let i = self.knots[1..n].partition_point(|&k| k <= u).min(n - 1);
        (i, self.knots[i + 1] - self.knots[i])
    }

    /// The patches (for their join measurement).
    pub fn patches(&self) -> &[Ode6Surface] {
        &self.patches
    }
}

impl Surface for Ode6Part {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let (i, h) = self.patch_at(u.value());
        self.patches[i].eval((u - self.knots[i]) / h, v / (2.0 * PI))
    }

    fn domain(&self) -> Domain {
        Domain {
            u: (self.knots[0], self.knots[self.knots.len() - 1]),
            v: (0.0, 2.0 * PI),
            closed_u: false,
            closed_v: true,
        }
    }

    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let vs: Vec<f64> = vs.iter().map(|v| v / (2.0 * PI)).collect();
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &u in us {
            let (i, h) = self.patch_at(u);
            out.extend(self.patches[i].grid(&[(u - self.knots[i]) / h], &vs));
        }
        out
    }
}

impl PartGeometry for Ode6Part {
    fn section(&self, u: f64, d: usize) -> Fourier3 {
        self.section_of(self.patch_at(u).0, u, d)
    }

    fn family(&self) -> &'static str {
        "ode6_c2"
    }

    fn internal_jumps(&self, samples: usize) -> [f64; 3] {
        // d^k S / du^k across each knot, relative to max(|derivative|, 1)
        // as the pde6 chain's measurement
        let samples = samples.max(1);
        let mut out = [0.0f64; 3];
        for &k in &self.knots[1..self.knots.len() - 1] {
            let (i, _) = self.patch_at(k);
            for (d, o) in out.iter_mut().enumerate() {
                // each side's section once per knot and order, then sampled
                let (sa, sb) = (self.section_of(i - 1, k, d), self.section_of(i, k, d));
                for j in 0..samples {
                    let v = 2.0 * PI * j as f64 / samples as f64;
                    let (a, b) = (sa.eval(v), sb.eval(v));
                    let big = crate::mesh::norm(a).max(crate::mesh::norm(b)).max(1.0);
                    *o = crate::check::Worst::worst(*o, crate::mesh::dist(a, b) / big);
                }
            }
        }
        out
    }
}

impl Ode6Part {
    /// Patch `i`'s section (or its `d`-th u-derivative) at global `u`, also
    /// past the patch's ends (for the jumps across a knot).
    fn section_of(&self, i: usize, u: f64, d: usize) -> Fourier3 {
        let h = self.knots[i + 1] - self.knots[i];
        let t = (u - self.knots[i]) / h;
        let g: [f64; 6] = if d <= 2 {
            self.basis.g(Jet::<3, 1>::var_u(t)).map(|x| x.deriv(d, 0))
        } else {
            self.basis.g(Jet::<7, 1>::var_u(t)).map(|x| x.deriv(d, 0))
        };
        let s = h.powi(-(d as i32));
        let terms: Vec<(f64, &Fourier3)> = g
            .iter()
            .zip(&self.curves[i])
            .map(|(w, c)| (w * s, c))
            .collect();
        Fourier3::weighted_sum(&terms)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::tol;
    use crate::mesh::dist;

    /// A ring of radius `r` and one second harmonic `w` around `(0, y, 0)`
    /// in the xz plane.
    fn ring(y: f64, x: f64, r: f64, w: f64) -> Fourier3 {
        Fourier3 {
            c0: [x, y, 0.0],
            cos: vec![[r, 0.0, 0.0], [w, 0.0, 0.0]],
            sin: vec![[0.0, 0.0, r], [0.0, 0.0, -w]],
        }
    }

    fn sections() -> Vec<(f64, Fourier3)> {
        vec![
            (0.0, ring(0.0, 0.0, 1.0, 0.1)),
            (0.7, ring(0.7, 0.2, 1.4, 0.0)),
            (1.5, ring(1.5, 0.1, 0.8, 0.2)),
            (2.0, ring(2.0, -0.3, 0.9, 0.05)),
        ]
    }

    fn params() -> Params {
        Params::new(1.0, 3.0, 1.0)
    }

    #[test]
    fn the_part_interpolates_its_sections_and_is_c2_at_each() {
        let s = sections();
        let part = build(params(), &s).unwrap();
        for (u, c) in &s {
            for k in 0..12 {
                let th = 2.0 * PI * k as f64 / 12.0;
                // through the patches' eval (Surface), not section()
                assert!(dist(part.point(*u, th), c.eval(th)) < tol::ROUNDING);
            }
        }
        let j = part.internal_jumps(16);
        assert!(j.iter().all(|x| *x < tol::ROUNDING), "{j:?}");
        // and a pde6-style jump would show: the ODE between the knots is
        // not the spline (the second derivative's third-order neighbour
        // jumps)
        let k = s[1].0;
        let third = dist(
            part.section_of(0, k, 3).eval(0.3),
            part.section_of(1, k, 3).eval(0.3),
        );
        assert!(third > tol::DETECTED, "{third}");
    }

    #[test]
    fn section_derivatives_match_the_surface_jets() {
        let part = build(params(), &sections()).unwrap();
        for u in [0.1, 0.69, 0.71, 1.2, 1.99] {
            for d in 0..=3 {
                for th in [0.0, 1.0, 4.0] {
                    let a = part.section(u, d).eval(th);
                    let b = part.derivative(u, th, d, 0);
                    let big = crate::mesh::norm(b).max(1.0);
                    assert!(dist(a, b) / big < tol::ROUNDING, "u {u} d {d}: {a:?} {b:?}");
                }
            }
        }
    }

    #[test]
    fn a_cone_is_reproduced_exactly() {
        // sections linear in u: every derivative past the first vanishes, so
        // the line solves eq 2 and meets eq 1: the unique solution
        let s: Vec<(f64, Fourier3)> = [0.0, 0.5, 1.75, 2.0]
            .iter()
            .map(|&u| (u, ring(u, 0.3 * u, 1.0 + 0.4 * u, 0.1 * u)))
            .collect();
        let part = build(params(), &s).unwrap();
        for u in [0.2, 0.6, 1.1, 1.9] {
            let want = ring(u, 0.3 * u, 1.0 + 0.4 * u, 0.1 * u);
            for th in [0.0, 2.0, 5.0] {
                assert!(dist(part.point(u, th), want.eval(th)) < tol::SOLVE);
            }
        }
    }

    #[test]
    fn too_few_sections_and_a_zero_rho_are_refused() {
        assert!(build(params(), &sections()[..1]).is_err());
        assert!(build(Params::new(0.0, 1.0, 1.0), &sections()).is_err());
    }
}
