//! An arm's first sections turned up toward its shoulder's corner
//! ([`turned_to_corner`]): the traced arm's sections are perpendicular to
//! its axis (`super::limb`), which leaves a hanging arm's shoulder above
//! its first ring to the shoulders transition; the first
//! [`SHOULDER_TILT_SECTIONS`] are turned from the armpit's side toward the
//! corner of the drawn shoulder ([`shoulder_corner`]) instead.

use super::poly::dist;

/// The shoulder's outer corner: on the outline from the shoulder point
/// `rest[0]` (the cut's upper end) toward the neck, up to `mid_x` (halfway
/// to the neck's side, where the shoulders transition's seam apex lies:
/// `derive`), the point farthest above the chord between the stretch's
/// two ends (its convex corner: a square shoulder's, or the top of a round
/// one). None when nothing lies above the chord (a straight or hollow
/// shoulder line: no corner to reach) or the stretch is empty. `side`: -1
/// for the left arm, +1 for the right.
pub fn shoulder_corner(rest: &[[f64; 2]], mid_x: f64, side: f64) -> Option<[f64; 2]> {
    let end = rest
        .iter()
        .position(|p| side * (p[0] - mid_x) <= 0.0)
        .unwrap_or(rest.len());
    let stretch = &rest[..end];
    let (a, b) = (*stretch.first()?, *stretch.last()?);
    let l = dist(a, b);
    if l.is_nan() || l <= 0.0 {
        return None;
    }
    // the chord's normal toward +y
    let mut n = [-(b[1] - a[1]) / l, (b[0] - a[0]) / l];
    if n[1] < 0.0 {
        n = [-n[0], -n[1]];
    }
    let above = |p: &[f64; 2]| (p[0] - a[0]) * n[0] + (p[1] - a[1]) * n[1];
    stretch
        .iter()
        .filter(|p| above(p) > 0.0)
        .max_by(|p, q| above(p).total_cmp(&above(q)))
        .copied()
}

/// Sections of an arm's start that are turned toward the shoulder's
/// corner: the first all the way, the next by half.
pub const SHOULDER_TILT_SECTIONS: usize = 2;

/// The section from `inner` (the arm's inner side) turned up toward the
/// shoulder's corner `aim` ([`shoulder_corner`]): the chord direction
/// `chord` (inner to outer side) turned by `f` times its angle to the
/// direction of `aim` from `inner`, toward +y only and never past the
/// vertical, to where it leaves the outline. The first section then
/// reaches the corner of a square shoulder, which the shoulders
/// transition's arch from the arm's ring to the seam apex cut off (the
/// corpus's arms_low, 1.9 % of the height inside its drawn front);
/// a fixed turn of 60 degrees (chosen on the bundled female and male)
/// fell short of corners straight above the armpit, and a fixed turn to
/// the vertical reached past sloping shoulders' corners up to the seam
/// apex, where the transition folded (docs/drawing-corpus.md, twenty-sixth
/// measurement). Returns (centre, unit direction, half length),
/// or None when there is nothing to turn or the turned chord leaves the
/// outline nearer than `w` or farther than 8 `w` (not the shoulder: keep
/// the section perpendicular).
fn tilted(
    front: &[[f64; 2]],
    inner: [f64; 2],
    chord: [f64; 2],
    f: f64,
    w: f64,
    aim: [f64; 2],
) -> Option<([f64; 2], [f64; 2], f64)> {
    // turn toward +y (the angle pi/2): counter-clockwise when the chord
    // points to +x (phi in [-pi/2, pi/2]), clockwise when it points to -x
    // (phi taken in (pi/2, 3 pi/2)), so a mirrored arm turns mirrored
    let up = if chord[0] >= 0.0 { 1.0 } else { -1.0 };
    let angle = |v: [f64; 2]| {
        if up > 0.0 {
            v[1].atan2(v[0])
        } else {
            v[1].atan2(v[0]).rem_euclid(std::f64::consts::TAU)
        }
    };
    let phi = angle(chord);
    let vertical = std::f64::consts::FRAC_PI_2;
    let to_aim = angle([aim[0] - inner[0], aim[1] - inner[1]]) - phi;
    // only upward turns, and less than a half turn (the aim beside the chord)
    if !(up * to_aim > 0.0 && to_aim.abs() < std::f64::consts::PI) {
        return None;
    }
    let mut target = phi + f * to_aim;
    let past_vertical = up * (target - vertical) > 0.0;
    if past_vertical {
        target = vertical;
    }
    // turned all the way to the aim (a vertex of the outline)
    let at_aim = f >= 1.0 && !past_vertical;
    if (target - phi).abs() < 1e-9 {
        return None;
    }
    let d = [target.cos(), target.sin()];
    let mut best = super::poly::ray_exit(front, inner, d, 0.5 * w);
    // turned all the way to the aim, the ray leaves the outline there at
    // the latest: a ray through a vertex can miss both of its edges by
    // rounding and find a crossing beyond it
    if at_aim {
        let reach = dist(aim, inner);
        best = Some(best.map_or(reach, |b| b.min(reach)));
    }
    let len = best.filter(|&l| l >= w && l <= 8.0 * w)?;
    Some((
        [inner[0] + 0.5 * len * d[0], inner[1] + 0.5 * len * d[1]],
        d,
        0.5 * len,
    ))
}

