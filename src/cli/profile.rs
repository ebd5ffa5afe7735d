//! `pdesculpt profile`: outlines of a view.
//!
//! * `profile extract MESH --view front|side|top -o OUT.svg [--resolution N]`
//! * `profile check SKETCH.svg|SKETCH.json --view V [--tolerance T]`
//!
//! With the global `--json` the report goes to stdout as JSON; without it a
//! summary goes to stderr.

use anyhow::{bail, Context};
use pdesculpt::mesh::io;
use pdesculpt::profile::{
    outline_of_mesh, read_json, read_svg, write_svg, OutlineOptions, Profile, View, MAX_RESOLUTION,
};
use std::path::PathBuf;

const CONVENTIONS: &str = "\
CONVENTIONS (SVG files; the same for sketches read by other commands):
  SVG user units are model units; the root viewBox is ignored, every other
  transform (groups, transform attributes) is applied.
  front: SVG x = model x, SVG y = -model y (y up)
  side:  SVG x = model z, SVG y = -model y
  top:   SVG x = model x, SVG y = model z
  A sketch holds exactly one closed outline (path ending in Z, rect, circle,
  ellipse, polygon) plus optional open cut paths/lines/polylines whose id
  starts with 'cut'. Curves are flattened to within --tolerance.
  JSON sketches: {\"view\": \"front\", \"points\": [[h, v], ...]} in the
  view's (horizontal, vertical) model coordinates.";

/// Arguments of `pdesculpt profile`.
#[derive(clap::Args, Debug)]
#[command(after_long_help = CONVENTIONS)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// The outer outline of a mesh's orthographic projection, as SVG.
    #[command(after_long_help = CONVENTIONS)]
    Extract(ExtractArgs),
    /// Validate a sketch (SVG or JSON) and report its size.
    #[command(after_long_help = CONVENTIONS)]
    Check(CheckArgs),
}

#[derive(clap::Args, Debug)]
pub struct ExtractArgs {
    /// Input mesh (.obj, .glb, .gltf, .stl, .ply; FILE.glb#NODE,... reads
    /// only the named nodes).
    pub mesh: PathBuf,
    /// View: front, side or top.
    #[arg(long)]
    pub view: String,
    /// Output SVG.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Pixels along the larger extent of the projection (accuracy: the
    /// outline is within one pixel of the exact one), at most 8192.
    #[arg(long, default_value_t = OutlineOptions::default().resolution)]
    pub resolution: usize,
}

#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// Sketch file (.svg, or .json).
    pub sketch: PathBuf,
    /// View the sketch is drawn in: front, side or top.
    #[arg(long)]
    pub view: String,
    /// Curve flattening tolerance, model units.
    #[arg(long, default_value_t = 1e-3)]
    pub tolerance: f64,
}

/// Runs a `profile` subcommand.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Command::Extract(a) => extract(a, json),
        Command::Check(a) => check(a, json),
    }
}

fn summary(p: &Profile) -> serde_json::Value {
    let (lo, hi) = p.bbox();
    serde_json::json!({
        "view": p.view(),
        "points": p.len(),
        "width": p.width(),
        "height": p.height(),
        "area": p.area(),
        "perimeter": p.perimeter(),
        "bbox": [lo, hi],
    })
}

fn extract(a: ExtractArgs, json: bool) -> anyhow::Result<i32> {
    let view: View = a.view.parse()?;
    if a.resolution == 0 || a.resolution > MAX_RESOLUTION {
        bail!(
            "--resolution must be between 1 and {MAX_RESOLUTION}, got {}",
            a.resolution
        );
    }
    let ext = a.output.extension().and_then(|e| e.to_str()).unwrap_or("");
    if !ext.eq_ignore_ascii_case("svg") {
        bail!("{}: the output must be an .svg file", a.output.display());
    }
    super::outputs::check(&[("MESH", &a.mesh)], &[("-o", &a.output)])?;
    let mesh = io::read(&a.mesh)?;
    let opts = OutlineOptions {
        resolution: a.resolution,
        ..OutlineOptions::default()
    };
    let p = outline_of_mesh(&mesh, view, &opts)
        .with_context(|| format!("{}: {view} outline", a.mesh.display()))?;
    write_svg(&a.output, &[&p])?;
    eprintln!(
        "wrote {}: {view} outline, {} points, width {:.6}, height {:.6}, area {:.6}",
        a.output.display(),
        p.len(),
        p.width(),
        p.height(),
        p.area()
    );
    if json {
        let mut v = summary(&p);
        v["output"] = serde_json::json!(a.output);
        v["resolution"] = serde_json::json!(a.resolution);
        super::print_json(&v)?;
    }
    Ok(0)
}

fn check(a: CheckArgs, json: bool) -> anyhow::Result<i32> {
    let view: View = a.view.parse()?;
    let is_json = a
        .sketch
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let (p, cuts) = if is_json {
        let p = read_json(&a.sketch)?;
        if p.view() != view {
            bail!(
                "{}: the sketch is a {} profile, --view says {view}",
                a.sketch.display(),
                p.view()
            );
        }
        (p, Vec::new())
    } else {
        let s = read_svg(&a.sketch, view, a.tolerance)
            .with_context(|| a.sketch.display().to_string())?;
        (s.outline, s.cuts)
    };
    eprintln!(
        "{}: valid {view} profile, {} points, width {:.6}, height {:.6}, area {:.6}, {} cuts",
        a.sketch.display(),
        p.len(),
        p.width(),
        p.height(),
        p.area(),
        cuts.len()
    );
    if json {
        let mut v = summary(&p);
        v["cuts"] = serde_json::json!(cuts);
        super::print_json(&v)?;
    }
    Ok(0)
}
