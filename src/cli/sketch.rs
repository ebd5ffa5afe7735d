//! `pdesculpt sketch build --front F.svg [--side S.svg] [--sections S.json]
//! [--level L] -o OUT [--save-doc CHAR.json] [--json]`.

use pdesculpt::character::doc::{BodyPlan, CharacterDoc, Inputs, KeySection, Level, ProfileInput};
use pdesculpt::character::Resolution;
use pdesculpt::mesh::io;
use pdesculpt::pipeline::{build_document, Built};
use std::path::{Path, PathBuf};

const CONVENTIONS: &str = "Input conventions: the model is the drawing's physical size in metres: \
the SVG root's width and height (mm, cm, in, pt, pc, px; a bare number is px = 1/96 in) over its \
viewBox give one user unit's length (no viewBox, or no width and height: one px), every transform \
on the way to a path is applied; --height 1.75m (175cm, 1750mm) scales the model uniformly to a \
height instead. JSON profiles are metres. SVG y points down and model y up; in a front view svg x \
is model x, in a side view svg x is model z (the front of the body at +z). Each view is placed by \
its own outline, wherever it sits on the page: its lowest point at y = 0, the front's torso axis at \
x = 0, the side's torso centred at z = 0; a side view whose height differs from the front's by at \
most 5 % is scaled to it with a warning, more is an error; a humanoid side view deeper than it is tall is an error. Each SVG holds one closed path for the \
outline (any path commands, flattened with --tolerance, at most 1 % of the drawing's height); extra paths whose id starts with \
`cut` are explicit part boundaries: drawn across an arm (below the armpit), a leg (below the crotch) \
or the neck, a cut places that join at its mean height. A .json profile is [[x, y], ...] or {\"points\": [...]}. Automatic \
segmentation expects a standing humanoid seen from the front, arms away from the body and legs apart \
(parts torso, head, arm_l, arm_r, leg_l, leg_r; _l is negative x); a drawing up to 12 degrees off \
upright is segmented about the principal axis of its thick core (limbs weigh little, so one raised arm \
is not a tilt). With a side view, a foot drawn in it turns each leg at the ankle: the leg's sections \
follow the foot to the toe. A four-legged animal (--body-plan quadruped, or \
auto: an outline longer than tall) is drawn in the same files: the front file holds its lateral \
silhouette (model x-y, head toward +x or -x, legs apart: 2, or all 4 in a walking pose), the side file \
the animal seen head-on (model z-y, left and right legs apart in z); parts body, head (neck and head), \
tail, back (a domed back between tail and withers, when drawn), legs leg_fl/fr/bl/br (4: the outer \
leg of each pair is the near one, at +z) or leg_f/leg_b (2, or the 4 when the head-on view shows each pair apart); the head rises above the back or is level with it, \
a tail rises above the back or hangs from the rump and a trunk from the head (parts tail, trunk). \
SECTIONS.json is {\"sections\": [{\"part\": \"torso\", \"y\": 1.2, \
\"points\": [[x, z], ...]}]}: closed curves in the horizontal plane at height y, fitted by GECs at \
the final level.";

/// Arguments of `pdesculpt sketch`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: Sub,
}

/// Sketch subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Sub {
    /// Build a character from sketched profiles (paper 000 sec 4.1).
    #[command(after_help = CONVENTIONS)]
    Build(BuildArgs),
}

