//! Paper-literal checks of paper 000 that build a printed statement itself:
//! the force profiles of eqs 2-3 with the printed fraction placement and the
//! printed maximum, and eq 15's `dbar` without `a_t2` against the Galerkin
//! solution when `a_t2` alone varies.

use super::*;
use crate::check::{worst, Worst};
use crate::pde4::force::bump;

/// Samples of the force range in the profile checks.
const PROFILE_SAMPLES: usize = 200;

/// Eq 2 as printed: `P_t = p_t sin pi(u - u_p0) / (u_p1 - u_p0)` (unit
/// magnitude), the division outside the sine.
pub fn printed_line_profile(u0: f64, u1: f64, u: f64) -> f64 {
    (PI * (u - u0)).sin() / (u1 - u0)
}

/// Eq 3 as printed: `p_t sin pi(u - u_p0) sin pi(v - v_p0) / [(u_p1 - u_p0)(v_p1 - v_p0)]`.
pub fn printed_area_profile(r: [f64; 4], u: f64, v: f64) -> f64 {
    let [u0, u1, v0, v1] = r;
    (PI * (u - u0)).sin() * (PI * (v - v0)).sin() / ((u1 - u0) * (v1 - v0))
}

/// Where the corrected bump on `[a, b]` peaks (grid search, `PROFILE_SAMPLES`).
fn corrected_peak(a: f64, b: f64) -> f64 {
    let mut best = (f64::NEG_INFINITY, f64::NAN);
    for i in 0..=PROFILE_SAMPLES {
        let x = a + (b - a) * i as f64 / PROFILE_SAMPLES as f64;
        let y = bump(a, b, x);
        if y > best.0 {
            best = (y, x);
        }
    }
    best.1
}

pub(super) fn printed_statement_checks(out: &mut Vec<Check>) {
    // eq 2 on a range of non-integer length (the sample line force's)
    let (u0, u1) = (0.2, 0.7);
    let grid = |a: f64, b: f64| {
        (0..=PROFILE_SAMPLES).map(move |i| a + (b - a) * i as f64 / PROFILE_SAMPLES as f64)
    };
    let line = grid(u0, u1)
        .map(|u| (printed_line_profile(u0, u1, u) - bump(u0, u1, u)).abs())
        .fold(0.0, worst);
    out.push(
        Check::paper_literal(F, P, "eq 2", "pde4.force.eq2_printed_profile", line, tol::ROUNDING, true)
            .note(format!("eq 2 built as printed, sin(pi(u - u0))/(u1 - u0), against the corrected bump sin(pi(u - u0)/(u1 - u0)) on [{u0}, {u1}]: max difference (the printed force is {:.3} at u1 where the force must vanish)", printed_line_profile(u0, u1, u1))),
    );
    let r = [0.35, 0.85, 0.4, 0.9];
    let mut area = 0.0f64;
    for u in grid(r[0], r[1]).step_by(10) {
        for v in grid(r[2], r[3]).step_by(10) {
            let right = bump(r[0], r[1], u) * bump(r[2], r[3], v);
            area = area.worst((printed_area_profile(r, u, v) - right).abs());
        }
    }
    out.push(
        Check::paper_literal(F, P, "eq 3", "pde4.force.eq3_printed_profile", area, tol::ROUNDING, true)
            .note("eq 3 built as printed (divisions outside the sines) against the corrected product of bumps on [0.35, 0.85] x [0.4, 0.9]: max difference"),
    );
    // the printed statement "maximum at u = (u_p1 - u_p0)/2"
    let printed_peak = 0.5 * (u1 - u0);
    let peak = corrected_peak(u0, u1);
    out.push(
        Check::paper_literal(F, P, "eqs 2-3", "pde4.force.eq2_printed_peak", (printed_peak - peak).abs(), 2.0 * (u1 - u0) / PROFILE_SAMPLES as f64, true)
            .note(format!("printed maximum u = (u1 - u0)/2 = {printed_peak} against the corrected force's peak {peak:.4} (grid search) on [{u0}, {u1}]")),
    );
    out.push(
        Check::new(
            F,
            P,
            "eqs 2-3",
            "pde4.force.corrected_peak_midpoint",
            Kind::Reference,
            (peak - 0.5 * (u0 + u1)).abs(),
            (u1 - u0) / PROFILE_SAMPLES as f64,
        )
        .note("the corrected bump peaks at the midpoint (u0 + u1)/2 (grid search, 200 samples)")
        .loose_because("a grid search: the midpoint is a grid sample, so it is found exactly; the tolerance is one grid step, the search's resolution"),
    );

    // eq 15: a_t2 varied alone, printed dbar and Galerkin
    let centre = |a2: f64, method| {
        plate_centre(
            ShapeParams {
                a1: 1.0,
                a2,
                a3: 1.0,
            },
            ForceKind::Uniform,
            PLATE_TERMS,
            method,
        )
    };
    let paper = four_sided::Method::Paper;
    let gal = four_sided::Method::Galerkin;
    let (p1, p3) = (centre(1.0, paper), centre(3.0, paper));
    let (g1, g3) = (centre(1.0, gal), centre(3.0, gal));
    let printed_effect = rel(p3, p1);
    let galerkin_effect = rel(g3, g1);
    out.push(
        Check::paper_literal(F, P, "eq 15", "pde4.four_sided.eq15_a2_printed_no_effect", printed_effect, tol::ROUNDING, false)
            .note(format!("eq 15 as printed has no a_t2: relative change of the printed centre deflection when a_t2 alone goes 1 -> 3 (uniform load, a1 = a3 = 1): {p1:.6} -> {p3:.6}")),
    );
    out.push(
        Check::paper_literal(F, P, "eq 15", "pde4.four_sided.eq15_a2_effect_missing", (galerkin_effect - printed_effect).abs(), tol::TABLE_4_DIGITS, true)
            .note(format!("the same a_t2 change in the Galerkin solution moves the centre deflection by {:.1} % ({g1:.6} -> {g3:.6}); the printed form misses that effect", 100.0 * galerkin_effect)),
    );
}
