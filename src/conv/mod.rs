//! SketchCo: convolution surfaces from sketched silhouette curves
//! (paper 003, Kúkelová, secs 3-4, Figs 2-8).
//!
//! Pipeline: a closed stroke is filtered ([`stroke`]: Douglas-Peucker plus
//! re-inserted points, self-intersection rejection), triangulated and
//! skeletonised ([`skeleton`]: CDT, terminal / sleeve / junction triangles,
//! circles, pruning), every skeletal line segment gets linear weights from
//! the threshold at the radius above its endpoints ([`fit`]), and a global
//! non-negative least-squares fit of the control scales $\lambda_i$ makes
//! the field equal the threshold $T$ at the silhouette points. The field is
//! the sum of closed-form line-segment fields of the Cauchy kernel
//! $h(r) = 1/(1+s^2r^2)^2$ ([`kernel`]):
//! $$F(r) = \sum_i \lambda_i \Big(w_{0,i} F_1(r; L_i) + \frac{w_{1,i}-w_{0,i}}{l_i} F_t(r; L_i)\Big),$$
//! and the surface is $F = T$, polygonised by
//! [`crate::mesh::isosurface`] (marching tetrahedra, as in the paper, or
//! surface nets). [`model`] places components on planes at depths, merges
//! and carves them, and reads / writes the compact JSON model file.

pub mod bvh;
pub mod check;
pub mod check_fast;
pub mod check_quadrature;
pub mod check_sides;
pub mod farfield;
pub mod fit;
pub mod frontier;
pub mod incremental;
pub mod kernel;
pub mod model;
pub mod narrow;
mod narrow_merge;
pub mod nnls;
pub mod sample;
pub mod samples;
pub mod shapes;
pub mod silhouette;
pub mod skeleton;
pub mod sketch;
mod sketch_cache;
pub mod stroke;

use thiserror::Error;

/// Errors of the conv family.
#[derive(Debug, Error)]
pub enum ConvError {
    #[error("stroke point {index} is not finite")]
    NonFinite { index: usize },
    #[error("stroke point {index} has coordinate {value:e}, beyond the {limit:e} a stroke may reach; scale the sketch down")]
    OutOfRange {
        index: usize,
        value: f64,
        limit: f64,
    },
    #[error(
        "stroke spans only {size:e} (bounding-box diagonal), below {limit:e}; scale the sketch up"
    )]
    TooSmall { size: f64, limit: f64 },
    #[error("stroke too short: {points} distinct points, at least {needed} needed")]
    TooShort { points: usize, needed: usize },
    #[error("stroke encloses (almost) no area: {area:e}")]
    ZeroArea { area: f64 },
    #[error("the filtered stroke intersects itself (edges {edge_a} and {edge_b}); sketch a curve without self-intersections")]
    SelfIntersecting { edge_a: usize, edge_b: usize },
    #[error("triangulation failed: {0}")]
    Triangulation(String),
    /// The constrained Delaunay triangulation refused a stroke vertex.
    #[error("triangulation failed: vertex {vertex}: {source:?}")]
    Insertion {
        vertex: usize,
        #[source]
        source: spade::InsertionError,
    },
    #[error("invalid parameter: {0}")]
    Parameter(String),
    #[error("numerical failure: {0}")]
    Numerical(String),
    #[error("model file: {0}")]
    Model(String),
    /// A model file is not the JSON of a model.
    #[error("model file: {0}")]
    ModelJson(#[source] serde_json::Error),
    /// A model's component failed to build.
    #[error("model file: component {name:?}: {source}")]
    Component {
        name: String,
        #[source]
        source: Box<ConvError>,
    },
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
}

impl ConvError {
    /// The triangulation's refusal of stroke vertex `vertex`.
    pub fn insertion(vertex: usize, source: spade::InsertionError) -> ConvError {
        ConvError::Insertion { vertex, source }
    }

    /// This error as the failure of a model's component `name`.
    pub fn in_component(self, name: &str) -> ConvError {
        ConvError::Component {
            name: name.into(),
            source: Box::new(self),
        }
    }
}
