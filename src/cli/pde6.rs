//! `pdesculpt pde6`: sixth-order PDE patches from cross sections (paper 002).
//!
//! * `pde6 patch CURVES.json [--a A] [--method global|method1|method2] -o OUT`
//!   (CURVES.json: the `patch` help below and `pdesculpt::pde6::input`)
//! * `pde6 body [--mesh BODY.obj | --morph NAME=W ...] -o OUT [--terms J] [--a A] [--anchors K] [--pull P]`:
//!   one closed body; `--open-parts [--method ...] [--sampling ...]`: the seven open parts
//! * `pde6 mode --a A --n N --values w0,...,w5 --at u`
//!
//! A short summary goes to stderr; with the global `--json` the report goes
//! to stdout.

use anyhow::bail;
use pdesculpt::body::closed::ClosedOptions;
use pdesculpt::body::parts::{reconstruct_base_parts, sampling_from_name, BodyOptions};
use pdesculpt::body::reconstruct_closed_from;
use pdesculpt::limits;
use pdesculpt::pde6::Method;
use pdesculpt::surface::{tessellate, Tessellation};
use std::path::PathBuf;

/// Arguments of `pdesculpt pde6`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
}

/// How neighbouring patches are joined.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum MethodArg {
    /// All patches solved together, C2, stable (default).
    Global,
    /// Paper method 1: windows of six sections sharing three (C0 only).
    Method1,
    /// Paper method 2: slope and curvature carried over (C2, unstable growth).
    Method2,
}

impl MethodArg {
    fn method(self) -> Method {
        match self {
            MethodArg::Global => Method::GlobalC2,
            MethodArg::Method1 => Method::SharedCurves,
            MethodArg::Method2 => Method::CarriedDerivatives,
        }
    }
}

#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// A patch chain through the sections of a JSON file, tessellated.
    ///
    /// CURVES.json: {"sections": [{"u": 0.0, "gec": GEC}, {"u": 1.0, "fourier":
    /// FOURIER3}, ...]}: u strictly increasing; GEC = {"frame": {"origin":
    /// [x,y,z], "e1": [..], "e2": [..]}, "centre": [x0, y0], "x": [[a_x1, b_x1],
    /// ..], "y": [[a_y1, b_y1], ..]} (paper 002 eq 1; the frame origin gives
    /// the z position, e.g. origin [0, 0, z_c] with e1 = X, e2 = Y);
    /// FOURIER3 = {"c0": [..], "cos": [[..], ..], "sin": [[..], ..]}. All
    /// sections need the same J. Sections: global 7 + 3k, method1/method2 6 + 3k.
    Patch {
        /// The sections JSON (format above).
        curves: PathBuf,
        /// PDE parameter a of eq 2 (|a| <= 10).
        #[arg(long, default_value_t = -0.5, allow_hyphen_values = true)]
        a: f64,
        #[arg(long, value_enum, default_value_t = MethodArg::Global)]
        method: MethodArg,
        /// Method 1 and 2: index of the centre patch's first section (multiple of 3).
        #[arg(long, default_value_t = 0)]
        first: usize,
        /// Tessellation: intervals per piece in u, and around v.
        #[arg(long, default_value_t = 16)]
        nu: usize,
        #[arg(long, default_value_t = 64)]
        nv: usize,
        /// Output mesh (obj, glb, stl, ply).
        #[arg(short, long)]
        output: PathBuf,
        #[command(flatten)]
        units: super::units::UnitArgs,
    },
    /// Reconstructs one closed body from cross sections (MakeHuman base body,
    /// a morph of it, or --mesh BODY.obj: a standing humanoid, Y up).
    Body {
        /// The body to reconstruct (obj, stl, ply, glb); default the bundled MakeHuman body.
        #[arg(long)]
        mesh: Option<PathBuf>,
        /// MakeHuman morph targets applied to the bundled body: NAME=WEIGHT (repeatable).
        #[arg(long)]
        morph: Vec<String>,
        /// The seven separate open parts of paper 002 instead of the closed body.
        #[arg(long)]
        open_parts: bool,
        #[arg(long, default_value_t = 10)]
        terms: usize,
        /// PDE parameter a (small |a| keeps the top harmonics from rippling between sections).
        #[arg(long, default_value_t = pdesculpt::body::parts::BODY_A, allow_hyphen_values = true)]
        a: f64,
        #[arg(long, value_enum, default_value_t = MethodArg::Global)]
        method: MethodArg,
        /// How section points get their angle: anchored (rays from the
        /// centroid, arc length between them; default) or a GEC fit rule
        /// (chord, centripetal, uniform, polar; start at the first sliced vertex).
        #[arg(long, default_value = "anchored")]
        sampling: String,
        /// Anchored sampling: number of rays.
        #[arg(long, default_value_t = pdesculpt::body::parts::DEFAULT_ANCHORS)]
        anchors: usize,
        /// Anchored sampling: how hard the rays pin theta (0 = arc length from
        /// the +z ray, 1 = ray k at exactly 2 pi k / K).
        #[arg(long, default_value_t = pdesculpt::body::parts::DEFAULT_PULL)]
        pull: f64,
        /// Output mesh (obj, glb, stl, ply).
        #[arg(short, long)]
        output: PathBuf,
        #[command(flatten)]
        units: super::units::OutputUnitArgs,
    },
    /// The single-harmonic function A_n(u) through six values at u = 0, 0.2, ..., 1.
    Mode {
        #[arg(long, allow_hyphen_values = true)]
        a: f64,
        #[arg(long)]
        n: usize,
        /// Six comma-separated values.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        values: Vec<f64>,
        #[arg(long, allow_hyphen_values = true)]
        at: f64,
    },
}

