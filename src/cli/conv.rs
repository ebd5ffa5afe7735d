//! `pdesculpt conv`: convolution surfaces from sketched silhouettes
//! (paper 003).
//!
//! * `pdesculpt conv build MODEL.json -o OUT.(obj|glb|stl|ply) [--resolution R]
//!   [--polygonizer mt|sn] [--sampler fast|reference]`: rebuilds a model
//!   file at any resolution.
//! * `pdesculpt conv field --segment x0,y0,z0,x1,y1,z1 --weights w0,w1 --s S
//!   --at x,y,z`: the closed-form field (and gradient) of one segment at a
//!   point, beside the adaptive-quadrature value.

use anyhow::{bail, Context};
use pdesculpt::conv::kernel::{self, Segment};
use pdesculpt::conv::model::{Model, Polygonizer};
use pdesculpt::conv::sample::Sampler;
use pdesculpt::mesh::topology::report;

/// Arguments of `pdesculpt conv`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(clap::Subcommand, Debug)]
enum Cmd {
    /// Build a model file (JSON) into a mesh.
    Build {
        /// The model file.
        model: std::path::PathBuf,
        /// Output mesh (.obj, .glb, .stl or .ply).
        #[arg(short, long)]
        output: std::path::PathBuf,
        /// Grid cells along the longest side of each component group.
        #[arg(long, default_value_t = 64)]
        resolution: usize,
        /// Polygoniser: mt (marching tetrahedra, the paper's) or sn (surface nets).
        #[arg(long, default_value = "mt")]
        polygonizer: String,
        /// Field sampler: fast (narrow band over a segment hierarchy, node
        /// values within 1e-4 T / 2) or reference (every node, every segment).
        #[arg(long, default_value = "fast")]
        sampler: String,
        #[command(flatten)]
        units: super::units::UnitArgs,
    },
    /// The closed-form field of one linearly weighted segment at a point.
    Field {
        /// x0,y0,z0,x1,y1,z1
        #[arg(long, allow_hyphen_values = true)]
        segment: String,
        /// w0,w1
        #[arg(long, allow_hyphen_values = true)]
        weights: String,
        /// Kernel width s.
        #[arg(long)]
        s: f64,
        /// x,y,z
        #[arg(long, allow_hyphen_values = true)]
        at: String,
    },
}

fn numbers(text: &str, n: usize, what: &str) -> anyhow::Result<Vec<f64>> {
    let v: Vec<f64> = text
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .with_context(|| format!("--{what}: expected {n} comma-separated numbers, got {text:?}"))?;
    if v.len() != n {
        bail!("--{what}: expected {n} numbers, got {}", v.len());
    }
    if let Some(x) = v.iter().find(|x| !x.is_finite()) {
        bail!("--{what}: {x} is not finite");
    }
    Ok(v)
}

/// Runs `pdesculpt conv`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.cmd {
        Cmd::Build {
            model,
            output,
            resolution,
            polygonizer,
            sampler,
            units,
        } => {
            let method = match polygonizer.as_str() {
                "mt" => Polygonizer::MarchingTetrahedra,
                "sn" => Polygonizer::SurfaceNets,
                other => bail!("--polygonizer: expected mt or sn, got {other:?}"),
            };
            let sampler_kind = match sampler.as_str() {
                "fast" => Sampler::NarrowBand,
                "reference" => Sampler::Reference,
                other => bail!("--sampler: expected fast or reference, got {other:?}"),
            };
            super::outputs::check(&[("MODEL", &model)], &[("-o", &output)])?;
            let text = pdesculpt::mesh::io::read_input_text(&model, "conv model")?;
            let m = Model::from_json(&text).with_context(|| format!("{}", model.display()))?;
            let t0 = std::time::Instant::now();
            let progress = pdesculpt::progress::Progress::spinner("conv build", json);
            let built = m.build()?;
            let mesh =
                built.polygonize_with(resolution, m.options.threshold, method, sampler_kind)?;
            progress.finish();
            let secs = t0.elapsed().as_secs_f64();
            pdesculpt::conv::sample::check_f32_output(&mesh)?;
            let unit = units.write_input(&mesh, &output)?;
            print_build(&built, &mesh, &output, &unit, &sampler, secs, json)?;
            Ok(0)
        }
        Cmd::Field {
            segment,
            weights,
            s,
            at,
        } => field(&segment, &weights, s, &at, json),
    }
}

