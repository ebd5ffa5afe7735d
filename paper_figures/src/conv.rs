//! Figures of the conv family (paper 003, SketchCo): analogues of Figs 2,
//! 4, 5, 7 and 8, each with a data JSON that includes the
//! silhouette-following error (surface outline projected onto the stroke
//! plane vs the stroke, relative to the stroke size).

use crate::common::{Ctx, Figure, PlotPng};
use pdesculpt::conv::fit::Solver;
use pdesculpt::conv::model::{BuiltModel, Component, Model, Polygonizer, View as PlaneView};
use pdesculpt::conv::silhouette::{silhouette_error, SilhouetteError};
use pdesculpt::conv::skeleton::TriangleKind;
use pdesculpt::conv::{shapes, sketch};
use pdesculpt::mesh::Mesh;
use pdesculpt::render::{render, Image, Overlay, RenderOptions, View};
use plotters::prelude::*;
use serde_json::json;

/// The figures of the conv family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "003-fig2",
            paper: "003",
            title: "Stroke filtering, CDT, triangle types, circles, skeleton, surface",
            run: fig2,
        },
        Figure {
            id: "003-fig4",
            paper: "003",
            title: "Surface without and with global interpolation",
            run: fig4,
        },
        Figure {
            id: "003-fig5",
            paper: "003",
            title: "Global interpolation solvers: projected LM, Hildreth-d'Esopo, Lawson-Hanson",
            run: fig5,
        },
        Figure {
            id: "003-fig7",
            paper: "003",
            title: "Merging two components sketched on planes at different depths",
            run: fig7,
        },
        Figure {
            id: "003-fig8",
            paper: "003",
            title: "Several silhouettes and their convolution surfaces (incl. a folding stroke)",
            run: fig8,
        },
        Figure {
            id: "003-polygonizers",
            paper: "003",
            title: "Marching tetrahedra vs surface nets: count, quality, topology, distance, time",
            run: fig_polygonizers,
        },
    ]
}

const RES: usize = 64;

fn single(name: &str, stroke: Vec<[f64; 2]>, solver: Solver) -> anyhow::Result<(BuiltModel, Mesh)> {
    let m = Model {
        name: name.into(),
        options: sketch::ConvOptions::default().with_solver(solver),
        components: vec![Component {
            name: name.into(),
            stroke,
            ..Default::default()
        }],
        operations: Vec::new(),
    };
    let b = m.build()?;
    let mesh = b.polygonize(RES, m.options.threshold, Polygonizer::MarchingTetrahedra)?;
    Ok((b, mesh))
}

fn front_error(b: &BuiltModel, mesh: &Mesh, comp: usize) -> SilhouetteError {
    let c = &b.components[comp];
    let n = c.frame[2];
    silhouette_error(
        mesh,
        [n[0] * c.depth, n[1] * c.depth, n[2] * c.depth],
        c.frame[0],
        c.frame[1],
        &c.sketch.polygon,
    )
}

fn overlay(poly: &[[f64; 2]]) -> Overlay {
    Overlay {
        points: poly.iter().map(|p| [p[0], p[1], 0.0]).collect(),
        closed: true,
        colour: [220, 30, 30, 255],
        depth_test: false,
    }
}

fn views(mesh: &Mesh, poly: Option<&[[f64; 2]]>, size: usize) -> Image {
    let mut front = RenderOptions::default().with_width(size).with_height(size);
    if let Some(p) = poly {
        front.overlays.push(overlay(p));
    }
    let persp = RenderOptions::default()
        .with_width(size)
        .with_height(size)
        .with_view(View::Perspective {
            yaw: 35.0,
            pitch: 20.0,
        });
    Image::hstack(&[render(mesh, &front), render(mesh, &persp)], [255; 4])
}

fn bounds(poly: &[[f64; 2]]) -> (f64, f64, f64, f64) {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for p in poly {
        x0 = x0.min(p[0]);
        x1 = x1.max(p[0]);
        y0 = y0.min(p[1]);
        y1 = y1.max(p[1]);
    }
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let h = 0.55 * (x1 - x0).max(y1 - y0);
    (cx - h, cx + h, cy - h, cy + h)
}

