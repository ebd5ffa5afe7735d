//! Figures of the ode6 family (paper 004): approach 1 (Figs 2-3), approach 2
//! (Figs 4-5), C1 against C2 joins (Fig 6), shape parameters (Fig 10), each
//! beside a loft through the same curves, and the data-size table (Table 1)
//! on MakeHuman regions.

mod continuity;
mod networks;
mod table;

use crate::common::{Ctx, Figure, PlotPng};
use anyhow::Context;
use pdesculpt::curve::Fourier3;
use pdesculpt::mesh::Mesh;
use pdesculpt::ode6::samples::test_curve;
use pdesculpt::ode6::spline::NaturalSpline;
use pdesculpt::ode6::VSplit;
use pdesculpt::ode6::{
    Approach2, Basis, BoundaryCurves, Chain, Curve, DiffFormula, Ode6Surface, Params,
};
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::surface::Joined;
use pdesculpt::surface::{tessellate, tessellate_grid, Domain, Surface, Tessellation};
use serde_json::json;

/// The figures of the ode6 family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure { id: "004-fig2-3", paper: "004", title: "Approach 1: boundary curves scaled by w1..w4 (closed and open), beside the loft", run: fig2_3 },
        Figure { id: "004-fig4-5", paper: "004", title: "Approach 2: four control curves, rho = lambda = 1 against 1e-4 (eta = 3), beside the loft", run: fig4_5 },
        Figure { id: "004-fig6", paper: "004", title: "C2 (ODE6) against C1 (rho = 0) and C0 (loft) joins: a chain (a), networks joined in v (b), in u and v (c), one surface in 4 patches with C1 and C2 joins (d)", run: fig6 },
        Figure { id: "004-fig7", paper: "004", title: "Objects from C2 ODE patches: vase, flower, plane, four-legged animal (bundled curve networks)", run: networks::fig7 },
        Figure { id: "004-fig8", paper: "004", title: "A face from its curve network alone: 48 C2 ODE patches (12 columns x 4 rows), one colour each", run: networks::fig8 },
        Figure { id: "004-fig9", paper: "004", title: "The face rebuilt from its curve network with the original's vertices and faces: MVE, wireframes of both", run: networks::fig9 },
        Figure { id: "004-fig11-12", paper: "004", title: "The face curve network on the MakeHuman base, front and side", run: networks::fig11_12 },
        Figure { id: "004-fig13", paper: "004", title: "Facial action units rebuilt from the moved network, with error colour maps", run: networks::fig13 },
        Figure { id: "004-fig10", paper: "004", title: "Shape parameters rho, eta, lambda on one patch, beside the loft", run: fig10 },
        Figure { id: "004-table1", paper: "004", title: "Data size of ODE6 curve networks on MakeHuman regions (leg, head, face)", run: table::table1 },
    ]
}

pub(crate) const NU: usize = 40;
pub(crate) const NV: usize = 96;
const VIEW: View = View::Perspective {
    yaw: 35.0,
    pitch: 25.0,
};
const GREY: [u8; 4] = [60, 60, 60, 255];
const RED: [u8; 4] = [200, 30, 30, 255];

/// Renders meshes side by side with one camera, overlays on each.
/// The figures build patches along z; the renderer has y up: (x, y, z) -> (x, z, -y).
pub(crate) fn y_up(p: [f64; 3]) -> [f64; 3] {
    [p[0], p[2], -p[1]]
}

