//! The `edit` family's checks of the 4-sided force inside a closed stroke
//! ([`Edit::ForceStroke`], [`super::stroke`]): C0 and C1 on the stroke,
//! zero outside, the map one-to-one, and a rectangle stroke reproducing the
//! rectangle force ([`Edit::ForceRegion`]).

use super::{field_of, ForceField};
use crate::character::assembly::Displacement;
use crate::character::doc::CharacterDoc;
use crate::character::log::stroke::StrokeMap;
use crate::character::log::Edit;
use crate::character::spec::PartSpec;
use crate::check::Worst;
use crate::check::{tol, Check, Kind};
use crate::mesh::norm;
use crate::pde4::{Force, ForceKind};
use std::f64::consts::PI;

/// Points of the sample stroke.
pub const SAMPLE_STROKE_POINTS: usize = 96;
/// Samples per direction of the grids of these checks.
const GRID: usize = 128;
/// Steps (box units) of the one-sided difference quotients at the stroke:
/// `H0`, `H0 / 4`, `H0 / 16`.
const H0: f64 = 1e-3;
/// Largest departure of the observed order of `|D(x + h n)| / h` (x on the
/// stroke, n its inward normal) from 1 (a displacement that leaves the
/// stroke with zero slope grows as `h^2`).
pub const C1_ORDER_TOL: f64 = 0.1;

/// A closed stroke in the middle of a part's parameters: a rounded
/// three-lobed curve `r = 1 + 0.2 cos 3 phi` (not convex: its curvature
/// changes sign between the lobes) over the middle half of the part's u
/// range by `[theta_c - 0.6, theta_c + 0.6]`, its last point repeating the
/// first.
pub fn sample_stroke(p: &PartSpec, theta_c: f64) -> Vec<[f64; 2]> {
    let (u0, u1) = (p.sections[0].u, p.sections[p.sections.len() - 1].u);
    let (uc, ru) = (0.5 * (u0 + u1), 0.25 * (u1 - u0) / 1.2);
    let rt = 0.6 / 1.2;
    (0..=SAMPLE_STROKE_POINTS)
        .map(|k| {
            let phi = 2.0 * PI * (k % SAMPLE_STROKE_POINTS) as f64 / SAMPLE_STROKE_POINTS as f64;
            let r = 1.0 + 0.2 * (3.0 * phi).cos();
            [uc + ru * r * phi.cos(), theta_c + rt * r * phi.sin()]
        })
        .collect()
}

/// The sample stroke force on a part: an area force in the middle of the
/// patch inside [`sample_stroke`], pushing along `push`.
pub fn sample_force_stroke(p: &PartSpec, theta_c: f64, push: [f64; 3]) -> Edit {
    Edit::ForceStroke {
        part: p.name.clone(),
        stroke: sample_stroke(p, theta_c),
        corners: None,
        force: Force {
            kind: ForceKind::Area {
                u0: 0.2,
                u1: 0.8,
                v0: 0.25,
                v1: 0.75,
            },
            p: push,
        },
        a: 1.0,
    }
}

