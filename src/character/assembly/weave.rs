//! The mesh of an assembly: a tube of rows per part, and each transition
//! woven from its parent's end ring through its seams to its children's
//! start rings, with shared vertices at every join.

use super::{Displacement, Resolution};
use crate::character::part::PartSurface;
use crate::character::ring::{RING_VERTICES, SEAM_VERTICES};
use crate::character::spec::End;
use crate::character::transition::{blend, column, Built, Run};
use crate::character::ModelError;
use crate::mesh::Mesh;

use std::f64::consts::PI;

/// A part's tube: its first and last row of vertices.
pub(super) struct Tube {
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

/// The rows of a part's tube from its start to its end, banded (or zipped
/// where the ring switches to `end_thetas`).
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

/// The tube of every part, in order: each part's rings at its angles
/// (`thetas`, or `uniform`), switching to `uniform` halfway along where
/// `end_uniform` says so, with the part's displacements added.
pub(super) fn part_tubes(
    mesh: &mut Mesh,
    parts: &[PartSurface],
    thetas: &[Option<Vec<f64>>],
    end_uniform: &[bool],
    uniform: &[f64],
    height: f64,
    res: Resolution,
    displacements: &[Displacement],
) -> Vec<Tube> {
    let mut tubes = Vec::new();
    for (i, p) in parts.iter().enumerate() {
        let th = thetas[i].clone().unwrap_or_else(|| uniform.to_vec());
        let rows = ((p.u1 - p.u0) / height * res.rings_per_height)
            .ceil()
            .max(8.0) as usize;
        let g = mesh.group_index(&p.name);
        let disp: Vec<&Displacement> = displacements.iter().filter(|d| d.part == p.name).collect();
        let end = end_uniform[i].then_some(uniform);
        tubes.push(tube(mesh, p, &th, end, rows, g, &disp));
    }
    tubes
}

/// The vertices along each of a transition's seams (their ends excluded:
/// those are the parent's ring vertices).
fn seam_vertices(mesh: &mut Mesh, b: &Built) -> Vec<Vec<u32>> {
    b.seams
        .iter()
        .map(|s| {
            (1..=SEAM_VERTICES)
                .map(|k| push(mesh, s.point(k as f64 / (SEAM_VERTICES + 1) as f64)))
                .collect()
        })
        .collect()
}

/// A transition's mesh: for each child, its loop (arcs of the parent's ring
/// and seam vertices) banded through the transition's rows to the child's
/// start ring.
pub(super) fn transition_mesh(
    mesh: &mut Mesh,
    b: &Built,
    parts: &[PartSurface],
    tubes: &[Tube],
    res: Resolution,
) -> Result<(), ModelError> {
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
    let seam_ids = seam_vertices(mesh, b);
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
        let columns: Vec<_> = (0..ct.n)
            .map(|i| column(ct, &parts[b.parent], &parts[ci], &b.seams, i as f64))
            .collect();
        for r in 1..=rows {
            let row: Vec<u32> = if r == rows {
                tubes[ci].start.clone()
            } else {
                let s = r as f64 / rows as f64;
                columns
                    .iter()
                    .map(|c| push(mesh, blend(ct, c, s, 0)))
                    .collect()
            };
            band(mesh, g, &prev, &row);
            prev = row;
        }
    }
    Ok(())
}
