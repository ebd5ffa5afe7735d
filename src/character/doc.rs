//! The character document: a character as its inputs plus what was derived
//! from them, in one versioned JSON file.
//!
//! # Schema (version 1)
//!
//! ```json
//! {
//!   "version": 1,
//!   "level": "initial" | "intermediate" | "final",
//!   "inputs": {
//!     "front": {"path": "front.svg"} | {"points": [[x, y], ...]},
//!     "side": null | {"path": "side.svg"} | {"points": [[z, y], ...]},
//!     "sections": [{"part": "torso", "y": 1.2, "points": [[x, z], ...]}],
//!     "tolerance": 0.002,
//!     "height": 1.75
//!   },
//!   "parts": [ PartSpec ... ],
//!   "transitions": [ TransitionSpec ... ],
//!   "removed_parts": [{"name": "hair", "front": {...}, "side": null}],
//!   "edits": [],
//!   "cursor": 0,
//!   "props": [{"name": "ball", "model": "ball.json", "translate": [0, 0, 0], "scale": 1}]
//! }
//! ```
//!
//! Every object rejects unknown fields. Paths are relative to the document's
//! directory. `parts` and `transitions` are *derived* from the inputs at the
//! document's `level` (`sketch build` fills them); when `parts` is empty,
//! `character build` derives them again, otherwise it builds the stored
//! parts as they are (so an editor can change a section and rebuild). The
//! mesh, the transition surfaces and the report are always recomputed.
//!
//! Part names are stable: `torso`, `head` (neck and head), `arm_l`, `arm_r`,
//! `leg_l`, `leg_r` (`_l` is the side of negative model x, the viewer's left
//! in the front view); transitions are `shoulders` and `hips`.
//!
//! A [`PartSpec`] is a tube: its key sections in order along its central
//! curve (`u` is arc length along the polyline through the section centres),
//! each a closed curve in the plane spanned by `e1`, `e2` about `centre`
//! (circle, ellipse or GEC coefficients in that frame), its surface family
//! and whether its start or end is a free (closed) end.
//!
//! `edits` is the edit log (local modeling, paper 000 sec 5): an ordered list
//! of typed edits ([`crate::character::log::Edit`], tagged by `"op"`), of
//! which the first `cursor` are active (undo/redo move the cursor). Building
//! replays the active edits on the stored (or derived) parts; the stored
//! parts themselves are never changed by an edit. A document with an empty
//! log (every version-1 document written before the log was typed) is valid.

pub use super::inputs::{
    BodyPlan, DocError, Inputs, KeySection, Level, ProfileInput, RemovedPart, VERSION,
};
pub use super::spec::{
    Continuity, End, EndCurvature, PartSpec, SectionShape, SectionSpec, SurfaceSpec, TransitionSpec,
};
use crate::mesh::io::write_atomic;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

pub mod access;

/// The character document.
///
/// Every field is private. The version and level are fixed when the
/// document is made ([`CharacterDoc::from_inputs`] or a load), and the log
/// changes only through its API ([`CharacterDoc::push_edit`],
/// [`CharacterDoc::append_edit`], [`CharacterDoc::undo`],
/// [`CharacterDoc::redo`], [`CharacterDoc::drop_inactive_edits`]), so the
/// cursor never points past the log's end. The inputs and the derived
/// parts, transitions, removed parts and props are read through accessors
/// and change only through named operations ([`access`]: a build's
/// [`CharacterDoc::set_derived`], the editor's commands, a template's
/// [`CharacterDoc::part_mut`]), which [`CharacterDoc::validate`] (run by
/// every save and build) checks.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CharacterDoc {
    version: u32,
    #[serde(default)]
    level: Level,
    inputs: Inputs,
    #[serde(default)]
    parts: Vec<PartSpec>,
    #[serde(default)]
    transitions: Vec<TransitionSpec>,
    #[serde(default)]
    removed_parts: Vec<RemovedPart>,
    /// The edit log (see [`crate::character::log`]).
    #[serde(default)]
    edits: Vec<crate::character::log::Edit>,
    /// How many of `edits` are active (at most `edits.len()`).
    #[serde(default)]
    cursor: usize,
    /// Props: conv models composed as separate components
    /// ([`crate::character::props`]); absent in older documents.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    props: Vec<crate::character::props::PropSpec>,
}

