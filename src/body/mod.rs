//! The whole-body reconstruction (issue 15; paper 002 section 4, Figs 5-6;
//! 000 Fig 13, 004 Table 1): a human body mesh cut into cross sections,
//! each part a C2 sixth-order PDE chain of the [`pde6`](crate::pde6) family,
//! the parts joined by the sketch's transition surfaces
//! ([`crate::character::build_model`]) into one closed mesh.
//!
//! This is modeling-level code: it sits above the sketch, the character
//! document and the equation families (it compares [`crate::pde6`] with
//! [`crate::ode6`] in [`study`]), so the `pde6` family stays a pure family
//! naming no module above it.
//!
//! * [`parts`]: the seven open parts of the paper (`pde6 body --open-parts`);
//! * [`layout`]: the part layout found from the mesh (no vertex ids);
//! * [`closed`]: one watertight body (`pde6 body`);
//! * [`hand`]: where the thumb separates from the palm, the thumb's and
//!   the palm's traces;
//! * [`cavity`]: the skin vertices in pockets (mouth, eye sockets) no outer
//!   section loop reaches;
//! * [`report`]: its measurements against the input body, [`sites`]: where
//!   its largest errors sit;
//! * [`intersect`]: self-intersections of the closed mesh (grid + triangle
//!   pairs);
//! * [`study`]: the data-size study (000 Fig 13);
//! * [`check`]: the `pde6.body_*` checks (family `body` in `verify`).

pub mod cavity;
pub mod check;
pub mod closed;
pub mod hand;
pub mod intersect;
pub mod joins;
pub mod layout;
pub mod parts;
pub mod report;
pub mod sections;
pub mod sites;
pub mod study;

/// Errors of the body reconstruction.
#[derive(Debug, thiserror::Error)]
pub enum BodyError {
    #[error("body layout: {what} not found: {detail}")]
    LayoutNotFound { what: &'static str, detail: String },
    #[error("{0} is not finite")]
    NotFinite(String),
    #[error("{what} = {got}: the C2 chain needs 7 + 3k sections (k = 0..30)")]
    SectionCount { what: &'static str, got: usize },
    #[error("{part}: no closed section at y = {y:.3}")]
    NoSection { part: String, y: f64 },
    #[error("the mesh has no vertices")]
    EmptyMesh,
    #[error("--morph {spec:?}: {problem}")]
    Morph { spec: String, problem: String },
    #[error("--morph applies to the bundled MakeHuman body, not to --mesh")]
    MorphWithMesh,
    #[error("--sampling {0}: expected anchored, chord, centripetal, uniform or polar")]
    SamplingName(String),
    #[error("assembling the closed body: {0}")]
    Assembly(#[from] crate::character::ModelError),
    #[error(transparent)]
    Pde6(#[from] crate::pde6::Pde6Error),
    #[error(transparent)]
    Gec(#[from] crate::curve::gec::GecError),
    #[error(transparent)]
    Ode6(#[from] crate::ode6::Ode6Error),
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
}

/// Loads the body ([`load_body`](report::load_body)), refuses an `output` that is the input
/// mesh, and reconstructs it closed.
pub fn reconstruct_closed_from(
    path: Option<&std::path::Path>,
    morphs: &[String],
    output: &std::path::Path,
    opts: &closed::ClosedOptions,
) -> Result<closed::ClosedBody, BodyError> {
    let skin = report::load_body(path, morphs)?;
    if let Some(m) = path {
        crate::mesh::io::refuse_overwriting_input(&[m], output)?;
    }
    closed::reconstruct_closed(&skin, opts)
}
