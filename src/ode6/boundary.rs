//! Boundary curves and the two ways of making the six constraints of eq 1.
//!
//! Every constraint curve is a linear combination of a few *key* curves:
//! $c_j(v) = \sum_m W_{jm} K_m(v)$. The surface of eq 19 is then
//! $S = \sum_m h_m(u) K_m(v)$ with $h_m = \sum_j g_j W_{jm}$.
//!
//! **Approach 1** (section 3): keys $c_1, c_4$; $c_2 = w_1 c_1$,
//! $c_3 = w_2 c_1$, $c_5 = w_3 c_4$, $c_6 = w_4 c_4$.
//!
//! **Approach 2** (eqs 3-7): keys $c_1, \bar c_2, \bar c_3, \bar c_5, \bar c_6,
//! c_4$, the control curves at $0 < u_2 < u_3$ and $u_5 < u_6 < 1$. Printed
//! (eqs 4-7): $c_2 = (\bar c_2 - c_1)/u_2$,
//! $c_3 = [u_2 \bar c_3 - u_3 \bar c_2 + (u_3 - u_2) c_1]/[u_2^2 (u_3 - u_2)]$,
//! $c_5 = (c_4 - \bar c_6)/(1 - u_6)$,
//! $c_6 = [(u_6 - u_5) c_4 + (1 - u_6)\bar c_5 - (1 - u_5)\bar c_6]/[(1-u_6)^2 (u_6 - u_5)]$.
//! The printed $c_3$ tends to $\tfrac{u_3}{2u_2} S_{uu}(0)$, not $S_{uu}(0)$
//! (and $c_6$ to $\tfrac{1-u_5}{2(1-u_6)} S_{uu}(1)$): it is a second
//! derivative only when $u_3 = 2u_2$. The default [`DiffFormula::ThreePoint`]
//! differentiates the quadratic through the three curves at each end (exact
//! for quadratics, first derivative $O(h^2)$, second $O(h)$).
//!
//! Curves: a [`Fourier3`] (closed, $\theta = 2\pi v$), a closed sampled
//! polyline (trigonometric interpolation, exact at the vertices, converted to
//! a [`Fourier3`]), or an open sampled polyline (natural cubic spline through
//! the vertices at $v_i = i/(m-1)$, C2 in $v$), a generalized elliptic
//! curve ([`Curve::from_gec`], exactly, as the [`Fourier3`] of the same angle
//! $\theta = 2\pi v$), or a quintic Hermite segment ([`Curve::Hermite`]: its
//! position, first and second derivative at both ends are given, which is
//! what eq 26 asks of patches adjacent in $v$: $c_k^{(i)}(1) = \hat
//! c_k^{(i)}(0)$, $i = 0, 1, 2$).

use super::spline::{self, NaturalSpline};
use super::Ode6Error;
use crate::curve::gec::Gec;
use crate::curve::Fourier3;
use crate::jet::Real;
use std::f64::consts::PI;

/// A boundary or control curve of parameter `v in [0, 1]`.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    /// Closed: `P(2 pi v)`.
    Fourier(Fourier3),
    /// Open: natural cubic spline through `points` at `v_i = i / (m - 1)`;
    /// `m2` are its second derivatives at the knots.
    Spline {
        points: Vec<[f64; 3]>,
        m2: Vec<[f64; 3]>,
    },
    /// Open quintic Hermite segment: `ends[e] = [P, P', P'']` at `v = e`
    /// (`e = 0, 1`), derivatives with respect to `v`.
    Hermite { ends: [[[f64; 3]; 3]; 2] },
    /// A piece of a longer cubic spline (a network line, see
    /// [`super::network`]): the cubic on each `[knots[i], knots[i + 1]]` with
    /// the values `points` and second derivatives `m2` at the knots, `knots`
    /// increasing from 0 to 1; `periodic` when the piece is a whole closed
    /// line (the curve is then closed in `v`).
    Piece {
        knots: Vec<f64>,
        points: Vec<[f64; 3]>,
        m2: Vec<[f64; 3]>,
        periodic: bool,
    },
}

