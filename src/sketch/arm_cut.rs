//! Where an arm's shell is cut off the body ([`super::humanoid_shells`]):
//! the cuts ([`ArmCut`]), the body's end of each ([`cut_tops`]), and the
//! upright cut's ([`upright_top`]).
//!
//! The shortest cut from the armpit ends on the arm's top: the body keeps
//! a wedge of the arm's root out to there. Where the two arms' wedges sit
//! at different heights, the body chain's sections, centred on its
//! middle, stand out of the drawing on one side (seed 3131's random_3,
//! 2.5 % of the height). The upright cut follows the body's side up under
//! the arm's root instead.

use super::limb::TracedArm;
use super::poly::dist;
use super::quadruped::root_cut::nearest_vertex;

/// A traced arm with its part's name and depth (the z its sections sit at).
pub struct ArmTrace {
    pub name: String,
    pub trace: TracedArm,
    pub z: f64,
}

/// Where an arm is cut off the body for its shell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArmCut {
    /// At the chord from the armpit to the shoulder point (the shortest
    /// cut, [`super::limb::trace_arm`]); the arm's dome reaches back past
    /// the chord's middle.
    Shoulder,
    /// At the chord from the armpit to the shoulder's corner
    /// ([`TracedArm::corner`]), the arm traced from the shortest cut as
    /// for `Shoulder`, its dome reaching back past this chord's middle.
    Corner,
    /// At the same chord, the arm traced on up its root to the corner
    /// ([`TracedArm::from_corner`]) and closed there: an arm joining the
    /// body below the crotch lies along the body from its armpit up to
    /// its shoulder, a run the shortest cut leaves to the body.
    Rooted,
    /// From the armpit up the body's side under the arm's root: to the
    /// corner where the arm's top meets the body's side, or where none is
    /// drawn, to where the line straight up from the armpit meets the
    /// shoulder ([`upright_top`]); the arm traced as for `Shoulder`, its
    /// dome reaching back past this cut's middle.
    Upright,
}

impl ArmCut {
    /// Whether the cut is made without the shoulder's corner.
    pub(super) fn needs_no_corner(self) -> bool {
        matches!(self, ArmCut::Shoulder | ArmCut::Upright)
    }

    /// The cuts in the order the build tries them.
    pub const ALL: [ArmCut; 4] = [
        ArmCut::Shoulder,
        ArmCut::Corner,
        ArmCut::Rooted,
        ArmCut::Upright,
    ];
}

/// The body's end of each arm's cut (`cut`): its shoulder point, its
/// shoulder's corner (the shoulder point where it has none), or
/// ([`upright_top`]) where the line straight up from the armpit meets the
/// outline beyond the shoulder point. None when an arm's armpit, shoulder
/// point and hand are not three distinct vertices of `front`.
pub(super) fn cut_tops(
    front: &[[f64; 2]],
    arms: &[ArmTrace],
    cut: ArmCut,
) -> Option<Vec<[f64; 2]>> {
    arms.iter()
        .map(|a| {
            let t = &a.trace;
            match cut {
                ArmCut::Shoulder => Some(t.shoulder),
                ArmCut::Corner | ArmCut::Rooted => Some(t.corner.unwrap_or(t.shoulder)),
                ArmCut::Upright => upright_top(front, t),
            }
        })
        .collect()
}

/// The body's end of arm `t`'s upright cut: on the outline `front` walked
/// from the shoulder point away from the hand to where it first crosses
/// the line straight up from the armpit (or to the outline's top), the
/// point farthest from the chord between these two ends on the body's
/// side of it: the corner where the arm's top meets the body's side (a
/// T-pose's square shoulder, a notch above a lowered arm). Where no point
/// lies on that side (a hanging arm's rounded shoulder), the crossing: the
/// body's side continued up under the arm's root.
pub(super) fn upright_top(front: &[[f64; 2]], t: &TracedArm) -> Option<[f64; 2]> {
    let n = front.len();
    let (_, s, forward) = arm_run(front, t.armpit, t.shoulder, t.tip)?;
    let step = if forward { 1 } else { n - 1 };
    let top = (0..n).max_by(|&i, &j| front[i][1].total_cmp(&front[j][1]))?;
    let x = t.armpit[0];
    let mut walk = vec![front[s]];
    let mut i = s;
    while i != top {
        let j = (i + step) % n;
        let (a, b) = (front[i], front[j]);
        if (a[0] - x) * (b[0] - x) <= 0.0 && a[0] != b[0] {
            let u = (x - a[0]) / (b[0] - a[0]);
            walk.push([x, a[1] + u * (b[1] - a[1])]);
            break;
        }
        walk.push(b);
        i = j;
    }
    let (first, last) = (walk[0], *walk.last()?);
    let l = dist(first, last);
    if l <= 0.0 {
        return Some(last);
    }
    // the chord's normal toward the body's middle (x = 0, the torso's axis)
    let mut nrm = [-(last[1] - first[1]) / l, (last[0] - first[0]) / l];
    if nrm[0] * t.armpit[0] > 0.0 {
        nrm = [-nrm[0], -nrm[1]];
    }
    let inward = |q: &[f64; 2]| (q[0] - first[0]) * nrm[0] + (q[1] - first[1]) * nrm[1];
    let corner = walk
        .iter()
        .copied()
        .max_by(|u, v| inward(u).total_cmp(&inward(v)))?;
    Some(if inward(&corner) > 0.0 { corner } else { last })
}

