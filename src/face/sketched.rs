//! A face network drawn in the front view (paper 004 Fig 8: "a female face
//! from a sketched curve network", its regions 4-sided and 3-sided
//! patches).
//!
//! The drawing is a polar web around the tip of the nose, as one would
//! sketch it over a front photograph: `spokes` straight strokes from the
//! tip outward and `rings` closed strokes around it, the outer one
//! following the face window ([`super::Window`]: forehead line, cheeks,
//! jaw and chin) at [`OUTER`] of the way from the tip to it. Each stroke
//! point is lifted onto the face along the view direction (the frontmost
//! skin of the face region over it, [`super::template::face_region`],
//! [`super::template::Front`]); over the eye openings and the mouth slit,
//! which have no face skin, a point takes the mean depth of the skin
//! around the opening. The patches touching the tip are **3-sided** (a fan, the tip
//! their apex), the others 4-sided; the web is closed around the tip, so
//! every edge is a u-edge (between rings) or a v-edge (along a spoke) and
//! the network is C2 across all of them
//! ([`crate::ode6::network`]). The tip is the frontmost skin point inside
//! the window; nothing else is fitted.

use super::template::Front;
use super::{FaceError, Window};
use crate::mesh::Mesh;
use crate::ode6::network::doc::{NetworkDoc, DEFAULT_PARAMS};
use crate::ode6::network::samples::{add_block, empty, Block};

/// How far the outer ring reaches from the tip toward the window's edge:
/// inside the window, whose edge is where the face turns away from the
/// front view (cheeks, jaw), with a 5 % margin so that the outer ring
/// stays on skin that faces the viewer. Not tuned to an error.
pub const OUTER: f64 = 0.95;
/// Default strokes: spokes and rings (48 patches, as many as the default
/// column network; 12 of them 3-sided).
pub const SPOKES: usize = 12;
pub const RINGS: usize = 4;
/// Grid spacing (dm) of the search for the tip and of the front buckets:
/// two thirds of the base face's median edge (0.030 dm), so the tip is
/// found within one triangle of the frontmost vertex.
const STEP: f64 = 0.02;
/// Radii (in `STEP`s) searched around a point over an opening.
const HOLE_SEARCH: usize = 12;

/// The frontmost skin point inside the window (the tip of the nose).
fn tip(front: &Front, win: &Window) -> Option<[f64; 3]> {
    let mut best: Option<[f64; 3]> = None;
    let n = (2.0 * win.a / STEP).ceil() as usize;
    for i in 0..=n {
        let x = -win.a + 2.0 * win.a * i as f64 / n as f64;
        let (lo, hi) = (win.y_lo(x), win.y_hi);
        let m = ((hi - lo) / STEP).ceil().max(1.0) as usize;
        for j in 0..=m {
            let y = lo + (hi - lo) * j as f64 / m as f64;
            if let Some((_, _, z)) = front.hit(x, y) {
                if best.is_none_or(|b| z > b[2]) {
                    best = Some([x, y, z]);
                }
            }
        }
    }
    best
}

fn inside(win: &Window, x: f64, y: f64) -> bool {
    let (s, w) = win.unit(x, y);
    (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&w)
}

/// Distance from `o` along `d` to the window's edge (bisection; `o` inside).
fn reach(win: &Window, o: [f64; 2], d: [f64; 2]) -> f64 {
    let (mut lo, mut hi) = (0.0, 4.0 * (win.a + win.y_hi - win.y_chin));
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if inside(win, o[0] + m * d[0], o[1] + m * d[1]) {
            lo = m;
        } else {
            hi = m;
        }
    }
    lo
}

/// Depth of the skin over `(x, y)`, or the mean over the nearest circle
/// around it that meets skin (an eye opening).
fn depth(front: &Front, x: f64, y: f64) -> Option<f64> {
    if let Some((_, _, z)) = front.hit(x, y) {
        return Some(z);
    }
    for k in 1..=HOLE_SEARCH {
        let r = k as f64 * STEP;
        let zs: Vec<f64> = (0..16)
            .filter_map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 16.0;
                front.hit(x + r * a.cos(), y + r * a.sin()).map(|h| h.2)
            })
            .collect();
        if !zs.is_empty() {
            return Some(zs.iter().sum::<f64>() / zs.len() as f64);
        }
    }
    None
}

