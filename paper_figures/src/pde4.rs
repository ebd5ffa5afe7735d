//! Figures of the pde4 family (paper 000 sec 3.1, sec 5.1).
//!
//! * `000-fig1`: 2-sided deformations of a limb-like part (concentrated, line,
//!   area, combined forces), exact solution.
//! * `000-fig2`: 4-sided deformations of the MakeHuman body in regions drawn
//!   as closed curves: small (nose), narrow band (arm), irregular (chest).
//! * `000-fig8-patch` (the character version is `000-fig8` in `edit`): a torso from boundary curves and tangents with a sculpting
//!   force: shape parameter a = 1.0 and 0.3 (read as the smoothing parameter
//!   of $a_1 = 1$, $a_2 = 2a^2$, $a_3 = a^4$: scaling all three alike only
//!   rescales the force response), changed boundary curve, changed tangents.
//! * `000-fig14`: one curve and one drag make a chest deformation.
//! * `000-pde4-twosided`: one Fourier mode of a 2-sided patch, printed eqs 7-9
//!   vs residual-minimising coefficients vs the exact solution.
//! * `000-pde4-plate`: printed eqs 14-15 vs the Galerkin solution vs classical
//!   clamped-plate values, with the Galerkin convergence.

use crate::common::{Ctx, Figure, PlotPng};
use anyhow::Context;
use pdesculpt::curve::Fourier3;
use pdesculpt::mesh::Mesh;
use pdesculpt::pde4::apply::{deform_region, Deformed, Direction};
use pdesculpt::pde4::check::{self as pc, plate_centre};
use pdesculpt::pde4::four_sided::{self, FourSided};
use pdesculpt::pde4::two_sided::{self, Boundary, TwoSided};
use pdesculpt::pde4::{samples, Force, ForceKind, ShapeParams};
use pdesculpt::render::{render, render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::surface::{tessellate, Revolution, Tessellation};
use plotters::prelude::*;
use std::f64::consts::PI;

/// The figures of the pde4 family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "000-fig1",
            paper: "000",
            title: "2-sided deformations by concentrated, line and area forces",
            run: fig1,
        },
        Figure {
            id: "000-fig2",
            paper: "000",
            title: "4-sided deformations in small, narrow and irregular regions",
            run: fig2,
        },
        Figure {
            id: "000-fig8-patch",
            paper: "000",
            title: "a synthetic torso patch: shape parameters, boundary curves and tangents",
            run: fig8,
        },
        Figure {
            id: "000-fig14",
            paper: "000",
            title: "one curve and one drag: chest deformation",
            run: fig14,
        },
        Figure {
            id: "000-pde4-plate",
            paper: "000",
            title: "printed vs Galerkin vs clamped-plate theory",
            run: fig_plate,
        },
        Figure {
            id: "000-pde4-twosided",
            paper: "000",
            title: "2-sided mode: printed eqs 7-9 vs least squares vs exact",
            run: fig_two_sided,
        },
    ]
}

const WHITE: [u8; 4] = [255, 255, 255, 255];

fn view() -> RenderOptions {
    RenderOptions::default()
        .with_width(320)
        .with_height(400)
        .with_view(View::Perspective {
            yaw: 35.0,
            pitch: 15.0,
        })
}

fn fig1(ctx: &Ctx) -> anyhow::Result<()> {
    let part = Revolution { r0: 1.0, r1: 0.15 };
    // a force of magnitude `mag` pointing radially out at v
    let radial = |mag: f64, v: f64| {
        let (c, s) = ((2.0 * PI * v).cos(), (2.0 * PI * v).sin());
        [mag * c, 0.0, mag * s]
    };
    let conc = Force {
        kind: ForceKind::Concentrated { u0: 0.5, v0: 0.2 },
        p: radial(30.0, 0.2),
    };
    let line = Force {
        kind: ForceKind::Line {
            u0: 0.15,
            u1: 0.85,
            v0: 0.6,
        },
        p: radial(90.0, 0.6),
    };
    let area = Force {
        kind: ForceKind::Area {
            u0: 0.25,
            u1: 0.75,
            v0: 0.8,
            v1: 0.95,
        },
        p: radial(1500.0, 0.875),
    };
    let t = Tessellation { nu: 80, nv: 96 };
    let mut panels = vec![render(&tessellate(&part, t), &view())];
    let mut data = Vec::new();
    for (name, fs) in [
        ("concentrated", vec![conc]),
        ("line", vec![line]),
        ("area", vec![area]),
        ("combined", vec![conc, line, area]),
    ] {
        let d = TwoSided::new(
            [ShapeParams::uniform(1.0); 3],
            &fs,
            24,
            16,
            two_sided::Method::Exact,
            None,
        )?;
        let res = pc::two_sided_residual(&d, 10);
        let bnd = pc::two_sided_boundary(&d, None, 32);
        let g = Deformed::new(part, d, (0.1, 0.9), (0.0, 1.0), 1.0)?;
        let m = tessellate(&g, t);
        let dmax = m
            .positions
            .iter()
            .zip(&tessellate(&part, t).positions)
            .map(|(a, b)| pdesculpt::mesh::dist(*a, *b))
            .fold(0.0, f64::max);
        data.push(serde_json::json!({"force": name, "residual_rel": res, "boundary_max": bnd, "max_displacement": dmax}));
        panels.push(render(&m, &view()));
    }
    Image::hstack(&panels, WHITE).save_png(&ctx.path("000-fig1.png"))?;
    ctx.write_json(
        "000-fig1.json",
        &serde_json::json!({"terms": [24, 16], "u_window": [0.1, 0.9], "panels": data}),
    )?;
    Ok(())
}

