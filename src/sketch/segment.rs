//! Segmentation of a standing humanoid's front outline (paper 000 sec 4.1.1,
//! Fig 6b) and the key sections of each part.
//!
//! Landmarks come from horizontal slices of the outline: the **gap tops**
//! (where, going up, two slice intervals merge: the armpits and the crotch,
//! the outline's concave corners) and the **neck** (the narrowest slice
//! between the armpits and the top, whose base is where the width first
//! exceeds [`NECK_FLARE`] times the neck width). Parts are then the slice
//! intervals of each region: `leg_l`/`leg_r` below the crotch (split at its
//! x), `arm_l`/`arm_r` outside the armpits, `torso` between crotch and
//! armpits, `head` above the neck base. An arm whose gap with the body
//! closes below the crotch or just above it (a big-headed figure's) has
//! its armpit there ([`super::refusal::low_armpit`]): no torso to build
//! between them ([`Landmarks::torso_is_short`]), the upper body is built
//! as shells (`super::humanoid_shells::short_torso_models`). A band of half-height
//! [`GAP_FRACTION`] of the model height is left to the transitions at each
//! join. Arms must hang away from the body and the legs must be apart
//! (otherwise the gaps are missing and segmentation fails with an error).
//!
//! Key sections: the centre of each slice is the central curve; sections are
//! placed by equidistributing half arc length, half the variation of the
//! profile (|w''| + |c''| of half-width w and centre c): dense where the
//! profile's curvature changes (simpler than the paper's manual placement).
//! A section is perpendicular to the central curve; its radius is the
//! half-width times the cosine of the curve's tilt.

use super::poly::{
    crotch_gap, gap_below, gap_tops, merge_repeats, neck_base, slice, GapTop, GAP_WALK_SLICES,
};
pub(crate) use super::region::reach;
pub use super::region::{interval, Pick, Region, SidePick};
use super::SketchError;

/// Half-height of a join band, as a fraction of the model height.
pub const GAP_FRACTION: f64 = 0.015;
/// The neck base is where the width exceeds this multiple of the neck width.
pub const NECK_FLARE: f64 = 1.3;
/// A part is longer than this many join bands between its two bands: a
/// margin over "positive", set on seed 4242's issue-range humanoids (4-6 %
/// torsos), checked on seed 9191 (docs/drawing-corpus.md, eighth).
pub const MIN_PART_BANDS: f64 = 0.5;
/// The least torso, crotch to armpits, of a model of height `h`: a join
/// band at each end and [`MIN_PART_BANDS`] between them.
pub fn torso_min(h: f64) -> f64 {
    (2.0 + MIN_PART_BANDS) * GAP_FRACTION * h
}

/// Slices used to find the landmarks.
pub const LANDMARK_SLICES: usize = 600;

/// The joins found on a front outline.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Landmarks {
    pub y_min: f64,
    pub y_max: f64,
    pub crotch: [f64; 2],
    pub armpit_l: [f64; 2],
    pub armpit_r: [f64; 2],
    /// Neck base height (bottom of the head part) and narrowest neck height.
    pub neck_base: f64,
    pub neck: f64,
}

impl Landmarks {
    pub fn height(&self) -> f64 {
        self.y_max - self.y_min
    }

    /// Whether the lower armpit is no more than the least torso
    /// ([`torso_min`]) above the crotch: no torso to build between them.
    pub fn torso_is_short(&self) -> bool {
        self.armpit_l[1].min(self.armpit_r[1]) - self.crotch[1] <= torso_min(self.height())
    }

    /// The refusal of a torso too short to build stacked
    /// ([`Self::torso_is_short`]), naming the lower armpit: below the
    /// crotch or too near above it.
    pub fn short_torso_error(&self) -> SketchError {
        let (which, a) = if self.armpit_l[1] <= self.armpit_r[1] {
            ("left", self.armpit_l)
        } else {
            ("right", self.armpit_r)
        };
        let h = self.height();
        super::refusal::arm_too_low(a, self.crotch, h, torso_min(h), which)
    }
}

