//! `pdesculpt profile`: outlines of a view.
//!
//! * `profile extract MESH --view front|side|top -o OUT.svg [--resolution N]
//!   [--group NAME]...`
//! * `profile check SKETCH.svg|SKETCH.json --view V [--tolerance T]`: sizes
//!   in metres (the drawing's physical size; JSON sketches are metres)
//!
//! With the global `--json` the report goes to stdout as JSON; without it a
//! summary goes to stderr.

use anyhow::{bail, Context};
use pdesculpt::mesh::io;
use pdesculpt::profile::{
    outline_of_mesh, read_json, read_svg_with, write_svg, Flatness, OutlineOptions, Profile, View,
    MAX_RESOLUTION,
};
use pdesculpt::sketch::input::DEFAULT_FLATNESS;
use std::path::PathBuf;

const CONVENTIONS: &str = "\
CONVENTIONS (SVG files; the same for sketches read by other commands):
  A drawing has its document's physical size, in metres: the root width and
  height (mm, cm, in, pt, pc, px; a bare number is px = 1/96 in) over the
  viewBox give the length of one user unit (no viewBox, or no width and
  height: one user unit is one px); every transform on the way to a path
  (groups, transform attributes, nested svg) is applied.
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
    /// Unit of the mesh's coordinates: m, dm, cm or mm (the SVG page is
    /// sized so that it reads back at the mesh's physical size).
    #[arg(long, default_value = "m")]
    pub input_unit: pdesculpt::mesh::unit::Unit,
    /// Pixels along the larger extent of the projection (accuracy: the
    /// outline is within one pixel of the exact one), at most 8192.
    #[arg(long, default_value_t = OutlineOptions::default().resolution)]
    pub resolution: usize,
    /// Outline only the triangles of this OBJ group (repeat for several;
    /// default: all). MakeHuman's `base.obj` needs `--group body`: its other
    /// groups are hidden helpers (a skirt, tights, hair, joints).
    #[arg(long = "group", value_name = "NAME")]
    pub groups: Vec<String>,
}

#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// Sketch file (.svg, or .json).
    pub sketch: PathBuf,
    /// View the sketch is drawn in: front, side or top.
    #[arg(long)]
    pub view: String,
    /// Curve flattening tolerance in metres of the drawing's physical size
    /// (default: 1/1000 of the drawing's height).
    #[arg(long)]
    pub tolerance: Option<f64>,
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
    let mesh = select_groups(io::read(&a.mesh)?, &a.groups)
        .with_context(|| format!("{}", a.mesh.display()))?;
    let opts = OutlineOptions::default().resolution(a.resolution);
    let p = outline_of_mesh(&mesh, view, &opts)
        .with_context(|| format!("{}: {view} outline", a.mesh.display()))?;
    write_svg(&a.output, &[&p], a.input_unit.metres())?;
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

/// The triangles of the named groups (all of the mesh when none is named;
/// then a mesh of several groups gets a note on stderr naming them).
fn select_groups(
    mesh: pdesculpt::mesh::Mesh,
    names: &[String],
) -> anyhow::Result<pdesculpt::mesh::Mesh> {
    if names.is_empty() {
        if mesh.groups.len() > 1 {
            eprintln!(
                "note: outlining all {} groups of the mesh; pass --group NAME to outline only some ({})",
                mesh.groups.len(),
                abbreviate(&mesh.groups)
            );
        }
        return Ok(mesh);
    }
    let mut wanted = Vec::new();
    for n in names {
        let Some(g) = mesh.groups.iter().position(|x| x == n) else {
            bail!(
                "no group '{n}' in the mesh; its groups: {}",
                abbreviate(&mesh.groups)
            );
        };
        wanted.push(g as u32);
    }
    let keep: Vec<bool> = mesh.tri_group.iter().map(|g| wanted.contains(g)).collect();
    if !keep.contains(&true) {
        bail!("the groups {} have no triangles", names.join(", "));
    }
    Ok(mesh.filter_triangles(&keep).0)
}

/// At most eight names, then how many more.
fn abbreviate(names: &[String]) -> String {
    let shown: Vec<&str> = names.iter().take(8).map(String::as_str).collect();
    match names.len().saturating_sub(8) {
        0 => shown.join(", "),
        more => format!("{}, and {more} more", shown.join(", ")),
    }
}

fn check(a: CheckArgs, json: bool) -> anyhow::Result<i32> {
    let view: View = a.view.parse()?;
    let is_json = a
        .sketch
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let mut units = None;
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
        let flat = match a.tolerance {
            Some(t) => Flatness::Metres(t),
            None => Flatness::OfHeight(DEFAULT_FLATNESS),
        };
        let s = read_svg_with(&a.sketch, view, flat)
            .and_then(|s| s.into_metres())
            .with_context(|| a.sketch.display().to_string())?;
        units = Some(s.units);
        (s.outline, s.cuts)
    };
    eprintln!(
        "{}: valid {view} profile, {} points, width {:.6} m, height {:.6} m, area {:.6} m^2, {} cuts{}",
        a.sketch.display(),
        p.len(),
        p.width(),
        p.height(),
        p.area(),
        cuts.len(),
        units
            .as_ref()
            .map_or(String::new(), |u| format!("; document unit {} ({})", u.unit, u.rule))
    );
    if json {
        let mut v = summary(&p);
        v["cuts"] = serde_json::json!(cuts);
        v["unit"] = serde_json::json!("m");
        v["height_m"] = serde_json::json!(p.height());
        v["document"] = serde_json::json!(units);
        super::print_json(&v)?;
    }
    Ok(0)
}
