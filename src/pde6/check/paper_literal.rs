//! Paper-literal checks of paper 002 that build a printed form itself.

use super::*;
use crate::check::worst;

/// Eq 26 as printed for the bottom patch P2 of a method-2 chain: x and y
/// from the patch, `z^{P2}(u, v) = A_{z0}^{P2}(0)` (a constant: the v-mean of
/// z at the patch's local u = 0). Returns the largest distance from the
/// printed patch to the sections in its range (16 v samples each).
pub fn eq26_printed_interpolation_error(c: &Chain, sections: &[Section]) -> f64 {
    c.pieces
        .first()
        .map_or(f64::NAN, |p| constant_z_error(p, sections))
}

/// Eq 27 as printed for the top patch P3: x and y from the patch,
/// `z^{P3}(u, v) = A_{z0}^{P3}(0)` constant. Largest distance from the printed
/// patch to the sections in its range (16 v samples each).
pub fn eq27_printed_interpolation_error(p: &Piece, sections: &[Section]) -> f64 {
    constant_z_error(p, sections)
}

/// Eqs 26-27 as printed: the piece's x and y with z frozen at
/// `A_{z0}(0)`; largest distance to the sections in the piece's range.
fn constant_z_error(p: &Piece, sections: &[Section]) -> f64 {
    let z0 = p.patch.section(0.0, 0).c0[2];
    sections
        .iter()
        .filter(|s| s.u >= p.start && s.u <= p.end)
        .map(|s| {
            section_distance(s, |v| {
                let [x, y, _] = p.eval(s.u, v);
                [x, y, z0]
            })
        })
        .fold(0.0, worst)
}

pub(super) fn printed_form_checks(out: &mut Vec<Check>) {
    let sec = synthetic_sections(12, 6);
    let (name, a) = SIGNS[0];
    let e =
        Chain::method2(a, &sec, 3).map_or(f64::NAN, |c| eq26_printed_interpolation_error(&c, &sec));
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 26", &format!("pde6.paper_literal.eq26_constant_z_{name}"), e, SOLVE_TOL, true)
            .note(format!("eq 26 built as printed for patch 2 of the 12-section method-2 chain (a = {a}): z = A_z0(0) constant; max distance to the sections C1-C4 it must pass through (eq 25); the corrected z = A_z0(u) passes within SOLVE_TOL (pde6.method2_interpolates_*)")),
    );
}
