//! Arms traced along their own axis (issue 28 item 3: T-pose to 75 degrees
//! below the horizontal), instead of horizontal slices, which a horizontal
//! arm does not have.
//!
//! From the armpit `A` the outline is walked away from the torso (counter-
//! clockwise for the right arm, clockwise for the left) until it reaches
//! the neck's side. The hand's **tip** is the walk's point farthest from
//! the arm's root, the line from `A` to the walk's end (from `A` alone, an
//! armpit below the crotch was farther from the shoulder's top than from
//! the hand); the distance to `A` falls back from the tip to the
//! **shoulder point** `S` (its smallest value after the tip): `AS` is the shortest cut across
//! the arm from the armpit, the line where the arm meets the shoulder. The
//! walk from `A` to the tip is the arm's inner side, the walk back from the
//! tip to `S` its outer side; both are resampled by arc length and paired
//! by equal fractions of their lengths. A pair's midpoint is a point of the
//! arm's central curve, half its distance the arm's half width there.
//!
//! Fingers drawn apart would pair finger with finger (the arm then
//! follows each finger: wiggles and folds), so the walk's notches are
//! closed first into a mitten ([`HAND_NOTCH_MOUTH`]).
//!
//! Nothing is assumed about the arm's direction: a T-pose arm (horizontal),
//! an A-pose arm and an arm hanging 75 degrees below the horizontal are
//! traced the same way. The tracer fails (in drawing terms) when the arm's
//! tip is not farther from the armpit than the shoulder cut is long (no arm
//! reaches out of the body there).

use super::arm_root::{pair_sides, resample_open, rooted_at_corner, run_to};
use super::poly::dist;
use super::shoulder_tilt::{section_shape, turned_to_corner, SHOULDER_TILT_SECTIONS};
use super::SketchError;

/// Samples along a traced arm (pairs of its two sides).
pub const TRACE_SAMPLES: usize = 240;

/// An arm traced from its armpit.
#[derive(Clone, Debug, PartialEq)]
pub struct TracedArm {
    pub armpit: [f64; 2],
    /// The shoulder end of the cut from the armpit.
    pub shoulder: [f64; 2],
    /// The hand's farthest point from the arm's root (the line from the
    /// armpit to where the walk reaches the neck's side).
    pub tip: [f64; 2],
    /// The shoulder's outer corner ([`super::shoulder_tilt::shoulder_corner`]), where the arm's
    /// first sections are turned to; None: no corner to reach.
    pub corner: Option<[f64; 2]>,
    /// Central curve points and half widths, from the cut to the tip.
    pub centre: Vec<[f64; 2]>,
    pub half_width: Vec<f64>,
    /// Unit direction of each pair's chord (inner side to outer side).
    pub chord: Vec<[f64; 2]>,
    /// A thumb held away from the hand, cut off the walk: its closed
    /// outline reaching into the hand ([`super::thumb`]).
    pub thumb: Option<Vec<[f64; 2]>>,
    /// The same arm traced from the chord between the armpit and the
    /// shoulder's corner (its `shoulder`): the outer side runs on to the
    /// corner. None: no corner.
    pub from_corner: Option<Box<TracedArm>>,
}

