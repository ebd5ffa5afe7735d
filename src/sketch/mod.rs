//! Characters from sketches: sketch-guided global modeling in three stages
//! (paper 000 sec 4.1, Figs 5-6).
//!
//! 1. **Initial** (sec 4.1.1): the front outline is segmented into parts at
//!    its concave corners ([`segment`]: armpits, crotch, neck); each part gets
//!    a central curve and key sections placed where the profile's curvature
//!    changes, circles whose diameter is the outline's width there
//!    ([`derive`]); each part is a C2 sixth-order PDE chain through its
//!    sections (`character::part`, paper 002); parts are joined by transition
//!    surfaces built from the parts' boundary curves and tangents
//!    (`character::transition`).
//! 2. **Intermediate** (sec 4.1.2): with a side outline the sections become
//!    ellipses, the depth and the centre's z from the side view (not for the
//!    arms, hidden by the torso in the side view: they keep circles), and
//!    the key sections are re-placed from the curvature of both profiles.
//! 3. **Final** (sec 4.1.3): key cross-section sketches are fitted by GECs
//!    (`curve::gec`) and replace the section nearest their height
//!    ([`keysection`]).
//!
//! A drawing a few degrees off upright is segmented upright about its
//! principal axis and the result turned back ([`align`]); cuts drawn in the
//! front SVG (`cut*` paths) place the joins they cross ([`cuts`]).
//!
//! Removed parts (hair, a tail, ears) are built from their own profiles as
//! separate closed components, not stitched ([`removed`]).
//!
//! Four-legged animals (body plan quadruped, auto-detected from an outline
//! longer than tall) are segmented from their lateral silhouette in the
//! front file ([`quadruped`]).
//!
//! Simpler than the paper: the transitions are Hermite blends, cubic (C1,
//! the default) or quintic with the parts' second derivatives (C2, per
//! transition `continuity: c2`), not PDE surfaces; sibling transitions meet
//! G1 along their seams; the mesh's creases are measured
//! (`character::crease`);
//! only standing humanoids (arms away from the body, legs apart)
//! and quadrupeds with tail and neck rising above the back are segmented; a
//! cut only moves a join that the automatic segmentation finds (it cannot
//! add a part), and quadrupeds take no cuts.
//!
//! The whole model is one mesh (`character::assembly`, built by
//! `crate::pipeline`): every part and transition shares the vertices of the
//! rings and seams it meets, and orientation is made consistent and
//! outward; watertightness, manifoldness and orientation are measured by
//! `mesh::topology`, the join jumps by `character::measure` and the
//! profile error per view by [`report`].

pub mod align;
pub mod apex;
pub mod arm_cut;
pub mod arm_root;
pub mod check;
pub mod check_ode6;
pub mod corpus;
pub mod cuts;
pub mod derive;
mod derived;
pub mod figure;
pub mod figure_animal;
pub mod figure_params;
mod foot;
pub mod humanoid_shells;
pub mod input;
pub mod keysection;
pub mod limb;
pub mod overlay;
pub mod part_slices;
pub mod place;
pub mod poly;
pub mod quadruped;
pub mod quality;
pub mod refusal;
pub mod region;
pub mod removed;
pub mod report;
pub mod section_place;
pub mod segment;
mod shoulder_tilt;
pub mod tangent_fit;
pub mod thumb;
mod tube;
pub mod uncross;
mod vertex_grid;
pub mod walk;

pub use report::SketchReport;

/// Errors of sketch-based modeling.
#[derive(Debug, thiserror::Error)]
pub enum SketchError {
    #[error("{what}: {message}")]
    Outline { what: String, message: String },
    #[error("{path}: {message}")]
    File { path: String, message: String },
    #[error("segmentation: {0}")]
    Segmentation(String),
    #[error("profiles do not match: {0}")]
    Mismatch(String),
    #[error("cut '{id}': {message}")]
    Cut { id: String, message: String },
    #[error("key section: {0}")]
    Section(String),
    /// A key section's curve cannot be fitted (`section` names it).
    #[error("key section: {section}: {source}")]
    SectionFit {
        section: String,
        #[source]
        source: Box<crate::curve::gec::GecError>,
    },
    /// A key section's plane has no valid frame.
    #[error("key section: {0}")]
    SectionFrame(#[source] Box<crate::curve::gec::GecError>),
    #[error("part '{part}': {message}")]
    Part { part: String, message: String },
    /// A built mesh's vertex is not finite (`group`: its part, quoted, or
    /// `?`).
    #[error("document: the built mesh has a non-finite vertex {index} {position:?} in part {group}: a value of the document or an edit is too large for the part's surface")]
    NonFiniteVertex {
        index: usize,
        position: [f64; 3],
        group: String,
    },
    /// A build's report holds a non-finite number (`path` names its field).
    #[error("document: the build's report holds a non-finite number ({path} = {value}): the model is degenerate there (a collapsed or overflowing section?)")]
    NonFiniteReport { path: String, value: f64 },
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
    /// Assembling the parts into one model failed.
    #[error(transparent)]
    Model(#[from] crate::character::ModelError),
    /// A document that fails its own validation (its message already says
    /// "document: ...").
    #[error(transparent)]
    Doc(#[from] crate::character::doc::DocError),
}

impl SketchError {
    /// A key section (`section` names it) whose curve cannot be fitted.
    pub fn section_fit(section: String, e: crate::curve::gec::GecError) -> SketchError {
        SketchError::SectionFit {
            section,
            source: Box::new(e),
        }
    }
}
