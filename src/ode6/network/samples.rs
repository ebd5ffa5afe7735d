//! Bundled networks (the Fig 7 analogues): a vase, a flower, a plane-like
//! shape and a four-legged animal, each made of parts, each part a block
//! of patches (3-sided fans where a part closes to a point), and small
//! test networks. The shapes are analytic parametrisations sampled into
//! curves; the network then knows only the curves, and the patches
//! between them are the ODE's (the `v`-sides pass near, not through, the
//! sampled curves: the report measures how near). `data/network/*.json`
//! are these documents (`tests/it/ode6_network.rs` compares them).

use super::doc::{Apex, CurveDoc, NetworkDoc, PatchDoc, DEFAULT_PARAMS, NETWORK_VERSION};
use crate::ode6::Params;
use std::f64::consts::PI;

/// Intervals per sampled curve in the bundled networks (chosen so a curve
/// follows its analytic arc to well under a percent of the part's size).
pub const CURVE_SAMPLES: usize = 8;

/// One part: `nu x nv` patches over the parameter rectangle `[0, nu] x
/// [0, nv]` of `f`; `closed_v` wraps `v`; `apex_start`/`apex_end`
/// collapse the first/last row of patches to 3-sided fans (`f(0, t)` or
/// `f(nu, t)` must then be one point for every `t`).
pub struct Block<'a> {
    pub name: &'a str,
    pub nu: usize,
    pub nv: usize,
    pub closed_v: bool,
    pub apex_start: bool,
    pub apex_end: bool,
    pub params: Params,
    pub f: &'a dyn Fn(f64, f64) -> [f64; 3],
}

/// An empty document named `name`.
pub fn empty(name: &str) -> NetworkDoc {
    NetworkDoc {
        version: NETWORK_VERSION,
        name: name.to_string(),
        nodes: Vec::new(),
        curves: Vec::new(),
        patches: Vec::new(),
    }
}

/// Appends `b` to `doc` (nodes, curves and patches of its own).
pub fn add_block(doc: &mut NetworkDoc, b: &Block) {
    let cols = if b.closed_v { b.nv } else { b.nv + 1 };
    let base = doc.nodes.len();
    let mut node = vec![vec![0usize; cols]; b.nu + 1];
    for (i, row) in node.iter_mut().enumerate() {
        let apex = (i == 0 && b.apex_start) || (i == b.nu && b.apex_end);
        for (j, n) in row.iter_mut().enumerate() {
            if apex && j > 0 {
                *n = doc.nodes.len() - 1;
                continue;
            }
            doc.nodes.push((b.f)(i as f64, j as f64));
            *n = doc.nodes.len() - 1;
        }
    }
    let _ = base;
    let m = CURVE_SAMPLES;
    let curve = |doc: &mut NetworkDoc, a: usize, bn: usize, pts: Vec<[f64; 3]>| {
        let mut pts = pts;
        pts[0] = doc.nodes[a];
        let l = pts.len() - 1;
        pts[l] = doc.nodes[bn];
        doc.curves.push(CurveDoc {
            from: a,
            to: bn,
            points: pts,
            params: None,
        });
        doc.curves.len() - 1
    };
    let jn = |j: usize| j % cols;
    // sections: along v at u = i
    let mut sec = vec![vec![usize::MAX; b.nv]; b.nu + 1];
    for i in 0..=b.nu {
        if (i == 0 && b.apex_start) || (i == b.nu && b.apex_end) {
            continue;
        }
        for j in 0..b.nv {
            let pts = (0..=m)
                .map(|k| (b.f)(i as f64, j as f64 + k as f64 / m as f64))
                .collect();
            sec[i][j] = curve(doc, node[i][j], node[i][jn(j + 1)], pts);
        }
    }
    // v-sides: along u at v = j
    let mut vs = vec![vec![0usize; cols]; b.nu];
    for (i, row) in vs.iter_mut().enumerate() {
        for (j, c) in row.iter_mut().enumerate() {
            let pts = (0..=m)
                .map(|k| (b.f)(i as f64 + k as f64 / m as f64, j as f64))
                .collect();
            *c = curve(doc, node[i][j], node[i + 1][j], pts);
        }
    }
    for i in 0..b.nu {
        for j in 0..b.nv {
            let (v0, v1) = (vs[i][j], vs[i][jn(j + 1)]);
            let (curves, apex) = if i == 0 && b.apex_start {
                (vec![v1, sec[1][j], v0], Apex::U0)
            } else if i + 1 == b.nu && b.apex_end {
                (vec![sec[i][j], v1, v0], Apex::U1)
            } else {
                (vec![sec[i][j], v1, sec[i + 1][j], v0], Apex::U0)
            };
            doc.patches.push(PatchDoc {
                name: Some(format!("{}.{i}.{j}", b.name)),
                curves,
                params: b.params,
                derivatives: None,
                apex,
            });
        }
    }
}