/// Traces the arm at `armpit` on the counter-clockwise outline `front`;
/// `side`: -1 for the left arm (negative x), +1 for the right; `neck_x`:
/// the x of the neck's side on that side (the walk stops there).
pub fn trace_arm(
    front: &[[f64; 2]],
    armpit: [f64; 2],
    side: f64,
    neck_x: f64,
    name: &str,
) -> Result<TracedArm, SketchError> {
    let n = front.len();
    let ia = (0..n)
        .min_by(|&i, &j| dist(front[i], armpit).total_cmp(&dist(front[j], armpit)))
        .ok_or_else(|| {
            SketchError::Segmentation(format!("{name}: empty outline: draw a closed outline"))
        })?;
    let step = |k: usize| -> usize {
        if side > 0.0 {
            (ia + k) % n
        } else {
            (ia + n - k % n) % n
        }
    };
    // the walk stops where it comes back to the neck's side from outside
    // it: an armpit within the neck's x (a neck as wide as the chest) is
    // left first along the arm's underside
    let mut walk = vec![armpit];
    let mut been_out = side * (armpit[0] - neck_x) > 0.0;
    for k in 1..n {
        let p = front[step(k)];
        let out = side * (p[0] - neck_x) > 0.0;
        if !out && been_out {
            break;
        }
        been_out |= out;
        walk.push(p);
    }
    if !been_out {
        walk.truncate(1);
    }
    let d: Vec<f64> = walk.iter().map(|p| dist(*p, armpit)).collect();
    let it = hand(&walk);
    let is = (it..walk.len())
        .min_by(|&i, &j| d[i].total_cmp(&d[j]))
        .unwrap_or(it);
    let (reach, cut) = (d[it], d[is]);
    if it == 0 || is <= it || reach <= cut {
        return Err(SketchError::Segmentation(format!(
            "{name}: no arm reaches out from the armpit at ({:.4}, {:.4}) (the outline beyond it comes no farther than {:.4} from it): \
             draw the arm away from the body, with a gap between the arm and the torso below the armpit",
            armpit[0], armpit[1], reach
        )));
    }
    let corner =
        super::shoulder_tilt::shoulder_corner(&walk[is..], 0.5 * (walk[is][0] + neck_x), side);
    let root_run = corner.map(|c| run_to(&walk[is..], c));
    // fingers: the notches between them are closed (a mitten), so that
    // the two sides pair hand to hand, not finger to finger
    // the walk follows the outline forward for the right arm (side > 0),
    // backward for the left; the inside is left of a counter-clockwise one
    let ccw = crate::polygon::signed_area(front) > 0.0;
    let inside_left = ccw == (side > 0.0);
    let walk = bridge_notches(&walk[..=is], inside_left, HAND_NOTCH_MOUTH * cut);
    // a thumb held away from the hand: cut off, built on its own
    let tip = farthest(&walk, armpit);
    let (walk, thumb) = match super::thumb::split_thumb(&walk, inside_left, tip, cut) {
        Some((rest, t)) => (rest, Some(t)),
        None => (walk, None),
    };
    let it = farthest(&walk, armpit);
    let is = walk.len() - 1;
    let inner = resample_open(&walk[..=it], TRACE_SAMPLES);
    let mut outer_walk: Vec<[f64; 2]> = walk[it..=is].to_vec();
    outer_walk.reverse();
    let outer = resample_open(&outer_walk, TRACE_SAMPLES);
    let (centre, half_width, chord) = pair_sides(&inner, &outer);
    let mut arm = TracedArm {
        armpit,
        shoulder: walk[is],
        tip: walk[it],
        corner,
        centre,
        half_width,
        chord,
        thumb,
        from_corner: None,
    };
    arm.from_corner = root_run.and_then(|run| rooted(&arm, &run));
    Ok(arm)
}

/// `arm` traced on up its root `run` (the outline from its shoulder
/// point to its corner, [`run_to`]) to the corner
/// ([`rooted_at_corner`]): its `shoulder` the corner, no corner or thumb
/// of its own. None: no corner, or no run beyond the cut.
fn rooted(arm: &TracedArm, run: &[[f64; 2]]) -> Option<Box<TracedArm>> {
    let c = arm.corner?;
    if run.len() < 2 || arm.centre.is_empty() {
        return None;
    }
    let (centre, half_width, chord) =
        rooted_at_corner(run, (&arm.centre, &arm.half_width, &arm.chord));
    Some(Box::new(TracedArm {
        armpit: arm.armpit,
        shoulder: c,
        tip: arm.tip,
        corner: None,
        centre,
        half_width,
        chord,
        thumb: None,
        from_corner: None,
    }))
}