fn panels(meshes: &[Mesh], overlays: &[Overlay], view: View) -> Image {
    let meshes: Vec<Mesh> = meshes
        .iter()
        .map(|m| {
            let mut m = m.clone();
            m.map_positions(y_up);
            m
        })
        .collect();
    let overlays: Vec<Overlay> = overlays
        .iter()
        .map(|o| Overlay {
            points: o.points.iter().map(|p| y_up(*p)).collect(),
            ..o.clone()
        })
        .collect();
    let corners: Vec<[f64; 3]> = meshes
        .iter()
        .flat_map(|m| {
            let (a, b) = m.bbox();
            [a, b]
        })
        .collect();
    let (lo, hi) =
        pdesculpt::vec3::bounds(&corners).unwrap_or(([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]));
    let o = RenderOptions::default()
        .with_width(360)
        .with_height(360)
        .with_view(view)
        .with_overlays(overlays);
    let cam = Camera::fit_box(lo, hi, view, o.width, o.height, o.margin);
    let imgs: Vec<Image> = meshes
        .iter()
        .map(|m| render_with_camera(m, &o, &cam))
        .collect();
    Image::hstack(&imgs, [255, 255, 255, 255])
}

/// Adds a title above `img` (panels of width `img.width / captions.len()`),
/// a caption under each panel (lines split at `\n`) and, in each panel's
/// lower-left corner, the model axes x, y, z as seen by `view` (`z_up`: the
/// render shows the model with z up, see [`y_up`]; else the model's own y
/// is up).
pub(crate) fn annotate(
    img: &Image,
    title: &str,
    captions: &[String],
    view: View,
    z_up: bool,
) -> anyhow::Result<Image> {
    use plotters::prelude::{Color, IntoFont, PathElement, RGBColor, Text};
    let lines = captions
        .iter()
        .map(|c| c.lines().count())
        .max()
        .unwrap_or(0);
    let (top, bottom) = (34usize, 10 + 17 * lines);
    let (w, h) = (img.width, img.height + top + bottom);
    let mut buf = vec![255u8; w * h * 3];
    for y in 0..img.height {
        for x in 0..img.width {
            let p = img.get(x, y);
            let o = 3 * ((y + top) * w + x);
            for c in 0..3 {
                let a = p[3] as u32;
                buf[o + c] = ((p[c] as u32 * a + 255 * (255 - a)) / 255) as u8;
            }
        }
    }
    let mut plot = PlotPng::from_rgb((w as u32, h as u32), buf);
    {
        let root = plot.area();
        let black = RGBColor(0, 0, 0);
        root.draw(&Text::new(
            title.to_string(),
            (10, 8),
            ("sans-serif", 18).into_font().color(&black),
        ))?;
        let n = captions.len().max(1);
        let pw = (w / n) as i32;
        let cam = Camera::fit_box([-1.0; 3], [1.0; 3], view, 10, 10, 0.1);
        let axes = [
            ("x", [1.0, 0.0, 0.0], RGBColor(200, 30, 30)),
            (
                "y",
                if z_up {
                    [0.0, 0.0, -1.0]
                } else {
                    [0.0, 1.0, 0.0]
                },
                RGBColor(20, 140, 40),
            ),
            (
                "z",
                if z_up {
                    [0.0, 1.0, 0.0]
                } else {
                    [0.0, 0.0, 1.0]
                },
                RGBColor(30, 60, 200),
            ),
        ];
        for (i, c) in captions.iter().enumerate() {
            let x0 = i as i32 * pw;
            if i > 0 {
                root.draw(&PathElement::new(
                    vec![(x0, top as i32), (x0, (top + img.height) as i32)],
                    RGBColor(200, 200, 200).stroke_width(1),
                ))?;
            }
            for (l, line) in c.lines().enumerate() {
                root.draw(&Text::new(
                    line.to_string(),
                    (x0 + 8, (top + img.height + 4 + 17 * l) as i32),
                    ("sans-serif", 14).into_font().color(&black),
                ))?;
            }
            let o = (x0 + 30, (top + img.height) as i32 - 30);
            for (name, axis, col) in axes {
                let d = cam.to_view_dir(axis);
                let e = (o.0 + (22.0 * d[0]) as i32, o.1 - (22.0 * d[1]) as i32);
                root.draw(&PathElement::new(vec![o, e], col.stroke_width(2)))?;
                root.draw(&Text::new(
                    name,
                    (e.0 + 2, e.1 - 7),
                    ("sans-serif", 13).into_font().color(&col),
                ))?;
            }
        }
        root.present().context("drawing the annotations")?;
    }
    Ok(plot.into_image())
}

