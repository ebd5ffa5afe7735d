//! `000-fig10`: sketch-assisted shape manipulation on the bundled female
//! (paper 000 sec 5.3, Fig 10): (a) a breast from a closed curve on the
//! torso plus a side and a top profile; (b) a nose from an auxiliary line
//! (half of its interface with the face, mirrored) plus the side profile;
//! (c) beside them, the PDESM 4-sided force inside a closed stroke drawn
//! on the torso (`force_stroke`, sec 5.1): the pde4 4-sided patch mapped
//! onto the stroke's inside, pushing the belly out.

use crate::common::{Ctx, Figure};
use pdesculpt::mesh::Mesh;
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::sasm::demo::female_fig10;
use pdesculpt::sasm::Stroke;
use serde_json::json;

/// The torso before and after a stroke force, the stroke on the surface,
/// the edit and its measures.
struct StrokeRow {
    before: Mesh,
    after: Mesh,
    stroke: Vec<[f64; 3]>,
    edit: pdesculpt::character::log::Edit,
    measures: pdesculpt::edit::check_stroke::StrokeMeasures,
    peak: f64,
    watertight: bool,
}

/// The sample three-lobed stroke on the front of the female's torso (the
/// angle whose surface point is farthest forward at mid-torso), pushing
/// forward (+z) with a peak displacement of 3 % of the height.
fn stroke_row() -> anyhow::Result<StrokeRow> {
    use pdesculpt::character::doc::Level;
    use pdesculpt::character::log::Edit;
    use pdesculpt::character::Resolution;
    use pdesculpt::edit::check_stroke::{sample_force_stroke, stroke_measures};
    use pdesculpt::edit::field_of;
    use pdesculpt::pipeline::build_document;
    use pdesculpt::sketch::check::bundled;
    use std::f64::consts::PI;
    let doc = bundled("female", Level::Final).ok_or_else(|| anyhow::anyhow!("bundled female"))?;
    let base = build_document(&doc, std::path::Path::new("."), Resolution::default(), true)?;
    let mut doc = base.doc.clone();
    let spec = doc.parts().iter().find(|p| p.name == "torso").cloned();
    let spec = spec.ok_or_else(|| anyhow::anyhow!("no torso"))?;
    let surf = base.model.parts.iter().find(|p| p.name == "torso");
    let surf = surf.ok_or_else(|| anyhow::anyhow!("no torso surface"))?;
    let um = 0.5 * (surf.u0 + surf.u1);
    let front = (0..360)
        .map(|k| 2.0 * PI * k as f64 / 360.0)
        .max_by(|a, b| surf.point(um, *a)[2].total_cmp(&surf.point(um, *b)[2]))
        .unwrap_or(0.0);
    let unit = sample_force_stroke(&spec, front, [0.0, 0.0, 1.0]);
    let (_, field) = field_of(&unit).ok_or_else(|| anyhow::anyhow!("a force"))??;
    let mut peak = 0.0f64;
    for i in 1..64 {
        for j in 0..256 {
            let th = 2.0 * PI * j as f64 / 256.0;
            peak = peak.max(field.at(i as f64 / 64.0, th)[2].abs());
        }
    }
    let p = 0.03 * base.report.height / peak;
    let edit = sample_force_stroke(&spec, front, [0.0, 0.0, p]);
    doc.push_edit(edit.clone())?;
    let after = build_document(
        &doc,
        std::path::Path::new("."),
        Resolution::default(),
        false,
    )?;
    let Edit::ForceStroke { stroke, .. } = &edit else {
        anyhow::bail!("not a stroke force");
    };
    let measures = stroke_measures(&edit).ok_or_else(|| anyhow::anyhow!("stroke measures"))?;
    Ok(StrokeRow {
        before: base.model.mesh.clone(),
        after: after.model.mesh.clone(),
        stroke: stroke.iter().map(|q| surf.point(q[0], q[1])).collect(),
        edit,
        measures,
        peak: 0.03 * base.report.height,
        watertight: after.report.topology.watertight,
    })
}

/// The figures of the SASM family.
pub fn figures() -> Vec<Figure> {
    vec![Figure {
        id: "000-fig10",
        paper: "000",
        title: "Sketch-assisted modeling on the sketched female: breast from curve + profiles, nose from an auxiliary line",
        run: fig10,
    }]
}

const W: usize = 240;
const H: usize = 280;
const RED: [u8; 4] = [220, 30, 30, 255];
const BLUE: [u8; 4] = [30, 60, 220, 255];
const GREEN: [u8; 4] = [20, 180, 40, 255];

/// A stroke as a 3D polyline in front of the model (`at`: the missing
/// coordinate, placed toward the viewer).
fn overlay(s: &Stroke, at: f64, colour: [u8; 4], closed: bool) -> Overlay {
    let (h, v) = s.view.axes();
    let d = 3 - h - v;
    Overlay {
        points: s
            .points
            .iter()
            .map(|p| {
                let mut q = [0.0; 3];
                q[h] = p[0];
                q[v] = p[1];
                q[d] = at;
                q
            })
            .collect(),
        closed,
        colour,
        depth_test: false,
    }
}

