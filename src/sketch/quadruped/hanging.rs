//! A tail or trunk hanging below an animal's body (the corpus elephant's
//! trunk, a dog's tail held down), modeled as paper 000 composes a removed
//! part (sec 4.1: a tail "removed" from the primary profile and modeled
//! from its own profile): cut off the lateral outline where it leaves the
//! body, built from its own outline as a separate closed chain
//! ([`super::super::removed::upright_chain`]) that reaches into the body.
//!
//! Before, such a part was left out: no region holds it (the body's
//! slices end above the legs, the legs reach the ground), and the model
//! missed it by up to 46 % of the height (docs/drawing-corpus.md,
//! thirty-second measurement).
//!
//! A **hanging part** is a part below the body's lowest slice that ends
//! above the ground ([`super::landmarks::parts_below`], the ground as the
//! refusal of a hanging part between legs takes it, `GROUND_FRACTION` of
//! the way up to the legs' gaps). It is followed up from there while it
//! stays a part of its own: its slice interval overlaps no other interval
//! of the slice below and is less than [`HANG_STEP`] times as wide as
//! there. Where it stops, the outline's run below that height between the
//! interval's ends is the part's outline, closed by a root bulging
//! [`HANG_ROOT`] of its width up into the body.

use super::super::poly::slice;
use super::super::removed::upright_chain;
use super::super::segment::{GAP_FRACTION, GROUND_FRACTION};
use super::QuadLandmarks;
use crate::character::doc::PartSpec;

/// A hanging part is followed up while its slice interval grows by less
/// than this factor between two slices half a percent of the height apart:
/// a trunk or tail tapers smoothly (a few percent per slice), and where it
/// meets the head or the rump the slice steps out to their width, several
/// times its own.
pub const HANG_STEP: f64 = 2.0;

/// How far (in the part's widths at its cut) its outline is carried up
/// into the body, as a thumb's into the hand ([`super::super::thumb::
/// THUMB_ROOT`], the same 0.5): the chain overlaps the body.
pub const HANG_ROOT: f64 = 0.5;

/// Slices per height followed up a hanging part: half a percent of the
/// height, as [`super::landmarks`] follows it down (a geometric
/// resolution).
const CLIMB_SLICES: usize = 200;

/// The closed outlines of the parts hanging below an animal's body, whose
/// lowest slice is at `body_y0`, with the x at their cut: each a run of
/// `front` below its cut, then its root ([`HANG_ROOT`]).
pub fn hanging_outlines(
    front: &[[f64; 2]],
    lm: &QuadLandmarks,
    body_y0: f64,
) -> Vec<Vec<[f64; 2]>> {
    let h = lm.height();
    let leg_top = lm.leg_gaps.iter().map(|p| p[1]).fold(lm.y_min, f64::max);
    let ground = lm.y_min + GROUND_FRACTION * (leg_top - lm.y_min);
    let floor = lm.y_min - GAP_FRACTION * h;
    super::landmarks::parts_below(front, body_y0, floor)
        .into_iter()
        .filter(|(_, low)| *low > ground)
        .filter_map(|(iv, _)| {
            let (y, range) = climb(front, body_y0, iv, h / CLIMB_SLICES as f64, lm.y_max);
            cut_off(front, y, range)
        })
        .collect()
}

/// Follows a part's slice interval `iv` at `y` up by `dy` while it stays
/// its own (see the module docs): the last height and interval.
fn climb(front: &[[f64; 2]], mut y: f64, mut iv: [f64; 2], dy: f64, top: f64) -> (f64, [f64; 2]) {
    while y + dy < top {
        let below = slice(front, y);
        let over: Vec<[f64; 2]> = slice(front, y + dy)
            .into_iter()
            .filter(|o| o[0] <= iv[1] && iv[0] <= o[1])
            .collect();
        let [o] = over[..] else {
            break;
        };
        let joins = below
            .iter()
            .filter(|b| b[0] <= o[1] && o[0] <= b[1])
            .count();
        if joins != 1 || o[1] - o[0] >= HANG_STEP * (iv[1] - iv[0]) {
            break;
        }
        (y, iv) = (y + dy, o);
    }
    (y, iv)
}

