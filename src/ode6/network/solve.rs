//! The patches of a network: each an ODE surface of eq 19 whose six
//! constraint curves come from the lines ([`super::lines`]) of its u-strip.
//!
//! Patch `k` of a u-strip spans sections `k` and `k + 1` (its `U0` and
//! `U1` sides): `c_1 = S_k`, `c_4 = S_{k+1}`. The cross derivatives
//! `c_2, c_3` (at `S_k`) and `c_5, c_6` (at `S_{k+1}`) are the document's
//! explicit ones where given, else the derivatives of the quadratic through
//! three neighbouring sections at unit spacing (one unit of `u` per patch):
//!
//! | where | $S_u$ | $S_{uu}$ |
//! |---|---|---|
//! | inside (or closed strip) | $(S_{k+1} - S_{k-1})/2$ | $S_{k+1} - 2S_k + S_{k-1}$ |
//! | first section | $(-3S_0 + 4S_1 - S_2)/2$ | $S_0 - 2S_1 + S_2$ |
//! | last section $m$ | $(3S_m - 4S_{m-1} + S_{m-2})/2$ | $S_m - 2S_{m-1} + S_{m-2}$ |
//! | a strip of one patch | $S_1 - S_0$ | $0$ |
//!
//! (exact for quadratics in `u`: `verify/ode6_network.py` derives the
//! weights and `tests/it/ode6_network.rs` compares them). Both patches
//! at a section read the same curves with the same weights, so a u-edge is
//! C2 by construction (eqs 23-25) for any shape parameters; the apex of a
//! 3-sided patch is a constant section (`S_0(v) = ` apex), so its cross
//! derivative `c_2(v)` turns with `v` like a polar parameterisation.

use super::doc::NetworkDoc;
use super::lines::{elem, Elem, Lines};
use super::topology::{Role, Strip, Topology};
use super::NetworkError;
use crate::mesh::Mesh;
use crate::ode6::{Basis, BoundaryCurves, Curve, Ode6Surface};
use crate::surface::Surface;
use std::collections::BTreeMap;

/// A triangle with sides below this fraction of its patch's size is a
/// sliver of a collapsed side (the apex row of a 3-sided patch agrees to
/// rounding, about 1e-16 of the size) and is dropped from the mesh.
pub const DEGENERATE: f64 = 1e-10;

/// A solved network.
#[derive(Clone, Debug)]
pub struct Network {
    pub doc: NetworkDoc,
    pub topology: Topology,
    pub lines: Lines,
    pub u_strips: Vec<Strip>,
    pub v_strips: Vec<Strip>,
    /// One surface per document patch, same order.
    pub patches: Vec<Ode6Surface>,
    /// `(u-strip, index in it)` of every patch.
    pub place: Vec<(usize, usize)>,
}

/// Weights of sections `k - 1, k, k + 1, ...` in `S_u` and `S_uu` at
/// section `k` of a strip with `count` sections: `(section, first,
/// second)` triples (see the module table).
pub fn stencil(k: usize, count: usize, closed: bool) -> Vec<(usize, f64, f64)> {
    if closed {
        let (a, b) = ((k + count - 1) % count, (k + 1) % count);
        return vec![(a, -0.5, 1.0), (k, 0.0, -2.0), (b, 0.5, 1.0)];
    }
    let m = count - 1;
    if m == 1 {
        return vec![(0, -1.0, 0.0), (1, 1.0, 0.0)];
    }
    if k == 0 {
        vec![(0, -1.5, 1.0), (1, 2.0, -2.0), (2, -0.5, 1.0)]
    } else if k == m {
        vec![(m, 1.5, 1.0), (m - 1, -2.0, -2.0), (m - 2, 0.5, 1.0)]
    } else {
        vec![(k - 1, -0.5, 1.0), (k, 0.0, -2.0), (k + 1, 0.5, 1.0)]
    }
}

/// The section elements of a u-strip (`n + 1` open, `n` closed).
pub fn sections(t: &Topology, strip: &Strip) -> Vec<Elem> {
    let mut s: Vec<Elem> = strip
        .patches
        .iter()
        .map(|&p| elem(t, p, Role::U0))
        .collect();
    if !strip.closed {
        let last = strip.patches[strip.patches.len() - 1];
        s.push(elem(t, last, Role::U1));
    }
    s
}

