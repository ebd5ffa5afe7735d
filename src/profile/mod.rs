//! Profiles: closed planar outlines of a character seen in one view (paper
//! 000 sec 4.1: the primary/front and secondary/side profiles of
//! sketch-guided modeling; sec 4.2: the template's profile curves).
//!
//! A [`Profile`] is a simple closed polygon, counter-clockwise in its own
//! 2D coordinates (horizontal, vertical), stored without a repeated closing
//! point. It comes from a sketch ([`read_svg`], [`read_json`]), from a mesh
//! ([`outline_of_mesh`]), or from code ([`Profile::new`]), and every source
//! goes through the same validation.
//!
//! # Coordinates and conventions
//!
//! Model coordinates are right-handed with y up. The 2D profile coordinates
//! of each [`View`] (see [`View::project`]):
//!
//! | view | horizontal | vertical | SVG x | SVG y |
//! |---|---|---|---|---|
//! | front | model x | model y | model x | -model y |
//! | side | model z | model y | model z | -model y |
//! | top | model x | model z | model x | model z |
//!
//! SVG input: [`parse_svg`] returns the outline in the document's **user
//! units** with every transform applied (groups, `transform` attributes,
//! nested `<svg>`) except the root `viewBox`; [`SvgSketch::units`] says how
//! many metres one user unit is, from the root's `width`/`height` and
//! `viewBox` ([`units`]), and [`SvgSketch::into_metres`] scales the sketch
//! to its physical size. Every command that reads a drawing (`sketch
//! build`, `template fit`, `template tbsm create`, `profile check`, the
//! TUI) reads it at its physical size in metres. In the front and side views model y = -(SVG y) (SVG y points
//! down); in the top view SVG y is model z (looking down on the character
//! from +y, +z, its front, toward the bottom of the page). Any path commands
//! and the basic shapes (`rect`, `circle`, `ellipse`, `polygon`, `polyline`,
//! `line`) are accepted; curves are flattened to within a given tolerance
//! (model units). A file holds **exactly one closed outline** (a shape whose
//! subpath is closed by `Z` or ends where it starts) plus any number of
//! **cuts**: paths, lines or polylines whose `id` starts with `cut`, kept as
//! open polylines in model coordinates ([`Cut`]). Errors: no closed shape
//! ([`ProfileError::NoOutline`]), an open shape that is not a cut
//! ([`ProfileError::OpenPath`], naming its id), several closed shapes
//! ([`ProfileError::SeveralOutlines`], naming their ids), a self-intersecting
//! outline ([`ProfileError::SelfIntersecting`]: the two segment indices and
//! the approximate location in model units). A page may hold several views,
//! each in a layer labelled with the view's name (`svg_layers`): reading a
//! view reads its layer only ([`ProfileError::NoViewLayer`] when the page
//! has view layers but not this one's, [`ProfileError::EmptyViewLayer`]
//! when its layer has no outline).
//!
//! JSON input: `{"view": "front", "points": [[h, v], ...]}` in profile
//! coordinates (unknown fields rejected).
//!
//! SVG output ([`to_svg`]): one closed `<path>` per profile, id = the view
//! name, stroke only, with a `viewBox` that fits; reading it back with
//! [`parse_svg`] gives the same profile up to f32 rounding (usvg parses in
//! f32).
//!
//! # Modules
//! - `polygon`: [`Profile`] and its validation and measures.
//! - `grid`: a uniform grid of segments (self-intersection test and distance
//!   queries in near-linear time).
//! - `distance`: [`profile_distance`], symmetric Hausdorff and RMS distance.
//! - `svg`, `json`: file input and output; `svg_layers`: the layers of a
//!   page holding several views.
//! - `outline`: the outline of a mesh's orthographic projection.
//! - `check`: the family's verification checks.

pub mod check;
mod coverage;
mod distance;
mod grid;
mod json;
mod outline;
mod polygon;
pub mod shapes;
mod svg;
mod svg_guard;
mod svg_layers;
mod svg_write;
pub mod units;

