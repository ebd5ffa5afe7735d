//! 4-sided sculpting forces inside a closed curve on a part (paper 000
//! sec 5.1, eqs 10-15): the displacement fields of force edits, 2-sided
//! ([`Edit::Force`]) and 4-sided ([`Edit::ForceRegion`] inside a parameter
//! rectangle, [`Edit::ForceStroke`] inside a closed stroke).
//!
//! The closed curve of a 4-sided force is the boundary of a rectangle
//! `[u_a, u_b] x [theta_a, theta_b]` of the part's parameter space (`u` the
//! part parameter, `theta` the section angle): on the part it is a closed
//! curve made of two section arcs and two lines of constant angle. Inside
//! it, a 4-sided pde4 patch (`pde4::four_sided`, Ritz-Galerkin in the eq 13
//! basis, all four edges clamped) maps affinely onto the rectangle
//! (`s = (u - u_a)/(u_b - u_a)`, `v = (theta - theta_a)/(theta_b -
//! theta_a)`); its solution is added to the part as a displacement. It
//! vanishes with both first derivatives on the curve (every basis function
//! `B_m(s) psi_n(v)` does), so the edited part equals the part on and
//! outside the curve and is C1 across it; outside the rectangle the field
//! is exactly zero. A curve of any simple shape (a closed stroke in the
//! part's parameters) uses the same patch through a mean value map of the
//! stroke's inside onto the square, bounded in its derivatives up to the
//! stroke, so the edit stays C1 across it (`crate::character::log::stroke`).

use crate::character::log::stroke::StrokeMap;
use crate::character::log::{Edit, EditError};
use crate::pde4::four_sided::Method as Method4;
use crate::pde4::two_sided::Method;
use crate::pde4::{FourSided, ShapeParams, TwoSided};
use crate::surface::Surface;
use std::f64::consts::PI;

/// Series terms `(M, N)` of a force edit's 2-sided patch (sine terms in u,
/// harmonics in v).
pub const FORCE_TERMS: (usize, usize) = (16, 8);

/// The 2-sided pde4 solution of a force edit (clamped at both ends of its
/// range: zero boundary curves and tangents), shape parameters
/// `a1 = 1, a2 = 2 a^2, a3 = a^4` (`ShapeParams::plate_ratio`: scaling all
/// three alike would only rescale the response).
pub fn force_field(e: &Edit) -> Result<TwoSided, EditError> {
    let Edit::Force { force, a, .. } = e else {
        return Err(EditError::Invalid {
            op: e.op(),
            part: e.part().unwrap_or("").into(),
            message: "not a force edit".into(),
        });
    };
    let p = ShapeParams::plate_ratio(*a);
    TwoSided::new(
        [p; 3],
        std::slice::from_ref(force),
        FORCE_TERMS.0,
        FORCE_TERMS.1,
        Method::Exact,
        None,
    )
    .map_err(|source| EditError::Patch {
        op: e.op(),
        part: e.part().unwrap_or("").into(),
        what: "force patch",
        source: Box::new(source),
    })
}

/// Galerkin terms `(M, N)` of a 4-sided force edit's patch.
pub const FORCE4_TERMS: (usize, usize) = (10, 10);

/// The displacement field of a force edit, in the patch's coordinates.
#[derive(Clone, Debug)]
pub enum ForceField {
    /// 2-sided: over a u-range, all the way round (`v = theta / 2 pi`).
    Two(TwoSided),
    /// 4-sided: inside the angle range `theta` (radians, `theta[0] <
    /// theta[1] <= theta[0] + 2 pi`) of the u-range.
    Four { patch: FourSided, theta: [f64; 2] },
    /// 4-sided inside a closed stroke: `s` across the stroke's u range, the
    /// patch evaluated at the stroke map's square coordinates.
    Stroke { patch: FourSided, map: StrokeMap },
}

impl ForceField {
    /// The displacement at patch coordinate `s` in `(0, 1)` along the
    /// u-range and angle `theta` (any real; zero outside a 4-sided patch's
    /// angle range).
    pub fn at(&self, s: f64, theta: f64) -> [f64; 3] {
        match self {
            ForceField::Two(f) => {
                let v = (theta / (2.0 * PI)).rem_euclid(1.0);
                let c = &f.comps;
                [c[0].eval(s, v), c[1].eval(s, v), c[2].eval(s, v)]
            }
            ForceField::Four { patch, theta: t } => match angle_coordinate(*t, theta) {
                Some(v) => patch.point(s, v),
                None => [0.0; 3],
            },
            ForceField::Stroke { patch, map } => match map.local(s, theta) {
                Some([x, y]) => patch.point(x, y),
                None => [0.0; 3],
            },
        }
    }
}

impl crate::character::assembly::DisplacementField for ForceField {
    fn at(&self, s: f64, theta: f64) -> [f64; 3] {
        ForceField::at(self, s, theta)
    }
}

/// `v = (theta - theta_a) / (theta_b - theta_a)` with `theta` taken modulo
/// `2 pi` after `theta_a`; `None` outside the open range.
pub fn angle_coordinate(range: [f64; 2], theta: f64) -> Option<f64> {
    let v = (theta - range[0]).rem_euclid(2.0 * PI) / (range[1] - range[0]);
    (v > 0.0 && v < 1.0).then_some(v)
}

/// The 4-sided pde4 solution of a 4-sided force edit (rectangle or
/// stroke): clamped on all four edges, shape parameters `a1 = 1, a2 = 2
/// a^2, a3 = a^4` (as the 2-sided force), [`FORCE4_TERMS`] Galerkin terms.
pub fn force_region_field(e: &Edit) -> Result<FourSided, EditError> {
    let (Edit::ForceRegion { force, a, .. } | Edit::ForceStroke { force, a, .. }) = e else {
        return Err(EditError::Invalid {
            op: e.op(),
            part: e.part().unwrap_or("").into(),
            message: "not a 4-sided force edit".into(),
        });
    };
    let p = ShapeParams::plate_ratio(*a);
    FourSided::new(
        [p; 3],
        std::slice::from_ref(force),
        FORCE4_TERMS.0,
        FORCE4_TERMS.1,
        Method4::Galerkin,
    )
    .map_err(|source| EditError::Patch {
        op: e.op(),
        part: e.part().unwrap_or("").into(),
        what: "4-sided force patch",
        source: Box::new(source),
    })
}

/// The displacement field of a force edit (2- or 4-sided) and its u-range;
/// `None` for other edits.
pub fn field_of(e: &Edit) -> Option<Result<([f64; 2], ForceField), EditError>> {
    match e {
        Edit::Force { u, .. } => Some(force_field(e).map(|f| (*u, ForceField::Two(f)))),
        Edit::ForceRegion { u, theta, .. } => Some(force_region_field(e).map(|patch| {
            (
                *u,
                ForceField::Four {
                    patch,
                    theta: *theta,
                },
            )
        })),
        Edit::ForceStroke { .. } => Some(stroke_map(e).and_then(|map| {
            let patch = force_region_field(e)?;
            Ok((map.u, ForceField::Stroke { patch, map }))
        })),
        _ => None,
    }
}

pub use crate::character::log::{stroke_map, THETA_SPAN_MAX, THETA_SPAN_MIN};
/// Smallest u range of a 4-sided force (rectangle or stroke's bounding
/// box) as a fraction of its part's u range.
pub const U_SPAN_MIN_FRACTION: f64 = 1e-3;
