//! Landmarks of an animal's lateral outline: the gaps between its legs
//! and the corners where tail, back and neck join the body (see the parent
//! module's docs).

use super::super::poly::{gap_tops, merge_repeats, slice, GapTop};
use super::super::segment::{interval, Pick, GAP_FRACTION, GROUND_FRACTION, LANDMARK_SLICES};
use super::super::SketchError;

/// The joins found on an animal's lateral outline.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct QuadLandmarks {
    pub y_min: f64,
    pub y_max: f64,
    /// Tops of the gaps between the legs, by x.
    pub leg_gaps: Vec<[f64; 2]>,
    /// Corners between tail, back and neck at the top, by x.
    pub top_gaps: Vec<[f64; 2]>,
    /// With no such corner, the back line under a lone part above the body
    /// (a neck: the tail hanging or absent), [`back_line`]; None also when
    /// nothing rises above the back (the body closes at the top).
    pub back_line: Option<[f64; 2]>,
    /// +1 when the head is toward +x, -1 toward -x.
    pub facing: f64,
}

impl QuadLandmarks {
    pub fn height(&self) -> f64 {
        self.y_max - self.y_min
    }
}

/// Whether an outline is longer than tall: its principal axis
/// (`align::axes`) is defined and within 45 degrees of horizontal.
pub fn longer_than_tall(front: &[[f64; 2]]) -> bool {
    let ax = super::super::align::axes(front);
    ax.anisotropy >= super::super::align::MIN_ANISOTROPY
        && ax.major.abs() < std::f64::consts::FRAC_PI_4
}

/// Finds the leg gaps and top corners.
pub fn landmarks(front: &[[f64; 2]]) -> Result<QuadLandmarks, SketchError> {
    let yr = crate::polygon::span(front, 1);
    let mid = 0.5 * (yr[0] + yr[1]);
    let g = GAP_FRACTION * (yr[1] - yr[0]);
    let mut legs: Vec<GapTop> = gap_tops(front, LANDMARK_SLICES);
    legs.retain(|t| t.y < mid);
    merge_repeats(&mut legs, g);
    let mut legs: Vec<[f64; 2]> = legs.iter().map(|t| [t.x, t.y]).collect();
    let flipped: Vec<[f64; 2]> = front.iter().map(|p| [p[0], -p[1]]).collect();
    let mut top: Vec<GapTop> = gap_tops(&flipped, LANDMARK_SLICES);
    top.retain(|t| -t.y > mid);
    merge_repeats(&mut top, g);
    let mut top: Vec<[f64; 2]> = top.iter().map(|t| [t.x, -t.y]).collect();
    prune_notches(front, &mut top, g);
    // one part above the body (a neck, the tail hanging or absent): no
    // corner between two rising parts, but the back line under it
    let lone = if top.is_empty() {
        back_line(front, mid)
    } else {
        None
    };
    if legs.len() != 1 && legs.len() != 3 {
        legs = without_hanging_ends(front, &legs, yr, g)
            .ok_or_else(|| legs_error(front, &legs, yr, g))?;
    }
    // none: nothing rises above the back (a head level with it, in front
    // of the body): the body closes at the top, when it is an animal's
    // long body (an upright outline forced to this plan is refused)
    if top.is_empty() && lone.is_none() && !longer_than_tall(front) {
        return Err(SketchError::Segmentation(
            "quadruped: nothing rises above the back of an outline taller than long: draw the animal's lateral view with its neck rising above the back".into(),
        ));
    }
    if top.len() > 2 {
        return Err(SketchError::Segmentation(format!(
            "quadruped: found {} corner(s) where parts above the body join it; expected at most a tail, a domed back and a neck rising above the back line (2 corners): draw fewer parts above the back",
            top.len()
        )));
    }
    Ok(QuadLandmarks {
        y_min: yr[0],
        y_max: yr[1],
        leg_gaps: legs,
        top_gaps: top,
        back_line: lone,
        facing: 1.0,
    })
}