/// Where the torso's `side` end (-1 left, +1 right) first moves outward
/// faster than [`ARMPIT_SLOPE`] times the rise, going up from the crotch
/// along the slice interval that holds the torso: an arm leaving the torso
/// (the merge of a hanging arm's interval at its gap top, or a T-pose arm's
/// underside, which closes no gap). Returns the torso's end just below
/// that height. The crotch's own gap closing there (the higher corner of
/// a square crotch drawn a little uneven, [`crotch_gap`]) is no arm: it
/// was taken for the left armpit of seed 7777's random_47, a torso of
/// 0 % of the height, refused. A second merge with an interval outside the torso further
/// up (below `top`) means the arm touched the body there and leaves it
/// again: an error naming the heights. None: the side never jumps out (an
/// arm joining the body below the crotch or just above it, whose root the
/// torso's interval holds from the crotch up: [`super::refusal::low_armpit`]).
fn armpit(
    front: &[[f64; 2]],
    crotch: GapTop,
    top: f64,
    side: f64,
    g: f64,
) -> Result<Option<GapTop>, SketchError> {
    let n = LANDMARK_SLICES;
    // from one slice above the crotch: an armpit just above it (a short
    // torso) is a merge like any other
    let dy = (top - crotch.y) / (n + 1) as f64;
    let y0 = crotch.y + dy;
    let which = if side < 0.0 { "left" } else { "right" };
    let mut mid = crotch.x;
    let mut prev: Option<(f64, f64, Option<f64>)> = None;
    let mut found: Option<GapTop> = None;
    let mut left_again: Option<f64> = None;
    for k in 0..n {
        let y = y0 + k as f64 * dy;
        let s = slice(front, y);
        let Some(iv) = s.iter().find(|iv| iv[0] <= mid && mid <= iv[1]).copied() else {
            break;
        };
        let end = if side > 0.0 { iv[1] } else { iv[0] };
        // the nearest end of another interval outside the torso on this
        // side (an arm apart, or the crotch's other corner): the gap's far side
        let beyond = s
            .iter()
            .map(|o| if side > 0.0 { o[0] } else { o[1] })
            .filter(|&b| side * (b - end) > 0.0)
            .min_by(|a, b| (side * a).total_cmp(&(side * b)));
        if let Some((py, pe, was_beyond)) = prev {
            let jump = side * (end - pe) > ARMPIT_SLOPE * (y - py);
            // the crotch's own gap closing (an uneven crotch's higher
            // corner) is not an arm leaving the torso (tested only at a
            // jump: it follows two gaps down)
            let crotch_closes = || {
                was_beyond.is_some_and(|b| {
                    let t = GapTop {
                        x: 0.5 * (pe + b),
                        y: py,
                    };
                    crotch_gap(front, &t, &crotch, g)
                })
            };
            match (found, left_again) {
                (None, _) if jump && !crotch_closes() => found = Some(GapTop { x: pe, y: py }),
                (Some(_), None) if side * (end - pe) < -ARMPIT_SLOPE * (y - py) => {
                    left_again = Some(y)
                }
                (Some(f), Some(y2)) if jump && was_beyond.is_some() => {
                    return Err(SketchError::Segmentation(format!(
                        "the {which} arm touches the body between y = {:.4} and {:.4}: draw the arm apart from the body there (leave a gap between them)",
                        f.y, y2
                    )));
                }
                _ => {}
            }
        }
        mid = 0.5 * (iv[0] + iv[1]);
        prev = Some((y, end, beyond));
    }
    Ok(found)
}

/// A torso side moving outward faster than this many times the rise is an
/// arm leaving it (a slope of 72 degrees from the vertical: steeper than
/// any hip or belly, shallower than a T-pose arm's underside; a geometric
/// choice, not fitted to drawings).
pub const ARMPIT_SLOPE: f64 = 3.0;
/// The crotch's gap must run down to this fraction of its height above the
/// lowest point (the legs reach the ground; a drawing a few degrees off
/// upright lifts one foot, so not to the lowest point itself). A gap
/// between a hanging arm and the torso ends at the hand, at least a third
/// of its height above the ground for any arm shorter than the legs.
pub const GROUND_FRACTION: f64 = 0.15;

