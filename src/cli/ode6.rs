//! `pdesculpt ode6`: C2 sixth-order ODE surfaces (paper 004).
//!
//! * `ode6 surface SPEC.json -o OUT.{obj,glb,stl,ply}`: tessellates a patch
//!   described by a JSON spec (`pdesculpt::ode6::spec::Spec`); curves are
//!   `fourier`, `polyline`, `gec` (a generalized elliptic curve as serialized
//!   by `pdesculpt gec`) or `hermite` (`{"start": [P, P', P''], "end": [...]}`).
//! * `ode6 eval --rho R --eta E --lambda L --bc c1,...,c6 --at u[,u...]`: one
//!   scalar iso-parametric line, its first two derivatives and the ODE
//!   residual (teaching and checking).
//! * `ode6 network NET.json -o OUT`: solves a curve network of 3- and
//!   4-sided patches (`pdesculpt::ode6::network`, schema in
//!   `docs/networks.md`) and writes one mesh group per patch, with the
//!   report (per-edge C0/C1/C2 jumps in u and v, data size).
//! * `ode6 face [--mesh BODY.obj] [--expression NAME=W ...] [--patches N]
//!   -o OUT`: rebuilds the face of a MakeHuman-topology mesh from a curve
//!   network of ODE patches (`pdesculpt::face`); OUT is the input with the
//!   face region's vertices replaced (an OBJ keeps the input's every
//!   other line).

use anyhow::Context;
use pdesculpt::limits;
use pdesculpt::ode6::spec::{eval_line, Spec};
use pdesculpt::ode6::{Basis, Params};
use pdesculpt::surface::{tessellate, Tessellation};
use std::path::PathBuf;

/// Arguments of `pdesculpt ode6`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: Cmd,
}

#[derive(clap::Subcommand, Debug)]
pub enum Cmd {
    /// Tessellate the ODE surface described by a JSON spec.
    Surface {
        /// The spec: params, curves (approach1 | approach2 | direct), optional force.
        spec: PathBuf,
        /// Output mesh (.obj, .glb, .stl, .ply).
        #[arg(short, long)]
        out: PathBuf,
        /// Samples in u (overrides the spec).
        #[arg(long)]
        nu: Option<usize>,
        /// Samples in v (overrides the spec).
        #[arg(long)]
        nv: Option<usize>,
        #[command(flatten)]
        units: super::units::UnitArgs,
    },
    /// Solve a curve network of 3- and 4-sided ODE patches (C2 across every edge).
    Network {
        /// The network document (JSON, version 1; schema in docs/networks.md).
        network: PathBuf,
        /// Output mesh (.obj, .glb, .stl, .ply): one group per patch.
        #[arg(short, long)]
        out: PathBuf,
        /// Cells per patch side in the output mesh.
        #[arg(long, default_value_t = 16)]
        samples: usize,
        #[command(flatten)]
        units: super::units::UnitArgs,
    },
    /// Rebuild the face of a MakeHuman-topology mesh from a C2 curve network.
    Face {
        /// A mesh with the MakeHuman base topology (OBJ; default: the bundled base).
        #[arg(long)]
        mesh: Option<PathBuf>,
        /// Apply an expression first: a FACS unit (AU1, AU12, ...) or a
        /// MakeHuman expression unit (mouth-parling, ...) with its weight.
        #[arg(long = "expression", value_name = "NAME=W")]
        expressions: Vec<String>,
        /// Patches in the face network (a multiple of 4: columns x 4 rows).
        #[arg(long, default_value_t = pdesculpt::face::extract::DEFAULT_PATCHES)]
        patches: usize,
        /// Keep the default shape parameters (no optimisation).
        #[arg(long)]
        no_optimise: bool,
        /// Output mesh: .obj (the input OBJ with the face vertices replaced)
        /// or .glb/.stl/.ply (triangles; the face in its own group).
        #[arg(short, long)]
        out: PathBuf,
        #[command(flatten)]
        units: super::units::OutputUnitArgs,
    },
    /// Evaluate one scalar iso-parametric line S(u) of eq 19.
    Eval {
        #[arg(long, allow_hyphen_values = true)]
        rho: f64,
        #[arg(long, allow_hyphen_values = true)]
        eta: f64,
        #[arg(long, allow_hyphen_values = true)]
        lambda: f64,
        /// The six constraints S(0), S'(0), S''(0), S(1), S'(1), S''(1).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        bc: Vec<f64>,
        /// Parameter values u (comma separated).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        at: Vec<f64>,
    },
}

