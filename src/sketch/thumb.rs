//! A thumb sticking out of a traced hand (a real body's front silhouette,
//! issue 28's held-out real bodies), modeled as paper 000 composes a
//! removed part (sec 4.1: hair, a tail, ears "removed" from the primary
//! profile and modeled from their own profiles): cut off the arm's walk
//! at its base, built from its own outline as a separate closed chain
//! ([`super::removed::upright_chain`]) that reaches into the hand.
//!
//! The notches between fingers are closed into a mitten first
//! ([`super::limb`]); a thumb held away from the hand leaves a notch too
//! wide to close, and the arm's tube, whose two sides are paired by equal
//! fractions of their lengths, averaged it away: the silhouette missed the
//! thumb's tip by 1.6-1.9 % of the height on four of nineteen MakeHuman
//! bodies (docs/drawing-corpus.md, thirty-first measurement).
//!
//! A **thumb** is a run of the walk between two points `i < j` whose
//! bridge is short and lies inside the outline (the run and the bridge
//! enclose material: a protrusion, the opposite of a notch), whose run is
//! more than [`THUMB_RATIO`] times as long as the bridge (longer than
//! wide: a bump of the forearm is not), narrower at its base than
//! [`THUMB_BASE`] of the arm's shoulder cut, away from the walk's ends
//! and not holding the hand's tip, and reaching out once
//! ([`THUMB_SWINGS`]: a serrated edge is not one thumb). Of those, the one with the longest run
//! (its base then the narrowest point of its root).

use super::poly::dist;

/// A thumb's base is at most this fraction of the arm's shoulder cut (the
/// arm's width where it leaves the body): a thumb is narrower than the
/// wrist, which the hand notches' mouth ([`super::limb::HAND_NOTCH_MOUTH`],
/// the same 0.5) already takes for the width of material.
pub const THUMB_BASE: f64 = 0.5;

/// A thumb's run along the outline is more than this many times its base:
/// the notch rule's factor ([`super::limb`]: a notch's walk is more than
/// twice its mouth) turned around; a half disc's is pi / 2.
pub const THUMB_RATIO: f64 = 2.0;

/// A thumb's distance from its base rises once to its tip and falls once:
/// over the run its changes add up to twice its depth (exactly 2.00 on
/// every thumb of the thirty-nine MakeHuman bodies). A serrated edge (fur,
/// a frilled sleeve: teeth steeper than 60 degrees are each longer than
/// twice their base) rises and falls once per tooth, at least four times
/// its depth for two teeth; the rule takes less than this, halfway, so a
/// hand-drawn thumb may wiggle by half its depth and a stretch of teeth is
/// not cut off as one thumb.
pub const THUMB_SWINGS: f64 = 3.0;

/// How far (in base widths) the thumb's own outline is carried into the
/// hand beyond its base, so the separate chain overlaps the hand's tube
/// instead of ending on its silhouette with a rounded gap.
pub const THUMB_ROOT: f64 = 0.5;

/// Points of the thumb's root beyond its base (a half ellipse), ends
/// excluded: a geometric resolution, the root's chord within 2 % of its
/// width.
const ROOT_POINTS: usize = 16;

/// The walk with a thumb's run replaced by its base, and the thumb's closed
/// outline (its run, then its base carried into the hand by
/// [`THUMB_ROOT`] as a half ellipse); `None` when the walk has no thumb. `inside_left`: the
/// outline's material lies left of the walk; `tip`: the index of the
/// hand's tip on the walk; `cut`: the arm's shoulder cut.
#[allow(clippy::type_complexity)]
pub fn split_thumb(
    walk: &[[f64; 2]],
    inside_left: bool,
    tip: usize,
    cut: f64,
) -> Option<(Vec<[f64; 2]>, Vec<[f64; 2]>)> {
    let m = walk.len();
    if m < 8 {
        return None;
    }
    let sums = super::walk::WalkSums::new(walk, inside_left);
    let base_max = THUMB_BASE * cut;
    let mut best: Option<(f64, usize, usize)> = None;
    for i in 1..m - 2 {
        for j in i + 2..m - 1 {
            if (i..=j).contains(&tip) {
                break;
            }
            let c = dist(walk[i], walk[j]);
            let run = sums.run(i, j);
            if !(c > 0.0 && c < base_max && run > THUMB_RATIO * c) {
                continue;
            }
            if best.is_some_and(|b| b.0 >= run) {
                continue;
            }
            if sums.material_area(i, j) > 0.0 && sums.clear(i, j) && one_peak(&walk[i..=j]) {
                best = Some((run, i, j));
            }
        }
    }
    let (_, i, j) = best?;
    let mut arm = walk[..=i].to_vec();
    arm.extend_from_slice(&walk[j..]);
    // the base carried into the hand: along its normal toward the material
    let (a, b) = (walk[i], walk[j]);
    let c = dist(a, b);
    let d = [(b[0] - a[0]) / c, (b[1] - a[1]) / c];
    // without the run the walk goes from a to b, its material (the hand)
    // on its left when `inside_left`
    let n = if inside_left {
        [-d[1], d[0]]
    } else {
        [d[1], -d[0]]
    };
    // a half ellipse beyond the base, reaching THUMB_ROOT base widths into
    // the hand: the chain closes round there (a flat root closed to a
    // point creased its rim)
    let mut thumb = walk[i..=j].to_vec();
    thumb.extend(root_arc(b, a, n, THUMB_ROOT * c));
    Some((arm, thumb))
}

