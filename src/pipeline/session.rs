//! An editing session (a document, where its profiles live, the mesh
//! resolution and a cache of built parts) and the checked push of an edit:
//! both build through the one [`build`].

use super::build::{build, BuildError, BuildOptions, Built};
use crate::character::assembly::PartCache;
use crate::character::doc::CharacterDoc;
use crate::character::log::{check_order, validate_params, Edit, EditError};
use crate::character::{Model, Resolution};
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
}

impl Session {
    /// A session on `doc` (profiles relative to `base`).
    pub fn new(doc: CharacterDoc, base: PathBuf, res: Resolution) -> Session {
        Session {
            doc,
            base,
            res,
            cache: PartCache::default(),
        }
    }

    /// Validates and appends an edit ([`CharacterDoc::push_edit`]).
    pub fn push(&mut self, e: Edit) -> Result<(), EditError> {
        self.doc.push_edit(e)
    }

    /// Builds the document's current state ([`build`]), re-solving only
    /// the parts whose specification changed since the last build.
    pub fn build(&mut self) -> Result<Built, BuildError> {
        let opts = BuildOptions::new(&self.base).res(self.res);
        build(&self.doc, &opts, Some(&mut self.cache))
    }

    /// The model of the current state: [`Session::build`]'s (the same
    /// function, so the props are in it too).
    pub fn model(&mut self) -> Result<Model, BuildError> {
        Ok(self.build()?.model)
    }
}

/// Pushes `e` and keeps it only when the document with it builds, with
/// finite geometry: the edit's own parameters and the log's order are
/// checked, the document with the edit is built once ([`build`], with
/// `cache` when given) and that build is returned; `doc` takes the edit.
/// On error `doc` is unchanged. An error of the new edit met in the replay
/// is reported as the edit's own (not as "edit i of the log").
pub fn push_checked(
    doc: &mut CharacterDoc,
    e: Edit,
    opts: &BuildOptions,
    cache: Option<&mut PartCache>,
) -> Result<Built, BuildError> {
    if doc.parts.is_empty() {
        return Err(EditError::NoParts.into());
    }
    validate_params(&e)?;
    let mut next = doc.clone();
    next.append_edit(e);
    check_order(&next.transitions, next.active_edits())?;
    let index = next.cursor - 1;
    let what = format!("edit {index} ({})", next.edits[index].summary());
    let built =
        super::effect::validate_by_build(&next, opts, cache, &what).map_err(|err| match err {
            BuildError::Edit(EditError::Replay {
                index: i, source, ..
            }) if i == index => BuildError::Edit(*source),
            other => other,
        })?;
    *doc = next;
    Ok(built)
}

/// Redoes the next undone edit and keeps it only when the document then
/// builds as [`push_checked`] requires (validated by its effect: a log
/// written by hand or by an older version is not trusted). On error `doc`
/// is unchanged.
pub fn redo_checked(
    doc: &mut CharacterDoc,
    opts: &BuildOptions,
    cache: Option<&mut PartCache>,
) -> Result<Built, BuildError> {
    let mut next = doc.clone();
    next.redo()
        .map_err(|err| BuildError::Sketch(SketchError::Document(err.to_string())))?;
    let i = next.cursor - 1;
    let what = format!("redo of edit {i} ({})", next.edits[i].summary());
    let built =
        super::effect::validate_by_build(&next, opts, cache, &what).map_err(|err| match err {
            BuildError::Cancelled => BuildError::Cancelled,
            other => BuildError::Sketch(SketchError::Document(format!(
                "{what} refused: the document it gives does not build: {other}"
            ))),
        })?;
    *doc = next;
    Ok(built)
}
