//! Least-squares fitting of a closed planar polyline by a GEC.
//!
//! Neither paper says how the data points get their parameter; given the
//! angles $\theta_k$ the fit is linear least squares with the design matrix
//! $A_{k,\cdot} = [1, \cos\theta_k, \sin\theta_k, \dots, \cos J\theta_k,
//! \sin J\theta_k]$ shared by $x$ and $y$ (the $y$ coefficients are then read
//! as (sin, cos) pairs). Parameter choices ([`Param`]): uniform in the point
//! index, chord length, centripetal (square root of chord length), and the
//! polar angle about the polygon's area centroid. The first three start at
//! the polar angle of the first point, so all choices are phase-aligned
//! across sections (the sixth-order families interpolate harmonic by
//! harmonic). The cross-section study measured which fits best and is the
//! [`Param::default`].
//!
//! The plane is fitted too: Newell's normal of the polygon (which also
//! orients it counter-clockwise), the area centroid as origin, and the
//! projection of a hint axis (global X, or Z when the normal is near X) as
//! $\mathbf{e}_1$.
//!
//! Solvers: Householder QR (default) or normal equations with Cholesky
//! ([`Solver`]); for uniformly spaced angles $\theta_k = \theta_0 + 2\pi
//! k/M$, $M > 2J$, the columns are discretely orthogonal and the
//! least-squares solution is the truncated DFT, computed by [`fit_fft`] after
//! resampling the polyline uniformly in the chosen parameter.

use super::metrics::{errors, FitErrors};
use super::{Frame, Gec, GecError};
use crate::mesh::{dist, norm};
use nalgebra::DMatrix;
use rustfft::num_complex::Complex;
use std::f64::consts::PI;

/// Two points closer than this times the polyline's diameter are "repeated".
pub const REPEAT_TOL: f64 = 1e-12;
/// Default planarity tolerance (relative to the diameter).
pub const PLANARITY_TOL: f64 = 1e-6;
/// Ratio of smallest to largest |R_ii| below which QR reports rank deficiency.
pub const RANK_TOL: f64 = 1e-12;

/// `(centre, x pairs, y pairs)` of a fitted GEC.
pub type Coefficients = ([f64; 2], Vec<[f64; 2]>, Vec<[f64; 2]>);

/// How data points get their angle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum Param {
    /// Equal steps in the point index.
    Uniform,
    /// Steps proportional to the chord lengths.
    #[default]
    ChordLength,
    /// Steps proportional to the square roots of the chord lengths.
    Centripetal,
    /// The polar angle about the area centroid (star-shaped curves only).
    PolarAngle,
}

impl Param {
    /// All choices.
    pub const ALL: [Param; 4] = [
        Param::Uniform,
        Param::ChordLength,
        Param::Centripetal,
        Param::PolarAngle,
    ];

    /// Stable name (CLI and JSON).
    pub fn name(self) -> &'static str {
        match self {
            Param::Uniform => "uniform",
            Param::ChordLength => "chord",
            Param::Centripetal => "centripetal",
            Param::PolarAngle => "polar",
        }
    }
}

impl std::str::FromStr for Param {
    type Err = GecError;
    fn from_str(s: &str) -> Result<Param, GecError> {
        Param::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                GecError::InvalidParameter(format!(
                    "unknown parameterisation '{s}' (uniform, chord, centripetal, polar)"
                ))
            })
    }
}

/// Linear least-squares solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum Solver {
    /// Householder QR of the design matrix.
    #[default]
    Qr,
    /// Cholesky of the normal equations $A^T A c = A^T b$.
    NormalEquations,
}

/// The plane the curve is placed in.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum FrameChoice {
    /// Fitted (Newell normal, area centroid).
    #[default]
    Auto,
    /// Given: points are projected onto it (still checked for planarity).
    Given(Frame),
}

/// Options of [`fit`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitOptions {
    pub terms: usize,
    pub param: Param,
    pub solver: Solver,
    pub frame: FrameChoice,
    /// Largest allowed distance from the plane, relative to the diameter.
    pub planarity_tol: f64,
    /// Angle of the first point for the non-polar parameterisations
    /// (`None`: its polar angle about the area centroid).
    pub theta0: Option<f64>,
}

