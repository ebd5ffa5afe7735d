//! Generalized elliptic curves (GECs): paper 000 eq 16 and paper 002 eq 1.
//!
//! # The two printed forms
//!
//! Paper 000 (eq 16), parameter $v \in [0, 1]$:
//! $$ x = x_0 + \sum_{j=1}^{J} (x_{2j-1} \cos 2j\pi v + x_{2j} \sin 2j\pi v), \quad
//!    y = y_0 + \sum_{j=1}^{J} (y_{2j-1} \sin 2j\pi v + y_{2j} \cos 2j\pi v), \quad z = z_c. $$
//!
//! Paper 002 (eq 1), parameter $v \in [0, 2\pi]$:
//! $$ x = a_{x0} + \sum_{n=1}^{N} (a_{xn} \cos nv + b_{xn} \sin nv), \quad
//!    y = a_{y0} + \sum_{n=1}^{N} (a_{yn} \sin nv + b_{yn} \cos nv), \quad z = z_c. $$
//!
//! They are one family: $\theta = 2\pi v_{000} = v_{002}$, $J = N$,
//! $x_{2j-1} = a_{xj}$, $x_{2j} = b_{xj}$, $y_{2j-1} = a_{yj}$,
//! $y_{2j} = b_{yj}$. Note the asymmetry: **x takes (cos, sin) pairs, y takes
//! (sin, cos) pairs**. [`Gec`] stores exactly these pairs
//! ([`Gec::x`]`[n-1] = (cos, sin)`, [`Gec::y`]`[n-1] = (sin, cos)`) against
//! the angle $\theta \in [0, 2\pi)$.
//!
//! # Placement
//!
//! The papers place the curve in the plane $z = z_c$. Here a [`Frame`]
//! (origin $\mathbf{o}$ and orthonormal in-plane axes $\mathbf{e}_1,
//! \mathbf{e}_2$) places it in any plane, the extension paper 000 sec 4.1.3
//! mentions: $\mathbf{P}(\theta) = \mathbf{o} + x(\theta)\mathbf{e}_1 +
//! y(\theta)\mathbf{e}_2$; [`Frame::z_plane`] is the papers' case.
//! [`Gec::to_fourier3`] turns a placed GEC into the [`Fourier3`] the surface
//! families consume: $\mathbf{c}_0 = \mathbf{o} + x_0\mathbf{e}_1 + y_0
//! \mathbf{e}_2$, $\mathbf{c}_n = a_{xn}\mathbf{e}_1 + b_{yn}\mathbf{e}_2$,
//! $\mathbf{s}_n = b_{xn}\mathbf{e}_1 + a_{yn}\mathbf{e}_2$.
//!
//! # Geometry
//!
//! Area (Green's theorem, exact, derived in `verify/gec_golden.py`):
//! $A = \pi \sum_n n\,(a_{xn} a_{yn} - b_{xn} b_{yn})$, positive for a
//! counter-clockwise curve in its frame. Centroid and arc length use the
//! periodic trapezoidal rule (exact for the trigonometric-polynomial
//! integrands of the centroid once the sample count exceeds $3J$; spectrally
//! accurate for the arc length).
//!
//! Submodules: [`fit`] (least squares, parameter choices, automatic $J$),
//! [`correct`] (parameter correction: the default fit's best geometric
//! error), [`section`] (input validation and the plane), [`fft`] (the
//! uniform-angle path), [`frame`], [`paper`] (the printed orderings and
//! literal forms), [`metrics`] (ErM, ErA of paper 002 Table 1, defined precisely
//! there), [`transform`] (coefficient-space manipulation, paper 000 sec 5.2),
//! [`study`] (the MakeHuman cross-section study), [`check`].
//!
//! # Tested ranges
//!
//! The property tests (`tests/it/gec.rs`) sweep: J in 1..=12; 2J+1 to 300
//! points; curve size 1e-3..1e3 with centre and plane origin up to 1e3 away;
//! any plane orientation; harmonic n up to 5 %/n^2 of the radius (a
//! regular, non-self-intersecting curve); star-shaped polygons with random radii; every
//! parameter choice and solver; transforms with scales in [-3, 3], any angle,
//! bumps |h| <= 0.5 with width 0.05..2, bends |kappa| <= 0.5. In these ranges
//! a refit reproduces the coefficients to 1e-8 of the size, the FFT path
//! equals QR to 1e-9, and bad input (NaN, infinite, repeated, too few
//! points, J = 0, non-positive tolerance) is an error, never a panic.
//! Input validation beyond [`fit`]: [`check_closed`] (open polylines),
//! [`repeated_points`] (non-consecutive repeats), [`strip_closing_copy`].

