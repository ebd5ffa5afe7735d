//! Tutorial chapter 7 (docs/tutorial/07_sketch.md): a character from
//! sketches, paper 000 sec 4.1.
//!
//! The bundled female drawing (front and side outline as SVG, three torso
//! cross sections as JSON) is built at the three levels of the paper:
//! initial (circles from the front view), intermediate (ellipses from both
//! views), final (key sections fitted by GECs). Each part is a C2 pde6
//! chain; the parts meet in C1 Hermite transitions. The example prints the
//! topology, the distance of the model's outlines from the drawing and the
//! largest C1 jump, and draws the final level in out/tutorial/07_sketch.png.
//!
//! Run: `cargo run --release --example 07_sketch`

use pdesculpt::character::doc::{BodyPlan, CharacterDoc, Inputs, KeySection, Level, ProfileInput};
use pdesculpt::character::Resolution;
use pdesculpt::pipeline::build_document;
use pdesculpt::render::{self, RenderOptions, View};
use std::path::Path;

#[derive(serde::Deserialize)]
struct SectionsFile {
    sections: Vec<KeySection>,
}

fn main() -> anyhow::Result<()> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/sketch");
    let path = |name: &str| ProfileInput::Path(dir.join(name).display().to_string());
    let text = std::fs::read_to_string(dir.join("female_sections.json"))?;
    let sections = serde_json::from_str::<SectionsFile>(&text)?.sections;

    let mut last = None;
    for level in [Level::Initial, Level::Intermediate, Level::Final] {
        let inputs = Inputs {
            front: path("female_front.svg"),
            side: Some(path("female_side.svg")),
            sections: sections.clone(),
            tolerance: None,
            height: None,
            body_plan: BodyPlan::Auto,
        };
        let doc = CharacterDoc::from_inputs(inputs, level);
        let built = build_document(&doc, Path::new("."), Resolution::default(), true)?;
        let r = &built.report;
        let c1 = r
            .transitions
            .iter()
            .flat_map(|t| &t.joins)
            .fold(0.0f64, |m, j| m.max(j.c1));
        let errors: Vec<String> = r
            .profile_error
            .iter()
            .map(|e| format!("{} {:.2} %", e.view, 100.0 * e.max_rel))
            .collect();
        println!(
            "{level:?}: {} parts, {} triangles, watertight {}; outline error {}; largest C1 jump {c1:.1e}",
            r.parts.len(),
            r.topology.triangles,
            r.topology.watertight,
            errors.join(", ")
        );
        last = Some(built);
    }

    let built = last.ok_or_else(|| anyhow::anyhow!("nothing built"))?;
    let options = RenderOptions::default().with_width(180).with_height(300);
    let image = render::render_views(&built.model.mesh, &[View::Front, View::Side], &options);
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(Path::new("out/tutorial/07_sketch.png"))?;
    println!("wrote out/tutorial/07_sketch.png (final level, front and side)");
    Ok(())
}
