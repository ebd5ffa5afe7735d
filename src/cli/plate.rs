//! `pdesculpt plate deform|compare` (paper 001).

use anyhow::Context;
use pdesculpt::mesh::io;
use pdesculpt::plate::baselines::{DeltaMushParams, LaplacianParams, Weights};
use pdesculpt::plate::parse_region;
use pdesculpt::plate::shapes::{compare, Shape};
use pdesculpt::plate::{
    BoundaryMethod, Direction, MappingMethod, Material, PlateDeformer, RegionOptions,
};
use std::path::PathBuf;

/// Arguments of `pdesculpt plate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: Cmd,
}

#[derive(clap::Subcommand, Debug)]
pub enum Cmd {
    /// Deform a region of a mesh by the clamped-plate solution (eq 12).
    Deform(DeformArgs),
    /// Compare ours, Delta Mush and the Laplacian deformer with the
    /// finite-element ground truth on a flat sheet (Figs 11-12).
    Compare(CompareArgs),
}

#[derive(clap::Args, Debug)]
pub struct DeformArgs {
    /// Input mesh (.obj, .glb, .gltf, .stl, .ply; FILE.glb#NODE,... reads
    /// only the named nodes).
    pub mesh: PathBuf,
    /// Region file: vertex indices (text), or JSON {"vertices": [...]} or
    /// {"lasso": {"view": [x,y,z], "polygon": [[x,y],...]}}.
    #[arg(long)]
    pub region: PathBuf,
    /// Cursor motion d = dx,dy,dz.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub force: Vec<f64>,
    /// Sensitivity s (q = s d).
    #[arg(long, default_value_t = pdesculpt::plate::SENSITIVITY_DEFAULT)]
    pub sensitivity: f64,
    /// Deform along the region normal instead of the cursor direction.
    #[arg(long)]
    pub normal: bool,
    /// Alpha-shape threshold alpha_0 (eq 15).
    #[arg(long, default_value_t = pdesculpt::plate::boundary::ALPHA0_DEFAULT)]
    pub alpha0: f64,
    /// Boundary from the region's mesh edges instead of the alpha shape
    /// (for non-uniform meshes).
    #[arg(long)]
    pub mesh_boundary: bool,
    /// Harmonic (Tutte) disk mapping instead of the paper's eq 16 (works
    /// for regions that are not star-shaped about their centroid).
    #[arg(long)]
    pub harmonic: bool,
    /// View direction x,y,z (default: the region normal).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub view: Option<Vec<f64>>,
    /// Young's modulus E, Poisson's ratio mu, thickness h.
    #[arg(long, default_value_t = Material::default().young)]
    pub young: f64,
    #[arg(long, default_value_t = Material::default().poisson)]
    pub poisson: f64,
    #[arg(long, default_value_t = Material::default().thickness)]
    pub thickness: f64,
    /// Output mesh (.obj, .glb, .stl, .ply).
    #[arg(short, long)]
    pub output: PathBuf,
    #[command(flatten)]
    pub units: super::units::UnitArgs,
}

#[derive(clap::Args, Debug)]
pub struct CompareArgs {
    /// square | rectangle | triangle | pentagram | circle
    #[arg(long)]
    pub shape: String,
    /// Grid cells per side of the sheet.
    #[arg(long, default_value_t = pdesculpt::plate::shapes::COMPARE_GRID_DEFAULT)]
    pub grid: usize,
    /// Delta Mush smoothing iterations.
    #[arg(long, default_value_t = DeltaMushParams::default().iterations)]
    pub dm_iterations: usize,
    /// Delta Mush step length.
    #[arg(long, default_value_t = DeltaMushParams::default().step)]
    pub dm_step: f64,
    /// Laplacian handle weight.
    #[arg(long, default_value_t = LaplacianParams::default().handle_weight)]
    pub lap_weight: f64,
    /// Uniform instead of cotangent Laplacian weights.
    #[arg(long)]
    pub lap_uniform: bool,
}

fn vec3(v: &[f64], what: &str) -> anyhow::Result<[f64; 3]> {
    match v {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok([*x, *y, *z]),
        _ => anyhow::bail!("{what} needs three finite numbers x,y,z, got {v:?}"),
    }
}

/// Runs `pdesculpt plate`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Cmd::Deform(a) => deform(a, json),
        Cmd::Compare(a) => run_compare(a, json),
    }
}

