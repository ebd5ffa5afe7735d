//! Reference meshes whose outlines are known exactly, and an independent
//! convex hull, for the checks and tests of [`super::outline_of_mesh`].

use crate::mesh::Mesh;
use std::f64::consts::PI;

/// Triangulated parametric grid `f(u, v)`, u, v in [0, 1] with `nu` x `nv`
/// cells (seams duplicated; the outline only needs the union of
/// triangles).
pub fn grid_mesh(nu: usize, nv: usize, f: impl Fn(f64, f64) -> [f64; 3]) -> Mesh {
    let mut pos = Vec::with_capacity((nu + 1) * (nv + 1));
    for i in 0..=nu {
        for j in 0..=nv {
            pos.push(f(i as f64 / nu as f64, j as f64 / nv as f64));
        }
    }
    let id = |i: usize, j: usize| (i * (nv + 1) + j) as u32;
    let mut tris = Vec::with_capacity(2 * nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            tris.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            tris.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    Mesh::new(pos, tris)
}

/// Axis-aligned box `[lo, hi]` (12 triangles).
pub fn box_mesh(lo: [f64; 3], hi: [f64; 3]) -> Mesh {
    let c = |k: usize| {
        [
            if k & 1 == 0 { lo[0] } else { hi[0] },
            if k & 2 == 0 { lo[1] } else { hi[1] },
            if k & 4 == 0 { lo[2] } else { hi[2] },
        ]
    };
    let pos = (0..8).map(c).collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let mut tris = Vec::new();
    for q in quads {
        tris.push([q[0], q[1], q[2]]);
        tris.push([q[0], q[2], q[3]]);
    }
    Mesh::new(pos, tris)
}

/// UV sphere of radius `r` centred at `c`, `n` segments around, `n / 2`
/// rings.
pub fn sphere(c: [f64; 3], r: f64, n: usize) -> Mesh {
    grid_mesh(n, n / 2, |u, v| {
        let (t, p) = (2.0 * PI * u, PI * v);
        [
            c[0] + r * p.sin() * t.cos(),
            c[1] + r * p.cos(),
            c[2] + r * p.sin() * t.sin(),
        ]
    })
}

/// Closed cylinder of radius `r` along y from `y0` to `y1`, `n` segments
/// (a vertex at angle 0, so its x and z extents are exactly +-r).
pub fn cylinder(r: f64, y0: f64, y1: f64, n: usize) -> Mesh {
    let mut m = grid_mesh(n, 1, |u, v| {
        let t = 2.0 * PI * u;
        [r * t.cos(), y0 + (y1 - y0) * v, r * t.sin()]
    });
    for y in [y0, y1] {
        m.append(&grid_mesh(n, 1, |u, v| {
            let t = 2.0 * PI * u;
            [r * v * t.cos(), y, r * v * t.sin()]
        }));
    }
    m
}

/// Torus around the y axis: radii `big` (centre circle) and `small`.
pub fn torus(big: f64, small: f64, n: usize) -> Mesh {
    grid_mesh(n, n / 2, |u, v| {
        let (t, p) = (2.0 * PI * u, 2.0 * PI * v);
        let rr = big + small * p.cos();
        [rr * t.cos(), small * p.sin(), rr * t.sin()]
    })
}

/// Convex hull (Andrew's monotone chain), counter-clockwise, collinear
/// points dropped.
pub fn convex_hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut p = points.to_vec();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut h: Vec<[f64; 2]> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in iter {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}
