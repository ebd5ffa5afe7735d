//! Cavity vertices of a skin: the skin vertices that no section method with
//! one outer loop per horizontal section can reach.
//!
//! The MakeHuman skin (group `body`) is one closed surface that folds in at
//! the lips into a mouth bag (from the chin to the nose, 0.88-0.92 of the
//! height) and at the eyelids into the eye sockets. Sliced horizontally,
//! such a pocket is a second loop nested inside the head's outer loop on
//! every slice but the lip slit itself (a few hundredths of a unit tall). A
//! section of the closed body ([`super::closed`], like paper 002's) is one
//! outer loop, so the reconstruction passes over the pocket and its inner
//! wall stays as far from it as the pocket is deep.
//!
//! Rule: a vertex is a *cavity* vertex when the loop of its horizontal slice
//! that passes through it lies inside another loop of that slice (a
//! majority of [`VOTES`] points of it inside). Every other vertex is on the
//! *outer skin*, including the pockets' vertices at the height of their
//! opening (the lip slit, the eye openings), whose loop there is the outer
//! one: the outer-skin maximum still counts them. The slice through a
//! vertex is taken a hair above (below, at a local top) its height so that
//! it cuts the vertex's own edges. Pockets elsewhere count as well (where
//! two toes touch, the loops between them nest: 2 vertices per foot).

use crate::mesh::Mesh;
use crate::polygon::point_in_polygon;
use crate::profile::boundary_distance;

/// Cavity vertices of a skin and how they were found.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct Cavities {
    /// `cavity[i]`: skin vertex `i` lies on a nested loop.
    #[serde(skip)]
    pub cavity: Vec<bool>,
    /// How many.
    pub count: usize,
    /// Their height range above the sole, relative to the body height
    /// (`None` when there is none).
    pub height_range_rel: Option<(f64, f64)>,
}

/// Triangles of `m` binned by their y range.
struct Bins {
    y0: f64,
    width: f64,
    tris: Vec<Vec<u32>>,
}

impl Bins {
    fn new(m: &Mesh, y0: f64, y1: f64) -> Bins {
        let n = (m.triangles.len() / 16).clamp(1, 4096);
        let width = ((y1 - y0) / n as f64).max(f64::MIN_POSITIVE);
        let mut tris = vec![Vec::new(); n];
        for (t, tri) in m.triangles.iter().enumerate() {
            let ys = tri.map(|v| m.positions[v as usize][1]);
            let lo = ys.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = ys.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let (a, b) = (Self::bin(y0, width, n, lo), Self::bin(y0, width, n, hi));
            for bin in &mut tris[a..=b] {
                bin.push(t as u32);
            }
        }
        Bins { y0, width, tris }
    }

    fn bin(y0: f64, width: f64, n: usize, y: f64) -> usize {
        (((y - y0) / width).floor().max(0.0) as usize).min(n - 1)
    }

    fn at(&self, y: f64) -> &[u32] {
        &self.tris[Self::bin(self.y0, self.width, self.tris.len(), y)]
    }
}

