//! Document -> model: a character document's drawings read, its parts
//! derived when it has none, its edit log replayed, its parts and
//! transitions assembled into one mesh, its props composed, and the result
//! measured.

use crate::character::assembly::{build_model_with, Model, PartCache};
use crate::character::doc::{CharacterDoc, Level};
use crate::character::log::{Edit, EditError};
use crate::character::part::PartSurface;
use crate::character::Resolution;
use crate::mesh::Mesh;
use crate::sketch::derive::derive;
use crate::sketch::input::{read_profile, Outline, ViewKind};
use crate::sketch::report::SketchReport;
use crate::sketch::SketchError;
use std::path::Path;

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

/// Builds a document: reads its profiles (relative to `base`), derives the
/// parts and transitions when the document has none, replays the active
/// edits of its log (`crate::edit`, `crate::sasm`), builds the mesh and measures it.
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
        .map(|r| crate::sketch::removed::removed_part(r, base, tol))
        .collect::<Result<Vec<_>, _>>()?;
    let mut out = doc.clone();
    let (yr, _) = crate::sketch::poly::bounds(&front.points);
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
    let edit_err = |e: EditError| SketchError::Document(e.to_string());
    crate::character::log::check_order(&out.transitions, active).map_err(edit_err)?;
    let edited = crate::edit::apply_to_parts(&out.parts, active).map_err(edit_err)?;
    let disp = crate::edit::displacements(active).map_err(edit_err)?;
    let mut model = build_model_with(&edited, &out.transitions, height, res, &disp, cache)?;
    apply_mesh_edits(&mut model.mesh, &model.parts, active).map_err(edit_err)?;
    let props =
        crate::character::props::compose(&mut model.mesh, &doc.props, base, res.rings_per_height)
            .map_err(|e| SketchError::Document(e.to_string()))?;
    let report = crate::sketch::report::report(
        &out,
        &edited,
        &model,
        &front,
        side.as_ref(),
        &removed,
        props,
        height,
    );
    Ok(Built {
        doc: out,
        model,
        report,
        front,
        side,
    })
}

/// Applies the mesh-level edits among `edits` to the built mesh, in log
/// order: plate bendings ([`Edit::Plate`]) and SASM features
/// ([`Edit::Sasm`], [`Edit::SasmAux`], on `parts`, the built part surfaces)
/// interleaved as the log has them (a SASM feature keeps what an earlier
/// plate or force did to its part: it adds its height to the vertices'
/// current positions).
pub fn apply_mesh_edits(
    mesh: &mut Mesh,
    parts: &[PartSurface],
    edits: &[Edit],
) -> Result<(), EditError> {
    for e in edits {
        match e {
            Edit::Plate { .. } => crate::edit::apply_plate(mesh, e)?,
            Edit::Sasm(_) | Edit::SasmAux(_) => {
                let invalid = |m: String| EditError::Invalid {
                    op: e.op(),
                    part: e.part().unwrap_or("").into(),
                    message: m,
                };
                if let Some(f) = crate::sasm::edit::feature_of(e, parts) {
                    let f = f.map_err(|err| invalid(err.to_string()))?;
                    let p = parts
                        .iter()
                        .find(|p| p.name == f.part)
                        .ok_or_else(|| invalid("the part is not built".into()))?;
                    crate::sasm::apply_feature(mesh, p, &f)
                        .map_err(|err| invalid(err.to_string()))?;
                }
            }
            _ => {}
        }
    }
    Ok(())
}