pub mod check;
pub mod correct;
pub mod fft;
pub mod fit;
pub mod frame;
pub mod input;
mod lsq;
pub mod metrics;
pub mod paper;
pub mod pipeline;
pub mod samples;
pub mod section;
pub mod study;
pub mod transform;

pub use correct::Correction;
pub use fit::{
    check_closed, fit, fit_auto, fit_fft, repeated_points, strip_closing_copy, FitOptions,
    FitReport, FrameChoice, Param, Solver,
};
pub use frame::{Frame, FRAME_TOL};
pub use metrics::{errors, FitErrors};
pub use paper::{paper_000_literal, paper_002_literal};

use crate::curve::Fourier3;
use crate::jet::{Jet8, Real};
use std::f64::consts::PI;

/// Errors of the gec family.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GecError {
    #[error("the number of terms J must be at least 1 (got 0)")]
    ZeroTerms,
    #[error("J = {terms} needs at least {needed} points (2J+1), got {got}")]
    TooFewPoints {
        terms: usize,
        needed: usize,
        got: usize,
    },
    #[error("point {index} is not finite: {point:?}")]
    NonFinite { index: usize, point: [f64; 3] },
    #[error("points {first} and {second} coincide (remove repeated points, including a closing copy of the first point)")]
    RepeatedPoint { first: usize, second: usize },
    #[error("the polyline is open: the gap from the last point back to the first ({gap:.3e}) is {ratio:.1} times the median segment ({median:.3e}) and longer than every other segment; a closed cross section is needed")]
    OpenPolyline { gap: f64, median: f64, ratio: f64 },
    #[error("the points are degenerate ({0})")]
    Degenerate(String),
    #[error("the points are not planar: largest distance from the best plane {deviation:.3e} exceeds {tolerance:.3e}")]
    NotPlanar { deviation: f64, tolerance: f64 },
    #[error("invalid frame: {0}")]
    InvalidFrame(String),
    #[error(
        "the least-squares system is rank deficient (parameters too clustered for J = {terms})"
    )]
    RankDeficient { terms: usize },
    #[error(
        "tolerance {tol:.3e} not reached with J <= {max_terms} (best relative ErM {best:.3e})"
    )]
    ToleranceUnreachable {
        tol: f64,
        best: f64,
        max_terms: usize,
    },
    #[error("invalid parameter: {0}")]
    InvalidParameter(String),
    #[error("coefficient arrays malformed: {0}")]
    Malformed(String),
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
}

/// A generalized elliptic curve placed in space.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gec {
    /// Placement (the papers' $z = z_c$ plane is [`Frame::z_plane`]).
    pub frame: Frame,
    /// In-plane centre $(x_0, y_0)$ = $(a_{x0}, a_{y0})$.
    pub centre: [f64; 2],
    /// `x[n-1] = (a_xn, b_xn)`: coefficients of `(cos n theta, sin n theta)`.
    pub x: Vec<[f64; 2]>,
    /// `y[n-1] = (a_yn, b_yn)`: coefficients of `(sin n theta, cos n theta)`.
    pub y: Vec<[f64; 2]>,
}

impl Gec {
    /// A GEC from its parts (the arrays must have equal length J >= 1 and
    /// finite entries).
    pub fn new(
        frame: Frame,
        centre: [f64; 2],
        x: Vec<[f64; 2]>,
        y: Vec<[f64; 2]>,
    ) -> Result<Gec, GecError> {
        if x.len() != y.len() {
            return Err(GecError::Malformed(format!(
                "x has {} pairs, y has {}",
                x.len(),
                y.len()
            )));
        }
        if x.is_empty() {
            return Err(GecError::ZeroTerms);
        }
        let g = Gec {
            frame: Frame::new(frame.origin, frame.e1, frame.e2)?,
            centre,
            x,
            y,
        };
        if !g.is_finite() {
            return Err(GecError::Malformed("non-finite coefficient".into()));
        }
        Ok(g)
    }