fn overlay(c: &Curve, colour: [u8; 4]) -> Overlay {
    let pts = (0..=120).map(|i| c.eval(i as f64 / 120.0)).collect();
    Overlay {
        points: pts,
        closed: c.closed(),
        colour,
        depth_test: false,
    }
}

/// The loft baseline: a natural cubic spline in u through `curves` at
/// `knots` (two curves: the ruled surface), sampled on the figure grid.
pub(crate) fn loft(curves: &[&Curve], knots: &[f64], nu: usize, nv: usize) -> anyhow::Result<Mesh> {
    let closed = curves[0].closed();
    let us: Vec<f64> = (0..=nu)
        .map(|i| knots[0] + (knots[knots.len() - 1] - knots[0]) * i as f64 / nu as f64)
        .collect();
    let nvp = if closed { nv } else { nv + 1 };
    let vs: Vec<f64> = (0..nvp).map(|j| j as f64 / nv as f64).collect();
    let mut pts = vec![[0.0; 3]; us.len() * nvp];
    for (j, &v) in vs.iter().enumerate() {
        let p: Vec<[f64; 3]> = curves.iter().map(|c| c.eval(v)).collect();
        for k in 0..3 {
            let y: Vec<f64> = p.iter().map(|q| q[k]).collect();
            let spline = NaturalSpline::new(knots, &y)?;
            for (i, &u) in us.iter().enumerate() {
                pts[i * nvp + j][k] = spline.eval(u);
            }
        }
    }
    let d = Domain {
        u: (knots[0], knots[knots.len() - 1]),
        v: (0.0, 1.0),
        closed_u: false,
        closed_v: closed,
    };
    Ok(tessellate_grid(pts, us.len(), nvp, d))
}

fn tess<S: Surface + Send + Sync>(s: &S) -> Mesh {
    tessellate(s, Tessellation { nu: NU, nv: NV })
}

/// An open arc (polyline -> natural spline) at height z.
fn open_curve(scale: f64, z: f64, bend: f64) -> anyhow::Result<Curve> {
    let pts: Vec<[f64; 3]> = (0..=24)
        .map(|i| {
            let s = i as f64 / 24.0;
            let a = std::f64::consts::PI * (0.1 + 0.8 * s);
            [
                scale * a.cos(),
                bend * scale * a.sin(),
                z + 0.1 * (3.0 * a).sin(),
            ]
        })
        .collect();
    Ok(Curve::from_polyline(&pts, false)?)
}

/// Largest distance from points to a mesh's vertices' closest triangle.
fn dist_to(points: &[[f64; 3]], m: &Mesh) -> f64 {
    pdesculpt::mesh::metrics::point_distances(points, m)
        .into_iter()
        .fold(0.0, f64::max)
}

