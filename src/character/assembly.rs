//! Assembling parts and transitions into one mesh with shared vertices at
//! every seam, and measuring the joins.

use super::measure::{measure, measure_seam};
pub use super::measure::{orient, JoinReport, SeamReport};
use super::part::{build_part, PartSurface};
use super::ring::{cut_table, RING_VERTICES, SEAM_VERTICES};
use super::seam::seams as make_seams;
use super::transition::{child_transition, eval as teval, Built, Run};
use super::ModelError;
use crate::character::spec::{End, PartSpec, TransitionSpec};
use crate::mesh::Mesh;

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

/// A displacement field over a part's parameters, in patch coordinates:
/// `s` in `(0, 1)` across its u-range, `theta` the ring angle. The force
/// edits' fields (`crate::edit::ForceField`: pde4 2-sided and 4-sided
/// solutions) are the ones the pipeline adds.
pub trait DisplacementField: std::fmt::Debug + Send + Sync {
    /// The displacement at patch coordinate `s` and angle `theta`.
    fn at(&self, s: f64, theta: f64) -> [f64; 3];
}

/// A displacement field added to a part's surface over a u-range of the
/// part (a force edit of `crate::edit`: the pde4 2-sided solution, which
/// vanishes with its u-derivative at both ends of the range, so the part
/// stays in place and C1 there and its ends, where transitions join, do not
/// move; or the 4-sided one inside an angle range too).
#[derive(Clone, Debug)]
pub struct Displacement {
    pub part: String,
    pub u: [f64; 2],
    pub field: std::sync::Arc<dyn DisplacementField>,
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
/// Largest Hermite tangent factor of a transition (`TransitionSpec::tangent_scale`):
/// past a few times the parts' own tangents the blend loops out of the body.
pub const TANGENT_SCALE_MAX: f64 = 10.0;

impl PartCache {
    /// The built part of `spec`, solved only when not cached.
    pub fn get(&mut self, spec: &PartSpec) -> Result<PartSurface, ModelError> {
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

/// Triangles between two rows of one part sampled at different angles
/// (`ta`, `tb`: each row's theta per vertex, each running once around the
/// circle, in either direction): the rows are merged by angle, measured
/// from `a`'s first vertex in `a`'s direction of travel, so every triangle
/// spans neighbouring angles (orientation is fixed by [`orient`]).
fn zip(m: &mut Mesh, g: u32, a: &[u32], ta: &[f64], b: &[u32], tb: &[f64]) {
    let tau = 2.0 * PI;
    let sigma = if ((ta[1] - ta[0] + PI).rem_euclid(tau) - PI) < 0.0 {
        -1.0
    } else {
        1.0
    };
    let alpha = |i: usize| {
        if i >= a.len() {
            tau
        } else {
            (sigma * (ta[i] - ta[0])).rem_euclid(tau)
        }
    };
    let mut order: Vec<(f64, u32)> = b
        .iter()
        .zip(tb)
        .map(|(&v, &t)| ((sigma * (t - ta[0])).rem_euclid(tau), v))
        .collect();
    order.sort_by(|x, y| x.0.total_cmp(&y.0));
    let beta = |j: usize| {
        if j >= order.len() {
            order[0].0 + tau
        } else {
            order[j].0
        }
    };
    let (na, nb) = (a.len(), order.len());
    let (mut i, mut j) = (0, 0);
    while i < na || j < nb {
        let bi = |j: usize| order[j % nb].1;
        if j >= nb || (i < na && alpha(i + 1) <= beta(j + 1)) {
            tri(m, g, a[i], a[(i + 1) % na], bi(j));
            i += 1;
        } else {
            tri(m, g, a[i % na], bi(j + 1), bi(j));
            j += 1;
        }
    }
}

fn tube(
    m: &mut Mesh,
    p: &PartSurface,
    thetas: &[f64],
    end_thetas: Option<&[f64]>,
    rows: usize,
    g: u32,
    disp: &[&Displacement],
) -> Tube {
    let mut prev: Vec<u32> = Vec::new();
    let mut first = Vec::new();
    let switch = rows / 2;
    let mut prev_th = thetas;
    for r in 0..=rows {
        let u = p.u0 + (p.u1 - p.u0) * r as f64 / rows as f64;
        let thetas = match end_thetas {
            Some(e) if r >= switch.max(1) => e,
            _ => thetas,
        };
        let sec = p.section(u, 0);
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
        } else if prev.len() > 1 && row.len() > 1 && !std::ptr::eq(prev_th, thetas) {
            zip(m, g, &prev, prev_th, &row, thetas);
        } else {
            band(m, g, &prev, &row);
        }
        prev = row;
        prev_th = thetas;
    }
    Tube {
        start: first,
        end: prev,
    }
}

/// Builds the mesh of parts and transitions and measures the joins.
pub fn build_model(
    specs: &[PartSpec],
    transitions: &[TransitionSpec],
    height: f64,
    res: Resolution,
) -> Result<Model, ModelError> {
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
) -> Result<Model, ModelError> {
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
            return Err(ModelError::Document(format!(
                "a displacement names unknown part '{}'",
                d.part
            )));
        }
    }
    let find = |n: &str| -> Result<usize, ModelError> {
        parts
            .iter()
            .position(|p| p.name == n)
            .ok_or_else(|| ModelError::Document(format!("unknown part '{n}'")))
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
        if !(t.tangent_scale.is_finite()
            && t.tangent_scale > 0.0
            && t.tangent_scale <= TANGENT_SCALE_MAX)
        {
            return Err(ModelError::Document(format!(
                "transition '{}': tangent_scale must be in (0, {TANGENT_SCALE_MAX}], got {}",
                t.name,
                crate::limits::Num(t.tangent_scale)
            )));
        }
        let km1 = k.saturating_sub(1);
        let out_of_range = t.cut_angles.iter().enumerate().find(|&(i, &a)| {
            let (lo, hi) = if i < km1 { (0.0, PI) } else { (PI, 2.0 * PI) };
            !(lo..=hi).contains(&a)
        });
        if let Some((i, &a)) = out_of_range {
            return Err(ModelError::Document(format!(
                "transition '{}': cut_angles[{i}] = {} is outside {} (front angles in [0, pi], back angles in [pi, 2 pi])",
                t.name,
                crate::limits::Num(a),
                if i < km1 { "[0, pi]" } else { "[pi, 2 pi]" }
            )));
        }
        if !t.cut_angles.is_empty() && cuts.is_empty() {
            return Err(ModelError::Document(format!(
                "transition '{}': cut_angles needs one finite angle per seam ({}), in (0, pi) and decreasing, optionally followed by one back angle per seam in (pi, 2 pi), increasing",
                t.name,
                k.saturating_sub(1)
            )));
        }
        let seams = make_seams(&parts[pi], t.parent_end, k, &t.seam_apex, &centres, &cuts);
        let mut cts = Vec::new();
        for (c, &idx) in ci.iter().enumerate() {
            if parts[idx].closed_start {
                return Err(ModelError::Document(format!(
                    "part '{}' joins transition '{}' at its start, which is closed",
                    parts[idx].name, t.name
                )));
            }
            let ct = child_transition(
                c,
                k,
                &parts[pi],
                t.parent_end,
                &parts[idx],
                &seams,
                &cuts,
                t.tangent_scale,
                t.continuity,
            );
            if thetas[idx].is_some() {
                return Err(ModelError::Document(format!(
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
    // a part that is a child (its start ring follows its transition's loop)
    // and the parent of a transition at its end (whose ring is the uniform
    // one the cuts index) switches from one ring to the other halfway
    // along its tube ([`zip`]): an arm under the shoulders ending at a wrist
    let mut end_uniform = vec![false; parts.len()];
    for b in &built {
        if thetas[b.parent].is_some() {
            if b.spec.parent_end == End::Start {
                return Err(ModelError::Document(format!(
                    "part '{}' is a child and the parent of transition '{}' at the same end (its start)",
                    parts[b.parent].name, b.spec.name
                )));
            }
            end_uniform[b.parent] = true;
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
        let end = end_uniform[i].then_some(uniform.as_slice());
        tubes.push(tube(&mut mesh, p, &th, end, rows, g, &disp));
    }
    for b in &built {
        let g = mesh.group_index(&b.spec.name);
        let ring = match b.spec.parent_end {
            End::Start => &tubes[b.parent].start,
            End::End => &tubes[b.parent].end,
        };
        if ring.len() != RING_VERTICES {
            return Err(ModelError::Document(format!(
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
