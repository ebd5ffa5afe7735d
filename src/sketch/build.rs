//! Assembling parts and transitions into one mesh with shared vertices at
//! every seam, and measuring the joins.

use super::part::{build_part, PartSurface};
use super::transition::{
    child_transition, cut_table, eval as teval, loop_eval, seams as make_seams, ChildTransition,
    Run, Seam, RING_VERTICES, SEAM_VERTICES,
};
use super::SketchError;
use crate::character::doc::{End, PartSpec, TransitionSpec};
use crate::mesh::{dist, norm, scale, sub, Mesh};
use crate::surface::{cross, Surface};
use serde::Serialize;
use std::f64::consts::PI;

/// Mesh resolution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolution {
    /// Rings per model height along a part.
    pub rings_per_height: f64,
    /// Rows across a transition.
    pub transition_rows: usize,
}

impl Default for Resolution {
    fn default() -> Resolution {
        Resolution {
            rings_per_height: 160.0,
            transition_rows: 10,
        }
    }
}

/// Jumps measured along one join (relative: C0 to the model height, C1 and
/// C2 to the largest scaled part derivative along the join).
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

/// A displacement field added to a part's surface over a u-range of the
/// part (a force edit of `character::edit`: the pde4 2-sided solution, which
/// vanishes with its u-derivative at both ends of the range, so the part
/// stays in place and C1 there and its ends, where transitions join, do not
/// move; or the 4-sided one inside an angle range too).
#[derive(Clone, Debug)]
pub struct Displacement {
    pub part: String,
    pub u: [f64; 2],
    pub field: crate::character::edit::ForceField,
}

impl Displacement {
    /// The displacement at part parameter `u`, angle `theta` (zero outside
    /// the range).
    pub fn at(&self, u: f64, theta: f64) -> [f64; 3] {
        let [a, b] = self.u;
        if u <= a || u >= b {
            return [0.0; 3];
        }
        self.field.at((u - a) / (b - a), theta)
    }
}

/// Built parts by specification: a rebuild re-solves only the parts whose
/// specification changed (an edit of one part re-solves that part only).
#[derive(Clone, Debug, Default)]
pub struct PartCache {
    entries: Vec<(PartSpec, PartSurface)>,
    /// Parts solved (cache misses) so far.
    pub solved: usize,
}

/// Most parts a [`PartCache`] keeps.
pub const PART_CACHE_SIZE: usize = 64;

impl PartCache {
    /// The built part of `spec`, solved only when not cached.
    pub fn get(&mut self, spec: &PartSpec) -> Result<PartSurface, SketchError> {
        if let Some((_, s)) = self.entries.iter().find(|(p, _)| p == spec) {
            return Ok(s.clone());
        }
        let s = build_part(spec)?;
        if self.entries.len() >= PART_CACHE_SIZE {
            self.entries.remove(0);
        }
        self.entries.push((spec.clone(), s.clone()));
        self.solved += 1;
        Ok(s)
    }
}

/// A built model: the mesh and the join measurements.
#[derive(Clone, Debug)]
pub struct Model {
    pub mesh: Mesh,
    pub parts: Vec<PartSurface>,
    pub joins: Vec<JoinReport>,
    pub seams: Vec<SeamReport>,
}

struct Tube {
    start: Vec<u32>,
    end: Vec<u32>,
}

fn push(m: &mut Mesh, p: [f64; 3]) -> u32 {
    m.positions.push(p);
    (m.positions.len() - 1) as u32
}

fn tri(m: &mut Mesh, g: u32, a: u32, b: u32, c: u32) {
    m.triangles.push([a, b, c]);
    m.tri_group.push(g);
}

/// Triangles between two rows (a row of one vertex is a pole).
fn band(m: &mut Mesh, g: u32, a: &[u32], b: &[u32]) {
    let n = a.len().max(b.len());
    for i in 0..n {
        let j = (i + 1) % n;
        match (a.len(), b.len()) {
            (1, _) => tri(m, g, a[0], b[j], b[i]),
            (_, 1) => tri(m, g, a[i], a[j], b[0]),
            _ => {
                tri(m, g, a[i], a[j], b[j]);
                tri(m, g, a[i], b[j], b[i]);
            }
        }
    }
}

