//! C1 plate-bending deformation of mesh regions (paper 001, eqs 1-16,
//! secs 4-5).
//!
//! A region of a mesh is projected onto the view plane (eq 13, corrected:
//! the printed form has $b\,p_x$ where $b\,p_y$ belongs), expressed in a local
//! frame (eq 14), its boundary is extracted as an alpha shape on a Delaunay
//! triangulation (eq 15, $\alpha = d_P \alpha_0$), and the region is mapped
//! onto the unit disk by the length-based mapping (eq 16). The deformation
//! is the clamped circular plate (eqs 1-12)
//!
//! $$D\nabla^4 \xi = q_\xi,\quad \xi = \frac{q_\xi}{64 D}(u^2+v^2-1)^2,
//! \quad D = \frac{E h^3}{12(1-\mu^2)},$$
//!
//! with $\xi = \partial_u\xi = \partial_v\xi = 0$ on $u^2+v^2=1$ (C1), and the
//! sculpting force $q_\xi = s\,d_\xi$ (sensitivity times cursor motion).
//!
//! Beyond the paper (options, the paper's choices stay the defaults):
//! [`BoundaryMethod::MeshEdges`] takes the boundary from the region's mesh
//! triangles (the rule $\alpha = 0.86\,d_P$ fails as soon as the vertex
//! spacing is non-uniform, e.g. near a sphere's pole), and
//! [`MappingMethod::Harmonic`] replaces eq 16 by a Tutte embedding that is
//! one-to-one for any disk-like region (no star-shape or centroid
//! condition, paper limit 2).
//!
//! Findings (measured in `shapes::compare`, the `001-table-errors` figure
//! and the checks):
//! * eq 12 lives on the unit disk, so the deflection does not grow with the
//!   region's size: against the physical clamped plate $D\nabla^4 w = q$ on
//!   the projected region the peak ratio is 1.15 (circle of radius 0.96)
//!   to 37 (pentagram); only the shape is comparable.
//! * eq 16 is continuous but not C1 inside the region: for a square of
//!   half-side $a$ it gives $\rho = \max(|x|,|y|)/a$, so $w$ has slope jumps
//!   along the diagonals (rays through boundary corners); C1 holds on the
//!   boundary as the paper states.
//!
//! Submodules: [`projection`] (eqs 13-14), [`boundary`] (eq 15),
//! [`mapping`] (eq 16), [`deformer`] (precomputed region, one pass per
//! cursor move), [`region`] (region files and lassos), [`mod@reference`] (Morley finite-element clamped-plate solver,
//! the ground truth), [`baselines`] (Laplacian deformer, Delta Mush),
//! [`shapes`] (test regions and the paper's comparisons), [`check`].

pub mod baselines;
pub mod boundary;
pub mod check;
pub mod deformer;
mod delaunay;
pub mod mapping;
pub mod projection;
pub mod reference;
pub mod region;
pub mod shapes;

use crate::jet::Real;

pub use deformer::{BoundaryMethod, Direction, MappingMethod, PlateDeformer, RegionOptions};
pub use region::{parse_region, region_from_lasso};

/// Errors of the plate family.
#[derive(Debug, thiserror::Error)]
pub enum PlateError {
    #[error("parameter {name} = {value} is out of range ({range})")]
    Parameter {
        name: &'static str,
        value: f64,
        range: &'static str,
    },
    #[error("region has {0} vertices; at least {1} are needed")]
    TooFewVertices(usize, usize),
    #[error("region vertex {0} is out of bounds (mesh has {1} vertices)")]
    VertexOutOfBounds(usize, usize),
    #[error("non-finite coordinate at vertex {0}")]
    NonFinite(usize),
    #[error("degenerate projection: {0}")]
    DegenerateProjection(String),
    /// The Delaunay triangulation of the projection refused a point.
    #[error("degenerate projection: {0:?}")]
    Insertion(#[source] spade::InsertionError),
    #[error(
        "the alpha shape (alpha_0 = {alpha0}) does not close into one boundary loop: {reason}"
    )]
    BoundaryNotClosed { alpha0: f64, reason: String },
    #[error("overlapping projection: {0} triangles of the region flip orientation in the view plane (paper limit 1)")]
    OverlappingProjection(usize),
    #[error("the region's centroid lies outside its boundary (paper limit 2)")]
    CentroidOutside,
    #[error("linear solve failed: {0}")]
    Solve(String),
    /// A sparse system's matrix could not be assembled.
    #[error("linear solve failed: {0:?}")]
    Matrix(#[source] faer::sparse::CreationError),
    /// A sparse system's Cholesky factorisation failed (`what` names the
    /// system).
    #[error("linear solve failed: {what}: {source:?}")]
    Cholesky {
        what: &'static str,
        #[source]
        source: faer::sparse::linalg::LltError,
    },
    #[error("malformed region file: {0}")]
    RegionFile(String),
    /// A JSON region file that does not parse.
    #[error("malformed region file: {0}")]
    RegionJson(#[source] serde_json::Error),
    #[error("cursor motion {d:?} with sensitivity {sensitivity} is not finite")]
    NonFiniteForce { d: [f64; 3], sensitivity: f64 },
    #[error("cursor motion {d:?} times sensitivity {sensitivity} {what}; reduce the motion")]
    ForceTooLarge {
        d: [f64; 3],
        sensitivity: f64,
        what: &'static str,
    },
}

impl PlateError {
    /// The failed Cholesky factorisation of the system `what`.
    pub fn cholesky(what: &'static str, source: faer::sparse::linalg::LltError) -> PlateError {
        PlateError::Cholesky { what, source }
    }
}

/// The cursor-to-force sensitivity $s$ of the CLI and the demo ($q = s d$).
pub const SENSITIVITY_DEFAULT: f64 = 70.0;

/// Material and thickness of the plate (eq 3).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Material {
    /// Young's modulus E.
    pub young: f64,
    /// Poisson's ratio mu, in [0, 0.5].
    pub poisson: f64,
    /// Thickness h.
    pub thickness: f64,
}

