//! The least-squares core of the GEC fit ([`super::fit`]): parameter
//! rules, the design matrix and its solvers, the fit's options and report.
//! Below the fit, its parameter correction ([`super::correct`]) and its FFT
//! path ([`super::fft`]), which all use it.

use super::metrics::{errors, FitErrors};
use super::section::{polygon_area_centroid, FrameChoice, Section, PLANARITY_TOL};
use super::{Gec, GecError};
use nalgebra::DMatrix;
use std::f64::consts::PI;

/// Whether the fit corrects the angles of its parameter rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum Correction {
    /// The angles of the parameter rule as they are (the fit before the
    /// correction existed).
    None,
    /// Iterative parameter correction from the angles of the given rule
    /// (see the module doc).
    Project,
    /// Per section, the best of every rule ([`super::Param::ALL`]), each
    /// uncorrected and corrected: the fit with the smallest ErM (the given
    /// rule first, so it wins ties).
    #[default]
    Best,
}

impl Correction {
    /// Every choice.
    pub const ALL: [Correction; 3] = [Correction::None, Correction::Project, Correction::Best];

    /// Stable name (CLI and JSON).
    pub fn name(self) -> &'static str {
        match self {
            Correction::None => "none",
            Correction::Project => "project",
            Correction::Best => "best",
        }
    }
}

impl std::str::FromStr for Correction {
    type Err = GecError;
    fn from_str(s: &str) -> Result<Correction, GecError> {
        Correction::ALL
            .into_iter()
            .find(|c| c.name() == s)
            .ok_or_else(|| {
                GecError::InvalidParameter(format!(
                    "unknown correction '{s}' (none, project, best)"
                ))
            })
    }
}

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

/// Options of [`fit`]. Outside the crate, start from
/// [`FitOptions::new`] (the defaults with a number of terms) and change
/// fields with the `with_*` setters (or by assignment).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct FitOptions {
    /// The number of terms J (given to [`FitOptions::new`]).
    pub terms: usize,
    /// How data points get their angle (default [`Param::ChordLength`]).
    pub param: Param,
    /// The least-squares solver (default [`Solver::Qr`]).
    pub solver: Solver,
    /// The plane the curve is placed in (default [`FrameChoice::Auto`]).
    pub frame: FrameChoice,
    /// Largest allowed distance from the plane, relative to the diameter
    /// (default [`PLANARITY_TOL`]).
    pub planarity_tol: f64,
    /// Whether the angles of `param` are corrected (default
    /// [`Correction::Best`]).
    pub correction: Correction,
    /// Angle of the first point for the non-polar parameterisations
    /// (default `None`: its polar angle about the area centroid).
    pub theta0: Option<f64>,
}

setters!(FitOptions {
    with_terms: terms: usize,
    with_param: param: Param,
    with_solver: solver: Solver,
    with_frame: frame: FrameChoice,
    with_planarity_tol: planarity_tol: f64,
    with_correction: correction: Correction,
    with_theta0: theta0: Option<f64>,
});

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
            correction: Correction::default(),
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
    /// The parameter rule whose angles started this fit.
    pub param: Param,
    /// The parameter-correction step whose fit this is (0: the angles of
    /// the parameter rule, uncorrected).
    pub correction_steps: usize,
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

