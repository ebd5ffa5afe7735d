//! The curve-network document (JSON, `version` 1, unknown fields refused)
//! and its validation. The schema, with an example, is in `docs/networks.md`.
//!
//! * `nodes`: points `[x, y, z]`;
//! * `curves`: `{from, to, points, params?}`: a polyline from node `from`
//!   to node `to` whose first and last points are those nodes (within
//!   [`NODE_TOLERANCE`] of the network's size), with optional parameters per
//!   point (strictly increasing from 0 to 1; default: chord length);
//! * `patches`: `{name?, curves, params?, derivatives?}`: three or four
//!   curve indices around the patch. Four sides `[a, b, c, d]` are the
//!   sides `u = 0` (from the corner `(0,0)` to `(0,1)`), `v = 1`, `u = 1`
//!   (from `(1,1)` to `(1,0)`) and `v = 0`, each curve used in whichever
//!   direction its nodes meet. Three sides `[b, c, d]` are a **3-sided
//!   patch**: its `u = 0` side is collapsed to the apex, the node shared by
//!   `b` and `d` (with `"apex": "u1"`, sides `[a, b, d]`: the `u = 1`
//!   side is collapsed to the node shared by `b` and `d`). `params` are the shape parameters of eq 2 (default
//!   `rho = 1, eta = 3, lambda = 1`, the paper's sec 6.1 values);
//!   `derivatives.u0` / `.u1` give the first and second cross derivative
//!   (with respect to the patch's `u`) at every point of the curve on that
//!   side, in the curve's own point order. Without them the cross
//!   derivatives come from the neighbouring patches (see [`super`]).

use super::NetworkError;
use crate::ode6::Params;
use serde::{Deserialize, Serialize};

/// The document version this code reads and writes.
pub const NETWORK_VERSION: u32 = 1;

/// A curve end must lie within this fraction of the network's bounding-box
/// diagonal of its node (a document written with f64 round trips is exact;
/// the slack admits hand-edited files with 12 digits).
pub const NODE_TOLERANCE: f64 = 1e-9;

/// The default shape parameters: the paper's sec 6.1 values (`rho = lambda
/// = 1`, `eta = 3`).
pub const DEFAULT_PARAMS: Params = Params {
    rho: 1.0,
    eta: 3.0,
    lambda: 1.0,
};

fn default_params() -> Params {
    DEFAULT_PARAMS
}

/// A curve network (see the module doc).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NetworkDoc {
    pub version: u32,
    #[serde(default)]
    pub name: String,
    pub nodes: Vec<[f64; 3]>,
    pub curves: Vec<CurveDoc>,
    pub patches: Vec<PatchDoc>,
}

/// A polyline between two nodes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveDoc {
    pub from: usize,
    pub to: usize,
    /// Every point, the two end points included.
    pub points: Vec<[f64; 3]>,
    /// Parameter of every point, from 0 to 1 (default: chord length).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub params: Option<Vec<f64>>,
}

/// A 3- or 4-sided patch.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PatchDoc {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    pub curves: Vec<usize>,
    #[serde(default = "default_params")]
    pub params: Params,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub derivatives: Option<Derivatives>,
    /// Where a 3-sided patch has its apex (default `u0`).
    #[serde(default, skip_serializing_if = "Apex::is_u0")]
    pub apex: Apex,
}

/// The collapsed side of a 3-sided patch: `u0` (sides `[v1, u1, v0]`,
/// the apex shared by the first and last) or `u1` (sides `[u0, v1, v0]`,
/// the apex shared by the last two).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Apex {
    #[default]
    U0,
    U1,
}

impl Apex {
    pub fn is_u0(&self) -> bool {
        *self == Apex::U0
    }
}

/// Explicit cross derivatives on the `u = 0` and `u = 1` sides.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Derivatives {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub u0: Option<Cross>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub u1: Option<Cross>,
}

/// `S_u` and `S_uu` at every point of a curve (the curve's point order).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cross {
    pub first: Vec<[f64; 3]>,
    pub second: Vec<[f64; 3]>,
}