fn fig2_3(ctx: &Ctx) -> anyhow::Result<()> {
    let paper = Params::new(1.0, 3.0, 1.0);
    let ws = [
        ("w = 0", [0.0; 4]),
        ("w1 = 1, w3 = 10", [1.0, 0.0, 10.0, 0.0]),
        ("w2 = 1, w4 = 10", [0.0, 1.0, 0.0, 10.0]),
    ];
    let mut data = Vec::new();
    for (name, c1, c4) in [
        (
            "fig2_closed",
            Curve::Fourier(test_curve(1.0, 0.0, 0.0)),
            Curve::Fourier(test_curve(0.6, 1.0, 1.0)),
        ),
        (
            "fig3_open",
            open_curve(1.0, 0.0, 1.0)?,
            open_curve(0.8, 1.0, 0.5)?,
        ),
    ] {
        let lofted = loft(&[&c1, &c4], &[0.0, 1.0], NU, NV)?;
        let mut meshes = vec![lofted.clone()];
        let mut rows = Vec::new();
        for (wname, w) in ws {
            let s = Ode6Surface::new(
                Basis::new(paper)?,
                BoundaryCurves::approach1(c1.clone(), c4.clone(), w)?,
            );
            let m = tess(&s);
            // w = 0 keeps every point on the segment c1(v)-c4(v): on the loft.
            rows.push(json!({"w": w, "label": wname, "max_distance_to_loft": dist_to(&m.positions, &lofted), "vertices": m.positions.len()}));
            meshes.push(m);
        }
        let img = panels(&meshes, &[overlay(&c1, RED), overlay(&c4, RED)], VIEW);
        let kind = if name.contains("closed") {
            "closed (Fig 2)"
        } else {
            "open (Fig 3)"
        };
        let mut caps = vec!["loft (ruled) through c1, c4".to_string()];
        caps.extend(ws.iter().map(|(l, _)| format!("ODE6 approach 1, {l}")));
        annotate(
            &img,
            &format!("Paper 004 approach 1, {kind} curves: c2 = w1 c1, c3 = w2 c1, c5 = w3 c4, c6 = w4 c4 (rho = lambda = 1, eta = 3); red: c1, c4"),
            &caps,
            VIEW,
            true,
        )?
        .save_png(&ctx.path(&format!("004-{name}.png")))?;
        data.push(json!({"figure": name, "panels": ["loft (ruled)", "w = 0", "w1 = 1, w3 = 10", "w2 = 1, w4 = 10"], "params": paper, "surfaces": rows}));
    }
    ctx.write_json("004-fig2-3.json", &json!({"figures": data, "note": "approach 1, rho = lambda = 1, eta = 3; w = 0 lies on the loft (distance ~ tessellation chord error only)"}))?;
    Ok(())
}

/// `c` scaled about its centre by `s`, moved to height `z`, turned by `a`.
fn control_from(c: &Fourier3, s: f64, z: f64, a: f64) -> Curve {
    let rot = |p: [f64; 3]| {
        [
            p[0] * a.cos() - p[1] * a.sin(),
            p[0] * a.sin() + p[1] * a.cos(),
            p[2],
        ]
    };
    let sc = |v: &Vec<[f64; 3]>| {
        v.iter()
            .map(|p| rot([p[0] * s, p[1] * s, p[2] * s]))
            .collect()
    };
    Curve::Fourier(Fourier3 {
        c0: [c.c0[0], c.c0[1], z],
        cos: sc(&c.cos),
        sin: sc(&c.sin),
    })
}

fn open_control(c: &Curve, s: f64, dz: f64) -> anyhow::Result<Curve> {
    let pts: Vec<[f64; 3]> = (0..=24)
        .map(|i| c.eval(i as f64 / 24.0))
        .map(|p| [p[0] * s, p[1] * s, p[2] + dz])
        .collect();
    Ok(Curve::from_polyline(&pts, false)?)
}