/// Arguments of `sketch build`.
#[derive(clap::Args, Debug)]
pub struct BuildArgs {
    /// Front (primary) profile: SVG or JSON polyline. A page holding both
    /// views reads its layer labelled front.
    #[arg(long)]
    pub front: PathBuf,
    /// Side (secondary) profile. Default: the front's page, when it has a
    /// layer labelled side.
    #[arg(long)]
    pub side: Option<PathBuf>,
    /// Key cross-section sketches (JSON).
    #[arg(long)]
    pub sections: Option<PathBuf>,
    /// initial | intermediate | final (default: the most the inputs allow).
    #[arg(long)]
    pub level: Option<Level>,
    /// SVG flattening tolerance in metres of the model (default: 1/1000 of
    /// the drawing's height).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// The model's height (`1.75m`, `175cm`, `1750mm`; a bare number is
    /// metres): the drawing is scaled uniformly to it. Default: the
    /// drawing's physical size.
    #[arg(long, value_parser = parse_height)]
    pub height: Option<f64>,
    /// auto | humanoid | quadruped: how the front outline is segmented
    /// (auto: a quadruped when the outline is longer than tall).
    #[arg(long, default_value = "auto")]
    pub body_plan: BodyPlan,
    /// Output mesh (.obj, .glb, .gltf, .stl, .ply): one node/object per
    /// part and transition.
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    pub layout: super::units::LayoutArgs,
    /// Also save the character document (with the derived parts).
    #[arg(long)]
    pub save_doc: Option<PathBuf>,
    /// Also write a picture (SVG) of where the model misses the drawing:
    /// per view, the drawn outline in red, the model's in blue, the
    /// largest miss circled.
    #[arg(long)]
    pub overlay: Option<PathBuf>,
}

/// A length with a unit (`m`, `dm`, `cm`, `mm`; bare: metres), in metres.
pub fn parse_height(s: &str) -> Result<f64, String> {
    let t = s.trim();
    let digits = t.trim_end_matches(|c: char| c.is_ascii_alphabetic());
    let unit = &t[digits.len()..];
    let x: f64 = digits
        .trim()
        .parse()
        .map_err(|_| format!("{s:?} is not a length (e.g. 1.75m, 175cm, 1750mm)"))?;
    let per = if unit.is_empty() {
        1.0
    } else {
        unit.parse::<pdesculpt::mesh::unit::Unit>()
            .map_err(|e| e.to_string())?
            .metres()
    };
    let m = x * per;
    if !(m.is_finite() && m > 0.0) {
        return Err(format!("{s:?}: a height must be positive and finite"));
    }
    Ok(m)
}

fn abs(p: &Path) -> anyhow::Result<String> {
    Ok(std::path::absolute(p)?.display().to_string())
}

/// The side view's file: `--side` when given, else the front's page when
/// it holds a layer labelled side (the drawing template's page, both
/// views on one page), said on stderr.
pub fn side_or_page(front: &Path, side: Option<PathBuf>) -> Option<PathBuf> {
    if side.is_some() {
        return side;
    }
    let views = pdesculpt::profile::page_views(front);
    if !views.contains(&pdesculpt::profile::View::Side) {
        return None;
    }
    eprintln!(
        "reading the side view from {}'s layer labelled side",
        front.display()
    );
    Some(front.to_path_buf())
}

