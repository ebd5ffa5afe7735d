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
//! armpits, `head` above the neck base. A band of half-height
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

use super::cuts::JoinHeights;
use super::poly::{gap_tops, slice, top_at, GapTop};
use super::SketchError;

/// Half-height of a join band, as a fraction of the model height.
pub const GAP_FRACTION: f64 = 0.015;
/// The neck base is where the width exceeds this multiple of the neck width.
pub const NECK_FLARE: f64 = 1.3;
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
}

/// Finds the armpits, crotch and neck.
pub fn landmarks(front: &[[f64; 2]]) -> Result<Landmarks, SketchError> {
    let (yr, _) = super::poly::bounds(front);
    let h = yr[1] - yr[0];
    let mut tops: Vec<GapTop> = gap_tops(front, LANDMARK_SLICES);
    tops.sort_by(|a, b| b.y.total_cmp(&a.y));
    if tops.len() < 3 {
        return Err(SketchError::Segmentation(format!(
            "found {} gap tops, a standing humanoid needs 3 (two armpits and the crotch): arms away from the body, legs apart",
            tops.len()
        )));
    }
    let (mut a0, mut a1) = (tops[0], tops[1]);
    if a0.x > a1.x {
        std::mem::swap(&mut a0, &mut a1);
    }
    let crotch = tops[2..]
        .iter()
        .find(|t| t.x > a0.x && t.x < a1.x && t.y < a0.y.min(a1.y) - 2.0 * GAP_FRACTION * h)
        .copied()
        .ok_or_else(|| {
            SketchError::Segmentation("no crotch (gap top between the armpits) found".into())
        })?;
    // neck: narrowest single interval between armpits and top
    let ya = a0.y.max(a1.y);
    let d = yr[1] - ya;
    let width = |y: f64| -> Option<f64> {
        slice(front, y)
            .iter()
            .map(|iv| iv[1] - iv[0])
            .fold(None, |m: Option<f64>, w| Some(m.map_or(w, |v| v.max(w))))
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
            "no neck found above the armpits".into(),
        ));
    }
    let mut base = neck.1;
    let step = d / 400.0;
    while base - step > ya + 2.0 * GAP_FRACTION * h {
        match width(base - step) {
            Some(w) if w < NECK_FLARE * neck.0 => base -= step,
            _ => break,
        }
    }
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

/// Which slice interval belongs to a part at height y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pick {
    /// The interval whose centre lies in `(lo, hi)`; the widest if several.
    CentreIn(f64, f64),
}

/// A region of the outline: the part's slices between two heights.
#[derive(Clone, Debug)]
pub struct Region {
    pub name: String,
    pub y0: f64,
    pub y1: f64,
    pub pick: Pick,
    /// The part is traversed from y1 down to y0 (limbs hang from the join).
    pub downward: bool,
    /// Free (closed) end at the far side.
    pub tip: bool,
    /// A limb hanging from a shoulder: its top section is tilted up toward
    /// the outline's outer side (sign of the outward x direction).
    pub shoulder: Option<f64>,
    /// Which part of the side profile gives the region's depth.
    pub side: SidePick,
    /// Sections stay horizontal whatever the central curve's tilt (an
    /// animal's long body, whose slice centres drift with its two ends).
    pub horizontal: bool,
}

/// Which part of the side profile's slice gives a region's depth and its
/// centre's z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SidePick {
    /// Hidden in the side view (a humanoid's arms, an animal's tail): the
    /// sections stay circles.
    Hidden,
    /// The slice's whole extent (torso, head, legs of a humanoid).
    Whole,
    /// The widest slice interval whose centre z lies in `(lo, hi)` (one leg
    /// of an animal's pair, seen apart in the view from its front).
    CentreIn(f64, f64),
}

/// The interval of a region at height y.
pub fn interval(front: &[[f64; 2]], pick: Pick, y: f64) -> Option<[f64; 2]> {
    let Pick::CentreIn(lo, hi) = pick;
    slice(front, y)
        .into_iter()
        .filter(|iv| {
            let c = 0.5 * (iv[0] + iv[1]);
            c > lo && c < hi
        })
        .max_by(|a, b| (a[1] - a[0]).total_cmp(&(b[1] - b[0])))
}

/// The six regions of a standing humanoid; a limb starts at its cut when
/// `cuts` gives one ([`super::cuts`]), else a join band below its armpit or
/// the crotch.
pub fn regions(
    front: &[[f64; 2]],
    lm: &Landmarks,
    cuts: &JoinHeights,
) -> Result<Vec<Region>, SketchError> {
    let g = GAP_FRACTION * lm.height();
    let big = 1e3 * lm.height();
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
            pick: Pick::CentreIn(lm.armpit_l[0], lm.armpit_r[0]),
            downward: false,
            tip: true,
            shoulder: None,
            horizontal: false,
            side: SidePick::Whole,
        },
    ];
    for (name, lo, hi, top, shoulder) in [
        ("arm_l", -big, lm.armpit_l[0], lm.armpit_l[1], Some(-1.0)),
        ("arm_r", lm.armpit_r[0], big, lm.armpit_r[1], Some(1.0)),
        ("leg_l", lm.armpit_l[0], lm.crotch[0], lm.crotch[1], None),
        ("leg_r", lm.crotch[0], lm.armpit_r[0], lm.crotch[1], None),
    ] {
        let pick = Pick::CentreIn(lo, hi);
        let y1 = cuts.limb(name).unwrap_or(top - g);
        if interval(front, pick, y1).is_none() {
            return Err(SketchError::Segmentation(format!(
                "{name}: no outline below its join"
            )));
        }
        // lowest height where the region still has an interval
        let (mut a, mut b) = (lm.y_min - g, y1);
        let n = 400;
        let mut last = y1;
        for k in 1..=n {
            let y = y1 - (y1 - a) * k as f64 / n as f64;
            if interval(front, pick, y).is_none() {
                a = y;
                b = last;
                break;
            }
            last = y;
        }
        for _ in 0..40 {
            let m = 0.5 * (a + b);
            if interval(front, pick, m).is_some() {
                b = m;
            } else {
                a = m;
            }
        }
        out.push(Region {
            name: name.into(),
            y0: b,
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
    for r in &out {
        if (r.y1 - r.y0).partial_cmp(&(2.0 * g)) != Some(std::cmp::Ordering::Greater) {
            return Err(SketchError::Segmentation(format!(
                "{}: too short ({:.4} between {:.4} and {:.4})",
                r.name,
                r.y1 - r.y0,
                r.y0,
                r.y1
            )));
        }
    }
    Ok(out)
}

/// Height of the outline's top above x (for the shoulder seams).
pub fn shoulder_top(front: &[[f64; 2]], x: f64) -> Option<f64> {
    top_at(front, x)
}