fn deform(a: DeformArgs, json: bool) -> anyhow::Result<i32> {
    let d = vec3(&a.force, "--force")?;
    if !a.sensitivity.is_finite() {
        anyhow::bail!("--sensitivity must be finite, got {}", a.sensitivity);
    }
    let view = a.view.as_deref().map(|v| vec3(v, "--view")).transpose()?;
    io::Format::from_path(&a.output)?;
    io::refuse_overwriting_input(&[&a.mesh, &a.region], &a.output)?;
    let mesh = io::read(&a.mesh)?;
    let text = io::read_input_text(&a.region, "region file")
        .with_context(|| format!("reading region file {}", a.region.display()))?;
    let region = parse_region(&text, &mesh)?;
    let opts = RegionOptions::default()
        .with_material(Material {
            young: a.young,
            poisson: a.poisson,
            thickness: a.thickness,
        })
        .with_alpha0(a.alpha0)
        .with_view(view)
        .with_boundary(if a.mesh_boundary {
            BoundaryMethod::MeshEdges
        } else {
            BoundaryMethod::AlphaShape
        })
        .with_mapping(if a.harmonic {
            MappingMethod::Harmonic
        } else {
            MappingMethod::LengthBased
        });
    let progress = pdesculpt::progress::Progress::spinner("plate: precomputing", json);
    let plate = PlateDeformer::new(&mesh, &region, &opts)?;
    progress.finish();
    let dir = if a.normal {
        Direction::Normal
    } else {
        Direction::Cursor
    };
    let out = plate.deform(&mesh, d, a.sensitivity, dir)?;
    let unit = a.units.write_input(&out, &a.output)?;
    let force = plate.checked_force(d, a.sensitivity, dir)?;
    let max_displacement = plate.max_displacement(force);
    let info = serde_json::json!({
        "output": a.output.display().to_string(),
        "unit": unit,
        "region_vertices": plate.region().len(),
        "boundary_vertices": plate.boundary().loop_indices.len(),
        "extra_boundary_loops": plate.boundary().extra_loops,
        "non_star_rays": plate.non_star_rays(),
        "rigidity": plate.rigidity(),
        "force": force,
        "max_displacement": max_displacement,
    });
    if json {
        super::print_json(&info)?;
    } else {
        eprintln!(
            "deformed {} region vertices ({} on the boundary), max displacement {:.4e}; wrote {}",
            plate.region().len(),
            plate.boundary().loop_indices.len(),
            max_displacement,
            a.output.display()
        );
        if plate.non_star_rays() > 0 {
            eprintln!(
                "warning: {} rays from the centroid cross the boundary more than once (region not star-shaped; eq 16 is not one-to-one there)",
                plate.non_star_rays()
            );
        }
    }
    Ok(0)
}

fn run_compare(a: CompareArgs, json: bool) -> anyhow::Result<i32> {
    let shape = Shape::parse(&a.shape).ok_or_else(|| {
        anyhow::anyhow!(
            "unknown shape {:?} (square, rectangle, triangle, pentagram, circle)",
            a.shape
        )
    })?;
    pdesculpt::limits::check("--grid", a.grid, pdesculpt::limits::PLATE_GRID)?;
    pdesculpt::limits::check(
        "--dm-iterations",
        a.dm_iterations,
        pdesculpt::limits::PLATE_ITERATIONS,
    )?;
    let dm = DeltaMushParams {
        iterations: a.dm_iterations,
        step: a.dm_step,
    };
    let lap = LaplacianParams {
        weights: if a.lap_uniform {
            Weights::Uniform
        } else {
            Weights::Cotangent
        },
        handle_weight: a.lap_weight,
    };
    let c = compare(shape, a.grid, &dm, &lap)?;
    if json {
        super::print_json(&serde_json::json!({
            "shape": shape.name(),
            "grid": c.grid,
            "region_vertices": c.region.len(),
            "errors": c.errors,
            "amplitude_ratio_ours_over_truth": c.amplitude_ratio,
            "delta_mush": dm,
            "laplacian": lap,
        }))?;
    } else {
        println!(
            "{} region ({} vertices, {}x{} sheet); error of the unit-peak deflection against the Morley FE ground truth:",
            shape.name(),
            c.region.len(),
            c.grid,
            c.grid
        );
        println!("{:<12} {:>10} {:>10}", "method", "rms", "max");
        for e in &c.errors {
            println!("{:<12} {:>10.4} {:>10.4}", e.method, e.rms, e.max);
        }
        println!(
            "ours / truth peak deflection (same q, D): {:.4}",
            c.amplitude_ratio
        );
    }
    Ok(0)
}
