//! The late depth blend of a transition's columns (`TransitionSpec::child_rises`).
//!
//! A transition's cubic (or quintic) Hermite column moves from the
//! parent's end ring to the child's ring along one position weight for all
//! three coordinates: in a side view it cuts every corner between the two
//! rings on a smooth S. A drawn body's shoulders are square in the side
//! view: the back rises to the top of the shoulders, then turns toward the
//! neck (the corpus's chubby figure: the head's transition 3 % of the
//! height inside the drawn side outline, docs/drawing-corpus.md). Here the
//! depth part (model z, the side view's horizontal axis) of a column's
//! chord `Q - L` follows a weight that starts late, at `s0`, and so do the
//! depth parts of the child's end derivatives (on the plain blend's whole
//! interval the neck's slope, carried down from the child's ring, pushed
//! the held-back column 2 % of the height out past the drawn back); the
//! rest of the chord and the parent's end derivatives keep the blend's
//! own weights: the column rises along its parent first, then turns in
//! depth. The end derivatives do not change ([`late_weight`]), so the
//! joins keep their order of continuity and the seams (the loop, `s = 0`)
//! their shared tangent planes. Sketch-guided modeling fits `s0` per child
//! and side to the drawing (`sketch::tangent_fit`).

use super::ring::{hermite, quintic};

/// Largest start of a late depth blend ([`late_weight`]): past it the
/// column turns in depth within a tenth of the transition, about one of
/// the mesh's rows, which the mesh cannot show as a smooth turn.
pub const RISE_MAX: f64 = 0.9;

/// The d-th derivative at `s` of the late depth weights starting at `s0`,
/// `[position, end tangent, end second derivative]`: the blend's own
/// weights of the value, first and second derivative at its end (cubic:
/// `h01`, `h11` and none; quintic: `H3`, `H4`, `H5`) on the late interval,
/// `u = (s - s0) / w`, `w = 1 - s0`, scaled so that they weigh derivatives
/// in `s` (`w h11(u)`, `w^2 H5(u)`); all 0 before `s0`. The position
/// weight's first (and for the quintic, second) derivatives vanish at both
/// ends, and the tangent weights have the basis' own end derivatives at
/// `s = 1`, so the column's end derivatives are those of the plain blend;
/// `s0 = 0` gives the plain blend's weights.
pub fn late_weight(s: f64, s0: f64, d: usize, quintic_blend: bool) -> [f64; 3] {
    let w = 1.0 - s0.clamp(0.0, RISE_MAX);
    let u = (s - (1.0 - w)) / w;
    if u < 0.0 {
        return [0.0; 3];
    }
    let u = u.min(1.0);
    let chain = w.powi(d as i32);
    if quintic_blend {
        let h = quintic(u, d);
        [h[3] / chain, w * h[4] / chain, w * w * h[5] / chain]
    } else {
        let h = hermite(u, d);
        [h[2] / chain, w * h[3] / chain, 0.0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Finite-difference step and its error bound on these polynomials
    /// (weights of order 1, derivatives up to about 30 / w^2).
    const FD_STEP: f64 = 1e-6;
    const FD_TOL: f64 = 1e-4;
    const EXACT: f64 = 1e-12;
    const STARTS: [f64; 3] = [0.3, 0.6, RISE_MAX];

    #[test]
    fn no_rise_is_the_plain_blend() {
        for i in 0..=20 {
            let s = i as f64 / 20.0;
            for d in 0..3 {
                let h = hermite(s, d);
                let q = quintic(s, d);
                let c = late_weight(s, 0.0, d, false);
                let p = late_weight(s, 0.0, d, true);
                for (a, b) in [
                    (c[0], h[2]),
                    (c[1], h[3]),
                    (p[0], q[3]),
                    (p[1], q[4]),
                    (p[2], q[5]),
                ] {
                    assert!((a - b).abs() <= EXACT, "s {s} d {d}: {a} against {b}");
                }
            }
        }
    }

    /// The late weights have the plain basis' end conditions: every
    /// derivative used (up to 1 for the cubic, 2 for the quintic) is 0 at
    /// s = 0, and at s = 1 the position weight is 1, the tangent weight's
    /// first and the second-derivative weight's second derivatives are 1,
    /// every other 0.
    #[test]
    fn late_weights_keep_the_end_conditions() {
        for s0 in STARTS {
            for quintic_blend in [false, true] {
                let top = if quintic_blend { 2 } else { 1 };
                let k = if quintic_blend { 3 } else { 2 };
                for d in 0..=top {
                    let at0 = late_weight(0.0, s0, d, quintic_blend);
                    let at1 = late_weight(1.0, s0, d, quintic_blend);
                    for j in 0..k {
                        assert!(
                            at0[j].abs() <= EXACT,
                            "s0 {s0} d {d} weight {j} at 0: {}",
                            at0[j]
                        );
                        let want = if j == d { 1.0 } else { 0.0 };
                        assert!(
                            (at1[j] - want).abs() <= EXACT,
                            "s0 {s0} d {d} weight {j} at 1: {} (want {want})",
                            at1[j]
                        );
                    }
                }
            }
        }
    }

    /// Each derivative the blend uses is the derivative of the one below
    /// it (finite differences), on both sides of the start `s0`, where the
    /// weights join their zero part with a matching value and slope.
    #[test]
    fn late_weight_derivatives_are_consistent_across_the_start() {
        for s0 in STARTS {
            for quintic_blend in [false, true] {
                let top = if quintic_blend { 2 } else { 1 };
                let pts = [0.5 * s0, s0 - 1e-3, s0 + 1e-3, 0.5 * (1.0 + s0), 1.0 - 1e-3];
                for s in pts {
                    for d in 0..top {
                        let lo = late_weight(s - FD_STEP, s0, d, quintic_blend);
                        let hi = late_weight(s + FD_STEP, s0, d, quintic_blend);
                        let mid = late_weight(s, s0, d + 1, quintic_blend);
                        for j in 0..3 {
                            let fd = (hi[j] - lo[j]) / (2.0 * FD_STEP);
                            assert!(
                                (fd - mid[j]).abs() <= FD_TOL,
                                "s0 {s0} s {s} d {d} weight {j}: {fd} against {}",
                                mid[j]
                            );
                        }
                    }
                }
            }
        }
    }
}