fn fig4_5(ctx: &Ctx) -> anyhow::Result<()> {
    let (u2, u3, u5, u6) = (0.15, 0.3, 0.7, 0.85);
    let (fa, fb) = (test_curve(1.0, 0.0, 0.0), test_curve(0.6, 1.0, 1.0));
    let closed = {
        let (c1, c4) = (Curve::Fourier(fa.clone()), Curve::Fourier(fb.clone()));
        let ctl = [
            control_from(&fa, 1.3, u2, 0.1),
            control_from(&fa, 1.2, u3, 0.2),
            control_from(&fb, 1.4, u5, -0.2),
            control_from(&fb, 1.2, u6, -0.1),
        ];
        (c1, ctl, c4)
    };
    let open = {
        let (c1, c4) = (open_curve(1.0, 0.0, 1.0)?, open_curve(0.8, 1.0, 0.5)?);
        let ctl = [
            open_control(&c1, 1.3, u2)?,
            open_control(&c1, 1.2, u3)?,
            open_control(&c4, 1.3, u5 - 1.0)?,
            open_control(&c4, 1.15, u6 - 1.0)?,
        ];
        (c1, ctl, c4)
    };
    let mut data = Vec::new();
    for (name, (c1, ctl, c4)) in [("fig4_closed", closed), ("fig5_open", open)] {
        let knots = [0.0, u2, u3, u5, u6, 1.0];
        let all = [&c1, &ctl[0], &ctl[1], &ctl[2], &ctl[3], &c4];
        let lofted = loft(&all, &knots, NU, NV)?;
        let mut meshes = vec![lofted.clone()];
        let mut rows = Vec::new();
        for (p, formula) in [
            (Params::new(1.0, 3.0, 1.0), DiffFormula::ThreePoint),
            (Params::new(1e-4, 3.0, 1e-4), DiffFormula::ThreePoint),
            (Params::new(1.0, 3.0, 1.0), DiffFormula::Printed),
        ] {
            let a = Approach2 {
                u2,
                u3,
                u5,
                u6,
                formula,
            };
            let s = Ode6Surface::new(
                Basis::new(p)?,
                BoundaryCurves::approach2(c1.clone(), ctl.clone(), c4.clone(), &a)?,
            );
            // Distance of each control curve to the surface's iso-line at its u.
            let ctl_dist: Vec<f64> = [(u2, &ctl[0]), (u3, &ctl[1]), (u5, &ctl[2]), (u6, &ctl[3])]
                .iter()
                .map(|(u, c)| {
                    (0..64)
                        .map(|j| j as f64 / 64.0)
                        .map(|v| pdesculpt::mesh::dist(s.point(*u, v), c.eval(v)))
                        .fold(0.0, f64::max)
                })
                .collect();
            let m = tess(&s);
            rows.push(json!({"params": p, "formula": format!("{formula:?}"), "case": s.basis.case.name(), "control_curve_distance_at_its_u": ctl_dist, "max_distance_to_loft": dist_to(&m.positions, &lofted)}));
            meshes.push(m);
        }
        let mut ov: Vec<Overlay> = all.iter().map(|c| overlay(c, RED)).collect();
        ov.truncate(6);
        let kind = if name.contains("closed") {
            "closed (Fig 4)"
        } else {
            "open (Fig 5)"
        };
        annotate(
            &panels(&meshes, &ov, VIEW),
            &format!("Paper 004 approach 2, {kind}: c1, c4 and control curves at u = {u2}, {u3}, {u5}, {u6} (red)"),
            &[
                "loft (natural spline in u)\nthrough the 6 curves".to_string(),
                "ODE6 rho = lambda = 1, eta = 3\n(three-point derivatives)".to_string(),
                "ODE6 rho = lambda = 1e-4, eta = 3\n(three-point derivatives)".to_string(),
                "ODE6 rho = lambda = 1, eta = 3\n(printed eqs 4-7)".to_string(),
            ],
            VIEW,
            true,
        )?
        .save_png(&ctx.path(&format!("004-{name}.png")))?;
        data.push(json!({"figure": name, "panels": ["loft through the 6 curves", "rho = lambda = 1, eta = 3 (three-point)", "rho = lambda = 1e-4, eta = 3 (three-point)", "rho = lambda = 1, eta = 3 (printed eqs 4-7)"], "u": [u2, u3, u5, u6], "surfaces": rows}));
    }
    ctx.write_json("004-fig4-5.json", &json!({"figures": data}))?;
    Ok(())
}

