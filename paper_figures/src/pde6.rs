//! Figures of the pde6 family (paper 002): the body parts from cross
//! sections (Fig 5), the whole body front and side (Fig 6), and a vase from
//! an analytic profile (Fig 7a) with its convergence study.

use crate::common::{Ctx, Figure, PlotPng};
use pdesculpt::body::parts::{makehuman_parts, reconstruct, BodyOptions, Part};
use pdesculpt::curve::Fourier3;
use pdesculpt::mesh::Mesh;
use pdesculpt::pde6::{Chain, Section};
use pdesculpt::render::{render, Image, Overlay, RenderOptions, View};
use pdesculpt::surface::{tessellate, Tessellation};
use std::f64::consts::PI;

mod ripples;

/// The figures of the pde6 family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "002-fig5",
            paper: "002",
            title: "Cross sections (GEC fits, red) and the PDE6 body parts built from them",
            run: fig5,
        },
        Figure {
            id: "002-fig6",
            paper: "002",
            title: "Cross sections of the MakeHuman body and the C2 PDE6 reconstruction, front and side",
            run: fig6,
        },
        Figure {
            id: "002-conditioning",
            paper: "002",
            title: "Condition numbers of the 6x6 solves: paper basis (eqs 6-8) vs pdesculpt's stable basis",
            run: conditioning,
        },
        Figure {
            id: "002-fig7a",
            paper: "002",
            title: "A vase from an analytic profile: global C2 PDE6 chain and its convergence",
            run: fig7a,
        },
        Figure {
            id: "002-body-ripples",
            paper: "002",
            title: "Diagonal ripples of the body: legacy, anchored parameter only, a = -0.01 only, both",
            run: ripples::body_ripples,
        },
    ]
}

const RED: [u8; 4] = [220, 30, 30, 255];
const BLUE: [u8; 4] = [30, 60, 220, 255];

fn section_overlays(parts: &[Part], colour: [u8; 4], fitted: bool) -> Vec<Overlay> {
    parts
        .iter()
        .flat_map(|p| {
            p.sections
                .iter()
                .zip(&p.polylines)
                .map(move |(s, l)| Overlay {
                    points: if fitted {
                        s.curve.sample(96)
                    } else {
                        l.points.clone()
                    },
                    closed: true,
                    colour,
                    depth_test: false,
                })
        })
        .collect()
}

fn fig5(ctx: &Ctx) -> anyhow::Result<()> {
    let body = pdesculpt::makehuman::base_body()?;
    let specs = makehuman_parts();
    let (parts, _, report) = reconstruct(&body.mesh, &specs, &BodyOptions::default())?;
    let mut panels = Vec::new();
    for name in ["torso", "shoulders_neck", "arm_left", "leg_left", "head"] {
        let Some(p) = parts.iter().find(|p| p.spec.name == name) else {
            anyhow::bail!("part {name} missing");
        };
        let one = std::slice::from_ref(p);
        let view = View::Perspective {
            yaw: 30.0,
            pitch: 15.0,
        };
        let empty = RenderOptions::default()
            .with_view(view)
            .with_width(300)
            .with_height(420)
            .with_overlays(
                section_overlays(one, BLUE, false)
                    .into_iter()
                    .chain(section_overlays(one, RED, true))
                    .collect(),
            );
        panels.push(render(&p.mesh, &empty));
        panels.push(render(
            &p.mesh,
            &RenderOptions::default()
                .with_view(view)
                .with_width(300)
                .with_height(420),
        ));
    }
    let img = Image::hstack(&panels, [255, 255, 255, 255]);
    ctx.write_bytes("002-fig5.png", &img.encode_png())?;
    ctx.write_json("002-fig5.json", &report)?;
    Ok(())
}

