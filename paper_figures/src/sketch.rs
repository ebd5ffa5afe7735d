//! Figures of the sketch family (paper 000 sec 4.1): the analogue of Fig 6,
//! the three modeling levels of the bundled female drawing side by side
//! (initial: circles from the front profile; intermediate: ellipses from the
//! front and side profiles; final: key cross-section sketches fitted by
//! GECs), each in front and side view with its sketched outline in red and
//! its profile errors in the caption. All three levels are measured against
//! both sketched views (the initial level is built without the side view,
//! so its side error shows what the side profile adds).

use crate::common::{Ctx, Figure};
use pdesculpt::character::doc::Level;
use pdesculpt::character::Resolution;
use pdesculpt::mesh::topology::report as topology;
use pdesculpt::mesh::Mesh;
use pdesculpt::pipeline::{build_document, Built};
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::sketch::check::{bundled, profile_errors};
use serde_json::json;
use std::path::Path;

/// The figures of the sketch family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "000-fig5",
            paper: "000",
            title:
                "Sketched female: outline, parts and central curves, key sections, initial model",
            run: fig5,
        },
        Figure {
            id: "000-fig6",
            paper: "000",
            title: "Sketched female: initial, intermediate and final models with profile errors",
            run: fig6,
        },
    ]
}

const PALETTE: [[u8; 4]; 6] = [
    [30, 90, 200, 255],
    [20, 150, 60, 255],
    [200, 120, 0, 255],
    [150, 40, 180, 255],
    [0, 150, 160, 255],
    [190, 40, 90, 255],
];

fn flat(points: Vec<[f64; 3]>, closed: bool, colour: [u8; 4]) -> Overlay {
    Overlay {
        points,
        closed,
        colour,
        depth_test: false,
    }
}

/// Points of a circle or ellipse section (GEC sections are not drawn).
fn section_points(s: &pdesculpt::character::doc::SectionSpec) -> Option<Vec<[f64; 3]>> {
    use pdesculpt::character::doc::SectionShape;
    let (a, b, off) = match s.shape {
        SectionShape::Circle { r } => (r, r, 0.0),
        SectionShape::Ellipse { a, b, offset } => (a, b, offset),
        SectionShape::Gec { .. } => return None,
    };
    Some(
        (0..48)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 48.0;
                let (c, sn) = (a * t.cos(), off + b * t.sin());
                [0, 1, 2].map(|d| s.centre[d] + c * s.e1[d] + sn * s.e2[d])
            })
            .collect(),
    )
}