pub use distance::{profile_distance, ProfileDistance, ProfileIndex};
pub use json::{parse_json, read_json, to_json};
pub use outline::{outline_of_mesh, OutlineOptions, MAX_RESOLUTION};
pub use polygon::{boundary_distance, Profile};
pub use svg::{parse_svg, parse_svg_with, read_svg, read_svg_with, Cut, Flatness, SvgSketch};
pub use svg_guard::estimate_points;
pub use svg_layers::page_views;
pub use svg_write::{to_svg, to_svg_physical, write_svg};
pub use units::{document_units, DocumentUnits};

pub use crate::polygon::View;
use thiserror::Error;

/// Errors of profile construction, input and output.
#[derive(Debug, Error)]
pub enum ProfileError {
    #[error("point {index} of the profile has a non-finite coordinate")]
    NonFinite { index: usize },
    #[error("a profile needs at least 3 distinct points, got {count}")]
    TooFewPoints { count: usize },
    #[error("the profile has zero area (all points on a line)")]
    ZeroArea,
    #[error(
        "the profile intersects itself: segment {a} crosses segment {b} near ({:.6}, {:.6})",
        at[0],
        at[1]
    )]
    SelfIntersecting { a: usize, b: usize, at: [f64; 2] },
    #[error("path {id:?} is open: the outline must be closed (end it with Z), or name it cut... to make it a cut")]
    OpenPath { id: String },
    #[error("the SVG has no closed outline (one closed path, rect, circle, ellipse or polygon)")]
    NoOutline,
    #[error("the SVG has several closed outlines ({}), expected exactly one (a page holding several views: put each in its own layer, labelled front, side or top)", ids.join(", "))]
    SeveralOutlines { ids: Vec<String> },
    #[error("the page has view layers ({}) but none labelled {view}: draw the {view} view in a layer labelled {view}, or read a file that holds only it", layers.join(", "))]
    NoViewLayer { view: View, layers: Vec<String> },
    #[error("the layer {layer:?} has no closed outline: draw the {view} view's outline in it (one closed path)")]
    EmptyViewLayer { view: View, layer: String },
    #[error("SVG: {message}")]
    Svg { message: String },
    #[error("SVG root element's {attribute}=\"{value}\": {reason}")]
    DocumentSize {
        attribute: String,
        value: String,
        reason: String,
    },
    #[error("expected a {expected} profile, got a {found} one")]
    WrongView { expected: View, found: View },
    #[error("invalid parameter: {message}")]
    InvalidParameter { message: String },
    #[error(
        "the mesh's projection covers no sample at resolution {resolution} (thinner than a pixel?)"
    )]
    EmptyProjection { resolution: usize },
    #[error("mesh: {0}")]
    Mesh(#[from] crate::mesh::MeshError),
    #[error(
        "the mesh's projection has {count} separate parts; the largest but one covers {fraction:.3} of the largest (limit {limit})"
    )]
    Disconnected {
        count: usize,
        fraction: f64,
        limit: f64,
    },
    #[error("{path}: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{0}")]
    Input(crate::mesh::MeshError),
    #[error("{0}")]
    Limit(#[from] crate::limits::LimitError),
    #[error("{element}: attribute {attribute} holds {token:?}, {why}")]
    BadNumber {
        element: String,
        attribute: String,
        token: String,
        why: &'static str,
    },
    #[error("shape {id}: {message}")]
    Shape { id: String, message: String },
    #[error("path {id:?} is closed, but an id starting with `cut` marks a cut, an open polyline across a part; rename it if it is the outline")]
    ClosedCut { id: String },
    #[error("flattening the drawing at tolerance {} would give about {} points ({largest} alone {}), over the limit of {limit}; raise the tolerance or simplify the drawing", crate::limits::Num(*.tolerance), crate::limits::Num(*.estimate), crate::limits::Num(*.largest_estimate))]
    TooManyPoints {
        tolerance: f64,
        estimate: f64,
        largest: String,
        largest_estimate: f64,
        limit: u64,
    },
    #[error("the drawing is {} user units across ({what}), outside the range {} to {} user units: scale the drawing on the page (the model's size is the drawing's physical size, or give --height)", crate::limits::Num(*.size), crate::limits::Num(*.min), crate::limits::Num(*.max))]
    DrawingSize {
        size: f64,
        what: String,
        min: f64,
        max: f64,
    },
    #[error("{path}: invalid JSON profile: {source}")]
    Json {
        path: String,
        #[source]
        source: serde_json::Error,
    },
}