/// The closed loops of the horizontal slice of `m` at `y`, in (x, z),
/// from the triangles `cand` (a vertex on the plane counts as above it,
/// as [`crate::mesh::slice::slice`] does). Segments are paired by the mesh
/// edge they share (sorted, no hashing: this runs once per skin vertex).
fn loops_at(m: &Mesh, cand: &[u32], y: f64) -> Vec<Vec<[f64; 2]>> {
    let d = |v: u32| {
        let s = m.positions[v as usize][1] - y;
        if s == 0.0 {
            f64::MIN_POSITIVE
        } else {
            s
        }
    };
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut segs: Vec<[(u32, u32); 2]> = Vec::new();
    for &t in cand {
        let tri = m.triangles[t as usize];
        let mut cut = [(0, 0); 2];
        let mut n = 0;
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            if (d(a) > 0.0) != (d(b) > 0.0) && n < 2 {
                cut[n] = key(a, b);
                n += 1;
            }
        }
        if n == 2 {
            segs.push(cut);
        }
    }
    // (edge, segment) sorted: a manifold edge is shared by two segments
    let mut ends: Vec<((u32, u32), u32)> = Vec::with_capacity(2 * segs.len());
    for (i, s) in segs.iter().enumerate() {
        ends.push((s[0], i as u32));
        ends.push((s[1], i as u32));
    }
    ends.sort_unstable();
    let mut other: Vec<[u32; 2]> = vec![[u32::MAX; 2]; segs.len()];
    for w in ends.windows(2) {
        let ((e, a), (f, b)) = (w[0], w[1]);
        if e == f {
            let side = |s: u32| usize::from(segs[s as usize][1] == e);
            other[a as usize][side(a)] = b;
            other[b as usize][side(b)] = a;
        }
    }
    let point = |e: (u32, u32)| {
        let (pa, pb) = (m.positions[e.0 as usize], m.positions[e.1 as usize]);
        let (da, db) = (d(e.0), d(e.1));
        let t = da / (da - db);
        [pa[0] + t * (pb[0] - pa[0]), pa[2] + t * (pb[2] - pa[2])]
    };
    let mut used = vec![false; segs.len()];
    let mut out = Vec::new();
    for start in 0..segs.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        let mut chain = vec![point(segs[start][0])];
        let (mut cur, mut end) = (start, segs[start][1]);
        let closed = loop {
            let next = other[cur][usize::from(segs[cur][1] == end)];
            if next == start as u32 {
                break true;
            }
            if next == u32::MAX || used[next as usize] {
                break false;
            }
            chain.push(point(end));
            cur = next as usize;
            used[cur] = true;
            end = if segs[cur][0] == end {
                segs[cur][1]
            } else {
                segs[cur][0]
            };
        };
        if closed && chain.len() >= 3 {
            out.push(chain);
        }
    }
    out
}

/// The loops of one slice level, kept while consecutive vertices (sorted
/// by height) ask for the same level.
struct Level {
    y: f64,
    loops: Vec<Vec<[f64; 2]>>,
}

impl Level {
    fn get<'a>(slot: &'a mut Option<Level>, m: &Mesh, bins: &Bins, y: f64) -> &'a Level {
        if slot.as_ref().is_some_and(|l| l.y != y) {
            *slot = None;
        }
        slot.get_or_insert_with(|| Level {
            y,
            loops: loops_at(m, bins.at(y), y),
        })
    }

    /// Whether the loop nearest to `p` (x, z) lies inside another loop.
    fn nested(&self, p: [f64; 2]) -> bool {
        let loops = &self.loops;
        let Some(own) = (0..loops.len()).min_by(|&a, &b| {
            boundary_distance(&loops[a], p).total_cmp(&boundary_distance(&loops[b], p))
        }) else {
            return false;
        };
        let l = &loops[own];
        // a majority of up to VOTES points of the loop, evenly spaced: the
        // morphed MakeHuman skin pokes through itself at the mouth corners,
        // where a few points of a pocket's loop lie outside the head's
        let k = l.len().min(VOTES);
        let votes: Vec<[f64; 2]> = (0..k).map(|j| l[j * l.len() / k]).collect();
        loops
            .iter()
            .enumerate()
            .filter(|&(i, _)| i != own)
            .any(|(_, m)| 2 * votes.iter().filter(|&&q| point_in_polygon(m, q)).count() > k)
    }
}

/// Points of a loop tested for nesting (a majority decides).
pub const VOTES: usize = 15;

