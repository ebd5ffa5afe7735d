//! From a character document to a model and its JSON report.

use super::build::{build_model_with, JoinReport, Model, PartCache, Resolution, SeamReport};
use super::derive::derive;
use super::input::{read_profile, Outline, ViewKind};
use super::SketchError;
use crate::character::doc::{CharacterDoc, Level, SectionShape};
use crate::mesh::topology::{report as topology, TopologyReport};
use serde::Serialize;
use std::path::Path;

/// One section in the report.
#[derive(Clone, Debug, Serialize)]
pub struct SectionReport {
    pub u: f64,
    pub centre: [f64; 3],
    pub shape: &'static str,
}

/// One part in the report.
#[derive(Clone, Debug, Serialize)]
pub struct PartReport {
    pub name: String,
    pub surface: String,
    pub sections: Vec<SectionReport>,
    pub closed_end: bool,
    pub joins: Vec<JoinReport>,
}

/// One transition in the report.
#[derive(Clone, Debug, Serialize)]
pub struct TransitionReport {
    pub name: String,
    pub parent: String,
    pub children: Vec<String>,
    pub surface: &'static str,
    pub joins: Vec<JoinReport>,
    pub seams: Vec<SeamReport>,
    /// Largest dihedral angle between adjacent triangles inside the
    /// transition (degrees; [`super::crease`]).
    pub crease_deg: f64,
    /// Largest dihedral angle across its joins with the parts (degrees).
    pub join_crease_deg: f64,
    /// Length of its interior edges turning by more than
    /// [`super::crease::CREASE_DEG`], relative to the model height.
    pub creased_length_rel: f64,
}

/// Model silhouette against a sketched profile, relative to model height.
#[derive(Clone, Debug, Serialize)]
pub struct ProfileErrorReport {
    pub view: &'static str,
    pub max_rel: f64,
    pub rms_rel: f64,
}

/// The JSON report of a build.
#[derive(Clone, Debug, Serialize)]
pub struct SketchReport {
    pub level: Level,
    pub height: f64,
    pub parts: Vec<PartReport>,
    pub transitions: Vec<TransitionReport>,
    pub topology: TopologyReport,
    pub profile_error: Vec<ProfileErrorReport>,
    /// Largest C1 jump of any transition join (relative).
    pub max_c1: f64,
    /// Largest dihedral angle inside any part (degrees): the level a smooth
    /// transition's `crease_deg` is read against.
    pub part_crease_deg: f64,
    /// Removed parts recorded in the document and not built.
    pub not_built: Vec<String>,
    /// Removed parts built from their own profiles ([`super::removed`]).
    pub removed: Vec<RemovedReport>,
    /// Props composed as separate components (`character::props`).
    pub props: Vec<crate::character::props::PropReport>,
}

/// A removed part: a separate closed component, not stitched to the body.
#[derive(Clone, Debug, Serialize)]
pub struct RemovedReport {
    pub name: String,
    pub stitched: bool,
    /// Its silhouette against its own profiles.
    pub profile_error: Vec<ProfileErrorReport>,
}

/// Everything a build produces.
#[derive(Clone, Debug)]
pub struct Built {
    /// The document with its derived parts and transitions filled in.
    pub doc: CharacterDoc,
    pub model: Model,
    pub report: SketchReport,
    pub front: Outline,
    pub side: Option<Outline>,
}

fn shape_name(s: &SectionShape) -> &'static str {
    match s {
        SectionShape::Circle { r } if *r == 0.0 => "point",
        SectionShape::Circle { .. } => "circle",
        SectionShape::Ellipse { .. } => "ellipse",
        SectionShape::Gec { .. } => "gec",
    }
}

/// Builds a document: reads its profiles (relative to `base`), derives the
/// parts and transitions when the document has none, replays the active
/// edits of its log (`character::edit`), builds the mesh and measures it.
/// `rederive` forces derivation from the inputs. `Built::doc` holds the
/// derived, unedited parts and the log; the report describes the edited
/// parts.
pub fn build_document(
    doc: &CharacterDoc,
    base: &Path,
    res: Resolution,
    rederive: bool,
) -> Result<Built, SketchError> {
    build_document_with(doc, base, res, rederive, None)
}