/// The quintic Hermite basis on `[0, 1]`: weights of `P(0), P'(0), P''(0),
/// P(1), P'(1), P''(1)`.
pub fn hermite5<T: Real>(t: T) -> [T; 6] {
    let t2 = t * t;
    let t3 = t2 * t;
    let t4 = t3 * t;
    let t5 = t4 * t;
    [
        T::one() - t3 * 10.0 + t4 * 15.0 - t5 * 6.0,
        t - t3 * 6.0 + t4 * 8.0 - t5 * 3.0,
        (t2 - t3 * 3.0 + t4 * 3.0 - t5) * 0.5,
        t3 * 10.0 - t4 * 15.0 + t5 * 6.0,
        t3 * (-4.0) + t4 * 7.0 - t5 * 3.0,
        (t3 - t4 * 2.0 + t5) * 0.5,
    ]
}

impl Curve {
    /// A sampled polyline: closed ones are interpolated trigonometrically,
    /// open ones by a natural cubic spline.
    pub fn from_polyline(points: &[[f64; 3]], closed: bool) -> Result<Curve, Ode6Error> {
        let m = points.len();
        if m < if closed { 3 } else { 2 } {
            return Err(Ode6Error::TooFewVertices {
                closed,
                min: if closed { 3 } else { 2 },
                got: m,
            });
        }
        if points.iter().flatten().any(|x| !x.is_finite()) {
            return Err(Ode6Error::NotFinite {
                what: "polyline vertex",
            });
        }
        Ok(if closed {
            Curve::Fourier(trig_interpolate(points))
        } else {
            Curve::Spline {
                points: points.to_vec(),
                m2: natural_spline_m2(points)?,
            }
        })
    }

    /// A generalized elliptic curve (paper 000 eq 16, paper 002 eq 1) placed
    /// in space: `P(v) = gec.eval_v(v)`, exactly (as its [`Fourier3`]).
    pub fn from_gec(gec: &Gec) -> Result<Curve, Ode6Error> {
        if !gec.is_finite() {
            return Err(Ode6Error::NotFinite {
                what: "a coefficient of the generalized elliptic curve",
            });
        }
        Ok(Curve::Fourier(gec.to_fourier3()))
    }

    /// A quintic Hermite segment from `[P, P', P'']` at `v = 0` and `v = 1`.
    pub fn hermite(start: [[f64; 3]; 3], end: [[f64; 3]; 3]) -> Result<Curve, Ode6Error> {
        if start.iter().chain(&end).flatten().any(|x| !x.is_finite()) {
            return Err(Ode6Error::NotFinite {
                what: "Hermite end data",
            });
        }
        Ok(Curve::Hermite { ends: [start, end] })
    }

    /// Whether the curve is closed in `v`.
    pub fn closed(&self) -> bool {
        matches!(
            self,
            Curve::Fourier(_) | Curve::Piece { periodic: true, .. }
        )
    }

    /// The constant curve `P(v) = p` (a collapsed side: the apex of a
    /// 3-sided network patch).
    pub fn constant(p: [f64; 3], periodic: bool) -> Curve {
        Curve::Piece {
            knots: vec![0.0, 1.0],
            points: vec![p, p],
            m2: vec![[0.0; 3]; 2],
            periodic,
        }
    }

