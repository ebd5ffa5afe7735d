//! The JSON deformation spec of `pdesculpt pde4` (documented in `src/cli/pde4.rs`).

use super::four_sided::{self, FourSided};
use super::two_sided::{self, Boundary, TwoSided};
use super::{Force, Pde4Error, ShapeParams};
use crate::jet::Real;
use crate::surface::{Domain, Surface};

/// Patch type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PatchKind {
    TwoSided,
    FourSided,
}

/// Solution method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SpecMethod {
    Exact,
    Paper,
    LeastSquares,
    Galerkin,
}

/// Shape parameters: one set for all components or one per component.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(untagged)]
pub enum Shape {
    All(ShapeParams),
    PerComponent([ShapeParams; 3]),
}

/// A deformation spec.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub patch: PatchKind,
    pub method: SpecMethod,
    pub shape: Shape,
    /// `[M, N]`.
    pub terms: [usize; 2],
    #[serde(default)]
    pub forces: Vec<Force>,
    /// 2-sided exact only: boundary curves and tangents.
    #[serde(default)]
    pub boundary: Option<Boundary>,
}

/// A solved patch of either type.
#[derive(Clone, Debug, PartialEq)]
pub enum Patch {
    Two(TwoSided),
    Four(FourSided),
}

impl Spec {
    /// Solves the spec; refuses a solution that is not finite on a 9 x 9
    /// grid of the patch (non-finite coefficients, e.g. the printed formulas
    /// at their singular shape parameters, or an overflow).
    pub fn solve(&self) -> Result<Patch, Pde4Error> {
        let patch = self.solve_unchecked()?;
        let ts: Vec<f64> = (0..=8).map(|k| k as f64 / 8.0).collect();
        let pts = patch.grid(&ts, &ts);
        if let Some(i) = pts.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
            return Err(Pde4Error::NonFiniteSolution {
                u: ts[i / ts.len()],
                v: ts[i % ts.len()],
                method: format!("{:?}", self.method),
            });
        }
        Ok(patch)
    }

    fn solve_unchecked(&self) -> Result<Patch, Pde4Error> {
        let params = match &self.shape {
            Shape::All(p) => [*p; 3],
            Shape::PerComponent(p) => *p,
        };
        let [m, n] = self.terms;
        match (self.patch, self.method) {
            (PatchKind::TwoSided, meth) => {
                let meth = match meth {
                    SpecMethod::Exact => two_sided::Method::Exact,
                    SpecMethod::Paper => two_sided::Method::Paper,
                    SpecMethod::LeastSquares => two_sided::Method::LeastSquares,
                    SpecMethod::Galerkin => {
                        return Err(Pde4Error::Unsupported("method 'galerkin' is for four-sided patches (two-sided: exact, paper, least-squares)"))
                    }
                };
                Ok(Patch::Two(TwoSided::new(
                    params,
                    &self.forces,
                    m,
                    n,
                    meth,
                    self.boundary.as_ref(),
                )?))
            }
            (PatchKind::FourSided, meth) => {
                if self.boundary.is_some() {
                    return Err(Pde4Error::Unsupported(
                        "boundary curves are supported for two-sided patches only",
                    ));
                }
                let meth = match meth {
                    SpecMethod::Galerkin => four_sided::Method::Galerkin,
                    SpecMethod::Paper => four_sided::Method::Paper,
                    _ => {
                        return Err(Pde4Error::Unsupported(
                            "four-sided patches take method 'galerkin' or 'paper'",
                        ))
                    }
                };
                Ok(Patch::Four(FourSided::new(
                    params,
                    &self.forces,
                    m,
                    n,
                    meth,
                )?))
            }
        }
    }
}

impl Surface for Patch {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        match self {
            Patch::Two(p) => p.eval(u, v),
            Patch::Four(p) => p.eval(u, v),
        }
    }
    fn domain(&self) -> Domain {
        match self {
            Patch::Two(p) => p.domain(),
            Patch::Four(p) => p.domain(),
        }
    }
    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        match self {
            Patch::Two(p) => p.grid(us, vs),
            Patch::Four(p) => p.grid(us, vs),
        }
    }
}