/// Paper 000 Fig 5 analogue: the stages of the initial model on the
/// bundled female's front outline.
fn fig5(ctx: &Ctx) -> anyhow::Result<()> {
    let doc = bundled("female", Level::Initial)
        .ok_or_else(|| anyhow::anyhow!("the bundled female does not parse"))?;
    let b = build_document(&doc, Path::new("."), Resolution::default(), true)?;
    let (lo, hi) = b.model.mesh.bbox();
    let cam = Camera::fit_box(lo, hi, View::Front, W, H, 0.04);
    let grey = [150, 150, 150, 255];
    let black = [0, 0, 0, 255];
    let outline = |c| outline_overlay(b.front.points(), View::Front).with_colour(c);
    let empty = Mesh::default();
    let draw = |m: &Mesh, overlays: Vec<Overlay>| {
        let o = RenderOptions::default()
            .with_width(W)
            .with_height(H)
            .with_view(View::Front)
            .with_overlays(overlays);
        render_with_camera(m, &o, &cam)
    };
    // (b) parts: each part's end sections (its boundaries) and its central
    // curve (the section centres); (c) every key section
    let mut parts = vec![outline(grey)];
    let mut sections = vec![outline(grey)];
    for (i, p) in b.doc.parts().iter().enumerate() {
        let col = PALETTE[i % PALETTE.len()];
        parts.push(flat(
            p.sections.iter().map(|s| s.centre).collect(),
            false,
            col,
        ));
        for s in [&p.sections[0], &p.sections[p.sections.len() - 1]] {
            if let Some(pts) = section_points(s) {
                parts.push(flat(pts, true, col));
            }
        }
        for s in &p.sections {
            if let Some(pts) = section_points(s) {
                sections.push(flat(pts, true, col));
            }
        }
    }
    let panels = vec![
        draw(&empty, vec![outline(black)]),
        draw(&empty, parts),
        draw(&empty, sections),
        draw(&b.model.mesh, vec![outline(RED)]),
    ];
    let r = &b.report;
    let n_sections: usize = b.doc.parts().iter().map(|p| p.sections.len()).sum();
    let front = r.profile_error.first();
    let captions = vec![
        format!("a outline ({} points)", b.front.points().len()),
        format!(
            "b {} parts: central curves\nand join boundaries",
            b.doc.parts().len()
        ),
        format!("c {n_sections} key sections (circles)"),
        format!(
            "d initial model\nfront error max {:.2} %",
            100.0 * front.map_or(f64::NAN, |e| e.max_rel)
        ),
    ];
    let img = Image::hstack(&panels, [255; 4]);
    let img = crate::ode6::annotate(
        &img,
        "Sketched female (paper 000 Fig 5): segmentation stages of the initial model",
        &captions,
        View::Front,
        false,
    )?;
    ctx.write_bytes("000-fig5.png", &img.encode_png())?;
    ctx.write_json(
        "000-fig5.json",
        &json!({
            "figure": "000-fig5",
            "model": "data/sketch/female_front.svg",
            "parts": b.doc.parts().iter().map(|p| json!({
                "name": p.name,
                "sections": p.sections.len(),
                "centres": p.sections.iter().map(|s| s.centre).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
            "transitions": b.doc.transitions().iter().map(|t| json!({"name": t.name, "parent": t.parent, "children": t.children})).collect::<Vec<_>>(),
            "profile_error": r.profile_error,
            "watertight": r.topology.watertight,
        }),
    )?;
    Ok(())
}

const W: usize = 260;
const H: usize = 520;
const RED: [u8; 4] = [220, 30, 30, 255];

trait WithColour {
    fn with_colour(self, c: [u8; 4]) -> Self;
}

impl WithColour for Overlay {
    fn with_colour(mut self, c: [u8; 4]) -> Overlay {
        self.colour = c;
        self
    }
}

fn outline_overlay(points: &[[f64; 2]], view: View) -> Overlay {
    Overlay {
        points: points
            .iter()
            .map(|p| match view {
                // side view: outline x is model z
                View::Side => [0.0, p[1], p[0]],
                _ => [p[0], p[1], 0.0],
            })
            .collect(),
        closed: true,
        colour: RED,
        depth_test: false,
    }
}

fn fig6(ctx: &Ctx) -> anyhow::Result<()> {
    let levels = [Level::Initial, Level::Intermediate, Level::Final];
    let mut built: Vec<Built> = Vec::new();
    for level in levels {
        let doc = bundled("female", level)
            .ok_or_else(|| anyhow::anyhow!("the bundled female does not parse"))?;
        built.push(build_document(
            &doc,
            Path::new("."),
            Resolution::default(),
            true,
        )?);
    }
    let side = built
        .iter()
        .find_map(|b| b.side.clone())
        .ok_or_else(|| anyhow::anyhow!("no level read the side profile"))?;
    let mut all = Mesh::default();
    for b in &built {
        all.append(&b.model.mesh);
    }
    let (lo, hi) = all.bbox();
    let cams = [View::Front, View::Side].map(|v| (v, Camera::fit_box(lo, hi, v, W, H, 0.04)));
    let mut panels = Vec::new();
    let mut captions = Vec::new();
    let mut rows = Vec::new();
    for b in &built {
        let r = &b.report;
        let errs = profile_errors(&b.model.mesh, &b.front, Some(&side), r.height);
        let views: Vec<Image> = cams
            .iter()
            .map(|(v, cam)| {
                let pts = match v {
                    View::Side => side.points(),
                    _ => b.front.points(),
                };
                let o = RenderOptions::default()
                    .with_width(W)
                    .with_height(H)
                    .with_view(*v)
                    .with_overlays(vec![outline_overlay(pts, *v)]);
                render_with_camera(&b.model.mesh, &o, cam)
            })
            .collect();
        panels.push(Image::hstack(&views, [255; 4]));
        let t = topology(&b.model.mesh);
        let from = match r.level {
            Level::Initial => "front only",
            Level::Intermediate => "front + side",
            Level::Final => "front + side + sections",
        };
        let mut cap = format!(
            "{} (from {from}; {} vertices)",
            r.level.name(),
            b.model.mesh.positions.len()
        );
        for e in &errs {
            cap.push_str(&format!(
                "\n{} error: max {:.2} %, rms {:.2} %",
                e.view,
                100.0 * e.max_rel,
                100.0 * e.rms_rel
            ));
        }
        captions.push(cap);
        rows.push(json!({
            "level": r.level,
            "built_from": from,
            "vertices": b.model.mesh.positions.len(),
            "triangles": b.model.mesh.triangles.len(),
            "watertight": t.watertight,
            "manifold": t.manifold,
            "oriented": t.oriented,
            "max_c1_jump": r.max_c1,
            "height": r.height,
            "profile_error_relative_to_height": errs,
            "parts": r.parts.iter().map(|p| json!({
                "name": p.name,
                "sections": p.sections.iter().map(|s| s.shape).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
        }));
    }
    let img = Image::hstack(&panels, [255; 4]);
    let img = crate::ode6::annotate(
        &img,
        "Sketched female (paper 000 Fig 6): initial, intermediate, final; red: the sketched outlines",
        &captions,
        View::Front,
        false,
    )?;
    ctx.write_bytes("000-fig6.png", &img.encode_png())?;
    ctx.write_json(
        "000-fig6.json",
        &json!({
            "figure": "000-fig6",
            "model": "data/sketch/female_*.svg, female_sections.json",
            "profile_error": "model silhouette (profile::outline_of_mesh) vs the sketched outline, symmetric boundary distance, max and RMS over model height; every level against both views",
            "levels": rows,
        }),
    )?;
    Ok(())
}