fn region_panel(
    body: &Mesh,
    curve: &[[f64; 3]],
    force: Force,
    drag: f64,
    depth: f64,
    dir: Direction,
) -> anyhow::Result<(Image, serde_json::Value)> {
    let d = FourSided::new(
        [ShapeParams::uniform(1.0); 3],
        &[force],
        10,
        10,
        four_sided::Method::Galerkin,
    )?;
    let r = deform_region(body, curve, &d, dir, drag, depth)?;
    let o = chest_view(curve);
    let moved = r.region.len();
    Ok((
        render_with_camera(&r.mesh, &o, &torso_camera(&o)),
        serde_json::json!({"moved_vertices": moved, "magnitude": r.magnitude, "drag": drag}),
    ))
}

/// Camera framing the upper body.
fn torso_camera(o: &RenderOptions) -> Camera {
    Camera::fit_box(
        [-1.5, 1.5, -1.0],
        [3.5, 8.0, 2.0],
        o.view,
        o.width,
        o.height,
        0.02,
    )
}

/// Ellipse in the plane `z = c[2]` with its long axis along `dir` (unit, in x-y).
fn band(c: [f64; 3], dir: [f64; 2], long: f64, short: f64, k: usize) -> Vec<[f64; 3]> {
    (0..k)
        .map(|i| {
            let a = 2.0 * PI * i as f64 / k as f64;
            let (p, q) = (long * a.cos(), short * a.sin());
            [
                c[0] + p * dir[0] - q * dir[1],
                c[1] + p * dir[1] + q * dir[0],
                c[2],
            ]
        })
        .collect()
}

fn body() -> anyhow::Result<Mesh> {
    Ok(pdesculpt::makehuman::base_body()
        .context("MakeHuman base body")?
        .mesh)
}

/// The chest panels' camera: three-quarter view with `curve` drawn in red.
fn chest_view(curve: &[[f64; 3]]) -> RenderOptions {
    RenderOptions::default()
        .with_width(360)
        .with_height(480)
        .with_view(View::Perspective {
            yaw: 25.0,
            pitch: 5.0,
        })
        .with_overlays(vec![Overlay {
            points: curve.to_vec(),
            closed: true,
            colour: [220, 30, 30, 255],
            depth_test: false,
        }])
}

/// The demo's chest outline (right side), drawn irregular.
fn chest_curve() -> Vec<[f64; 3]> {
    samples::chest_curve(1.0, 0.12)
}

fn fig2(ctx: &Ctx) -> anyhow::Result<()> {
    let b = body()?;
    let nose = samples::drawn_ellipse([0.0, 7.0, 1.7], 0.18, 0.3, 24, 0.0);
    let arm = band([2.65, 4.05, 0.6], [0.62, -0.78], 0.75, 0.14, 40);
    let (a, ja) = region_panel(
        &b,
        &nose,
        Force {
            kind: ForceKind::Concentrated { u0: 0.5, v0: 0.4 },
            p: [1.0; 3],
        },
        0.15,
        0.6,
        Direction::Vector([0.0, 0.0, 1.0]),
    )?;
    let (c, jc) = region_panel(
        &b,
        &arm,
        Force {
            kind: ForceKind::Line {
                u0: 0.1,
                u1: 0.9,
                v0: 0.5,
            },
            p: [1.0; 3],
        },
        0.12,
        0.8,
        Direction::Normal,
    )?;
    let (d, jd) = region_panel(
        &b,
        &chest_curve(),
        Force {
            kind: ForceKind::Area {
                u0: 0.0,
                u1: 1.0,
                v0: 0.0,
                v1: 1.0,
            },
            p: [1.0; 3],
        },
        0.35,
        0.8,
        Direction::Vector([0.0, 0.0, 1.0]),
    )?;
    Image::hstack(&[a, c, d], WHITE).save_png(&ctx.path("000-fig2.png"))?;
    ctx.write_json(
        "000-fig2.json",
        &serde_json::json!({"nose": ja, "arm_band": jc, "chest": jd}),
    )?;
    Ok(())
}