fn circle_path(c: [f64; 2], r: f64) -> Vec<(f64, f64)> {
    (0..=64)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 64.0;
            (c[0] + r * t.cos(), c[1] + r * t.sin())
        })
        .collect()
}

fn closed(poly: &[[f64; 2]]) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = poly.iter().map(|p| (p[0], p[1])).collect();
    if let Some(&f) = v.first() {
        v.push(f);
    }
    v
}

/// Panels (a)-(e) of Fig 2 for one sketch.
fn fig2_panels(
    path: &std::path::Path,
    raw: &[[f64; 2]],
    sk: &sketch::Sketch,
) -> anyhow::Result<()> {
    let panel = 360u32;
    let mut plot = PlotPng::new((panel * 5, panel + 30));
    {
        let root = plot.area();
        root.fill(&WHITE)?;
        let areas = root.split_evenly((1, 5));
        let (x0, x1, y0, y1) = bounds(&sk.polygon);
        let titles = [
            "(a) stroke, filtered",
            "(b) CDT",
            "(c) T / S / J triangles",
            "(d) circles",
            "(e) skeleton",
        ];
        let poly = &sk.polygon;
        for (k, area) in areas.iter().enumerate() {
            let mut ch = ChartBuilder::on(area)
                .caption(titles[k], ("sans-serif", 18))
                .margin(6)
                .build_cartesian_2d(x0..x1, y0..y1)?;
            let tri_pts = |t: &pdesculpt::conv::skeleton::SkeletonTriangle| {
                t.vertices
                    .iter()
                    .map(|&i| (poly[i][0], poly[i][1]))
                    .collect::<Vec<_>>()
            };
            match k {
                0 => {
                    ch.draw_series(LineSeries::new(closed(raw), RGBColor(160, 160, 160)))?;
                    ch.draw_series(LineSeries::new(closed(poly), BLACK.stroke_width(2)))?;
                    ch.draw_series(
                        poly.iter()
                            .map(|p| Circle::new((p[0], p[1]), 3, RED.filled())),
                    )?;
                }
                1 | 2 => {
                    for t in &sk.skeleton.triangles {
                        let col = match (k, t.kind) {
                            (1, _) => RGBColor(235, 235, 235),
                            (_, TriangleKind::Terminal) => RGBColor(90, 120, 230),
                            (_, TriangleKind::Sleeve) => RGBColor(90, 200, 110),
                            (_, TriangleKind::Junction) => RGBColor(230, 80, 80),
                        };
                        ch.draw_series(std::iter::once(Polygon::new(
                            tri_pts(t),
                            col.mix(0.7).filled(),
                        )))?;
                        let mut p = tri_pts(t);
                        p.push(p[0]);
                        ch.draw_series(LineSeries::new(p, BLACK.stroke_width(1)))?;
                    }
                }
                3 => {
                    ch.draw_series(LineSeries::new(closed(poly), BLACK.stroke_width(2)))?;
                    for t in &sk.skeleton.triangles {
                        let col = match t.circle {
                            pdesculpt::conv::skeleton::CircleKind::Circumcircle => {
                                RGBColor(230, 80, 80)
                            }
                            pdesculpt::conv::skeleton::CircleKind::Incircle => {
                                RGBColor(90, 120, 230)
                            }
                            pdesculpt::conv::skeleton::CircleKind::EdgeTangent => {
                                RGBColor(40, 160, 60)
                            }
                        };
                        ch.draw_series(LineSeries::new(
                            circle_path(t.centre, t.radius),
                            col.mix(0.6),
                        ))?;
                    }
                }
                _ => {
                    ch.draw_series(LineSeries::new(closed(poly), BLACK.stroke_width(2)))?;
                    for (i, &c) in sk.skeleton.nodes.iter().enumerate() {
                        ch.draw_series(LineSeries::new(
                            circle_path(c, sk.skeleton.radii[i]),
                            RGBColor(180, 180, 180),
                        ))?;
                    }
                    for s in &sk.segments {
                        ch.draw_series(LineSeries::new(
                            vec![(s.p[0], s.p[1]), (s.q[0], s.q[1])],
                            RGBColor(200, 40, 40).stroke_width(3),
                        ))?;
                    }
                    ch.draw_series(
                        sk.skeleton
                            .nodes
                            .iter()
                            .map(|c| Circle::new((c[0], c[1]), 3, BLUE.filled())),
                    )?;
                }
            }
        }
        root.present()?;
    }
    plot.save(path)?;
    Ok(())
}