    /// The point at `v` (generic: jets give the derivatives in `v`).
    pub fn eval<T: Real>(&self, v: T) -> [T; 3] {
        match self {
            Curve::Fourier(f) => f.eval(v * (2.0 * PI)),
            Curve::Spline { points, m2 } => {
                let n = points.len() - 1;
                let i = ((v.value() * n as f64).floor().max(0.0) as usize).min(n - 1);
                let t = [i as f64 / n as f64, (i + 1) as f64 / n as f64];
                std::array::from_fn(|k| {
                    spline::segment(
                        t,
                        [points[i][k], points[i + 1][k]],
                        [m2[i][k], m2[i + 1][k]],
                        v,
                    )
                })
            }
            Curve::Hermite { ends } => {
                let h = hermite5(v);
                let mut p = [T::zero(); 3];
                for k in 0..3 {
                    for e in 0..2 {
                        for i in 0..3 {
                            p[k] += h[3 * e + i] * ends[e][i][k];
                        }
                    }
                }
                p
            }
            Curve::Piece {
                knots, points, m2, ..
            } => {
                let n = knots.len() - 1;
                let i = knots
                    .partition_point(|&t| t <= v.value())
                    .saturating_sub(1)
                    .min(n - 1);
                let t = [knots[i], knots[i + 1]];
                std::array::from_fn(|k| {
                    spline::segment(
                        t,
                        [points[i][k], points[i + 1][k]],
                        [m2[i][k], m2[i + 1][k]],
                        v,
                    )
                })
            }
        }
    }

    /// The curve multiplied by `s`.
    pub fn scaled(&self, s: f64) -> Curve {
        let sc = |v: &[[f64; 3]]| v.iter().map(|p| [p[0] * s, p[1] * s, p[2] * s]).collect();
        match self {
            Curve::Fourier(f) => Curve::Fourier(Fourier3 {
                c0: [f.c0[0] * s, f.c0[1] * s, f.c0[2] * s],
                cos: sc(&f.cos),
                sin: sc(&f.sin),
            }),
            Curve::Spline { points, m2 } => Curve::Spline {
                points: sc(points),
                m2: sc(m2),
            },
            Curve::Hermite { ends } => {
                let mut e = *ends;
                e.iter_mut().flatten().flatten().for_each(|x| *x *= s);
                Curve::Hermite { ends: e }
            }
            Curve::Piece {
                knots,
                points,
                m2,
                periodic,
            } => Curve::Piece {
                knots: knots.clone(),
                points: sc(points),
                m2: sc(m2),
                periodic: *periodic,
            },
        }
    }

    /// Number of stored scalars (for the data-size table).
    pub fn scalars(&self) -> usize {
        match self {
            Curve::Fourier(f) => 3 * (1 + f.cos.len() + f.sin.len()),
            Curve::Spline { points, .. } => 3 * points.len(),
            Curve::Hermite { .. } => 18,
            // the knots are the curve's own parameters: one more per point
            Curve::Piece { points, .. } => 4 * points.len(),
        }
    }
}

/// Trigonometric interpolation of a closed polyline at `theta_k = 2 pi k/m`.
pub fn trig_interpolate(points: &[[f64; 3]]) -> Fourier3 {
    let m = points.len();
    let nh = m / 2;
    let mut c0 = [0.0; 3];
    let mut cos = vec![[0.0; 3]; nh];
    let mut sin = vec![[0.0; 3]; nh];
    for (j, p) in points.iter().enumerate() {
        for k in 0..3 {
            c0[k] += p[k] / m as f64;
        }
        for n in 1..=nh {
            let t = 2.0 * PI * (n * j % m) as f64 / m as f64;
            // The Nyquist term of an even m is shared by +-n: half weight.
            let w = if 2 * n == m { 1.0 } else { 2.0 } / m as f64;
            for k in 0..3 {
                cos[n - 1][k] += w * p[k] * t.cos();
                if 2 * n != m {
                    sin[n - 1][k] += w * p[k] * t.sin();
                }
            }
        }
    }
    Fourier3 { c0, cos, sin }
}

/// Second derivatives of the natural cubic spline through `points` at the
/// uniform knots `v_i = i / (m - 1)`, per component.
fn natural_spline_m2(points: &[[f64; 3]]) -> Result<Vec<[f64; 3]>, Ode6Error> {
    let v = uniform_knots(points.len());
    let mut m2 = vec![[0.0; 3]; points.len()];
    for k in 0..3 {
        let y: Vec<f64> = points.iter().map(|p| p[k]).collect();
        let s = NaturalSpline::new(&v, &y)?;
        for (m, d) in m2.iter_mut().zip(s.second_derivatives()) {
            m[k] = *d;
        }
    }
    Ok(m2)
}