/// Runs `pdesculpt pde6`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Command::Patch {
            curves,
            a,
            method,
            first,
            nu,
            nv,
            output,
            units,
        } => {
            limits::check("--nu", nu, limits::TESS_NU)?;
            limits::check("--nv", nv, limits::TESS_NV)?;
            pdesculpt::mesh::io::Format::from_path(&output)?;
            pdesculpt::mesh::io::refuse_overwriting_input(&[&curves], &output)?;
            let sections = pdesculpt::pde6::input::read_sections(&curves)?;
            let chain = pdesculpt::pde6::input::build_chain(a, method.method(), &sections, first)?;
            let nu_total = limits::mul("--nu", nu, chain.pieces.len())?;
            limits::mesh_vertices("--nu/--nv", nu_total, nv)?;
            let mesh = tessellate(&chain, Tessellation { nu: nu_total, nv });
            if mesh.positions.iter().flatten().any(|x| !x.is_finite()) {
                bail!("the surface has non-finite points");
            }
            let unit = units.write_input(&mesh, &output)?;
            let (mut summary, line) =
                pdesculpt::pde6::input::patch_summary(&chain, sections.len(), &mesh, a, &output);
            summary["unit"] = serde_json::json!(unit);
            emit(json, &summary, &format!("{line}\n"))
        }
        Command::Body {
            mesh,
            morph,
            open_parts,
            terms,
            a,
            method,
            sampling,
            anchors,
            pull,
            output,
            units,
        } => {
            limits::check("--terms", terms, limits::BODY_TERMS)?;
            limits::check("--anchors", anchors, limits::BODY_ANCHORS)?;
            pdesculpt::mesh::io::Format::from_path(&output)?;
            let sampling = sampling_from_name(&sampling, anchors, pull)?;
            if !open_parts {
                let opts = ClosedOptions::default()
                    .with_terms(terms)
                    .with_a(a)
                    .with_anchors(anchors)
                    .with_pull(pull);
                return body_closed(mesh, &morph, &opts, &output, units, json);
            }
            eprintln!("pde6 body: slicing, fitting and solving the open parts");
            let opts = BodyOptions::default()
                .with_terms(terms)
                .with_a(a)
                .with_method(method.method())
                .with_sampling(sampling);
            let progress = pdesculpt::progress::Progress::spinner("pde6 body", json);
            let (mesh, report) = reconstruct_base_parts(&opts)?;
            progress.finish();
            let unit = units.write(&mesh, &output, pdesculpt::mesh::unit::MAKEHUMAN)?;
            let mut out = serde_json::to_value(&report)?;
            out["unit"] = serde_json::json!(unit);
            out["report_unit"] = serde_json::json!(pdesculpt::mesh::unit::MAKEHUMAN);
            let line = pdesculpt::body::parts::open_parts_summary(&report, &output);
            emit(json, &out, &line)
        }
        Command::Mode { a, n, values, at } => {
            let (out, line) = pdesculpt::pde6::input::mode_at(a, n, &values, at)?;
            if json {
                super::print_json(&out)?;
            } else {
                println!("{line}");
            }
            Ok(0)
        }
    }
}

fn body_closed(
    mesh: Option<PathBuf>,
    morph: &[String],
    opts: &ClosedOptions,
    output: &std::path::Path,
    units: super::units::OutputUnitArgs,
    json: bool,
) -> anyhow::Result<i32> {
    eprintln!("pde6 body: finding the layout, tracing, fitting and joining the parts");
    let progress = pdesculpt::progress::Progress::spinner("pde6 body", json);
    let b = reconstruct_closed_from(mesh.as_deref(), morph, output, opts)?;
    progress.finish();
    let unit = units.write(&b.model.mesh, output, pdesculpt::mesh::unit::MAKEHUMAN)?;
    let r = &b.report;
    for arm in &r.thumbless {
        eprintln!("pde6 body: warning: no thumb, the hand is a mitten ({arm})");
    }
    let mut out = serde_json::to_value(r)?;
    out["unit"] = serde_json::json!(unit);
    emit(json, &out, &r.summary(output))
}

/// The JSON report on stdout with `--json`, else the summary on stderr.
fn emit(json: bool, report: &serde_json::Value, summary: &str) -> anyhow::Result<i32> {
    if json {
        super::print_json(report)?;
    } else {
        eprint!("{summary}");
    }
    Ok(0)
}