fn count_kinds(sk: &sketch::Sketch) -> serde_json::Value {
    let c = |k: TriangleKind| sk.skeleton.triangles.iter().filter(|t| t.kind == k).count();
    json!({
        "terminal": c(TriangleKind::Terminal),
        "sleeve": c(TriangleKind::Sleeve),
        "junction": c(TriangleKind::Junction),
    })
}

fn fig2(ctx: &Ctx) -> anyhow::Result<()> {
    let raw = shapes::figure(600);
    let (b, mesh) = single("figure", raw.clone(), Solver::HildrethDEsopo)?;
    let sk = &b.components[0].sketch;
    fig2_panels(&ctx.path("003-fig2_steps.png"), &raw, sk)?;
    views(&mesh, Some(&sk.polygon), 420).save_png(&ctx.path("003-fig2_surface.png"))?;
    let e = front_error(&b, &mesh, 0);
    ctx.write_json(
        "003-fig2.json",
        &json!({
            "stroke_samples": raw.len(),
            "filtered_points": sk.polygon.len(),
            "triangles": count_kinds(sk),
            "skeleton_nodes_kept": sk.skeleton.nodes.len(),
            "segments": sk.segments.len(),
            "s": sk.s,
            "fit": sk.fit,
            "mesh_triangles": mesh.triangles.len(),
            "topology": pdesculpt::mesh::topology::report(&mesh),
            "silhouette_error": e,
        }),
    )?;
    eprintln!(
        "  silhouette error max {:.3e} mean {:.3e}",
        e.max_rel, e.mean_rel
    );
    Ok(())
}

fn fig4(ctx: &Ctx) -> anyhow::Result<()> {
    let mut rows = Vec::new();
    let mut imgs = Vec::new();
    for (name, raw) in [
        ("star", shapes::star(5, 0.6, 1.6, 400)),
        ("ellipse", shapes::ellipse(2.0, 1.0, 300)),
    ] {
        for solver in [Solver::None, Solver::HildrethDEsopo] {
            let (b, mesh) = single(name, raw.clone(), solver)?;
            let e = front_error(&b, &mesh, 0);
            let sk = &b.components[0].sketch;
            imgs.push(views(&mesh, Some(&sk.polygon), 300));
            eprintln!("  {name} {solver:?}: silhouette max {:.3e}", e.max_rel);
            rows.push(
                json!({"stroke": name, "global_interpolation": solver != Solver::None,
                "solver": solver, "fit": sk.fit, "silhouette_error": e,
                "volume": mesh.signed_volume()}),
            );
        }
    }
    let top = Image::hstack(&imgs[0..2], [255; 4]);
    let bottom = Image::hstack(&imgs[2..4], [255; 4]);
    top.save_png(&ctx.path("003-fig4_star.png"))?;
    bottom.save_png(&ctx.path("003-fig4_ellipse.png"))?;
    ctx.write_json("003-fig4.json", &json!({"note": "left: lambda = 1 (no global interpolation), right: Hildreth-d'Esopo; red: the filtered stroke", "rows": rows}))?;
    Ok(())
}

