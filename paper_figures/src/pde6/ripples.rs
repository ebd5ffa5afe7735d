//! 002-body-ripples: the diagonal ripples of the body reconstruction and
//! their two causes. Panels left to right: legacy (a = -0.5, chord-length
//! parameter from the first sliced vertex), only the anchored
//! parameterisation, only a = -0.01, both (the default); torso, shoulders
//! and head in perspective. The JSON holds per part the roughness, the slip
//! and the distances to the skin of every variant.

use crate::common::Ctx;
use pdesculpt::body::parts::{legacy_options, makehuman_parts, reconstruct, BodyOptions, BODY_A};
use pdesculpt::curve::gec::fit::Param;
use pdesculpt::pde6::sampling::Sampling;
use pdesculpt::render::{render_with_camera, Camera, Image, RenderOptions, View};

const PARTS: [&str; 3] = ["torso", "shoulders_neck", "head"];

pub fn body_ripples(ctx: &Ctx) -> anyhow::Result<()> {
    let body = pdesculpt::makehuman::base_body()?;
    let specs: Vec<_> = makehuman_parts()
        .into_iter()
        .filter(|p| PARTS.contains(&p.name))
        .collect();
    let new = BodyOptions::default();
    let variants = [
        (
            "legacy: a = -0.5, chord from first vertex",
            legacy_options(),
        ),
        ("anchored parameter only (a = -0.5)", new.with_a(-0.5)),
        (
            "a = -0.01 only (chord from first vertex)",
            new.with_sampling(Sampling::Gec(Param::ChordLength)),
        ),
        ("default: anchored, a = -0.01", new),
    ];
    let view = View::Perspective {
        yaw: 25.0,
        pitch: 10.0,
    };
    let mut panels = Vec::new();
    let mut data = Vec::new();
    let mut camera = None;
    for (label, opts) in &variants {
        let (_, mesh, report) = reconstruct(&body.mesh, &specs, opts)?;
        let o = RenderOptions::default()
            .with_view(view)
            .with_width(360)
            .with_height(560);
        let cam: &Camera = camera.get_or_insert_with(|| {
            let (lo, hi) = mesh.bbox();
            Camera::fit_box(lo, hi, view, o.width, o.height, o.margin)
        });
        panels.push(render_with_camera(&mesh, &o, cam));
        data.push(serde_json::json!({
            "variant": label, "a": opts.a,
            "recon_to_skin_rms_rel": report.recon_to_skin_rms_rel,
            "recon_to_skin_max_rel": report.recon_to_skin_max_rel,
            "skin_to_recon_rms_rel": report.skin_to_recon_rms_rel,
            "skin_to_recon_max_rel": report.skin_to_recon_max_rel,
            "parts": report.parts.iter().map(|p| serde_json::json!({
                "name": p.name, "roughness_u": p.roughness.u, "roughness_v": p.roughness.v,
                "slip_deg": p.slip_deg, "start_angle_deg": p.start_angle_deg,
                "recon_to_skin_rms_rel": p.recon_to_skin_rms_rel, "recon_to_skin_max_rel": p.recon_to_skin_max_rel,
            })).collect::<Vec<_>>(),
        }));
    }
    let img = Image::hstack(&panels, [255, 255, 255, 255]);
    ctx.write_bytes("002-body-ripples.png", &img.encode_png())?;
    ctx.write_json(
        "002-body-ripples.json",
        &serde_json::json!({ "body_a": BODY_A, "panels_left_to_right": data }),
    )?;
    Ok(())
}