impl CharacterDoc {
    /// A document with only inputs (nothing derived yet).
    pub fn from_inputs(inputs: Inputs, level: Level) -> CharacterDoc {
        CharacterDoc {
            version: VERSION,
            level,
            inputs,
            parts: Vec::new(),
            transitions: Vec::new(),
            removed_parts: Vec::new(),
            edits: Vec::new(),
            cursor: 0,
            props: Vec::new(),
        }
    }

    /// The schema version ([`VERSION`] for every valid document).
    pub fn version(&self) -> u32 {
        self.version
    }

    /// The level the parts are derived at.
    pub fn level(&self) -> Level {
        self.level
    }

    /// Parses and validates a document's text (`path` names it in errors).
    pub fn parse(text: &str, path: &Path) -> Result<CharacterDoc, DocError> {
        let text = crate::mesh::io::strip_bom(text);
        let v: serde_json::Value =
            serde_json::from_str(text).map_err(|source| DocError::Parse {
                path: path.into(),
                source,
            })?;
        if let Some(found) = v.get("version").and_then(|x| x.as_u64()) {
            if found != VERSION as u64 {
                return Err(DocError::Version {
                    path: path.into(),
                    found: found as u32,
                });
            }
        }
        let doc: CharacterDoc = serde_json::from_value(v).map_err(|source| DocError::Parse {
            path: path.into(),
            source,
        })?;
        doc.validate()?;
        Ok(doc)
    }

    /// Reads a document (a regular file only, at most
    /// [`crate::limits::INPUT_BYTES`]).
    pub fn load(path: &Path) -> Result<CharacterDoc, DocError> {
        let text =
            crate::mesh::io::read_input_text(path, "character document").map_err(|e| match e {
                crate::mesh::MeshError::Io { source, .. } => DocError::Io {
                    path: path.into(),
                    source,
                },
                e => DocError::Write(e),
            })?;
        CharacterDoc::parse(&text, path)
    }

    /// Writes the document atomically (temporary file, then rename).
    pub fn save(&self, path: &Path) -> Result<(), DocError> {
        write_atomic(path, &self.to_bytes()?)?;
        Ok(())
    }

    /// The validated document as the JSON a save writes (for a command
    /// that writes it together with other files).
    pub fn to_bytes(&self) -> Result<Vec<u8>, DocError> {
        self.validate()?;
        serde_json::to_vec_pretty(self).map_err(DocError::Serialise)
    }