fn fig5(ctx: &Ctx) -> anyhow::Result<()> {
    let mut rows = Vec::new();
    let mut imgs = Vec::new();
    let strokes = [
        ("folding", shapes::folding(1.5, 0.4, 4.0, 400)),
        ("figure", shapes::figure(500)),
    ];
    for (name, raw) in &strokes {
        for solver in [
            Solver::ProjectedLm,
            Solver::HildrethDEsopo,
            Solver::LawsonHanson,
        ] {
            // time the fit alone several times (the build includes it once)
            let (b, mesh) = single(name, raw.clone(), solver)?;
            let sk = &b.components[0].sketch;
            let reps = 5;
            let mut best = f64::INFINITY;
            for _ in 0..reps {
                let pts: Vec<[f64; 3]> = sk.polygon.iter().map(|p| [p[0], p[1], 0.0]).collect();
                let mut segs = sk.segments.clone();
                for s in &mut segs {
                    s.lambda = 1.0;
                }
                let r = pdesculpt::conv::fit::global_fit(&segs, &pts, sk.threshold, sk.s, solver)?;
                best = best.min(r.seconds);
            }
            let e = front_error(&b, &mesh, 0);
            if *name == "folding" {
                imgs.push(views(&mesh, Some(&sk.polygon), 300));
            }
            eprintln!(
                "  {name} {solver:?}: rms {:.3e} max {:.3e} it {} time {:.2e} s silhouette {:.3e}",
                sk.fit.rms_rel_error, sk.fit.max_rel_error, sk.fit.iterations, best, e.max_rel
            );
            rows.push(
                json!({"stroke": name, "solver": solver, "segments": sk.segments.len(),
                "points": sk.polygon.len(), "fit_rms_rel_error": sk.fit.rms_rel_error,
                "fit_max_rel_error": sk.fit.max_rel_error, "iterations": sk.fit.iterations,
                "best_fit_seconds": best, "silhouette_error": e}),
            );
        }
    }
    Image::hstack(&imgs, [255; 4]).save_png(&ctx.path("003-fig5.png"))?;
    ctx.write_json("003-fig5.json", &json!({"note": "folding stroke: projected LM | Hildreth-d'Esopo | Lawson-Hanson (front + perspective each); times: best of 5 fits (release build)", "rows": rows}))?;
    Ok(())
}

fn fig7(ctx: &Ctx) -> anyhow::Result<()> {
    let body = shapes::ellipse(1.2, 1.6, 300);
    let arm: Vec<[f64; 2]> = shapes::ellipse(1.1, 0.35, 200)
        .into_iter()
        .map(|p| [p[0] + 1.6, p[1] + 0.6])
        .collect();
    let mk = |merged: bool| Model {
        name: "merge".into(),
        options: Default::default(),
        components: vec![
            Component {
                name: "body".into(),
                stroke: body.clone(),
                ..Default::default()
            },
            Component {
                name: "arm".into(),
                stroke: arm.clone(),
                depth: Some(0.35),
                view: PlaneView::Front,
                ..Default::default()
            },
        ],
        operations: if merged {
            vec![pdesculpt::conv::model::Operation::Merge {
                a: "body".into(),
                b: "arm".into(),
            }]
        } else {
            Vec::new()
        },
    };
    let mut rows = Vec::new();
    let mut imgs = Vec::new();
    for merged in [false, true] {
        let m = mk(merged);
        let b = m.build()?;
        let mesh = b.polygonize(RES, m.options.threshold, Polygonizer::MarchingTetrahedra)?;
        let topo = pdesculpt::mesh::topology::report(&mesh);
        // silhouette error of each component against its own group (unmerged) / the union
        let mut errs = Vec::new();
        for (i, c) in b.components.iter().enumerate() {
            let sub = if merged {
                mesh.clone()
            } else {
                mesh.group_submesh(&c.name).map(|x| x.0).unwrap_or_default()
            };
            errs.push(json!({"component": c.name, "silhouette_error": front_error(&b, &sub, i)}));
        }
        // the whole outline against the boundary of the union of both strokes
        let polys: Vec<&[[f64; 2]]> = b
            .components
            .iter()
            .map(|c| c.sketch.polygon.as_slice())
            .collect();
        let union = pdesculpt::conv::silhouette::silhouette_error_union(
            &mesh,
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            &polys,
        );
        imgs.push(views(&mesh, None, 320));
        eprintln!(
            "  merged {merged}: {} groups, euler {}, union silhouette max {:.3e} mean {:.3e}",
            b.groups.len(),
            topo.euler,
            union.max_rel,
            union.mean_rel
        );
        rows.push(
            json!({"merged": merged, "groups": b.groups.len(), "topology": topo,
            "triangles": mesh.triangles.len(), "per_component": errs,
            "silhouette_error": union}),
        );
    }
    Image::hstack(&imgs, [255; 4]).save_png(&ctx.path("003-fig7.png"))?;
    ctx.write_json("003-fig7.json", &json!({"note": "left: body and arm (arm plane at depth 0.35) as separate surfaces; right: merged (fields summed). For the merged model the per-component silhouette error measures the union outline against each stroke, so it includes the other component's part by construction; silhouette_error: the whole outline against the boundary of the union of both strokes (both lie in front planes), relative to the union's size.", "rows": rows}))?;
    Ok(())
}