/// The outline's crossings of the height `y` (edge index, x) nearest
/// `range`'s two ends: a chord across a part there; None when one edge
/// holds both (or none crosses).
pub(super) fn chord_ends(
    front: &[[f64; 2]],
    y: f64,
    range: [f64; 2],
) -> Option<((usize, f64), (usize, f64))> {
    let n = front.len();
    let crossings: Vec<(usize, f64)> = (0..n)
        .filter_map(|i| {
            let (p, q) = (front[i], front[(i + 1) % n]);
            ((p[1] < y) != (q[1] < y))
                .then(|| (i, p[0] + (y - p[1]) / (q[1] - p[1]) * (q[0] - p[0])))
        })
        .collect();
    let nearest = |x: f64| {
        crossings
            .iter()
            .min_by(|a, b| (a.1 - x).abs().total_cmp(&(b.1 - x).abs()))
            .copied()
    };
    let (a, b) = (nearest(range[0])?, nearest(range[1])?);
    (a.0 != b.0).then_some((a, b))
}

/// The outline's run below `y` from its crossing at `range[1]` to its
/// crossing at `range[0]`, then its root above `y`; None when the run
/// between the two crossings rises above `y` (the part is not cut off by
/// the one chord).
fn cut_off(front: &[[f64; 2]], y: f64, range: [f64; 2]) -> Option<Vec<[f64; 2]>> {
    let n = front.len();
    let (a, b) = chord_ends(front, y, range)?;
    // the two runs between the crossings; the part's stays below y
    let run = |from: usize, to: usize| -> Vec<[f64; 2]> {
        let mut k = (from + 1) % n;
        let mut out = Vec::new();
        loop {
            out.push(front[k]);
            if k == to {
                break out;
            }
            k = (k + 1) % n;
        }
    };
    let (pa, pb) = ([a.1, y], [b.1, y]);
    let (s, mut part, e) = [(pb, run(b.0, a.0), pa), (pa, run(a.0, b.0), pb)]
        .into_iter()
        .find(|(_, r, _)| r.iter().all(|p| p[1] < y))?;
    // closed from its end back to its start, bulging up (+y) into the body
    part.insert(0, s);
    part.push(e);
    let push = HANG_ROOT * (range[1] - range[0]);
    part.extend(super::super::thumb::root_arc(e, s, [0.0, 1.0], push));
    Some(part)
}