/// The gap tops left when the outermost parts below the body that end
/// above the ground (a trunk in front of the front legs, a tail behind
/// the hind legs, whose gaps with those legs close below the outline's
/// middle and were counted as leg gaps) are not legs: their gaps dropped,
/// when 1 or 3 remain and each dropped gap closes more than a join band
/// `g` above the highest kept one (the part then leaves the body above the
/// belly and is built on its own, [`super::hanging`]). None otherwise
/// (refused by [`legs_error`]).
fn without_hanging_ends(
    front: &[[f64; 2]],
    legs: &[[f64; 2]],
    yr: [f64; 2],
    g: f64,
) -> Option<Vec<[f64; 2]>> {
    let (parts, ground) = parts_under_gaps(front, legs, yr, g)?;
    let mut kept = legs.to_vec();
    kept.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let n = parts.len();
    let hanging = |k: usize| parts[k].1 > ground;
    if n != kept.len() + 1 || (1..n - 1).any(hanging) {
        return None;
    }
    let mut dropped = Vec::new();
    if hanging(n - 1) {
        dropped.extend(kept.pop());
    }
    if hanging(0) && !kept.is_empty() {
        dropped.push(kept.remove(0));
    }
    let top = kept.iter().map(|l| l[1]).fold(f64::MIN, f64::max);
    let above = dropped.iter().all(|d| d[1] > top + g);
    (!dropped.is_empty() && above && (kept.len() == 1 || kept.len() == 3)).then_some(kept)
}

/// A part below the body: its x range where counted and its lowest height.
type PartBelow = ([f64; 2], f64);

/// The parts below the body, counted under the gap tops `legs` as
/// [`legs_error`] counts them, and the height under which a part reaches
/// the ground.
fn parts_under_gaps(
    front: &[[f64; 2]],
    legs: &[[f64; 2]],
    yr: [f64; 2],
    g: f64,
) -> Option<(Vec<PartBelow>, f64)> {
    // the parts are counted a join band below the gap top whose slice
    // there parts the most (the higher of equals): not the lowest top (a
    // part ending between two longer ones is itself reported as a gap top,
    // the gap between those two being covered above its end), nor the
    // highest (a tail's gap with a leg can close above the legs' gaps)
    let parted = |y: f64| slice(front, y - g).len();
    let low = legs
        .iter()
        .map(|l| l[1])
        .max_by(|a, b| parted(*a).cmp(&parted(*b)).then(a.total_cmp(b)))?;
    let parts = parts_below(front, low - g, yr[0] - g);
    Some((parts, yr[0] + GROUND_FRACTION * (low - yr[0])))
}

/// The refusal of a lateral outline without 2 or 4 legs below the body
/// (its `legs` gap tops, height range `yr`, join band `g`): the parts
/// below the body that end above the ground (a hanging tail or trunk,
/// [`parts_below`]) are named, as what to change.
fn legs_error(front: &[[f64; 2]], legs: &[[f64; 2]], yr: [f64; 2], g: f64) -> SketchError {
    let generic = format!(
        "quadruped: found {} gap(s) between legs below the body ({} leg(s)); draw the lateral view with 2 or 4 legs apart",
        legs.len(),
        legs.len() + 1
    );
    let Some((parts, ground)) = parts_under_gaps(front, legs, yr, g) else {
        return SketchError::Segmentation(generic);
    };
    let hanging: Vec<String> = parts
        .iter()
        .filter(|p| p.1 > ground)
        .map(|([a, b], y)| format!("the part between x = {a:.4} and {b:.4} ends at y = {y:.4}"))
        .collect();
    if hanging.is_empty() {
        return SketchError::Segmentation(generic);
    }
    SketchError::Segmentation(format!(
        "quadruped: {} of the {} parts below the body end(s) above the ground (y = {:.4}): {}; a tail or trunk \
         hanging down is modelled only where it leaves the body above the belly, at the front or the back: \
         draw it raised above the back line, or leave it out ({} leg(s) reach the ground)",
        hanging.len(),
        parts.len(),
        yr[0],
        hanging.join(", "),
        parts.len() - hanging.len()
    ))
}

/// Slices that follow a part below the body down ([`parts_below`]): a
/// part's lowest point is found to half a percent of the height below
/// the body (a hanging part ends well above [`GROUND_FRACTION`] of it;
/// a geometric resolution, not fitted to drawings). Only a refusal
/// takes this path.
const BELOW_SLICES: usize = 200;

/// The parts below `top` (the slice intervals there), each followed down
/// through the intervals overlapping it, to `floor`: each part's x range
/// at `top` and its lowest height.
pub(super) fn parts_below(front: &[[f64; 2]], top: f64, floor: f64) -> Vec<PartBelow> {
    slice(front, top)
        .into_iter()
        .map(|iv| {
            let (mut range, mut low) = (iv, top);
            for k in 1..=BELOW_SLICES {
                let y = top + (floor - top) * k as f64 / BELOW_SLICES as f64;
                let over: Vec<[f64; 2]> = slice(front, y)
                    .into_iter()
                    .filter(|o| o[0] <= range[1] && range[0] <= o[1])
                    .collect();
                let (Some(a), Some(b)) = (over.first(), over.last()) else {
                    break;
                };
                range = [a[0], b[1]];
                low = y;
            }
            (iv, low)
        })
        .collect()
}