/// Runs `sketch`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    let Sub::Build(mut a) = args.command;
    a.side = side_or_page(&a.front, a.side.take());
    io::Format::from_path(&a.output)?;
    let mut inputs: Vec<(&str, &Path)> = vec![("--front", &a.front)];
    if let Some(p) = &a.side {
        inputs.push(("--side", p));
    }
    if let Some(p) = &a.sections {
        inputs.push(("--sections", p));
    }
    let mut outs: Vec<(&str, &Path)> = vec![("-o", &a.output)];
    if let Some(p) = &a.save_doc {
        super::outputs::doc_output("--save-doc", p)?;
        outs.push(("--save-doc", p));
    }
    if let Some(p) = &a.overlay {
        super::outputs::svg_output("--overlay", p)?;
        outs.push(("--overlay", p));
    }
    super::outputs::check(&inputs, &outs)?;
    let sections: Vec<KeySection> = match &a.sections {
        Some(p) => {
            #[derive(serde::Deserialize)]
            #[serde(deny_unknown_fields)]
            struct File {
                sections: Vec<KeySection>,
            }
            let text = io::read_input_text(p, "sections file")?;
            serde_json::from_str::<File>(&text)
                .map_err(|e| anyhow::anyhow!("{}: not a sections file: {e}", p.display()))?
                .sections
        }
        None => Vec::new(),
    };
    // key sections are used at the final level only, which needs a side
    // profile: never drop them silently
    if !sections.is_empty() && a.side.is_none() {
        anyhow::bail!(
            "--sections are used at the final level, which also needs a side profile: give --side SIDE.svg"
        );
    }
    if !sections.is_empty() && a.level.is_some_and(|l| l != Level::Final) {
        eprintln!("note: --sections are kept in the document but used only at --level final");
    }
    let level = a.level.unwrap_or(match (&a.side, sections.is_empty()) {
        (None, _) => Level::Initial,
        (Some(_), true) => Level::Intermediate,
        (Some(_), false) => Level::Final,
    });
    let inputs = Inputs {
        front: ProfileInput::Path(abs(&a.front)?),
        side: a
            .side
            .as_deref()
            .map(abs)
            .transpose()?
            .map(ProfileInput::Path),
        sections,
        tolerance: a.tolerance,
        height: a.height,
        body_plan: a.body_plan,
    };
    let doc = CharacterDoc::from_inputs(inputs, level);
    let progress = pdesculpt::progress::Progress::spinner("sketch build", json);
    let built = build_document(&doc, Path::new("."), Resolution::default(), true)?;
    progress.finish();
    let with_doc = a.save_doc.as_deref().map(|p| (&built.doc, p));
    let overlay = a.overlay.as_deref().map(|p| (p, built.overlay_svg()));
    super::outputs::write_mesh_and_doc(
        &built.model.mesh,
        &a.output,
        a.layout.layout(),
        with_doc,
        overlay,
    )?;
    report(&built, &a.output, json)
}

/// Prints the report of a build written to `output` (shared with
/// `character build`).
pub fn report(built: &Built, output: &Path, json: bool) -> anyhow::Result<i32> {
    let r = &built.report;
    for w in &r.warnings {
        eprintln!("warning: {w}");
    }
    eprintln!(
        "wrote {} ({} vertices, {} triangles; watertight {}, manifold {}, oriented {}; max C1 jump {:.2e})",
        output.display(),
        r.topology.vertices,
        r.topology.triangles,
        r.topology.watertight,
        r.topology.manifold,
        r.topology.oriented,
        r.max_c1
    );
    eprintln!(
        "model height {:.4} m (drawn {:.4} m, document unit {})",
        r.height_m, r.drawing.drawn_height_m, r.drawing.document_unit
    );
    for p in &r.quality.whole.views {
        eprintln!(
            "profile error ({}): max {:.3} %, rms {:.3} % of height; outside the drawing {:.3} %",
            p.view,
            100.0 * p.max_rel,
            100.0 * p.rms_rel,
            100.0 * p.outside_rel
        );
    }
    eprintln!(
        "largest dihedral turn {:.1} degrees, creased length {:.3} heights",
        r.quality.whole.dihedral_deg, r.quality.whole.creased_rel
    );
    if let Some(d) = &r.derivation {
        let excess: Vec<String> = d
            .excess
            .iter()
            .map(|e| e.map_or("not built".into(), |e| format!("{e:.3}")))
            .collect();
        let (tried, first) = if d.first_shells {
            ("all shells, the arms cut off at different places", "shells")
        } else {
            ("the stacked one, then shells", "stacked")
        };
        let kept = match d.kept {
            0 => format!("the first model ({first})"),
            k => format!("model {} (shells)", k + 1),
        };
        eprintln!(
            "tried {} models ({tried}), their excess over issue 28's bounds {}: kept {kept}",
            d.excess.len(),
            excess.join(", ")
        );
    }
    if json {
        super::print_json(r)?;
    }
    Ok(0)
}