impl FitOptions {
    /// Defaults with `terms` terms.
    pub fn new(terms: usize) -> FitOptions {
        FitOptions {
            terms,
            param: Param::default(),
            solver: Solver::default(),
            frame: FrameChoice::Auto,
            planarity_tol: PLANARITY_TOL,
            theta0: None,
        }
    }
}

/// A fitted GEC with its parameters and errors.
#[derive(Clone, Debug)]
pub struct FitReport {
    pub gec: Gec,
    /// The angle given to each input point.
    pub thetas: Vec<f64>,
    /// Input points in the frame.
    pub plane_points: Vec<[f64; 2]>,
    /// Largest distance of an input point from the plane.
    pub off_plane: f64,
    pub errors: FitErrors,
}

/// A validated closed polyline in its plane.
#[derive(Clone, Debug)]
pub struct Section {
    pub frame: Frame,
    pub points: Vec<[f64; 2]>,
    pub off_plane: f64,
    pub diameter: f64,
}

fn diameter(points: &[[f64; 3]]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    dist(lo, hi)
}

/// Smallest and largest diameter (and largest coordinate magnitude) of a
/// point set the fit accepts: outside, squared distances underflow or
/// overflow and the repeated-point, planarity and least-squares tests would
/// give false answers.
pub const SCALE_RANGE: (f64, f64) = (1e-100, 1e100);

/// Refuses points whose diameter or coordinates lie outside
/// [`SCALE_RANGE`] (a clear error instead of a false "coincide" or a
/// non-finite fit).
pub fn check_scale(points: &[[f64; 3]]) -> Result<(), GecError> {
    let (lo, hi) = SCALE_RANGE;
    if let Some(i) = points.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
        return Err(GecError::NonFinite {
            index: i,
            point: points[i],
        });
    }
    let big = points.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut d = [0.0f64; 3];
    for k in 0..3 {
        let (a, b) = points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p[k]), b.max(p[k]))
            });
        d[k] = b - a;
    }
    let span = d[0].max(d[1]).max(d[2]);
    if points.len() > 1 && !(span >= lo && big <= hi) {
        return Err(GecError::InvalidParameter(format!(
            "the points span {span:.3e} with coordinates up to {big:.3e}; the fit supports spans of at least {lo:e} and coordinates up to {hi:e} (rescale the input)"
        )));
    }
    Ok(())
}

/// Signed area and area centroid of a closed planar polygon.
pub fn polygon_area_centroid(p: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let n = p.len();
    let (mut a, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (q, r) = (p[i], p[(i + 1) % n]);
        let c = q[0] * r[1] - r[0] * q[1];
        a += c;
        cx += (q[0] + r[0]) * c;
        cy += (q[1] + r[1]) * c;
    }
    a *= 0.5;
    if a == 0.0 {
        return (0.0, [0.0; 2]);
    }
    (a, [cx / (6.0 * a), cy / (6.0 * a)])
}