    /// The standard ellipse `(a cos theta, b sin theta)` about `centre`.
    pub fn ellipse(frame: Frame, centre: [f64; 2], a: f64, b: f64) -> Gec {
        Gec {
            frame,
            centre,
            x: vec![[a, 0.0]],
            y: vec![[b, 0.0]],
        }
    }

    /// Number of terms J.
    pub fn terms(&self) -> usize {
        self.x.len()
    }

    /// All coefficients and the frame finite.
    pub fn is_finite(&self) -> bool {
        let f = &self.frame;
        f.origin
            .iter()
            .chain(&f.e1)
            .chain(&f.e2)
            .chain(&self.centre)
            .chain(self.x.iter().flatten())
            .chain(self.y.iter().flatten())
            .all(|v| v.is_finite())
    }

    /// In-plane point at angle `theta` (generic: jets give derivatives).
    pub fn eval_plane<T: Real>(&self, theta: T) -> [T; 2] {
        let mut x = T::cst(self.centre[0]);
        let mut y = T::cst(self.centre[1]);
        for (i, (cx, cy)) in self.x.iter().zip(&self.y).enumerate() {
            let (s, c) = (theta * (i + 1) as f64).sin_cos();
            x += c * cx[0] + s * cx[1];
            y += s * cy[0] + c * cy[1];
        }
        [x, y]
    }

    /// Space point at angle `theta` in `[0, 2 pi)` (paper 002's `v`).
    pub fn eval<T: Real>(&self, theta: T) -> [T; 3] {
        let [x, y] = self.eval_plane(theta);
        self.frame.place(x, y)
    }

    /// Space point at paper 000's parameter `v` in `[0, 1]`.
    pub fn eval_v<T: Real>(&self, v: T) -> [T; 3] {
        self.eval(v * (2.0 * PI))
    }

    /// `d^k P / d theta^k` at `theta` (k <= 8, exact via jets).
    pub fn derivative(&self, theta: f64, k: usize) -> [f64; 3] {
        let p = self.eval(Jet8::var_u(theta));
        [p[0].deriv(k, 0), p[1].deriv(k, 0), p[2].deriv(k, 0)]
    }

    /// In-plane first derivative (plain f64 fast path).
    pub fn tangent_plane(&self, theta: f64) -> [f64; 2] {
        let (mut dx, mut dy) = (0.0, 0.0);
        for (i, (cx, cy)) in self.x.iter().zip(&self.y).enumerate() {
            let n = (i + 1) as f64;
            let (s, c) = (n * theta).sin_cos();
            dx += n * (-s * cx[0] + c * cx[1]);
            dy += n * (c * cy[0] - s * cy[1]);
        }
        [dx, dy]
    }

    /// `m` space points at `theta = 2 pi k / m` (a closed polyline).
    pub fn sample(&self, m: usize) -> Vec<[f64; 3]> {
        (0..m)
            .map(|k| self.eval(2.0 * PI * k as f64 / m as f64))
            .collect()
    }

    /// `m` in-plane points at `theta = 2 pi k / m`.
    ///
    /// Term `i` at sample `k` needs `cos`/`sin` of `2 pi k (i + 1) / m`,
    /// which is the table entry `k (i + 1) mod m` of the `m` values of
    /// `2 pi j / m`: `m` sine-cosine pairs in all instead of `m` per term
    /// (the metrics' dense sampling spent 43 % of `verify --family gec` in
    /// `sincos`). The reduced angle is also the more accurate argument;
    /// [`Gec::eval_plane`] agrees to rounding (test
    /// `gec::sample_plane_equals_eval_plane`).
    pub fn sample_plane(&self, m: usize) -> Vec<[f64; 2]> {
        let table: Vec<(f64, f64)> = (0..m)
            .map(|j| {
                let (s, c) = (2.0 * PI * j as f64 / m as f64).sin_cos();
                (c, s)
            })
            .collect();
        (0..m)
            .map(|k| {
                let (mut x, mut y) = (self.centre[0], self.centre[1]);
                for (i, (cx, cy)) in self.x.iter().zip(&self.y).enumerate() {
                    let (c, s) = table[(k * (i + 1)) % m];
                    x += c * cx[0] + s * cx[1];
                    y += s * cy[0] + c * cy[1];
                }
                [x, y]
            })
            .collect()
    }

