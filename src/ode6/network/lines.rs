//! The boundary curves of the patches as pieces of **lines**: C2 cubic
//! splines through the `u`-sides of a v-strip, joined at the shared
//! corners, so that the constraint curves $c_k$ of two patches meeting
//! across a v-edge agree with their first and second `v`-derivatives
//! there (eq 26's $c_k^{(i)}(1) = \hat c_k^{(i)}(0)$).
//!
//! Every `U0`/`U1` side is an *element* (a curve, or the apex of a
//! 3-sided patch). Element `e` continues into `e'` at the `v = 1` end of
//! patch `p` when `e'` is the same side of the patch across `p`'s `V1`
//! side. Where two patches sharing `e` disagree about its continuation
//! (the network is irregular there) the line ends, the join stays C0 and
//! its C1/C2 jumps are reported by [`super::report`]. A line's element
//! `j` spans the spline parameter `[j, j + 1]` (one unit per patch: the
//! patches' `v` then have equal speed at the join, which eq 26 compares),
//! its points at their own parameters inside; closed lines use the
//! periodic spline. Explicit cross derivatives form lines of their own
//! along the same chains (runs of elements that all have them); at a
//! shared node their two values are averaged.

use super::doc::{chord_params, NetworkDoc};
use super::topology::{Role, Topology};
use super::NetworkError;
use crate::ode6::spline::{natural_second_derivatives, periodic_second_derivatives};
use crate::ode6::Curve;
use std::collections::HashMap;

/// A `u`-side: a curve, or the collapsed `u = 0` side of a 3-sided patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Elem {
    Curve(usize),
    Apex(usize),
}

/// A chain of elements in the direction of `v`.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    pub elems: Vec<Elem>,
    pub closed: bool,
}

/// The data of one element in the direction of `v`: parameters 0..1,
/// points, and explicit cross derivatives if any.
#[derive(Clone, Debug)]
struct ElemData {
    t: Vec<f64>,
    points: Vec<[f64; 3]>,
    cross: Option<[Vec<[f64; 3]>; 2]>,
}

/// The curves of every element.
#[derive(Clone, Debug, Default)]
pub struct Lines {
    pub lines: Vec<Line>,
    pub position: HashMap<Elem, Curve>,
    /// `[S_u, S_uu]` where the document gives them.
    pub cross: HashMap<Elem, [Curve; 2]>,
}

/// Relative tolerance for two patches' explicit derivatives on one curve.
pub const CROSS_AGREEMENT: f64 = 1e-9;

/// The element on side `role` of patch `p`.
pub fn elem(t: &Topology, p: usize, role: Role) -> Elem {
    match t.sides[p].side(role) {
        Some(s) => Elem::Curve(s.curve),
        None => Elem::Apex(p),
    }
}

impl Lines {
    pub fn new(doc: &NetworkDoc, t: &Topology) -> Result<Lines, NetworkError> {
        let data = elem_data(doc, t)?;
        let lines = chains(t);
        let mut out = Lines::default();
        for line in &lines {
            let pos: Vec<(&[f64], &[[f64; 3]])> = line
                .elems
                .iter()
                .map(|e| (&data[e].t[..], &data[e].points[..]))
                .collect();
            for (e, c) in line.elems.iter().zip(pieces(&pos, line.closed)) {
                out.position.insert(*e, c);
            }
            // runs of elements with explicit derivatives
            let has = |e: &Elem| data[e].cross.is_some();
            let whole = line.closed && line.elems.iter().all(has);
            let mut i = 0;
            while i < line.elems.len() {
                if !has(&line.elems[i]) {
                    i += 1;
                    continue;
                }
                let j = (i..line.elems.len())
                    .find(|&j| !has(&line.elems[j]))
                    .unwrap_or(line.elems.len());
                let run = &line.elems[i..j];
                let mut d: [Vec<Curve>; 2] = [Vec::new(), Vec::new()];
                for (k, dk) in d.iter_mut().enumerate() {
                    let parts: Vec<(&[f64], &[[f64; 3]])> = run
                        .iter()
                        .map(|e| {
                            let ed = &data[e];
                            let c = ed.cross.as_ref().map_or(&ed.points, |c| &c[k]);
                            (&ed.t[..], &c[..])
                        })
                        .collect();
                    *dk = pieces(&parts, whole);
                }
                let [d1, d2] = d;
                for ((e, a), b) in run.iter().zip(d1).zip(d2) {
                    out.cross.insert(*e, [a, b]);
                }
                i = j;
            }
        }
        out.lines = lines;
        Ok(out)
    }
}

/// Element data in the direction of `v`, explicit derivatives gathered
/// from both patches of a curve (and compared).
fn elem_data(doc: &NetworkDoc, t: &Topology) -> Result<HashMap<Elem, ElemData>, NetworkError> {
    let mut out: HashMap<Elem, ElemData> = HashMap::new();
    for (p, patch) in doc.patches.iter().enumerate() {
        for role in [Role::U0, Role::U1] {
            let e = elem(t, p, role);
            let Some(side) = t.sides[p].side(role) else {
                let corner = if role == Role::U0 { 0 } else { 2 };
                let apex = doc.nodes[t.sides[p].corners[corner]];
                out.entry(e).or_insert(ElemData {
                    t: vec![0.0, 1.0],
                    points: vec![apex, apex],
                    cross: None,
                });
                continue;
            };
            let c = &doc.curves[side.curve];
            let mut tt = c
                .params
                .clone()
                .or_else(|| chord_params(&c.points))
                .ok_or(NetworkError::DegenerateCurve { curve: side.curve })?;
            let mut points = c.points.clone();
            // the ends are the nodes exactly
            points[0] = doc.nodes[c.from];
            let last = points.len() - 1;
            points[last] = doc.nodes[c.to];
            let given = patch.derivatives.as_ref().and_then(|d| match role {
                Role::U0 => d.u0.as_ref(),
                _ => d.u1.as_ref(),
            });
            let mut cross = given.map(|g| [g.first.clone(), g.second.clone()]);
            if !side.along {
                tt = tt.iter().rev().map(|x| 1.0 - x).collect();
                points.reverse();
                if let Some(c) = &mut cross {
                    c[0].reverse();
                    c[1].reverse();
                }
            }
            let entry = out.entry(e).or_insert(ElemData {
                t: tt,
                points,
                cross: None,
            });
            if let Some(new) = cross {
                if let Some(old) = &entry.cross {
                    compare_cross(side.curve, p, old, &new)?;
                }
                entry.cross = Some(new);
            }
        }
    }
    Ok(out)
}

