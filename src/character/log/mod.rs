//! The edit log of a character document: local modeling as undoable edits
//! (paper 000 sec 5; paper 001 for the mesh-level plate edit). This module
//! holds what an edit *is* (its data, its own parameter checks, the order
//! rule of the log, undo and redo); applying edits is `crate::edit` (part
//! surfaces, forces, plates) and `crate::sasm` (features), and replaying
//! the log is `crate::pipeline`.
//!
//! A character is its inputs plus an ordered edit log: `doc.edits()`, of which
//! the first `doc.cursor()` are active. `CharacterDoc::push_edit` (`crate::pipeline`) validates
//! an edit against the document's current state (the stored parts with the
//! active edits applied) *before* changing anything, drops the redo tail and
//! appends; [`CharacterDoc::undo`] / [`CharacterDoc::redo`] move the cursor.
//! `pipeline::build` replays the active edits in order after deriving
//! or reading the parts, so the same document always gives the same mesh,
//! bit for bit. The stored `parts` are never rewritten by an edit: the log is
//! the only record of a change (saving a built document keeps the log and the
//! unedited parts, so replay never applies an edit twice).
//!
//! # Edits
//!
//! * [`Edit::ShapeParameter`] (PDESM, sec 5.1, Fig 8): the part's PDE
//!   parameter `a` (the pde6 C2 chain's `w_uuuuuu + a w_vvvvvv = 0`),
//!   accepted in the family's documented range `|a| <=` [`pde6::A_MAX`];
//!   the solver's conditioning guard is run at push time.
//! * [`Edit::GecTransform`] (GECDSM, sec 5.2, Fig 9): a coefficient-space
//!   transform ([`SectionTransform`], `curve::gec::transform`) of one key
//!   section or of all sections of a part; circles and ellipses are first
//!   converted to GEC coefficients in their frame (exactly: same curve).
//!   Sections keep their parameter `u`, so the part surface, linear in its
//!   section data harmonic by harmonic, undergoes the same transform: a
//!   translation of all sections translates the surface; an in-plane scale or
//!   rotation of all sections about their centres, when the sections' frames
//!   are parallel, scales or rotates every ring of the surface about the
//!   surface's centre curve (harmonic 0). Checked in `verify` family `edit`.
//! * [`Edit::Force`] (PDESM sculpting force, sec 5.1, Fig 8): how a force
//!   acts on a pde6 C2 chain part: the paper's pde4 2-sided patch over a
//!   u-range of the part (concentrated, line, area or uniform force in the
//!   patch's coordinates; shape parameters `a1 = 1, a2 = 2a^2, a3 = a^4`),
//!   clamped at both range ends, is *added to the part as a displacement*.
//!   It vanishes with its u-derivative at the range ends, so the part stays
//!   in place and C1 there, and the part's ends (where transitions join)
//!   never move. The chain is not re-solved.
//! * [`Edit::ForceRegion`] (PDESM 4-sided force, sec 5.1, eqs 10-15): the
//!   pde4 4-sided patch inside the closed curve bounding a rectangle
//!   `[u_a, u_b] x [theta_a, theta_b]` of the part's parameter space,
//!   clamped on all four edges, added to the part as a displacement that
//!   vanishes with its first derivatives on the curve (`crate::edit::force4`).
//! * [`Edit::ForceStroke`] (the same inside a closed stroke of any simple
//!   shape on the part): the stroke's inside is mapped onto the unit square
//!   by a mean value map, fold-checked ([`stroke`]), and the 4-sided patch
//!   is evaluated there: zero outside the stroke, C1 across it.
//! * [`Edit::Boundary`] (PDESM boundary curves and tangents, sec 5.1): a new
//!   boundary curve is a new end section (the transition at that end is
//!   rebuilt from it); a boundary tangent change moves the sections within
//!   reach of the end by `t (u - u_e)(1 - |u - u_e|/L)^3 / r`, `r` the
//!   solved chain's measured (linear) response, so the end tangent changes
//!   by exactly `t` and the end curve stays. Why not the pde4 non-zero
//!   boundary solution: a part is one C2 chain, not a 2-sided pde4 patch;
//!   changing it through its sections keeps the transitions C1.
//! * [`Edit::Plate`] (paper 001, the mesh level of 000 Fig 12): the C1
//!   plate bending of a region of the built mesh.
//! * [`Edit::Sasm`], [`Edit::SasmAux`] (000 sec 5.3): a feature grown on
//!   the built mesh (`crate::sasm`).
//!
//! # Order
//! The log is applied in order: PDE-level edits to the part surfaces (the
//! mesh is then built from them), mesh-level edits (plate, SASM) to the
//! built mesh, interleaved as the log has them (`crate::pipeline::apply_mesh_edits`; a
//! SASM feature adds its height to the mesh as it is, keeping an earlier
//! plate or force). A PDE-level edit after a mesh-level edit of the same
//! part (or of a child of a transition it belongs to) would rebuild the
//! mesh under that edit: [`check_order`] refuses such a log when the edit is
//! pushed (and when a hand-written document is built).
//!
//! Every edit names its target part ([`Edit::part`]) and validates its
//! parameters: finite numbers, ranges named in [`EditError::Parameter`], a
//! section that would self-intersect after a transform
//! ([`EditError::SelfIntersecting`]), a part whose chain would not solve
//! ([`EditError::Build`]).