/// `v_i = i / (m - 1)`, `i = 0..m` (exactly 0 and 1 at the ends).
fn uniform_knots(m: usize) -> Vec<f64> {
    (0..m).map(|i| i as f64 / (m - 1) as f64).collect()
}

/// The constraint curves of eq 1 as combinations of key curves.
#[derive(Clone, Debug)]
pub struct BoundaryCurves {
    pub keys: Vec<Curve>,
    /// `weights[m][j]`: weight of key `m` in constraint `c_{j+1}`.
    pub weights: Vec<[f64; 6]>,
}

impl BoundaryCurves {
    /// Six explicit curves `c_1..c_6`.
    pub fn direct(c: [Curve; 6]) -> Result<BoundaryCurves, Ode6Error> {
        let weights = (0..6)
            .map(|m| {
                let mut w = [0.0; 6];
                w[m] = 1.0;
                w
            })
            .collect();
        BoundaryCurves::new(c.to_vec(), weights)
    }

    /// Approach 1: `c_2 = w1 c_1, c_3 = w2 c_1, c_5 = w3 c_4, c_6 = w4 c_4`.
    pub fn approach1(c1: Curve, c4: Curve, w: [f64; 4]) -> Result<BoundaryCurves, Ode6Error> {
        if w.iter().any(|x| !x.is_finite()) {
            return Err(Ode6Error::NonFiniteWeights { weights: w });
        }
        BoundaryCurves::new(
            vec![c1, c4],
            vec![
                [1.0, w[0], w[1], 0.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, 1.0, w[2], w[3]],
            ],
        )
    }

    /// Approach 2: boundary curves `c1`, `c4` and control curves
    /// `[c̄2, c̄3, c̄5, c̄6]` at the positions of `a`.
    pub fn approach2(
        c1: Curve,
        controls: [Curve; 4],
        c4: Curve,
        a: &Approach2,
    ) -> Result<BoundaryCurves, Ode6Error> {
        let w = a.weights()?;
        let [k2, k3, k5, k6] = controls;
        BoundaryCurves::new(vec![c1, k2, k3, k5, k6, c4], w.to_vec())
    }

    /// Constraint curves `c_j = sum_m weights[m][j] keys[m]` (all keys open or
    /// all closed, finite).
    pub fn new(keys: Vec<Curve>, weights: Vec<[f64; 6]>) -> Result<BoundaryCurves, Ode6Error> {
        if keys.is_empty() {
            return Err(Ode6Error::NoCurves);
        }
        let closed = keys[0].closed();
        if keys.iter().any(|k| k.closed() != closed) {
            return Err(Ode6Error::MixedClosure);
        }
        for k in &keys {
            let finite = match k {
                Curve::Fourier(f) => f.is_finite(),
                Curve::Spline { points, m2 } => {
                    points.iter().chain(m2).flatten().all(|x| x.is_finite())
                }
                Curve::Hermite { ends } => ends.iter().flatten().flatten().all(|x| x.is_finite()),
                Curve::Piece {
                    knots, points, m2, ..
                } => {
                    knots.iter().all(|x| x.is_finite())
                        && points.iter().chain(m2).flatten().all(|x| x.is_finite())
                }
            };
            if !finite {
                return Err(Ode6Error::NotFinite {
                    what: "a boundary curve coefficient",
                });
            }
        }
        Ok(BoundaryCurves { keys, weights })
    }

    /// Closed in `v` (all keys closed).
    pub fn closed(&self) -> bool {
        self.keys[0].closed()
    }

    /// The constraint curve `c_{j+1}(v)`.
    pub fn c<T: Real>(&self, j: usize, v: T) -> [T; 3] {
        let mut p = [T::zero(); 3];
        for (key, w) in self.keys.iter().zip(&self.weights) {
            if w[j] != 0.0 {
                let k = key.eval(v);
                for d in 0..3 {
                    p[d] += k[d] * w[j];
                }
            }
        }
        p
    }
}