/// The root of a part cut off an outline at the chord from `from` to `to`
/// (the part's outline runs from `to` to `from`): a half ellipse from
/// `from` back to `to` bulging `push` along the unit `into` (into the
/// parent's material), ends excluded, so the part's separate chain
/// overlaps its parent instead of ending on the cut with a rounded gap.
pub(super) fn root_arc(from: [f64; 2], to: [f64; 2], into: [f64; 2], push: f64) -> Vec<[f64; 2]> {
    let mid = [0.5 * (from[0] + to[0]), 0.5 * (from[1] + to[1])];
    let half = [0.5 * (from[0] - to[0]), 0.5 * (from[1] - to[1])];
    (1..ROOT_POINTS)
        .map(|k| {
            let phi = std::f64::consts::PI * k as f64 / ROOT_POINTS as f64;
            let (c, s) = (phi.cos(), push * phi.sin());
            [
                mid[0] + c * half[0] + s * into[0],
                mid[1] + c * half[1] + s * into[1],
            ]
        })
        .collect()
}

/// Whether the run's distance from its base (the chord between its ends)
/// rises and falls once: its total change under [`THUMB_SWINGS`] times its
/// largest value.
fn one_peak(run: &[[f64; 2]]) -> bool {
    let (a, b) = (run[0], run[run.len() - 1]);
    let c = dist(a, b);
    let depth =
        |p: &[f64; 2]| ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])).abs() / c;
    let (mut swing, mut deepest, mut last) = (0.0, 0.0f64, 0.0);
    for p in run {
        let d = depth(p);
        swing += (d - last).abs();
        deepest = deepest.max(d);
        last = d;
    }
    swing < THUMB_SWINGS * deepest
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fixture thumb's length and base width (exact coordinates).
    const LEN: f64 = 2.0;
    const BASE: f64 = 0.6;
    /// Coordinates built from the fixture's exact values, compared exactly
    /// up to rounding.
    const EXACT: f64 = 1e-12;

    /// The inner side of a right arm walked down from an armpit at the
    /// origin (the material, the arm, on the walk's left), a thumb sticking
    /// out of it near the hand, the hand's tip, and back up the outer side.
    fn arm_with_thumb(thumb_len: f64) -> (Vec<[f64; 2]>, usize) {
        let mut w: Vec<[f64; 2]> = (0..=20).map(|k| [0.0, -0.5 * k as f64]).collect();
        // the thumb: out to -x from y = -10, its base BASE wide
        w.push([-thumb_len, -10.1]);
        w.push([-thumb_len, -10.5]);
        w.extend((0..=8).map(|k| [0.0, -10.0 - BASE - 0.5 * k as f64]));
        let tip = w.len();
        w.push([1.0, -15.0]);
        w.extend((0..=30).map(|k| [2.0, -15.0 + 0.5 * k as f64]));
        (w, tip)
    }

    #[test]
    fn a_thumb_is_cut_off_at_its_base_and_carried_into_the_hand() {
        let (w, tip) = arm_with_thumb(LEN);
        // the arm walks down (-y) with the material on its left (+x)
        let (arm, thumb) = split_thumb(&w, true, tip, 2.0).expect("a thumb");
        assert!(
            arm.iter().all(|p| p[0] >= 0.0),
            "the thumb left the arm: {arm:?}"
        );
        assert_eq!(
            arm.len() + 2,
            w.len(),
            "only the thumb's two outer points go"
        );
        let (lo, hi) = thumb
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p[0]), b.max(p[0])));
        assert_eq!(lo, -LEN, "the thumb's tip is kept: {thumb:?}");
        // its root reaches THUMB_ROOT base widths into the hand (+x)
        assert!(
            (hi - THUMB_ROOT * BASE).abs() < EXACT,
            "root at {hi}: {thumb:?}"
        );
    }

    #[test]
    fn a_bump_a_short_stub_or_a_wide_thumb_is_not_a_thumb() {
        // a stub not longer than its base
        let (w, tip) = arm_with_thumb(0.3);
        assert!(split_thumb(&w, true, tip, 2.0).is_none());
        // a base wider than half the shoulder cut
        let (w, tip) = arm_with_thumb(LEN);
        assert!(split_thumb(&w, true, tip, 1.0).is_none());
        // a notch (the run turns against the material) is not a thumb
        let (w, tip) = arm_with_thumb(LEN);
        assert!(split_thumb(&w, false, tip, 2.0).is_none());
    }

    #[test]
    fn a_serrated_edge_is_not_cut_off_as_one_thumb() {
        // the arm of the fixture, its inner side serrated near the hand:
        // TEETH teeth 0.2 wide and 0.5 high (each 5 times longer than its
        // base), the stretch 0.6 wide, under half the shoulder cut
        const TEETH: usize = 3;
        let (w, h) = (0.2, 0.5);
        let mut walk: Vec<[f64; 2]> = (0..=20).map(|k| [0.0, -0.5 * k as f64]).collect();
        for t in 0..TEETH {
            let y = -10.0 - w * t as f64;
            walk.push([-h, y - 0.5 * w]);
            walk.push([0.0, y - w]);
        }
        walk.extend((1..=8).map(|k| [0.0, -10.0 - w * TEETH as f64 - 0.5 * k as f64]));
        let tip = walk.len();
        walk.push([1.0, -15.0]);
        walk.extend((0..=30).map(|k| [2.0, -15.0 + 0.5 * k as f64]));
        let tips = |pts: &[[f64; 2]]| pts.iter().filter(|p| p[0] == -h).count();
        // at most one tooth may be read as a thumb (a lone spike is one)
        if let Some((arm, thumb)) = split_thumb(&walk, true, tip, 2.0) {
            assert!(tips(&thumb) <= 1, "teeth cut off as one thumb: {thumb:?}");
            assert_eq!(tips(&arm), TEETH - tips(&thumb));
        }
    }
}