/// `conv build`'s report: the JSON document or the human summary with one
/// line per component.
fn print_build(
    built: &pdesculpt::conv::model::BuiltModel,
    mesh: &pdesculpt::mesh::Mesh,
    output: &std::path::Path,
    unit: &pdesculpt::mesh::unit::Unit,
    sampler: &str,
    secs: f64,
    json: bool,
) -> anyhow::Result<()> {
    let topo = report(mesh);
    let comps: Vec<serde_json::Value> = built
        .components
        .iter()
        .map(|c| {
            serde_json::json!({
                "name": c.name,
                "group": c.group,
                "depth": c.depth,
                "segments": c.segments.len(),
                "s": c.sketch.s,
                "fit_max_rel_error": c.sketch.fit.max_rel_error,
                "fit_rms_rel_error": c.sketch.fit.rms_rel_error,
                "fit_iterations": c.sketch.fit.iterations,
                "fit_converged": c.sketch.fit.converged,
            })
        })
        .collect();
    if json {
        super::print_json(&serde_json::json!({
            "output": output.display().to_string(),
            "unit": unit,
            "triangles": mesh.triangles.len(),
            "vertices": mesh.positions.len(),
            "topology": topo,
            "sampler": sampler,
            "seconds": secs,
            "components": comps,
        }))?;
    } else {
        println!(
            "wrote {} ({} triangles, watertight {}, manifold {}, oriented {}) in {:.2} s",
            output.display(),
            mesh.triangles.len(),
            topo.watertight,
            topo.manifold,
            topo.oriented,
            secs
        );
        for c in &built.components {
            println!(
                "  {}: group {}, depth {:.3}, {} segments, fit |F-T|/T max {:.2e} rms {:.2e}{}",
                c.name,
                c.group,
                c.depth,
                c.segments.len(),
                c.sketch.fit.max_rel_error,
                c.sketch.fit.rms_rel_error,
                if c.sketch.fit.converged {
                    String::new()
                } else {
                    format!(
                        " (solver stopped at its cap of {} iterations, not converged)",
                        c.sketch.fit.iterations
                    )
                }
            );
        }
    }
    Ok(())
}

/// `conv field`: the closed-form field of one segment, its basis and
/// gradient, against quadrature.
fn field(segment: &str, weights: &str, s: f64, at: &str, json: bool) -> anyhow::Result<i32> {
    let g = numbers(segment, 6, "segment")?;
    let w = numbers(weights, 2, "weights")?;
    let r = numbers(at, 3, "at")?;
    if !(s.is_finite() && s > 0.0) {
        bail!("--s must be positive and finite, got {s}");
    }
    let seg = Segment {
        p: [g[0], g[1], g[2]],
        q: [g[3], g[4], g[5]],
        w0: w[0],
        w1: w[1],
        lambda: 1.0,
    };
    if seg.length() <= 0.0 {
        bail!("--segment: the two endpoints coincide");
    }
    let r = [r[0], r[1], r[2]];
    let f = seg.field(r, s);
    let (f1, ft) = seg.basis(r, s);
    let grad = seg.gradient(r, s);
    if !(f.is_finite() && f1.is_finite() && ft.is_finite() && grad.iter().all(|g| g.is_finite())) {
        bail!(
            "the field is not representable for --s {s} at --at {r:?} (s times the distances \
             over- or underflows); use s and coordinates with s * |at - segment| between 1e-100 and 1e100"
        );
    }
    let quad = kernel::field_by_quadrature(&seg, r, s, 1e-14 * f.abs().max(1e-300));
    if json {
        super::print_json(&serde_json::json!({
            "field": f, "f1": f1, "ft": ft, "gradient": grad,
            "quadrature": quad, "relative_difference": (f - quad).abs() / quad.abs().max(1e-300),
        }))?;
    } else {
        println!("F    = {f:.15e}");
        println!("F_1  = {f1:.15e}");
        println!("F_t  = {ft:.15e}");
        println!(
            "grad = [{:.12e}, {:.12e}, {:.12e}]",
            grad[0], grad[1], grad[2]
        );
        println!(
            "quadrature F = {quad:.15e} (relative difference {:.2e})",
            (f - quad).abs() / quad.abs().max(1e-300)
        );
    }
    Ok(0)
}
