//! `pdesculpt convert IN -o OUT`: mesh format conversion by extension;
//! models and parts are kept (a GLB's root nodes and their part nodes).

use pdesculpt::mesh::io;
use std::path::PathBuf;

/// Arguments of `pdesculpt convert`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input mesh (.obj, .glb, .gltf, .stl, .ply); FILE#NAME[,NAME...]
    /// keeps only the named glTF nodes or OBJ groups.
    pub input: PathBuf,
    /// Output mesh (.obj, .glb, .gltf, .stl, .ply).
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    pub units: super::units::UnitArgs,
}

/// Reads, validates and writes (atomically).
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    // check the output format before reading anything
    io::Format::from_path(&args.output)?;
    let (input_file, _) = io::split_selection(&args.input);
    io::refuse_overwriting_input(&[&input_file], &args.output)?;
    let scene = io::read_scene(&args.input)?;
    let unit = args
        .units
        .write_scene(&scene, &args.output, args.units.input_unit)?;
    let m = scene.flatten();
    eprintln!(
        "wrote {} ({} vertices, {} triangles)",
        args.output.display(),
        m.positions.len(),
        m.triangles.len()
    );
    if json {
        super::print_json(&serde_json::json!({
            "output": args.output,
            "vertices": m.positions.len(),
            "triangles": m.triangles.len(),
            "groups": m.groups,
            "models": scene.models.iter().map(|x| &x.name).collect::<Vec<_>>(),
            // the bounding box as read, in --input-unit (GLB: metres)
            "bbox": {"min": m.bbox().0, "max": m.bbox().1},
            "unit": unit,
        }))?;
    }
    Ok(0)
}
