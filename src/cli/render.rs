//! `pdesculpt render MESH -o PNG [--view front|side|top|perspective]...`.

use pdesculpt::limits;
use pdesculpt::mesh::io;
use pdesculpt::render::{render_views, RenderOptions, View};
use std::path::PathBuf;

/// Arguments of `pdesculpt render`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input mesh (.obj, .glb, .gltf, .stl, .ply; FILE.glb#NODE,... reads
    /// only the named nodes).
    pub mesh: PathBuf,
    /// Output PNG.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Views, side by side (repeat or comma-separate).
    #[arg(long, value_delimiter = ',', default_values_t = vec!["front".to_string()])]
    pub view: Vec<String>,
    /// Width and height of each view in pixels.
    #[arg(long, default_value_t = 512)]
    pub size: usize,
}

/// Renders the mesh.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    limits::check("--size", args.size, limits::RENDER_SIZE)?;
    limits::check("--view (count)", args.view.len(), limits::RENDER_VIEWS)?;
    let pixels = limits::mul("--size", args.size, args.size)
        .and_then(|p| limits::mul("--size", p, args.view.len()))?;
    if pixels as u64 > limits::RENDER_PIXELS.max {
        anyhow::bail!(
            "--size {} with {} view(s) makes a {pixels}-pixel image, over the limit of {} pixels; reduce --size or the views",
            args.size,
            args.view.len(),
            limits::RENDER_PIXELS.max
        );
    }
    let ext = args
        .output
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if ext != "png" {
        anyhow::bail!("{}: the output must be a .png file", args.output.display());
    }
    let views: Vec<View> = args
        .view
        .iter()
        .map(|v| v.parse::<View>().map_err(anyhow::Error::msg))
        .collect::<anyhow::Result<_>>()?;
    io::refuse_overwriting_input(&[&args.mesh], &args.output)?;
    let m = io::read(&args.mesh)?;
    let img = render_views(
        &m,
        &views,
        &RenderOptions::default()
            .with_width(args.size)
            .with_height(args.size),
    );
    img.save_png(&args.output)?;
    eprintln!("wrote {}", args.output.display());
    if json {
        super::print_json(&serde_json::json!({
            "output": args.output, "width": img.width, "height": img.height,
        }))?;
    }
    Ok(0)
}