pub mod stroke;
mod strokes;
mod summary;
mod validate;

pub use strokes::{AuxSpec, SasmSpec, Stroke};
pub use validate::{
    param, stroke_map, validate_params, A_FORCE_MAX, A_FORCE_MIN, THETA_SPAN_MAX, THETA_SPAN_MIN,
};

use crate::character::spec::{End, PartSpec, SectionShape};
use serde::{Deserialize, Serialize};

/// One edit of the log.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum Edit {
    /// PDESM shape parameter: the part's surface parameter `a`.
    ShapeParameter { part: String, a: f64 },
    /// GECDSM: a coefficient-space transform of the part's key section
    /// `section` (index in the part's section list), or of every section when
    /// `section` is absent.
    GecTransform {
        part: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        section: Option<usize>,
        transform: SectionTransform,
    },
    /// PDESM sculpting force (sec 5.1): the pde4 2-sided patch over the part
    /// parameter range `u = [u_a, u_b]` (inside the part), clamped at both
    /// ends of the range, with `force` in patch coordinates (`u` in `[0, 1]`
    /// across the range, `v = theta / 2 pi`) and uniform shape parameters
    /// `a` (default 1); its solution is added to the part as a displacement.
    Force {
        part: String,
        u: [f64; 2],
        force: crate::pde4::Force,
        #[serde(default = "one")]
        a: f64,
    },
    /// PDESM 4-sided sculpting force (sec 5.1, eqs 10-15): the pde4
    /// 4-sided patch inside the closed curve bounding the part-parameter
    /// rectangle `u = [u_a, u_b]` (inside the part) by `theta = [theta_a,
    /// theta_b]` (radians, `0 < theta_b - theta_a <= 2 pi`), clamped on the
    /// whole curve, with `force` in patch coordinates (`s` across the u
    /// range, `v` across the angle range, both in `[0, 1]`) and shape
    /// parameters `a` (default 1); its solution is added to the part as a
    /// displacement, zero outside the curve (`crate::edit::force4`).
    ForceRegion {
        part: String,
        u: [f64; 2],
        theta: [f64; 2],
        force: crate::pde4::Force,
        #[serde(default = "one")]
        a: f64,
    },
    /// PDESM 4-sided sculpting force inside a closed stroke of any simple
    /// shape (sec 5.1): `stroke` is the closed curve as points `(u, theta)`
    /// of the part's parameters (the last point returns to the first; angles
    /// in radians, spanning less than the ring), inside the part's u range;
    /// `corners` (optional) are four indices into `stroke`, in order along
    /// it, where the curve is split into the patch's four sides (default:
    /// its extreme points towards the bounding box's corners). The pde4
    /// 4-sided patch of `force` (patch coordinates as for `force_region`)
    /// and shape parameters `a` (default 1), mapped onto the stroke's inside
    /// by a mean value map ([`stroke`]), is added to the part as a
    /// displacement: zero outside the stroke, C1 across it.
    ForceStroke {
        part: String,
        stroke: Vec<[f64; 2]>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        corners: Option<[usize; 4]>,
        force: crate::pde4::Force,
        #[serde(default = "one")]
        a: f64,
    },
    /// PDESM boundary change (sec 5.1) at one end of a part: a new boundary
    /// `curve` (the end section's shape, in its frame) and/or a change
    /// `tangent` of the end's u-tangent (model units per unit u), made by
    /// moving the sections within `reach` (a fraction of the part's length,
    /// default 0.3) of that end so that the solved chain's end tangent
    /// changes by exactly `tangent` while the end curve stays in place.
    Boundary {
        part: String,
        end: End,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        curve: Option<SectionShape>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        tangent: Option<[f64; 3]>,
        #[serde(default = "default_reach")]
        reach: f64,
    },
    /// Mesh-level C1 plate bending (paper 001) on the built mesh: the region
    /// is the part's vertices within `radius` of `centre`, bent as a clamped
    /// plate so that its peak displacement is `d` (the cursor motion).
    /// Applied to the built mesh, in log order with the SASM edits.
    Plate {
        part: String,
        centre: [f64; 3],
        radius: f64,
        d: [f64; 3],
    },
    /// SASM sketch on the model (000 sec 5.3, Fig 10a): a closed stroke on
    /// the part plus one or two profile strokes grow a feature inside the
    /// curve (`crate::sasm`; applied to the built mesh, in log order with
    /// the plate edits).
    Sasm(SasmSpec),
    /// SASM auxiliary line (Fig 10b): half an interface, mirrored, plus the
    /// main profile (`crate::sasm::AuxSpec`).
    SasmAux(AuxSpec),
}

