//! `000-fig10`: sketch-assisted shape manipulation on the bundled female
//! (paper 000 sec 5.3, Fig 10): (a) a breast from a closed curve on the
//! torso plus a side and a top profile; (b) a nose from an auxiliary line
//! (half of its interface with the face, mirrored) plus the side profile.

use crate::common::{Ctx, Figure};
use pdesculpt::mesh::Mesh;
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::sasm::demo::female_fig10;
use pdesculpt::sasm::Stroke;
use serde_json::json;

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
    let o = RenderOptions {
        width: W,
        height: H,
        view,
        overlays,
        ..Default::default()
    };
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
    let img = Image::hstack(
        &[Image::hstack(&a, [255; 4]), Image::hstack(&b, [255; 4])],
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
        "Paper 000 Fig 10 analogue: (a) breast from a closed curve (red) + side and top profiles (blue); (b) nose from an auxiliary line (green) + side profile (blue)",
        &[cap("(a) breast", &d.breast), cap("(b) nose", &d.nose)],
        View::Front,
        false,
    )?;
    ctx.write_bytes("000-fig10.png", &img.encode_png())?;
    ctx.write_json(
        "000-fig10.json",
        &json!({
            "figure": "000-fig10",
            "model": "data/sketch/female_* (final level), strokes from pdesculpt::sasm::demo",
            "panels": "(a) front with curve, side with profile, edited perspective, edited side; (b) the same for the nose",
            "breast": d.breast,
            "nose": d.nose,
            "applied": d.applied,
        }),
    )?;
    Ok(())
}