/// The cavity vertices of a closed skin (module doc); `height` is the body
/// height, `sole` its lowest y.
pub fn find_cavities(skin: &Mesh, sole: f64, height: f64) -> Cavities {
    let n = skin.positions.len();
    if n == 0 || skin.triangles.is_empty() || !(height > 0.0 && height.is_finite()) {
        return Cavities {
            cavity: vec![false; n],
            ..Cavities::default()
        };
    }
    let (lo, hi) = skin.bbox();
    let bins = Bins::new(skin, lo[1], hi[1]);
    // the smallest rise / fall from each vertex along its edges
    let (mut up, mut down) = (vec![f64::INFINITY; n], vec![f64::INFINITY; n]);
    for t in &skin.triangles {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            let dy = skin.positions[b][1] - skin.positions[a][1];
            for (from, g) in [(a, dy), (b, -dy)] {
                if g > 0.0 {
                    up[from] = up[from].min(g);
                } else if g < 0.0 {
                    down[from] = down[from].min(-g);
                }
            }
        }
    }
    let hair = 1e-6 * height;
    // the level through each vertex, a hair above (below at a local top)
    let own: Vec<f64> = (0..n)
        .map(|i| {
            let y = skin.positions[i][1];
            if up[i].is_finite() {
                y + (0.5 * up[i]).min(hair)
            } else if down[i].is_finite() {
                y - (0.5 * down[i]).min(hair)
            } else {
                y
            }
        })
        .collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| own[a].total_cmp(&own[b]));
    let mut cavity = vec![false; n];
    let mut slot = None;
    for &i in &order {
        let p = skin.positions[i];
        cavity[i] = Level::get(&mut slot, skin, &bins, own[i]).nested([p[0], p[2]]);
    }
    let heights = skin
        .positions
        .iter()
        .zip(&cavity)
        .filter(|(_, &c)| c)
        .map(|(p, _)| (p[1] - sole) / height);
    let range = heights.fold(None, |r: Option<(f64, f64)>, h| {
        Some(r.map_or((h, h), |(a, b)| (a.min(h), b.max(h))))
    });
    Cavities {
        count: cavity.iter().filter(|&&c| c).count(),
        cavity,
        height_range_rel: range,
    }
}

/// A unit sphere and a reversed sphere of radius 0.5 in it, one closed
/// mesh (both shells manifold and outward-oriented as a solid); the index
/// of the first inner vertex.
pub fn nested_shells() -> (Mesh, usize) {
    let mut m = closed_sphere([0.0; 3], 1.0, 32, 17);
    let inner = closed_sphere([0.1, 0.05, 0.0], 0.5, 24, 13);
    let k = m.positions.len();
    m.positions.extend(&inner.positions);
    m.triangles.extend(
        inner
            .triangles
            .iter()
            .map(|t| [t[0] + k as u32, t[2] + k as u32, t[1] + k as u32]),
    );
    m.tri_group = vec![0; m.triangles.len()];
    (m, k)
}

/// A welded UV sphere (poles on y, `nv - 1` rings of `nu` vertices),
/// outward-oriented.
fn closed_sphere(c: [f64; 3], r: f64, nu: usize, nv: usize) -> Mesh {
    use std::f64::consts::PI;
    let mut pos = vec![[c[0], c[1] - r, c[2]]];
    for j in 1..nv {
        let p = PI * j as f64 / nv as f64;
        for i in 0..nu {
            let t = 2.0 * PI * i as f64 / nu as f64;
            pos.push([
                c[0] + r * p.sin() * t.cos(),
                c[1] - r * p.cos(),
                c[2] + r * p.sin() * t.sin(),
            ]);
        }
    }
    pos.push([c[0], c[1] + r, c[2]]);
    let top = (pos.len() - 1) as u32;
    let id = |j: usize, i: usize| (1 + (j - 1) * nu + i % nu) as u32;
    let mut tris = Vec::new();
    for i in 0..nu {
        tris.push([0, id(1, i + 1), id(1, i)]);
        for j in 1..nv - 1 {
            tris.push([id(j, i), id(j, i + 1), id(j + 1, i + 1)]);
            tris.push([id(j, i), id(j + 1, i + 1), id(j + 1, i)]);
        }
        tris.push([id(nv - 1, i), id(nv - 1, i + 1), top]);
    }
    Mesh::new(pos, tris)
}