/// Which difference formulas turn control curves into derivatives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum DiffFormula {
    /// Eqs 4-7 as printed (one-sided differences of differences).
    Printed,
    /// Derivatives of the quadratic through the three curves at each end.
    ThreePoint,
}

/// Positions of the control curves of approach 2.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Approach2 {
    pub u2: f64,
    pub u3: f64,
    pub u5: f64,
    pub u6: f64,
    pub formula: DiffFormula,
}

impl Approach2 {
    /// Weights of the keys `[c1, c̄2, c̄3, c̄5, c̄6, c4]` in `c_1..c_6`.
    pub fn weights(&self) -> Result<[[f64; 6]; 6], Ode6Error> {
        let Approach2 {
            u2,
            u3,
            u5,
            u6,
            formula,
        } = *self;
        let ok = [u2, u3, u5, u6].iter().all(|x| x.is_finite())
            && 0.0 < u2
            && u2 < u3
            && u3 < 1.0
            && 0.0 < u5
            && u5 < u6
            && u6 < 1.0;
        if !ok {
            return Err(Ode6Error::ControlPositions { u2, u3, u5, u6 });
        }
        // (weight of c1, c̄2, c̄3) in c2, c3 and (c4, c̄6, c̄5) in c5, c6.
        let (d1_0, d2_0, d1_1, d2_1) = match formula {
            DiffFormula::Printed => {
                let (h6, h56) = (1.0 - u6, u6 - u5);
                (
                    [-1.0 / u2, 1.0 / u2, 0.0],
                    [
                        (u3 - u2) / (u2 * u2 * (u3 - u2)),
                        -u3 / (u2 * u2 * (u3 - u2)),
                        u2 / (u2 * u2 * (u3 - u2)),
                    ],
                    [1.0 / h6, -1.0 / h6, 0.0],
                    [
                        h56 / (h6 * h6 * h56),
                        -(1.0 - u5) / (h6 * h6 * h56),
                        h6 / (h6 * h6 * h56),
                    ],
                )
            }
            DiffFormula::ThreePoint => {
                let (a, b) = (u2, u3);
                let first0 = [-(a + b) / (a * b), b / (a * (b - a)), -a / (b * (b - a))];
                let second0 = [2.0 / (a * b), -2.0 / (a * (b - a)), 2.0 / (b * (b - a))];
                // Mirror s = 1 - u: d/du = -d/ds; nodes s = 0, 1 - u6, 1 - u5.
                let (a, b) = (1.0 - u6, 1.0 - u5);
                let first1 = [(a + b) / (a * b), -b / (a * (b - a)), a / (b * (b - a))];
                let second1 = [2.0 / (a * b), -2.0 / (a * (b - a)), 2.0 / (b * (b - a))];
                (first0, second0, first1, second1)
            }
        };
        // keys: 0 c1, 1 c̄2, 2 c̄3, 3 c̄5, 4 c̄6, 5 c4
        let mut w = [[0.0; 6]; 6];
        w[0] = [1.0, d1_0[0], d2_0[0], 0.0, 0.0, 0.0];
        w[1] = [0.0, d1_0[1], d2_0[1], 0.0, 0.0, 0.0];
        w[2] = [0.0, d1_0[2], d2_0[2], 0.0, 0.0, 0.0];
        w[5] = [0.0, 0.0, 0.0, 1.0, d1_1[0], d2_1[0]];
        w[4] = [0.0, 0.0, 0.0, 0.0, d1_1[1], d2_1[1]];
        w[3] = [0.0, 0.0, 0.0, 0.0, d1_1[2], d2_1[2]];
        Ok(w)
    }

    /// `(c2, c3, c5, c6)` for scalar samples `f(0), f(u2), f(u3), f(u5),
    /// f(u6), f(1)` of one iso-parametric line.
    pub fn derivatives(&self, f: [f64; 6]) -> Result<[f64; 4], Ode6Error> {
        let w = self.weights()?;
        let c = |j: usize| (0..6).map(|m| w[m][j] * f[m]).sum::<f64>();
        Ok([c(1), c(2), c(4), c(5)])
    }
}
