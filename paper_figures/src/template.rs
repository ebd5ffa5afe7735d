//! Figures of the template family (paper 000 sec 4.2): the analogue of
//! Fig 7. MakeHuman's own morph targets are the "sketch": a young male
//! becomes a fat man and a boy, a young female a pregnant woman. Each row
//! shows the template, the low, medium and high levels, and the target,
//! in front and side view with the sketched outlines (the target's) in
//! red; captions give the RMS / max vertex error against the target
//! (relative to height) and the bounding-box baseline's.

use crate::common::{Ctx, Figure};
use pdesculpt::makehuman;
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use pdesculpt::template::study::{makehuman_template, run_case, sketch_of, CASES};
use pdesculpt::template::{FitOptions, OnMiss};
use serde_json::json;

/// The figures of the template family.
pub fn figures() -> Vec<Figure> {
    vec![Figure {
        id: "000-fig7",
        paper: "000",
        title: "Template-based modeling: MakeHuman male -> fat man / boy, female -> pregnant, three levels against the artist's targets",
        run: fig7,
    }]
}

const W: usize = 150;
const H: usize = 300;
const RED: [u8; 4] = [220, 30, 30, 255];

fn outline_overlay(points: &[[f64; 2]], view: View) -> Overlay {
    Overlay {
        points: points
            .iter()
            .map(|p| match view {
                View::Side => [0.0, p[1], p[0]],
                _ => [p[0], p[1], 0.0],
            })
            .collect(),
        closed: true,
        colour: RED,
        depth_test: false,
    }
}

fn vstack(images: &[Image]) -> Image {
    let w = images.iter().map(|i| i.width).max().unwrap_or(0);
    let h = images.iter().map(|i| i.height).sum();
    let mut out = Image::new(w, h, [255; 4]);
    let mut y0 = 0;
    for im in images {
        for y in 0..im.height {
            for x in 0..im.width {
                out.put(x as i64, (y0 + y) as i64, im.get(x, y));
            }
        }
        y0 += im.height;
    }
    out
}

fn fig7(ctx: &Ctx) -> anyhow::Result<()> {
    let mut opts = FitOptions::default();
    opts.condition = false;
    opts.on_miss = OnMiss::Report;
    let mut rows_img = Vec::new();
    let mut data = Vec::new();
    for name in ["male->fat", "male->boy", "female->pregnant"] {
        let case = CASES
            .iter()
            .find(|c| c.name == name)
            .ok_or_else(|| anyhow::anyhow!("no study case {name}"))?;
        let template = makehuman_template(case.template)?;
        let ts = case
            .target
            .iter()
            .map(|n| Ok((makehuman::target(n)?, 1.0)))
            .collect::<anyhow::Result<Vec<_>>>()?;
        let target = makehuman::body(&ts)?.mesh;
        let sketch = sketch_of(&target)?;
        let side = sketch.side.clone().unwrap_or_default();
        let (rows, meshes) = run_case(case, &opts)?;
        let mut models: Vec<pdesculpt::mesh::Mesh> =
            meshes.iter().map(|p| template.skin_at(p)).collect();
        models.push(target.clone());
        let mut all = pdesculpt::mesh::Mesh::default();
        for m in &models {
            all.append(m);
        }
        let (lo, hi) = all.bbox();
        let cams = [View::Front, View::Side].map(|v| (v, Camera::fit_box(lo, hi, v, W, H, 0.04)));
        let mut panels = Vec::new();
        for m in &models {
            let views: Vec<Image> = cams
                .iter()
                .map(|(v, cam)| {
                    let pts = if *v == View::Side {
                        &side
                    } else {
                        &sketch.front
                    };
                    let o = RenderOptions::default()
                        .with_width(W)
                        .with_height(H)
                        .with_view(*v)
                        .with_overlays(vec![outline_overlay(pts, *v)]);
                    render_with_camera(m, &o, cam)
                })
                .collect();
            panels.push(Image::hstack(&views, [255; 4]));
        }
        let bbox = rows
            .iter()
            .find(|r| r.method == "bbox")
            .ok_or_else(|| anyhow::anyhow!("{name}: the study has no bbox row"))?;
        let mut captions = vec![format!(
            "template\nbbox baseline: {:.2} / {:.2} %",
            100.0 * bbox.rms_rel,
            100.0 * bbox.max_rel
        )];
        for r in rows
            .iter()
            .filter(|r| r.method != "bbox" && r.method != "target")
        {
            let prof: Vec<String> = r
                .profiles
                .iter()
                .map(|p| format!("{} {:.2}", p.view.name(), 100.0 * p.distance.max_rel))
                .collect();
            captions.push(format!(
                "{}: vertex {:.2} / {:.2} %\nprofile % {}",
                r.method,
                100.0 * r.rms_rel,
                100.0 * r.max_rel,
                prof.join(", ")
            ));
        }
        captions.push(format!("target ({name})"));
        let img = crate::ode6::annotate(
            &Image::hstack(&panels, [255; 4]),
            &format!("{name}: template, low, medium, high, MakeHuman target (red: the target's outlines)"),
            &captions,
            View::Front,
            false,
        )?;
        rows_img.push(img);
        data.push(json!({ "case": name, "rows": rows }));
    }
    ctx.write_bytes("000-fig7.png", &vstack(&rows_img).encode_png())?;
    ctx.write_json(
        "000-fig7.json",
        &json!({
            "figure": "000-fig7",
            "sketch": "the MakeHuman target's front and side outlines (profile::outline_of_mesh) and 6 torso sections",
            "errors": "vertex: RMS / max distance to the target's vertex, over height; profile: fitted outline vs sketch, max over height",
            "cases": data,
        }),
    )?;
    Ok(())
}