fn fig14(ctx: &Ctx) -> anyhow::Result<()> {
    let b = body()?;
    let curve = chest_curve();
    let o = chest_view(&curve);
    let before = render_with_camera(&b, &o, &torso_camera(&o));
    let (after, j) = region_panel(
        &b,
        &curve,
        Force {
            kind: ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
            p: [1.0; 3],
        },
        0.4,
        0.8,
        Direction::Normal,
    )?;
    Image::hstack(&[before, after], WHITE).save_png(&ctx.path("000-fig14.png"))?;
    ctx.write_json(
        "000-fig14.json",
        &serde_json::json!({"curve_points": curve.len(), "manual_operations": 2, "result": j}),
    )?;
    Ok(())
}

fn ring(r: f64, y: f64, squash: f64) -> Fourier3 {
    Fourier3 {
        c0: [0.0, y, 0.0],
        cos: vec![[r, 0.0, 0.0]],
        sin: vec![[0.0, 0.0, r * squash]],
    }
}

fn fig8(ctx: &Ctx) -> anyhow::Result<()> {
    let base = Boundary {
        curve0: ring(1.0, 0.0, 0.8),
        curve1: ring(1.0, 3.0, 0.8),
        tangent0: ring(2.5, 3.0, 0.8),
        tangent1: ring(-2.5, 3.0, 0.8),
    };
    let force = Force {
        kind: ForceKind::Area {
            u0: 0.2,
            u1: 0.8,
            v0: 0.15,
            v1: 0.35,
        },
        p: [0.0, 0.0, 300.0],
    };
    let mut curves = base.clone();
    curves.curve1 = ring(0.6, 3.0, 1.0);
    let mut tangents = base.clone();
    tangents.tangent0 = ring(6.0, 3.0, 0.8);
    tangents.tangent1 = ring(-6.0, 3.0, 0.8);
    let cases: Vec<(&str, f64, &Boundary, Vec<Force>)> = vec![
        ("a: boundary curves only", 0.3, &base, vec![]),
        ("b: shape parameters 1.0", 1.0, &base, vec![force]),
        ("c: shape parameters 0.3", 0.3, &base, vec![force]),
        ("d: changed boundary curve", 0.3, &curves, vec![force]),
        ("e: changed tangents", 0.3, &tangents, vec![force]),
    ];
    let mut panels = Vec::new();
    let mut data = Vec::new();
    for (name, a, b, fs) in cases {
        let s = TwoSided::new(
            [ShapeParams::plate_ratio(a); 3],
            &fs,
            24,
            8,
            two_sided::Method::Exact,
            Some(b),
        )?;
        let bnd = pc::two_sided_boundary(&s, Some(b), 32);
        let res = pc::two_sided_residual(&s, 10);
        let top = pdesculpt::surface::Surface::point(&s, 0.5, 0.25);
        data.push(serde_json::json!({"panel": name, "shape_parameter": a, "boundary_err": bnd, "residual_rel": res, "point_u0.5_v0.25": top}));
        panels.push(render(
            &tessellate(&s, Tessellation { nu: 64, nv: 64 }),
            &RenderOptions::default()
                .with_width(300)
                .with_height(360)
                .with_view(View::Perspective {
                    yaw: 20.0,
                    pitch: 20.0,
                }),
        ));
    }
    Image::hstack(&panels, WHITE).save_png(&ctx.path("000-fig8-patch.png"))?;
    ctx.write_json(
        "000-fig8-patch.json",
        &serde_json::json!({"terms": [24, 8], "shape": "a1 = 1, a2 = 2 a^2, a3 = a^4", "panels": data}),
    )?;
    Ok(())
}