fn fig6(ctx: &Ctx) -> anyhow::Result<()> {
    let body = pdesculpt::makehuman::base_body()?;
    let (parts, mesh, report) =
        reconstruct(&body.mesh, &makehuman_parts(), &BodyOptions::default())?;
    let mut panels = Vec::new();
    for view in [View::Front, View::Side] {
        let o = RenderOptions::default()
            .with_view(view)
            .with_width(360)
            .with_height(640)
            .with_overlays(section_overlays(&parts, RED, true));
        panels.push(render(&body.mesh, &o));
        panels.push(render(
            &mesh,
            &RenderOptions::default()
                .with_view(view)
                .with_width(360)
                .with_height(640),
        ));
    }
    let img = Image::hstack(&panels, [255, 255, 255, 255]);
    ctx.write_bytes("002-fig6.png", &img.encode_png())?;
    // glTF is metres; the MakeHuman body is decimetres (mesh::unit)
    pdesculpt::mesh::io::write_in_unit(
        &mesh,
        &ctx.path("002-fig6-body.glb"),
        pdesculpt::mesh::unit::MAKEHUMAN,
        pdesculpt::mesh::unit::GLB,
    )?;
    ctx.write_json("002-fig6.json", &report)?;
    Ok(())
}

/// Vase profile r(y), y in [0, 3], with a six-lobed fluting of amplitude 0.04 r.
fn radius(y: f64) -> f64 {
    0.55 + 0.35 * (2.1 * y - 0.6).sin() + 0.08 * y
}

fn vase_sections(m: usize) -> Vec<Section> {
    (0..m)
        .map(|i| {
            let y = 3.0 * i as f64 / (m - 1) as f64;
            let r = radius(y);
            let mut cos = vec![[0.0; 3]; 6];
            let mut sin = vec![[0.0; 3]; 6];
            cos[0] = [r, 0.0, 0.0];
            sin[0] = [0.0, 0.0, -r];
            cos[5] = [0.04 * r, 0.0, 0.0];
            sin[5] = [0.0, 0.0, 0.04 * r];
            Section {
                u: y,
                curve: Fourier3 {
                    c0: [0.0, y, 0.0],
                    cos,
                    sin,
                },
            }
        })
        .collect()
}

/// Max over y of |(x(y, 0) - x(y, pi)) / 2 (the first-harmonic radius) of the chain - r(y)|.
fn radius_error(c: &Chain) -> f64 {
    (0..=600)
        .map(|k| {
            let y = 3.0 * k as f64 / 600.0;
            let p = c.pieces[c.piece_at(y)].eval(y, 0.0);
            let q = c.pieces[c.piece_at(y)].eval(y, PI);
            ((p[0] - q[0]) / 2.0 - radius(y)).abs()
        })
        .fold(0.0, f64::max)
}

#[derive(serde::Serialize)]
struct Convergence {
    sections: usize,
    max_radius_error: f64,
    observed_order: Option<f64>,
}

fn fig7a(ctx: &Ctx) -> anyhow::Result<()> {
    // the vase study keeps the family's usual a = -0.5 (the body uses BODY_A)
    let a = -0.5;
    let mut conv: Vec<Convergence> = Vec::new();
    let mut conv_a0: Vec<Convergence> = Vec::new();
    for (av, conv) in [(a, &mut conv), (0.0, &mut conv_a0)] {
        for m in [7usize, 10, 13, 19, 25, 37, 49] {
            let c = Chain::c2_global(av, &vase_sections(m))?;
            let e = radius_error(&c);
            let order = conv.last().map(|p| {
                (p.max_radius_error / e).ln() / (((m - 1) as f64) / ((p.sections - 1) as f64)).ln()
            });
            conv.push(Convergence {
                sections: m,
                max_radius_error: e,
                observed_order: order,
            });
        }
    }
    let sec = vase_sections(13);
    let chain = Chain::c2_global(a, &sec)?;
    let mesh: Mesh = tessellate(&chain, Tessellation { nu: 96, nv: 96 });
    let overlays = sec
        .iter()
        .map(|s| Overlay {
            points: s.curve.sample(96),
            closed: true,
            colour: RED,
            depth_test: true,
        })
        .collect();
    let view = View::Perspective {
        yaw: 20.0,
        pitch: 20.0,
    };
    let a_img = render(
        &mesh,
        &RenderOptions::default()
            .with_view(view)
            .with_overlays(overlays),
    );
    let b_img = render(&mesh, &RenderOptions::default().with_view(view));
    ctx.write_bytes(
        "002-fig7a.png",
        &Image::hstack(&[a_img, b_img], [255, 255, 255, 255]).encode_png(),
    )?;
    let jumps = pdesculpt::surface::Joined::join_jumps(&chain, pdesculpt::pde6::JOIN_SAMPLES);
    ctx.write_json(
        "002-fig7a.json",
        &serde_json::json!({
            "profile": "r(y) = 0.55 + 0.35 sin(2.1 y - 0.6) + 0.08 y, y in [0, 3], six-lobed fluting 0.04 r",
            "a": a, "sections": 13, "pieces": chain.pieces.len(),
            "join_jumps_c0_c1_c2": jumps,
            "max_condition": chain.max_condition(),
            "convergence": conv,
            "convergence_a0": conv_a0,
            "note": "for a != 0 the harmonic function space does not contain constants (A = 1 does not solve A^(6) = a n^6 A), so refining the sections converges at order ~6 only down to a floor set by a; with a = 0 (quintics) the order stays ~6",
        }),
    )?;
    Ok(())
}

