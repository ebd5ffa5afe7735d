//! Refusals of a humanoid front outline's segmentation
//! ([`super::segment`]), in drawing terms: which landmark is where, and
//! what to draw differently.

use super::poly::{same_gap, GapTop};
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

/// When no armpit is found on `side` (-1 left, +1 right) of a model of
/// height `h` whose torso must be longer than `least` (`g`: a join band,
/// the depth [`same_gap`] looks below two tops): the highest gap
/// top on that side below the torso's least top (an arm whose gap with
/// the body closes at the hip or the thigh, or just above the crotch)
/// names the drawing's problem. Gap tops of the crotch's own gap (its
/// repeats, a square crotch's corners) are not an arm's; a gap between a
/// leg and an arm hanging to the ground is.
pub fn arm_too_low(
    front: &[[f64; 2]],
    tops: &[GapTop],
    crotch: GapTop,
    [h, least, g]: [f64; 3],
    side: f64,
) -> Option<SketchError> {
    let which = if side < 0.0 { "left" } else { "right" };
    let t = tops
        .iter()
        .filter(|t| side * (t.x - crotch.x) > 0.0 && t.y <= crotch.y + least)
        .filter(|t| !same_gap(front, **t, crotch, g))
        .max_by(|a, b| a.y.total_cmp(&b.y))?;
    Some(if t.y < crotch.y {
        SketchError::Segmentation(format!(
            "the {which} arm's gap with the body closes at y = {:.4}, below the crotch (y = {:.4}): \
             an arm must leave the torso above the crotch; draw the {which} arm apart from the hip and leg up to its armpit",
            t.y, crotch.y
        ))
    } else {
        torso_too_short(t.y, crotch.y, h, least)
    })
}
