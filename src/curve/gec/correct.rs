//! Parameter correction: the default GEC fit reaches the best geometric
//! error its parameter rule leads to.
//!
//! A parameter rule ([`super::Param`]) gives each data point
//! $\mathbf{p}_k$ an angle $\theta_k$ once, before the fit; the least
//! squares then minimises $\sum_k |\mathbf{C}(\theta_k) - \mathbf{p}_k|^2$,
//! a *parametric* error that is larger than the geometric one
//! $\sum_k \min_\theta |\mathbf{C}(\theta) - \mathbf{p}_k|^2$ wherever the
//! rule puts a point's angle away from where the fitted curve passes closest
//! to it (chord length is off at corners and where the curve's speed
//! varies). Parameter correction (Hoschek's intrinsic parameterisation)
//! alternates the two minimisations:
//!
//! 1. fit the coefficients at the angles $\theta_k$ (linear least squares);
//! 2. move each $\theta_k$ to the closest point of the fitted curve near it:
//!    Newton on $f(\theta) = \tfrac12|\mathbf{C}(\theta) - \mathbf{p}_k|^2$
//!    from $\theta_k$ ($\theta \leftarrow \theta - f'/f''$, steps clamped to
//!    $\pi / 4J$ so a point does not jump to another part of the curve; exact
//!    derivatives by jets).
//!
//! Each half-step lowers $\sum_k |\mathbf{C}(\theta_k) - \mathbf{p}_k|^2$,
//! so that sum decreases monotonically to a geometric least-squares fit. The
//! brief's measure is the maximum error ErM, which need not fall at every
//! step: the iteration keeps the iterate with the smallest maximum projected
//! distance, stops when that has not decreased (by more than [`GAIN_TOL`]
//! times the section's diagonal) for [`PATIENCE`] steps or after
//! [`MAX_CORRECTIONS`], and [`super::fit`] returns the corrected fit only if
//! its global ErM ([`super::metrics`]) is smaller than the uncorrected one's.
//! So the corrected fit is never worse than its parameter rule, by
//! construction (and `gec.correction_never_worse` measures it on the body).
//!
//! The default, [`Correction::Best`], does this from each parameter rule
//! and keeps the fit (corrected or not) with the smallest ErM: the rules
//! start from different local minima of the geometric error and none is
//! best on every section (on the MakeHuman sections at J = 10 uniform
//! angles, corrected, are best on the hips, chord length on the chest).
//! [`Correction::None`] keeps the old behaviour (angles from the rule only)
//! for comparison, [`Correction::Project`] corrects the given rule only.

use super::lsq::{solve, Coefficients, Solver};
use super::metrics::diagonal;
use super::{Frame, Gec};
use crate::jet::Jet;
use std::f64::consts::PI;

pub use super::lsq::Correction;

/// Most correction steps (fit, project).
pub const MAX_CORRECTIONS: usize = 100;
/// Steps without a smaller maximum distance before the iteration stops.
pub const PATIENCE: usize = 10;
/// A step counts as a gain only when the maximum distance falls by more
/// than this times the section's diagonal.
pub const GAIN_TOL: f64 = 1e-12;
/// Newton iterations of one local projection.
const PROJECT_ITERS: usize = 6;

/// Moves each angle to the closest curve point near it (Newton from the
/// given angle, steps clamped to `pi / 4J`). Returns the new angles and the
/// largest distance from a point to its curve point.
pub fn project_local(gec: &Gec, points: &[[f64; 2]], thetas: &[f64]) -> (Vec<f64>, f64) {
    let clamp = PI / (4 * gec.terms().max(1)) as f64;
    let mut worst = 0.0f64;
    let out = points
        .iter()
        .zip(thetas)
        .map(|(p, &t0)| {
            let d2 = |t: f64| {
                let c = gec.eval_plane(t);
                (c[0] - p[0]).powi(2) + (c[1] - p[1]).powi(2)
            };
            let (mut t, mut best_t, mut best) = (t0, t0, d2(t0));
            for _ in 0..PROJECT_ITERS {
                let c = gec.eval_plane(Jet::<3, 1>::var_u(t));
                let r = [c[0].value() - p[0], c[1].value() - p[1]];
                let d1 = [c[0].deriv(1, 0), c[1].deriv(1, 0)];
                let dd = [c[0].deriv(2, 0), c[1].deriv(2, 0)];
                let g = r[0] * d1[0] + r[1] * d1[1];
                let h = d1[0] * d1[0] + d1[1] * d1[1] + r[0] * dd[0] + r[1] * dd[1];
                // f'' <= 0 (a point beyond the centre of curvature): a
                // gradient step scaled by |C'|^2 instead
                let h = if h > 0.0 {
                    h
                } else {
                    d1[0] * d1[0] + d1[1] * d1[1]
                };
                if !(h.is_finite() && h > 0.0 && g.is_finite()) {
                    break;
                }
                let step = (g / h).clamp(-clamp, clamp);
                t -= step;
                let d = d2(t);
                if d < best {
                    (best, best_t) = (d, t);
                }
                if step.abs() <= 1e-15 * (1.0 + t.abs()) {
                    break;
                }
            }
            worst = worst.max(best.sqrt());
            best_t
        })
        .collect();
    (out, worst)
}

/// The outcome of [`correct`].
#[derive(Clone, Debug)]
pub struct Corrected {
    /// The angles of the best iterate's least squares.
    pub thetas: Vec<f64>,
    pub coefficients: Coefficients,
    /// Largest local distance of the best iterate (from [`project_local`]).
    pub max_distance: f64,
    /// The same for the uncorrected fit.
    pub initial_max_distance: f64,
    /// The correction step that gave the best iterate.
    pub steps: usize,
}

/// Corrects the angles `thetas` of the fit `initial` (coefficients at those
/// angles) of in-plane `points` (see the module doc). Returns `None` when
/// no step lowered the maximum distance.
pub fn correct(
    points: &[[f64; 2]],
    thetas: &[f64],
    initial: &Gec,
    solver: Solver,
    frame: Frame,
) -> Option<Corrected> {
    let terms = initial.terms();
    let gain = GAIN_TOL * diagonal(points);
    let (mut t, first) = project_local(initial, points, thetas);
    let mut best: Option<Corrected> = None;
    let mut best_d = first;
    let mut stall = 0;
    for step in 1..=MAX_CORRECTIONS {
        let Ok(coeffs) = solve(points, &t, terms, solver) else {
            break;
        };
        let Ok(g) = Gec::new(frame, coeffs.0, coeffs.1.clone(), coeffs.2.clone()) else {
            break;
        };
        let (next, d) = project_local(&g, points, &t);
        if d < best_d - gain {
            best_d = d;
            best = Some(Corrected {
                thetas: t.clone(),
                coefficients: coeffs,
                max_distance: d,
                initial_max_distance: first,
                steps: step,
            });
            stall = 0;
        } else {
            stall += 1;
            if stall >= PATIENCE {
                break;
            }
        }
        t = next;
    }
    best
}