/// Runs `pdesculpt ode6`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Cmd::Surface {
            spec,
            out,
            nu,
            nv,
            units,
        } => run_surface(&spec, &out, nu, nv, units, json),
        Cmd::Network {
            network,
            out,
            samples,
            units,
        } => run_network(&network, &out, samples, units, json),
        Cmd::Face {
            mesh,
            expressions,
            patches,
            no_optimise,
            out,
            units,
        } => run_face(
            mesh.as_deref(),
            &expressions,
            patches,
            !no_optimise,
            &out,
            units,
            json,
        ),
        Cmd::Eval {
            rho,
            eta,
            lambda,
            bc,
            at,
        } => {
            let c: [f64; 6] = bc.as_slice().try_into().map_err(|_| {
                anyhow::anyhow!("--bc needs six values c1,...,c6 (got {})", bc.len())
            })?;
            if let Some(u) = at.iter().find(|u| !(0.0..=1.0).contains(*u)) {
                anyhow::bail!(
                    "--at {u}: must lie in [0, 1] (the parameter of the iso-parametric line)"
                );
            }
            let b = Basis::new(Params::new(rho, eta, lambda))?;
            let points = eval_line(&b, &c, &at)?;
            if json {
                super::print_json(
                    &serde_json::json!({"case": b.case.name(), "rcond": b.rcond, "points": points}),
                )?;
            } else {
                println!("case: {}", b.case.name());
                for p in &points {
                    println!(
                        "u = {}  S = {}  S' = {}  S'' = {}  residual = {:.3e}",
                        p.u, p.s, p.s_u, p.s_uu, p.residual
                    );
                }
            }
            Ok(0)
        }
    }
}

fn run_surface(
    spec: &std::path::Path,
    out: &std::path::Path,
    nu: Option<usize>,
    nv: Option<usize>,
    units: super::units::UnitArgs,
    json: bool,
) -> anyhow::Result<i32> {
    pdesculpt::mesh::io::Format::from_path(out)?;
    pdesculpt::mesh::io::refuse_overwriting_input(&[spec], out)?;
    if let Some(n) = nu {
        limits::check("--nu", n, limits::TESS_NU)?;
    }
    if let Some(n) = nv {
        limits::check("--nv", n, limits::TESS_NV)?;
    }
    let text = pdesculpt::mesh::io::read_input_text(spec, "spec")
        .with_context(|| format!("reading {}", spec.display()))?;
    let sp: Spec =
        serde_json::from_str(&text).with_context(|| format!("parsing spec {}", spec.display()))?;
    let s = sp.build()?;
    let [nu, nv] = sp.resolution(nu, nv)?;
    let mesh = tessellate(&s, Tessellation { nu, nv });
    anyhow::ensure!(
        mesh.positions.iter().flatten().all(|x| x.is_finite()),
        "surface has non-finite points"
    );
    let unit = units.write_input(&mesh, out)?;
    let info = serde_json::json!({
        "out": out.display().to_string(),
        "unit": unit,
        "case": s.basis.case.name(),
        "vertices": mesh.positions.len(),
        "triangles": mesh.triangles.len(),
        "scalars": s.scalars(),
    });
    if json {
        super::print_json(&info)?;
    } else {
        eprintln!(
            "wrote {} ({} vertices, case: {})",
            out.display(),
            mesh.positions.len(),
            s.basis.case.name()
        );
    }
    Ok(0)
}

