//! Applying a feature to the character's mesh: local refinement of the
//! host part around the region (conforming, so the mesh stays watertight),
//! then the displacement of the vertices inside the region.
//!
//! The feature is added to the mesh as it is when the edit applies (log
//! order): a vertex of the mesh moves by the height along the depth axis,
//! so what an earlier force or plate edit did to it is kept; a vertex the
//! refinement adds is placed on the analytic surface plus the depth offset
//! of the mesh from that surface interpolated from its edge's ends (zero on
//! an unedited part), plus the height.

use super::feature::Feature;
use super::project::Projector;
use super::{depth_axis, SasmError};
use crate::character::part::PartSurface;
use crate::mesh::{dist, Mesh};
use serde::Serialize;
use std::collections::HashMap;

/// Target edge length: the region's diameter over this.
pub const EDGE_PER_DIAMETER: f64 = 48.0;
/// Most refinement levels.
pub const MAX_LEVELS: usize = 6;
/// Refinement reaches this far outside the curve (in rho).
const ZONE: f64 = 1.1;

/// What applying a feature did.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ApplyReport {
    pub part: String,
    pub refine_levels: usize,
    pub triangles_before: usize,
    pub triangles_after: usize,
    pub vertices_moved: usize,
    pub max_displacement: f64,
    /// Vertices inside the region whose ray missed the part (left alone).
    pub missed: usize,
}