fn panel(m: &Mesh, lo: [f64; 3], hi: [f64; 3], view: View, overlays: Vec<Overlay>) -> Image {
    let cam = Camera::fit_box(lo, hi, view, W, H, 0.04);
    let o = RenderOptions::default()
        .with_width(W)
        .with_height(H)
        .with_view(view)
        .with_overlays(overlays);
    render_with_camera(m, &o, &cam)
}

fn fig10(ctx: &Ctx) -> anyhow::Result<()> {
    let d = female_fig10()?;
    let persp = View::Perspective {
        yaw: 40.0,
        pitch: 5.0,
    };
    // breast: torso's upper half
    let (blo, bhi) = ([-0.2, 0.95, -0.15], [0.2, 1.25, 0.2]);
    let bs = &d.breast_spec;
    let mut ov = vec![overlay(&bs.curve, 1.0, RED, true)];
    ov.push(overlay(&bs.profiles[0], 0.066, BLUE, false));
    ov.push(overlay(&bs.profiles[1], 1.075, BLUE, false));
    let a = [
        panel(&d.before, blo, bhi, View::Front, vec![ov[0].clone()]),
        panel(&d.before, blo, bhi, View::Side, vec![ov[1].clone()]),
        panel(&d.after, blo, bhi, persp, Vec::new()),
        panel(&d.after, blo, bhi, View::Side, Vec::new()),
    ];
    let (nlo, nhi) = ([-0.1, 1.45, -0.1], [0.1, 1.7, 0.13]);
    let ns = &d.nose_spec;
    let b = [
        panel(
            &d.before,
            nlo,
            nhi,
            View::Front,
            vec![overlay(&ns.line, 1.0, GREEN, false)],
        ),
        panel(
            &d.before,
            nlo,
            nhi,
            View::Side,
            vec![overlay(&ns.profile, 1.0, BLUE, false)],
        ),
        panel(&d.after, nlo, nhi, persp, Vec::new()),
        panel(&d.after, nlo, nhi, View::Side, Vec::new()),
    ];
    let sr = stroke_row()?;
    let (clo, chi) = ([-0.22, 0.8, -0.2], [0.22, 1.3, 0.25]);
    let line = |z: f64| Overlay {
        points: sr.stroke.iter().map(|p| [p[0], p[1], p[2] + z]).collect(),
        closed: true,
        colour: RED,
        depth_test: false,
    };
    let c = [
        panel(&sr.before, clo, chi, View::Front, vec![line(0.0)]),
        panel(&sr.before, clo, chi, View::Side, vec![line(0.0)]),
        panel(&sr.after, clo, chi, persp, Vec::new()),
        panel(&sr.after, clo, chi, View::Side, Vec::new()),
    ];
    let img = Image::hstack(
        &[
            Image::hstack(&a, [255; 4]),
            Image::hstack(&b, [255; 4]),
            Image::hstack(&c, [255; 4]),
        ],
        [255; 4],
    );
    let cap = |n: &str, r: &pdesculpt::sasm::check::SasmReport| {
        format!(
            "{n}: curve + profile, before (front, side); after (perspective, side)\npeak height {:.3} m; join C0 {:.1e} of peak, C1 normal angle {:.1e} rad\nprofile error {} of peak; watertight {}",
            r.peak,
            r.c0_rel,
            r.c1_angle_extrapolated,
            r.profile_error_rel
                .iter()
                .map(|e| format!("{:.1} %", 100.0 * e))
                .collect::<Vec<_>>()
                .join(", "),
            r.watertight
        )
    };
    let img = crate::ode6::annotate(
        &img,
        "Paper 000 Fig 10 analogue: (a) breast from a closed curve (red) + side and top profiles (blue); (b) nose from an auxiliary line (green) + side profile (blue); (c) PDESM force inside a closed stroke (red)",
        &[
            cap("(a) breast", &d.breast),
            cap("(b) nose", &d.nose),
            format!(
                "(c) 4-sided force inside a closed stroke: before (front, side); after (perspective, side)\npeak push {:.3} m; on the stroke C0 {:.0e} of peak, slope order {:.2} (C1)\nmean value map folds {}; watertight {}",
                sr.peak,
                sr.measures.c0,
                sr.measures.order,
                sr.measures.folded + sr.measures.negative_jacobians,
                sr.watertight
            ),
        ],
        View::Front,
        false,
    )?;
    ctx.write_bytes("000-fig10.png", &img.encode_png())?;
    ctx.write_json(
        "000-fig10.json",
        &json!({
            "figure": "000-fig10",
            "model": "data/sketch/female_* (final level), strokes from pdesculpt::sasm::demo",
            "panels": "(a) front with curve, side with profile, edited perspective, edited side; (b) the same for the nose; (c) the torso before (front, side, with the stroke) and after a 4-sided force inside the stroke (perspective, side)",
            "breast": d.breast,
            "nose": d.nose,
            "applied": d.applied,
            "stroke_force": {
                "edit": sr.edit,
                "peak_push": sr.peak,
                "c0_on_stroke_rel": sr.measures.c0,
                "slope_order": sr.measures.order,
                "folded": sr.measures.folded + sr.measures.negative_jacobians,
                "min_jacobian": sr.measures.min_jacobian,
                "watertight": sr.watertight,
            },
        }),
    )?;
    Ok(())
}
