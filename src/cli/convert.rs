//! `pdesculpt convert IN -o OUT`: mesh format conversion by extension.

use pdesculpt::mesh::io;
use std::path::PathBuf;

/// Arguments of `pdesculpt convert`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input mesh (.obj, .stl, .ply).
    pub input: PathBuf,
    /// Output mesh (.obj, .glb, .stl, .ply).
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    pub units: super::units::UnitArgs,
}

/// Reads, validates and writes (atomically).
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    // check the output format before reading anything
    io::Format::from_path(&args.output)?;
    io::refuse_overwriting_input(&[&args.input], &args.output)?;
    let m = io::read(&args.input)?;
    let unit = args.units.write_input(&m, &args.output)?;
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
            "unit": unit,
        }))?;
    }
    Ok(0)
}