pub(super) fn finish(
    sec: Section,
    thetas: Vec<f64>,
    centre: [f64; 2],
    x: Vec<[f64; 2]>,
    y: Vec<[f64; 2]>,
    param: Param,
) -> Result<FitReport, GecError> {
    let gec = Gec::new(sec.frame, centre, x, y)?;
    let errors = errors(&gec, &sec.points);
    Ok(FitReport {
        gec,
        thetas: thetas.iter().map(|t| t.rem_euclid(2.0 * PI)).collect(),
        plane_points: sec.points,
        off_plane: sec.off_plane,
        errors,
        param,
        correction_steps: 0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fit's reported angles are each point's angle, wrapped into
    /// [0, 2 pi): the curve at `thetas[i]` is the i-th point (2J + 1
    /// points are interpolated). A mutation sample found nothing checking
    /// the wrap (`rem_euclid(2 pi)` -> `rem_euclid(2 + pi)` survived).
    #[test]
    fn reported_angles_are_the_points_angles_in_one_turn() {
        // five points of a slanted, off-centre ellipse, starting at 3/4
        // of a turn so that some angles pass 2 pi before the wrap
        let pts: Vec<[f64; 3]> = (0..5)
            .map(|k| {
                let t = 1.5 * PI + 2.0 * PI * k as f64 / 5.0;
                [
                    2.0 + 3.0 * t.cos() - 0.5 * t.sin(),
                    -1.0 + 1.2 * t.sin(),
                    0.0,
                ]
            })
            .collect();
        let r = super::super::fit::fit(&pts, &FitOptions::new(2)).expect("five points fit J = 2");
        assert_eq!(r.thetas.len(), pts.len());
        for (t, q) in r.thetas.iter().zip(&r.plane_points) {
            assert!((0.0..2.0 * PI).contains(t), "angle {t} outside one turn");
            let p = r.gec.eval_plane(*t);
            let d = (p[0] - q[0]).hypot(p[1] - q[1]);
            assert!(d < crate::check::tol::SOLVE, "at {t}: {p:?} against {q:?}");
        }
    }

    /// Chord-length angles grow with the distance between neighbours, and
    /// centripetal ones with its square root; uniform ones do not look at
    /// the points (a mutation sample found nothing telling them apart:
    /// `dist2` -> 1.0 survived, every rule then uniform). A square of side
    /// 2 with a point added halfway up one side: chords 2, 1, 1, 2, 2.
    #[test]
    fn chord_length_and_centripetal_angles_follow_the_distances() {
        let p = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [2.0, 2.0], [0.0, 2.0]];
        let chords = [2.0f64, 1.0, 1.0, 2.0, 2.0];
        for (param, step) in [
            (Param::ChordLength, chords),
            (Param::Centripetal, chords.map(f64::sqrt)),
            (Param::Uniform, [1.0; 5]),
        ] {
            let total: f64 = step.iter().sum();
            let got = parameters(&p, param, Some(0.0));
            let mut s = 0.0;
            for (i, t) in got.iter().enumerate() {
                let want = 2.0 * PI * s / total;
                assert!(
                    (t - want).abs() <= crate::check::tol::ROUNDING,
                    "{param:?} point {i}: {t} against {want}"
                );
                s += step[i];
            }
        }
    }

    /// The corrections' stable names (`Correction::name`), each parsing
    /// back to its own choice (`FromStr`); a mutation sample found nothing
    /// reading a name (`name` -> `""` survived).
    #[test]
    fn each_correction_parses_back_from_its_name() {
        let names: Vec<&str> = Correction::ALL.iter().map(|c| c.name()).collect();
        assert_eq!(names, ["none", "project", "best"]);
        for c in Correction::ALL {
            assert_eq!(c.name().parse::<Correction>().ok(), Some(c));
        }
        assert!("".parse::<Correction>().is_err());
    }

    /// The counts a fit needs before any matrix is built: J >= 1 and
    /// 2J + 1 points (a mutation sample found that nothing else noticed
    /// `check_counts` doing nothing: the least squares then reports a rank
    /// deficiency instead of naming the missing points).
    #[test]
    fn check_counts_names_what_is_missing() {
        assert!(matches!(check_counts(10, 0), Err(GecError::ZeroTerms)));
        assert!(matches!(
            check_counts(4, 2),
            Err(GecError::TooFewPoints {
                terms: 2,
                needed: 5,
                got: 4
            })
        ));
        assert!(check_counts(5, 2).is_ok());
        let too_many = crate::limits::GEC_TERMS.max as usize + 1;
        assert!(check_counts(4 * too_many, too_many).is_err());
    }
}