fn edge(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// One red-green refinement step of the marked triangles; the new
/// vertices' edge ends are appended to `parents`.
fn refine(m: &mut Mesh, marked: &[bool], parents: &mut Vec<(u32, u32)>) {
    let mut split: HashMap<(u32, u32), u32> = HashMap::new();
    for (t, tr) in m.triangles.iter().enumerate() {
        if marked[t] {
            for e in 0..3 {
                split.insert(edge(tr[e], tr[(e + 1) % 3]), u32::MAX);
            }
        }
    }
    // closure: a triangle with two split edges gets its third split too
    loop {
        let mut changed = false;
        for tr in &m.triangles {
            let es = [edge(tr[0], tr[1]), edge(tr[1], tr[2]), edge(tr[2], tr[0])];
            let n = es.iter().filter(|e| split.contains_key(e)).count();
            if n == 2 {
                for e in es {
                    split.entry(e).or_insert(u32::MAX);
                }
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let mut keys: Vec<(u32, u32)> = split.keys().copied().collect();
    keys.sort_unstable();
    for k in keys {
        let (a, b) = (m.positions[k.0 as usize], m.positions[k.1 as usize]);
        m.positions.push([
            (a[0] + b[0]) / 2.0,
            (a[1] + b[1]) / 2.0,
            (a[2] + b[2]) / 2.0,
        ]);
        split.insert(k, (m.positions.len() - 1) as u32);
        parents.push(k);
    }
    let mut tris = Vec::with_capacity(m.triangles.len() * 2);
    let mut groups = Vec::with_capacity(m.triangles.len() * 2);
    for (t, tr) in m.triangles.iter().enumerate() {
        let g = m.tri_group[t];
        let mid = |e: usize| split.get(&edge(tr[e], tr[(e + 1) % 3])).copied();
        let ms = [mid(0), mid(1), mid(2)];
        let mut put = |x: [u32; 3]| {
            tris.push(x);
            groups.push(g);
        };
        match ms {
            [Some(ab), Some(bc), Some(ca)] => {
                put([tr[0], ab, ca]);
                put([ab, tr[1], bc]);
                put([ca, bc, tr[2]]);
                put([ab, bc, ca]);
            }
            [Some(ab), None, None] => {
                put([tr[0], ab, tr[2]]);
                put([ab, tr[1], tr[2]]);
            }
            [None, Some(bc), None] => {
                put([tr[0], tr[1], bc]);
                put([tr[0], bc, tr[2]]);
            }
            [None, None, Some(ca)] => {
                put([tr[0], tr[1], ca]);
                put([ca, tr[1], tr[2]]);
            }
            _ => put(*tr),
        }
    }
    m.triangles = tris;
    m.tri_group = groups;
}

/// Refines the host part around the feature and displaces it. Vertices
/// outside the region keep their positions bit for bit (the refinement
/// only appends vertices).
pub fn apply_feature(
    m: &mut Mesh,
    part: &PartSurface,
    f: &Feature,
) -> Result<ApplyReport, SasmError> {
    let g = m
        .groups
        .iter()
        .position(|n| *n == f.part)
        .ok_or_else(|| SasmError::UnknownPart(f.part.clone()))? as u32;
    if part.name != f.part {
        return Err(SasmError::UnknownPart(part.name.clone()));
    }
    let host = Host {
        f,
        pr: Projector::new(part, f.view),
        d: depth_axis(f.view),
        sheet: 0.25 * f.region.a0,
        g,
    };
    let mut rep = ApplyReport {
        part: f.part.clone(),
        triangles_before: m.triangles.len(),
        ..Default::default()
    };
    let n0 = m.positions.len();
    let mut parents: Vec<(u32, u32)> = Vec::new();
    rep.refine_levels = refine_zone(m, &host, &mut parents);
    let offset = new_vertex_offsets(m, &host, &parents, n0);
    displace(m, &host, &offset, n0, &mut rep);
    rep.triangles_after = m.triangles.len();
    Ok(rep)
}

/// A feature on its host part: the projector onto the part, the depth
/// axis, the sheet depth (how far behind the surface a vertex still
/// belongs to the front) and the part's triangle group.
struct Host<'a> {
    f: &'a Feature,
    pr: Projector<'a>,
    d: usize,
    sheet: f64,
    g: u32,
}

/// Refines the host part's triangles longer than the target edge with a
/// vertex in the zone (within [`ZONE`] of the curve, on the front sheet),
/// up to [`MAX_LEVELS`] times; the new vertices' edge ends go to
/// `parents`. Returns the number of levels.
fn refine_zone(m: &mut Mesh, host: &Host, parents: &mut Vec<(u32, u32)>) -> usize {
    let (f, pr, d, sheet, g) = (host.f, &host.pr, host.d, host.sheet, host.g);
    let target = 2.0 * f.region.max_radius() / EDGE_PER_DIAMETER;
    let mut levels = 0;
    // zone membership per vertex (positions of existing vertices never
    // change during refinement)
    let mut zone: Vec<Option<bool>> = Vec::new();
    let in_zone = |m: &Mesh, v: u32, zone: &mut Vec<Option<bool>>| -> bool {
        zone.resize(m.positions.len(), None);
        if let Some(z) = zone[v as usize] {
            return z;
        }
        let p = m.positions[v as usize];
        let q = f.view.project(p);
        let z =
            f.region.polar(q).0 < ZONE && pr.cast(q).is_some_and(|h| p[d] >= h.point[d] - sheet);
        zone[v as usize] = Some(z);
        z
    };
    for _ in 0..MAX_LEVELS {
        let mut marked = vec![false; m.triangles.len()];
        let mut any = false;
        for t in 0..m.triangles.len() {
            if m.tri_group[t] != g {
                continue;
            }
            let tr = m.triangles[t];
            let c = m.corners(t);
            let longest = dist(c[0], c[1]).max(dist(c[1], c[2])).max(dist(c[2], c[0]));
            if longest > target && tr.iter().any(|&v| in_zone(m, v, &mut zone)) {
                marked[t] = true;
                any = true;
            }
        }
        if !any {
            break;
        }
        refine(m, &marked, parents);
        levels += 1;
    }
    levels
}

/// The depth offset of the mesh from the analytic surface at each vertex
/// the refinement added (in order): measured at the vertices the mesh had
/// (the first `n0`), interpolated along edges for the new ones.
fn new_vertex_offsets(m: &Mesh, host: &Host, parents: &[(u32, u32)], n0: usize) -> Vec<f64> {
    let (f, pr, d, sheet) = (host.f, &host.pr, host.d, host.sheet);
    let mut measured: HashMap<u32, f64> = HashMap::new();
    let mut at = |v: u32, m: &Mesh| -> f64 {
        *measured.entry(v).or_insert_with(|| {
            let p = m.positions[v as usize];
            match pr.cast(f.view.project(p)) {
                Some(h) if (p[d] - h.point[d]).abs() <= sheet => p[d] - h.point[d],
                _ => 0.0,
            }
        })
    };
    let mut offset: Vec<f64> = Vec::with_capacity(parents.len());
    for &(a, b) in parents {
        let side = |x: u32, offset: &[f64], at: &mut dyn FnMut(u32, &Mesh) -> f64| {
            if (x as usize) < n0 {
                at(x, m)
            } else {
                offset[x as usize - n0]
            }
        };
        let o = 0.5 * (side(a, &offset, &mut at) + side(b, &offset, &mut at));
        offset.push(o);
    }
    offset
}

/// Moves the host part's vertices inside the region and on the front
/// sheet by the feature's height along the depth axis (a new vertex from
/// the analytic surface plus its `offset`); counts them, the misses and
/// the largest move in `rep`.
fn displace(m: &mut Mesh, host: &Host, offset: &[f64], n0: usize, rep: &mut ApplyReport) {
    let (f, pr, d, sheet, g) = (host.f, &host.pr, host.d, host.sheet, host.g);
    let mut on_host = vec![false; m.positions.len()];
    for (t, tr) in m.triangles.iter().enumerate() {
        if m.tri_group[t] == g {
            for &v in tr {
                on_host[v as usize] = true;
            }
        }
    }
    for v in 0..m.positions.len() {
        if !on_host[v] {
            continue;
        }
        let p = m.positions[v];
        let q = f.view.project(p);
        if f.region.polar(q).0.partial_cmp(&1.0) != Some(std::cmp::Ordering::Less) {
            continue;
        }
        let Some(hit) = pr.cast(q) else {
            rep.missed += 1;
            continue;
        };
        if p[d] < hit.point[d] - sheet {
            continue;
        }
        let mut np = if v < n0 { p } else { hit.point };
        np[d] += f.height(q) + if v < n0 { 0.0 } else { offset[v - n0] };
        rep.max_displacement = rep.max_displacement.max(dist(np, p));
        m.positions[v] = np;
        rep.vertices_moved += 1;
    }
}