/// Whether the gap below `t` runs down to the ground ([`GROUND_FRACTION`])
/// between two intervals (the legs) at every height: the crotch's gap
/// does, a gap between a hanging arm and the torso opens to the outside
/// below the hand. Returns the gap's middle at the ground.
fn reaches_ground(front: &[[f64; 2]], t: &GapTop, y_min: f64) -> Option<[f64; 2]> {
    let ground = y_min + GROUND_FRACTION * (t.y - y_min);
    gap_below(front, t, ground, GAP_WALK_SLICES).map(|x| [x, ground])
}

/// The crotch among the gap tops (highest first) whose gaps reach the
/// ground: the gap between the two legs, whose sides both run down to the
/// feet. An arm hanging nearly to the ground beside a leg also leaves a
/// gap that reaches it ([`GROUND_FRACTION`]), but one of its sides is the
/// hand, which mostly ends above the feet: the gaps whose higher-ending
/// side ends lowest (within a join band `g`) are kept (one gap: it). A hand
/// that reaches the feet ties with them; the legs' gap lies under the
/// head, an arm's beside the body: of the kept gaps, those nearest the
/// figure's axis (the middle of the widest interval of the outline's slice
/// a join band below its top `yr[1]`, within a band `g`), and of these the highest top (a gap
/// between the ankles of legs touching at the knees lies under the crotch).
fn crotch_of(front: &[[f64; 2]], tops: &[GapTop], yr: [f64; 2], g: f64) -> Option<GapTop> {
    let y_min = yr[0];
    let grounded: Vec<(GapTop, [f64; 2])> = tops
        .iter()
        .filter_map(|t| Some((*t, reaches_ground(front, t, y_min)?)))
        .collect();
    if grounded.len() < 2 {
        return grounded.first().map(|c| c.0);
    }
    let ends: Vec<(GapTop, f64)> = grounded
        .into_iter()
        .map(|(t, [x, ground])| {
            let end = |side: f64| reach(front, Pick::Beside(x, side), ground, y_min - g);
            (t, end(-1.0).max(end(1.0)))
        })
        .collect();
    let lowest = ends.iter().map(|e| e.1).fold(f64::INFINITY, f64::min);
    let tied: Vec<GapTop> = ends
        .into_iter()
        .filter(|e| e.1 <= lowest + g)
        .map(|e| e.0)
        .collect();
    let anywhere = Pick::CentreIn(f64::NEG_INFINITY, f64::INFINITY);
    let axis = interval(front, anywhere, yr[1] - g).map(|iv| 0.5 * (iv[0] + iv[1]));
    let off = |t: &GapTop| axis.map_or(0.0, |a| (t.x - a).abs());
    let nearest = tied.iter().map(off).fold(f64::INFINITY, f64::min);
    tied.into_iter().find(|t| off(t) <= nearest + g)
}