fn tube(
    m: &mut Mesh,
    p: &PartSurface,
    thetas: &[f64],
    rows: usize,
    g: u32,
    disp: &[&Displacement],
) -> Tube {
    let mut prev: Vec<u32> = Vec::new();
    let mut first = Vec::new();
    for r in 0..=rows {
        let u = p.u0 + (p.u1 - p.u0) * r as f64 / rows as f64;
        let sec = p.chain.pieces[p.chain.piece_at(u)].global_section(u, 0);
        let pole = (r == 0 && p.closed_start) || (r == rows && p.closed_end);
        let row: Vec<u32> = if pole {
            vec![push(m, sec.c0)]
        } else {
            thetas
                .iter()
                .map(|&t| {
                    let mut x = sec.eval(t);
                    for d in disp {
                        let e = d.at(u, t);
                        x = [x[0] + e[0], x[1] + e[1], x[2] + e[2]];
                    }
                    push(m, x)
                })
                .collect()
        };
        if r == 0 {
            first = row.clone();
        } else {
            band(m, g, &prev, &row);
        }
        prev = row;
    }
    Tube {
        start: first,
        end: prev,
    }
}

struct Built {
    spec: TransitionSpec,
    parent: usize,
    children: Vec<usize>,
    seams: Vec<Seam>,
    cts: Vec<ChildTransition>,
}

/// Builds the mesh of parts and transitions and measures the joins.
pub fn build_model(
    specs: &[PartSpec],
    transitions: &[TransitionSpec],
    height: f64,
    res: Resolution,
) -> Result<Model, SketchError> {
    build_model_with(specs, transitions, height, res, &[], None)
}

/// [`build_model`] with displacement fields on parts (force edits) and an
/// optional cache of built parts (only changed parts are re-solved).
pub fn build_model_with(
    specs: &[PartSpec],
    transitions: &[TransitionSpec],
    height: f64,
    res: Resolution,
    displacements: &[Displacement],
    cache: Option<&mut PartCache>,
) -> Result<Model, SketchError> {
    let parts = match cache {
        Some(c) => specs
            .iter()
            .map(|s| c.get(s))
            .collect::<Result<Vec<_>, _>>()?,
        None => specs
            .iter()
            .map(build_part)
            .collect::<Result<Vec<_>, _>>()?,
    };
    for d in displacements {
        if !parts.iter().any(|p| p.name == d.part) {
            return Err(SketchError::Document(format!(
                "a displacement names unknown part '{}'",
                d.part
            )));
        }
    }
    let find = |n: &str| -> Result<usize, SketchError> {
        parts
            .iter()
            .position(|p| p.name == n)
            .ok_or_else(|| SketchError::Document(format!("unknown part '{n}'")))
    };
    let mut built = Vec::new();
    let mut thetas: Vec<Option<Vec<f64>>> = vec![None; parts.len()];
    let uniform: Vec<f64> = (0..RING_VERTICES)
        .map(|i| 2.0 * PI * i as f64 / RING_VERTICES as f64)
        .collect();
    for t in transitions {
        let pi = find(&t.parent)?;
        let ci: Vec<usize> = t
            .children
            .iter()
            .map(|c| find(c))
            .collect::<Result<_, _>>()?;
        let k = ci.len();
        let centres: Vec<[f64; 3]> = ci
            .iter()
            .map(|&c| parts[c].section(parts[c].u0, 0).c0)
            .collect();
        let cuts = cut_table(k, &t.cut_angles);
        if !t.cut_angles.is_empty() && cuts.is_empty() {
            return Err(SketchError::Document(format!(
                "transition '{}': cut_angles needs one finite angle per seam ({}), in (0, pi) and decreasing",
                t.name,
                k.saturating_sub(1)
            )));
        }
        let seams = make_seams(&parts[pi], t.parent_end, k, &t.seam_apex, &centres, &cuts);
        let mut cts = Vec::new();
        for (c, &idx) in ci.iter().enumerate() {
            if parts[idx].closed_start {
                return Err(SketchError::Document(format!(
                    "part '{}' joins transition '{}' at its start, which is closed",
                    parts[idx].name, t.name
                )));
            }
            let ct = child_transition(c, k, &parts[pi], t.parent_end, &parts[idx], &seams, &cuts);
            if thetas[idx].is_some() {
                return Err(SketchError::Document(format!(
                    "part '{}' is the child of two transitions",
                    parts[idx].name
                )));
            }
            thetas[idx] = Some(
                (0..ct.n)
                    .map(|i| ct.theta0 + ct.sigma * 2.0 * PI * i as f64 / ct.n as f64)
                    .collect(),
            );
            cts.push(ct);
        }
        built.push(Built {
            spec: t.clone(),
            parent: pi,
            children: ci,
            seams,
            cts,
        });
    }
    for b in &built {
        if thetas[b.parent].is_some() {
            return Err(SketchError::Document(format!(
                "part '{}' is both a child and a parent of transitions (not supported in version 1)",
                parts[b.parent].name
            )));
        }
    }
    let mut mesh = Mesh::default();
    let mut tubes = Vec::new();
    for (i, p) in parts.iter().enumerate() {
        let th = thetas[i].clone().unwrap_or_else(|| uniform.clone());
        let rows = ((p.u1 - p.u0) / height * res.rings_per_height)
            .ceil()
            .max(8.0) as usize;
        let g = mesh.group_index(&p.name);
        let disp: Vec<&Displacement> = displacements.iter().filter(|d| d.part == p.name).collect();
        tubes.push(tube(&mut mesh, p, &th, rows, g, &disp));
    }
    for b in &built {
        let g = mesh.group_index(&b.spec.name);
        let ring = match b.spec.parent_end {
            End::Start => &tubes[b.parent].start,
            End::End => &tubes[b.parent].end,
        };
        if ring.len() != RING_VERTICES {
            return Err(SketchError::Document(format!(
                "transition '{}': the parent's end is closed",
                b.spec.name
            )));
        }
        let seam_ids: Vec<Vec<u32>> = b
            .seams
            .iter()
            .map(|s| {
                (1..=SEAM_VERTICES)
                    .map(|k| push(&mut mesh, s.point(k as f64 / (SEAM_VERTICES + 1) as f64)))
                    .collect()
            })
            .collect();
        for (ct, &ci) in b.cts.iter().zip(&b.children) {
            let mut row0 = Vec::with_capacity(ct.n);
            for r in &ct.runs {
                match *r {
                    Run::Arc { from, count } => {
                        row0.extend((0..count).map(|i| ring[(from + i) % RING_VERTICES]));
                    }
                    Run::Seam { j, reversed } => {
                        let s = &b.seams[j];
                        row0.push(ring[if reversed { s.i_back } else { s.i_front }]);
                        if reversed {
                            row0.extend(seam_ids[j].iter().rev());
                        } else {
                            row0.extend(seam_ids[j].iter());
                        }
                    }
                }
            }
            let mut prev = row0;
            let rows = res.transition_rows;
            for r in 1..=rows {
                let row: Vec<u32> = if r == rows {
                    tubes[ci].start.clone()
                } else {
                    let s = r as f64 / rows as f64;
                    (0..ct.n)
                        .map(|i| {
                            let p =
                                teval(ct, &parts[b.parent], &parts[ci], &b.seams, s, i as f64, 0);
                            push(&mut mesh, p)
                        })
                        .collect()
                };
                band(&mut mesh, g, &prev, &row);
                prev = row;
            }
        }
    }
    orient(&mut mesh);
    let mut joins = Vec::new();
    let mut seam_reports = Vec::new();
    for b in &built {
        for (ct, &ci) in b.cts.iter().zip(&b.children) {
            joins.push(measure(
                b,
                ct,
                &parts[b.parent],
                &parts[b.parent].name,
                true,
                &parts[ci],
                height,
            ));
            joins.push(measure(
                b,
                ct,
                &parts[b.parent],
                &parts[ci].name,
                false,
                &parts[ci],
                height,
            ));
        }
        for (j, _) in b.seams.iter().enumerate() {
            seam_reports.push(measure_seam(b, j, &parts));
        }
    }
    Ok(Model {
        mesh,
        parts,
        joins,
        seams: seam_reports,
    })
}

