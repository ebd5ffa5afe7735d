//! How the patches of a [`NetworkDoc`] fit together: each side's role and
//! direction, the edges between patches, and the strips of patches through
//! them.
//!
//! A side of a patch is one of `U0`, `U1` (the boundary curves of eq 1,
//! `c_1` and `c_4`) or `V0`, `V1` (iso-parametric lines of the ODE). An
//! edge (a curve used by two patches) is a **u-edge** when it is the `U1`
//! side of one patch and the `U0` side of the other, with `v` running the
//! same way along it (eqs 23-25: the shared constraint curves make it C2
//! whatever the shape parameters), and a **v-edge** when it is the `V1`
//! side of one and the `V0` side of the other with `u` running the same
//! way (eq 26: C2 when the two patches have the same shape parameters and
//! C2 constraint curves across the shared corners). Any other pairing
//! (a u-side against a v-side, or directions that disagree) cannot be C2
//! by the paper's construction and is refused by name.
//!
//! A **u-strip** is a maximal run of patches joined through u-edges (its
//! patch boundaries are the *sections* of a chain, eqs 23-25); a
//! **v-strip** a run joined through v-edges. Either may close on itself.

use super::doc::{Apex, NetworkDoc};
use super::NetworkError;

/// A side's role in its patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Role {
    U0,
    U1,
    V0,
    V1,
}

/// A curve used as a side: which curve, and whether the patch's own
/// parameter along that side (`v` on `U0`/`U1`, `u` on `V0`/`V1`) grows
/// from the curve's `from` to its `to`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Side {
    pub curve: usize,
    pub along: bool,
}

/// The sides of one patch; `u0` (or `u1`) is `None` for a 3-sided patch
/// with its apex there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PatchSides {
    pub u0: Option<Side>,
    pub u1: Option<Side>,
    pub v0: Side,
    pub v1: Side,
    /// The corner nodes `(0,0), (0,1), (1,1), (1,0)`.
    pub corners: [usize; 4],
}

impl PatchSides {
    pub fn side(&self, role: Role) -> Option<Side> {
        match role {
            Role::U0 => self.u0,
            Role::U1 => self.u1,
            Role::V0 => Some(self.v0),
            Role::V1 => Some(self.v1),
        }
    }
}

/// What a curve is between patches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EdgeKind {
    /// Used by one patch only.
    Boundary { patch: usize, role: Role },
    /// `U1` of `below`, `U0` of `above`.
    U { below: usize, above: usize },
    /// `V1` of `below`, `V0` of `above`.
    V { below: usize, above: usize },
    /// Used by no patch.
    Unused,
}

/// The network's combinatorics.
#[derive(Clone, Debug)]
pub struct Topology {
    pub sides: Vec<PatchSides>,
    pub edges: Vec<EdgeKind>,
    /// `u_next[p]`: the patch across `p`'s `U1` side.
    pub u_next: Vec<Option<usize>>,
    pub u_prev: Vec<Option<usize>>,
    pub v_next: Vec<Option<usize>>,
    pub v_prev: Vec<Option<usize>>,
}

/// A run of patches; `closed` when the last joins the first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Strip {
    pub patches: Vec<usize>,
    pub closed: bool,
}

impl Topology {
    /// Orients every patch and classifies every curve.
    pub fn new(doc: &NetworkDoc) -> Result<Topology, NetworkError> {
        let sides = doc
            .patches
            .iter()
            .enumerate()
            .map(|(p, patch)| orient(doc, p, &patch.curves, patch.apex))
            .collect::<Result<Vec<_>, _>>()?;
        let mut uses: Vec<Vec<(usize, Role, bool)>> = vec![Vec::new(); doc.curves.len()];
        for (p, s) in sides.iter().enumerate() {
            for role in [Role::U0, Role::U1, Role::V0, Role::V1] {
                if let Some(side) = s.side(role) {
                    uses[side.curve].push((p, role, side.along));
                }
            }
        }
        let n = sides.len();
        let mut t = Topology {
            sides,
            edges: Vec::with_capacity(uses.len()),
            u_next: vec![None; n],
            u_prev: vec![None; n],
            v_next: vec![None; n],
            v_prev: vec![None; n],
        };
        for (k, u) in uses.iter().enumerate() {
            let edge = classify(doc, k, u)?;
            match edge {
                EdgeKind::U { below, above } => {
                    t.u_next[below] = Some(above);
                    t.u_prev[above] = Some(below);
                }
                EdgeKind::V { below, above } => {
                    t.v_next[below] = Some(above);
                    t.v_prev[above] = Some(below);
                }
                _ => {}
            }
            t.edges.push(edge);
        }
        Ok(t)
    }

    /// The u-strips, each patch in exactly one.
    pub fn u_strips(&self) -> Vec<Strip> {
        strips(&self.u_next, &self.u_prev)
    }

    /// The v-strips, each patch in exactly one.
    pub fn v_strips(&self) -> Vec<Strip> {
        strips(&self.v_next, &self.v_prev)
    }
}