/// Finds the crotch, armpits and neck. The crotch is the top of the gap
/// between the legs, which runs down to the ground ([`crotch_of`]); each
/// armpit is where the torso's side, followed up from the crotch, meets
/// its arm ([`armpit`]): for arms hanging apart the gap top between arm
/// and torso, for a T-pose the arm's underside.
pub fn landmarks(front: &[[f64; 2]]) -> Result<Landmarks, SketchError> {
    let yr = crate::polygon::span(front, 1);
    let h = yr[1] - yr[0];
    let mut tops: Vec<GapTop> = gap_tops(front, LANDMARK_SLICES);
    merge_repeats(&mut tops, GAP_FRACTION * h);
    tops.sort_by(|a, b| b.y.total_cmp(&a.y));
    let crotch = crotch_of(front, &tops, yr, GAP_FRACTION * h).ok_or_else(|| {
            SketchError::Segmentation(
                "no crotch found (no gap between the legs running down to the ground): draw the legs apart, \
                 or add a cut path across each leg"
                    .into(),
            )
        })?;
    // a hanging arm's gap closes at a gap top: the armpit is that point
    // (where the gap's two sides meet), not the torso's side below it
    let at_gap = |a: GapTop| -> GapTop {
        tops.iter()
            .filter(|t| (t.x - a.x).hypot(t.y - a.y) <= 2.0 * GAP_FRACTION * h)
            .filter(|t| !crotch_gap(front, t, &crotch, GAP_FRACTION * h))
            .min_by(|p, q| {
                (p.x - a.x)
                    .hypot(p.y - a.y)
                    .total_cmp(&(q.x - a.x).hypot(q.y - a.y))
            })
            .copied()
            .unwrap_or(a)
    };
    let find = |side: f64| -> Result<GapTop, SketchError> {
        match armpit(front, crotch, yr[1], side, GAP_FRACTION * h)? {
            Some(a) => Ok(at_gap(a)),
            None => super::refusal::low_armpit(
                front,
                &tops,
                crotch,
                [torso_min(h), GAP_FRACTION * h],
                side,
            )
            .ok_or_else(|| {
                let which = if side < 0.0 { "left" } else { "right" };
                SketchError::Segmentation(format!(
                    "no {which} armpit found: the torso's {which} side never meets an arm going up from the crotch; \
                     draw the {which} arm reaching out from the shoulder"
                ))
            }),
        }
    };
    let a0 = find(-1.0)?;
    let a1 = find(1.0)?;
    // neck: narrowest single interval between armpits and top
    let ya = a0.y.max(a1.y);
    let d = yr[1] - ya;
    // the width of the interval on the torso's axis (a T-pose's arms are
    // in it up to the shoulders; an arm's top beside the neck is not)
    let axis = 0.5 * (a0.x + a1.x);
    let width = |y: f64| -> Option<f64> {
        slice(front, y)
            .iter()
            .find(|iv| iv[0] <= axis && axis <= iv[1])
            .map(|iv| iv[1] - iv[0])
    };
    let n = 200;
    let mut neck = (f64::INFINITY, ya);
    for k in 0..=n {
        let y = ya + d * (0.15 + 0.55 * k as f64 / n as f64);
        if let Some(w) = width(y) {
            if w < neck.0 {
                neck = (w, y);
            }
        }
    }
    if !neck.0.is_finite() {
        return Err(SketchError::Segmentation(
            "no neck found above the armpits: draw the head on a neck narrower than the shoulders, above both arms".into(),
        ));
    }
    let narrow = |y: f64| matches!(width(y), Some(w) if w < NECK_FLARE * neck.0);
    let base = neck_base(narrow, neck.1, ya + 2.0 * GAP_FRACTION * h, d);
    Ok(Landmarks {
        y_min: yr[0],
        y_max: yr[1],
        crotch: [crotch.x, crotch.y],
        armpit_l: [a0.x, a0.y],
        armpit_r: [a1.x, a1.y],
        neck_base: base,
        neck: neck.1,
    })
}

/// The neck's slice interval at the neck base: the one on the torso's axis
/// (midway between the armpits; an arm's top beside the neck at that
/// height is not the neck).
pub fn neck_interval(front: &[[f64; 2]], lm: &Landmarks) -> Option<[f64; 2]> {
    let axis = 0.5 * (lm.armpit_l[0] + lm.armpit_r[0]);
    slice(front, lm.neck_base)
        .into_iter()
        .find(|iv| iv[0] <= axis && axis <= iv[1])
}

