//! An editing session (a document, where its profiles live, the mesh
//! resolution and a cache of built parts) and the checked push of an edit.

use super::build::{apply_mesh_edits, build_document_with, Built};
use crate::character::assembly::{build_model_with, PartCache};
use crate::character::doc::CharacterDoc;
use crate::character::log::{Edit, EditError};
use crate::character::{Model, Resolution};
use crate::edit::displacements;
use crate::sketch::SketchError;
use std::path::PathBuf;

/// An editing session: the document, where its profiles live, the mesh
/// resolution and a cache of built parts, so that a rebuild after an edit
/// re-solves only the part the edit changed.
#[derive(Clone, Debug)]
pub struct Session {
    pub doc: CharacterDoc,
    pub base: PathBuf,
    pub res: Resolution,
    pub cache: PartCache,
    /// Model height, read from the front profile at the first build.
    pub height: Option<f64>,
}

impl Session {
    /// A session on `doc` (profiles relative to `base`).
    pub fn new(doc: CharacterDoc, base: PathBuf, res: Resolution) -> Session {
        Session {
            doc,
            base,
            res,
            cache: PartCache::default(),
            height: None,
        }
    }

    /// Validates and appends an edit ([`CharacterDoc::push_edit`]).
    pub fn push(&mut self, e: Edit) -> Result<(), EditError> {
        self.doc.push_edit(e)
    }

    /// Builds the document's current state, re-solving only changed parts
    /// (with the report: profiles read, silhouettes measured).
    pub fn build(&mut self) -> Result<Built, SketchError> {
        let b = build_document_with(
            &self.doc,
            &self.base,
            self.res,
            false,
            Some(&mut self.cache),
        )?;
        self.height = Some(b.report.height);
        Ok(b)
    }

    /// The interactive path: only the model (mesh and joins) of the current
    /// state, re-solving only changed parts, without reading the profiles or
    /// measuring silhouettes (the mesh equals [`Session::build`]'s bit for
    /// bit). Needs stored parts; the first call runs [`Session::build`] once
    /// to learn the height.
    pub fn model(&mut self) -> Result<Model, SketchError> {
        let height = match self.height {
            Some(h) => h,
            None => self.build()?.report.height,
        };
        if self.doc.parts.is_empty() {
            return Err(SketchError::Document(
                "the session's document has no stored parts".into(),
            ));
        }
        let active = self.doc.active_edits();
        let err = |e: EditError| SketchError::Document(e.to_string());
        crate::character::log::check_order(&self.doc.transitions, active).map_err(err)?;
        let edited = crate::edit::apply_to_parts(&self.doc.parts, active).map_err(err)?;
        let disp = displacements(active).map_err(err)?;
        let mut model = build_model_with(
            &edited,
            &self.doc.transitions,
            height,
            self.res,
            &disp,
            Some(&mut self.cache),
        )?;
        apply_mesh_edits(&mut model.mesh, &model.parts, active).map_err(err)?;
        Ok(model)
    }
}

/// Pushes `e` and keeps it only when the document still builds as
/// `character build` builds it (default resolution, profiles read from
/// `base`): [`CharacterDoc::push_edit`] validates an edit against the parts,
/// but a mesh-level edit (a plate region whose projection overlaps, a
/// motion that overflows) can only be judged on the built mesh. On error
/// `doc` is unchanged.
pub fn push_checked(
    doc: &mut CharacterDoc,
    e: Edit,
    base: &std::path::Path,
) -> Result<Built, SketchError> {
    let mut next = doc.clone();
    next.push_edit(e)
        .map_err(|err| SketchError::Document(err.to_string()))?;
    let built = super::build_document(&next, base, Resolution::default(), false)?;
    *doc = next;
    Ok(built)
}
