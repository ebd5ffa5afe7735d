//! An editing session (a document, where its profiles live, the mesh
//! resolution and a cache of built parts) and the checked push of an edit:
//! both build through the one [`build`].

use super::build::{build, BuildError, BuildOptions, Built};
use super::effect::{Extent, GROWTH};
use crate::character::assembly::PartCache;
use crate::character::doc::CharacterDoc;
use crate::character::log::{check_order, validate_params, Edit, EditError};
use crate::character::{Model, Resolution};
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
    if doc.parts().is_empty() {
        return Err(EditError::NoParts.into());
    }
    validate_params(&e)?;
    let mut next = doc.clone();
    next.append_edit(e);
    check_order(next.transitions(), next.active_edits())?;
    let (index, pushed) = next.last_active().expect("an edit was just appended");
    let what = format!("edit {index} ({})", pushed.summary());
    let built = validate_by_build(&next, opts, cache, &what).map_err(|err| match err {
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
    next.redo()?;
    let (i, redone) = next.last_active().expect("an edit was just redone");
    let what = format!("redo of edit {i} ({})", redone.summary());
    let built = validate_by_build(&next, opts, cache, &what).map_err(|err| match err {
        BuildError::Cancelled => BuildError::Cancelled,
        other => BuildError::RedoRefused {
            what: what.clone(),
            source: Box::new(other),
        },
    })?;
    *doc = next;
    Ok(built)
}

/// Builds `doc` once ([`super::build`] with `opts` and `cache`) and
/// accepts it only if the result is finite ([`super::effect::finite_result`], checked by
/// every build) and the model (props aside) stays within [`GROWTH`] model
/// sizes of its stored, unedited parts ([`Extent::of_parts`](Extent::of_parts)). `what`
/// names the change in messages (`edit 3 (force on arm_l)`). A failed
/// build's error is returned as it is, so that callers can name it.
pub fn validate_by_build(
    doc: &CharacterDoc,
    opts: &BuildOptions,
    cache: Option<&mut PartCache>,
    what: &str,
) -> Result<Built, BuildError> {
    let built = build(doc, opts, cache)?;
    if !doc.parts().is_empty() {
        let b = Extent::of_parts(doc.parts());
        let props: Vec<&str> = doc.props().iter().map(|p| p.name.as_str()).collect();
        let after = Extent::of_groups(&built.model.mesh, &props);
        let reach = b.overreach(&after);
        if reach.is_nan() || reach > GROWTH {
            return Err(BuildError::Growth {
                what: what.into(),
                reach,
                diagonal: b.diagonal(),
            });
        }
    }
    Ok(built)
}