/// A surface of revolution about `axis` through `origin`: profile
/// `(radius, height)` at `s`, angle `2 pi t / nv`, radii scaled by
/// `(ax, ay)` in the plane across the axis (a flattened section).
fn revolve(
    s: f64,
    t: f64,
    nv: usize,
    profile: &dyn Fn(f64) -> (f64, f64),
    frame: &Frame,
) -> [f64; 3] {
    let (r, h) = profile(s);
    let th = 2.0 * PI * t / nv as f64;
    frame.at(
        h,
        r * frame.scale[0] * th.cos(),
        r * frame.scale[1] * th.sin(),
    )
}

/// A placement: `origin + h axis + x side + y up'`.
#[derive(Clone, Copy)]
struct Frame {
    origin: [f64; 3],
    axis: [f64; 3],
    side: [f64; 3],
    other: [f64; 3],
    scale: [f64; 2],
}

impl Frame {
    fn new(origin: [f64; 3], axis: [f64; 3], side: [f64; 3], scale: [f64; 2]) -> Frame {
        use crate::vec3::{cross, normalize};
        let axis = normalize(axis);
        let other = normalize(cross(axis, side));
        let side = cross(other, axis);
        Frame {
            origin,
            axis,
            side,
            other,
            scale,
        }
    }

    fn at(&self, h: f64, x: f64, y: f64) -> [f64; 3] {
        std::array::from_fn(|k| {
            self.origin[k] + h * self.axis[k] + x * self.side[k] + y * self.other[k]
        })
    }
}

/// A closed body of revolution from `h0` to `h1` along its frame's axis,
/// radius `radius(f)` for `f in [0, 1]` (zero at both ends), `nu x nv`
/// patches with fans at both ends.
fn capsule(
    doc: &mut NetworkDoc,
    name: &str,
    frame: Frame,
    (nu, nv): (usize, usize),
    radius: &dyn Fn(f64) -> f64,
    (h0, h1): (f64, f64),
) {
    let profile = |s: f64| {
        let f = s / nu as f64;
        (radius(f), h0 + (h1 - h0) * f)
    };
    let f = |s: f64, t: f64| revolve(s, t, nv, &profile, &frame);
    add_block(
        doc,
        &Block {
            name,
            nu,
            nv,
            closed_v: true,
            apex_start: true,
            apex_end: true,
            params: DEFAULT_PARAMS,
            f: &f,
        },
    );
}

/// An ellipsoid-like radius: `r sin(pi f)^e`.
fn dome(r: f64, e: f64) -> impl Fn(f64) -> f64 {
    move |f: f64| r * (PI * f).sin().max(0.0).powf(e)
}

/// A vase: a fan of 3-sided patches for the base, five rings of 4-sided
/// patches up the wall to an open rim (closed in `v`).
pub fn vase() -> NetworkDoc {
    let mut doc = empty("vase");
    let (nu, nv) = (6, 4);
    let profile = |s: f64| {
        if s <= 1.0 {
            (0.55 * s, 0.0)
        } else {
            let z = (s - 1.0) / (nu as f64 - 1.0);
            (0.55 + 0.35 * (PI * z * 1.1).sin() - 0.2 * z, 1.6 * z)
        }
    };
    let frame = Frame::new([0.0; 3], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0]);
    let f = |s: f64, t: f64| revolve(s, t, nv, &profile, &frame);
    add_block(
        &mut doc,
        &Block {
            name: "vase",
            nu,
            nv,
            closed_v: true,
            apex_start: true,
            apex_end: false,
            params: DEFAULT_PARAMS,
            f: &f,
        },
    );
    doc
}

