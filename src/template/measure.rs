//! Measurements of a fit: profile errors per view (the fitted mesh's
//! outline, extracted again by [`crate::profile::outline_of_mesh`], against
//! the sketch) and per-vertex errors against a ground-truth mesh; the
//! bounding-box baseline (the template scaled to the sketch's box).

use super::fit::{Sketch, Template};
use super::{TemplateError, View};
use crate::profile::{outline_of_mesh, profile_distance, OutlineOptions, Profile, ProfileDistance};

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
        let fitted = Profile::new(view, mesh_outline(&skin, view)?).map_err(bad)?;
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
