//! Measurements of a solved [`Network`]: the jumps of every derivative up
//! to order two across every edge, in `u` and in `v`; how far the ODE
//! lines of the `v`-sides pass from the document's curves; the
//! interpolation of the `u`-sides and apexes; the residual of eq 8 inside
//! the patches; and the data size against a mesh. Measurements only: the
//! tests and `ode6.network_*` checks judge them.

use super::lines::Elem;
use super::solve::Network;
use super::topology::{EdgeKind, Role};
use crate::jet::{Jet, Real};
use crate::surface::Surface;
use crate::vec3::{dist, norm};

/// Samples along an edge (and along each side) for the jump measurements.
pub const EDGE_SAMPLES: usize = 16;
/// Magnitudes below this fraction of the network size (per derivative
/// order, scaled to unit parameter) make a relative jump meaningless; the
/// floor keeps the ratio finite.
pub const MAGNITUDE_FLOOR: f64 = 1e-12;

/// Jumps across one edge between two patches.
#[derive(Clone, Debug, serde::Serialize)]
pub struct EdgeReport {
    pub curve: usize,
    pub kind: EdgeKind,
    /// Largest `|Δ d^i S / du^i|`, `i = 0, 1, 2`.
    pub u: [f64; 3],
    /// Largest `|Δ d^j S / dv^j|`, `j = 0, 1, 2`.
    pub v: [f64; 3],
    /// Largest `|Δ S_uv|`.
    pub uv: f64,
    /// Largest `|d^i S|` of order `i = 0, 1, 2` on the first patch there.
    pub magnitude: [f64; 3],
    /// `[C0, C1, C2]`: the order-0 jump over the network size, the order-1
    /// and order-2 jumps over their magnitudes.
    pub relative: [f64; 3],
}

/// How far a `v`-side (an ODE line) passes from its document curve.
#[derive(Clone, Debug, serde::Serialize)]
pub struct SideReport {
    pub patch: usize,
    pub role: Role,
    pub curve: usize,
    /// Largest distance from a document point to the line, absolute.
    pub max_distance: f64,
    /// Over the network size.
    pub relative: f64,
}

/// Stored numbers against the mesh's vertex coordinates (Table 1).
#[derive(Clone, Debug, serde::Serialize)]
pub struct DataSize {
    /// Node and curve-point coordinates, explicit parameters and
    /// derivatives, three shape parameters per patch.
    pub stored_numbers: usize,
    pub mesh_vertices: usize,
    /// `3 x mesh_vertices`.
    pub mesh_numbers: usize,
    /// `stored_numbers / mesh_numbers`.
    pub ratio: f64,
}

/// Everything measured on a network.
#[derive(Clone, Debug, serde::Serialize)]
pub struct NetworkReport {
    pub name: String,
    pub patches: usize,
    pub three_sided: usize,
    pub curves: usize,
    pub nodes: usize,
    pub u_strips: usize,
    pub v_strips: usize,
    pub lines: usize,
    pub u_edges: usize,
    pub v_edges: usize,
    pub boundary_curves: usize,
    pub size: f64,
    pub edges: Vec<EdgeReport>,
    /// `[C0, C1, C2]` relative jumps, largest over all u-edges.
    pub max_relative_u_edges: [f64; 3],
    /// The same over all v-edges.
    pub max_relative_v_edges: [f64; 3],
    pub v_sides: Vec<SideReport>,
    /// Largest relative distance of a `v`-side from its document curve.
    pub max_side_relative: f64,
    /// Largest `|S(0 or 1, t_i) - P_i|` over the `u`-sides' document points,
    /// relative to the size.
    pub u_side_interpolation: f64,
    /// Largest `|S(0, v) - apex|` of a 3-sided patch, relative to the size.
    pub apex_interpolation: f64,
    /// Largest relative residual of eq 8 inside the patches.
    pub residual: f64,
    pub data: DataSize,
}

/// The order-0..2 jets `[S, S_u, S_uu, S_v, S_vv, S_uv]` at `(u, v)`.
fn jets(s: &impl Surface, u: f64, v: f64) -> [[f64; 3]; 6] {
    let p = s.eval(Jet::<3, 3>::var_u(u), Jet::<3, 3>::var_v(v));
    let d = |i: usize, j: usize| [p[0].deriv(i, j), p[1].deriv(i, j), p[2].deriv(i, j)];
    [d(0, 0), d(1, 0), d(2, 0), d(0, 1), d(0, 2), d(1, 1)]
}

impl NetworkReport {
    /// The largest relative `[C0, C1, C2]` jump over all u- and v-edges
    /// (NaN when any is NaN).
    pub fn max_relative_jump(&self) -> f64 {
        self.max_relative_u_edges
            .iter()
            .chain(&self.max_relative_v_edges)
            .fold(0.0, |a, b| nan_max(a, *b))
    }
}

