//! The JSON report of a character built from its drawings: parts,
//! transitions, joins, creases, topology and the model's silhouettes against
//! the drawings (`crate::pipeline::build_document` builds, this measures).

use super::input::Outline;
use super::removed::BuiltRemoved;
use crate::character::assembly::{JoinReport, Model, SeamReport};
use crate::character::doc::{CharacterDoc, Level, PartSpec, SectionShape};
use crate::character::props::PropReport;
use crate::mesh::topology::{report as topology, TopologyReport};
use crate::mesh::Mesh;
use crate::profile::{profile_distance, View};
use serde::Serialize;

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
    /// transition (degrees; [`crate::character::crease`]).
    pub crease_deg: f64,
    /// Largest dihedral angle across its joins with the parts (degrees).
    pub join_crease_deg: f64,
    /// Length of its interior edges turning by more than
    /// [`crate::character::crease::CREASE_DEG`], relative to the model height.
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
    /// The model's unit (always `"m"`).
    pub unit: &'static str,
    /// The model's height in metres (the front outline's, after scaling).
    pub height_m: f64,
    pub height: f64,
    /// The drawing's size and placement ([`super::place`]).
    pub drawing: super::place::DrawingReport,
    /// Everything the build warns about (also printed on stderr by the
    /// CLI): a side view scaled to the front's height, a measure over its
    /// bound ([`super::quality`]).
    pub warnings: Vec<String>,
    /// Profile error, outside distance, dihedral and creased length per
    /// part and for the whole model ([`super::quality`]).
    pub quality: super::quality::Quality,
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
    /// When the build tried other derivations of the drawing (a model as
    /// shells) because the first missed issue 28's bounds: which it kept
    /// (`crate::pipeline::build`). None: the first, built alone.
    pub derivation: Option<DerivationReport>,
}

/// The models a build tried and the one it kept.
#[derive(Clone, Debug, Serialize)]
pub struct DerivationReport {
    /// The kept model's index in `excess` (0: the first model, stacked
    /// unless `first_shells`; more: a model as shells).
    pub kept: usize,
    /// Each tried model's excess over issue 28's bounds
    /// ([`super::quality::excess`]: the sum of each whole-model measure's
    /// excess over its bound, as a fraction of it), in the order tried;
    /// null: that model did not build.
    pub excess: Vec<Option<f64>>,
    /// Whether the first model is itself shells (a humanoid with no torso
    /// to build stacked: the arms cut at the shoulder points, then at the
    /// shoulders' corners) rather than stacked.
    pub first_shells: bool,
}

/// A removed part: a separate closed component, not stitched to the body.
#[derive(Clone, Debug, Serialize)]
pub struct RemovedReport {
    pub name: String,
    pub stitched: bool,
    /// Its silhouette against its own profiles.
    pub profile_error: Vec<ProfileErrorReport>,
}

fn shape_name(s: &SectionShape) -> &'static str {
    match s {
        SectionShape::Circle { r } if *r == 0.0 => "point",
        SectionShape::Circle { .. } => "circle",
        SectionShape::Ellipse { .. } => "ellipse",
        SectionShape::Gec { .. } => "gec",
    }
}

/// The report of a built document: `doc` with its derived (unedited)
/// parts, `edited` the parts with the log's spec-level edits applied,
/// `model` their model with every edit and prop, measured against the
/// drawings `front` and `side` (of model height `height`), the removed
/// parts built from their own profiles and the props' reports.
#[allow(clippy::too_many_arguments)]
pub fn report(
    doc: &CharacterDoc,
    edited: &[PartSpec],
    model: &Model,
    front: &Outline,
    side: Option<&Outline>,
    removed: &[BuiltRemoved],
    props: Vec<PropReport>,
    height: f64,
    drawing: super::place::DrawingReport,
    mut warnings: Vec<String>,
) -> SketchReport {
    let out = doc;
    let topo = topology(&model.mesh);
    let parts = part_reports(edited, model);
    let creases = crate::character::crease::creases(&model.mesh);
    let crease_of = |name: &str| creases.iter().find(|c| c.group == name);
    let part_crease_deg = edited
        .iter()
        .filter_map(|p| crease_of(&p.name))
        .map(|c| c.interior_deg)
        .fold(0.0, f64::max);
    let transitions = transition_reports(out, model, &creases, height);
    let max_c1 = model.joins.iter().map(|j| j.c1).fold(0.0, f64::max);
    let mut names: Vec<&str> = removed.iter().map(|r| r.spec.name.as_str()).collect();
    names.extend(props.iter().map(|p| p.name.as_str()));
    let body = without_groups(&model.mesh, &names);
    let outlines = super::quality::ModelOutlines::of(&body, side.is_some());
    let profile_error = profile_errors_with(&outlines, front, side, height);
    let removed_reports = removed_errors(&model.mesh, removed, height);
    let part_names: Vec<String> = edited
        .iter()
        .map(|p| p.name.clone())
        .filter(|n| !names.contains(&n.as_str()))
        .chain(out.transitions().iter().map(|t| t.name.clone()))
        .collect();
    let quality = super::quality::measure_with(
        &body,
        &outlines,
        &front.profile,
        side.map(|s| &s.profile),
        height,
        &part_names,
    );
    warnings.extend(super::quality::warnings(
        &quality,
        &super::quality::Bounds::ISSUE,
    ));
    SketchReport {
        level: out.level(),
        unit: "m",
        height_m: height,
        height,
        drawing,
        warnings,
        quality,
        parts,
        transitions,
        topology: topo,
        profile_error,
        max_c1,
        part_crease_deg,
        not_built: out
            .removed_parts()
            .iter()
            .filter(|r| !out.parts().iter().any(|p| p.name == r.name))
            .map(|r| r.name.clone())
            .collect(),
        removed: removed_reports,
        derivation: None,
        props,
    }
}