/// The index of the hand's tip on an arm's walk from its armpit (its
/// first point): the point farthest from the arm's root, the line from
/// the armpit to where the walk comes back to the neck (its last point).
/// An armpit below the crotch, a big-headed figure's, is farther from the
/// shoulder's top than from the hand: the farthest from the armpit alone
/// was the shoulder (seed 4242's random_22).
fn hand(walk: &[[f64; 2]]) -> usize {
    let (Some(&a), Some(&end)) = (walk.first(), walk.last()) else {
        return 0;
    };
    let root: Vec<f64> = walk
        .iter()
        .map(|p| crate::polygon::seg_dist(*p, a, end))
        .collect();
    (0..walk.len())
        .max_by(|&i, &j| root[i].total_cmp(&root[j]))
        .unwrap_or(0)
}

/// The index of the walk's point farthest from `armpit` (the hand's tip).
fn farthest(walk: &[[f64; 2]], armpit: [f64; 2]) -> usize {
    let d: Vec<f64> = walk.iter().map(|p| dist(*p, armpit)).collect();
    (0..walk.len())
        .max_by(|&i, &j| d[i].total_cmp(&d[j]))
        .unwrap_or(0)
}

/// A notch of a traced arm's outline (between two fingers, or a thumb
/// and the hand) is closed when its mouth is narrower than this fraction
/// of the shoulder cut (the arm's width where it leaves the body): a
/// finger's gap is a small part of it, the arm across its wrist (about
/// half of it) is material, which no bridge may cross anyway.
pub const HAND_NOTCH_MOUTH: f64 = 0.5;

/// The open polyline `walk` (part of a closed outline whose inside is on
/// the walk's left when `inside_left`) with its notches closed: from each
/// point, a bridge to the farthest later point that is nearer than
/// `mouth`, where the walk between them is more than twice as long as the
/// bridge (a notch, not a straight side) and the bridge lies outside the
/// outline: the loop of the walk and the bridge turns against the inside
/// (it encloses a gap, not a finger or the wrist; its signed area from
/// prefix sums, O(1) per candidate) and the bridge crosses no edge of the
/// walk between its ends.
fn bridge_notches(walk: &[[f64; 2]], inside_left: bool, mouth: f64) -> Vec<[f64; 2]> {
    let m = walk.len();
    let sums = super::walk::WalkSums::new(walk, inside_left);
    let bridge = |i: usize, j: usize| -> bool {
        let c = dist(walk[i], walk[j]);
        c < mouth && sums.run(i, j) > 2.0 * c && sums.material_area(i, j) < 0.0 && sums.clear(i, j)
    };
    let mut out = vec![walk[0]];
    let mut i = 0;
    while i + 1 < m {
        let next = (i + 2..m).rev().find(|&j| bridge(i, j)).unwrap_or(i + 1);
        out.push(walk[next]);
        i = next;
    }
    out
}