impl Network {
    /// The report of the network meshed with `n x n` cells per patch.
    pub fn report(&self, n: usize) -> NetworkReport {
        let size = self.doc.size();
        let edges: Vec<EdgeReport> = self
            .topology
            .edges
            .iter()
            .enumerate()
            .filter_map(|(k, e)| self.edge_report(k, *e, size, EDGE_SAMPLES))
            .collect();
        let max_of = |want_u: bool| {
            let mut m = [0.0f64; 3];
            for e in &edges {
                if matches!(e.kind, EdgeKind::U { .. }) == want_u {
                    for i in 0..3 {
                        m[i] = nan_max(m[i], e.relative[i]);
                    }
                }
            }
            m
        };
        let v_sides = self.side_reports(size);
        let mesh = self.mesh(n);
        let stored = self.stored_numbers();
        let count = |f: fn(&EdgeKind) -> bool| self.topology.edges.iter().filter(|e| f(e)).count();
        NetworkReport {
            name: self.doc.name.clone(),
            patches: self.patches.len(),
            three_sided: self
                .doc
                .patches
                .iter()
                .filter(|p| p.curves.len() == 3)
                .count(),
            curves: self.doc.curves.len(),
            nodes: self.doc.nodes.len(),
            u_strips: self.u_strips.len(),
            v_strips: self.v_strips.len(),
            lines: self.lines.lines.len(),
            u_edges: count(|e| matches!(e, EdgeKind::U { .. })),
            v_edges: count(|e| matches!(e, EdgeKind::V { .. })),
            boundary_curves: count(|e| matches!(e, EdgeKind::Boundary { .. })),
            size,
            max_relative_u_edges: max_of(true),
            max_relative_v_edges: max_of(false),
            max_side_relative: v_sides.iter().fold(0.0, |a, s| nan_max(a, s.relative)),
            v_sides,
            u_side_interpolation: self.u_side_interpolation() / size,
            apex_interpolation: self.apex_interpolation() / size,
            residual: self.residual(6),
            edges,
            data: DataSize {
                stored_numbers: stored,
                mesh_vertices: mesh.positions.len(),
                mesh_numbers: 3 * mesh.positions.len(),
                ratio: stored as f64 / (3 * mesh.positions.len()).max(1) as f64,
            },
        }
    }

    /// `(u-edges, v-edges)` largest `[C0, C1, C2]` relative jumps, without
    /// the rest of [`Network::report`].
    /// `samples + 1` points along each edge.
    pub fn max_jumps(&self, samples: usize) -> ([f64; 3], [f64; 3]) {
        let size = self.doc.size();
        let (mut u, mut v) = ([0.0f64; 3], [0.0f64; 3]);
        for (k, e) in self.topology.edges.iter().enumerate() {
            if let Some(r) = self.edge_report(k, *e, size, samples.max(1)) {
                let m = if matches!(e, EdgeKind::U { .. }) {
                    &mut u
                } else {
                    &mut v
                };
                for i in 0..3 {
                    m[i] = nan_max(m[i], r.relative[i]);
                }
            }
        }
        (u, v)
    }

    fn edge_report(
        &self,
        curve: usize,
        kind: EdgeKind,
        size: f64,
        samples: usize,
    ) -> Option<EdgeReport> {
        let (a, b, at) = match kind {
            EdgeKind::U { below, above } => (below, above, true),
            EdgeKind::V { below, above } => (below, above, false),
            _ => return None,
        };
        let mut r = EdgeReport {
            curve,
            kind,
            u: [0.0; 3],
            v: [0.0; 3],
            uv: 0.0,
            magnitude: [0.0; 3],
            relative: [0.0; 3],
        };
        for i in 0..=samples {
            let t = i as f64 / samples as f64;
            let ((ua, va), (ub, vb)) = if at {
                ((1.0, t), (0.0, t))
            } else {
                ((t, 1.0), (t, 0.0))
            };
            let (ja, jb) = (
                jets(&self.patches[a], ua, va),
                jets(&self.patches[b], ub, vb),
            );
            let d = |k: usize| dist(ja[k], jb[k]);
            r.u = [
                nan_max(r.u[0], d(0)),
                nan_max(r.u[1], d(1)),
                nan_max(r.u[2], d(2)),
            ];
            r.v = [
                nan_max(r.v[0], d(0)),
                nan_max(r.v[1], d(3)),
                nan_max(r.v[2], d(4)),
            ];
            r.uv = nan_max(r.uv, d(5));
            let m = |ks: &[usize]| ks.iter().fold(0.0f64, |acc, &k| nan_max(acc, norm(ja[k])));
            r.magnitude = [
                nan_max(r.magnitude[0], m(&[0])),
                nan_max(r.magnitude[1], m(&[1, 3])),
                nan_max(r.magnitude[2], m(&[2, 4, 5])),
            ];
        }
        let floor = MAGNITUDE_FLOOR * size;
        let j1 = nan_max(r.u[1], r.v[1]);
        let j2 = nan_max(nan_max(r.u[2], r.v[2]), r.uv);
        r.relative = [
            r.u[0] / size,
            j1 / r.magnitude[1].max(floor),
            j2 / r.magnitude[2].max(floor),
        ];
        Some(r)
    }