fn run_network(
    network: &std::path::Path,
    out: &std::path::Path,
    samples: usize,
    units: super::units::UnitArgs,
    json: bool,
) -> anyhow::Result<i32> {
    use pdesculpt::ode6::network::{Network, NetworkDoc};
    pdesculpt::mesh::io::Format::from_path(out)?;
    pdesculpt::mesh::io::refuse_overwriting_input(&[network], out)?;
    limits::check("--samples", samples, limits::TESS_NU)?;
    let text = pdesculpt::mesh::io::read_input_text(network, "network")
        .with_context(|| format!("reading {}", network.display()))?;
    let doc =
        NetworkDoc::from_json(&text).with_context(|| format!("network {}", network.display()))?;
    let net = Network::build(doc).with_context(|| format!("network {}", network.display()))?;
    eprintln!("solved {} patches; measuring the joins", net.patches.len());
    let mesh = net.mesh(samples);
    anyhow::ensure!(
        mesh.positions.iter().flatten().all(|x| x.is_finite()),
        "the network's surface has non-finite points"
    );
    let report = net.report(samples);
    let unit = units.write_input(&mesh, out)?;
    if json {
        super::print_json(&serde_json::json!({
            "out": out.display().to_string(),
            "unit": unit,
            "triangles": mesh.triangles.len(),
            "report": report,
        }))?;
    } else {
        eprintln!(
            "wrote {} ({} patches, {} 3-sided, {} vertices); largest relative jumps [C0, C1, C2]: \
             u-edges {:?}, v-edges {:?}; data {} numbers for {} mesh numbers ({:.0} %)",
            out.display(),
            report.patches,
            report.three_sided,
            mesh.positions.len(),
            report.max_relative_u_edges,
            report.max_relative_v_edges,
            report.data.stored_numbers,
            report.data.mesh_numbers,
            100.0 * report.data.ratio
        );
    }
    Ok(0)
}

fn run_face(
    mesh: Option<&std::path::Path>,
    expressions: &[String],
    patches: usize,
    optimise: bool,
    out: &std::path::Path,
    units: super::units::OutputUnitArgs,
    json: bool,
) -> anyhow::Result<i32> {
    use pdesculpt::face::{expression, extract};
    use pdesculpt::mesh::unit::MAKEHUMAN;
    let fmt = pdesculpt::mesh::io::Format::from_path(out)?;
    if let Some(m) = mesh {
        pdesculpt::mesh::io::refuse_overwriting_input(&[m], out)?;
    }
    extract::columns_for(patches)?;
    let mut targets = Vec::new();
    for e in expressions {
        let (name, w) = e
            .split_once('=')
            .ok_or_else(|| anyhow::anyhow!("--expression {e:?}: expected NAME=WEIGHT"))?;
        let w: f64 = w
            .trim()
            .parse()
            .map_err(|_| anyhow::anyhow!("--expression {e:?}: weight {w:?} is not a number"))?;
        targets.extend(expression::expression(name.trim(), w)?);
    }
    let text = match mesh {
        Some(p) => {
            anyhow::ensure!(
                p.extension().is_some_and(|x| x.eq_ignore_ascii_case("obj")),
                "--mesh {}: the face needs an OBJ with the MakeHuman base topology",
                p.display()
            );
            pdesculpt::mesh::io::read_input_text(p, "mesh")
                .with_context(|| format!("reading {}", p.display()))?
        }
        None => pdesculpt::makehuman::BASE_OBJ.to_string(),
    };
    let name = mesh.map_or("data/makehuman/base.obj".to_string(), |p| {
        p.display().to_string()
    });
    let mut input = pdesculpt::mesh::io::parse_obj(&text, &name)?;
    expression::apply(&mut input.positions, &targets)?;
    eprintln!(
        "rebuilding the face ({patches} patches{})",
        if optimise { ", optimising" } else { "" }
    );
    let (positions, report, _) =
        extract::rebuild(&input, &extract::FaceOptions::new(patches, optimise))?;
    let unit = if matches!(fmt, pdesculpt::mesh::io::Format::Obj) {
        let scale = MAKEHUMAN.factor_to(units.unit);
        let obj = extract::rewrite_obj(&text, &positions, scale)?;
        pdesculpt::mesh::io::write_atomic(out, obj.as_bytes())?;
        units.unit
    } else {
        let mut m = input.clone();
        m.positions = positions;
        extract::mark_face(&mut m, patches)?;
        units.write(&m, out, MAKEHUMAN)?
    };
    if json {
        super::print_json(&serde_json::json!({
            "out": out.display().to_string(),
            "unit": unit,
            "expressions": expressions,
            "report": report,
        }))?;
    } else {
        eprintln!(
            "wrote {}: {} face vertices of {}, MVE {:.4} dm ({:.3} % of the head height {:.3} dm), \
             RMS {:.4} dm; {} curve points ({} variables, {:.0} % of the face vertices)",
            out.display(),
            report.face_vertices,
            report.vertices,
            report.max_error,
            100.0 * report.max_relative,
            report.head_height,
            report.rms_error,
            report.curve_points,
            report.curve_variables,
            100.0 * report.data_ratio
        );
    }
    Ok(0)
}
