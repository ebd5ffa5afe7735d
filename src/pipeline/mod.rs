//! Document -> model: the one build of a character (paper 000 secs 4-5).
//!
//! A character document (`crate::character::doc`) is its inputs, its
//! derived parts and transitions and an edit log. [`build`] reads
//! the drawings, derives the parts when the document has none
//! (`crate::sketch`), replays the active edits of the log in order
//! (spec-level and force edits: `crate::edit`; plate and SASM edits on the
//! built mesh: [`apply_mesh_edits`]), assembles the parts and transitions
//! into one mesh (`crate::character::assembly`), composes the props and
//! measures the result (`crate::sketch::report`).
//! [`CharacterDoc::push_edit`](crate::character::doc::CharacterDoc::push_edit)
//! validates an edit of any kind before it enters the log; a [`Session`]
//! keeps a cache of built parts across edits.
//!
//! This is the top of the modeling layer: it names the operations
//! (`sketch`, `edit`, `sasm`), which never name each other.

mod alternatives;
mod build;
pub mod corpus;
pub mod effect;
mod push;
mod session;

pub use build::{apply_mesh_edits, build, build_document, BuildError, BuildOptions, Built};
pub use push::project_force_stroke;
pub use session::{push_checked, redo_checked, Session};