/// The smallest rise of the widest slice interval's width, going down one
/// landmark slice, that marks the back line under a lone neck, as a
/// fraction of the outline's length: the corpus dog with its tail down
/// steps from its neck's width to its body's, 0.58 of its length; a
/// rounded back or head widens by a few thousandths of it per slice.
pub const BACK_STEP: f64 = 0.25;

/// Where a lone part above the body (a neck) rises from the back line:
/// the highest step down (in the upper half, above `mid`) where the widest
/// slice interval widens by at least [`BACK_STEP`] of the outline's
/// length between two landmark slices, as the neck's centre x over the
/// height of the step. None when no such step exists.
fn back_line(front: &[[f64; 2]], mid: f64) -> Option<[f64; 2]> {
    let xr = crate::polygon::span(front, 0);
    let yr = crate::polygon::span(front, 1);
    let n = LANDMARK_SLICES;
    let widest = |y: f64| {
        slice(front, y)
            .into_iter()
            .max_by(|a, b| (a[1] - a[0]).total_cmp(&(b[1] - b[0])))
    };
    let step = BACK_STEP * (xr[1] - xr[0]);
    let dy = (yr[1] - mid) / n as f64;
    let mut above = widest(yr[1] - 0.5 * dy)?;
    for k in 1..n {
        let y = yr[1] - (k as f64 + 0.5) * dy;
        let Some(iv) = widest(y) else { continue };
        if (iv[1] - iv[0]) - (above[1] - above[0]) >= step {
            return Some([0.5 * (above[0] + above[1]), y + 0.5 * dy]);
        }
        above = iv;
    }
    None
}

