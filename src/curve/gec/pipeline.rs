//! The `gec fit` and `gec eval` pipelines as library calls: validation of a
//! points file, the choice of plane and solver, the fit and the check of its
//! result; evaluation of a fitted curve's derivatives in radians or turns.
//! The CLI (`src/cli/gec.rs`) parses flags, calls these and prints.

use super::fit::{check_scale, fit, fit_auto, fit_fft, FitOptions, FitReport, FrameChoice};
use super::input::PointsFile;
use super::{
    check_closed, repeated_points, strip_closing_copy, Frame, Gec, GecError, Param, Solver,
};
use std::f64::consts::PI;

/// J when neither `terms` nor `tol` is given.
pub const DEFAULT_TERMS: usize = 10;
/// Largest J tried by a tolerance-driven fit unless told otherwise.
pub const DEFAULT_MAX_TERMS: usize = 30;

/// Plane of the fitted curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plane {
    /// Fitted plane (Newell normal, origin at the area centroid).
    Auto,
    /// The plane z = z of the points (all z equal), axes X and Y.
    Z,
}

/// Least-squares method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Householder QR of the design matrix.
    Qr,
    /// Cholesky of the normal equations.
    Normal,
    /// Uniform resampling in the parameter, then a truncated FFT.
    Fft,
}

/// What to fit and how; [`Default`] gives the documented defaults.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitRequest {
    /// J; [`DEFAULT_TERMS`] when `None` and no `tol`.
    pub terms: Option<usize>,
    /// Smallest J whose relative ErM is at most this.
    pub tol: Option<f64>,
    pub max_terms: usize,
    pub param: Param,
    /// Angle of the first point (default: its polar angle about the centroid).
    pub theta0: Option<f64>,
    pub method: Method,
    /// `None`: `Z` when every point has the same z, `Auto` otherwise.
    pub plane: Option<Plane>,
    /// Skip the test that the closing gap looks like an opening.
    pub assume_closed: bool,
}

impl Default for FitRequest {
    fn default() -> FitRequest {
        FitRequest {
            terms: None,
            tol: None,
            max_terms: DEFAULT_MAX_TERMS,
            param: Param::default(),
            theta0: None,
            method: Method::Qr,
            plane: None,
            assume_closed: false,
        }
    }
}

/// Why a fit request failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitFailure {
    #[error("the file declares the polyline open; a GEC needs a closed cross section")]
    DeclaredOpen,
    #[error("theta0 {0}: must be finite")]
    Theta0(f64),
    #[error("--frame z needs every point at the same z; use --frame auto")]
    NotFlat,
    #[error("--solver fft needs --terms (--tol uses least squares)")]
    FftNeedsTerms,
    /// The closing gap looks like an opening (`assume_closed` skips this).
    #[error("{0}")]
    Open(GecError),
    #[error("the fit produced non-finite values")]
    NonFiniteResult,
    #[error(transparent)]
    Gec(#[from] GecError),
}

/// A fit with what was done to its input.
#[derive(Clone, Debug)]
pub struct FitOutcome {
    pub report: FitReport,
    /// Points fitted (after dropping a closing copy).
    pub points: usize,
    pub dropped_closing_copy: bool,
}

/// Validates a points file and fits it. Errors about one point carry its
/// index (`GecError::NonFinite`, `GecError::RepeatedPoint`) so the caller
/// can name its line.
pub fn fit_points(input: &PointsFile, req: &FitRequest) -> Result<FitOutcome, FitFailure> {
    if let Some(t) = req.theta0.filter(|t| !t.is_finite()) {
        return Err(FitFailure::Theta0(t));
    }
    if input.declared_open {
        return Err(FitFailure::DeclaredOpen);
    }
    let mut points = input.points.clone();
    let dropped = strip_closing_copy(&mut points);
    check_scale(&points)?;
    if let Some((first, second)) = repeated_points(&points) {
        return Err(GecError::RepeatedPoint { first, second }.into());
    }
    if !req.assume_closed {
        check_closed(&points).map_err(FitFailure::Open)?;
    }
    let z0 = points[0][2];
    let flat = points.iter().all(|p| p[2] == z0);
    let frame = match req
        .plane
        .unwrap_or(if flat { Plane::Z } else { Plane::Auto })
    {
        Plane::Z if !flat => return Err(FitFailure::NotFlat),
        Plane::Z => FrameChoice::Given(Frame::z_plane(z0)),
        Plane::Auto => FrameChoice::Auto,
    };
    let opts = FitOptions {
        param: req.param,
        frame,
        theta0: req.theta0,
        solver: if req.method == Method::Normal {
            Solver::NormalEquations
        } else {
            Solver::Qr
        },
        ..FitOptions::new(req.terms.unwrap_or(DEFAULT_TERMS))
    };
    let report = match (req.tol, req.method) {
        (Some(_), Method::Fft) => return Err(FitFailure::FftNeedsTerms),
        (Some(e), _) => fit_auto(&points, e, req.max_terms, &opts)?,
        (None, Method::Fft) => {
            let m = points.len().max(4 * opts.terms + 2);
            fit_fft(&points, &opts, m)?
        }
        (None, _) => fit(&points, &opts)?,
    };
    if !(report.gec.is_finite() && report.errors.erm.is_finite() && report.errors.era.is_finite()) {
        return Err(FitFailure::NonFiniteResult);
    }
    Ok(FitOutcome {
        report,
        points: points.len(),
        dropped_closing_copy: dropped,
    })
}

/// `n` parameters evenly around one turn: `theta = 2 pi k / n`, or with
/// `turns` paper 000's `v = k / n`.
pub fn even_parameters(n: usize, turns: bool) -> Vec<f64> {
    (0..n)
        .map(|k| {
            let f = k as f64 / n as f64;
            if turns {
                f
            } else {
                2.0 * PI * f
            }
        })
        .collect()
}

/// The `k`-th derivative of `g` at each parameter: `t` is the angle theta,
/// or with `turns` paper 000's `v` (theta = 2 pi v, derivatives with respect
/// to v, so scaled by (2 pi)^k). Refuses non-finite parameters and values.
pub fn derivatives(g: &Gec, ts: &[f64], k: usize, turns: bool) -> Result<Vec<[f64; 3]>, GecError> {
    if let Some(t) = ts.iter().find(|t| !t.is_finite()) {
        return Err(GecError::InvalidParameter(format!(
            "--at {t}: must be finite"
        )));
    }
    let factor = if turns {
        (2.0 * PI).powi(k as i32)
    } else {
        1.0
    };
    let pts: Vec<[f64; 3]> = ts
        .iter()
        .map(|&t| {
            let theta = if turns { 2.0 * PI * t } else { t };
            let d = g.derivative(theta, k);
            [d[0] * factor, d[1] * factor, d[2] * factor]
        })
        .collect();
    if pts.iter().flatten().any(|x| !x.is_finite()) {
        return Err(GecError::InvalidParameter(
            "non-finite value (parameter too large?)".into(),
        ));
    }
    Ok(pts)
}
