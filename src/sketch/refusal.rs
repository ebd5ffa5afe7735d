//! Refusals of a humanoid front outline's segmentation
//! ([`super::segment`]), in drawing terms: which landmark is where, and
//! what to draw differently.

use super::poly::{crotch_gap, GapTop};
use super::SketchError;

/// The arms leave the body at `ya`, too near the crotch at `crotch_y`: a
/// model of height `h` needs a torso longer than `least`
/// (`segment::torso_min`).
pub fn torso_too_short(ya: f64, crotch_y: f64, h: f64, least: f64) -> SketchError {
    SketchError::Segmentation(format!(
        "the torso is too short: the arms leave the body at y = {:.4}, {:.1} % of the height above the crotch (y = {:.4}); \
         it needs more than {:.2} %: draw the armpits higher (the arms leaving the body nearer the shoulders) or the crotch lower",
        ya,
        100.0 * (ya - crotch_y) / h,
        crotch_y,
        100.0 * least / h
    ))
}

/// The arm's join on `side` (-1 left, +1 right) of a model of height `h`
/// whose torso must be longer than `least` when going up from the crotch
/// finds no armpit (`g`: a join band, how far below the lower of two
/// tops [`crotch_gap`] compares their gaps): the highest gap top on that
/// side below the torso's least top, an arm whose gap with the body
/// closes at the hip or the thigh, or just above the crotch (a
/// big-headed figure's short torso). Gap tops of the crotch's own gap
/// (its repeats, a square or wavy crotch's corners) are not an arm's; a
/// gap between a leg and an arm hanging to the ground is. The same test
/// as the armpit scan's ([`crotch_gap`]).
pub fn low_armpit(
    front: &[[f64; 2]],
    tops: &[GapTop],
    crotch: GapTop,
    [least, g]: [f64; 2],
    side: f64,
) -> Option<GapTop> {
    tops.iter()
        .filter(|t| side * (t.x - crotch.x) > 0.0 && t.y <= crotch.y + least)
        .filter(|t| !crotch_gap(front, t, &crotch, g))
        .max_by(|a, b| a.y.total_cmp(&b.y))
        .copied()
}

/// The refusal of a humanoid whose `which` arm joins the body at `armpit`,
/// below the crotch or too near above it ([`torso_too_short`]), when its
/// upper body cannot be built as shells either
/// ([`super::humanoid_shells`]).
pub fn arm_too_low(
    armpit: [f64; 2],
    crotch: [f64; 2],
    h: f64,
    least: f64,
    which: &str,
) -> SketchError {
    if armpit[1] < crotch[1] {
        SketchError::Segmentation(format!(
            "the {which} arm's gap with the body closes at y = {:.4}, below the crotch (y = {:.4}): \
             an arm must leave the torso above the crotch; draw the {which} arm apart from the hip and leg up to its armpit",
            armpit[1], crotch[1]
        ))
    } else {
        torso_too_short(armpit[1], crotch[1], h, least)
    }
}