/// A linear combination of curves of one kind (Fourier, or splines with
/// equal vertex counts): both representations are linear in their data.
fn lin_curves(terms: &[(f64, &Curve)]) -> Curve {
    match terms[0].1 {
        Curve::Fourier(_) => {
            let fs: Vec<(f64, &Fourier3)> = terms
                .iter()
                .filter_map(|(w, c)| match c {
                    Curve::Fourier(f) => Some((*w, f)),
                    _ => None,
                })
                .collect();
            Curve::Fourier(Fourier3::weighted_sum(&fs))
        }
        Curve::Spline { points, .. } => {
            let n = points.len();
            let mut p = vec![[0.0; 3]; n];
            let mut m = vec![[0.0; 3]; n];
            for (w, c) in terms {
                if let Curve::Spline { points, m2 } = c {
                    for i in 0..n.min(points.len()) {
                        for k in 0..3 {
                            p[i][k] += w * points[i][k];
                            m[i][k] += w * m2[i][k];
                        }
                    }
                }
            }
            Curve::Spline { points: p, m2: m }
        }
        Curve::Hermite { .. } => {
            let mut ends = [[[0.0; 3]; 3]; 2];
            for (w, c) in terms {
                if let Curve::Hermite { ends: e } = c {
                    for (a, b) in ends
                        .iter_mut()
                        .flatten()
                        .flatten()
                        .zip(e.iter().flatten().flatten())
                    {
                        *a += w * b;
                    }
                }
            }
            Curve::Hermite { ends }
        }
        Curve::Piece {
            knots, periodic, ..
        } => {
            let n = knots.len();
            let (mut p, mut m) = (vec![[0.0; 3]; n], vec![[0.0; 3]; n]);
            for (w, c) in terms {
                if let Curve::Piece { points, m2, .. } = c {
                    for i in 0..n.min(points.len()) {
                        for k in 0..3 {
                            p[i][k] += w * points[i][k];
                            m[i][k] += w * m2[i][k];
                        }
                    }
                }
            }
            Curve::Piece {
                knots: knots.clone(),
                points: p,
                m2: m,
                periodic: *periodic,
            }
        }
    }
}

/// Sections with finite-difference first and second derivative curves (per
/// unit of patch parameter).
pub(crate) fn sections_from(p: &[Curve]) -> Vec<[Curve; 3]> {
    let n = p.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            let d1 = lin_curves(&[
                (1.0 / (b - a) as f64, &p[b]),
                (-1.0 / (b - a) as f64, &p[a]),
            ]);
            let (a2, m2, b2) = if i == 0 {
                (0, 1, 2)
            } else if i == n - 1 {
                (n - 3, n - 2, n - 1)
            } else {
                (i - 1, i, i + 1)
            };
            let d2 = lin_curves(&[(1.0, &p[a2]), (-2.0, &p[m2]), (1.0, &p[b2])]);
            [p[i].clone(), d1, d2]
        })
        .collect()
}

