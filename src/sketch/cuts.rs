//! User-drawn cuts (SVG paths whose id starts with `cut`) as explicit part
//! boundaries of the automatic humanoid segmentation.
//!
//! A cut is an open polyline drawn across a part (validated by
//! `input::validate_cut`: it crosses the outline at least twice). Its
//! **crossings** with the outline are found exactly (segment intersection);
//! the first and last crossing along the cut bound the part, their midpoint
//! `m` says which join the cut marks and their mean height `y_c` is where
//! that join is placed (a tilted cut is taken as horizontal at `y_c`):
//!
//! | midpoint `m` | join | effect |
//! |---|---|---|
//! | outside an armpit's x, below it | that arm's shoulder | the arm starts at `y_c` |
//! | between the armpits, below the crotch | that leg's hip (left or right of the crotch) | the leg starts at `y_c` |
//! | between the armpits, above them | the neck | the head starts at `y_c` |
//!
//! Anything else (a cut across the torso, an arm above its armpit, two cuts
//! for one join) is an error naming the cut. Without cuts every join is
//! placed from the outline's concave corners ([`super::segment`]).

/// Join heights set by cuts (defined with the segmentation that reads them).
pub use super::segment::JoinHeights;
use super::segment::{Landmarks, GAP_FRACTION};
use super::SketchError;

/// A cut: its SVG id and its points (model coordinates).
pub type CutPath = (String, Vec<[f64; 2]>);

/// Crossings of a polyline with a closed outline, in order along the cut.
pub fn crossings(cut: &[[f64; 2]], outline: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let n = outline.len();
    let mut out = Vec::new();
    for w in cut.windows(2) {
        let (a, b) = (w[0], w[1]);
        let mut here: Vec<(f64, [f64; 2])> = Vec::new();
        for i in 0..n {
            let (c, d) = (outline[i], outline[(i + 1) % n]);
            let r = [b[0] - a[0], b[1] - a[1]];
            let Some((t, u)) = crate::polygon::line_segment_params(a, r, c, d) else {
                continue;
            };
            if (0.0..=1.0).contains(&t) && (0.0..1.0).contains(&u) {
                here.push((t, [a[0] + t * r[0], a[1] + t * r[1]]));
            }
        }
        here.sort_by(|x, y| x.0.total_cmp(&y.0));
        out.extend(here.into_iter().map(|h| h.1));
    }
    out
}

/// The join heights the cuts set, on the upright outline and its landmarks.
pub fn join_heights(
    front: &[[f64; 2]],
    lm: &Landmarks,
    cuts: &[CutPath],
) -> Result<JoinHeights, SketchError> {
    let mut j = JoinHeights::default();
    let g = GAP_FRACTION * lm.height();
    let xr = crate::polygon::span(front, 0);
    for (id, pts) in cuts {
        let bad = |m: String| SketchError::Cut {
            id: id.clone(),
            message: m,
        };
        let x = crossings(pts, front);
        if x.len() < 2 {
            return Err(bad(format!(
                "crosses the outline {} time(s); a cut runs across one part, from outside to outside",
                x.len()
            )));
        }
        let (p, q) = (x[0], x[x.len() - 1]);
        let m = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])];
        let yc = m[1];
        let ya_l = lm.armpit_l[1];
        let ya_r = lm.armpit_r[1];
        let (slot, what, below): (&mut Option<f64>, &str, Option<f64>) = if m[0] < lm.armpit_l[0] {
            (&mut j.arm_l, "arm_l", Some(ya_l - g))
        } else if m[0] > lm.armpit_r[0] {
            (&mut j.arm_r, "arm_r", Some(ya_r - g))
        } else if yc < lm.crotch[1] {
            if m[0] < lm.crotch[0] {
                (&mut j.leg_l, "leg_l", Some(lm.crotch[1] - g))
            } else {
                (&mut j.leg_r, "leg_r", Some(lm.crotch[1] - g))
            }
        } else if yc > ya_l.max(ya_r) + 2.0 * g {
            (&mut j.neck, "head", None)
        } else {
            return Err(bad(format!(
                    "crosses the torso at y = {yc:.4} (x from {:.4} to {:.4}): cuts mark where an arm, a leg or the head joins (outline x from {:.4} to {:.4})",
                    p[0].min(q[0]),
                    p[0].max(q[0]),
                    xr[0],
                    xr[1]
                )));
        };
        if let Some(top) = below {
            if yc > top {
                return Err(bad(format!(
                    "crosses {what} at y = {yc:.4}, above where it separates from the body (y = {top:.4}): draw it across the limb below the armpit or crotch"
                )));
            }
        }
        if slot.is_some() {
            return Err(bad(format!("a second cut for {what}")));
        }
        *slot = Some(yc);
    }
    Ok(j)
}
