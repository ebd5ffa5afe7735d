//! `pdesculpt template tbsm`: template-based shape manipulation (000 sec
//! 5.4, Fig 11).
//!
//! - `tbsm replace DOC.json --part NAME -o OUT.json`: the part's elliptic
//!   (or round) key sections are replaced by the template part's real
//!   sections at the same normalised position, scaled to each ellipse and
//!   GEC-fitted; `u`, centres and frames are kept (Fig 11b).
//! - `tbsm create --profile P.svg -o OUT.obj`: the template part's mesh
//!   warped so its front (or side, `--view side`) outline is the sketched
//!   profile (Fig 11a).
//!
//! The template part is MakeHuman's left foot (`makehuman-foot`, the only
//! bundled part) or a mesh with an axis (`--axis`).

use anyhow::{bail, Context};
use pdesculpt::character::doc::CharacterDoc;
use pdesculpt::mesh::io;
use pdesculpt::mesh::Mesh;
use pdesculpt::profile::View;
use pdesculpt::template::measure::mesh_outline;
use pdesculpt::template::tbsm::{
    makehuman_foot_part, part_from_view, replace_in_doc, TemplatePart,
};
use std::path::PathBuf;

/// `template tbsm` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum TbsmCommand {
    /// Replace a part's elliptic sections by the template part's sections (Fig 11b).
    Replace(ReplaceArgs),
    /// Create a part mesh from a sketched front or side profile by correspondence with the template part (Fig 11a).
    Create(CreateArgs),
}

/// Where the template part comes from.
#[derive(clap::Args, Debug)]
pub struct PartSource {
    /// `makehuman-foot` (MakeHuman's left foot, heel to toe) or a mesh file
    /// (needs --axis).
    #[arg(long, default_value = "makehuman-foot")]
    pub template: String,
    /// Axis of a mesh template: `X0,Y0,Z0,X1,Y1,Z1` (start to end).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub axis: Option<Vec<f64>>,
    /// Direction of the sections' first axis for a mesh template: `X,Y,Z`
    /// (default 1,0,0; makehuman-foot has its own frame and refuses it).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub e1: Option<Vec<f64>>,
    /// Template sections (2 to 64).
    #[arg(long, default_value_t = 6)]
    pub template_sections: usize,
}

#[derive(clap::Args, Debug)]
pub struct ReplaceArgs {
    /// Character document (JSON, see `pdesculpt character --help`).
    pub doc: PathBuf,
    /// Name of the part whose sections are replaced.
    #[arg(long)]
    pub part: String,
    #[command(flatten)]
    pub source: PartSource,
    /// GEC terms of the new sections (1 to 40).
    #[arg(long, default_value_t = 10)]
    pub terms: usize,
    /// Output document (may be DOC itself).
    #[arg(short, long)]
    pub output: PathBuf,
}

#[derive(clap::Args, Debug)]
pub struct CreateArgs {
    /// Sketched profile of the new part (SVG or JSON).
    #[arg(long)]
    pub profile: PathBuf,
    /// The profile's view: `front` (model x, y) or `side` (model z, y).
    #[arg(long, default_value = "front")]
    pub view: String,
    #[command(flatten)]
    pub source: PartSource,
    /// Output mesh (.obj, .glb, .stl, .ply).
    #[arg(short, long)]
    pub output: PathBuf,
}

fn template_part(s: &PartSource) -> anyhow::Result<(TemplatePart, Mesh)> {
    if !(2..=64).contains(&s.template_sections) {
        bail!(
            "--template-sections must be 2 to 64, got {}",
            s.template_sections
        );
    }
    if s.template == "makehuman-foot" {
        if s.axis.is_some() {
            bail!("--axis is for a mesh template, not makehuman-foot");
        }
        if s.e1.is_some() {
            bail!("--e1 is for a mesh template, not makehuman-foot (its sections' frame is the foot's own)");
        }
        return Ok(makehuman_foot_part(s.template_sections)?);
    }
    let mesh = io::read(std::path::Path::new(&s.template))
        .with_context(|| format!("template part {}", s.template))?;
    let Some(a) = &s.axis else {
        bail!("a mesh template needs --axis X0,Y0,Z0,X1,Y1,Z1");
    };
    if a.len() != 6 {
        bail!("--axis takes 6 numbers X0,Y0,Z0,X1,Y1,Z1, got {}", a.len());
    }
    let e1 = s.e1.clone().unwrap_or_else(|| vec![1.0, 0.0, 0.0]);
    if e1.len() != 3 {
        bail!("--e1 takes 3 numbers X,Y,Z, got {}", e1.len());
    }
    if a.iter().chain(&e1).any(|v| !v.is_finite()) {
        bail!("--axis and --e1 must be finite numbers");
    }
    let part = TemplatePart::from_mesh(
        &mesh,
        [a[0], a[1], a[2]],
        [a[3], a[4], a[5]],
        [e1[0], e1[1], e1[2]],
        (0.05, 0.95, s.template_sections),
    )?;
    Ok((part, mesh))
}