/// Validates a closed polyline (finite, no repeated consecutive points, at
/// least `min_points`), fits or applies the frame, projects the points.
pub fn section(
    points: &[[f64; 3]],
    frame: FrameChoice,
    planarity_tol: f64,
    min_points: usize,
) -> Result<Section, GecError> {
    if !(planarity_tol.is_finite() && planarity_tol >= 0.0) {
        return Err(GecError::InvalidParameter(format!(
            "planarity tolerance {planarity_tol}"
        )));
    }
    if let Some((i, p)) = points
        .iter()
        .enumerate()
        .find(|(_, p)| !p.iter().all(|x| x.is_finite()))
    {
        return Err(GecError::NonFinite {
            index: i,
            point: *p,
        });
    }
    let n = points.len();
    if n < min_points.max(3) {
        return Err(GecError::Degenerate(format!(
            "{n} points, at least {} needed",
            min_points.max(3)
        )));
    }
    let diam = diameter(points);
    if diam.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) || !diam.is_finite() {
        return Err(GecError::Degenerate("all points coincide".into()));
    }
    for i in 0..n {
        let j = (i + 1) % n;
        if dist(points[i], points[j]) <= REPEAT_TOL * diam {
            return Err(GecError::RepeatedPoint {
                first: i.min(j),
                second: i.max(j),
            });
        }
    }
    let frame = match frame {
        FrameChoice::Given(f) => Frame::new(f.origin, f.e1, f.e2)?,
        FrameChoice::Auto => {
            // Newell's normal (oriented: counter-clockwise about it)
            let mut nrm = [0.0; 3];
            let mut mean = [0.0; 3];
            for i in 0..n {
                let (a, b) = (points[i], points[(i + 1) % n]);
                nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
                nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
                nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
                for k in 0..3 {
                    mean[k] += a[k] / n as f64;
                }
            }
            if norm(nrm) <= REPEAT_TOL * diam * diam {
                return Err(GecError::Degenerate("the polygon encloses no area".into()));
            }
            let f0 = Frame::from_normal(mean, nrm, [1.0, 0.0, 0.0])?;
            let p2: Vec<[f64; 2]> = points.iter().map(|p| f0.project(*p).0).collect();
            let (_, c) = polygon_area_centroid(&p2);
            let o = f0.place(c[0], c[1]);
            Frame { origin: o, ..f0 }
        }
    };
    let mut off = 0.0f64;
    let plane: Vec<[f64; 2]> = points
        .iter()
        .map(|p| {
            let (q, d) = frame.project(*p);
            off = off.max(d.abs());
            q
        })
        .collect();
    if off > planarity_tol * diam {
        return Err(GecError::NotPlanar {
            deviation: off,
            tolerance: planarity_tol * diam,
        });
    }
    let (area, _) = polygon_area_centroid(&plane);
    if area.abs() <= REPEAT_TOL * diam * diam {
        return Err(GecError::Degenerate(
            "the polygon encloses no area in its plane".into(),
        ));
    }
    Ok(Section {
        frame,
        points: plane,
        off_plane: off,
        diameter: diam,
    })
}

/// A closing gap longer than this many median segments (and longer than
/// every other segment) marks a polyline as open; see [`check_closed`].
pub const OPEN_GAP_FACTOR: f64 = 10.0;

/// Drops a closing copy of the first point (last point within
/// [`REPEAT_TOL`] times the diameter of the first), the usual way files
/// write a closed polyline. Returns whether a point was dropped.
pub fn strip_closing_copy(points: &mut Vec<[f64; 3]>) -> bool {
    if points.len() < 2 {
        return false;
    }
    let diam = diameter(points);
    let (first, last) = (points[0], points[points.len() - 1]);
    if diam.is_finite() && dist(first, last) <= REPEAT_TOL * diam {
        points.pop();
        return true;
    }
    false
}

/// The first pair `(i, j)`, `i < j`, of points closer than [`REPEAT_TOL`]
/// times the diameter, consecutive or not (sort by x, then scan the window
/// of equal-enough x: O(n log n) for generic data). Non-finite points are
/// skipped (they are reported by [`fit`]).
pub fn repeated_points(points: &[[f64; 3]]) -> Option<(usize, usize)> {
    let finite: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].iter().all(|v| v.is_finite()))
        .collect();
    let sel: Vec<[f64; 3]> = finite.iter().map(|&i| points[i]).collect();
    let tol = REPEAT_TOL * diameter(&sel);
    if !tol.is_finite() {
        return None;
    }
    let mut order = finite;
    order.sort_by(|&a, &b| points[a][0].total_cmp(&points[b][0]));
    let mut best: Option<(usize, usize)> = None;
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if points[j][0] - points[i][0] > tol {
                break;
            }
            if dist(points[i], points[j]) <= tol {
                let pair = (i.min(j), i.max(j));
                if best.is_none_or(|b| pair < b) {
                    best = Some(pair);
                }
            }
        }
    }
    best
}

/// Rejects a polyline that looks open: with $g$ the gap from the last point
/// back to the first and $\tilde s$ the median of the other segments, the
/// polyline is open when $g > $ [`OPEN_GAP_FACTOR`] $\tilde s$ **and** $g$
/// exceeds every other segment. (A uniformly sampled arc missing more than
/// about ten sample steps is open; a closed curve sampled densely on one
/// side and sparsely on the other is not, because its closing segment is no
/// longer than the sparse ones.) Needs at least 3 points.
pub fn check_closed(points: &[[f64; 3]]) -> Result<(), GecError> {
    let n = points.len();
    if n < 3 {
        return Ok(());
    }
    let mut segs: Vec<f64> = (0..n - 1).map(|i| dist(points[i], points[i + 1])).collect();
    let gap = dist(points[n - 1], points[0]);
    let longest = segs.iter().copied().fold(0.0, f64::max);
    segs.sort_by(f64::total_cmp);
    let median = segs[segs.len() / 2];
    if !(gap.is_finite() && median.is_finite()) {
        return Ok(());
    }
    if gap > OPEN_GAP_FACTOR * median && gap > longest {
        return Err(GecError::OpenPolyline {
            gap,
            median,
            ratio: if median > 0.0 {
                gap / median
            } else {
                f64::INFINITY
            },
        });
    }
    Ok(())
}