fn fig6(ctx: &Ctx) -> anyhow::Result<()> {
    let secs = [
        test_curve(1.0, 0.0, 0.0),
        test_curve(0.6, 1.0, 0.8),
        test_curve(1.1, 2.0, -0.5),
        test_curve(0.7, 3.0, 0.3),
    ];
    let sections = sections_from(
        &secs
            .iter()
            .map(|f| Curve::Fourier(f.clone()))
            .collect::<Vec<_>>(),
    );
    let c2 = Chain::from_sections(
        &sections,
        (0..3)
            .map(|_| Basis::new(Params::new(1.0, 3.0, 1.0)))
            .collect::<Result<_, _>>()?,
    )?;
    let c1 = Chain::from_sections(
        &sections,
        (0..3)
            .map(|_| Basis::reduced(Params::new(0.0, 1.0, 0.0)))
            .collect::<Result<_, _>>()?,
    )?;
    let curves: Vec<Curve> = secs.iter().map(|f| Curve::Fourier(f.clone())).collect();
    let lofted: Vec<Mesh> = (0..3)
        .map(|i| {
            loft(
                &[&curves[i], &curves[i + 1]],
                &[i as f64, i as f64 + 1.0],
                NU,
                NV,
            )
        })
        .collect::<anyhow::Result<_>>()?;
    let mut loft_mesh = lofted[0].clone();
    loft_mesh.append(&lofted[1]);
    loft_mesh.append(&lofted[2]);
    let tc = |c: &Chain| tessellate(c, Tessellation { nu: 3 * NU, nv: NV });
    let ov: Vec<Overlay> = curves.iter().map(|c| overlay(c, RED)).collect();
    annotate(
        &panels(&[loft_mesh, tc(&c1), tc(&c2)], &ov, VIEW),
        "Paper 004 Fig 6: a chain of 3 patches through 4 sections (red), joins at u = 1, 2",
        &[
            "loft per pair of sections\n(C0 joins)".to_string(),
            "rho = 0, eta = 1, lambda = 0\n(C1: positions + tangents)".to_string(),
            "ODE6 rho = lambda = 1, eta = 3\n(C2 joins, eqs 23-25)".to_string(),
        ],
        VIEW,
        true,
    )?
    .save_png(&ctx.path("004-fig6.png"))?;
    // Curvature |S_uu| along u at v = 0.1 through the joins.
    let v = 0.1;
    let n = 600;
    let prof = |c: &Chain| -> Vec<(f64, f64)> {
        (0..=n)
            .map(|i| {
                let u = 3.0 * i as f64 / n as f64 * 0.99999;
                let k = (u.floor() as usize).min(2);
                let d = c.patches[k].derivative(u - k as f64, v, 2, 0);
                (u, pdesculpt::mesh::norm(d))
            })
            .collect()
    };
    let (p2, p1) = (prof(&c2), prof(&c1));
    plot_profiles(
        &ctx.path("004-fig6_curvature.png"),
        "|S_uu| along u at v = 0.1 (joins at u = 1, 2)",
        3.0,
        &[
            ("C2: ODE6 rho = lambda = 1, eta = 3", &p2),
            ("C1: rho = 0 (positions + tangents only)", &p1),
        ],
    )?;
    let j2 = c2.join_jumps(32);
    let j1 = c1.join_jumps(32);
    // Fig 6b: v-split with the paper's parameters against equal ones.
    let bc =
        BoundaryCurves::approach1(curves[0].clone(), curves[1].clone(), [1.0, 0.5, -1.0, 2.0])?;
    let split = |pa: Params, pb: Params| -> anyhow::Result<[f64; 3]> {
        let a = Ode6Surface::new(Basis::new(pa)?, bc.clone()).with_v_range(0.0, 0.5)?;
        let b = Ode6Surface::new(Basis::new(pb)?, bc.clone()).with_v_range(0.5, 1.0)?;
        Ok(VSplit {
            below: &a,
            above: &b,
        }
        .join_jumps(40))
    };
    ctx.write_json(
        "004-fig6.json",
        &json!({
            "panels": ["loft per pair of sections (C0)", "rho = 0 chain (C1)", "ODE6 chain (C2)"],
            "u_jumps_c2_chain": {"c0": j2[0], "c1": j2[1], "c2": j2[2]},
            "u_jumps_c1_chain": {"c0": j1[0], "c1": j1[1], "c2": j1[2]},
            "grid_3x2_jumps": pdesculpt::ode6::samples::grid_3x2()?.join_jumps(32),
            "v_split_fig6b_params_jumps": split(Params::new(1.0, 1.0, 3.0), Params::new(0.1, 0.1, 3.0))?,
            "networks_b_c_d": continuity::fig6_networks(ctx)?,
            "note": "S_uu jumps across the joins of the rho = 0 (C1) chain; the ODE6 chain is C2 to rounding. grid_3x2_jumps: the separately built 3 x 2 grid of the check ode6.continuity_grid_3x2 (jumps and derivative magnitudes at its u- and v-joins). Fig 6b's parameters (rho = eta = 1 vs 0.1, lambda = 3) on one split patch break even C0 in v."
        }),
    )?;
    Ok(())
}

