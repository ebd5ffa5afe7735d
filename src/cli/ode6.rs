//! `pdesculpt ode6`: C2 sixth-order ODE surfaces (paper 004).
//!
//! * `ode6 surface SPEC.json -o OUT.{obj,glb,stl,ply}`: tessellates a patch
//!   described by a JSON spec (`pdesculpt::ode6::spec::Spec`); curves are
//!   `fourier`, `polyline`, `gec` (a generalized elliptic curve as serialized
//!   by `pdesculpt gec`) or `hermite` (`{"start": [P, P', P''], "end": [...]}`).
//! * `ode6 eval --rho R --eta E --lambda L --bc c1,...,c6 --at u[,u...]`: one
//!   scalar iso-parametric line, its first two derivatives and the ODE
//!   residual (teaching and checking).

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
        } => {
            pdesculpt::mesh::io::Format::from_path(&out)?;
            pdesculpt::mesh::io::refuse_overwriting_input(&[&spec], &out)?;
            if let Some(n) = nu {
                limits::check("--nu", n, limits::TESS_NU)?;
            }
            if let Some(n) = nv {
                limits::check("--nv", n, limits::TESS_NV)?;
            }
            let text = pdesculpt::mesh::io::read_input_text(&spec, "spec")
                .with_context(|| format!("reading {}", spec.display()))?;
            let sp: Spec = serde_json::from_str(&text)
                .with_context(|| format!("parsing spec {}", spec.display()))?;
            let s = sp.build()?;
            let [nu, nv] = sp.resolution(nu, nv)?;
            let mesh = tessellate(&s, Tessellation { nu, nv });
            anyhow::ensure!(
                mesh.positions.iter().flatten().all(|x| x.is_finite()),
                "surface has non-finite points"
            );
            let unit = units.write_input(&mesh, &out)?;
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
