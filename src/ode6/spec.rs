//! The JSON surface spec of `pdesculpt ode6 surface` and one-line
//! evaluation of `ode6 eval`: the types and the building live here so that
//! the CLI only parses, calls and prints.
//!
//! A spec names the ODE parameters, how the six constraint curves of eq 1
//! are made (approach 1, approach 2 or all six directly), an optional
//! sculpting force and the default tessellation. Curves are `fourier`,
//! `polyline`, `gec` (a generalized elliptic curve as serialized by
//! `pdesculpt gec`) or `hermite` (`{"start": [P, P', P''], "end": [...]}`).

use super::{Approach2, Basis, BoundaryCurves, Curve, DiffFormula, Force, Ode6Error};
use super::{Ode6Surface, Params};
use crate::curve::gec::Gec;
use crate::curve::Fourier3;
use crate::jet::Jet;
use crate::limits;
use serde::Deserialize;

/// Default tessellation intervals in u when neither the spec nor the caller
/// gives them.
pub const DEFAULT_NU: usize = 32;
/// Default tessellation intervals around v.
pub const DEFAULT_NV: usize = 64;

/// Largest tessellation of one patch in either direction.
pub const MAX_INTERVALS: usize = 4096;

/// One curve of a spec.
#[derive(Deserialize, Debug)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CurveSpec {
    Fourier(Fourier3),
    Polyline {
        points: Vec<[f64; 3]>,
        closed: bool,
    },
    /// A generalized elliptic curve (frame, centre, x and y coefficient pairs).
    Gec(Gec),
    /// An open quintic Hermite segment: `[P, P', P'']` at v = 0 and v = 1.
    Hermite {
        start: [[f64; 3]; 3],
        end: [[f64; 3]; 3],
    },
}

impl CurveSpec {
    /// Checks the curve's size against the limits and builds it.
    pub fn build(&self) -> Result<Curve, Ode6Error> {
        match self {
            CurveSpec::Polyline { points, .. } => {
                limits::check("polyline points", points.len(), limits::POLYLINE_POINTS)?;
            }
            CurveSpec::Fourier(f) => {
                limits::check(
                    "fourier harmonics",
                    f.cos.len().max(f.sin.len()),
                    limits::CURVE_HARMONICS,
                )?;
            }
            CurveSpec::Gec(g) => {
                limits::check(
                    "gec terms",
                    g.x.len().max(g.y.len()),
                    limits::CURVE_HARMONICS,
                )?;
            }
            CurveSpec::Hermite { .. } => {}
        }
        match self {
            CurveSpec::Fourier(f) => Ok(Curve::Fourier(f.clone())),
            CurveSpec::Polyline { points, closed } => Curve::from_polyline(points, *closed),
            CurveSpec::Gec(g) => {
                // Re-validate the frame and coefficients of deserialized data.
                let g = Gec::new(g.frame, g.centre, g.x.clone(), g.y.clone())?;
                Curve::from_gec(&g)
            }
            CurveSpec::Hermite { start, end } => Curve::hermite(*start, *end),
        }
    }
}

/// How the six constraint curves are made.
#[derive(Deserialize, Debug)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CurvesSpec {
    Approach1 {
        c1: CurveSpec,
        c4: CurveSpec,
        w: [f64; 4],
    },
    Approach2 {
        c1: CurveSpec,
        controls: [CurveSpec; 4],
        c4: CurveSpec,
        /// `[u2, u3, u5, u6]`.
        u: [f64; 4],
        #[serde(default = "three_point")]
        formula: DiffFormula,
    },
    Direct([CurveSpec; 6]),
}

fn three_point() -> DiffFormula {
    DiffFormula::ThreePoint
}

/// A surface spec.
#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub params: Params,
    pub curves: CurvesSpec,
    #[serde(default)]
    pub force: Option<Force>,
    #[serde(default)]
    pub nu: Option<usize>,
    #[serde(default)]
    pub nv: Option<usize>,
}