/// The angle of each point under `param` (see the module doc).
pub fn parameters(p: &[[f64; 2]], param: Param, theta0: Option<f64>) -> Vec<f64> {
    let n = p.len();
    let (area, c) = polygon_area_centroid(p);
    let polar = |q: [f64; 2]| (q[1] - c[1]).atan2(q[0] - c[0]);
    if param == Param::PolarAngle {
        return p.iter().map(|q| polar(*q)).collect();
    }
    let sign = if area < 0.0 { -1.0 } else { 1.0 };
    let step = |i: usize| -> f64 {
        let d = dist2(p[i], p[(i + 1) % n]);
        match param {
            Param::Uniform => 1.0,
            Param::ChordLength => d,
            Param::Centripetal => d.sqrt(),
            Param::PolarAngle => unreachable!(),
        }
    };
    let steps: Vec<f64> = (0..n).map(step).collect();
    let total: f64 = steps.iter().sum();
    let t0 = theta0.unwrap_or_else(|| polar(p[0]));
    let mut s = 0.0;
    let mut out = Vec::with_capacity(n);
    for st in &steps {
        out.push(t0 + sign * 2.0 * PI * s / total);
        s += st;
    }
    out
}

fn dist2(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The design matrix `[1, cos t, sin t, .., cos J t, sin J t]` (harmonics by
/// the angle-addition recurrence from `cos t, sin t`: two trigonometric
/// calls per row; the recurrence's rounding grows like `n eps`).
pub fn design_matrix(thetas: &[f64], terms: usize) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(thetas.len(), 2 * terms + 1);
    for (r, &t) in thetas.iter().enumerate() {
        a[(r, 0)] = 1.0;
        let (s1, c1) = t.sin_cos();
        let (mut c, mut s) = (c1, s1);
        for n in 1..=terms {
            a[(r, 2 * n - 1)] = c;
            a[(r, 2 * n)] = s;
            (c, s) = (c * c1 - s * s1, s * c1 + c * s1);
        }
    }
    a
}

/// Solves the least-squares problem for in-plane points at given angles.
/// Returns `(centre, x pairs, y pairs)`.
pub fn solve(
    points: &[[f64; 2]],
    thetas: &[f64],
    terms: usize,
    solver: Solver,
) -> Result<Coefficients, GecError> {
    check_counts(points.len(), terms)?;
    let a = design_matrix(thetas, terms);
    let b = DMatrix::from_fn(points.len(), 2, |r, c| points[r][c]);
    let sol = match solver {
        Solver::Qr => {
            let qr = a.qr();
            let r = qr.r();
            let dmax = (0..r.ncols()).map(|i| r[(i, i)].abs()).fold(0.0, f64::max);
            let dmin = (0..r.ncols())
                .map(|i| r[(i, i)].abs())
                .fold(f64::INFINITY, f64::min);
            if dmin.is_nan() || dmin <= RANK_TOL * dmax {
                return Err(GecError::RankDeficient { terms });
            }
            let qtb = qr.q().transpose() * b;
            r.solve_upper_triangular(&qtb)
                .ok_or(GecError::RankDeficient { terms })?
        }
        Solver::NormalEquations => {
            let ata = a.transpose() * &a;
            let atb = a.transpose() * b;
            let ch = ata.cholesky().ok_or(GecError::RankDeficient { terms })?;
            ch.solve(&atb)
        }
    };
    if sol.iter().any(|v| !v.is_finite()) {
        return Err(GecError::RankDeficient { terms });
    }
    Ok(unpack(&sol, terms))
}

fn unpack(sol: &DMatrix<f64>, terms: usize) -> ([f64; 2], Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let centre = [sol[(0, 0)], sol[(0, 1)]];
    let x = (1..=terms)
        .map(|n| [sol[(2 * n - 1, 0)], sol[(2 * n, 0)]])
        .collect();
    // y takes (sin, cos) pairs
    let y = (1..=terms)
        .map(|n| [sol[(2 * n, 1)], sol[(2 * n - 1, 1)]])
        .collect();
    (centre, x, y)
}

/// Checks J against [`crate::limits::GEC_TERMS`] (so `2J + 1` cannot wrap),
/// the point count against `2J + 1`, and the least-squares cost
/// (`n x (2J+1)` design matrix, `n (2J+1)^2` operations) against the budgets.
pub fn check_counts(n: usize, terms: usize) -> Result<(), GecError> {
    if terms == 0 {
        return Err(GecError::ZeroTerms);
    }
    crate::limits::check("terms J", terms, crate::limits::GEC_TERMS)?;
    let cols = (2 * terms + 1) as f64;
    let what = format!("the least-squares fit of {n} points");
    crate::limits::check_memory("terms J", terms, &what, 8.0 * 3.0 * n as f64 * cols)?;
    crate::limits::check_work("terms J", terms, &what, 2.0 * n as f64 * cols * cols)?;
    if n < 2 * terms + 1 {
        return Err(GecError::TooFewPoints {
            terms,
            needed: 2 * terms + 1,
            got: n,
        });
    }
    Ok(())
}

/// Fits a closed polyline (3D points in a plane, not repeating the first
/// point at the end) with `opts.terms` terms.
pub fn fit(points: &[[f64; 3]], opts: &FitOptions) -> Result<FitReport, GecError> {
    check_scale(points)?;
    check_counts(points.len(), opts.terms)?;
    let sec = section(points, opts.frame, opts.planarity_tol, 2 * opts.terms + 1)?;
    let thetas = parameters(&sec.points, opts.param, opts.theta0);
    let (centre, x, y) = solve(&sec.points, &thetas, opts.terms, opts.solver)?;
    finish(sec, thetas, centre, x, y)
}

fn finish(
    sec: Section,
    thetas: Vec<f64>,
    centre: [f64; 2],
    x: Vec<[f64; 2]>,
    y: Vec<[f64; 2]>,
) -> Result<FitReport, GecError> {
    let gec = Gec::new(sec.frame, centre, x, y)?;
    let errors = errors(&gec, &sec.points);
    Ok(FitReport {
        gec,
        thetas: thetas.iter().map(|t| t.rem_euclid(2.0 * PI)).collect(),
        plane_points: sec.points,
        off_plane: sec.off_plane,
        errors,
    })
}

/// Truncated DFT of in-plane points at uniform angles `theta_0 + 2 pi k / M`:
/// the least-squares solution for those angles (M > 2J).
pub fn dft_coefficients(
    points: &[[f64; 2]],
    theta0: f64,
    terms: usize,
) -> Result<Coefficients, GecError> {
    let m = points.len();
    check_counts(m, terms)?;
    let mut buf: Vec<Complex<f64>> = points.iter().map(|p| Complex::new(p[0], p[1])).collect();
    rustfft::FftPlanner::new()
        .plan_fft_forward(m)
        .process(&mut buf);
    // z_k = x_k + i y_k; Z_n = sum z_k e^{-2 pi i n k / M}. For a real
    // sequence f: a_n = (2/M) Re F_n, b_n = -(2/M) Im F_n, with
    // F_n = (Z_n + conj Z_{M-n}) / 2 (x) and (Z_n - conj Z_{M-n}) / (2i) (y).
    let mf = m as f64;
    let centre = [buf[0].re / mf, buf[0].im / mf];
    let mut x = Vec::with_capacity(terms);
    let mut y = Vec::with_capacity(terms);
    for n in 1..=terms {
        let zn = buf[n];
        let zc = buf[m - n].conj();
        let fx = (zn + zc) * 0.5;
        let fy = (zn - zc) * Complex::new(0.0, -0.5);
        // shift by theta0: coefficients in theta, samples at theta0 + ...
        let rot = Complex::from_polar(1.0, -(n as f64) * theta0);
        let (gx, gy) = (fx * rot, fy * rot);
        let (ax, bx) = (2.0 * gx.re / mf, -2.0 * gx.im / mf);
        let (ay_cos, ay_sin) = (2.0 * gy.re / mf, -2.0 * gy.im / mf);
        x.push([ax, bx]);
        y.push([ay_sin, ay_cos]);
    }
    Ok((centre, x, y))
}

/// Resamples a closed polyline at `m` angles uniform in `[t0, t0 + 2 pi)`
/// by linear interpolation in the (monotone) parameter `thetas`.
pub fn resample_uniform(
    points: &[[f64; 2]],
    thetas: &[f64],
    m: usize,
) -> Result<(f64, Vec<[f64; 2]>), GecError> {
    let n = points.len();
    // unwrap into a strictly increasing sequence spanning one turn
    let mut t = Vec::with_capacity(n + 1);
    t.push(thetas[0]);
    for i in 1..n {
        let mut d = (thetas[i] - thetas[i - 1]).rem_euclid(2.0 * PI);
        if d > PI {
            d -= 2.0 * PI;
        }
        t.push(t[i - 1] + d);
    }
    let turn = t[n - 1] - t[0];
    let sign = if turn < 0.0 { -1.0 } else { 1.0 };
    t.push(t[0] + sign * 2.0 * PI);
    let s: Vec<f64> = t.iter().map(|v| sign * (v - t[0])).collect();
    if s.windows(2).any(|w| w[1] <= w[0]) {
        return Err(GecError::InvalidParameter(
            "the parameter is not monotone along the polyline (polar angle on a curve that is not star-shaped?)".into(),
        ));
    }
    let mut out = Vec::with_capacity(m);
    let mut seg = 0;
    for k in 0..m {
        let sk = 2.0 * PI * k as f64 / m as f64;
        while seg + 1 < n && s[seg + 1] <= sk {
            seg += 1;
        }
        let (a, b) = (points[seg], points[(seg + 1) % n]);
        let w = (sk - s[seg]) / (s[seg + 1] - s[seg]);
        out.push([a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1])]);
    }
    // samples are at angle t0 + sign * 2 pi k / m; for sign < 0 reverse order
    if sign < 0.0 {
        out[1..].reverse();
    }
    Ok((t[0], out))
}