fn compare_cross(
    curve: usize,
    patch: usize,
    a: &[Vec<[f64; 3]>; 2],
    b: &[Vec<[f64; 3]>; 2],
) -> Result<(), NetworkError> {
    for k in 0..2 {
        let scale = a[k]
            .iter()
            .chain(&b[k])
            .map(|x| crate::vec3::norm(*x))
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        let diff = a[k]
            .iter()
            .zip(&b[k])
            .map(|(x, y)| crate::vec3::dist(*x, *y))
            .fold(0.0, f64::max);
        if diff > CROSS_AGREEMENT * scale {
            return Err(NetworkError::CrossDisagree {
                curve,
                patch,
                order: k + 1,
                difference: diff,
            });
        }
    }
    Ok(())
}

/// Chains of elements along the v-strips; a link is kept only when every
/// patch that proposes it agrees.
fn chains(t: &Topology) -> Vec<Line> {
    let mut next: HashMap<Elem, Option<Elem>> = HashMap::new();
    let mut prev: HashMap<Elem, Option<Elem>> = HashMap::new();
    let mut all: Vec<Elem> = Vec::new();
    for p in 0..t.sides.len() {
        for role in [Role::U0, Role::U1] {
            all.push(elem(t, p, role));
            let Some(q) = t.v_next[p] else { continue };
            let (a, b) = (elem(t, p, role), elem(t, q, role));
            let n = next.entry(a).or_insert(Some(b));
            if *n != Some(b) {
                *n = None;
            }
            let r = prev.entry(b).or_insert(Some(a));
            if *r != Some(a) {
                *r = None;
            }
        }
    }
    all.sort();
    all.dedup();
    let link = |e: Elem| {
        let b = next.get(&e).copied().flatten()?;
        (prev.get(&b).copied().flatten() == Some(e)).then_some(b)
    };
    let has_prev = |e: Elem| {
        let a = prev.get(&e).copied().flatten();
        a.is_some_and(|a| link(a) == Some(e))
    };
    let mut seen: HashMap<Elem, ()> = HashMap::new();
    let mut out = Vec::new();
    let starts: Vec<Elem> = all.iter().copied().filter(|&e| !has_prev(e)).collect();
    for start in starts.into_iter().chain(all.iter().copied()) {
        if seen.contains_key(&start) {
            continue;
        }
        seen.insert(start, ());
        let mut elems = vec![start];
        let mut closed = false;
        let mut e = start;
        while let Some(b) = link(e) {
            if b == start {
                closed = true;
                break;
            }
            if seen.insert(b, ()).is_some() {
                break;
            }
            elems.push(b);
            e = b;
        }
        out.push(Line { elems, closed });
    }
    out
}

/// One spline through the concatenated parts (part `j` on `[j, j + 1]`,
/// values at a join averaged), cut back into one [`Curve::Piece`] per part.
fn pieces(parts: &[(&[f64], &[[f64; 3]])], closed: bool) -> Vec<Curve> {
    let mut t: Vec<f64> = Vec::new();
    let mut y: Vec<[f64; 3]> = Vec::new();
    let mut offsets = Vec::with_capacity(parts.len());
    for (j, (tt, pp)) in parts.iter().enumerate() {
        let skip = usize::from(j > 0);
        if j > 0 {
            let last = y.len() - 1;
            y[last] = crate::vec3::scale(crate::vec3::add(y[last], pp[0]), 0.5);
        }
        offsets.push(t.len() - skip.min(t.len()));
        for (x, p) in tt.iter().zip(pp.iter()).skip(skip) {
            t.push(j as f64 + x);
            y.push(*p);
        }
    }
    if closed {
        let (first, last) = (y[0], y[y.len() - 1]);
        let mid = crate::vec3::scale(crate::vec3::add(first, last), 0.5);
        y[0] = mid;
        let n = y.len() - 1;
        y[n] = mid;
    }
    let mut m2 = vec![[0.0; 3]; y.len()];
    for k in 0..3 {
        let yk: Vec<f64> = y.iter().map(|p| p[k]).collect();
        let mk = if closed {
            let mut m = periodic_second_derivatives(&t, &yk);
            m.push(m[0]);
            m
        } else {
            natural_second_derivatives(&t, &yk)
        };
        for (m, v) in m2.iter_mut().zip(mk) {
            m[k] = v;
        }
    }
    let periodic = closed && parts.len() == 1;
    parts
        .iter()
        .enumerate()
        .map(|(j, (tt, _))| {
            let o = offsets[j];
            let r = o..o + tt.len();
            Curve::Piece {
                knots: t[r.clone()].iter().map(|x| x - j as f64).collect(),
                points: y[r.clone()].to_vec(),
                m2: m2[r].to_vec(),
                periodic,
            }
        })
        .collect()
}