/// The sketched polar network on a mesh with the base topology (`body`:
/// which triangles are skin), `rings x spokes` patches, the inner ring of
/// them 3-sided.
pub fn polar_network(
    m: &Mesh,
    body: &[bool],
    win: &Window,
    rings: usize,
    spokes: usize,
) -> Result<NetworkDoc, FaceError> {
    if rings < 1 || spokes < 3 {
        return Err(FaceError::Template(format!(
            "a polar face network needs at least 1 ring and 3 spokes (got {rings} and {spokes})"
        )));
    }
    // the skin is the face region (`face_region`: frontmost, facing the
    // viewer, connected to the nose tip) over a slightly larger window, so
    // a stroke over the mouth slit or an eye opening finds no skin there
    // (and takes the depth around it) instead of the throat or the back of
    // the eye socket behind it
    let d = super::template::MARGIN;
    let wide = Window {
        a: win.a + d,
        y_hi: win.y_hi + d,
        y_chin: win.y_chin - d,
        y_jaw: win.y_jaw - d,
    };
    let region = super::template::face_region(m, body, &wide)?;
    let tris: Vec<u32> = (0..m.triangles.len() as u32)
        .filter(|&t| m.triangles[t as usize].iter().all(|&i| region[i as usize]))
        .collect();
    let front = Front::new(m, tris, 2.0 * STEP);
    let t = tip(&front, win).ok_or(FaceError::Template("no skin in the face window".into()))?;
    // each sample is a point of the drawing (tip + fraction of the reach
    // along the spoke direction), lifted onto the skin
    let missing = std::cell::Cell::new(None);
    let f = |s: f64, a: f64| -> [f64; 3] {
        let th = std::f64::consts::TAU * a / spokes as f64;
        let d = [th.cos(), th.sin()];
        let r = OUTER * reach(win, [t[0], t[1]], d) * s / rings as f64;
        let (x, y) = (t[0] + r * d[0], t[1] + r * d[1]);
        let z = depth(&front, x, y).unwrap_or_else(|| {
            missing.set(Some((x, y)));
            t[2]
        });
        [x, y, z]
    };
    let mut doc = empty("face-sketched");
    add_block(
        &mut doc,
        &Block {
            name: "face",
            nu: rings,
            nv: spokes,
            closed_v: true,
            apex_start: true,
            apex_end: false,
            params: DEFAULT_PARAMS,
            f: &f,
        },
    );
    if let Some((x, y)) = missing.get() {
        return Err(FaceError::Template(format!(
            "no skin within {} dm of ({x:.3}, {y:.3}) in the front view",
            HOLE_SEARCH as f64 * STEP
        )));
    }
    Ok(doc)
}

/// How far the skin lies from the network's surface: the distance of
/// every face-region vertex ([`super::template::face_region`]) whose front
/// projection is inside the web's outer ring to `net_mesh` (the network
/// meshed), in the mesh's units. `doc` is the web ([`polar_network`]: its
/// first node is the tip).
pub fn skin_distance(
    m: &Mesh,
    body: &[bool],
    win: &Window,
    doc: &NetworkDoc,
    net_mesh: &Mesh,
) -> Result<crate::mesh::metrics::DistanceStats, FaceError> {
    let t = *doc
        .nodes
        .first()
        .ok_or(FaceError::Template("an empty web".into()))?;
    let region = super::template::face_region(m, body, win)?;
    let pts: Vec<[f64; 3]> = m
        .positions
        .iter()
        .zip(&region)
        .filter(|(p, &r)| {
            let (dx, dy) = (p[0] - t[0], p[1] - t[1]);
            let r2 = dx.hypot(dy);
            r && (r2 == 0.0 || r2 <= OUTER * reach(win, [t[0], t[1]], [dx / r2, dy / r2]))
        })
        .map(|(p, _)| *p)
        .collect();
    Ok(crate::mesh::metrics::stats(
        &crate::mesh::metrics::point_distances(&pts, net_mesh),
    ))
}