fn fig8(ctx: &Ctx) -> anyhow::Result<()> {
    let strokes = [
        ("folding", shapes::folding(1.5, 0.4, 4.0, 400)),
        ("folding_tight", shapes::folding(1.0, 0.35, 4.6, 400)),
        ("star", shapes::star(5, 0.6, 1.6, 400)),
        ("figure", shapes::figure(500)),
        ("ellipse", shapes::ellipse(2.0, 1.0, 300)),
    ];
    let mut rows = Vec::new();
    let mut imgs = Vec::new();
    for (name, raw) in &strokes {
        let (b, mesh) = single(name, raw.clone(), Solver::HildrethDEsopo)?;
        let sk = &b.components[0].sketch;
        let e = front_error(&b, &mesh, 0);
        let persp = RenderOptions::default()
            .with_width(300)
            .with_height(300)
            .with_view(View::Perspective {
                yaw: 30.0,
                pitch: 25.0,
            });
        let front = RenderOptions::default()
            .with_width(300)
            .with_height(300)
            .with_overlays(vec![overlay(&sk.polygon)]);
        imgs.push(Image::hstack(
            &[render(&mesh, &front), render(&mesh, &persp)],
            [255; 4],
        ));
        eprintln!(
            "  {name}: silhouette max {:.3e} mean {:.3e}",
            e.max_rel, e.mean_rel
        );
        rows.push(
            json!({"stroke": name, "segments": sk.segments.len(), "fit": sk.fit,
            "topology": pdesculpt::mesh::topology::report(&mesh), "silhouette_error": e}),
        );
    }
    for (k, img) in imgs.iter().enumerate() {
        img.save_png(&ctx.path(&format!("003-fig8_{}.png", strokes[k].0)))?;
    }
    ctx.write_json("003-fig8.json", &json!({"note": "front (stroke in red) and perspective view per stroke; Hildreth-d'Esopo fit, marching tetrahedra at 64 cells", "rows": rows}))?;
    Ok(())
}

/// Mean and max of `xs`.
fn mean_max(xs: &[f64]) -> (f64, f64) {
    let n = xs.len().max(1) as f64;
    (
        xs.iter().sum::<f64>() / n,
        xs.iter().copied().fold(0.0, f64::max),
    )
}

