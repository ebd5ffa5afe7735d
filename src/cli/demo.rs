//! `pdesculpt demo`: the main job on bundled data.
//!
//! For now: the MakeHuman body (a young male, morph targets applied) as
//! GLB, OBJ and a front/side PNG in `out/`.

use pdesculpt::makehuman;
use pdesculpt::mesh::io;
use pdesculpt::render::{render_views, RenderOptions, View};
use std::path::PathBuf;

/// Arguments of `pdesculpt demo`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Output directory.
    #[arg(short, long, default_value = "out")]
    pub out: PathBuf,
}

/// Builds the demo outputs.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    eprintln!("loading the MakeHuman body with targets caucasian-male-young + universal-male-young-averagemuscle-averageweight");
    let targets = vec![
        (makehuman::target("caucasian-male-young")?, 1.0),
        (
            makehuman::target("universal-male-young-averagemuscle-averageweight")?,
            1.0,
        ),
    ];
    let body = makehuman::body(&targets)?;
    let glb = args.out.join("demo.glb");
    let obj = args.out.join("demo.obj");
    let png = args.out.join("demo.png");
    io::write(&body.mesh, &glb)?;
    io::write(&body.mesh, &obj)?;
    render_views(
        &body.mesh,
        &[View::Front, View::Side],
        &RenderOptions {
            width: 400,
            height: 800,
            ..Default::default()
        },
    )
    .save_png(&png)?;
    for p in [&glb, &obj, &png] {
        eprintln!("wrote {}", p.display());
    }
    if json {
        super::print_json(&serde_json::json!({
            "outputs": [glb, obj, png],
            "vertices": body.mesh.positions.len(),
            "triangles": body.mesh.triangles.len(),
        }))?;
    }
    Ok(0)
}