impl NetworkDoc {
    /// Merges nodes and curves that coincide within `1e-12` of the
    /// network size (blocks built side by side share their seams).
    pub fn stitch(&mut self) {
        let doc = self;
        let size = doc.size();
        let tol = 1e-12 * size;
        let mut map: Vec<usize> = (0..doc.nodes.len()).collect();
        for i in 0..doc.nodes.len() {
            if let Some(j) = (0..i)
                .find(|&j| map[j] == j && crate::vec3::dist(doc.nodes[i], doc.nodes[j]) <= tol)
            {
                map[i] = j;
            }
        }
        for c in &mut doc.curves {
            c.from = map[c.from];
            c.to = map[c.to];
        }
        let same = |a: &CurveDoc, b: &CurveDoc| {
            let close = |p: &[f64; 3], q: &[f64; 3]| crate::vec3::dist(*p, *q) <= tol;
            let n = a.points.len() == b.points.len();
            let fwd = a.from == b.from
                && a.to == b.to
                && a.points.iter().zip(&b.points).all(|(p, q)| close(p, q));
            let rev = a.from == b.to
                && a.to == b.from
                && a.points
                    .iter()
                    .zip(b.points.iter().rev())
                    .all(|(p, q)| close(p, q));
            n && (fwd || rev)
        };
        let mut cmap: Vec<usize> = (0..doc.curves.len()).collect();
        for i in 0..doc.curves.len() {
            if let Some(j) = (0..i).find(|&j| cmap[j] == j && same(&doc.curves[i], &doc.curves[j]))
            {
                cmap[i] = j;
            }
        }
        for p in &mut doc.patches {
            for c in &mut p.curves {
                *c = cmap[*c];
            }
        }
        // drop the merged curves and nodes, renumbering
        let keep_c: Vec<usize> = (0..doc.curves.len()).filter(|&i| cmap[i] == i).collect();
        let mut new_c = vec![0; doc.curves.len()];
        for (n, &i) in keep_c.iter().enumerate() {
            new_c[i] = n;
        }
        doc.curves = keep_c.iter().map(|&i| doc.curves[i].clone()).collect();
        for p in &mut doc.patches {
            for c in &mut p.curves {
                *c = new_c[*c];
            }
        }
        let keep_n: Vec<usize> = (0..doc.nodes.len()).filter(|&i| map[i] == i).collect();
        let mut new_n = vec![0; doc.nodes.len()];
        for (n, &i) in keep_n.iter().enumerate() {
            new_n[i] = n;
        }
        doc.nodes = keep_n.iter().map(|&i| doc.nodes[i]).collect();
        for c in &mut doc.curves {
            c.from = new_n[c.from];
            c.to = new_n[c.to];
        }
    }

