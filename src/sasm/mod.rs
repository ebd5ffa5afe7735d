//! Sketch-assisted shape manipulation, SASM (paper 000 sec 5.3, Fig 10):
//! local features grown out of a character part from strokes drawn in a
//! view.
//!
//! Two inputs, one construction:
//! - **sketch on the model** ([`SasmSpec`], Fig 10a, a breast): a closed
//!   stroke in a view (the feature's outline on the part) plus one or two
//!   profile strokes in other views (the feature's silhouette there);
//! - **auxiliary line** ([`AuxSpec`], Fig 10b, a nose): an open stroke along
//!   one half of the interface between feature and part, mirrored about the
//!   character's symmetry axis to close it, plus the main profile (the
//!   side-view contour of the feature).
//!
//! # What is built, and why
//! Strokes are 2D in a [`View`] (model units, the conventions of
//! `crate::profile`); the viewer sits on the positive side of the view's
//! third (depth) axis. [`project`] casts rays along the depth axis onto the
//! part's analytic surface (the C2 pde6 chain): a cell search on a sampled
//! grid, then Newton on `P(S(u, theta)) = q`, the first hit kept, so every
//! stroke point gets its `(u, theta)` and 3D point to rounding.
//!
//! The region ([`region`]) is the closed stroke's interior, star-shaped
//! about the feature's peak; its polar radius `R(phi)` is fitted by a
//! Fourier series ([`region::HARMONICS`] terms, the deviation from the
//! stroke reported), so the join curve is smooth. The feature ([`feature`])
//! is a **displacement of the part along the depth axis** by a height field
//! `h(rho, phi)` over the view plane (`rho = r / R(phi)`): the profile gives
//! the height along its rays (up/down from a side profile, left/right from a
//! top profile), blended in angle by `cos^2`/`sin^2` weights, and multiplied
//! by a smoothstep that brings `h` and its gradient to exactly zero at
//! `rho = 1` over the outer [`feature::BLEND`] of each radius. Hence the
//! edited surface `S + h e_depth` equals the host on the curve (C0) and
//! shares its tangent plane there (C1), for any stroke and profile; both are
//! measured on the surface by [`check`]. Displacing along the view
//! direction keeps each point's projection in the stroke's view, so the
//! feature lies inside the closed stroke there by construction (measured).
//!
//! Why a displacement and not a separate patch: the character stays one
//! watertight mesh with the topology of the sketch build; a fourth-order PDE
//! patch would need its own boundary stitched to the part's triangles. The
//! host mesh (48 vertices per ring) is too coarse for a breast or a nose, so
//! [`apply`] first refines the part's triangles around the region (1-to-4
//! splits with red-green closure, conforming, hence still watertight) to a
//! target edge of [`apply::EDGE_PER_DIAMETER`] per region diameter; the
//! vertices inside the region are placed on the analytic surface and
//! displaced, every vertex outside is left bit for bit.
//!
//! As edits ([`edit`]): `Edit::Sasm` and `Edit::SasmAux` of the character
//! log are validated against the built part when pushed and applied to the
//! built mesh in log order with the plate edits.
//!
//! Simpler than the paper: the feature is a height field in one view (no
//! overhangs, no undercut beyond the view direction); the interior is C1
//! except at the peak, where the rays meet (a point where the profiles'
//! slopes differ).

pub mod apply;
pub mod check;
pub mod demo;
pub mod edit;
pub mod feature;
pub mod measure;
pub mod project;
pub mod region;
pub mod silhouette;

pub use apply::{apply_feature, ApplyReport};
pub use feature::Feature;

use crate::limits::Num;
use crate::profile::View;

pub use crate::character::log::{AuxSpec, SasmSpec, Stroke};

/// A closed stroke's ends must meet within this fraction of its length.
pub const CLOSE_TOLERANCE: f64 = 0.02;

/// An auxiliary line's ends must lie within this fraction of its length
/// from the mirror axis.
pub const AXIS_TOLERANCE: f64 = 0.05;

/// Most points in one stroke.
pub const MAX_POINTS: usize = 100_000;

/// Errors of SASM.
#[derive(Debug, thiserror::Error)]
pub enum SasmError {
    #[error("{what}: point {index} has a non-finite coordinate")]
    NonFinite { what: String, index: usize },
    #[error("{what}: {count} points (expected {min} to {MAX_POINTS})")]
    PointCount {
        what: String,
        count: usize,
        min: usize,
    },
    #[error("{what} is open: its ends are {} apart, more than {CLOSE_TOLERANCE} of its length {}", Num(*gap), Num(*length))]
    Open { what: String, gap: f64, length: f64 },
    #[error("{what}: {message}")]
    Shape { what: String, message: String },
    #[error("{what}: point {index} at ({}, {}) misses part '{part}' (no ray hit in the {view} view)", Num(at[0]), Num(at[1]))]
    Misses {
        what: String,
        part: String,
        view: View,
        index: usize,
        at: [f64; 2],
    },
    #[error("{what} is drawn in the {found} view; {expected}")]
    View {
        what: String,
        found: View,
        expected: String,
    },
    #[error("unknown part '{0}'")]
    UnknownPart(String),
    #[error("the region is not star-shaped about the feature's peak ({:.4}, {:.4}): {message}", centre[0], centre[1])]
    NotStarShaped { centre: [f64; 2], message: String },
    #[error("profile ({view} view) covers {covered:?} along the {axis} axis, but the feature spans {needed:?}")]
    ProfileShort {
        view: View,
        axis: &'static str,
        covered: [f64; 2],
        needed: [f64; 2],
    },
    #[error("mesh: {0}")]
    Mesh(String),
}