/// The arm's part: key sections along the traced central curve from
/// `start` (arc length from the cut's midpoint, the join band left to the
/// shoulder transition) to the tip, placed where the width and the curve
/// change ([`super::section_place::place`]), each a circle perpendicular to the
/// curve (arms are hidden in the side view) at depth `z` but the first
/// [`SHOULDER_TILT_SECTIONS`], turned toward the shoulder's corner when
/// the drawing has one ([`turned_to_corner`]: ellipses of the arm's own
/// depth); the last one collapses to the tip. The curve's direction is taken over the arm's
/// half width ([`super::uncross::tangent`]), and neighbouring sections
/// that would still cut through each other are turned apart
/// ([`super::uncross::sections`]); the chain's parameter runs along the
/// sections' rims ([`super::uncross::rim_arc_lengths`]).
pub fn part_from_trace(
    front: &[[f64; 2]],
    name: &str,
    t: &TracedArm,
    start: f64,
    z: f64,
) -> Result<crate::character::doc::PartSpec, SketchError> {
    use super::section_place::{place, Sample, SECTIONS_PER_PART};
    use crate::character::doc::{EndCurvature, PartSpec, SectionSpec, SurfaceSpec};
    let mut s_len = vec![0.0; t.centre.len()];
    for i in 1..t.centre.len() {
        s_len[i] = s_len[i - 1] + dist(t.centre[i - 1], t.centre[i]);
    }
    let first = s_len.iter().position(|&s| s >= start).unwrap_or(0);
    let idx_all: Vec<usize> = (first..t.centre.len()).collect();
    if idx_all.len() < SECTIONS_PER_PART + 2 {
        return Err(SketchError::Segmentation(format!(
            "{name}: the arm is too short beyond its shoulder ({:.4} along its axis): draw it longer",
            s_len.last().copied().unwrap_or(0.0)
        )));
    }
    let samples: Vec<Sample> = idx_all
        .iter()
        .map(|&i| Sample {
            y: t.centre[i][1],
            c: t.centre[i][0],
            w: t.half_width[i],
        })
        .collect();
    let chosen = place(&samples, None, SECTIONS_PER_PART);
    let mut sections: Vec<SectionSpec> = Vec::with_capacity(chosen.len());
    let mut u = 0.0;
    for (j, &k) in chosen.iter().enumerate() {
        let i = idx_all[k];
        let tg = super::uncross::tangent(&t.centre, i, t.half_width[i]);
        let e1 = [tg[1], -tg[0], 0.0];
        let cos = (t.chord[i][0] * e1[0] + t.chord[i][1] * e1[1]).abs();
        let last = j + 1 == chosen.len();
        let mut centre = if last {
            [t.tip[0], t.tip[1], z]
        } else {
            [t.centre[i][0], t.centre[i][1], z]
        };
        let mut e1 = e1;
        // the last one collapses to the tip (a half width of 0)
        let w_i = if last { 0.0 } else { t.half_width[i] };
        let mut r = across(front, t.centre[i], [e1[0], e1[1]], w_i, cos);
        // a tilted section's depth stays the arm's own (hidden in the side
        // view: a circle of the untilted radius), however long its tilt
        let mut depth = None;
        if j < SHOULDER_TILT_SECTIONS && !last {
            if let Some((c, dir, half)) = turned_to_corner(
                front,
                [t.centre[i], t.chord[i]],
                t.half_width[i],
                t.corner,
                j,
            ) {
                centre = [c[0], c[1], z];
                // keep the ring's orientation: e1 on the side it was
                e1 = if dir[0] * e1[0] + dir[1] * e1[1] < 0.0 {
                    [-dir[0], -dir[1], 0.0]
                } else {
                    [dir[0], dir[1], 0.0]
                };
                depth = Some(r.min(half));
                r = half;
            }
        }
        if let Some(p) = sections.last() {
            u += crate::mesh::dist(p.centre, centre);
        }
        sections.push(SectionSpec {
            u,
            centre,
            e1,
            e2: [0.0, 0.0, 1.0],
            shape: section_shape(r, depth),
        });
    }
    // sections that cut through each other turned apart; the radius of a
    // turned one is its chord's projection, as above
    let at: Vec<usize> = chosen.iter().map(|&k| idx_all[k]).collect();
    super::uncross::sections(&mut sections, SHOULDER_TILT_SECTIONS, |j, e1| {
        let i = at[j];
        t.half_width[i] * (t.chord[i][0] * e1[0] + t.chord[i][1] * e1[1]).abs()
    });
    super::uncross::rim_arc_lengths(&mut sections);
    Ok(PartSpec {
        name: name.into(),
        surface: SurfaceSpec::Pde6C2 {
            a: 0.0,
            open_ends: EndCurvature::Guarded,
        },
        sections,
        closed_start: false,
        closed_end: true,
    })
}