/// A flower: a stem (an open tube), a centre, five petals and two leaves
/// (flattened closed bodies with fans at both ends).
pub fn flower() -> NetworkDoc {
    let mut doc = empty("flower");
    let stem = Frame::new([0.0; 3], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0]);
    let sprofile = |s: f64| (0.05, 2.0 * s / 3.0);
    let sf = |s: f64, t: f64| revolve(s, t, 4, &sprofile, &stem);
    add_block(
        &mut doc,
        &Block {
            name: "stem",
            nu: 3,
            nv: 4,
            closed_v: true,
            apex_start: false,
            apex_end: false,
            params: DEFAULT_PARAMS,
            f: &sf,
        },
    );
    let top = [0.0, 2.0, 0.0];
    let centre = Frame::new(
        [0.0, 1.95, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0],
    );
    capsule(
        &mut doc,
        "centre",
        centre,
        (3, 6),
        &dome(0.22, 0.6),
        (0.0, 0.2),
    );
    for k in 0..5 {
        let a = 2.0 * PI * k as f64 / 5.0;
        let dir = [a.cos(), 0.35, a.sin()];
        let fr = Frame::new(top, dir, [0.0, 1.0, 0.0], [0.12, 1.0]);
        let r = |f: f64| 0.35 * (PI * f).sin().powf(0.8) * (1.0 - 0.3 * f);
        capsule(&mut doc, &format!("petal{k}"), fr, (3, 4), &r, (0.1, 0.95));
    }
    for (k, side) in [(0, 1.0), (1, -1.0)] {
        let o = [0.0, 0.7 + 0.3 * k as f64, 0.0];
        let fr = Frame::new(o, [side, 0.5, 0.2], [0.0, 1.0, 0.0], [0.08, 1.0]);
        let r = |f: f64| 0.18 * (PI * f).sin().powf(0.9);
        capsule(&mut doc, &format!("leaf{k}"), fr, (3, 4), &r, (0.0, 0.7));
    }
    doc
}

/// A plane-like shape: fuselage, two wings, tailplane and fin (closed
/// bodies with fans at both ends; wings and tail flattened).
pub fn plane() -> NetworkDoc {
    let mut doc = empty("plane");
    let x = [1.0, 0.0, 0.0];
    let fus = Frame::new([0.0; 3], x, [0.0, 1.0, 0.0], [1.0, 1.0]);
    let body = |f: f64| 0.3 * (PI * f).sin().powf(0.45) * (1.0 - 0.35 * f);
    capsule(&mut doc, "fuselage", fus, (6, 6), &body, (0.0, 4.0));
    for (name, side) in [("wing-left", 1.0), ("wing-right", -1.0)] {
        let fr = Frame::new(
            [1.6, -0.05, 0.0],
            [-0.15, 0.0, side],
            [1.0, 0.0, 0.0],
            [1.0, 0.12],
        );
        let chord = |f: f64| 0.55 * (PI * (0.5 + 0.5 * f)).sin().powf(0.5) * (1.0 - 0.4 * f);
        capsule(&mut doc, name, fr, (4, 6), &chord, (-0.3, 2.0));
    }
    for (name, side) in [("tail-left", 1.0), ("tail-right", -1.0)] {
        let fr = Frame::new(
            [3.5, 0.05, 0.0],
            [-0.2, 0.0, side],
            [1.0, 0.0, 0.0],
            [1.0, 0.12],
        );
        let chord = |f: f64| 0.3 * (PI * (0.5 + 0.5 * f)).sin().powf(0.5);
        capsule(&mut doc, name, fr, (3, 6), &chord, (-0.1, 0.8));
    }
    let fin = Frame::new(
        [3.5, 0.1, 0.0],
        [-0.35, 1.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 0.12],
    );
    let chord = |f: f64| 0.35 * (PI * (0.5 + 0.5 * f)).sin().powf(0.5);
    capsule(&mut doc, "fin", fin, (3, 6), &chord, (-0.05, 0.8));
    doc
}