fn fig_plate(ctx: &Ctx) -> anyhow::Result<()> {
    let gal = four_sided::Method::Galerkin;
    let cases = [
        (
            "square, uniform",
            ShapeParams::PLATE,
            ForceKind::Uniform,
            pc::PLATE_SQUARE_UNIFORM_PRECISE,
        ),
        (
            "b/a = 1.5, uniform",
            ShapeParams::plate_ratio(1.0 / 1.5),
            ForceKind::Uniform,
            pc::PLATE_RECT_15_UNIFORM,
        ),
        (
            "b/a = 2, uniform",
            ShapeParams::plate_ratio(0.5),
            ForceKind::Uniform,
            pc::PLATE_RECT_2_UNIFORM,
        ),
        (
            "square, central point",
            ShapeParams::PLATE,
            ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
            pc::PLATE_SQUARE_POINT,
        ),
    ];
    // sinusoidal load sin(pi x/a) sin(pi y/b): no trusted published clamped
    // value, reference = the independent FD solver (Richardson n = FD_GRID, 2 FD_GRID)
    let sine = |u: f64, v: f64| (PI * u).sin() * (PI * v).sin();
    let fd = |p: ShapeParams| -> anyhow::Result<f64> {
        Ok(pdesculpt::pde4::fd::fd_centre_extrapolated(p, pc::FD_GRID, sine)?.0)
    };
    let cases = cases.into_iter().chain([
        (
            "square, sinusoidal (FD ref.)",
            ShapeParams::PLATE,
            samples::SINE_LOAD,
            fd(ShapeParams::PLATE)?,
        ),
        (
            "b/a = 1.5, sinusoidal (FD ref.)",
            ShapeParams::plate_ratio(1.0 / 1.5),
            samples::SINE_LOAD,
            fd(ShapeParams::plate_ratio(1.0 / 1.5))?,
        ),
        (
            "b/a = 2, sinusoidal (FD ref.)",
            ShapeParams::plate_ratio(0.5),
            samples::SINE_LOAD,
            fd(ShapeParams::plate_ratio(0.5))?,
        ),
    ]);
    let terms = [2usize, 4, 6, 8, 12, 16, 20];
    let mut rows = Vec::new();
    let mut series = Vec::new();
    for (name, p, k, reference) in cases {
        let vals: Vec<f64> = terms.iter().map(|&t| plate_centre(p, k, t, gal)).collect();
        let printed: Vec<f64> = terms
            .iter()
            .map(|&t| plate_centre(p, k, t, four_sided::Method::Paper))
            .collect();
        rows.push(serde_json::json!({"case": name, "reference": reference, "terms": terms, "galerkin": vals, "printed_eq14_15": printed,
            "galerkin_rel_err": vals.iter().map(|v| pc::rel(*v, reference)).collect::<Vec<_>>(),
            "printed_rel_err": printed.iter().map(|v| pc::rel(*v, reference)).collect::<Vec<_>>()}));
        series.push((
            name,
            vals.iter()
                .map(|v| pc::rel(*v, reference))
                .collect::<Vec<_>>(),
            printed
                .iter()
                .map(|v| pc::rel(*v, reference))
                .collect::<Vec<_>>(),
        ));
    }
    ctx.write_json("000-pde4-plate.json", &serde_json::json!({"cases": rows,
        "references": "Timoshenko & Woinowsky-Krieger tables 35 (uniform) and the central-load table; 0.00126532 Taylor & Govindjee 2004; sinusoidal loads: pdesculpt::pde4::fd (13-point FD, Richardson-extrapolated; it reproduces 0.00126532 to 1e-6)"}))?;
    let path = ctx.path("000-pde4-plate.png");
    {
        let mut plot = PlotPng::new((1100, 600));
        {
            let root = plot.area();
            root.fill(&WHITE_RGB)?;
            let mut chart = ChartBuilder::on(&root)
                .caption(
                    "clamped plate centre deflection: relative error vs plate theory",
                    ("sans-serif", 20),
                )
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(60)
                .build_cartesian_2d((1.5f64..150.0).log_scale(), (1e-5f64..10.0).log_scale())?;
            chart
                .configure_mesh()
                .x_desc("terms M = N")
                .y_desc("|w - w_ref| / w_ref")
                .label_style(("sans-serif", 14))
                .draw()?;
            let colours = [
                RED,
                BLUE,
                GREEN,
                MAGENTA,
                CYAN,
                RGBColor(230, 140, 0),
                RGBColor(110, 60, 20),
            ];
            for (i, (name, g, p)) in series.iter().enumerate() {
                let c = colours[i % colours.len()];
                let pts: Vec<(f64, f64)> = terms
                    .iter()
                    .zip(g)
                    .map(|(t, e)| (*t as f64, e.max(1e-5)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))?
                    .label(format!("Galerkin, {name}"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(2))
                    });
                chart.draw_series(pts.iter().map(|p| Circle::new(*p, 3, c.filled())))?;
                let pp: Vec<(f64, f64)> = terms
                    .iter()
                    .zip(p)
                    .map(|(t, e)| (*t as f64, e.clamp(1e-5, 10.0)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(pp, c.mix(0.5).stroke_width(1)))?
                    .label(format!("printed eqs 14-15, {name}"))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], c.mix(0.5)));
            }
            chart
                .draw_series(LineSeries::new(
                    vec![(1.5, 5e-3), (22.0, 5e-3)],
                    BLACK.stroke_width(1),
                ))?
                .label("0.5 %")
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], BLACK));
            chart
                .configure_series_labels()
                .background_style(WHITE_RGB.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 12))
                .position(SeriesLabelPosition::LowerRight)
                .draw()?;
            root.present()?;
        }
        plot.save(&path)?;
    }
    Ok(())
}