fn one() -> f64 {
    1.0
}

fn default_reach() -> f64 {
    0.3
}

/// A GEC coefficient-space transform (paper 000 sec 5.2).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SectionTransform {
    /// Move by `d` (model units).
    Translate { d: [f64; 3] },
    /// Scale by `sx` along the section's `e1` and `sy` along `e2` about the
    /// section's centre; factors in `(0, SCALE_MAX]`.
    Scale { sx: f64, sy: f64 },
    /// Rotate in the section's plane by `angle` radians about its centre.
    Rotate { angle: f64 },
    /// Bend deformer (`curve::gec::transform::Bend`): pivot at the part's
    /// first section centre, direction from the first to the last section
    /// centre, bending about `axis` (made orthogonal to the direction) with
    /// curvature `kappa` (1/model units, `|kappa| * part length <= pi`);
    /// each section moves rigidly with the deformer at its centre.
    Bend { kappa: f64, axis: [f64; 3] },
    /// A local bump of height `h` (model units) at in-plane angle `theta`
    /// (radians, from `e1` towards `e2`) of angular width `sigma` in
    /// `(0, SIGMA_MAX]`.
    Bump { h: f64, theta: f64, sigma: f64 },
}

/// Largest scale factor of [`SectionTransform::Scale`].
pub const SCALE_MAX: f64 = 100.0;
/// Largest bump width of [`SectionTransform::Bump`].
pub const SIGMA_MAX: f64 = 10.0;
/// Samples of a section when testing it for self-intersection.
pub const SECTION_SAMPLES: usize = 256;

/// Errors of edits.
#[derive(Debug, thiserror::Error)]
pub enum EditError {
    #[error("unknown part '{part}' (the document's parts: {known})")]
    UnknownPart { part: String, known: String },
    #[error("the document has no parts yet: derive and store them first (`pdesculpt character build CHAR.json -o OUT --save-doc CHAR.json`)")]
    NoParts,
    #[error("part '{part}': section {section} does not exist (the part has {count} sections)")]
    NoSection {
        part: String,
        section: usize,
        count: usize,
    },
    #[error("{op} on part '{part}': {name} = {} is out of range: {expected}", crate::limits::Num(*.value))]
    Parameter {
        op: &'static str,
        part: String,
        name: &'static str,
        value: f64,
        expected: String,
    },
    #[error("{op} on part '{part}': section {section} would self-intersect (edges {first} and {second} of {SECTION_SAMPLES} samples cross)")]
    SelfIntersecting {
        op: &'static str,
        part: String,
        section: usize,
        first: usize,
        second: usize,
    },
    #[error("{op} on part '{part}': section {section}: {source}")]
    Section {
        op: &'static str,
        part: String,
        section: usize,
        #[source]
        source: Box<crate::curve::gec::GecError>,
    },
    #[error("{op} on part '{part}': {what}: {source}")]
    Patch {
        op: &'static str,
        part: String,
        /// Which patch: the 2-sided or the 4-sided force patch.
        what: &'static str,
        #[source]
        source: Box<crate::pde4::Pde4Error>,
    },
    #[error("{op} on part '{part}': {message}")]
    Invalid {
        op: &'static str,
        part: String,
        message: String,
    },
    #[error("{op} on part '{part}': the edited part does not build: {source}")]
    Build {
        op: &'static str,
        part: String,
        #[source]
        source: crate::character::ModelError,
    },
    #[error("edit {index} ({summary}) changes the PDE surface of part '{part}' after edit {earlier} ({earlier_summary}) changed its built mesh: a PDE-level edit rebuilds the mesh of its part (and of the children of its transitions), so it cannot follow a mesh-level edit (plate, sasm) there; undo the mesh-level edit first")]
    Order {
        index: usize,
        summary: String,
        part: String,
        earlier: usize,
        earlier_summary: String,
    },
    #[error("nothing to undo (the cursor is at the start of the log)")]
    NothingToUndo,
    #[error("nothing to redo (the cursor is at the end of the log, {len} edits)")]
    NothingToRedo { len: usize },
    #[error("edit {index} of the log ({summary}): {source}")]
    Replay {
        index: usize,
        summary: String,
        source: Box<EditError>,
    },
}

