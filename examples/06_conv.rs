//! Tutorial chapter 6 (docs/tutorial/06_conv.md): convolution surfaces from a
//! sketched silhouette, paper 003.
//!
//! One closed stroke (a five-armed star) becomes a skeleton of line segments
//! with linear weights; the surface is the level set F(r) = T of the
//! convolution of the Cauchy kernel 1 / (1 + s^2 r^2)^2 along them. The
//! segments' scales are fitted so that F = T on the stroke (global
//! interpolation). The example builds the star without and with that fit,
//! reports the field's miss on the stroke, the mesh's topology and how
//! closely its outline follows the stroke, and draws the fitted one in
//! out/tutorial/06_conv.png.
//!
//! Run: `cargo run --release --example 06_conv`

use pdesculpt::conv::model::{Model, Polygonizer};
use pdesculpt::conv::{shapes, silhouette};
use pdesculpt::mesh::topology;
use pdesculpt::render::{self, RenderOptions, View};

fn main() -> anyhow::Result<()> {
    let stroke = shapes::star(5, 0.6, 1.6, 300); // arms, inner and outer radius, points
    let mut fitted = None;
    for solver in ["None", "HildrethDEsopo"] {
        let json = serde_json::json!({
            "options": { "solver": solver },
            "components": [{ "name": "star", "stroke": stroke }]
        });
        let model = Model::from_json(&json.to_string())?;
        let built = model.build()?;
        let sketch = &built.components[0].sketch;
        let mesh =
            built.polygonize(64, model.options.threshold, Polygonizer::MarchingTetrahedra)?;
        let t = topology::report(&mesh);
        // the outline seen along z against the stroke (plane z = 0, axes x, y)
        let e = silhouette::silhouette_error(
            &mesh,
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            &stroke,
        );
        println!("global interpolation {solver}:");
        println!(
            "  {} segments; field on the stroke: max |F - T| / T = {:.3}, RMS {:.3}",
            sketch.segments.len(),
            sketch.fit.max_rel_error,
            sketch.fit.rms_rel_error
        );
        println!(
            "  {} triangles, watertight {}, manifold {}, oriented {}",
            t.triangles, t.watertight, t.manifold, t.oriented
        );
        println!(
            "  outline vs stroke: max {:.2} %, mean {:.2} % of the stroke's size (a pixel is {:.2} %)",
            100.0 * e.max_rel,
            100.0 * e.mean_rel,
            100.0 * e.pixel_rel
        );
        fitted = Some(mesh);
    }

    let mesh = fitted.ok_or_else(|| anyhow::anyhow!("no mesh"))?;
    let options = RenderOptions::default().with_width(240).with_height(240);
    let image = render::render_views(
        &mesh,
        &[
            View::Front,
            View::Perspective {
                yaw: 30.0,
                pitch: 50.0,
            },
        ],
        &options,
    );
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(std::path::Path::new("out/tutorial/06_conv.png"))?;
    println!("wrote out/tutorial/06_conv.png (with global interpolation)");
    Ok(())
}