#[derive(serde::Serialize)]
struct CondRow {
    a: f64,
    n: usize,
    q: f64,
    stable_method1: f64,
    paper_method1: f64,
    stable_method2: f64,
    paper_method2: f64,
}

fn conditioning(ctx: &Ctx) -> anyhow::Result<()> {
    use pdesculpt::pde6::mode::{
        method1_conditions, method2_conditions, paper_basis_condition, ModeBasis, ModeSolver,
        NODES_METHOD1,
    };
    use plotters::prelude::*;
    let mut rows = Vec::new();
    for a in [-10.0, -1.0, -1e-4, 1e-4, 1.0, 10.0] {
        for n in 1..=20usize {
            let b = ModeBasis::new(a, n);
            let c1 = method1_conditions(NODES_METHOD1);
            let c2 = method2_conditions(1.0);
            let st = |c| ModeSolver::new(b, c).map_or(f64::INFINITY, |s| s.condition_number);
            rows.push(CondRow {
                a,
                n,
                q: b.q,
                stable_method1: st(c1),
                paper_method1: paper_basis_condition(&b, &c1),
                stable_method2: st(c2),
                paper_method2: paper_basis_condition(&b, &c2),
            });
        }
    }
    let path = ctx.path("002-conditioning.png");
    {
        let mut plot = PlotPng::new((900, 560));
        {
            let root = plot.area();
            root.fill(&WHITE)?;
            let mut chart = ChartBuilder::on(&root)
                .caption(
                    "method-2 6x6 condition number vs harmonic n",
                    ("sans-serif", 22),
                )
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(70)
                .build_cartesian_2d(1f64..20f64, (1f64..1e26f64).log_scale())?;
            chart
                .configure_mesh()
                .x_desc("harmonic n")
                .y_desc("1-norm condition number")
                .y_label_formatter(&|y| format!("{y:.0e}"))
                .x_label_formatter(&|x| format!("{x:.0}"))
                .label_style(("sans-serif", 14))
                .draw()?;
            let styles = [(-1.0, RED), (1.0, BLUE), (10.0, GREEN), (-1e-4, MAGENTA)];
            for (a, colour) in styles {
                let sel: Vec<&CondRow> = rows.iter().filter(|r| r.a == a).collect();
                chart
                    .draw_series(LineSeries::new(
                        sel.iter()
                            .map(|r| (r.n as f64, r.paper_method2.clamp(1.0, 1e26))),
                        colour.stroke_width(1),
                    ))?
                    .label(format!("paper basis, a = {a}"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(1))
                    });
                chart
                    .draw_series(LineSeries::new(
                        sel.iter()
                            .map(|r| (r.n as f64, r.stable_method2.clamp(1.0, 1e26))),
                        colour.stroke_width(3),
                    ))?
                    .label(format!("stable basis, a = {a}"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(3))
                    });
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .position(SeriesLabelPosition::UpperLeft)
                .draw()?;
            root.present()?;
        }
        plot.save(&path)?;
    }
    eprintln!("  wrote {}", path.display());
    ctx.write_json("002-conditioning.json", &rows)?;
    Ok(())
}