/// Each part's surface, sections and joins.
fn part_reports(edited: &[PartSpec], model: &Model) -> Vec<PartReport> {
    edited
        .iter()
        .map(|p| PartReport {
            name: p.name.clone(),
            surface: p.surface.describe(),
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
        .collect()
}

/// Each transition's surface, creases, joins and seams.
fn transition_reports(
    out: &CharacterDoc,
    model: &Model,
    creases: &[crate::character::crease::CreaseReport],
    height: f64,
) -> Vec<TransitionReport> {
    let crease_of = |name: &str| creases.iter().find(|c| c.group == name);
    out.transitions()
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
        .collect()
}

/// Profile error per given view: the model's silhouette
/// (`profile::outline_of_mesh`, default resolution) against the sketched
/// outline (`profile::profile_distance`: symmetric boundary distance), max
/// and RMS divided by the model height; a projection in separate pieces is
/// measured on its largest (`quality::model_outline`; the quality report
/// warns). A view whose silhouette cannot be extracted reports NaN (and
/// fails every threshold).
pub fn profile_errors(
    mesh: &Mesh,
    front: &Outline,
    side: Option<&Outline>,
    height: f64,
) -> Vec<ProfileErrorReport> {
    let outlines = super::quality::ModelOutlines::of(mesh, side.is_some());
    profile_errors_with(&outlines, front, side, height)
}

/// [`profile_errors`] with the model's outlines already taken.
pub fn profile_errors_with(
    outlines: &super::quality::ModelOutlines,
    front: &Outline,
    side: Option<&Outline>,
    height: f64,
) -> Vec<ProfileErrorReport> {
    let mut out = Vec::new();
    let views = [(View::Front, Some(front)), (View::Side, side)];
    for (view, o) in views {
        let Some(o) = o else { continue };
        let d = outlines
            .get(view)
            .map(|(model, _)| profile_distance(model, &o.profile))
            .map(|d| (d.max / height, d.rms / height))
            .unwrap_or((f64::NAN, f64::NAN));
        out.push(ProfileErrorReport {
            view: view.name(),
            max_rel: d.0,
            rms_rel: d.1,
        });
    }
    out
}

/// The mesh without the triangles of the named groups.
pub fn without_groups(mesh: &Mesh, names: &[&str]) -> Mesh {
    if names.is_empty() {
        return mesh.clone();
    }
    let keep: Vec<bool> = mesh
        .tri_group
        .iter()
        .map(|&g| !names.contains(&mesh.groups[g as usize].as_str()))
        .collect();
    mesh.filter_triangles(&keep).0
}

/// Each removed part's silhouette (its own group) against its profiles,
/// relative to the model height.
pub fn removed_errors(
    mesh: &Mesh,
    removed: &[super::removed::BuiltRemoved],
    height: f64,
) -> Vec<super::report::RemovedReport> {
    removed
        .iter()
        .map(|r| {
            let profile_error = match mesh.group_submesh(&r.spec.name) {
                Some((m, _)) => profile_errors(&m, &r.front, r.side.as_ref(), height),
                None => Vec::new(),
            };
            super::report::RemovedReport {
                name: r.spec.name.clone(),
                stitched: false,
                profile_error,
            }
        })
        .collect()
}