/// Keys and weights of one patch, merged by key.
#[derive(Default)]
struct Keys {
    index: BTreeMap<(u8, Elem), usize>,
    keys: Vec<Curve>,
    weights: Vec<[f64; 6]>,
}

impl Keys {
    fn add(&mut self, kind: u8, e: Elem, curve: &Curve, j: usize, w: f64) {
        let i = *self.index.entry((kind, e)).or_insert_with(|| {
            self.keys.push(curve.clone());
            self.weights.push([0.0; 6]);
            self.keys.len() - 1
        });
        self.weights[i][j] += w;
    }
}

impl Network {
    /// Validates, orients, builds the lines and solves every patch.
    pub fn build(doc: NetworkDoc) -> Result<Network, NetworkError> {
        doc.validate()?;
        let topology = Topology::new(&doc)?;
        let lines = Lines::new(&doc, &topology)?;
        let u_strips = topology.u_strips();
        let v_strips = topology.v_strips();
        let mut patches: Vec<Option<Ode6Surface>> = vec![None; doc.patches.len()];
        let mut place = vec![(0, 0); doc.patches.len()];
        for (si, strip) in u_strips.iter().enumerate() {
            let secs = sections(&topology, strip);
            for (k, &p) in strip.patches.iter().enumerate() {
                place[p] = (si, k);
                let mut keys = Keys::default();
                for (end, s) in [(0usize, k), (3, (k + 1) % secs.len())] {
                    let e = secs[s];
                    keys.add(0, e, &lines.position[&e], end, 1.0);
                    if let Some([d1, d2]) = lines.cross.get(&e) {
                        keys.add(1, e, d1, end + 1, 1.0);
                        keys.add(2, e, d2, end + 2, 1.0);
                        continue;
                    }
                    for (m, w1, w2) in stencil(s, secs.len(), strip.closed) {
                        let em = secs[m];
                        let c = &lines.position[&em];
                        keys.add(0, em, c, end + 1, w1);
                        keys.add(0, em, c, end + 2, w2);
                    }
                }
                let params = doc.patches[p].params;
                let basis = Basis::new(params)
                    .map_err(|source| NetworkError::Params { patch: p, source })?;
                let curves = BoundaryCurves::new(keys.keys, keys.weights)
                    .map_err(|source| NetworkError::Solve { patch: p, source })?;
                patches[p] = Some(Ode6Surface::new(basis, curves));
            }
        }
        let patches = patches
            .into_iter()
            .enumerate()
            .map(|(p, s)| s.ok_or(NetworkError::Unplaced { patch: p }))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Network {
            doc,
            topology,
            lines,
            u_strips,
            v_strips,
            patches,
            place,
        })
    }

    /// The name of patch `p` (the document's, or `patch-<p>`).
    pub fn patch_name(&self, p: usize) -> String {
        self.doc.patches[p]
            .name
            .clone()
            .unwrap_or_else(|| format!("patch-{p}"))
    }

    /// Every patch on an `(n + 1) x (n + 1)` grid of `(u, v)`, one mesh
    /// group per patch (named as [`Network::patch_name`]); seams are not
    /// welded, and the degenerate triangles at an apex are dropped.
    pub fn mesh(&self, n: usize) -> Mesh {
        let n = n.max(1);
        let ts: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
        let mut out: Option<Mesh> = None;
        for (p, s) in self.patches.iter().enumerate() {
            let pts = s.grid(&ts, &ts);
            let mut m = Mesh::grid(pts, n + 1, n + 1, [false, false]);
            let floor = (DEGENERATE * m.diagonal()).powi(2);
            m.triangles.retain(|t| {
                let [a, b, c] = t.map(|i| m.positions[i as usize]);
                let area = crate::vec3::norm(crate::vec3::cross(
                    crate::vec3::sub(b, a),
                    crate::vec3::sub(c, a),
                ));
                area > floor
            });
            m.tri_group = vec![0; m.triangles.len()];
            m.set_single_group(&self.patch_name(p));
            match &mut out {
                None => out = Some(m),
                Some(o) => o.append(&m),
            }
        }
        out.unwrap_or_else(|| Mesh::new(Vec::new(), Vec::new()))
    }
}