    /// Parses and validates a document.
    pub fn from_json(text: &str) -> Result<NetworkDoc, NetworkError> {
        let doc: NetworkDoc = serde_json::from_str(text).map_err(|e| NetworkError::Json {
            line: e.line(),
            message: e.to_string(),
        })?;
        doc.validate()?;
        Ok(doc)
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// The network's bounding-box diagonal (1 for an empty one).
    pub fn size(&self) -> f64 {
        let pts: Vec<[f64; 3]> = self
            .nodes
            .iter()
            .chain(self.curves.iter().flat_map(|c| c.points.iter()))
            .copied()
            .collect();
        let d = crate::vec3::bounds(&pts).map_or(0.0, |(lo, hi)| crate::vec3::dist(lo, hi));
        if d.is_finite() && d > 0.0 {
            d
        } else {
            1.0
        }
    }

    /// Everything that can be checked on one element at a time: version,
    /// indices, finite values, curve ends on their nodes, parameters, sides.
    pub fn validate(&self) -> Result<(), NetworkError> {
        if self.version != NETWORK_VERSION {
            return Err(NetworkError::Version {
                found: self.version,
                supported: NETWORK_VERSION,
            });
        }
        if self.patches.is_empty() {
            return Err(NetworkError::Empty);
        }
        use crate::limits::{check, NETWORK_CURVES, NETWORK_CURVE_POINTS, NETWORK_PATCHES};
        check("patches (count)", self.patches.len(), NETWORK_PATCHES)?;
        check("curves (count)", self.curves.len(), NETWORK_CURVES)?;
        check("nodes (count)", self.nodes.len(), NETWORK_CURVES)?;
        for (k, c) in self.curves.iter().enumerate() {
            check(
                &format!("curves[{k}].points (count)"),
                c.points.len(),
                NETWORK_CURVE_POINTS,
            )?;
        }
        for (i, p) in self.nodes.iter().enumerate() {
            finite(p, || format!("node {i}"))?;
        }
        let tol = NODE_TOLERANCE * self.size();
        for (k, c) in self.curves.iter().enumerate() {
            self.validate_curve(k, c, tol)?;
        }
        for (p, patch) in self.patches.iter().enumerate() {
            self.validate_patch(p, patch)?;
        }
        Ok(())
    }

    fn validate_curve(&self, k: usize, c: &CurveDoc, tol: f64) -> Result<(), NetworkError> {
        for node in [c.from, c.to] {
            if node >= self.nodes.len() {
                return Err(NetworkError::NodeIndex {
                    curve: k,
                    node,
                    nodes: self.nodes.len(),
                });
            }
        }
        if c.points.len() < 2 {
            return Err(NetworkError::TooFewPoints {
                curve: k,
                got: c.points.len(),
            });
        }
        for (i, p) in c.points.iter().enumerate() {
            finite(p, || format!("curve {k} point {i}"))?;
        }
        let ends = [
            (c.from, c.points[0], "first"),
            (c.to, c.points[c.points.len() - 1], "last"),
        ];
        for (node, p, end) in ends {
            let d = crate::vec3::dist(p, self.nodes[node]);
            if d > tol {
                return Err(NetworkError::CurveOffNode {
                    curve: k,
                    end,
                    node,
                    distance: d,
                    tolerance: tol,
                });
            }
        }
        if let Some(t) = &c.params {
            let ok = t.len() == c.points.len()
                && t.iter().all(|x| x.is_finite())
                && t[0] == 0.0
                && t[t.len() - 1] == 1.0
                && t.windows(2).all(|w| w[1] > w[0]);
            if !ok {
                return Err(NetworkError::CurveParams { curve: k });
            }
        } else if chord_params(&c.points).is_none() {
            return Err(NetworkError::DegenerateCurve { curve: k });
        }
        Ok(())
    }

    fn validate_patch(&self, p: usize, patch: &PatchDoc) -> Result<(), NetworkError> {
        let n = patch.curves.len();
        if n != 3 && n != 4 {
            return Err(NetworkError::Sides { patch: p, sides: n });
        }
        if n == 4 && patch.apex != Apex::U0 {
            return Err(NetworkError::ApexOnQuad { patch: p });
        }
        for &k in &patch.curves {
            if k >= self.curves.len() {
                return Err(NetworkError::CurveIndex {
                    patch: p,
                    curve: k,
                    curves: self.curves.len(),
                });
            }
        }
        crate::ode6::Basis::new(patch.params)
            .map_err(|source| NetworkError::Params { patch: p, source })?;
        let Some(d) = &patch.derivatives else {
            return Ok(());
        };
        for (side, cross) in [("u0", &d.u0), ("u1", &d.u1)] {
            let Some(cross) = cross else { continue };
            let curve = match (n, patch.apex, side) {
                (3, Apex::U0, "u0") | (3, Apex::U1, "u1") => {
                    return Err(NetworkError::ApexDerivatives { patch: p, side })
                }
                (3, Apex::U0, _) => patch.curves[1],
                (3, Apex::U1, _) => patch.curves[0],
                (_, _, "u0") => patch.curves[0],
                _ => patch.curves[2],
            };
            let expected = self.curves[curve].points.len();
            for (what, v) in [("first", &cross.first), ("second", &cross.second)] {
                if v.len() != expected {
                    return Err(NetworkError::CrossLength {
                        patch: p,
                        side,
                        what,
                        got: v.len(),
                        expected,
                    });
                }
                for (i, x) in v.iter().enumerate() {
                    finite(x, || format!("patch {p} {side} {what} derivative {i}"))?;
                }
            }
        }
        Ok(())
    }
}

/// A point's coordinates: finite and within [`crate::limits::MODEL_COORD`].
fn finite(p: &[f64; 3], what: impl Fn() -> String) -> Result<(), NetworkError> {
    if !p.iter().all(|x| x.is_finite()) {
        return Err(NetworkError::NonFinite { what: what() });
    }
    let max = crate::limits::MODEL_COORD;
    match p.iter().find(|x| x.abs() > max) {
        Some(&value) => Err(NetworkError::Coordinate {
            what: what(),
            value,
            max,
        }),
        None => Ok(()),
    }
}

/// Chord-length parameters of a polyline, 0 to 1; `None` when it has no
/// length or two consecutive points coincide.
pub fn chord_params(points: &[[f64; 3]]) -> Option<Vec<f64>> {
    let mut t = vec![0.0];
    for w in points.windows(2) {
        let d = crate::vec3::dist(w[0], w[1]);
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        t.push(t[t.len() - 1] + d);
    }
    let total = t[t.len() - 1];
    if !(total.is_finite() && total > 0.0) {
        return None;
    }
    let n = t.len();
    for x in &mut t {
        *x /= total;
    }
    t[n - 1] = 1.0;
    Some(t)
}