/// The FFT path: resample uniformly in the chosen parameter with `m` points
/// (`m > 2J`), then take the truncated DFT. Errors are measured against the
/// original points.
pub fn fit_fft(points: &[[f64; 3]], opts: &FitOptions, m: usize) -> Result<FitReport, GecError> {
    check_scale(points)?;
    check_counts(points.len(), opts.terms)?;
    check_counts(m, opts.terms)?;
    let sec = section(points, opts.frame, opts.planarity_tol, 2 * opts.terms + 1)?;
    let thetas = parameters(&sec.points, opts.param, opts.theta0);
    let (t0, uni) = resample_uniform(&sec.points, &thetas, m)?;
    let (centre, x, y) = dft_coefficients(&uni, t0, opts.terms)?;
    finish(sec, thetas, centre, x, y)
}

/// The smallest J in `1..=max_terms` whose relative ErM (see
/// [`super::metrics`]) is at most `tol`.
pub fn fit_auto(
    points: &[[f64; 3]],
    tol: f64,
    max_terms: usize,
    opts: &FitOptions,
) -> Result<FitReport, GecError> {
    if !(tol.is_finite() && tol > 0.0) {
        return Err(GecError::InvalidParameter(format!(
            "tolerance must be positive and finite, got {tol}"
        )));
    }
    if max_terms == 0 {
        return Err(GecError::ZeroTerms);
    }
    crate::limits::check("max terms", max_terms, crate::limits::GEC_TERMS)?;
    let cap = max_terms.min(points.len().saturating_sub(1) / 2);
    check_counts(points.len(), 1)?;
    let c = cap as f64;
    crate::limits::check_work(
        "max terms",
        max_terms,
        &format!("the search over J = 1..={cap} with {} points", points.len()),
        2.0 * points.len() as f64 * (4.0 / 3.0) * c * c * c,
    )?;
    let mut best = f64::INFINITY;
    for j in 1..=cap {
        let r = fit(points, &FitOptions { terms: j, ..*opts })?;
        best = best.min(r.errors.erm_rel);
        if r.errors.erm_rel <= tol {
            return Ok(r);
        }
    }
    Err(GecError::ToleranceUnreachable {
        tol,
        best,
        max_terms: cap,
    })
}
