//! Paper 004 Fig 6b-d on curve networks: two patches joined in `v` (6b),
//! a grid of patches joined in `u` and `v` with a different shape-parameter
//! set per column (6c), and one surface decomposed into four patches and
//! rebuilt with C1 and with C2 joins (6d), shown by a colour map of
//! `|S_uu|` (a C1 join leaves a step in it at the join; a C2 join does not)
//! and by `|S_uu|` along the strip.

use super::{annotate, plot_profiles, y_up, Profile};
use crate::common::Ctx;
use pdesculpt::mesh::Mesh;
use pdesculpt::ode6::network::{samples, Network};
use pdesculpt::ode6::{Basis, Ode6Surface, Params};
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::surface::Surface;
use serde_json::json;

const VIEW: View = View::Perspective {
    yaw: 25.0,
    pitch: 35.0,
};
/// Cells per patch side in the figure's meshes.
const CELLS: usize = 24;
/// Colour levels of the `|S_uu|` maps.
const LEVELS: usize = 32;
/// The C1 rebuild of 6d: `rho = 0` imposes positions and tangents only
/// (`Basis::reduced`), as in panel (a)'s C1 chain.
const C1_PARAMS: Params = Params {
    rho: 0.0,
    eta: 1.0,
    lambda: 0.0,
};

fn curves(net: &Network) -> Vec<Overlay> {
    net.doc
        .curves
        .iter()
        .map(|c| Overlay {
            points: c.points.iter().map(|&p| y_up(p)).collect(),
            closed: false,
            colour: [20, 20, 20, 255],
            depth_test: true,
        })
        .collect()
}

fn render(m: &Mesh, overlays: Vec<Overlay>, colours: Option<Vec<[u8; 3]>>) -> Image {
    let mut m = m.clone();
    m.map_positions(y_up);
    let (lo, hi) = m.bbox();
    let o = RenderOptions::default()
        .with_width(380)
        .with_height(320)
        .with_view(VIEW)
        .with_overlays(overlays)
        .with_group_colours(colours);
    let cam = Camera::fit_box(lo, hi, o.view, o.width, o.height, o.margin);
    render_with_camera(&m, &o, &cam)
}

/// A blue-yellow-red ramp over `LEVELS` levels.
fn ramp(k: usize) -> [u8; 3] {
    let t = k as f64 / (LEVELS - 1) as f64;
    let (a, b, s) = if t < 0.5 {
        ([40.0, 90.0, 200.0], [245.0, 225.0, 90.0], 2.0 * t)
    } else {
        ([245.0, 225.0, 90.0], [200.0, 35.0, 35.0], 2.0 * t - 1.0)
    };
    let c = |i: usize| (a[i] + (b[i] - a[i]) * s).round() as u8;
    [c(0), c(1), c(2)]
}

/// Every patch of `patches` on a `CELLS x CELLS` grid, each triangle in the
/// group of its `|S_uu|` level (at its centre) over `0..=top`.
fn suu_mesh(patches: &[Ode6Surface], top: f64) -> Mesh {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    let mut tri_group = Vec::new();
    let n = CELLS;
    for s in patches {
        let (v0, v1) = s.v_range;
        let at = |a: f64, b: f64| (a / n as f64, v0 + (v1 - v0) * b / n as f64);
        let base = positions.len() as u32;
        for i in 0..=n {
            for j in 0..=n {
                let (u, v) = at(i as f64, j as f64);
                positions.push(s.point(u, v));
            }
        }
        let id = |i: usize, j: usize| base + (i * (n + 1) + j) as u32;
        for i in 0..n {
            for j in 0..n {
                let (u, v) = at(i as f64 + 0.5, j as f64 + 0.5);
                let level = pdesculpt::mesh::norm(s.derivative(u, v, 2, 0)) / top;
                let g = ((level * (LEVELS - 1) as f64).round() as usize).min(LEVELS - 1) as u32;
                triangles.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                triangles.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
                tri_group.extend([g, g]);
            }
        }
    }
    Mesh {
        positions,
        triangles,
        tri_group,
        groups: (0..LEVELS).map(|k| format!("level-{k}")).collect(),
    }
}

/// `|S_uu|` along a u-strip at `v` (patches in strip order).
fn suu_profile(net: &Network, patches: &[Ode6Surface], v: f64) -> Profile {
    let mut order: Vec<usize> = (0..patches.len()).collect();
    order.sort_by_key(|&p| net.place[p]);
    let n = 150;
    let mut out = Vec::new();
    for (k, &p) in order.iter().enumerate() {
        for i in 0..=n {
            let u = i as f64 / n as f64;
            let d = patches[p].derivative(u, v, 2, 0);
            out.push((k as f64 + u, pdesculpt::mesh::norm(d)));
        }
    }
    out
}