/// Samples per loop vertex for the join measurements.
const JOIN_SAMPLES: usize = 3;

fn measure(
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
                (0.0, ct.parent_u, phi, ct.sgn * ct.ell, parent)
            } else {
                let th = ct.theta0 + ct.sigma * 2.0 * PI * tau / ct.n as f64;
                (1.0, ct.child_u, th, ct.ell, child)
            };
            let x0 = teval(ct, parent, child, &b.seams, s, tau, 0);
            let x1 = teval(ct, parent, child, &b.seams, s, tau, 1);
            let x2 = teval(ct, parent, child, &b.seams, s, tau, 2);
            let p0 = surf.chain.point(u, v.rem_euclid(2.0 * PI));
            let p1 = scale(surf.chain.derivative(u, v.rem_euclid(2.0 * PI), 1, 0), scl);
            let p2 = scale(
                surf.chain.derivative(u, v.rem_euclid(2.0 * PI), 2, 0),
                scl * scl,
            );
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
        c2: c2 / s2.max(f64::MIN_POSITIVE),
    }
}

fn measure_seam(b: &Built, j: usize, parts: &[PartSurface]) -> SeamReport {
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
    use std::collections::HashMap;
    let mut edges: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (t, tr) in m.triangles.iter().enumerate() {
        for e in 0..3 {
            let (a, b) = (tr[e], tr[(e + 1) % 3]);
            edges.entry((a.min(b), a.max(b))).or_default().push(t);
        }
    }
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
                for &o in &edges[&(a.min(b), a.max(b))] {
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