impl Edit {
    /// The target part, if any.
    pub fn part(&self) -> Option<&str> {
        match self {
            Edit::ShapeParameter { part, .. }
            | Edit::GecTransform { part, .. }
            | Edit::Force { part, .. }
            | Edit::ForceRegion { part, .. }
            | Edit::ForceStroke { part, .. }
            | Edit::Boundary { part, .. }
            | Edit::Plate { part, .. } => Some(part),
            Edit::Sasm(s) => Some(&s.part),
            Edit::SasmAux(s) => Some(&s.part),
        }
    }

    /// Whether the edit acts on the built mesh (plate, SASM) rather than on
    /// the part's PDE surface.
    pub fn mesh_level(&self) -> bool {
        matches!(self, Edit::Plate { .. } | Edit::Sasm(_) | Edit::SasmAux(_))
    }

    /// The operation's name (the `op` tag).
    pub fn op(&self) -> &'static str {
        match self {
            Edit::ShapeParameter { .. } => "shape_parameter",
            Edit::GecTransform { .. } => "gec_transform",
            Edit::Force { .. } => "force",
            Edit::ForceRegion { .. } => "force_region",
            Edit::ForceStroke { .. } => "force_stroke",
            Edit::Boundary { .. } => "boundary",
            Edit::Plate { .. } => "plate",
            Edit::Sasm(_) => "sasm",
            Edit::SasmAux(_) => "sasm_aux",
        }
    }
}

fn known_parts(parts: &[PartSpec]) -> String {
    parts
        .iter()
        .map(|p| p.name.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Refuses a log whose order cannot be honoured: the log is applied in
/// order, except that every PDE-level edit (shape parameter, GEC
/// transform, force, boundary) is applied to the part surfaces before the
/// mesh is built and the mesh-level edits (plate, SASM) act on it in log
/// order. That equals applying the whole log in order as long as no
/// PDE-level edit follows a mesh-level edit of a part whose built mesh it
/// changes (the same part, or a child of a transition whose parent or
/// another child it edits); such a log is refused.
pub fn check_order(
    transitions: &[crate::character::spec::TransitionSpec],
    edits: &[Edit],
) -> Result<(), EditError> {
    // the mesh of part `q` depends on part `p`'s surface when they are the
    // same, or `q` is a child of a transition whose parent or another
    // child is `p` (a child's ring sampling follows its parent and the
    // seams between siblings; a parent's does not follow its children)
    let touches = |p: &str, q: &str| {
        p == q
            || transitions.iter().any(|t| {
                t.children.iter().any(|c| c == q)
                    && (t.parent == p || t.children.iter().any(|c| c == p))
            })
    };
    for (i, e) in edits.iter().enumerate() {
        if e.mesh_level() {
            continue;
        }
        let Some(p) = e.part() else { continue };
        if let Some(j) = edits[..i]
            .iter()
            .position(|m| m.mesh_level() && m.part().is_some_and(|q| touches(p, q)))
        {
            return Err(EditError::Order {
                index: i,
                summary: e.summary(),
                part: p.into(),
                earlier: j,
                earlier_summary: edits[j].summary(),
            });
        }
    }
    Ok(())
}

pub(crate) fn unknown_part(parts: &[PartSpec], part: &str) -> EditError {
    EditError::UnknownPart {
        part: part.into(),
        known: known_parts(parts),
    }
}
