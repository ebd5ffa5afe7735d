//! The data of the SASM edits (paper 000 sec 5.3, Fig 10): strokes drawn
//! in a view, the sketch on the model and the auxiliary line. What they do
//! to a built part is `crate::sasm`.

use crate::profile::View;
use serde::{Deserialize, Serialize};

/// A stroke in one view, points in that view's profile coordinates.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stroke {
    pub view: View,
    pub points: Vec<[f64; 2]>,
}

/// Sketch on the model (Fig 10a): a closed stroke on `part` and one or two
/// profile strokes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SasmSpec {
    pub part: String,
    /// The closed outline of the feature on the part (last point equal to
    /// the first, within `crate::sasm::CLOSE_TOLERANCE` of its length).
    pub curve: Stroke,
    /// The feature's silhouette in one or two other views.
    pub profiles: Vec<Stroke>,
}

/// Auxiliary line (Fig 10b): one half of the interface, mirrored about the
/// vertical line `horizontal = mirror` of its view, plus the main profile.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AuxSpec {
    pub part: String,
    /// Open stroke from the axis (top) around to the axis (bottom).
    pub line: Stroke,
    /// Horizontal coordinate of the symmetry axis in the line's view.
    pub mirror: f64,
    pub profile: Stroke,
}
