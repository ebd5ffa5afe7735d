//! Measurements of a fit: profile errors per view (the fitted mesh's
//! outline, extracted again by [`crate::profile::outline_of_mesh`], against
//! the sketch) and per-vertex errors against a ground-truth mesh; the
//! bounding-box baseline (the template scaled to the sketch's box).

use super::options::{Sketch, Template};
use super::{TemplateError, View};
use crate::mesh::{dot, norm, Mesh};
use crate::profile::{outline_of_mesh, profile_distance, OutlineOptions, Profile, ProfileDistance};
use std::collections::HashMap;

/// A mesh's outer outline in a view (default [`OutlineOptions`]).
pub fn mesh_outline(m: &crate::mesh::Mesh, view: View) -> Result<Vec<[f64; 2]>, TemplateError> {
    outline_of_mesh(m, view, &OutlineOptions::default())
        .map(|p| p.points().to_vec())
        .map_err(|e| TemplateError::NoOutline {
            view: view.name().into(),
            problem: e.to_string(),
        })
}

/// One view's profile error (relative values divide by the sketch's height).
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct ViewError {
    pub view: View,
    #[serde(flatten)]
    pub distance: ProfileDistance,
}

/// The fitted skin's outlines against the sketch's, for the views it has.
pub fn profile_errors(
    template: &Template,
    positions: &[[f64; 3]],
    sketch: &Sketch,
) -> Result<Vec<ViewError>, TemplateError> {
    profile_errors_with(template, positions, sketch, &mesh_outline)
}

/// [`profile_errors`] with the outlines from `outline` (a
/// [`super::memo::OutlineMemo`] of [`mesh_outline`] that the fit used: the
/// last level's outlines are then not extracted again).
pub fn profile_errors_with(
    template: &Template,
    positions: &[[f64; 3]],
    sketch: &Sketch,
    outline: &super::OutlineFn,
) -> Result<Vec<ViewError>, TemplateError> {
    let skin = template.skin_at(positions);
    let mut out = Vec::new();
    let mut views = vec![(View::Front, &sketch.front)];
    if let Some(s) = &sketch.side {
        views.push((View::Side, s));
    }
    for (view, pts) in views {
        let bad = |e: crate::profile::ProfileError| TemplateError::BadProfile {
            what: format!("the {} profile", view.name()),
            problem: e.to_string(),
        };
        let fitted = Profile::new(view, outline(&skin, view)?).map_err(bad)?;
        let sketched = Profile::new(view, pts.clone()).map_err(bad)?;
        out.push(ViewError {
            view,
            distance: profile_distance(&fitted, &sketched),
        });
    }
    Ok(out)
}

/// RMS and max per-vertex distance between two equally indexed point sets,
/// divided by `height`.
pub fn vertex_errors(a: &[[f64; 3]], b: &[[f64; 3]], height: f64) -> (f64, f64) {
    let mut s2 = 0.0;
    let mut mx = 0.0f64;
    for (p, q) in a.iter().zip(b) {
        let d2 = (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2);
        s2 += d2;
        mx = mx.max(d2.sqrt());
    }
    ((s2 / a.len().max(1) as f64).sqrt() / height, mx / height)
}

/// The baseline: every template vertex scaled (per axis) and moved so the
/// skin's bounding box matches the sketch's front box (x, y) and, when
/// given, the side box (z); without a side profile z is scaled like y.
pub fn bbox_baseline(template: &Template, sketch: &Sketch) -> Vec<[f64; 3]> {
    let (lo, hi) = super::polygon::bbox(&sketch.front);
    let mut tlo = [f64::INFINITY; 3];
    let mut thi = [f64::NEG_INFINITY; 3];
    for p in &template.skin.positions {
        for k in 0..3 {
            tlo[k] = tlo[k].min(p[k]);
            thi[k] = thi[k].max(p[k]);
        }
    }
    let sx = (hi[0] - lo[0]) / (thi[0] - tlo[0]);
    let sy = (hi[1] - lo[1]) / (thi[1] - tlo[1]);
    let (sz, z0) = match &sketch.side {
        Some(s) => {
            let (slo, shi) = super::polygon::bbox(s);
            ((shi[0] - slo[0]) / (thi[2] - tlo[2]), slo[0])
        }
        None => (sy, 0.5 * (tlo[2] + thi[2]) - sy * 0.5 * (thi[2] - tlo[2])),
    };
    template
        .mesh
        .positions
        .iter()
        .map(|p| {
            [
                lo[0] + sx * (p[0] - tlo[0]),
                lo[1] + sy * (p[1] - tlo[1]),
                z0 + sz * (p[2] - tlo[2]),
            ]
        })
        .collect()
}

/// Dihedral angle (radians, 0 for a flat pair) across every interior edge
/// of `m` (edges with exactly two faces), keyed by the edge's vertices;
/// `None` for an edge next to a degenerate face.
pub fn dihedral_angles(m: &Mesh) -> HashMap<(u32, u32), Option<f64>> {
    let normal = |t: usize| {
        let n = m.face_normal_area(t);
        let l = norm(n);
        (l > 0.0).then(|| n.map(|x| x / l))
    };
    let mut faces: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (f, t) in m.triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            faces.entry((a.min(b), a.max(b))).or_default().push(f);
        }
    }
    faces
        .into_iter()
        .filter_map(|(e, f)| {
            let [f0, f1] = f[..] else { return None };
            let ang = normal(f0)
                .zip(normal(f1))
                .map(|(a, b)| dot(a, b).clamp(-1.0, 1.0).acos());
            Some((e, ang))
        })
        .collect()
}
/// A crease: the largest increase of the dihedral angle (radians) across
/// an interior edge of the skin from `rest` to `moved` (same topology),
/// over edges whose two vertices (at rest) satisfy `region`.
pub fn crease(rest: &Mesh, moved: &Mesh, region: &dyn Fn(&[f64; 3]) -> bool) -> f64 {
    creases(rest, moved, &[region])[0]
}

/// A region of the rest mesh: whether a vertex (at rest) lies in it.
pub type Region<'a> = &'a dyn Fn(&[f64; 3]) -> bool;

/// [`crease`] for each of `regions`, the dihedral angles computed once.
pub fn creases(rest: &Mesh, moved: &Mesh, regions: &[Region]) -> Vec<f64> {
    let masks: Vec<Vec<bool>> = regions
        .iter()
        .map(|region| rest.positions.iter().map(region).collect())
        .collect();
    let masks: Vec<&[bool]> = masks.iter().map(Vec::as_slice).collect();
    creases_in(rest, moved, &masks)
}

/// [`crease`] for each region given as a mask over `rest`'s vertices (an
/// edge counts when both its vertices are in the region).
pub fn creases_in(rest: &Mesh, moved: &Mesh, masks: &[&[bool]]) -> Vec<f64> {
    let (a, b) = (dihedral_angles(rest), dihedral_angles(moved));
    let inside = |m: &[bool], i: u32| m.get(i as usize).copied().unwrap_or(false);
    masks
        .iter()
        .map(|m| {
            a.iter()
                .filter(|(e, _)| inside(m, e.0) && inside(m, e.1))
                .filter_map(|(e, x)| Some(b.get(e).copied().flatten()? - (*x)?))
                .fold(0.0, f64::max)
        })
        .collect()
}
