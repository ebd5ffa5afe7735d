//! Tutorial chapter 8 (docs/tutorial/08_local.md): local modeling, paper 000
//! sec 5, as an undoable edit log.
//!
//! Starting from the bundled female (final level), two edits are pushed:
//! a sculpting force on the torso (the pde4 2-sided patch of chapter 2,
//! clamped at both ends of its u range and added to the part) and a GEC bend
//! of every key section of the left arm (sec 5.2). The example measures the
//! force's displacement at its clamped ends, counts the vertices each edit
//! moved, undoes both and checks that the rebuild is the original bit for
//! bit, and draws before and after in out/tutorial/08_local.png.
//!
//! Run: `cargo run --release --example 08_local`

use pdesculpt::character::doc::Level;
use pdesculpt::character::log::Edit;
use pdesculpt::character::Resolution;
use pdesculpt::edit::force_field;
use pdesculpt::pipeline::build_document;
use pdesculpt::render::{self, Image, RenderOptions, View};
use pdesculpt::sketch::check::bundled;
use pdesculpt::surface::Surface;
use std::path::Path;

fn main() -> anyhow::Result<()> {
    let start = bundled("female", Level::Final).ok_or_else(|| anyhow::anyhow!("bundled female"))?;
    let build = |d: &pdesculpt::character::doc::CharacterDoc, derive: bool| {
        build_document(d, Path::new("."), Resolution::default(), derive)
    };
    let before = build(&start, true)?; // derives and stores the parts
    let mut doc = before.doc.clone();

    // a force pushing the front of the torso out, over the middle of its u range
    let torso = doc
        .parts()
        .iter()
        .find(|p| p.name == "torso")
        .ok_or_else(|| anyhow::anyhow!("torso"))?;
    let (u0, u1) = (
        torso.sections[0].u,
        torso.sections[torso.sections.len() - 1].u,
    );
    let force: Edit = serde_json::from_value(serde_json::json!({
        "op": "force", "part": "torso", "u": [u0 + 0.3 * (u1 - u0), u0 + 0.6 * (u1 - u0)],
        "force": {"type": "area", "u0": 0.3, "u1": 0.7, "v0": 0.15, "v1": 0.35, "p": [0.0, 0.0, 200.0]}
    }))?;
    let field = force_field(&force)?; // the displacement d(s, v) on the unit square
    let (mut peak, mut ends): (f64, f64) = (0.0, 0.0);
    for j in 0..64 {
        let v = j as f64 / 64.0;
        peak = peak.max(pdesculpt::vec3::norm(field.point(0.5, v)));
        for s in [0.0, 1.0] {
            ends = ends.max(pdesculpt::vec3::norm(field.point(s, v)));
            ends = ends.max(pdesculpt::vec3::norm(field.derivative(s, v, 1, 0)));
        }
    }
    println!("force: peak displacement {peak:.3e}, |d| and |d_u| at the clamped ends {ends:.1e}");
    doc.push_edit(force)?;

    // bend every key section of the left arm in GEC coefficient space
    doc.push_edit(serde_json::from_str(
        r#"{"op": "gec_transform", "part": "arm_l", "transform": {"kind": "bend", "kappa": 2.0, "axis": [0, 0, 1]}}"#,
    )?)?;
    let after = build(&doc, false)?;
    let (a, b) = (&before.model.mesh.positions, &after.model.mesh.positions);
    let moved = a.iter().zip(b).filter(|(p, q)| p != q).count();
    println!("two edits moved {moved} of {} vertices", a.len());

    doc.undo()?;
    doc.undo()?;
    let again = build(&doc, false)?;
    println!(
        "after two undos the mesh equals the original: {}",
        again.model.mesh == before.model.mesh
    );

    let options = RenderOptions::default().with_width(150).with_height(280);
    let views = |m| render::render_views(m, &[View::Front, View::Side], &options);
    let image = Image::hstack(
        &[views(&before.model.mesh), views(&after.model.mesh)],
        [255; 4],
    );
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(Path::new("out/tutorial/08_local.png"))?;
    println!("wrote out/tutorial/08_local.png (before: left pair, after: right pair)");
    Ok(())
}
