//! The face from a MakeHuman-topology mesh rebuilt by a curve network of
//! C2 ODE patches (paper 004 sec 6.3, Figs 9, 11-13, Table 1).
//!
//! The paper's process: "extracting a curve network from one template
//! mesh; generating the mesh by the curve network and the C2 ODE method;
//! comparing the reconstructed mesh with the original to optimise the
//! shape control parameters". Here:
//!
//! 1. [`template`]: from the bundled base mesh, once, the face region (its
//!    vertices by index), each region vertex's patch and `(u, v)`, and the
//!    curve samples as barycentric points of base triangles;
//! 2. [`extract`]: for an input mesh with the same topology, the network
//!    document: the column curves through the samples on the input (so
//!    the network moves with an expression), their first and second cross
//!    derivatives from the input's surface beside them (stored, as the
//!    paper stores 489 curve points with their derivatives), and node rows
//!    splitting the columns into patches;
//! 3. the network is solved ([`crate::ode6::network`]), every region vertex
//!    is regenerated at its `(u, v)`, the rest of the mesh is kept: the
//!    output has the input's vertices, faces and order;
//! 4. [`fit`]: per column of patches, the shape parameters that minimise
//!    the squared vertex error against the input (one set per column: a
//!    v-join is C2 only with equal parameters, eq 26);
//! 5. [`expression`]: MakeHuman's expression units and the FACS map.
//!
//! Errors are measured against the **input's** vertices, absolute and over
//! the head height (highest body vertex to lowest face vertex).

pub mod check;
pub mod ear;
pub mod expression;
pub mod extract;
pub mod fit;
pub mod sketched;
pub mod template;

pub use expression::{facs_units, unit_target, FacsUnit};
pub use extract::{rebuild, FaceOptions, FaceReport};
pub use template::{FaceTemplate, Window, BASE_WINDOW};

/// Errors of the face reconstruction.
#[derive(Debug, thiserror::Error)]
pub enum FaceError {
    #[error(
        "the mesh does not have the MakeHuman base topology: {why} \
         (expected the {vertices} vertices and {triangles} triangles of data/makehuman/base.obj, in order)"
    )]
    Topology {
        why: String,
        vertices: usize,
        triangles: usize,
    },
    #[error("unknown expression {name:?}; known: {known}")]
    UnknownExpression { name: String, known: String },
    #[error("expression weight for {name} is {weight}: a weight is a finite number in [-{max}, {max}] (MakeHuman's sliders span [0, 1])", max = crate::makehuman::MORPH_WEIGHT_MAX)]
    Weight { name: String, weight: f64 },
    #[error("face template: {0}")]
    Template(String),
    /// An embedded expression unit could not be decompressed.
    #[error("face template: expression {name}: {source}")]
    Expression {
        name: String,
        #[source]
        source: std::io::Error,
    },
    #[error("--patches {patches}: the face network has {rows} rows, so patches must be a multiple of {rows} between {min} and {max}")]
    Patches {
        patches: usize,
        rows: usize,
        min: usize,
        max: usize,
    },
    #[error("input vertex {index} is not finite")]
    NonFinite { index: usize },
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
    #[error(transparent)]
    Network(Box<crate::ode6::network::NetworkError>),
}

impl From<crate::ode6::network::NetworkError> for FaceError {
    fn from(e: crate::ode6::network::NetworkError) -> Self {
        FaceError::Network(Box::new(e))
    }
}
