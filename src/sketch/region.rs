//! A part's region of an outline: which slice interval belongs to it at
//! each height ([`Pick`], [`interval`]), how far down or up it reaches
//! ([`reach`]), and which part of the side view gives its depth
//! ([`SidePick`]). The vocabulary of the humanoid's segmentation
//! ([`super::segment`]) and the quadruped's.

use super::poly::slice;

/// Which slice interval belongs to a part at height y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pick {
    /// The interval whose centre lies in `(lo, hi)`; the widest if several.
    CentreIn(f64, f64),
    /// A leg beside the crotch: `Beside(x, side)` is the interval whose
    /// centre lies on `side` (-1 left, +1 right) of `x`, the nearest to
    /// `x` (an arm hanging beside a thin leg is farther out, and may be
    /// wider). Below the crotch the legs are apart down to the ground (a
    /// simple outline whose legs touched would enclose the gap above them:
    /// no crotch there).
    Beside(f64, f64),
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
    /// The slice's widest interval (torso, head, legs of a humanoid: a hand
    /// hanging apart in the side view is left out).
    Whole,
    /// The slice's extent from its first interval to its last (an animal's
    /// body seen head-on, where its legs are still apart at the belly).
    Span,
    /// The widest slice interval whose centre z lies in `(lo, hi)` (one leg
    /// of an animal's pair, seen apart in the view from its front).
    CentreIn(f64, f64),
    /// The widest slice interval clipped to `[lo, hi]` (one leg of a pair
    /// that a two-legged lateral view shows as one: where the head-on
    /// view has the pair apart, its own leg; where they merge into the
    /// body, the body's half on its side, so the depth runs on without a
    /// jump).
    Within(f64, f64),
}

/// The interval of a region at height y: of its [`candidates`], the
/// widest (`CentreIn`) or the nearest to the side's x (`Beside`).
pub fn interval(front: &[[f64; 2]], pick: Pick, y: f64) -> Option<[f64; 2]> {
    choose(pick, &candidates(front, pick, y))
}

/// Of a slice's admitted intervals `c` ([`candidates`]), the one `pick`
/// takes ([`interval`]).
pub fn choose(pick: Pick, c: &[[f64; 2]]) -> Option<[f64; 2]> {
    let widest = |a: &&[f64; 2], b: &&[f64; 2]| (a[1] - a[0]).total_cmp(&(b[1] - b[0]));
    let c = c.iter();
    match pick {
        Pick::CentreIn(..) => c.max_by(widest),
        Pick::Beside(x, _) => c.min_by(|a, b| {
            (0.5 * (a[0] + a[1]) - x)
                .abs()
                .total_cmp(&(0.5 * (b[0] + b[1]) - x).abs())
        }),
    }
    .copied()
}

/// The slice intervals at height y that `pick` admits: those centred
/// between its two x (`CentreIn`) or on its side of its x (`Beside`).
pub fn candidates(front: &[[f64; 2]], pick: Pick, y: f64) -> Vec<[f64; 2]> {
    let centre = |iv: &[f64; 2]| 0.5 * (iv[0] + iv[1]);
    slice(front, y)
        .into_iter()
        .filter(|iv| match pick {
            Pick::CentreIn(lo, hi) => centre(iv) > lo && centre(iv) < hi,
            Pick::Beside(x, side) => side * (centre(iv) - x) > 0.0,
        })
        .collect()
}

/// The farthest height from `from` toward `to` where the region still has
/// an interval (scan, then bisection).
pub(crate) fn reach(front: &[[f64; 2]], pick: Pick, from: f64, to: f64) -> f64 {
    let n = 400;
    let (mut out, mut inside) = (to, from);
    let mut last = from;
    for k in 1..=n {
        let y = from + (to - from) * k as f64 / n as f64;
        if interval(front, pick, y).is_none() {
            out = y;
            inside = last;
            break;
        }
        last = y;
    }
    for _ in 0..40 {
        let m = 0.5 * (out + inside);
        if interval(front, pick, m).is_some() {
            inside = m;
        } else {
            out = m;
        }
    }
    inside
}