/// The six regions of a standing humanoid; a limb starts at its cut when
/// `cuts` gives one ([`super::cuts`]), else a join band below its armpit or
/// the crotch.
///
/// A leg is the slice interval nearest the crotch's x on its side
/// ([`Pick::Beside`]). Bounded by the armpit's x (once), a wide stance's
/// leg became a stub; the widest interval (next) was a hand beside a thin
/// thigh, and `section_place::connected_run` cut the leg at the knee
/// (corpus random_5: its sections crowded, its chain ill-conditioned).
pub fn regions(
    front: &[[f64; 2]],
    lm: &Landmarks,
    cuts: &JoinHeights,
) -> Result<Vec<Region>, SketchError> {
    let g = GAP_FRACTION * lm.height();
    let ya = lm.armpit_l[1].min(lm.armpit_r[1]);
    let mut out = vec![
        Region {
            name: "torso".into(),
            y0: lm.crotch[1] + g,
            y1: ya - g,
            pick: Pick::CentreIn(lm.armpit_l[0], lm.armpit_r[0]),
            downward: false,
            tip: false,
            shoulder: None,
            horizontal: false,
            side: SidePick::Whole,
        },
        Region {
            name: "head".into(),
            y0: lm.neck_base,
            y1: lm.y_max,
            // slices centred over the neck (within a neck's width of it):
            // not an arm's top beside it
            pick: match neck_interval(front, lm) {
                Some([a, b]) => Pick::CentreIn(a - (b - a), b + (b - a)),
                None => Pick::CentreIn(lm.armpit_l[0], lm.armpit_r[0]),
            },
            downward: false,
            tip: true,
            shoulder: None,
            horizontal: false,
            side: SidePick::Whole,
        },
    ];
    // arms: traced along their own axis (`super::limb`); legs: see the doc
    for (name, side, top, shoulder) in [
        ("leg_l", -1.0, lm.crotch[1], None),
        ("leg_r", 1.0, lm.crotch[1], None),
    ] {
        let pick = Pick::Beside(lm.crotch[0], side);
        let y1 = cuts.limb(name).unwrap_or(top - g);
        if interval(front, pick, y1).is_none() {
            return Err(SketchError::Segmentation(format!(
                "{name}: no outline below its join: draw each leg reaching down to the ground"
            )));
        }
        // lowest height where the region still has an interval
        let y0 = reach(front, pick, y1, lm.y_min - g);
        out.push(Region {
            name: name.into(),
            y0,
            y1,
            pick,
            downward: true,
            tip: true,
            shoulder,
            horizontal: false,
            side: if shoulder.is_some() {
                SidePick::Hidden
            } else {
                SidePick::Whole
            },
        });
    }
    // the torso lies between a band above the crotch and one below the
    // armpits; a shorter one is built with the arms as shells
    // (`super::derive`), its region giving only its start
    let short = lm.torso_is_short();
    for r in out.iter().filter(|r| !(short && r.name == "torso")) {
        if (r.y1 - r.y0).partial_cmp(&(MIN_PART_BANDS * g)) != Some(std::cmp::Ordering::Greater) {
            return Err(SketchError::Segmentation(format!(
                "{}: too short to build ({:.4} between y = {:.4} and {:.4}, at most half a join band of {:.4}): \
                 draw it longer",
                r.name,
                r.y1 - r.y0,
                r.y0,
                r.y1,
                MIN_PART_BANDS * g
            )));
        }
    }
    Ok(out)
}

/// Height of the shoulder's top above `x`, for the shoulder seams: the
/// outline's highest top over `x` below the neck's narrowest height
/// (`lm.neck`; a head wider than its neck is above it), or None.
pub fn shoulder_top(front: &[[f64; 2]], x: f64, lm: &Landmarks) -> Option<f64> {
    super::poly::top_below(front, x, lm.neck)
}

/// Join heights set by cut paths (`sketch::cuts`; None: automatic).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JoinHeights {
    pub arm_l: Option<f64>,
    pub arm_r: Option<f64>,
    pub leg_l: Option<f64>,
    pub leg_r: Option<f64>,
    pub neck: Option<f64>,
}

impl JoinHeights {
    /// The cut height of a limb region by name.
    pub fn limb(&self, name: &str) -> Option<f64> {
        match name {
            "arm_l" => self.arm_l,
            "arm_r" => self.arm_r,
            "leg_l" => self.leg_l,
            "leg_r" => self.leg_r,
            _ => None,
        }
    }
}