    /// Structural checks that do not need the geometry, and every value's
    /// documented range ([`super::doc_ranges`]).
    pub fn validate(&self) -> Result<(), DocError> {
        if self.version != VERSION {
            return Err(DocError::Invalid(format!(
                "version {} (expected {VERSION})",
                self.version
            )));
        }
        super::doc_ranges::check(&super::doc_ranges::Fields {
            inputs: &self.inputs,
            parts: &self.parts,
            transitions: &self.transitions,
            removed_parts: &self.removed_parts,
            props: &self.props,
            edits: self.edits.len(),
        })?;
        if self.cursor > self.edits.len() {
            return Err(DocError::Invalid(format!(
                "cursor {} is past the end of the edit log ({} edits)",
                self.cursor,
                self.edits.len()
            )));
        }
        for (i, e) in self.edits.iter().enumerate() {
            crate::character::log::validate_params(e).map_err(|e| DocError::Edit {
                index: i,
                source: Box::new(e),
            })?;
        }
        for (name, v) in [
            ("inputs.tolerance", self.inputs.tolerance),
            ("inputs.height", self.inputs.height),
        ] {
            if let Some(v) = v.filter(|v| !(v.is_finite() && *v > 0.0)) {
                return Err(DocError::Invalid(format!(
                    "{name} must be positive, got {v}"
                )));
            }
        }
        let mut names: Vec<&str> = self.parts.iter().map(|p| p.name.as_str()).collect();
        names.extend(self.transitions.iter().map(|t| t.name.as_str()));
        names.extend(self.props.iter().map(|p| p.name.as_str()));
        if self.props.len() > crate::character::props::MAX_PROPS {
            return Err(DocError::Invalid(format!(
                "{} props (at most {})",
                self.props.len(),
                crate::character::props::MAX_PROPS
            )));
        }
        for p in &self.props {
            p.validate()?;
        }
        let mut sorted = names.clone();
        sorted.sort_unstable();
        if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
            return Err(DocError::Invalid(format!("name '{}' is used twice", w[0])));
        }
        for t in &self.transitions {
            for n in std::iter::once(&t.parent).chain(&t.children) {
                if !self.parts.iter().any(|p| &p.name == n) {
                    return Err(DocError::Invalid(format!(
                        "transition '{}' names unknown part '{n}'",
                        t.name
                    )));
                }
            }
            if t.children.is_empty() || t.seam_apex.len() + 1 != t.children.len() {
                return Err(DocError::Invalid(format!(
                    "transition '{}' needs one seam apex fewer than its {} children, got {}",
                    t.name,
                    t.children.len(),
                    t.seam_apex.len()
                )));
            }
        }
        Ok(())
    }

    /// Resolves a profile path against the document's directory.
    pub fn resolve(doc_path: &Path, p: &str) -> PathBuf {
        let p = Path::new(p);
        if p.is_absolute() {
            return p.into();
        }
        doc_path.parent().unwrap_or(Path::new(".")).join(p)
    }
}

/// The document's edit log: the active edits, undo and redo (pushing an
/// edit, which validates it against the built parts, is
/// `crate::pipeline`'s `CharacterDoc::push_edit`).
impl CharacterDoc {
    /// The whole edit log: the active edits, then the undone ones (the
    /// redo tail).
    pub fn edits(&self) -> &[crate::character::log::Edit] {
        &self.edits
    }

    /// How many edits are active (the first `cursor()` of [`Self::edits`]).
    pub fn cursor(&self) -> usize {
        self.cursor
    }

    /// The active edits (`edits()[..cursor()]`).
    pub fn active_edits(&self) -> &[crate::character::log::Edit] {
        &self.edits[..self.cursor.min(self.edits.len())]
    }

    /// The most recently applied edit (the one `undo` would undo) and its
    /// index in the log.
    pub fn last_active(&self) -> Option<(usize, &crate::character::log::Edit)> {
        let i = self.cursor.checked_sub(1)?;
        self.edits.get(i).map(|e| (i, e))
    }

    /// Drops the undone edits (the redo tail), as a change that is not an
    /// edit (an input command) does.
    pub fn drop_inactive_edits(&mut self) {
        self.edits.truncate(self.cursor);
    }

    /// Drops the redo tail, appends `e` and moves the cursor to the end,
    /// judging nothing: `push_edit` and `pipeline::push_checked` (which
    /// builds the document with the edit) judge it first.
    pub fn append_edit(&mut self, e: crate::character::log::Edit) {
        self.edits.truncate(self.cursor);
        self.edits.push(e);
        self.cursor = self.edits.len();
    }

    /// Moves the cursor back by one edit.
    pub fn undo(&mut self) -> Result<(), crate::character::log::EditError> {
        if self.cursor == 0 {
            return Err(crate::character::log::EditError::NothingToUndo);
        }
        self.cursor -= 1;
        Ok(())
    }

    /// Moves the cursor forward by one edit.
    pub fn redo(&mut self) -> Result<(), crate::character::log::EditError> {
        if self.cursor >= self.edits.len() {
            return Err(crate::character::log::EditError::NothingToRedo {
                len: self.edits.len(),
            });
        }
        self.cursor += 1;
        Ok(())
    }
}
