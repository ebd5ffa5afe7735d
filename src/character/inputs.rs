//! The inputs of a character document and its errors: the level of
//! detail, the body plan, the drawings, key sections and removed parts
//! (`doc` re-exports them; `doc_ranges` checks them without naming the
//! document's own file).

use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// Current document version.
pub const VERSION: u32 = 1;

/// Errors reading or writing a document.
#[derive(Debug, thiserror::Error)]
pub enum DocError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: not a character document: {source}")]
    Parse {
        path: PathBuf,
        #[source]
        source: serde_json::Error,
    },
    #[error(
        "{path}: document version {found} is not supported (this build reads version {VERSION})"
    )]
    Version { path: PathBuf, found: u32 },
    #[error("document: {0}")]
    Invalid(String),
    /// An edit of the log has a parameter out of its range.
    #[error("document: edit {index}: {source}")]
    Edit {
        index: usize,
        #[source]
        source: Box<super::log::EditError>,
    },
    /// A prop fails its own checks.
    #[error("document: {0}")]
    Prop(#[from] super::props::PropError),
    /// The document cannot be written as JSON.
    #[error("document: cannot serialise: {0}")]
    Serialise(#[source] serde_json::Error),
    #[error("document field {field} = {value} is out of range: {expected}")]
    Range {
        field: String,
        value: String,
        expected: String,
    },
    #[error("{0}")]
    Write(#[from] crate::mesh::MeshError),
}

/// Modeling stage (paper 000 sec 4.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// Circles from the primary (front) profile.
    #[default]
    Initial,
    /// Ellipses from the front and side profiles.
    Intermediate,
    /// Key cross-section sketches fitted by GECs replace the ellipses there.
    Final,
}

impl std::str::FromStr for Level {
    type Err = String;
    fn from_str(s: &str) -> Result<Level, String> {
        match s {
            "initial" => Ok(Level::Initial),
            "intermediate" => Ok(Level::Intermediate),
            "final" => Ok(Level::Final),
            _ => Err(format!(
                "unknown level '{s}' (initial, intermediate, final)"
            )),
        }
    }
}

impl Level {
    /// Stable name.
    pub fn name(self) -> &'static str {
        match self {
            Level::Initial => "initial",
            Level::Intermediate => "intermediate",
            Level::Final => "final",
        }
    }
}

/// How the primary (front) outline is segmented into parts
/// (`sketch::segment` for a humanoid, `sketch::quadruped` for a
/// four-legged animal).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum BodyPlan {
    /// Decided from the outline: longer than tall (principal axis within 45
    /// degrees of horizontal) is a quadruped, else a humanoid.
    #[default]
    Auto,
    Humanoid,
    Quadruped,
}

impl std::str::FromStr for BodyPlan {
    type Err = String;
    fn from_str(s: &str) -> Result<BodyPlan, String> {
        match s {
            "auto" => Ok(BodyPlan::Auto),
            "humanoid" => Ok(BodyPlan::Humanoid),
            "quadruped" => Ok(BodyPlan::Quadruped),
            _ => Err(format!(
                "unknown body plan '{s}' (auto, humanoid, quadruped)"
            )),
        }
    }
}

impl BodyPlan {
    /// Stable name.
    pub fn name(self) -> &'static str {
        match self {
            BodyPlan::Auto => "auto",
            BodyPlan::Humanoid => "humanoid",
            BodyPlan::Quadruped => "quadruped",
        }
    }

    fn is_auto(&self) -> bool {
        *self == BodyPlan::Auto
    }
}

/// A profile given by file or inline.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
pub enum ProfileInput {
    /// An SVG (or JSON polyline) file, relative to the document.
    Path(String),
    /// The outline's points in model units (front: (x, y); side: (z, y)).
    Points(Vec<[f64; 2]>),
}

/// A key cross-section sketch: a closed curve in the horizontal plane at
/// height `y`, points as (x, z).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeySection {
    pub part: String,
    pub y: f64,
    pub points: Vec<[f64; 2]>,
}

/// The inputs a character is derived from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Inputs {
    pub front: ProfileInput,
    #[serde(default)]
    pub side: Option<ProfileInput>,
    #[serde(default)]
    pub sections: Vec<KeySection>,
    /// SVG flattening tolerance in metres of the drawing as drawn (None:
    /// 1/1000 of its height, `sketch::input::DEFAULT_FLATNESS`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// The model's height in metres: the drawing is scaled uniformly to it
    /// (None: the drawing's physical size, `sketch::place`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
    /// Humanoid or quadruped segmentation (default: decided from the front
    /// outline's shape).
    #[serde(default, skip_serializing_if = "BodyPlan::is_auto")]
    pub body_plan: BodyPlan,
}

/// A part removed from the main profile, to be modeled from its own
/// profiles (paper 000 sec 4.1). Recorded; not built in version 1.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RemovedPart {
    pub name: String,
    pub front: ProfileInput,
    #[serde(default)]
    pub side: Option<ProfileInput>,
}
