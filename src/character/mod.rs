//! The character: its document and the assembly of its parts,
//! transitions and props into one model (paper 000 secs 4-5). The bottom
//! of the modeling layer: it names no modeling operation (`sketch`,
//! `template`, `edit`, `sasm`, `body` sit above it and meet here).
//!
//! Bottom up: [`spec`] (what a document specifies of parts and
//! transitions), [`log`] (the edit log's data and its own checks), [`doc`]
//! (the versioned document: inputs, derived parts, log, props); [`part`]
//! (a part's pde6 C2 chain), [`ring`] (the end ring the seams cut),
//! [`seam`], [`transition`] (Hermite branch transitions, G1 seams),
//! [`tangent_cap`] (sketched transitions' tangents capped where a ring flares),
//! [`measure`] (join jumps), [`assembly`] (one shared-vertex mesh, the part
//! cache, displacement fields), [`crease`], [`props`] (conv models composed
//! into the mesh). From a document to a model is `crate::pipeline`.

pub mod assembly;
pub mod crease;
pub mod doc;
pub mod doc_ranges;
pub mod inputs;
pub mod log;
pub mod measure;
pub mod part;
pub mod props;
pub mod ring;
pub mod rise;
pub mod runs;
pub mod seam;
pub mod spec;
pub mod tangent_cap;
pub mod transition;

pub use assembly::{build_model, Model, Resolution};

/// Errors of assembling a document's parts and transitions into one model.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    /// A GEC key section's frame or curve is invalid (boxed: the GEC
    /// error is large and this error travels inside edit errors).
    #[error("key section: {0}")]
    Section(#[source] Box<crate::curve::gec::GecError>),
    #[error("part '{part}': {message}")]
    Part { part: String, message: String },
    #[error("document: {0}")]
    Document(String),
}

impl From<crate::curve::gec::GecError> for ModelError {
    fn from(e: crate::curve::gec::GecError) -> ModelError {
        ModelError::Section(Box::new(e))
    }
}
