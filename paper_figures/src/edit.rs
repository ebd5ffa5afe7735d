//! Figures of the edit family (paper 000 sec 5): local modeling as edits of
//! the bundled female's character document.
//!
//! * `000-fig8`: PDESM on the female's torso (the paper uses a pig torso;
//!   pdesculpt bundles no animal): original; a sculpting force (pde4 2-sided
//!   patch over the torso's middle, shape parameters a1 = 1, a2 = 2a^2,
//!   a3 = a^4) with a = 1.0 and a = 0.3 (same force); a changed boundary
//!   curve (the hip end's section 25 % wider); a changed boundary tangent
//!   (the shoulder end's tangent tilted forward).
//! * `000-fig9`: GECDSM on the bundled four-legged animal (as the paper's
//!   Fig 9 on an elephant): original; neck and head bent forward; body sections
//!   scaled; a knee bump on a front leg; tail bent.

use crate::common::{Ctx, Figure};
use pdesculpt::character::doc::{CharacterDoc, End, Level, SectionShape};
use pdesculpt::character::log::{Edit, SectionTransform};
use pdesculpt::character::Resolution;
use pdesculpt::edit::check::sample_force;
use pdesculpt::edit::force_field;
use pdesculpt::mesh::{norm, Mesh};
use pdesculpt::pipeline::{build_document, Built};
use pdesculpt::render::{render_with_camera, Camera, Image, RenderOptions, View};
use pdesculpt::sketch::check::bundled;
use pdesculpt::surface::Surface;
use serde_json::json;
use std::path::Path;

/// The figures of the edit family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "000-fig8",
            paper: "000",
            title: "PDESM on the female torso: shape parameters, boundary curve, boundary tangent",
            run: fig8,
        },
        Figure {
            id: "000-fig9",
            paper: "000",
            title: "GECDSM on the four-legged animal: bend, scale, bump",
            run: fig9,
        },
    ]
}

const W: usize = 260;
const H: usize = 480;
/// Landscape panels for the animal.
const ANIMAL_W: usize = 360;
const ANIMAL_H: usize = 300;
const VIEW: View = View::Perspective {
    yaw: 20.0,
    pitch: 10.0,
};

fn female() -> anyhow::Result<CharacterDoc> {
    let doc = bundled("female", Level::Final).ok_or_else(|| anyhow::anyhow!("bundled female"))?;
    Ok(build_document(&doc, Path::new("."), Resolution::default(), true)?.doc)
}

/// Builds `doc` with `edits` pushed (each validated).
fn with(doc: &CharacterDoc, edits: &[Edit]) -> anyhow::Result<Built> {
    let mut d = doc.clone();
    for e in edits {
        d.push_edit(e.clone())?;
    }
    Ok(build_document(
        &d,
        Path::new("."),
        Resolution::default(),
        false,
    )?)
}

fn panels(
    ctx: &Ctx,
    id: &str,
    title: &str,
    cases: Vec<(String, Built)>,
    base: &Mesh,
    (w, h): (usize, usize),
) -> anyhow::Result<Vec<serde_json::Value>> {
    let mut all = Mesh::default();
    for (_, b) in &cases {
        all.append(&b.model.mesh);
    }
    let (lo, hi) = all.bbox();
    let cam = Camera::fit_box(lo, hi, VIEW, w, h, 0.04);
    let mut imgs = Vec::new();
    let mut caps = Vec::new();
    let mut rows = Vec::new();
    for (name, b) in &cases {
        let o = RenderOptions::default()
            .with_width(w)
            .with_height(h)
            .with_view(VIEW);
        imgs.push(render_with_camera(&b.model.mesh, &o, &cam));
        let t = &b.report.topology;
        let moved = if b.model.mesh.positions.len() == base.positions.len() {
            b.model
                .mesh
                .positions
                .iter()
                .zip(&base.positions)
                .map(|(p, q)| pdesculpt::mesh::dist(*p, *q))
                .fold(0.0, f64::max)
        } else {
            f64::NAN
        };
        caps.push(format!(
            "{name}\nlargest move {:.3} (height {:.2})\nwatertight {}",
            moved, b.report.height, t.watertight
        ));
        rows.push(json!({
            "panel": name,
            "edits": b.doc.active_edits(),
            "largest_vertex_move": moved,
            "watertight": t.watertight,
            "manifold": t.manifold,
            "oriented": t.oriented,
            "max_transition_c1_jump": b.report.max_c1,
        }));
    }
    let img = Image::hstack(&imgs, [255; 4]);
    let img = crate::ode6::annotate(&img, title, &caps, VIEW, false)?;
    ctx.write_bytes(&format!("{id}.png"), &img.encode_png())?;
    Ok(rows)
}