fn axis_name(a: usize) -> &'static str {
    ["x", "y", "z"][a]
}

/// The depth axis of a view (the one it does not show); the viewer is on
/// its positive side.
pub fn depth_axis(v: View) -> usize {
    let (h, w) = v.axes();
    3 - h - w
}

/// Checks a stroke's points: count, finiteness, no repeated consecutive
/// points. Returns the points with exact consecutive duplicates removed.
pub fn clean(what: &str, s: &[[f64; 2]], min: usize) -> Result<Vec<[f64; 2]>, SasmError> {
    if s.len() < min || s.len() > MAX_POINTS {
        return Err(SasmError::PointCount {
            what: what.into(),
            count: s.len(),
            min,
        });
    }
    if let Some(i) = s
        .iter()
        .position(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(SasmError::NonFinite {
            what: what.into(),
            index: i,
        });
    }
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(s.len());
    for p in s {
        if out.last() != Some(p) {
            out.push(*p);
        }
    }
    if out.len() < min {
        return Err(SasmError::PointCount {
            what: what.into(),
            count: out.len(),
            min,
        });
    }
    Ok(out)
}

/// Length of a polyline.
pub fn length(s: &[[f64; 2]]) -> f64 {
    s.windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum()
}

/// A closed stroke as a polygon without its repeated closing point
/// (validated: closed, simple, non-degenerate).
pub fn closed_polygon(what: &str, s: &[[f64; 2]]) -> Result<Vec<[f64; 2]>, SasmError> {
    let mut p = clean(what, s, 4)?;
    let len = length(&p);
    let (a, b) = (p[0], p[p.len() - 1]);
    let gap = (a[0] - b[0]).hypot(a[1] - b[1]);
    if len.is_nan() || len <= 0.0 || gap > CLOSE_TOLERANCE * len {
        return Err(SasmError::Open {
            what: what.into(),
            gap,
            length: len,
        });
    }
    if gap <= CLOSE_TOLERANCE * len {
        p.pop();
    }
    simple(what, &p)?;
    Ok(p)
}

/// The auxiliary line mirrored about `horizontal = mirror`, closed.
pub fn mirrored_polygon(
    what: &str,
    s: &[[f64; 2]],
    mirror: f64,
) -> Result<Vec<[f64; 2]>, SasmError> {
    let p = clean(what, s, 3)?;
    if !mirror.is_finite() {
        return Err(SasmError::Shape {
            what: what.into(),
            message: "the mirror axis is not finite".into(),
        });
    }
    let len = length(&p);
    for (k, e) in [p[0], p[p.len() - 1]].iter().enumerate() {
        if (e[0] - mirror).abs() > AXIS_TOLERANCE * len {
            return Err(SasmError::Shape {
                what: what.into(),
                message: format!(
                    "its {} end ({:.4}, {:.4}) is not on the mirror axis {mirror:.4} (an auxiliary line runs from the axis around to the axis)",
                    ["first", "last"][k],
                    e[0],
                    e[1]
                ),
            });
        }
    }
    let side = p
        .iter()
        .map(|q| q[0] - mirror)
        .fold(0.0, |a: f64, d| if d.abs() > a.abs() { d } else { a });
    if p.iter()
        .any(|q| (q[0] - mirror) * side < -AXIS_TOLERANCE * len)
    {
        return Err(SasmError::Shape {
            what: what.into(),
            message: "it crosses the mirror axis (draw one half of the interface)".into(),
        });
    }
    let mut poly: Vec<[f64; 2]> = p
        .iter()
        .map(|q| [mirror + (q[0] - mirror).abs() * side.signum(), q[1]])
        .collect();
    poly[0][0] = mirror;
    let last = poly.len() - 1;
    poly[last][0] = mirror;
    let back: Vec<[f64; 2]> = poly[1..last]
        .iter()
        .rev()
        .map(|q| [2.0 * mirror - q[0], q[1]])
        .collect();
    poly.extend(back);
    simple(what, &poly)?;
    Ok(poly)
}

fn simple(what: &str, p: &[[f64; 2]]) -> Result<(), SasmError> {
    crate::profile::Profile::new(View::Front, p.to_vec())
        .map(|_| ())
        .map_err(|e| SasmError::Shape {
            what: what.into(),
            message: e.to_string(),
        })
}
