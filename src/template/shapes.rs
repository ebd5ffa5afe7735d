//! Synthetic test shapes with exactly known outlines: a figure in A-pose
//! (front outline with head, arms, armpits, legs and crotch) and its prism.

use crate::mesh::Mesh;

/// Shape parameters of [`figure`]; `Figure::default()` is the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Figure {
    /// Half-width of the waist.
    pub waist: f64,
    /// Half-width of the shoulders.
    pub shoulders: f64,
    /// Height of the head top.
    pub height: f64,
    /// Horizontal reach of the hands.
    pub reach: f64,
}

impl Default for Figure {
    fn default() -> Self {
        Figure {
            waist: 2.0,
            shoulders: 2.2,
            height: 16.0,
            reach: 5.0,
        }
    }
}

/// The figure's front outline, counter-clockwise from the top of the head.
pub fn figure(f: Figure) -> Vec<[f64; 2]> {
    let s = f.height / 16.0;
    let w = f.waist;
    let sh = f.shoulders;
    let r = f.reach;
    // left half, from the top of the head down to the crotch
    let left: Vec<[f64; 2]> = vec![
        [-0.5, 15.9],
        [-1.0, 15.5],
        [-1.2, 14.5],
        [-0.6, 13.4],
        [-0.6, 13.0],
        [-sh, 12.6],
        [-0.6 * sh - 0.4 * r, 10.0],
        [-r + 0.2, 7.4],
        [-r, 7.0],
        [-r + 0.6, 7.1],
        [-0.7 * r, 9.0],
        [-0.6 * sh - 0.4 * r + 0.6, 10.4],
        [-sh + 0.1, 11.0],
        [-w, 9.0],
        [-w - 0.2, 7.5],
        [-1.9, 4.0],
        [-1.6, 0.8],
        [-2.2, 0.2],
        [-1.3, -0.1],
        [-0.5, 0.1],
        [-0.4, 0.8],
        [-0.3, 6.5],
    ];
    let mut out = vec![[0.0, 16.0 * s]];
    out.extend(left.iter().map(|p| [p[0], p[1] * s]));
    out.push([0.0, 7.0 * s]);
    out.extend(left.iter().rev().map(|p| [-p[0], p[1] * s]));
    out
}

/// The outline subdivided so that no edge is longer than `step`.
pub fn refined(p: &[[f64; 2]], step: f64) -> Vec<[f64; 2]> {
    let n = p.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let l = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        let k = ((l / step).ceil() as usize).max(1);
        for j in 0..k {
            let t = j as f64 / k as f64;
            out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }
    out
}

/// A prism over a front outline (no caps): vertex `i` and `n + i` are the
/// outline's point `i` at depth `-depth` and `+depth`, so the prism's front
/// outline is the polygon itself.
pub fn prism(p: &[[f64; 2]], depth: f64) -> Mesh {
    let n = p.len();
    let mut pos: Vec<[f64; 3]> = p.iter().map(|q| [q[0], q[1], -depth]).collect();
    pos.extend(p.iter().map(|q| [q[0], q[1], depth]));
    let mut tris = Vec::with_capacity(2 * n);
    for i in 0..n {
        let j = (i + 1) % n;
        let (a, b, c, d) = (i as u32, j as u32, (n + j) as u32, (n + i) as u32);
        tris.push([a, b, c]);
        tris.push([a, c, d]);
    }
    Mesh::new(pos, tris)
}