/// Section `j` (below [`SHOULDER_TILT_SECTIONS`]) of a traced arm, whose
/// pair of sides there has its middle at `centre`, half width `w` and
/// unit chord `chord` (inner to outer side), turned toward the shoulder's
/// `corner` ([`tilted`], by `1 - j / SHOULDER_TILT_SECTIONS` of the turn)
/// from the arm's inner side; None when the arm has no corner or the turn
/// is refused.
pub fn turned_to_corner(
    front: &[[f64; 2]],
    [centre, chord]: [[f64; 2]; 2],
    w: f64,
    corner: Option<[f64; 2]>,
    j: usize,
) -> Option<([f64; 2], [f64; 2], f64)> {
    let f = 1.0 - j as f64 / SHOULDER_TILT_SECTIONS as f64;
    let inner = [centre[0] - w * chord[0], centre[1] - w * chord[1]];
    tilted(front, inner, chord, f, w, corner?)
}

/// A traced arm section's shape: a circle of radius `r`, or, turned
/// (`depth`: the arm's own radius), an ellipse of half length `r` in the
/// drawing's plane and `depth` across it (hidden in the side view, the
/// arm keeps its own depth however long the turned section).
pub fn section_shape(r: f64, depth: Option<f64>) -> crate::character::doc::SectionShape {
    use crate::character::doc::SectionShape;
    match depth {
        Some(b) => SectionShape::Ellipse {
            a: r,
            b,
            offset: 0.0,
        },
        None => SectionShape::Circle { r },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square shoulder's corner is found where the outline turns from
    /// the arm's outer side to the shoulder's top, for either arm; the
    /// walk stops halfway to the neck (a point beyond it is not taken);
    /// a straight shoulder line, a hollow one and an empty walk have none.
    #[test]
    fn the_shoulder_corner_is_the_square_shoulder_s_turn() {
        // right arm: up the outer side from S = (3, 0) to the corner
        // (3, 2), then in along the top toward a neck at x = 0 (halfway:
        // x = 1.5); the point at x = 1 rises higher but lies past halfway
        let right = [[3.0, 0.0], [3.0, 1.0], [3.0, 2.0], [2.0, 2.0], [1.0, 5.0]];
        assert_eq!(shoulder_corner(&right, 1.5, 1.0), Some([3.0, 2.0]));
        let left: Vec<[f64; 2]> = right.iter().map(|p| [-p[0], p[1]]).collect();
        assert_eq!(shoulder_corner(&left, -1.5, -1.0), Some([-3.0, 2.0]));
        // a straight slope and a hollow one: nothing above the chord
        let straight = [[3.0, 0.0], [2.5, 1.0], [2.0, 2.0], [1.0, 4.0]];
        assert_eq!(shoulder_corner(&straight, 1.5, 1.0), None);
        let hollow = [[3.0, 0.0], [2.2, 0.5], [2.0, 2.0], [1.0, 4.0]];
        assert_eq!(shoulder_corner(&hollow, 1.5, 1.0), None);
        assert_eq!(shoulder_corner(&[], 1.5, 1.0), None);
        // S already inside halfway: no stretch
        assert_eq!(shoulder_corner(&[[1.0, 0.0], [0.5, 1.0]], 1.5, 1.0), None);
    }

    /// A mirrored arm's shoulder section is the mirror image: both chords
    /// turn toward +y and stop at the vertical (before, a chord pointing
    /// to -x was measured against -pi/2 and turned past the vertical, so
    /// the left arm's top ring leaned over its shoulder: the A-pose fold).
    #[test]
    fn a_mirrored_chord_turns_to_the_mirrored_section() {
        let square = [[-3.0, -3.0], [3.0, -3.0], [3.0, 3.0], [-3.0, 3.0]];
        let mirrored: Vec<[f64; 2]> = square.iter().rev().map(|p| [-p[0], p[1]]).collect();
        let h = std::f64::consts::FRAC_1_SQRT_2;
        for chord_y in [h, 0.2, -0.3] {
            let c = [(1.0f64 - chord_y * chord_y).sqrt(), chord_y];
            for f in [1.0, 0.5] {
                // aimed at a corner up and out, mirrored for the left arm
                let (ca, da, la) =
                    tilted(&square, [0.0, 0.0], c, f, 1.0, [1.0, 10.0]).expect("right");
                let (cb, db, lb) =
                    tilted(&mirrored, [0.0, 0.0], [-c[0], c[1]], f, 1.0, [-1.0, 10.0])
                        .expect("left");
                let eps = crate::check::tol::ROUNDING;
                assert!(
                    (ca[0] + cb[0]).abs() < eps && (ca[1] - cb[1]).abs() < eps,
                    "{ca:?} {cb:?}"
                );
                assert!(
                    (da[0] + db[0]).abs() < eps && (da[1] - db[1]).abs() < eps,
                    "{da:?} {db:?}"
                );
                assert!((la - lb).abs() < eps);
                // never past the vertical
                assert!(da[0] >= -eps && db[0] <= eps, "{da:?} {db:?}");
            }
        }
    }
}
