//! What segmentation derives from the outlines ([`Derived`]: parts,
//! transitions, landmarks), shared by the humanoid (`sketch::derive`) and
//! the quadruped (`sketch::quadruped`), and the checks of the side view's
//! placement both run first.

use super::align::Alignment;
use super::quadruped::landmarks::QuadLandmarks;
use super::segment::Landmarks;
use super::SketchError;
use crate::character::doc::{BodyPlan, PartSpec, SectionShape, TransitionSpec};

/// Largest allowed side/front height mismatch (relative).
pub const HEIGHT_MISMATCH: f64 = 0.05;

/// The largest |cos| of a derived transition's cut on its parent's end
/// ring (the quadruped's cuts at its seam apexes, the humanoid's shoulders
/// at a wide neck): the child beside a cut keeps at least the ring's arc
/// within 18 degrees of its side. Not tuned: the quadruped's first bound,
/// kept for both.
pub const CUT_MAX_COS: f64 = 0.95;

/// The angle, in `[0, pi]`, of the end-ring point whose e1 coordinate is
/// `x` on a ring centred at `centre` with half width `half` along e1
/// (negative when e1 runs along -x), `|cos|` at most [`CUT_MAX_COS`].
pub(super) fn ring_angle(centre: f64, half: f64, x: f64) -> f64 {
    ((x - centre) / half)
        .clamp(-CUT_MAX_COS, CUT_MAX_COS)
        .acos()
}

/// A section's half width along its e1 (0 for a GEC, whose extent is not
/// one number).
pub(super) fn e1_half_width(shape: &SectionShape) -> f64 {
    match shape {
        SectionShape::Circle { r } => *r,
        SectionShape::Ellipse { a, .. } => *a,
        SectionShape::Gec { .. } => 0.0,
    }
}

/// Parts and transitions derived from the outlines.
#[derive(Clone, Debug)]
pub struct Derived {
    /// The body plan used (never `Auto`).
    pub plan: BodyPlan,
    /// The drawing's rotation from upright (identity when upright).
    pub alignment: Alignment,
    /// A humanoid's landmarks in the upright frame.
    pub landmarks: Option<Landmarks>,
    /// A quadruped's landmarks.
    pub quadruped: Option<QuadLandmarks>,
    pub parts: Vec<PartSpec>,
    pub transitions: Vec<TransitionSpec>,
    /// Seam apexes the transition fit may take instead of the derived
    /// ones (`sketch::apex`, `tangent_fit::fit_apexes`).
    pub apex_alternatives: Vec<ApexAlternative>,
    /// Other parts and transitions derived by another method, which the
    /// build measures beside these and keeps when they miss the issue's
    /// bounds by less (`pipeline::build`, [`super::quality::excess`]): an
    /// animal's body as shells (`quadruped::shells`).
    pub alternatives: Vec<(Vec<PartSpec>, Vec<TransitionSpec>)>,
    /// Whether `parts` are themselves shells (a humanoid with no torso to
    /// build stacked, `humanoid_shells::short_torso_models`).
    pub shells: bool,
}

impl Derived {
    /// A humanoid's upright derivation of `parts` and `transitions`
    /// found with `lm`: no apex alternatives, no alternatives, stacked.
    pub fn humanoid(lm: Landmarks, parts: Vec<PartSpec>, transitions: Vec<TransitionSpec>) -> Self {
        Derived {
            plan: BodyPlan::Humanoid,
            alignment: Alignment::identity(),
            landmarks: Some(lm),
            quadruped: None,
            parts,
            transitions,
            apex_alternatives: Vec::new(),
            alternatives: Vec::new(),
            shells: false,
        }
    }
}

/// A seam apex the transition fit tries beside the derived one.
#[derive(Clone, Debug, PartialEq)]
pub struct ApexAlternative {
    /// Index of the transition in `Derived::transitions`.
    pub transition: usize,
    /// Its seam (between children `seam` and `seam + 1`).
    pub seam: usize,
    pub apex: [f64; 3],
}

/// The side profile must be drawn at the front's heights: its lowest point
/// within [`HEIGHT_MISMATCH`] of the front's height from the front's (the
/// views share model y; a side drawn 5 m higher would be measured against
/// a model that is not there). Checked on the outlines as drawn.
pub(super) fn check_side_position(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
) -> Result<(), SketchError> {
    let Some(sd) = side else { return Ok(()) };
    let fy = crate::polygon::span(front, 1);
    let ys = crate::polygon::span(sd, 1);
    let shift = (ys[0] - fy[0]).abs() / (fy[1] - fy[0]);
    if shift > HEIGHT_MISMATCH {
        return Err(SketchError::Mismatch(format!(
            "the side profile spans model y {:.4} to {:.4}, the front {:.4} to {:.4}: draw both views at the same heights (their lowest points within {:.0} % of the height; they differ by {:.1} %)",
            ys[0],
            ys[1],
            fy[0],
            fy[1],
            100.0 * HEIGHT_MISMATCH,
            100.0 * shift
        )));
    }
    Ok(())
}

/// The side profile's height must match the front's within
/// [`HEIGHT_MISMATCH`].
pub(super) fn check_side_height(
    front_height: f64,
    side: Option<&[[f64; 2]]>,
) -> Result<(), SketchError> {
    if let Some(sd) = side {
        let ys = crate::polygon::span(sd, 1);
        let hs = ys[1] - ys[0];
        let rel = (hs - front_height).abs() / front_height;
        if rel > HEIGHT_MISMATCH {
            return Err(SketchError::Mismatch(format!(
                "side profile height {hs:.4} differs from the front height {front_height:.4} by {:.1} % (> {:.0} %)",
                100.0 * rel,
                100.0 * HEIGHT_MISMATCH
            )));
        }
    }
    Ok(())
}