/// The boundary of the rectangle `u x theta` as a closed stroke of
/// `per_side` edges per side, counter-clockwise from `(u_a, theta_a)`, and
/// its corner indices.
pub fn rectangle_stroke(
    u: [f64; 2],
    theta: [f64; 2],
    per_side: usize,
) -> (Vec<[f64; 2]>, [usize; 4]) {
    let c = [
        [u[0], theta[0]],
        [u[1], theta[0]],
        [u[1], theta[1]],
        [u[0], theta[1]],
    ];
    let mut pts = Vec::with_capacity(4 * per_side + 1);
    for k in 0..4 {
        let (a, b) = (c[k], c[(k + 1) % 4]);
        for j in 0..per_side {
            let t = j as f64 / per_side as f64;
            pts.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }
    pts.push(c[0]);
    (pts, [0, per_side, 2 * per_side, 3 * per_side])
}

/// What the stroke checks measure on one stroke force edit.
#[derive(Clone, Copy, Debug)]
pub struct StrokeMeasures {
    /// Largest displacement on the stroke / peak.
    pub c0: f64,
    /// `max |D(x + h n)| / h / peak` at the smallest step (box units).
    pub slope: f64,
    /// Observed order of that quotient over the three steps.
    pub order: f64,
    /// Largest displacement off the stroke's inside / peak.
    pub outside: f64,
    /// Grid cells ([`GRID`]) inside the stroke whose image folds.
    pub folded: usize,
    /// Inside grid points where the map's Jacobian is not positive.
    pub negative_jacobians: usize,
    /// Smallest Jacobian over the inside grid points.
    pub min_jacobian: f64,
}

/// The measures of a stroke force edit (`None` for other edits or a
/// failing one).
pub fn stroke_measures(e: &Edit) -> Option<StrokeMeasures> {
    let Some(Ok((u, field))) = field_of(e) else {
        return None;
    };
    let ForceField::Stroke { map, .. } = &field else {
        return None;
    };
    let d = Displacement {
        part: e.part()?.to_string(),
        u,
        field: std::sync::Arc::new(field.clone()),
    };
    // part parameters of box point x
    let at = |x: [f64; 2]| {
        d.at(
            u[0] + x[0] * (u[1] - u[0]),
            map.theta[0] + x[1] * (map.theta[1] - map.theta[0]),
        )
    };
    let mut peak = 0.0f64;
    let (mut folded_pts, mut min_jac) = (0usize, f64::INFINITY);
    for i in 1..GRID {
        for j in 1..GRID {
            let x = [i as f64 / GRID as f64, j as f64 / GRID as f64];
            if map.contains(x) {
                peak = peak.worst(norm(at(x)));
                let jac = map.jacobian(x, tol::CENTRAL_DIFFERENCE);
                min_jac = min_jac.least(jac);
                if jac.is_nan() || jac <= 0.0 {
                    folded_pts += 1;
                }
            }
        }
    }
    let (c0, q) = on_stroke(map, &at);
    let outside = outside(map, &d, u);
    let (folded, _) = map.folded_cells(GRID);
    (peak > 0.0).then(|| StrokeMeasures {
        c0: c0 / peak,
        slope: q[2] / peak,
        order: (q[1] / q[2]).ln() / 4f64.ln(),
        outside: outside / peak,
        folded,
        negative_jacobians: folded_pts,
        min_jacobian: min_jac,
    })
}

/// The largest displacement at the stroke's vertices and edge midpoints,
/// and the largest `|D(x + h n)| / h` there for the three steps.
fn on_stroke(map: &StrokeMap, at: &dyn Fn([f64; 2]) -> [f64; 3]) -> (f64, [f64; 3]) {
    let p = &map.poly;
    let n = p.len();
    let (mut c0, mut q) = (0.0f64, [0.0f64; 3]);
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        c0 = c0.worst(norm(at(a))).worst(norm(at(m)));
        let l = (b[0] - a[0]).hypot(b[1] - a[1]);
        let nrm = [-(b[1] - a[1]) / l, (b[0] - a[0]) / l];
        for (k, qk) in q.iter_mut().enumerate() {
            let h = H0 / 4f64.powi(k as i32);
            if l < 4.0 * H0 {
                continue;
            }
            *qk = qk.worst(norm(at([m[0] + h * nrm[0], m[1] + h * nrm[1]])) / h);
        }
    }
    (c0, q)
}

/// The largest displacement at part-parameter samples (u over twice the
/// stroke's range, every angle) off the stroke's inside.
fn outside(map: &StrokeMap, d: &Displacement, u: [f64; 2]) -> f64 {
    let l = u[1] - u[0];
    let mut worst = 0.0f64;
    for i in 0..=2 * GRID {
        let uu = u[0] - 0.5 * l + 2.0 * l * i as f64 / (2 * GRID) as f64;
        for j in 0..2 * GRID {
            let th = map.theta[0] - PI + 2.0 * PI * j as f64 / (2 * GRID) as f64;
            let x = [(uu - u[0]) / l, map.y_of(th)];
            if !map.contains(x) {
                worst = worst.worst(norm(d.at(uu, th)));
            }
        }
    }
    worst
}

