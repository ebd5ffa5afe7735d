//! The ear from four curves (paper 004 Fig 9e-f: "the curve network can
//! also be used to generate detailed areas, such as the ear part, which
//! uses 4 curves to reconstruct the ear part").
//!
//! The face's machinery ([`super::template`], [`super::extract`]) seen
//! from the side: the mesh is turned so that the left ear (`+x`) faces the
//! viewer (`view = (zc - z, y, x)`, a rotation about `y` and a shift), the
//! ear region is what [`super::template::face_region`] finds in
//! [`EAR_WINDOW`] (frontmost skin facing the viewer, connected to the
//! ear's outermost point), and **three columns of one patch each** span
//! the window between **four column curves**; their cross derivatives are
//! read off the skin beside them, as for the face. Every region vertex is
//! regenerated at its `(u, v)`; errors are against the input's vertices.
//! A single-valued patch over the side view cannot follow the helix where
//! it folds over itself, nor the step from the ear's rim down to the
//! scalp inside the window: the worst vertices are there.

use super::extract::{errors, face_network};
use super::template::FaceTemplate;
use super::{FaceError, Window};
use crate::mesh::Mesh;
use crate::ode6::network::doc::DEFAULT_PARAMS;
use crate::ode6::network::Network;

/// The ear's window in the side view (decimetres, the view frame's `x` is
/// `EAR_CENTRE_Z - z`). Chosen from the base's side view: the ear spans
/// `z` 0.33..0.60 and `y` 6.95..7.38 where the skin stands out more than
/// 0.74 dm from the midline; not tuned to any error.
pub const EAR_WINDOW: Window = Window {
    a: 0.15,
    y_hi: 7.40,
    y_chin: 6.93,
    y_jaw: 6.93,
};
/// The `z` of the ear window's vertical axis.
pub const EAR_CENTRE_Z: f64 = 0.46;
/// Columns of patches: four column curves.
pub const EAR_COLUMNS: usize = 3;
/// Rows of patches (one patch per column) and samples per row.
const EAR_ROWS: usize = 1;
const EAR_PER_ROW: usize = 16;

fn to_view(p: [f64; 3]) -> [f64; 3] {
    [EAR_CENTRE_Z - p[2], p[1], p[0]]
}

/// A point of the ear's view frame back in the model frame.
pub fn from_view(q: [f64; 3]) -> [f64; 3] {
    [q[2], q[1], EAR_CENTRE_Z - q[0]]
}

/// What the ear rebuild measured.
#[derive(Clone, Debug, serde::Serialize)]
pub struct EarReport {
    /// Ear-region vertices regenerated.
    pub vertices: usize,
    pub column_curves: usize,
    pub patches: usize,
    /// Largest and RMS distance (dm) of a regenerated vertex from the
    /// input's, and the worst vertex.
    pub max_error: f64,
    pub rms_error: f64,
    pub worst_vertex: u32,
    /// The ear region's height (dm) and the errors relative to it.
    pub ear_height: f64,
    pub max_relative: f64,
    pub rms_relative: f64,
    /// Points on the four column curves (nodes included).
    pub curve_points: usize,
}

/// Rebuilds the left ear of `mesh` (base topology; `body[t]` marks skin
/// triangles): the output positions (the ear region regenerated, the rest
/// kept), the report and the network (in the view frame).
pub fn rebuild_ear(
    mesh: &Mesh,
    body: &[bool],
) -> Result<(Vec<[f64; 3]>, EarReport, Network), FaceError> {
    let mut view = mesh.clone();
    view.map_positions(to_view);
    let t = FaceTemplate::new(
        &view,
        body,
        EAR_WINDOW,
        (EAR_COLUMNS, EAR_ROWS, EAR_PER_ROW),
    )?;
    let net = Network::build(face_network(
        &t,
        &view.positions,
        &[DEFAULT_PARAMS; EAR_COLUMNS],
    ))?;
    let n = t.vertices.len();
    if n == 0 {
        return Err(FaceError::Template(
            "no ear region in the ear window".into(),
        ));
    }
    // distances are the same in the view frame (a rotation and a shift)
    let (max, rms, worst, regenerated) = errors(&t, &net, &view.positions);
    let mut out = mesh.positions.clone();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (p, s) in t.vertices.iter().zip(regenerated) {
        let y = mesh.positions[p.vertex as usize][1];
        lo = lo.min(y);
        hi = hi.max(y);
        out[p.vertex as usize] = from_view(s);
    }
    let height = hi - lo;
    let curve_points = t.columns.iter().map(Vec::len).sum();
    let report = EarReport {
        vertices: n,
        column_curves: EAR_COLUMNS + 1,
        patches: EAR_COLUMNS * EAR_ROWS,
        max_error: max,
        rms_error: rms,
        worst_vertex: worst,
        ear_height: height,
        max_relative: max / height,
        rms_relative: rms / height,
        curve_points,
    };
    Ok((out, report, net))
}