/// The parts hanging below the body ([`hanging_outlines`]), each a closed
/// chain at depth `z` (the body's middle; circles: a trunk or tail has no
/// slice of its own in the head-on view) named by where it hangs: `trunk`
/// at the head's end (`lm.facing`, from the legs' middle), `tail` at the
/// other, a second one of a name numbered; a part whose chain cannot be
/// built is left out, as before.
pub fn hanging_parts(
    front: &[[f64; 2]],
    lm: &QuadLandmarks,
    body_y0: f64,
    z: f64,
    taken: &[String],
) -> Vec<PartSpec> {
    let n = lm.leg_gaps.len().max(1) as f64;
    let legs = lm.leg_gaps.iter().map(|p| p[0]).sum::<f64>() / n;
    let mut names: Vec<String> = taken.to_vec();
    let mut out = Vec::new();
    for outline in hanging_outlines(front, lm, body_y0) {
        let xc = outline.iter().map(|p| p[0]).sum::<f64>() / outline.len() as f64;
        let base = if (xc - legs) * lm.facing > 0.0 {
            "trunk"
        } else {
            "tail"
        };
        let name = (1..)
            .map(|k| {
                if k == 1 {
                    base.to_string()
                } else {
                    format!("{base}_{k}")
                }
            })
            .find(|c| !names.contains(c))
            .unwrap_or_default();
        let Ok(mut spec) = upright_chain(&name, &outline, None) else {
            continue;
        };
        for s in &mut spec.sections {
            s.centre[2] += z;
        }
        names.push(name);
        out.push(spec);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::character::doc::Level;

    /// A body 4.2 long and 1.5 deep on two legs, its head's underside at
    /// y = 1.6 over the front leg, a trunk x 4.0 to 4.2 hanging from it to
    /// y = 0.4 (counter-clockwise).
    fn trunk() -> Vec<[f64; 2]> {
        trunk_from(UNDERSIDE)
    }

    /// [`trunk`] with the head's underside at `y`.
    fn trunk_from(y: f64) -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [0.5, 0.0],
            [0.5, 1.0],
            [3.0, 1.0],
            [3.0, 0.0],
            [3.5, 0.0],
            [3.5, y],
            [4.0, y],
            [4.0, 0.4],
            [4.2, 0.4],
            [4.2, 2.5],
            [0.0, 2.5],
        ]
    }

    /// The trunk's extent in the fixture (exact coordinates).
    const TRUNK_X: [f64; 2] = [4.0, 4.2];
    const TRUNK_LOW: f64 = 0.4;
    const UNDERSIDE: f64 = 1.6;
    /// Crossings and the end of the climb are exact up to rounding and one
    /// climbing step (half a percent of the height, 2.5).
    const STEP: f64 = 2.5 / CLIMB_SLICES as f64 + 1e-9;

    #[test]
    fn a_hanging_trunk_is_cut_off_below_the_head_and_rooted_in_it() {
        let front = trunk();
        let mut lm = super::super::landmarks(&front).expect("two legs, the trunk's gap high");
        let regs = super::super::regions(&front, None, &mut lm).expect("regions");
        let outlines = hanging_outlines(&front, &lm, regs[0].y0);
        assert_eq!(outlines.len(), 1, "{outlines:?}");
        let t = &outlines[0];
        let (xr, yr) = (crate::polygon::span(t, 0), crate::polygon::span(t, 1));
        assert!(
            (xr[0] - TRUNK_X[0]).abs() < STEP && (xr[1] - TRUNK_X[1]).abs() < STEP,
            "{xr:?}"
        );
        assert_eq!(yr[0], TRUNK_LOW);
        // cut where it meets the head's underside, rooted half its width
        // up into the head
        let root = HANG_ROOT * (TRUNK_X[1] - TRUNK_X[0]);
        assert!((yr[1] - (UNDERSIDE + root)).abs() < STEP, "{yr:?}");
        // the whole build: a trunk at the head's end (the animal faces +x)
        let d = super::super::derive(&front, None, &[], &[], Level::Intermediate).expect("builds");
        let names: Vec<&str> = d.parts.iter().map(|p| p.name.as_str()).collect();
        assert!(names.contains(&"trunk"), "{names:?}");
    }

    #[test]
    fn a_trunk_leaving_the_head_below_the_middle_is_not_a_leg() {
        // the head's underside at 1.2, under the outline's middle (1.25):
        // the trunk's gap with the front leg reads as a leg gap (3 parts
        // below); it closes above the belly (1.0) by more than a join band,
        // so the trunk is a hanging part and the animal has 2 legs
        const LOW_UNDERSIDE: f64 = 1.2;
        let front = trunk_from(LOW_UNDERSIDE);
        let d = super::super::derive(&front, None, &[], &[], Level::Intermediate)
            .expect("a trunk, not a third leg");
        let mut names: Vec<&str> = d.parts.iter().map(|p| p.name.as_str()).collect();
        names.sort_unstable();
        assert_eq!(names, ["body", "leg_b", "leg_f", "trunk"]);
        // leaving the body level with the belly it cannot be cut off
        // above the legs: refused, named
        const AT_BELLY: f64 = 1.02;
        let e = super::super::landmarks(&trunk_from(AT_BELLY))
            .expect_err("a part hanging at the belly")
            .to_string();
        assert!(e.contains("the part between x = 4.0000 and 4.2000"), "{e}");
    }

    #[test]
    fn legs_reaching_the_ground_hang_nothing() {
        let mut front = trunk();
        // the trunk down to the ground: it is a third leg (refused), so
        // take it away instead: the head's underside runs to its front
        front.splice(7..10, [[4.2, 1.6]]);
        let mut lm = super::super::landmarks(&front).expect("two legs");
        let regs = super::super::regions(&front, None, &mut lm).expect("regions");
        assert!(hanging_outlines(&front, &lm, regs[0].y0).is_empty());
    }
}