/// Largest difference between the displacements of a rectangle force and
/// the same rectangle given as a stroke, over part-parameter samples, /
/// the peak displacement.
pub fn rectangle_difference(region: &Edit) -> f64 {
    let Edit::ForceRegion {
        part,
        u,
        theta,
        force,
        a,
    } = region
    else {
        return f64::NAN;
    };
    let (stroke, corners) = rectangle_stroke(*u, *theta, 16);
    let stroke_edit = Edit::ForceStroke {
        part: part.clone(),
        stroke,
        corners: Some(corners),
        force: *force,
        a: *a,
    };
    let disp = |e: &Edit| {
        field_of(e)
            .and_then(|r| r.ok())
            .map(|(u, field)| Displacement {
                part: part.clone(),
                u,
                field: std::sync::Arc::new(field),
            })
    };
    let (Some(r), Some(s)) = (disp(region), disp(&stroke_edit)) else {
        return f64::NAN;
    };
    let (mut peak, mut diff) = (0.0f64, 0.0f64);
    let l = u[1] - u[0];
    for i in 0..=GRID {
        let uu = u[0] - 0.25 * l + 1.5 * l * i as f64 / GRID as f64;
        for j in 0..GRID {
            let th = theta[0] - 0.5 + (theta[1] - theta[0] + 1.0) * j as f64 / GRID as f64;
            let (x, y) = (r.at(uu, th), s.at(uu, th));
            peak = peak.worst(norm(x));
            diff = diff.worst(norm([x[0] - y[0], x[1] - y[1], x[2] - y[2]]));
        }
    }
    if peak > 0.0 {
        diff / peak
    } else {
        f64::NAN
    }
}

/// The stroke force checks on the document's first part (the torso).
pub fn checks(doc: &CharacterDoc, mesh_local: impl Fn(&Edit) -> f64) -> Vec<Check> {
    let c = |eq: &str, n: &str, kind, m: f64, t: f64| {
        Check::new("edit", "000", eq, &format!("edit.{n}"), kind, m, t)
    };
    let torso = &doc.parts()[0];
    let e = sample_force_stroke(torso, 0.8, [0.0, 0.0, 5.0]);
    let m = stroke_measures(&e);
    let get = |f: &dyn Fn(&StrokeMeasures) -> f64| m.as_ref().map(f).unwrap_or(f64::NAN);
    let mut out = vec![
        c("sec 5.1 eq 10", "force_stroke_clamped_c0", Kind::Boundary, get(&|m| m.c0), tol::ROUNDING).note(
            "4-sided force inside a closed three-lobed (non-convex) stroke on the torso, mean value map onto the square: largest displacement at the stroke's 96 vertices and edge midpoints / peak",
        ),
        c("sec 5.1 eq 10", "force_stroke_c1_order", Kind::Continuity, get(&|m| (m.order - 1.0).abs()), C1_ORDER_TOL).note(
            "stroke force: |D(x + h n)| / h at the stroke's edge midpoints (n inward, h = 1e-3, 2.5e-4, 6.25e-5 of the box) falls as h^1 (|observed order - 1|): the displacement leaves the stroke with zero slope, C1 across it",
        ),
        c("sec 5.1", "force_stroke_outside", Kind::Threshold, get(&|m| m.outside), 0.0).note(
            "stroke force: largest displacement at 257 x 256 part-parameter samples off the stroke's inside (u over twice its range, every angle) / peak (exactly zero)",
        ),
        c("sec 5.1", "force_stroke_one_to_one", Kind::Threshold, get(&|m| (m.folded + m.negative_jacobians) as f64), 0.0).note(
            "stroke force: grid cells (128 x 128 over the stroke's box) inside the stroke whose image folds, plus inside grid points with a non-positive Jacobian (central differences)",
        ),
        c("sec 5.1", "force_stroke_rectangle", Kind::Reference, rectangle_difference(&super::samples::sample_force_region(torso, 0.2, [0.0, 0.0, 5.0])), tol::ROUNDING).note(
            "the sample rectangle force given as a closed stroke (16 points a side, its corners): largest displacement difference from the rectangle force over the part's parameters / peak (linear precision of the mean value map)",
        ),
    ];
    out.push(
        c("sec 5.1", "force_stroke_mesh_local", Kind::Threshold, mesh_local(&e), 0.0).note(
            "stroke force on the female: vertices moved outside the torso's group (the edit did move torso vertices; NaN if not)",
        ),
    );
    out
}
