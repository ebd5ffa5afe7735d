//! Measuring a built model's joins (C0/C1/C2 jumps of each transition
//! against its parts, normal jumps across seams) and orienting its mesh.

use super::part::PartSurface;
use super::ring::{RING_VERTICES, SEAM_VERTICES};
use super::transition::{eval as teval, loop_eval, Built, ChildTransition, Run};
use crate::mesh::{dist, norm, scale, sub, Mesh};
use crate::surface::cross;
use serde::Serialize;
use std::f64::consts::PI;

/// Jumps measured along one join (relative: C0 to the model height, C1 to
/// the largest scaled first part derivative along the join, C2 to the
/// largest scaled first or second one).
#[derive(Clone, Debug, Serialize)]
pub struct JoinReport {
    pub transition: String,
    pub part: String,
    pub samples: usize,
    pub c0: f64,
    pub c1: f64,
    pub c2: f64,
}

/// Normal jump across a seam between two sibling transitions.
#[derive(Clone, Debug, Serialize)]
pub struct SeamReport {
    pub transition: String,
    pub between: [String; 2],
    /// Largest angle between the two sides' normals along the seam (degrees).
    pub max_angle_deg: f64,
    /// The angle at the seam's apex (degrees).
    pub apex_angle_deg: f64,
}

/// Samples per loop vertex for the join measurements.
const JOIN_SAMPLES: usize = 3;

pub(super) fn measure(
    b: &Built,
    ct: &ChildTransition,
    parent: &PartSurface,
    name: &str,
    at_parent: bool,
    child: &PartSurface,
    height: f64,
) -> JoinReport {
    let (mut c0, mut c1, mut c2) = (0.0f64, 0.0f64, 0.0f64);
    let (mut s1, mut s2) = (0.0f64, 0.0f64);
    let mut samples = 0;
    let mut start = 0.0;
    let n_ring = RING_VERTICES as f64;
    for r in &ct.runs {
        let len = match r {
            Run::Arc { count, .. } => *count as f64,
            Run::Seam { .. } => (SEAM_VERTICES + 1) as f64,
        };
        let on_arc = matches!(r, Run::Arc { .. });
        if at_parent && !on_arc {
            start += len;
            continue;
        }
        let m = (len as usize) * JOIN_SAMPLES;
        for q in 0..m {
            let tau = start + len * q as f64 / m as f64;
            let (s, u, v, scl, surf) = if at_parent {
                let Run::Arc { from, count } = *r else {
                    unreachable!()
                };
                let f = (tau - start) / len;
                let phi = 2.0 * PI * (from as f64 + f * count as f64) / n_ring;
                (0.0, ct.parent_u, phi, ct.sgn * ct.ell_at(tau), parent)
            } else {
                let th = ct.theta0 + ct.sigma * 2.0 * PI * tau / ct.n as f64;
                (1.0, ct.child_u, th, ct.ell_at(tau), child)
            };
            let x0 = teval(ct, parent, child, &b.seams, s, tau, 0);
            let x1 = teval(ct, parent, child, &b.seams, s, tau, 1);
            let x2 = teval(ct, parent, child, &b.seams, s, tau, 2);
            let p0 = surf.point(u, v.rem_euclid(2.0 * PI));
            let p1 = scale(surf.derivative(u, v.rem_euclid(2.0 * PI), 1, 0), scl);
            let p2 = scale(surf.derivative(u, v.rem_euclid(2.0 * PI), 2, 0), scl * scl);
            c0 = c0.max(dist(x0, p0));
            c1 = c1.max(dist(x1, p1));
            c2 = c2.max(dist(x2, p2));
            s1 = s1.max(norm(p1));
            s2 = s2.max(norm(p2));
            samples += 1;
        }
        start += len;
    }
    JoinReport {
        transition: b.spec.name.clone(),
        part: name.into(),
        samples,
        c0: c0 / height,
        c1: c1 / s1.max(f64::MIN_POSITIVE),
        // relative to the larger of the scaled first and second
        // derivatives (both lengths): a part whose second derivative
        // vanishes along the join (a straight tube, the natural end of an
        // ode6 part) has no scale of its own to divide by
        c2: c2 / s2.max(s1).max(f64::MIN_POSITIVE),
    }
}