fn strips(next: &[Option<usize>], prev: &[Option<usize>]) -> Vec<Strip> {
    let n = next.len();
    let mut seen = vec![false; n];
    let mut out = Vec::new();
    // open strips from their first patch, then the cycles that remain
    for start in (0..n).filter(|&p| prev[p].is_none()).chain(0..n) {
        if seen[start] {
            continue;
        }
        let mut patches = vec![start];
        seen[start] = true;
        let mut closed = false;
        let mut p = start;
        while let Some(q) = next[p] {
            if q == start {
                closed = true;
                break;
            }
            if seen[q] {
                break;
            }
            seen[q] = true;
            patches.push(q);
            p = q;
        }
        out.push(Strip { patches, closed });
    }
    out
}

/// The nodes of a curve in the direction of use.
fn ends(doc: &NetworkDoc, curve: usize, forward: bool) -> (usize, usize) {
    let c = &doc.curves[curve];
    if forward {
        (c.from, c.to)
    } else {
        (c.to, c.from)
    }
}

/// Walks the sides in order, each starting where the previous ended,
/// trying both directions of the first.
fn orient(
    doc: &NetworkDoc,
    p: usize,
    curves: &[usize],
    apex: Apex,
) -> Result<PatchSides, NetworkError> {
    let walk = |first: bool| -> Option<Vec<bool>> {
        let mut dirs = vec![first];
        let mut at = ends(doc, curves[0], first).1;
        for &k in &curves[1..] {
            let c = &doc.curves[k];
            let forward = if c.from == at {
                true
            } else if c.to == at {
                false
            } else {
                return None;
            };
            at = ends(doc, k, forward).1;
            dirs.push(forward);
        }
        (at == ends(doc, curves[0], first).0).then_some(dirs)
    };
    let dirs = walk(true)
        .or_else(|| walk(false))
        .ok_or(NetworkError::OpenBoundary { patch: p })?;
    let node = |i: usize| ends(doc, curves[i], dirs[i]).0;
    // traversal order: U0 (v up), V1 (u up), U1 (v down), V0 (u down)
    let s = |i: usize, up: bool| Side {
        curve: curves[i],
        along: dirs[i] == up,
    };
    Ok(match (curves.len(), apex) {
        (4, _) => PatchSides {
            u0: Some(s(0, true)),
            v1: s(1, true),
            u1: Some(s(2, false)),
            v0: s(3, false),
            corners: [node(0), node(1), node(2), node(3)],
        },
        (_, Apex::U0) => PatchSides {
            u0: None,
            v1: s(0, true),
            u1: Some(s(1, false)),
            v0: s(2, false),
            corners: [node(0), node(0), node(1), node(2)],
        },
        (_, Apex::U1) => PatchSides {
            u0: Some(s(0, true)),
            v1: s(1, true),
            u1: None,
            v0: s(2, false),
            corners: [node(0), node(1), node(2), node(2)],
        },
    })
}

fn classify(
    doc: &NetworkDoc,
    curve: usize,
    uses: &[(usize, Role, bool)],
) -> Result<EdgeKind, NetworkError> {
    match uses {
        [] => Ok(EdgeKind::Unused),
        [(patch, role, _)] => Ok(EdgeKind::Boundary {
            patch: *patch,
            role: *role,
        }),
        [a, b] => {
            let pair = |x: Role, y: Role| {
                if a.1 == x && b.1 == y {
                    Some((a, b))
                } else if b.1 == x && a.1 == y {
                    Some((b, a))
                } else {
                    None
                }
            };
            let bad = |why: &'static str| NetworkError::Join {
                curve,
                patches: [a.0, b.0],
                roles: [a.1, b.1],
                why,
            };
            if let Some((lo, hi)) = pair(Role::U1, Role::U0) {
                if lo.2 != hi.2 {
                    return Err(bad("v runs in opposite directions along the shared curve"));
                }
                return Ok(EdgeKind::U {
                    below: lo.0,
                    above: hi.0,
                });
            }
            if let Some((lo, hi)) = pair(Role::V1, Role::V0) {
                if lo.2 != hi.2 {
                    return Err(bad("u runs in opposite directions along the shared curve"));
                }
                let (pa, pb) = (doc.patches[lo.0].params, doc.patches[hi.0].params);
                if pa != pb {
                    return Err(NetworkError::VParams {
                        curve,
                        patches: [lo.0, hi.0],
                    });
                }
                return Ok(EdgeKind::V {
                    below: lo.0,
                    above: hi.0,
                });
            }
            let u = |r: Role| matches!(r, Role::U0 | Role::U1);
            Err(bad(if u(a.1) != u(b.1) {
                "a boundary curve (u side) of one patch is an iso-parametric side (v side) of the other"
            } else {
                "both patches start (or both end) their parameter at the shared curve"
            }))
        }
        _ => Err(NetworkError::Shared {
            curve,
            patches: uses.iter().map(|u| u.0).collect(),
        }),
    }
}