/// [`build_document`] with an optional cache of built parts (an editing
/// session re-solves only the parts an edit changed; the result is the same
/// bit for bit).
pub fn build_document_with(
    doc: &CharacterDoc,
    base: &Path,
    res: Resolution,
    rederive: bool,
    cache: Option<&mut PartCache>,
) -> Result<Built, SketchError> {
    doc.validate()?;
    let tol = doc.inputs.tolerance;
    let front = read_profile(&doc.inputs.front, base, ViewKind::Front, tol)?;
    let side = match &doc.inputs.side {
        Some(s) => Some(read_profile(s, base, ViewKind::Side, tol)?),
        None => None,
    };
    if doc.level != Level::Initial && side.is_none() {
        return Err(SketchError::Document(format!(
            "level {} needs a side profile",
            doc.level.name()
        )));
    }
    if doc.level == Level::Final && doc.inputs.sections.is_empty() {
        return Err(SketchError::Document(
            "level final needs key cross-section sketches".into(),
        ));
    }
    let removed = doc
        .removed_parts
        .iter()
        .map(|r| super::removed::removed_part(r, base, tol))
        .collect::<Result<Vec<_>, _>>()?;
    let mut out = doc.clone();
    let (yr, _) = super::poly::bounds(&front.points);
    let height = yr[1] - yr[0];
    if rederive || doc.parts.is_empty() {
        let d = derive(
            &front.points,
            side.as_ref().map(|s| s.points.as_slice()),
            &doc.inputs.sections,
            &front.cuts,
            doc.level,
            doc.inputs.body_plan,
        )?;
        out.parts = d.parts;
        out.parts.extend(removed.iter().map(|r| r.spec.clone()));
        out.transitions = d.transitions;
    }
    // replay the edit log on a copy: `out` keeps the unedited parts and the
    // log, so saving it and building again never applies an edit twice
    // PDE-level edits change the parts (spec edits) or add displacements
    // (forces); mesh-level edits (plate, SASM) then act on the built mesh,
    // in log order
    let active = out.active_edits();
    let edit_err = |e: crate::character::edit::EditError| SketchError::Document(e.to_string());
    crate::character::edit::check_order(&out.transitions, active).map_err(edit_err)?;
    let edited = crate::character::edit::apply_to_parts(&out.parts, active).map_err(edit_err)?;
    let disp = crate::character::edit::displacements(active).map_err(edit_err)?;
    let mut model = build_model_with(&edited, &out.transitions, height, res, &disp, cache)?;
    crate::character::edit::apply_mesh_edits(&mut model.mesh, &model.parts, active)
        .map_err(edit_err)?;
    let props =
        crate::character::props::compose(&mut model.mesh, &doc.props, base, res.rings_per_height)
            .map_err(|e| SketchError::Document(e.to_string()))?;
    let topo = topology(&model.mesh);
    let parts = edited
        .iter()
        .map(|p| PartReport {
            name: p.name.clone(),
            surface: match p.surface {
                crate::character::doc::SurfaceSpec::Pde6C2 { a } => {
                    format!("pde6 C2 chain (a = {a})")
                }
            },
            sections: p
                .sections
                .iter()
                .map(|s| SectionReport {
                    u: s.u,
                    centre: s.centre,
                    shape: shape_name(&s.shape),
                })
                .collect(),
            closed_end: p.closed_end,
            joins: model
                .joins
                .iter()
                .filter(|j| j.part == p.name)
                .cloned()
                .collect(),
        })
        .collect();
    let creases = super::crease::creases(&model.mesh);
    let crease_of = |name: &str| creases.iter().find(|c| c.group == name);
    let part_crease_deg = edited
        .iter()
        .filter_map(|p| crease_of(&p.name))
        .map(|c| c.interior_deg)
        .fold(0.0, f64::max);
    let transitions = out
        .transitions
        .iter()
        .map(|t| TransitionReport {
            crease_deg: crease_of(&t.name).map_or(0.0, |c| c.interior_deg),
            join_crease_deg: crease_of(&t.name).map_or(0.0, |c| c.border_deg),
            creased_length_rel: crease_of(&t.name).map_or(0.0, |c| c.creased_length / height),
            name: t.name.clone(),
            parent: t.parent.clone(),
            children: t.children.clone(),
            surface: match t.continuity {
                crate::character::doc::Continuity::C1 => "cubic Hermite blend (C1 to the parts)",
                crate::character::doc::Continuity::C2 => "quintic Hermite blend (C2 to the parts)",
            },
            joins: model
                .joins
                .iter()
                .filter(|j| j.transition == t.name)
                .cloned()
                .collect(),
            seams: model
                .seams
                .iter()
                .filter(|s| s.transition == t.name)
                .cloned()
                .collect(),
        })
        .collect();
    let max_c1 = model.joins.iter().map(|j| j.c1).fold(0.0, f64::max);
    let mut names: Vec<&str> = removed.iter().map(|r| r.spec.name.as_str()).collect();
    names.extend(props.iter().map(|p| p.name.as_str()));
    let body = super::check::without_groups(&model.mesh, &names);
    let profile_error = super::check::profile_errors(&body, &front, side.as_ref(), height);
    let removed_reports = super::check::removed_errors(&model.mesh, &removed, height);
    let report = SketchReport {
        level: out.level,
        height,
        parts,
        transitions,
        topology: topo,
        profile_error,
        max_c1,
        part_crease_deg,
        not_built: out
            .removed_parts
            .iter()
            .filter(|r| !out.parts.iter().any(|p| p.name == r.name))
            .map(|r| r.name.clone())
            .collect(),
        removed: removed_reports,
        props,
    };
    crate::character::edit::effect::finite_result(&model.mesh, &report)?;
    Ok(Built {
        doc: out,
        model,
        report,
        front,
        side,
    })
}