fn fig_polygonizers(ctx: &Ctx) -> anyhow::Result<()> {
    use pdesculpt::mesh::isosurface::{
        marching_tetrahedra, smallest_angles_deg, surface_nets, triangle_quality, ScalarGrid,
    };
    let star = Model {
        name: "star".into(),
        options: Default::default(),
        components: vec![Component {
            name: "star".into(),
            stroke: shapes::star(5, 0.6, 1.6, 400),
            ..Default::default()
        }],
        operations: Vec::new(),
    }
    .build()?;
    let teddy_model = Model::from_json(include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../data/conv/teddy.json"
    )))?;
    let teddy = teddy_model.build()?;
    anyhow::ensure!(teddy.groups.len() == 1, "teddy: expected one merged group");
    // the sphere: F = 2 / (1 + |x|^2), F = 1 on the unit sphere
    let sphere_f = |r: [f64; 3]| 2.0 / (1.0 + pdesculpt::mesh::dot(r, r));
    let sphere_g = |r: [f64; 3]| {
        let q = 1.0 + pdesculpt::mesh::dot(r, r);
        pdesculpt::mesh::scale(r, -4.0 / (q * q))
    };
    let mut rows = Vec::new();
    let mut table = String::from(
        "| field | cells | method | triangles | min angle mean / min (deg) | < 10 deg | aspect mean / max | watertight manifold oriented | implicit dist mean / max (cells) | exact dist max (cells) | time (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut hist: Vec<(String, Vec<f64>)> = Vec::new();
    let mut imgs = Vec::new();
    for field in ["sphere", "star", "teddy"] {
        for res in [32usize, 64, 96] {
            let grid: ScalarGrid = match field {
                "sphere" => ScalarGrid::sample([-1.4; 3], [1.4; 3], [res + 1; 3], sphere_f)?,
                "star" => star
                    .sample_group(0, res, 1.0)?
                    .ok_or_else(|| anyhow::anyhow!("star: no surface"))?,
                _ => teddy
                    .sample_group(0, res, teddy_model.options.threshold)?
                    .ok_or_else(|| anyhow::anyhow!("teddy: no surface"))?,
            };
            let cell = grid.spacing[0].max(grid.spacing[1]).max(grid.spacing[2]);
            let nodes = grid.values.len();
            for method in [Polygonizer::MarchingTetrahedra, Polygonizer::SurfaceNets] {
                let run = || match method {
                    Polygonizer::MarchingTetrahedra => marching_tetrahedra(&grid, 1.0),
                    Polygonizer::SurfaceNets => surface_nets(&grid, 1.0),
                };
                let mut best = f64::INFINITY;
                let mut mesh = Mesh::default();
                for _ in 0..3 {
                    let t = std::time::Instant::now();
                    mesh = run();
                    best = best.min(t.elapsed().as_secs_f64());
                }
                let q = triangle_quality(&mesh);
                let topo = pdesculpt::mesh::topology::report(&mesh);
                // distance to the implicit surface F = T at the vertices:
                // Newton steps along the gradient onto the surface, the
                // distance to the foot point (first-order estimate
                // |F - T| / |grad F| where Newton does not converge)
                let fg = |p: [f64; 3]| match field {
                    "sphere" => (sphere_f(p), sphere_g(p)),
                    "star" => (star.group_field(0, p), star.group_gradient(0, p)),
                    _ => (teddy.group_field(0, p), teddy.group_gradient(0, p)),
                };
                let mut unconverged = 0usize;
                let implicit: Vec<f64> = mesh
                    .positions
                    .iter()
                    .map(|&p0| {
                        let (f0, g0) = fg(p0);
                        let first = (f0 - 1.0).abs() / pdesculpt::mesh::norm(g0).max(1e-300);
                        let mut p = p0;
                        for _ in 0..30 {
                            let (f, g) = fg(p);
                            if (f - 1.0).abs() < 1e-12 {
                                return pdesculpt::mesh::dist(p, p0);
                            }
                            let g2 = pdesculpt::mesh::dot(g, g);
                            if g2.is_nan() || g2 <= 0.0 {
                                break;
                            }
                            let step = pdesculpt::mesh::scale(g, -(f - 1.0) / g2);
                            // never step more than a cell at a time
                            let len = pdesculpt::mesh::norm(step);
                            let step = pdesculpt::mesh::scale(step, (cell / len).min(1.0));
                            p = pdesculpt::mesh::add(p, step);
                        }
                        unconverged += 1;
                        first
                    })
                    .collect();
                let (imean, imax) = mean_max(&implicit);
                let exact = (field == "sphere").then(|| {
                    let d: Vec<f64> = mesh
                        .positions
                        .iter()
                        .map(|&p| (pdesculpt::mesh::norm(p) - 1.0).abs())
                        .collect();
                    mean_max(&d)
                });
                let tag = match method {
                    Polygonizer::MarchingTetrahedra => "MT",
                    Polygonizer::SurfaceNets => "SN",
                };
                eprintln!(
                    "  {field} {res} {tag}: {} tris, min angle mean {:.1} min {:.2}, <10deg {:.3}, aspect {:.2}/{:.1}, w/m/o {}/{}/{}, dist max {:.3} cells, {:.2} ms",
                    q.triangles, q.mean_min_angle_deg, q.min_angle_deg, q.frac_below_10deg,
                    q.mean_aspect, q.max_aspect, topo.watertight, topo.manifold, topo.oriented,
                    imax / cell, best * 1e3
                );
                table.push_str(&format!(
                    "| {field} | {res} | {tag} | {} | {:.1} / {:.2} | {:.3} | {:.2} / {:.1} | {} {} {} | {:.3} / {:.3} | {} | {:.2} |\n",
                    q.triangles, q.mean_min_angle_deg, q.min_angle_deg, q.frac_below_10deg,
                    q.mean_aspect, q.max_aspect, topo.watertight, topo.manifold, topo.oriented,
                    imean / cell, imax / cell,
                    exact.map(|e| format!("{:.3}", e.1 / cell)).unwrap_or_else(|| "-".into()),
                    best * 1e3
                ));
                if res == 64 && field == "teddy" {
                    hist.push((tag.to_string(), smallest_angles_deg(&mesh)));
                }
                if res == 32 && field == "teddy" {
                    imgs.push(views(&mesh, None, 300));
                }
                rows.push(json!({
                    "field": field, "resolution": res, "grid_nodes": nodes, "cell": cell,
                    "method": method, "quality": q, "topology": topo,
                    "implicit_distance_mean": imean, "implicit_distance_max": imax,
                    "implicit_distance_max_cells": imax / cell,
                    "implicit_distance_unconverged_vertices": unconverged,
                    "exact_distance_mean": exact.map(|e| e.0),
                    "exact_distance_max": exact.map(|e| e.1),
                    "best_seconds_of_3": best,
                }));
            }
        }
    }
    // min-angle histograms (teddy, 64 cells)
    {
        let path = ctx.path("003-polygonizers_angles.png");
        let mut plot = PlotPng::new((640, 400));
        {
            let root = plot.area();
            root.fill(&WHITE)?;
            let bins = 30usize;
            let counts: Vec<Vec<f64>> = hist
                .iter()
                .map(|(_, a)| {
                    let mut c = vec![0.0; bins];
                    for &x in a {
                        c[((x / 60.0 * bins as f64) as usize).min(bins - 1)] +=
                            1.0 / a.len() as f64;
                    }
                    c
                })
                .collect();
            let ymax = counts.iter().flatten().copied().fold(0.0, f64::max) * 1.1;
            let mut ch = ChartBuilder::on(&root)
                .caption(
                    "smallest angle per triangle, teddy, 64 cells",
                    ("sans-serif", 18),
                )
                .margin(10)
                .x_label_area_size(35)
                .y_label_area_size(50)
                .build_cartesian_2d(0.0..60.0, 0.0..ymax)?;
            ch.configure_mesh()
                .x_desc("degrees")
                .y_desc("fraction of triangles")
                .draw()?;
            for (k, ((name, _), c)) in hist.iter().zip(&counts).enumerate() {
                let col = if k == 0 {
                    RGBColor(200, 60, 60)
                } else {
                    RGBColor(50, 90, 200)
                };
                let pts: Vec<(f64, f64)> = c
                    .iter()
                    .enumerate()
                    .map(|(i, &v)| ((i as f64 + 0.5) * 60.0 / bins as f64, v))
                    .collect();
                ch.draw_series(LineSeries::new(pts, col.stroke_width(2)))?
                    .label(name.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col));
            }
            ch.configure_series_labels()
                .border_style(BLACK)
                .background_style(WHITE)
                .draw()?;
            root.present()?;
        }
        plot.save(&path)?;
    }
    Image::hstack(&imgs, [255; 4]).save_png(&ctx.path("003-polygonizers_teddy32.png"))?;
    std::fs::write(ctx.path("003-polygonizers.md"), &table)?;
    ctx.write_json(
        "003-polygonizers.json",
        &json!({"note": "same sampled grid for both polygonizers per (field, resolution); sphere: F = 2/(1+|x|^2), T = 1 (exact distance | |x| - 1 |); star, teddy: convolution fields (data/conv/teddy.json), implicit distance from each vertex to the foot point of Newton steps along grad F onto F = T (first-order |F - T| / |grad F| for the few vertices where Newton does not converge, counted); cells along the longest side; times: best of 3 polygonizations of the sampled grid (release build, sampling excluded); teddy image: MT (front, perspective) then SN (front, perspective)",
        "rows": rows}),
    )?;
    Ok(())
}