impl Default for Material {
    /// The paper's defaults (sec 5): E = 1e6, mu = 0.5 (rubber), h = 0.1.
    fn default() -> Self {
        Material {
            young: 1e6,
            poisson: 0.5,
            thickness: 0.1,
        }
    }
}

impl Material {
    /// Bending rigidity $D = E h^3 / (12 (1 - \mu^2))$ (eq 3).
    pub fn rigidity(&self) -> Result<f64, PlateError> {
        let ok = |name, value: f64, range, good: bool| {
            if value.is_finite() && good {
                Ok(())
            } else {
                Err(PlateError::Parameter { name, value, range })
            }
        };
        ok("E", self.young, "> 0", self.young > 0.0)?;
        ok("h", self.thickness, "> 0", self.thickness > 0.0)?;
        ok(
            "mu",
            self.poisson,
            "[0, 0.5]",
            (0.0..=0.5).contains(&self.poisson),
        )?;
        Ok(self.young * self.thickness.powi(3) / (12.0 * (1.0 - self.poisson * self.poisson)))
    }
}

/// The disk solution (eq 12): $\xi(u, v) = \frac{q}{64 D}(u^2+v^2-1)^2$,
/// written once for f64 and jets.
pub fn disk_solution<T: Real>(q: f64, rigidity: f64, u: T, v: T) -> T {
    let s = u * u + v * v - 1.0;
    s * s * (q / (64.0 * rigidity))
}

/// Radial profile of eq 12 on the unit disk for $q/D = 1$:
/// $(1-\rho^2)^2/64$, zero outside the disk.
pub fn disk_profile(rho: f64) -> f64 {
    if rho >= 1.0 {
        0.0
    } else {
        let s = 1.0 - rho * rho;
        s * s / 64.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Eq 3's rigidity is refused, naming the parameter, for a modulus or
    /// thickness that is not positive and finite and a Poisson ratio
    /// outside [0, 0.5]; the paper's rubber gives E h^3 / 9 (a mutation
    /// sample found no check of the refusals: `finite && good` -> `||`
    /// survived).
    #[test]
    fn rigidity_refuses_what_is_not_a_material() {
        let rubber = Material::default();
        let d = rubber.rigidity().expect("the paper's rubber");
        assert_eq!(d, 1e6 * 0.1f64.powi(3) / 9.0);
        let bad = [
            (
                "E",
                Material {
                    young: -1.0,
                    ..rubber
                },
            ),
            // E = 0 is the boundary itself: no rigidity, no plate (a
            // `>=` in the check let it through, mutation sample plate 7/20)
            (
                "E",
                Material {
                    young: 0.0,
                    ..rubber
                },
            ),
            (
                "E",
                Material {
                    young: f64::INFINITY,
                    ..rubber
                },
            ),
            (
                "h",
                Material {
                    thickness: 0.0,
                    ..rubber
                },
            ),
            (
                "h",
                Material {
                    thickness: f64::NAN,
                    ..rubber
                },
            ),
            (
                "mu",
                Material {
                    poisson: 0.6,
                    ..rubber
                },
            ),
            (
                "mu",
                Material {
                    poisson: -0.1,
                    ..rubber
                },
            ),
        ];
        for (name, m) in bad {
            match m.rigidity() {
                Err(PlateError::Parameter { name: n, .. }) => assert_eq!(n, name, "{m:?}"),
                other => panic!("{m:?}: {other:?}"),
            }
        }
    }
}
