//! `pdesculpt demo`: the main job on bundled data.
//!
//! The MakeHuman base body as template, a chest sculpt (paper 000: one
//! curve, one drag, fourth-order PDE), a pregnancy belly (paper 001: C1
//! plate bending, compared with MakeHuman's own pregnancy morph), the C2
//! sixth-order PDE reconstruction of the result from its cross sections
//! (paper 002), and a teddy bear sketched in eight silhouette strokes
//! standing beside it (paper 003, convolution surfaces). Writes into `out/`:
//! `demo.glb`, `demo.obj`, `demo.png` (the sculpted body, the skirt and
//! the teddy: three models, objects `body`, `skirt` and `teddy`; front and
//! side), `demo-pde6.glb`, `demo-pde6.png` (the reconstruction, model
//! `reconstruction`, one node and colour per part and transition),
//! `demo-sketch.glb` (step 1: the bundled female built from her sketches,
//! paper 000 sec 4.1; model `female`, one node per part and transition)
//! and `demo.json` (what every step measured). GLBs are metres (a
//! 1.67 m body), `demo.obj` is in `--unit` (default metres), `demo.json`'s
//! lengths are decimetres, the MakeHuman template's unit (`"unit": "dm"`).

use pdesculpt::demo;
use pdesculpt::mesh::io::{self, Scene};
use pdesculpt::render::{render_views, RenderOptions, View};
use std::path::PathBuf;

/// Arguments of `pdesculpt demo`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Output directory.
    #[arg(short, long, default_value = "out")]
    pub out: PathBuf,
    #[command(flatten)]
    pub units: super::units::OutputUnitArgs,
}

/// Builds the demo outputs.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    // the output directory is checked (and made) before the long build
    if args.out.exists() && !args.out.is_dir() {
        anyhow::bail!(
            "-o {}: is a file; the demo writes several files into a directory",
            args.out.display()
        );
    }
    std::fs::create_dir_all(&args.out).map_err(|e| {
        anyhow::anyhow!(
            "-o {}: cannot create the directory: {e}",
            args.out.display()
        )
    })?;
    eprintln!("step 1: the bundled female from her sketches (front, side, key sections)");
    eprintln!("template: the MakeHuman base body");
    eprintln!(
        "sculpting (chest: 4-sided PDE; belly: plate bending), reconstructing (C2 PDE6 patches), sketching a prop (convolution surfaces)..."
    );
    let progress = pdesculpt::progress::Progress::spinner("demo", json);
    let d = demo::build()?;
    progress.finish();
    let models = Scene::single("body", d.sculpted.clone())
        .with("skirt", d.skirt.clone())
        .with("teddy", d.prop.clone());
    let scene = models.flatten();
    let views = |m| {
        render_views(
            m,
            &[View::Front, View::Side],
            &RenderOptions::default().with_width(400).with_height(800),
        )
    };
    let files = [
        args.out.join("demo.glb"),
        args.out.join("demo.obj"),
        args.out.join("demo.png"),
        args.out.join("demo-pde6.glb"),
        args.out.join("demo-pde6.png"),
        args.out.join("demo.json"),
        args.out.join("demo-sketch.glb"),
    ];
    let unit_glb = args.units.write_scene(&models, &files[0], d.unit)?;
    let unit_obj = args.units.write_scene(&models, &files[1], d.unit)?;
    views(&scene).save_png(&files[2])?;
    let reconstruction = Scene::single("reconstruction", d.reconstruction.clone());
    args.units.write_scene(&reconstruction, &files[3], d.unit)?;
    views(&d.reconstruction).save_png(&files[4])?;
    io::write_atomic(&files[5], &serde_json::to_vec_pretty(&d.report)?)?;
    let female = Scene::single("female", d.sketched.clone());
    args.units
        .write_scene(&female, &files[6], pdesculpt::mesh::unit::Unit::M)?;
    print_summary(&d.report);
    for p in &files {
        eprintln!("wrote {}", p.display());
    }
    eprintln!(
        "units: GLB {unit_glb}, OBJ {unit_obj}, report lengths {}",
        d.unit
    );
    if json {
        super::print_json(&serde_json::json!({
            "outputs": files,
            "units": {"demo.glb": unit_glb, "demo.obj": unit_obj, "demo-pde6.glb": unit_glb, "report": d.unit},
            "vertices": scene.positions.len(),
            "triangles": scene.triangles.len(),
            "report": d.report,
        }))?;
    }
    Ok(0)
}

/// One line per model of the demo report on stderr: the sketched female,
/// the local edits, the plate belly against the morph, the closed
/// reconstruction, the skirt and the teddy.
fn print_summary(report: &demo::DemoReport) {
    let k = &report.sketched;
    eprintln!(
        "  sketched female (paper 000 sec 4.1, {} level): {} triangles, closed {}, profile error {}, max C1 jump {:.1e}",
        k.level,
        k.triangles,
        k.watertight,
        k.profile_error
            .iter()
            .map(|(v, e)| format!("{v} {:.2} %", 100.0 * e))
            .collect::<Vec<_>>()
            .join(", "),
        k.max_c1
    );
    for e in &report.edits {
        eprintln!(
            "  {} (paper {}): {} vertices moved, max {:.3} dm, first ring inside the clamped edge {:.3} dm",
            e.name, e.paper, e.moved_vertices, e.max_displacement, e.max_first_ring_displacement
        );
    }
    let b = &report.belly_vs_morph;
    eprintln!(
        "  plate belly vs MakeHuman's pregnancy morph ({} vertices, peak {:.2} dm): RMS {:.1} % / max {:.1} % of the peak",
        b.region_vertices,
        b.peak,
        100.0 * b.rms_rel,
        100.0 * b.max_rel
    );
    let r = &report.reconstruction;
    eprintln!(
        "  reconstruction (paper 002, closed body): {} parts, watertight {}, RMS {:.2} % / max {:.2} % of body height, {} GEC numbers for {} vertex coordinates",
        r.sections.len(),
        r.topology.watertight,
        100.0 * r.recon_to_skin_rms_rel,
        100.0 * r.recon_to_skin_max_rel,
        r.gec_numbers,
        r.skin_vertex_numbers
    );
    let s = &report.skirt;
    eprintln!(
        "  skirt (paper 004): C2 ODE surface through 2 boundary + 4 control rings, {} numbers for {} vertex coordinates, clearance min {:.3} dm, {:.1} % of vertices inside the body",
        s.ode_numbers,
        s.mesh_numbers,
        s.min_clearance,
        100.0 * s.inside_fraction
    );
    let p = &report.prop;
    eprintln!(
        "  teddy (paper 003): {} strokes, {} segments, {} triangles (watertight {}, manifold {}, oriented {}), fit |F-T|/T max {:.1e}, body outline vs stroke max {:.1} % of its size",
        p.components,
        p.segments,
        p.triangles,
        p.watertight,
        p.manifold,
        p.oriented,
        p.fit_max_rel,
        100.0 * p.body_silhouette_max_rel
    );
}