impl Spec {
    /// Builds the surface of the spec.
    pub fn build(&self) -> Result<Ode6Surface, Ode6Error> {
        let basis = Basis::new(self.params)?;
        let curves = match &self.curves {
            CurvesSpec::Approach1 { c1, c4, w } => {
                BoundaryCurves::approach1(c1.build()?, c4.build()?, *w)?
            }
            CurvesSpec::Approach2 {
                c1,
                controls,
                c4,
                u,
                formula,
            } => {
                let [a, b, c, d] = controls;
                let a2 = Approach2 {
                    u2: u[0],
                    u3: u[1],
                    u5: u[2],
                    u6: u[3],
                    formula: *formula,
                };
                BoundaryCurves::approach2(
                    c1.build()?,
                    [a.build()?, b.build()?, c.build()?, d.build()?],
                    c4.build()?,
                    &a2,
                )?
            }
            CurvesSpec::Direct(cs) => {
                let [a, b, c, d, e, f] = cs;
                BoundaryCurves::direct([
                    a.build()?,
                    b.build()?,
                    c.build()?,
                    d.build()?,
                    e.build()?,
                    f.build()?,
                ])?
            }
        };
        let s = Ode6Surface::new(basis, curves);
        match &self.force {
            Some(f) => s.with_force(f),
            None => Ok(s),
        }
    }

    /// The tessellation: the caller's values first, then the spec's, then
    /// [`DEFAULT_NU`] x [`DEFAULT_NV`]; checked against the limits.
    pub fn resolution(
        &self,
        nu: Option<usize>,
        nv: Option<usize>,
    ) -> Result<[usize; 2], Ode6Error> {
        let nu = nu.or(self.nu).unwrap_or(DEFAULT_NU);
        let nv = nv.or(self.nv).unwrap_or(DEFAULT_NV);
        limits::check("nu", nu, limits::TESS_NU)?;
        limits::check("nv", nv, limits::TESS_NV)?;
        if nu > MAX_INTERVALS || nv > MAX_INTERVALS {
            return Err(Ode6Error::Intervals {
                nu,
                nv,
                max: MAX_INTERVALS,
            });
        }
        Ok([nu, nv])
    }
}

/// One point of a scalar iso-parametric line (eq 19) with its derivatives
/// and the residual of eq 2 without force.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct LinePoint {
    pub u: f64,
    pub s: f64,
    pub s_u: f64,
    pub s_uu: f64,
    /// `rho S^(6) + eta S^(4) + lambda S''`.
    pub residual: f64,
}

/// Evaluates the line `S(u) = sum g_j(u) c_j` of eq 19 at each `u` in
/// [0, 1]; refuses values outside [0, 1] and results that are not finite
/// in double precision.
pub fn eval_line(basis: &Basis, c: &[f64; 6], at: &[f64]) -> Result<Vec<LinePoint>, Ode6Error> {
    if at.is_empty() {
        return Err(Ode6Error::NoParameterValues);
    }
    if let Some(x) = c.iter().chain(at).find(|x| !x.is_finite()) {
        return Err(Ode6Error::NonFiniteValue {
            what: "constraint or parameter value",
            value: *x,
        });
    }
    if let Some(&u) = at.iter().find(|u| !(0.0..=1.0).contains(*u)) {
        return Err(Ode6Error::OutOfRange {
            what: "u",
            value: u,
            range: "[0, 1] (the parameter of the iso-parametric line)",
        });
    }
    let Params { rho, eta, lambda } = basis.params;
    at.iter()
        .map(|&u| {
            let s = basis.line(Jet::<7, 1>::var_u(u), c);
            let p = LinePoint {
                u,
                s: s.deriv(0, 0),
                s_u: s.deriv(1, 0),
                s_uu: s.deriv(2, 0),
                residual: rho * s.deriv(6, 0) + eta * s.deriv(4, 0) + lambda * s.deriv(2, 0),
            };
            if [p.s, p.s_u, p.s_uu, p.residual]
                .iter()
                .all(|x| x.is_finite())
            {
                Ok(p)
            } else {
                Err(Ode6Error::LineOverflow {
                    u,
                    rho,
                    eta,
                    lambda,
                })
            }
        })
        .collect()
}