#[derive(serde::Serialize)]
struct ReplaceReport {
    output: String,
    part: String,
    sections: usize,
    replaced: usize,
    template_sections: usize,
    seconds: f64,
}

#[derive(serde::Serialize)]
struct CreateReport {
    output: String,
    vertices: usize,
    triangles: usize,
    seconds: f64,
}

/// Runs a `template tbsm` subcommand.
pub fn run(cmd: TbsmCommand, json: bool) -> anyhow::Result<i32> {
    let t0 = std::time::Instant::now();
    match cmd {
        TbsmCommand::Replace(a) => {
            if !(1..=40).contains(&a.terms) {
                bail!("--terms must be 1 to 40, got {}", a.terms);
            }
            super::super::outputs::doc_output("-o", &a.output)?;
            // the output may be DOC itself (updated in place); never the
            // template mesh
            let mut inputs: Vec<(&str, &std::path::Path)> = Vec::new();
            if a.source.template != "makehuman-foot" {
                inputs.push(("--template", std::path::Path::new(&a.source.template)));
            }
            super::super::outputs::check(&inputs, &[("-o", &a.output)])?;
            let mut doc = CharacterDoc::load(&a.doc)?;
            let (part, _) = template_part(&a.source)?;
            let replaced = replace_in_doc(&mut doc, &a.part, &part, a.terms)?;
            doc.save(&a.output)?;
            let sections = doc
                .parts()
                .iter()
                .find(|p| p.name == a.part)
                .map_or(0, |p| p.sections.len());
            let rep = ReplaceReport {
                output: a.output.display().to_string(),
                part: a.part,
                sections,
                replaced,
                template_sections: part.sections.len(),
                seconds: t0.elapsed().as_secs_f64(),
            };
            if json {
                super::super::print_json(&rep)?;
            } else {
                eprintln!(
                    "part '{}': {} of {} sections replaced by the template's ({} template sections); wrote {} in {:.2} s",
                    rep.part, rep.replaced, rep.sections, rep.template_sections, rep.output, rep.seconds
                );
            }
        }
        TbsmCommand::Create(a) => {
            io::Format::from_path(&a.output)?;
            let mut inputs: Vec<(&str, &std::path::Path)> = vec![("--profile", &a.profile)];
            if a.source.template != "makehuman-foot" {
                inputs.push(("--template", std::path::Path::new(&a.source.template)));
            }
            super::super::outputs::check(&inputs, &[("-o", &a.output)])?;
            let view = match a.view.as_str() {
                "front" => View::Front,
                "side" => View::Side,
                v => bail!("--view must be front or side, got '{v}'"),
            };
            // the part's drawing at its physical size (metres), not
            // placed: a part is drawn where it sits; in the template's unit
            let profile = super::profile(&a.profile, view).context("part profile")?;
            let source = if a.source.template == "makehuman-foot" {
                pdesculpt::mesh::unit::MAKEHUMAN
            } else {
                pdesculpt::mesh::unit::Unit::M
            };
            let k = 1.0 / source.metres();
            let pts: Vec<[f64; 2]> = profile
                .points()
                .iter()
                .map(|p| [k * p[0], k * p[1]])
                .collect();
            let (_, mut mesh) = template_part(&a.source)?;
            mesh.positions = part_from_view(&mesh, &pts, view, &mesh_outline)?;
            io::write_in_unit(&mesh, &a.output, source, pdesculpt::mesh::unit::Unit::M)?;
            let rep = CreateReport {
                output: a.output.display().to_string(),
                vertices: mesh.positions.len(),
                triangles: mesh.triangles.len(),
                seconds: t0.elapsed().as_secs_f64(),
            };
            if json {
                super::super::print_json(&rep)?;
            } else {
                eprintln!(
                    "wrote {} ({} vertices, {} triangles) in {:.2} s",
                    rep.output, rep.vertices, rep.triangles, rep.seconds
                );
            }
        }
    }
    Ok(0)
}