/// The vertices of `front` nearest an arm's armpit and the body's end
/// `top` of its cut, and whether its hand (`tip`) lies on the run walked
/// forward from the one to the other (else on the other run). None when
/// the three are not three distinct vertices.
pub(super) fn arm_run(
    front: &[[f64; 2]],
    armpit: [f64; 2],
    top: [f64; 2],
    tip: [f64; 2],
) -> Option<(usize, usize, bool)> {
    let n = front.len();
    let (p, s, h) = (
        nearest_vertex(front, armpit),
        nearest_vertex(front, top),
        nearest_vertex(front, tip),
    );
    if p == s || p == h || s == h {
        return None;
    }
    let ahead = |k: usize| (k + n - p) % n;
    Some((p, s, ahead(h) < ahead(s)))
}

/// `front` with `q` inserted on its nearest edge.
pub(super) fn with_vertex(front: &[[f64; 2]], q: [f64; 2]) -> Vec<[f64; 2]> {
    let n = front.len();
    let seg = |i: usize| crate::polygon::seg_dist(q, front[i], front[(i + 1) % n]);
    let Some(i) = (0..n).min_by(|&i, &j| seg(i).total_cmp(&seg(j))) else {
        return front.to_vec();
    };
    let mut out = front.to_vec();
    if out[i] != q && out[(i + 1) % n] != q {
        out.insert(i + 1, q);
    }
    out
}

/// Test drawings shared with [`super::humanoid_shells`]'s tests.
#[cfg(test)]
pub(super) mod fixtures {
    use super::*;

    /// A traced arm with only its three points.
    pub fn arm(armpit: [f64; 2], shoulder: [f64; 2], tip: [f64; 2]) -> ArmTrace {
        ArmTrace {
            name: "arm_r".into(),
            trace: TracedArm {
                armpit,
                shoulder,
                tip,
                corner: None,
                centre: Vec::new(),
                half_width: Vec::new(),
                chord: Vec::new(),
                thumb: None,
                from_corner: None,
            },
            z: 0.0,
        }
    }

    /// A figure x -1..1 with a T-pose arm on its right (y 3..4 out to
    /// x = 4), the body above the arm a little wider than at the armpit
    /// (x = 1.1 up to y = 6), a roof to the top at (0, 7), counter-clockwise;
    /// the arm's armpit (1, 3), shoulder point (1.5, 4), tip (4, 3.5).
    pub fn t_pose() -> (Vec<[f64; 2]>, ArmTrace) {
        let front = vec![
            [-1.0, 0.0],
            [1.0, 0.0],
            [1.0, 3.0],
            [4.0, 3.0],
            [4.0, 4.0],
            [1.5, 4.0],
            [1.1, 4.0],
            [1.1, 6.0],
            [0.0, 7.0],
            [-1.1, 6.0],
        ];
        (front, arm([1.0, 3.0], [1.5, 4.0], [4.0, 3.5]))
    }
}

#[cfg(test)]
mod tests {
    use super::fixtures::{arm, t_pose};
    use super::*;

    /// The upright cut of a T-pose arm ends at the corner where the arm's
    /// top meets the body's side, not where the line up from the armpit
    /// meets the roof; of a hanging arm under a sloping shoulder, where
    /// that line meets the shoulder.
    #[test]
    fn an_upright_cut_ends_at_the_arm_s_top_corner_or_over_the_armpit() {
        let (front, t) = t_pose();
        assert_eq!(upright_top(&front, &t.trace), Some([1.1, 4.0]));

        // a hanging arm x 1.2..1.6 down to y = 1, the shoulder rounding
        // over from (1.6, 3.5) to the neck's base at (0.6, 4.5)
        let hanging = vec![
            [-1.0, 0.0],
            [1.0, 0.0],
            [1.0, 3.0],
            [1.2, 3.0],
            [1.2, 1.0],
            [1.6, 1.0],
            [1.6, 3.0],
            [1.6, 3.5],
            [1.4, 4.0],
            [0.6, 4.5],
            [0.6, 6.0],
            [0.0, 6.5],
            [-0.6, 6.0],
            [-0.6, 4.5],
            [-1.0, 4.0],
        ];
        let t = arm([1.0, 3.0], [1.6, 3.0], [1.4, 1.0]);
        let top = upright_top(&hanging, &t.trace).unwrap();
        let want = [1.0, 4.25];
        assert!(
            dist(top, want) <= crate::check::tol::ROUNDING,
            "{top:?} for {want:?}"
        );
    }
}