const WHITE_RGB: RGBColor = RGBColor(255, 255, 255);

fn fig_two_sided(ctx: &Ctx) -> anyhow::Result<()> {
    let force = [Force {
        kind: ForceKind::Line {
            u0: 0.2,
            u1: 0.7,
            v0: 0.0,
        },
        p: [1.0, 0.0, 0.0],
    }];
    let us: Vec<f64> = (0..=100).map(|i| i as f64 / 100.0).collect();
    let mut data = Vec::new();
    let mut curves = Vec::new();
    for (label, p) in [
        ("a = (1, 2, 1)", ShapeParams::PLATE),
        ("a = 0.3", ShapeParams::uniform(0.3)),
    ] {
        let mut row = serde_json::Map::new();
        for (name, meth) in [
            ("exact", two_sided::Method::Exact),
            ("printed", two_sided::Method::Paper),
            ("least-squares", two_sided::Method::LeastSquares),
        ] {
            let s = TwoSided::new([p; 3], &force, 16, 2, meth, None)?;
            // mode n = 1 (cos 2 pi v) of component x
            let w: Vec<f64> = us.iter().map(|&u| s.comps[0].mode(1).eval(u)).collect();
            row.insert(name.into(), serde_json::json!(w));
            curves.push((format!("{name}, {label}"), w));
        }
        let ex = row["exact"]
            .as_array()
            .map(|a| a.iter().filter_map(|x| x.as_f64()).collect::<Vec<_>>())
            .unwrap_or_default();
        let sc = ex.iter().fold(0.0f64, |a, b| a.max(b.abs()));
        for name in ["printed", "least-squares"] {
            let w: Vec<f64> = row[name]
                .as_array()
                .map(|a| a.iter().filter_map(|x| x.as_f64()).collect())
                .unwrap_or_default();
            row.insert(
                format!("{name}_max_rel_diff_vs_exact"),
                serde_json::json!(pdesculpt::check::max_abs_diff(&w, &ex) / sc),
            );
        }
        row.insert("params".into(), serde_json::json!(label));
        data.push(serde_json::Value::Object(row));
    }
    ctx.write_json("000-pde4-twosided.json", &serde_json::json!({"force": "line u in [0.2, 0.7], v0 = 0, p = 1", "mode": "cos 2 pi v", "terms": [16, 2], "u": us, "cases": data}))?;
    let path = ctx.path("000-pde4-twosided.png");
    let lo = curves
        .iter()
        .flat_map(|c| c.1.iter())
        .fold(0.0f64, |a, b| a.min(*b));
    let hi = curves
        .iter()
        .flat_map(|c| c.1.iter())
        .fold(0.0f64, |a, b| a.max(*b));
    let mut plot = PlotPng::new((900, 520));
    {
        let root = plot.area();
        root.fill(&WHITE_RGB)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "2-sided patch, Fourier mode cos 2πv of a line force",
                ("sans-serif", 20),
            )
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(0.0f64..1.0, (lo * 1.1)..(hi * 1.1))?;
        chart
            .configure_mesh()
            .x_desc("u")
            .y_desc("mode amplitude")
            .label_style(("sans-serif", 14))
            .draw()?;
        let colours = [BLACK, RED, BLUE, BLACK, RED, BLUE];
        for (i, (name, w)) in curves.iter().enumerate() {
            let c = colours[i];
            let width = if i < 3 { 2 } else { 1 };
            chart
                .draw_series(LineSeries::new(
                    us.iter().copied().zip(w.iter().copied()),
                    c.stroke_width(width),
                ))?
                .label(name.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(width))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE_RGB.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 12))
            .position(SeriesLabelPosition::LowerLeft)
            .draw()?;
        root.present()?;
    }
    plot.save(&path)?;
    Ok(())
}