/// A four-legged animal after Fig 7a: torso, neck, head, tail, two ears,
/// two eyes, front legs of three patches and rear legs of two patches
/// along their length (each part closed with fans, or an open tube).
pub fn quadruped() -> NetworkDoc {
    let mut doc = empty("quadruped");
    let x = [1.0, 0.0, 0.0];
    let y = [0.0, 1.0, 0.0];
    let torso = Frame::new([0.0, 1.0, 0.0], x, y, [1.0, 0.85]);
    capsule(
        &mut doc,
        "torso",
        torso,
        (5, 6),
        &dome(0.38, 0.5),
        (-1.0, 1.0),
    );
    let neck = Frame::new(
        [0.75, 1.15, 0.0],
        [0.6, 0.8, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 1.0],
    );
    let np = |s: f64| (0.2 - 0.03 * s, 0.55 * s / 2.0);
    let nf = |s: f64, t: f64| revolve(s, t, 6, &np, &neck);
    add_block(
        &mut doc,
        &Block {
            name: "neck",
            nu: 2,
            nv: 6,
            closed_v: true,
            apex_start: false,
            apex_end: false,
            params: DEFAULT_PARAMS,
            f: &nf,
        },
    );
    let head = Frame::new([1.05, 1.55, 0.0], [1.0, -0.25, 0.0], y, [0.9, 1.0]);
    capsule(
        &mut doc,
        "head",
        head,
        (4, 6),
        &dome(0.2, 0.55),
        (-0.15, 0.45),
    );
    for (k, z) in [(0, 0.12), (1, -0.12)] {
        let ear = Frame::new([1.0, 1.72, z], [-0.4, 1.0, z], x, [1.0, 0.25]);
        capsule(
            &mut doc,
            &format!("ear{k}"),
            ear,
            (2, 4),
            &dome(0.08, 0.7),
            (0.0, 0.25),
        );
        let eye = Frame::new([1.3, 1.6, z * 0.9], x, y, [1.0, 1.0]);
        capsule(
            &mut doc,
            &format!("eye{k}"),
            eye,
            (2, 4),
            &dome(0.035, 0.5),
            (-0.035, 0.035),
        );
    }
    tail_and_legs(&mut doc);
    doc
}

/// The quadruped's tail and legs (front: 3 patches, rear: 2; closed at the tip).
fn tail_and_legs(doc: &mut NetworkDoc) {
    let x = [1.0, 0.0, 0.0];
    let y = [0.0, 1.0, 0.0];
    let tail = Frame::new([-0.95, 1.1, 0.0], [-1.0, 0.7, 0.0], y, [1.0, 1.0]);
    let tp = |s: f64| {
        let f = s / 3.0;
        (0.06 * (1.0 - f).max(0.0).powf(0.5), 0.7 * f)
    };
    let tf = |s: f64, t: f64| revolve(s, t, 4, &tp, &tail);
    add_block(
        doc,
        &Block {
            name: "tail",
            nu: 3,
            nv: 4,
            closed_v: true,
            apex_start: false,
            apex_end: true,
            params: DEFAULT_PARAMS,
            f: &tf,
        },
    );
    for (name, xo, nu) in [
        ("leg-front-left", 0.65, 3),
        ("leg-front-right", 0.65, 3),
        ("leg-rear-left", -0.65, 2),
        ("leg-rear-right", -0.65, 2),
    ] {
        let z = if name.ends_with("left") { 0.2 } else { -0.2 };
        let fr = Frame::new([xo, 0.95, z], [0.0, -1.0, 0.0], x, [1.0, 1.0]);
        let lp = move |s: f64| {
            let f = s / nu as f64;
            let r = 0.11 - 0.04 * f;
            // the paw: the last row closes to the tip
            let r = if f > 1.0 - 1.0 / nu as f64 {
                r * (1.0 - (f - 1.0 + 1.0 / nu as f64) * nu as f64)
                    .max(0.0)
                    .sqrt()
            } else {
                r
            };
            (r, 0.95 * f)
        };
        let lf = move |s: f64, t: f64| revolve(s, t, 4, &lp, &fr);
        add_block(
            doc,
            &Block {
                name,
                nu,
                nv: 4,
                closed_v: true,
                apex_start: false,
                apex_end: true,
                params: DEFAULT_PARAMS,
                f: &lf,
            },
        );
    }
}

/// The bundled networks by name.
pub fn bundled() -> Vec<(&'static str, NetworkDoc)> {
    vec![
        ("vase", vase()),
        ("flower", flower()),
        ("plane", plane()),
        ("quadruped", quadruped()),
    ]
}

/// A small open test network: `nu x nv` patches over a wavy height field,
/// shape parameters per column of patches (`params[i]` for u-strip
/// position `i`, equal along each v-strip as eq 26 needs).
pub fn wavy_grid(nu: usize, nv: usize, params: &[Params]) -> NetworkDoc {
    let mut doc = empty("wavy-grid");
    for i in 0..nu {
        let f = move |s: f64, t: f64| {
            let (x, y) = (s + i as f64, t);
            [
                x,
                y,
                0.3 * (1.3 * x).sin() * (0.9 * y + 0.4).cos() + 0.05 * x * y,
            ]
        };
        let p = params.get(i).copied().unwrap_or(DEFAULT_PARAMS);
        add_block(
            &mut doc,
            &Block {
                name: "column",
                nu: 1,
                nv,
                closed_v: false,
                apex_start: false,
                apex_end: false,
                params: p,
                f: &f,
            },
        );
    }
    doc.stitch();
    doc
}