/// Removes top gaps that separate nothing: a corner of the outline that
/// opens upward with no part rising above it between its neighbours (a
/// notch where a tail's underside meets the body's rounded end, below the
/// back line that really separates tail and neck). While some region
/// between consecutive gaps has no outline a band `g` above its higher
/// bounding gap, the lower of its bounding gaps is dropped.
fn prune_notches(front: &[[f64; 2]], top: &mut Vec<[f64; 2]>, g: f64) {
    let big = f64::MAX;
    loop {
        let empty = (0..=top.len()).find(|&i| {
            let lo = if i == 0 { -big } else { top[i - 1][0] };
            let hi = top.get(i).map_or(big, |p| p[0]);
            let y = [i.checked_sub(1), Some(i)]
                .iter()
                .flatten()
                .filter_map(|&j| top.get(j))
                .map(|p| p[1])
                .fold(f64::MIN, f64::max);
            !top.is_empty() && interval(front, Pick::CentreIn(lo, hi), y + g).is_none()
        });
        let Some(i) = empty else { return };
        let lower = [i.checked_sub(1), Some(i)]
            .into_iter()
            .flatten()
            .filter(|&j| j < top.len())
            .min_by(|&a, &b| top[a][1].total_cmp(&top[b][1]));
        match lower {
            Some(j) => {
                top.remove(j);
            }
            None => return,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat-backed body 4 long with a tail post at its left end and a
    /// taller neck post at its right (counter-clockwise).
    fn flat_back() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 3.0],
            [3.5, 3.0],
            [3.5, 1.0],
            [0.5, 1.0],
            [0.5, 2.0],
            [0.0, 2.0],
        ]
    }

    /// A body 4 long on two legs with a neck post over its right end and
    /// no tail (counter-clockwise).
    fn lone_neck() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [0.5, 0.0],
            [0.5, 1.0],
            [3.0, 1.0],
            [3.0, 0.0],
            [3.5, 0.0],
            [3.5, 1.0],
            [4.0, 1.0],
            [4.0, 2.0],
            [3.8, 2.0],
            [3.8, 3.2],
            [3.2, 3.2],
            [3.2, 2.0],
            [0.0, 2.0],
        ]
    }

    #[test]
    fn a_lone_neck_rises_from_the_back_line_and_is_the_head() {
        use crate::check::tol::{ROUNDING, SOLVE};
        let front = lone_neck();
        let mut lm = landmarks(&front).expect("a lone neck is accepted");
        assert!(lm.top_gaps.is_empty());
        let [x, y] = lm.back_line.expect("the back line under the neck");
        // the neck's centre to rounding, the back line to a landmark slice
        let slice_h = (3.2 - 1.6) / LANDMARK_SLICES as f64;
        assert!(
            (x - 3.5).abs() <= ROUNDING && (y - 2.0).abs() <= slice_h,
            "{x} {y}"
        );
        let regs = super::super::regions(&front, None, &mut lm).expect("regions");
        let names: Vec<&str> = regs.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["body", "head", "leg_b", "leg_f"]);
        assert_eq!(lm.facing, 1.0);
        let head = &regs[1];
        // the head's region from the back line up to the top (`reach`
        // bisects to 2^-40 of its scan step)
        assert!(head.y0 > y && (head.y1 - 3.2).abs() <= SOLVE, "{head:?}");
        // without the neck's step (a flat box on legs) nothing is found,
        // and the body closes at the top with nothing above it
        let mut flat = front.clone();
        flat.drain(9..13);
        assert!(back_line(&flat, 1.0).is_none());
        let mut lm = landmarks(&flat).expect("a long box on legs");
        assert!(lm.top_gaps.is_empty() && lm.back_line.is_none());
        let regs = super::super::regions(&flat, None, &mut lm).expect("regions");
        let mut names: Vec<&str> = regs.iter().map(|r| r.name.as_str()).collect();
        names.sort_unstable();
        assert_eq!(names, ["body", "leg_b", "leg_f"]);
        assert!(
            regs[0].tip && (regs[0].y1 - 2.0).abs() <= ROUNDING,
            "{:?}",
            regs[0]
        );
        // the same box stood on end (taller than long) is refused
        let tall: Vec<[f64; 2]> = flat.iter().map(|p| [p[0] / 4.0, p[1] * 2.0]).collect();
        assert!(landmarks(&tall).is_err());
    }

    /// A long body on two legs with a tail hanging between them from its
    /// underside at x 1.5 to 1.7, ending at y = 0.5 (counter-clockwise).
    fn hanging_tail() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [0.5, 0.0],
            [0.5, 1.0],
            [1.5, 1.0],
            [1.5, 0.5],
            [1.7, 0.5],
            [1.7, 1.0],
            [3.5, 1.0],
            [3.5, 0.0],
            [4.0, 0.0],
            [4.0, 2.5],
            [0.0, 2.5],
        ]
    }

    #[test]
    fn a_part_hanging_above_the_ground_is_named_as_what_to_change() {
        let e = landmarks(&hanging_tail())
            .expect_err("3 parts below")
            .to_string();
        assert!(
            e.contains("the part between x = 1.5000 and 1.7000 ends at y = 0.5")
                && e.contains("hanging down is modelled only where")
                && e.contains("(2 leg(s) reach the ground)"),
            "{e}"
        );
        // the same part reaching the ground is a third leg: the count
        let mut three = hanging_tail();
        three[4][1] = 0.0;
        three[5][1] = 0.0;
        let e = landmarks(&three).expect_err("3 legs").to_string();
        assert!(
            e.contains("2 gap(s) between legs") && !e.contains("hanging"),
            "{e}"
        );
        // parts ending between longer ones are tops of gaps themselves:
        // counted below the highest top, each is named (a comb of 3 legs
        // with 2 short parts between them)
        let comb = vec![
            [0.0, 0.0],
            [0.5, 0.0],
            [0.5, 1.0],
            [1.0, 1.0],
            [1.0, 0.5],
            [1.2, 0.5],
            [1.2, 1.0],
            [1.7, 1.0],
            [1.7, 0.0],
            [2.2, 0.0],
            [2.2, 1.0],
            [2.7, 1.0],
            [2.7, 0.5],
            [2.9, 0.5],
            [2.9, 1.0],
            [3.5, 1.0],
            [3.5, 0.0],
            [4.0, 0.0],
            [4.0, 2.5],
            [0.0, 2.5],
        ];
        let e = landmarks(&comb).expect_err("5 parts below").to_string();
        assert!(
            e.contains("2 of the 5 parts") && e.contains("(3 leg(s) reach the ground)"),
            "{e}"
        );
        // without it: a box on two legs
        let mut two = hanging_tail();
        two.drain(4..6);
        assert!(landmarks(&two).is_ok());
    }

    #[test]
    fn a_notch_with_nothing_above_it_is_dropped() {
        let front = flat_back();
        // the back line between the posts, and a notch below it that would
        // leave the stretch of back between them as a part of its own
        let mut top = vec![[1.0, 0.95], [2.0, 1.0]];
        prune_notches(&front, &mut top, 0.05);
        assert_eq!(top, vec![[2.0, 1.0]]);
        // the back line alone separates two parts: kept
        let mut top = vec![[2.0, 1.0]];
        prune_notches(&front, &mut top, 0.05);
        assert_eq!(top, vec![[2.0, 1.0]]);
    }
}