    fn side_reports(&self, size: f64) -> Vec<SideReport> {
        let mut out = Vec::new();
        let us: Vec<f64> = (0..=400).map(|i| i as f64 / 400.0).collect();
        for (p, s) in self.topology.sides.iter().enumerate() {
            for (role, side, v) in [(Role::V0, s.v0, 0.0), (Role::V1, s.v1, 1.0)] {
                let line = self.patches[p].grid(&us, &[v]);
                let pts = &self.doc.curves[side.curve].points;
                let d = pts
                    .iter()
                    .map(|q| polyline_distance(&line, *q))
                    .fold(0.0, nan_max);
                out.push(SideReport {
                    patch: p,
                    role,
                    curve: side.curve,
                    max_distance: d,
                    relative: d / size,
                });
            }
        }
        out
    }

    fn u_side_interpolation(&self) -> f64 {
        let mut worst = 0.0f64;
        for (p, s) in self.topology.sides.iter().enumerate() {
            for (side, u) in [(s.u0, 0.0), (s.u1, 1.0)] {
                let Some(side) = side else { continue };
                let c = &self.doc.curves[side.curve];
                let Some(t) = c
                    .params
                    .clone()
                    .or_else(|| super::doc::chord_params(&c.points))
                else {
                    continue;
                };
                for (ti, q) in t.iter().zip(&c.points) {
                    let v = if side.along { *ti } else { 1.0 - ti };
                    worst = nan_max(worst, dist(self.patches[p].point(u, v), *q));
                }
            }
        }
        worst
    }

    fn apex_interpolation(&self) -> f64 {
        let mut worst = 0.0f64;
        for (p, s) in self.topology.sides.iter().enumerate() {
            let (u, corner) = match (s.u0, s.u1) {
                (None, _) => (0.0, 0),
                (_, None) => (1.0, 2),
                _ => continue,
            };
            let apex = self.doc.nodes[s.corners[corner]];
            for i in 0..=EDGE_SAMPLES {
                let v = i as f64 / EDGE_SAMPLES as f64;
                worst = nan_max(worst, dist(self.patches[p].point(u, v), apex));
            }
        }
        worst
    }

    /// Largest `|rho S^(6) + eta S^(4) + lambda S''|` over the sum of the
    /// three terms' magnitudes, on an `n x n` grid of interior points of
    /// every patch. The sum is floored at `(|rho| + |eta| + |lambda|)` times
    /// the network size, so a component that is linear in `u` (all three
    /// terms rounding noise) does not read as a relative error of one.
    pub fn residual(&self, n: usize) -> f64 {
        let mut worst = 0.0f64;
        let size = self.doc.size();
        for s in &self.patches {
            let pr = s.basis.params;
            let floor = (pr.rho.abs() + pr.eta.abs() + pr.lambda.abs()) * size;
            for i in 1..n {
                for k in 1..n {
                    let (u, v) = (i as f64 / n as f64, k as f64 / n as f64);
                    let q = s.eval(Jet::<7, 1>::var_u(u), Jet::<7, 1>::cst(v));
                    for c in &q {
                        let t = [
                            pr.rho * c.deriv(6, 0),
                            pr.eta * c.deriv(4, 0),
                            pr.lambda * c.deriv(2, 0),
                        ];
                        let scale = (t[0].abs() + t[1].abs() + t[2].abs()).max(floor);
                        worst = nan_max(worst, (t[0] + t[1] + t[2]).abs() / scale);
                    }
                }
            }
        }
        worst
    }

    /// Numbers a network stores (see [`DataSize`]).
    pub fn stored_numbers(&self) -> usize {
        let d = &self.doc;
        let mut n = 3 * d.nodes.len() + 3 * d.patches.len();
        for c in &d.curves {
            // interior points: the ends are the nodes
            n += 3 * c.points.len().saturating_sub(2);
            n += c.params.as_ref().map_or(0, |t| t.len().saturating_sub(2));
        }
        for p in &d.patches {
            if let Some(dv) = &p.derivatives {
                for c in [&dv.u0, &dv.u1].into_iter().flatten() {
                    n += 3 * (c.first.len() + c.second.len());
                }
            }
        }
        n
    }

    /// The lines' element count (for reports of irregular networks).
    pub fn line_lengths(&self) -> Vec<usize> {
        self.lines.lines.iter().map(|l| l.elems.len()).collect()
    }

    /// Whether element `e` has explicit derivatives.
    pub fn has_explicit(&self, e: Elem) -> bool {
        self.lines.cross.contains_key(&e)
    }
}

/// `max` that keeps a NaN (a NaN measurement must fail every check).
pub fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Distance from `q` to a polyline.
pub fn polyline_distance(line: &[[f64; 3]], q: [f64; 3]) -> f64 {
    let mut best = f64::INFINITY;
    for w in line.windows(2) {
        let d = crate::vec3::sub(w[1], w[0]);
        let l2 = crate::vec3::dot(d, d);
        let t = if l2 > 0.0 {
            (crate::vec3::dot(crate::vec3::sub(q, w[0]), d) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let p = crate::vec3::add(w[0], crate::vec3::scale(d, t));
        best = best.min(dist(p, q));
    }
    if line.len() == 1 {
        best = dist(line[0], q);
    }
    best
}