/// A traced arm section's radius at the pair's middle `c`, its axis `e1`
/// (unit, perpendicular to the arm's curve), the pair's half width `w`
/// and `cos`, the cosine between the pair's chord and `e1`: the
/// outline's half width along `e1` through `c` (the mean of the two
/// rays' runs to it), kept between the chord's projection `w cos` and
/// its half length `w`. The projection alone is the width of a tube
/// whose sides are parallel; where one side is longer (a thumb on the
/// inner side of a real hand) the pairs by equal fractions turn oblique
/// and it pinched the wrist: MakeHuman's young male's, 0.016-0.020 where
/// the drawn wrist is 0.028-0.032 across its own axis.
fn across(front: &[[f64; 2]], c: [f64; 2], e1: [f64; 2], w: f64, cos: f64) -> f64 {
    let lo = w * cos;
    match (
        super::poly::ray_exit(front, c, e1, 0.0),
        super::poly::ray_exit(front, c, [-e1[0], -e1[1]], 0.0),
    ) {
        (Some(a), Some(b)) => (0.5 * (a + b)).clamp(lo, w.max(lo)),
        _ => lo,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hand of three fingers (tips at x = 6, 5.5, 6, gaps 0.4 wide and
    /// 1.5-2 deep): its notches close into a mitten; the bottoms of the
    /// gaps are gone, the fingertips stay. A strip's two long sides, 0.4
    /// apart across material, are never bridged.
    #[test]
    fn notches_between_fingers_close_and_material_is_never_bridged() {
        let hand = [
            [0.0, 0.0],
            [6.0, 0.0],
            [6.0, 0.4],
            [4.0, 0.4],
            [4.0, 0.8],
            [5.5, 0.8],
            [5.5, 1.2],
            [4.0, 1.2],
            [4.0, 1.6],
            [6.0, 1.6],
            [6.0, 2.0],
            [0.0, 2.0],
        ];
        // the x of the gaps' bottoms between the fingers
        let gap_bottom = 5.5;
        let mitten = bridge_notches(&hand, true, 1.0);
        assert!(mitten.len() < hand.len(), "{mitten:?}");
        assert!(
            mitten[1..mitten.len() - 1]
                .iter()
                .all(|p| p[0] >= gap_bottom),
            "a gap's bottom is left: {mitten:?}"
        );
        assert_eq!(
            mitten,
            [
                [0.0, 0.0],
                [6.0, 0.0],
                [6.0, 0.4],
                [5.5, 1.2],
                [6.0, 1.6],
                [6.0, 2.0],
                [0.0, 2.0]
            ]
        );
        // the same hand walked the other way round (a left arm's walk):
        // the same bridges, reversed
        let back: Vec<[f64; 2]> = hand.iter().rev().copied().collect();
        let mut mitten_back = bridge_notches(&back, false, 1.0);
        mitten_back.reverse();
        assert_eq!(mitten_back.len(), mitten.len(), "{mitten_back:?}");
        assert!(mitten_back[1..mitten_back.len() - 1]
            .iter()
            .all(|p| p[0] >= gap_bottom));
        // a mouth narrower than the gaps closes nothing
        assert_eq!(bridge_notches(&hand, true, 0.3), hand.to_vec());
        let strip = [[0.0, 0.0], [6.0, 0.0], [6.0, 0.4], [0.0, 0.4]];
        assert_eq!(bridge_notches(&strip, true, 1.0), strip.to_vec());
    }

    /// A tube 2 across (a rectangle along x): a pair whose chord is
    /// oblique (half length 1.5, cosine 0.5 with the section's axis)
    /// projects to 0.75, the tube's half width along the axis is 1; a
    /// pair whose chord is longer than the outline is across (half length
    /// 0.8) keeps its half length; outside the outline (no ray crosses
    /// on one side), the projection.
    #[test]
    fn a_section_is_as_wide_as_the_outline_across_its_axis() {
        let tube = [[-10.0, -1.0], [10.0, -1.0], [10.0, 1.0], [-10.0, 1.0]];
        let tol = crate::check::tol::ROUNDING;
        let r = across(&tube, [0.0, 0.0], [0.0, 1.0], 1.5, 0.5);
        assert!((r - 1.0).abs() < tol, "{r}");
        let r = across(&tube, [0.0, 0.0], [0.0, 1.0], 0.8, 1.0);
        assert!((r - 0.8).abs() < tol, "{r}");
        let r = across(&tube, [0.0, 5.0], [0.0, 1.0], 1.5, 0.5);
        assert!((r - 0.75).abs() < tol, "{r}");
    }
}