/// Fig 6b-d (see the module doc).
pub fn fig6_networks(ctx: &Ctx) -> anyhow::Result<serde_json::Value> {
    let d = pdesculpt::ode6::network::doc::DEFAULT_PARAMS;
    // (b) one column of two patches: a v-edge
    let b = Network::build(samples::wavy_grid(1, 2, &[d]))?;
    let rb = b.report(8);
    // (c) three columns, two rows, a parameter set per column (eq 26 needs
    // equal parameters along each v-strip, not across u)
    let cols = [d, Params::new(0.5, 2.0, 1.5), Params::new(2.0, 4.0, 0.5)];
    let c = Network::build(samples::wavy_grid(3, 2, &cols))?;
    let rc = c.report(8);
    // (d) one surface in four patches along u: C2 as built, C1 with the
    // reduced basis on the same boundary curves
    let c2 = Network::build(samples::wavy_grid(4, 1, &[d; 4]))?;
    let mut c1 = c2.clone();
    for p in c1.patches.iter_mut() {
        *p = Ode6Surface::new(Basis::reduced(C1_PARAMS)?, p.curves.clone());
    }
    let (r2, r1) = (c2.report(8), c1.report(8));
    let (p2, p1) = (
        suu_profile(&c2, &c2.patches, 0.5),
        suu_profile(&c1, &c1.patches, 0.5),
    );
    let top = p1
        .iter()
        .chain(&p2)
        .map(|p| p.1)
        .fold(f64::NEG_INFINITY, f64::max);
    let colours: Vec<[u8; 3]> = (0..LEVELS).map(ramp).collect();
    let panels = [
        render(&b.mesh(CELLS), curves(&b), None),
        render(&c.mesh(CELLS), curves(&c), None),
        render(
            &suu_mesh(&c1.patches, top),
            curves(&c1),
            Some(colours.clone()),
        ),
        render(&suu_mesh(&c2.patches, top), curves(&c2), Some(colours)),
    ];
    let jumps = |j: [f64; 3]| format!("{:.0e}, {:.0e}, {:.0e}", j[0], j[1], j[2]);
    annotate(
        &Image::hstack(&panels, [255, 255, 255, 255]),
        "Paper 004 Fig 6b-d: curve networks joined in v, in u and v, and C1 against C2 (colour: |S_uu|, blue low, red high)",
        &[
            format!(
                "(b) 2 patches joined in v\nv-edge jumps [C0, C1, C2]\n{}",
                jumps(rb.max_relative_v_edges)
            ),
            format!(
                "(c) 3 x 2 patches, own params\nper column; u: {}\nv: {}",
                jumps(rc.max_relative_u_edges),
                jumps(rc.max_relative_v_edges)
            ),
            format!(
                "(d) 4 patches, C1 (rho = 0)\nu-edge jumps [C0, C1, C2]\n{}",
                jumps(r1.max_relative_u_edges)
            ),
            format!(
                "(d) the same curves, C2 (ODE6)\nu-edge jumps [C0, C1, C2]\n{}",
                jumps(r2.max_relative_u_edges)
            ),
        ],
        VIEW,
        true,
    )?
    .save_png(&ctx.path("004-fig6bcd.png"))?;
    plot_profiles(
        &ctx.path("004-fig6d_curvature.png"),
        "|S_uu| along u at v = 0.5 over 4 patches (joins at u = 1, 2, 3)",
        4.0,
        &[
            ("C2: ODE6 rho = lambda = 1, eta = 3", &p2),
            ("C1: rho = 0", &p1),
        ],
    )?;
    Ok(json!({
        "b_two_patches_in_v": {"max_relative_v_edges": rb.max_relative_v_edges, "v_edges": rb.v_edges},
        "c_grid_3x2": {"params_per_column": cols, "max_relative_u_edges": rc.max_relative_u_edges,
            "max_relative_v_edges": rc.max_relative_v_edges, "u_edges": rc.u_edges, "v_edges": rc.v_edges},
        "d_four_patches": {"c1_max_relative_u_edges": r1.max_relative_u_edges,
            "c2_max_relative_u_edges": r2.max_relative_u_edges, "c1_params": C1_PARAMS, "c2_params": d},
        "note": "(b)-(d) are samples::wavy_grid networks (an analytic wavy height field sampled into curves). (d): the C1 rebuild keeps every patch's boundary curves and replaces its basis by Basis::reduced(rho = 0, eta = 1, lambda = 0), which imposes positions and first cross derivatives only, so S_uu jumps at the joins; the C2 network's jumps are rounding."
    }))
}