/// A sampled function `(x, y)`.
pub(crate) type Profile = Vec<(f64, f64)>;

/// Line plots of profiles over `0..x_max`.
pub(crate) fn plot_profiles(
    path: &std::path::Path,
    caption: &str,
    x_max: f64,
    series: &[(&str, &Profile)],
) -> anyhow::Result<()> {
    use plotters::prelude::*;
    let ymax = series
        .iter()
        .flat_map(|s| s.1.iter().map(|p| p.1))
        .fold(0.0, f64::max)
        * 1.1;
    let mut plot = PlotPng::new((900, 420));
    {
        let root = plot.area();
        root.fill(&WHITE)?;
        let mut ch = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 20))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(55)
            .build_cartesian_2d(0.0..x_max, 0.0..ymax)?;
        ch.configure_mesh()
            .x_desc(format!("u ({x_max} patches)"))
            .y_desc("|S_uu|")
            .draw()?;
        let colours = [RGBColor(30, 90, 200), RGBColor(200, 40, 40)];
        for (i, (name, pts)) in series.iter().enumerate() {
            let c = colours[i % 2];
            ch.draw_series(LineSeries::new(pts.iter().copied(), c.stroke_width(2)))?
                .label(*name)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                });
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
        root.present().context("writing plot")?;
    }
    plot.save(path)?;
    Ok(())
}

fn fig10(ctx: &Ctx) -> anyhow::Result<()> {
    let (c1, c4) = (
        Curve::Fourier(test_curve(1.0, 0.0, 0.0)),
        Curve::Fourier(test_curve(0.6, 1.0, 1.0)),
    );
    let w = [1.0, 2.0, -1.0, 4.0];
    let lofted = loft(&[&c1, &c4], &[0.0, 1.0], NU, NV)?;
    let sets = [
        Params::new(1.0, 3.0, 1.0),
        Params::new(1.0, 1.0, 3.0),
        Params::new(1e-4, 3.0, 1e-4),
        Params::new(1.0, -20.0, 50.0),
        Params::new(1.0, 30.0, 200.0),
    ];
    let mut meshes = vec![lofted.clone()];
    let mut rows = Vec::new();
    for p in sets {
        let s = Ode6Surface::new(
            Basis::new(p)?,
            BoundaryCurves::approach1(c1.clone(), c4.clone(), w)?,
        );
        let m = tess(&s);
        rows.push(json!({"params": p, "case": s.basis.case.name(), "boundary_error": s.basis.boundary_error(), "max_distance_to_loft": dist_to(&m.positions, &lofted)}));
        meshes.push(m);
    }
    let mut caps = vec!["loft (ruled) through c1, c4".to_string()];
    caps.extend(rows.iter().map(|r| {
        format!(
            "rho = {}, eta = {}, lambda = {}\n{}",
            r["params"]["rho"],
            r["params"]["eta"],
            r["params"]["lambda"],
            r["case"]
                .as_str()
                .unwrap_or("")
                .split(" (")
                .next()
                .unwrap_or("")
        )
    }));
    annotate(
        &panels(&meshes, &[overlay(&c1, GREY), overlay(&c4, GREY)], VIEW),
        &format!(
            "Paper 004 Fig 10: shape parameters on one approach-1 patch (w = {w:?}); grey: c1, c4"
        ),
        &caps,
        VIEW,
        true,
    )?
    .save_png(&ctx.path("004-fig10.png"))?;
    ctx.write_json("004-fig10.json", &json!({"panels": ["loft", "rho=1 eta=3 lambda=1", "rho=1 eta=1 lambda=3 (complex roots)", "rho=lambda=1e-4 eta=3", "rho=1 eta=-20 lambda=50 (growing)", "rho=1 eta=30 lambda=200 (oscillatory)"], "w": w, "surfaces": rows}))?;
    Ok(())
}