fn fig8(ctx: &Ctx) -> anyhow::Result<()> {
    let doc = female()?;
    let torso = doc
        .parts()
        .iter()
        .find(|p| p.name == "torso")
        .ok_or_else(|| anyhow::anyhow!("no torso"))?
        .clone();
    // the force: scaled so that its peak displacement at a = 1 is 4 % of
    // the height
    let unit = sample_force(&torso, [0.0, 0.0, 1.0]);
    let field = force_field(&unit)?;
    let mut peak = 0.0f64;
    for i in 0..=32 {
        for j in 0..32 {
            peak = peak.max(norm(field.point(i as f64 / 32.0, j as f64 / 32.0)));
        }
    }
    let p = 0.04 * 1.7 / peak;
    let force = |a: f64| match sample_force(&torso, [0.0, 0.0, p]) {
        Edit::Force { part, u, force, .. } => Edit::Force { part, u, force, a },
        e => e,
    };
    let wider = match &torso.sections[0].shape {
        SectionShape::Ellipse { a, b, offset } => SectionShape::Ellipse {
            a: 1.25 * a,
            b: 1.25 * b,
            offset: *offset,
        },
        SectionShape::Circle { r } => SectionShape::Circle { r: 1.25 * r },
        s => s.clone(),
    };
    let base = with(&doc, &[])?;
    let cases = vec![
        ("a: original".to_string(), base.clone()),
        (
            "b: force, shape parameter 1.0".into(),
            with(&doc, &[force(1.0)])?,
        ),
        (
            "c: force, shape parameter 0.3".into(),
            with(&doc, &[force(0.3)])?,
        ),
        (
            "d: boundary curve (hips end 25 % wider)".into(),
            with(
                &doc,
                &[Edit::Boundary {
                    part: "torso".into(),
                    end: End::Start,
                    curve: Some(wider),
                    tangent: None,
                    reach: 0.3,
                }],
            )?,
        ),
        (
            "e: boundary tangent (shoulder end tilted forward)".into(),
            with(
                &doc,
                &[Edit::Boundary {
                    part: "torso".into(),
                    end: End::End,
                    curve: None,
                    tangent: Some([0.0, 0.0, 0.5]),
                    reach: 0.5,
                }],
            )?,
        ),
    ];
    let rows = panels(
        ctx,
        "000-fig8",
        "PDESM on the sketched female's torso (paper 000 Fig 8 analogue; the paper uses a pig torso)",
        cases,
        &base.model.mesh,
        (W, H),
    )?;
    ctx.write_json(
        "000-fig8.json",
        &json!({
            "figure": "000-fig8",
            "model": "bundled female (data/sketch), final level, default resolution",
            "force": "pde4 2-sided area force over the torso's middle half (u in [0.25, 0.75] of its length, v in [0.1, 0.4]), clamped at both range ends; shape parameters a1 = 1, a2 = 2 a^2, a3 = a^4; force scaled so that the peak displacement at a = 1 is 4 % of the height",
            "boundary": "curve: the torso's start section replaced (part-level, the hips transition follows); tangent: sections within reach moved so the solved end tangent changes by exactly the request (edit.boundary_tangent)",
            "panels": rows,
        }),
    )?;
    Ok(())
}

fn fig9(ctx: &Ctx) -> anyhow::Result<()> {
    let doc = bundled("animal", Level::Final).ok_or_else(|| anyhow::anyhow!("bundled animal"))?;
    let doc = build_document(&doc, Path::new("."), Resolution::default(), true)?.doc;
    let gec = |part: &str, section: Option<usize>, transform| Edit::GecTransform {
        part: part.into(),
        section,
        transform,
    };
    let base = with(&doc, &[])?;
    let height = base.report.height;
    let leg = doc
        .parts()
        .iter()
        .find(|p| p.name == "leg_fl")
        .ok_or_else(|| anyhow::anyhow!("the animal has no leg_fl"))?;
    let n = leg.sections.len();
    // a bump on the middle third of the front leg's sections (a knee)
    let bump: Vec<Edit> = (n / 3..(2 * n) / 3)
        .map(|s| {
            gec(
                "leg_fl",
                Some(s),
                SectionTransform::Bump {
                    h: 0.025 * height,
                    theta: 0.0,
                    sigma: 0.6,
                },
            )
        })
        .collect();
    let z = [0.0, 0.0, 1.0];
    let cases = vec![
        ("a: original".to_string(), base.clone()),
        (
            "b: neck and head bent forward".into(),
            with(
                &doc,
                &[gec(
                    "head",
                    None,
                    SectionTransform::Bend {
                        kappa: -2.5 / height,
                        axis: z,
                    },
                )],
            )?,
        ),
        (
            "c: body sections scaled (1.2, 1.15)".into(),
            with(
                &doc,
                &[gec(
                    "body",
                    None,
                    SectionTransform::Scale { sx: 1.2, sy: 1.15 },
                )],
            )?,
        ),
        ("d: knee bump on the front leg".into(), with(&doc, &bump)?),
        (
            "e: tail bent".into(),
            with(
                &doc,
                &[gec(
                    "tail",
                    None,
                    SectionTransform::Bend {
                        kappa: 5.0 / height,
                        axis: z,
                    },
                )],
            )?,
        ),
    ];
    let rows = panels(
        ctx,
        "000-fig9",
        "GECDSM on the sketched four-legged animal (paper 000 Fig 9 analogue)",
        cases,
        &base.model.mesh,
        (ANIMAL_W, ANIMAL_H),
    )?;
    ctx.write_json(
        "000-fig9.json",
        &json!({
            "figure": "000-fig9",
            "model": "bundled four-legged animal (data/sketch/animal_*.svg), final level, default resolution",
            "transforms": "curve::gec::transform in coefficient space on the parts' key sections (circles/ellipses converted to GECs exactly), parts re-solved",
            "panels": rows,
        }),
    )?;
    Ok(())
}