    /// Signed enclosed area in the frame (exact closed form).
    pub fn area(&self) -> f64 {
        PI * self
            .x
            .iter()
            .zip(&self.y)
            .enumerate()
            .map(|(i, (cx, cy))| (i + 1) as f64 * (cx[0] * cy[0] - cx[1] * cy[1]))
            .sum::<f64>()
    }

    /// Arc length by the periodic trapezoidal rule with `m` nodes.
    pub fn arc_length_with(&self, m: usize) -> f64 {
        let m = m.max(1);
        let h = 2.0 * PI / m as f64;
        (0..m)
            .map(|k| {
                let [dx, dy] = self.tangent_plane(h * k as f64);
                dx.hypot(dy)
            })
            .sum::<f64>()
            * h
    }

    /// Arc length (trapezoidal rule with `max(256, 64 J)` nodes).
    pub fn arc_length(&self) -> f64 {
        self.arc_length_with((64 * self.terms()).max(256))
    }

    /// Area centroid in space (Green's theorem, trapezoidal rule exact for
    /// these trigonometric polynomials). Falls back to the centre `(x0, y0)`
    /// when the area vanishes.
    pub fn centroid(&self) -> [f64; 3] {
        let a = self.area();
        if a.abs() <= f64::EPSILON * self.scale().powi(2) {
            return self.frame.place(self.centre[0], self.centre[1]);
        }
        let m = 4 * self.terms() + 4;
        let h = 2.0 * PI / m as f64;
        let (mut mx, mut my) = (0.0, 0.0);
        for k in 0..m {
            let t = h * k as f64;
            let [x, y] = self.eval_plane(t);
            let [dx, dy] = self.tangent_plane(t);
            // Cx = (1/A) oint x^2/2 dy, Cy = -(1/A) oint y^2/2 dx
            mx += 0.5 * x * x * dy;
            my -= 0.5 * y * y * dx;
        }
        self.frame.place(mx * h / a, my * h / a)
    }

    /// A length scale: `|centre| + sum of |coefficients|` (bounds the curve's
    /// extent from the frame origin).
    pub fn scale(&self) -> f64 {
        self.centre[0].abs()
            + self.centre[1].abs()
            + self
                .x
                .iter()
                .chain(&self.y)
                .flatten()
                .map(|v| v.abs())
                .sum::<f64>()
    }

    /// The closed space curve as a [`Fourier3`] in the same angle `theta`.
    pub fn to_fourier3(&self) -> Fourier3 {
        let f = &self.frame;
        let c0 = f.place(self.centre[0], self.centre[1]);
        let comb = |a: f64, b: f64| -> [f64; 3] {
            let mut v = [0.0; 3];
            for k in 0..3 {
                v[k] = a * f.e1[k] + b * f.e2[k];
            }
            v
        };
        Fourier3 {
            c0,
            cos: self
                .x
                .iter()
                .zip(&self.y)
                .map(|(cx, cy)| comb(cx[0], cy[1]))
                .collect(),
            sin: self
                .x
                .iter()
                .zip(&self.y)
                .map(|(cx, cy)| comb(cx[1], cy[0]))
                .collect(),
        }
    }

    /// The same curve with `j` terms (zero-padded or truncated).
    pub fn with_terms(&self, j: usize) -> Gec {
        let mut g = self.clone();
        g.x.resize(j, [0.0; 2]);
        g.y.resize(j, [0.0; 2]);
        g
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A NaN anywhere in a curve (a coefficient, the centre) makes it
    /// non-finite, and `Gec::new` refuses it by name; a finite one is
    /// finite.
    #[test]
    fn a_nan_coefficient_or_centre_is_not_finite() {
        let frame = Frame::z_plane(0.0);
        assert!(Gec::ellipse(frame, [0.0, 0.0], 2.0, 1.0).is_finite());
        assert!(!Gec::ellipse(frame, [0.0, 0.0], f64::NAN, 1.0).is_finite());
        assert!(!Gec::ellipse(frame, [0.0, f64::INFINITY], 2.0, 1.0).is_finite());
        let r = Gec::new(frame, [0.0, 0.0], vec![[1.0, f64::NAN]], vec![[0.0, 1.0]]);
        assert!(matches!(r, Err(GecError::Malformed(_))), "{r:?}");
    }
}