pub(super) fn measure_seam(b: &Built, j: usize, parts: &[PartSurface]) -> SeamReport {
    let (l, r) = (&b.cts[j], &b.cts[j + 1]);
    let parent = &parts[b.parent];
    // loop parameter of seam j's start in each child's loop
    let seam_tau = |ct: &ChildTransition| -> (f64, bool) {
        let mut start = 0.0;
        for run in &ct.runs {
            match *run {
                Run::Arc { count, .. } => start += count as f64,
                Run::Seam { j: jj, reversed } => {
                    if jj == j {
                        return (start, reversed);
                    }
                    start += (SEAM_VERTICES + 1) as f64;
                }
            }
        }
        (0.0, false)
    };
    let normal = |ct: &ChildTransition, child: usize, t: f64| -> [f64; 3] {
        let (st, rev) = seam_tau(ct);
        let f = if rev { 1.0 - t } else { t };
        let tau = st + f * (SEAM_VERTICES + 1) as f64;
        let h = 1e-5;
        let (a, _) = loop_eval(ct, parent, &b.seams, tau - h);
        let (c, _) = loop_eval(ct, parent, &b.seams, tau + h);
        let xt = sub(c, a);
        let xs = teval(ct, parent, &parts[child], &b.seams, 0.0, tau, 1);
        let nn = cross(xs, xt);
        scale(nn, 1.0 / norm(nn).max(f64::MIN_POSITIVE))
    };
    let angle = |t: f64| -> f64 {
        let a = normal(l, b.children[j], t);
        let c = normal(r, b.children[j + 1], t);
        // both cross tangent and seam tangent flip between the two sides,
        // so for a tangent-continuous surface the normals agree
        let d = crate::mesh::dot(a, c).clamp(-1.0, 1.0);
        d.acos().to_degrees()
    };
    let m = 40;
    let max = (1..m)
        .map(|k| angle(k as f64 / m as f64))
        .fold(0.0, f64::max);
    SeamReport {
        transition: b.spec.name.clone(),
        between: [
            parts[b.children[j]].name.clone(),
            parts[b.children[j + 1]].name.clone(),
        ],
        max_angle_deg: max,
        apex_angle_deg: angle(0.5),
    }
}

/// Makes triangle orientation consistent across shared edges (depth
/// first) and each connected component outward (positive signed volume).
pub fn orient(m: &mut Mesh) {
    let edges = super::crease::edge_triangles(m);
    let n = m.triangles.len();
    let mut seen = vec![false; n];
    for s in 0..n {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        let mut stack = vec![s];
        let mut component = vec![s];
        while let Some(t) = stack.pop() {
            let tr = m.triangles[t];
            for e in 0..3 {
                let (a, b) = (tr[e], tr[(e + 1) % 3]);
                for &o in edges.get((a.min(b), a.max(b))) {
                    let o = o as usize;
                    if o == t || seen[o] {
                        continue;
                    }
                    let to = m.triangles[o];
                    let same = (0..3).any(|k| to[k] == a && to[(k + 1) % 3] == b);
                    if same {
                        m.triangles[o].swap(1, 2);
                    }
                    seen[o] = true;
                    stack.push(o);
                    component.push(o);
                }
            }
        }
        // each closed component outward (separate removed parts)
        let vol: f64 = component
            .iter()
            .map(|&t| {
                let [a, b, c] = m.corners(t);
                crate::mesh::dot(a, cross(b, c))
            })
            .sum();
        if vol < 0.0 {
            for &t in &component {
                m.triangles[t].swap(1, 2);
            }
        }
    }
}
