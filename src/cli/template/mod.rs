//! `pdesculpt template fit`: template-based global modeling (000 sec 4.2);
//! `pdesculpt template tbsm`: template-based shape manipulation (sec 5.4,
//! [`tbsm`]).
//!
//! `template fit --template makehuman|MESH --front F.svg [--side S.svg]
//! [--sections SECTIONS.json] -o OUT`: writes the deformed template (every
//! vertex and face in the template's order) and reports the profile error
//! per view, the RBF centres and condition per level, and the time.

use anyhow::Context;
use pdesculpt::mesh::io;
use pdesculpt::profile::{read_json, read_svg_with, Flatness, View};
use pdesculpt::template::measure::{mesh_outline, profile_errors, ViewError};
use pdesculpt::template::sections::SectionSketch;
use pdesculpt::template::study::makehuman_template;
use pdesculpt::template::{fit, FitOptions, LevelReport, OnMiss, Sketch, Template};
use std::path::{Path, PathBuf};

mod tbsm;

const FORMATS: &str = "\
SECTIONS.json: {\"sections\": [{\"y\": 10.4, \"loops\": [[[x, z], ...], ...]}, ...]}:
  key cross-sections at heights y, each loop a closed polyline in the
  horizontal plane (model x, z); loops are GEC-fitted (10 terms).
Sketches: SVG (see `pdesculpt profile --help`) or JSON profiles.";

/// Arguments of `pdesculpt template`.
#[derive(clap::Args, Debug)]
#[command(after_long_help = FORMATS)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Deform a template so its profiles fit sketched ones (low, medium, high level).
    #[command(after_long_help = FORMATS)]
    Fit(FitArgs),
    /// Template-based shape manipulation (sec 5.4, Fig 11): replace a part's
    /// elliptic sections by a template part's, or create a part from a profile.
    #[command(subcommand)]
    Tbsm(tbsm::TbsmCommand),
}

#[derive(clap::Args, Debug)]
pub struct FitArgs {
    /// `makehuman` (the bundled base body, every OBJ vertex) or a mesh file
    /// (.obj, .glb, .gltf, .stl, .ply).
    #[arg(long)]
    pub template: String,
    /// Front profile (SVG or JSON); a page holding both views reads its
    /// layer labelled front.
    #[arg(long)]
    pub front: PathBuf,
    /// Side profile (SVG or JSON): medium level. Default: the front's
    /// page, when it has a layer labelled side.
    #[arg(long)]
    pub side: Option<PathBuf>,
    /// Key cross-sections (JSON): high level (needs --side).
    #[arg(long)]
    pub sections: Option<PathBuf>,
    /// Output mesh (.obj, .glb, .gltf, .stl, .ply).
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    pub layout: super::units::LayoutArgs,
    /// Refuse (an error, no output) when a fitted profile stays farther
    /// than 0.5 % of the height from the sketch. Default: write the best
    /// fit, warn with the measured miss on stderr (and `within: false` in
    /// --json) and exit 0.
    #[arg(long)]
    pub strict: bool,
    /// The default since `--strict` exists (kept so scripts keep working).
    #[arg(long, hide = true)]
    pub accept_miss: bool,
    /// The character's height (`1.75m`, `175cm`, `1750mm`): the drawings
    /// are scaled uniformly to it. Default: the drawings' physical size.
    #[arg(long, value_parser = crate::cli::sketch::parse_height)]
    pub height: Option<f64>,
}

#[derive(serde::Serialize)]
struct Report {
    output: String,
    /// The written mesh's unit (always metres).
    unit: &'static str,
    /// The model's height in metres (the placed front drawing's).
    height_m: f64,
    /// The drawings' size and placement (as `sketch build` reports it).
    drawing: pdesculpt::sketch::place::DrawingReport,
    /// Placement warnings (side height scaled).
    warnings: Vec<String>,
    vertices: usize,
    levels: Vec<LevelReport>,
    profile_errors: Vec<ViewError>,
    seconds: f64,
}

/// A drawing at its physical size in metres (SVG: the document's size;
/// JSON: metres), as `sketch build` reads it.
fn profile(path: &Path, view: View) -> anyhow::Result<pdesculpt::sketch::input::Outline> {
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"))
    {
        let p = read_json(path)?;
        return Ok(pdesculpt::sketch::input::Outline {
            profile: p,
            cuts: Vec::new(),
            units: None,
        });
    }
    let flat = Flatness::OfHeight(pdesculpt::sketch::input::DEFAULT_FLATNESS);
    let s = read_svg_with(path, view, flat)?.into_metres()?;
    Ok(pdesculpt::sketch::input::Outline {
        profile: s.outline,
        cuts: Vec::new(),
        units: Some(s.units),
    })
}

/// Runs a `template` subcommand.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Command::Fit(a) => run_fit(a, json),
        Command::Tbsm(c) => tbsm::run(c, json),
    }
}

fn run_fit(mut a: FitArgs, json: bool) -> anyhow::Result<i32> {
    let t0 = std::time::Instant::now();
    a.side = crate::cli::sketch::side_or_page(&a.front, a.side.take());
    io::Format::from_path(&a.output)?;
    let mut inputs: Vec<(&str, &Path)> = vec![("--front", &a.front)];
    if a.template != "makehuman" {
        inputs.push(("--template", Path::new(&a.template)));
    }
    if let Some(p) = &a.side {
        inputs.push(("--side", p));
    }
    if let Some(p) = &a.sections {
        inputs.push(("--sections", p));
    }
    super::outputs::check(&inputs, &[("-o", &a.output)])?;
    let template: Template = if a.template == "makehuman" {
        makehuman_template(&[])?
    } else {
        let m = io::read(Path::new(&a.template))?;
        Template::whole(m)
    };
    let front = profile(&a.front, View::Front).context("front profile")?;
    let side = match &a.side {
        Some(s) => Some(profile(s, View::Side).context("side profile")?),
        None => None,
    };
    // the same size and placement as `sketch build` (the template's unit:
    // MakeHuman is decimetres, a mesh file metres)
    let placed =
        pdesculpt::sketch::place::place(&front, side.as_ref(), a.height, Default::default())?;
    for w in &placed.warnings {
        eprintln!("warning: {w}");
    }
    let sketch = template_sketch(&a, &placed)?;
    let mut opts = FitOptions::default();
    opts.on_miss = if a.strict {
        OnMiss::Fail
    } else {
        OnMiss::Report
    };
    let progress = pdesculpt::progress::Progress::spinner("template fit", json);
    let r = fit(&template, &sketch, &opts, &mesh_outline)?;
    progress.finish();
    let errors = profile_errors(&template, r.last(), &sketch)?;
    let mut out = template.mesh.clone();
    out.positions = r.last().to_vec();
    // the fitted mesh is in the template's unit; written in metres
    let k = if a.template == "makehuman" {
        pdesculpt::mesh::unit::MAKEHUMAN.metres()
    } else {
        1.0
    };
    let mut metres = out.clone();
    for p in &mut metres.positions {
        *p = [k * p[0], k * p[1], k * p[2]];
    }
    a.layout.write(&metres, &a.output)?;
    let report = Report {
        output: a.output.display().to_string(),
        unit: "m",
        height_m: placed.report.height_m,
        drawing: placed.report.clone(),
        warnings: placed.warnings.clone(),
        vertices: out.positions.len(),
        levels: r.levels.iter().map(|(l, _)| l.clone()).collect(),
        profile_errors: errors,
        seconds: t0.elapsed().as_secs_f64(),
    };
    print_report(&report, &opts, json)?;
    Ok(0)
}

/// The placed drawings in the template's unit (MakeHuman's decimetres, a
/// mesh file's metres), with the key sections of `--sections`.
fn template_sketch(
    a: &FitArgs,
    placed: &pdesculpt::sketch::place::Placed,
) -> anyhow::Result<Sketch> {
    let k = if a.template == "makehuman" {
        1.0 / pdesculpt::mesh::unit::MAKEHUMAN.metres()
    } else {
        1.0
    };
    let to_template = |o: &pdesculpt::sketch::input::Outline| -> Vec<[f64; 2]> {
        o.points().iter().map(|p| [k * p[0], k * p[1]]).collect()
    };
    let mut sketch = Sketch {
        front: to_template(&placed.front),
        ..Default::default()
    };
    sketch.side = placed.side.as_ref().map(to_template);
    if let Some(s) = &a.sections {
        let text = io::read_input_text(s, "sections file")?;
        #[derive(serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        struct File {
            sections: Vec<SectionSketch>,
        }
        let f: File = serde_json::from_str(&text)
            .with_context(|| format!("{}: invalid sections JSON", s.display()))?;
        sketch.sections = f.sections;
    }
    Ok(sketch)
}

/// The fit's warnings, then its report: JSON on stdout, or text on
/// stderr.
fn print_report(report: &Report, opts: &FitOptions, json: bool) -> anyhow::Result<()> {
    for l in &report.levels {
        for v in l.profiles.iter().filter(|v| !v.within) {
            eprintln!(
                "warning: {} level: {} profile {:.2} % of the height off the sketch (tolerance {:.2} %): the best fit is written (--strict refuses)",
                l.level.name(),
                v.view.name(),
                100.0 * v.max_rel,
                100.0 * opts.tolerance
            );
        }
    }
    if json {
        super::print_json(&report)?;
    } else {
        for l in &report.levels {
            eprintln!(
                "{}: {} centres, {} correction passes, condition {}, residual {:.1e}, max move {:.4}, {:.2} s",
                l.level.name(),
                l.centres,
                l.passes,
                l.condition.map_or("-".into(), |c| format!("{c:.3e}")),
                l.residual,
                l.max_displacement,
                l.seconds
            );
        }
        for e in &report.profile_errors {
            eprintln!(
                "{} profile: max {:.4} ({:.2} % of height), rms {:.4}",
                e.view.name(),
                e.distance.max,
                100.0 * e.distance.max_rel,
                e.distance.rms
            );
        }
        eprintln!(
            "wrote {} ({} vertices) in {:.2} s",
            report.output, report.vertices, report.seconds
        );
    }
    Ok(())
}
