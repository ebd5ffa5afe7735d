//! `pdesculpt ode6`: C2 sixth-order ODE surfaces (paper 004).
//!
//! * `ode6 surface SPEC.json -o OUT.{obj,glb,stl,ply}`: tessellates a patch
//!   described by a JSON spec (see [`Spec`]); curves are `fourier`,
//!   `polyline`, `gec` (a generalized elliptic curve as serialized by
//!   `pdesculpt gec`) or `hermite` (`{"start": [P, P', P''], "end": [...]}`).
//! * `ode6 eval --rho R --eta E --lambda L --bc c1,...,c6 --at u[,u...]`: one
//!   scalar iso-parametric line, its first two derivatives and the ODE
//!   residual (teaching and checking).

use anyhow::Context;
use pdesculpt::curve::gec::Gec;
use pdesculpt::curve::Fourier3;
use pdesculpt::jet::Jet;
use pdesculpt::limits;
use pdesculpt::ode6::{
    Approach2, Basis, BoundaryCurves, Curve, DiffFormula, Force, Ode6Surface, Params,
};
use pdesculpt::surface::{tessellate, Tessellation};
use serde::Deserialize;
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

/// One curve of a spec.
#[derive(Deserialize, Debug)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CurveSpec {
    Fourier(Fourier3),
    Polyline {
        points: Vec<[f64; 3]>,
        closed: bool,
    },
    /// A generalized elliptic curve (frame, centre, x and y coefficient pairs).
    Gec(Gec),
    /// An open quintic Hermite segment: `[P, P', P'']` at v = 0 and v = 1.
    Hermite {
        start: [[f64; 3]; 3],
        end: [[f64; 3]; 3],
    },
}

impl CurveSpec {
    fn build(&self) -> anyhow::Result<Curve> {
        match self {
            CurveSpec::Polyline { points, .. } => {
                limits::check("polyline points", points.len(), limits::POLYLINE_POINTS)?;
            }
            CurveSpec::Fourier(f) => {
                limits::check(
                    "fourier harmonics",
                    f.cos.len().max(f.sin.len()),
                    limits::CURVE_HARMONICS,
                )?;
            }
            CurveSpec::Gec(g) => {
                limits::check(
                    "gec terms",
                    g.x.len().max(g.y.len()),
                    limits::CURVE_HARMONICS,
                )?;
            }
            CurveSpec::Hermite { .. } => {}
        }
        Ok(match self {
            CurveSpec::Fourier(f) => Curve::Fourier(f.clone()),
            CurveSpec::Polyline { points, closed } => Curve::from_polyline(points, *closed)?,
            CurveSpec::Gec(g) => {
                // Re-validate the frame and coefficients of deserialized data.
                let g = Gec::new(g.frame, g.centre, g.x.clone(), g.y.clone())
                    .context("invalid gec curve")?;
                Curve::from_gec(&g)?
            }
            CurveSpec::Hermite { start, end } => Curve::hermite(*start, *end)?,
        })
    }
}

/// How the six constraint curves are made.
#[derive(Deserialize, Debug)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CurvesSpec {
    Approach1 {
        c1: CurveSpec,
        c4: CurveSpec,
        w: [f64; 4],
    },
    Approach2 {
        c1: CurveSpec,
        controls: [CurveSpec; 4],
        c4: CurveSpec,
        /// `[u2, u3, u5, u6]`.
        u: [f64; 4],
        #[serde(default = "three_point")]
        formula: DiffFormula,
    },
    Direct([CurveSpec; 6]),
}

fn three_point() -> DiffFormula {
    DiffFormula::ThreePoint
}

/// A surface spec.
#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub params: Params,
    pub curves: CurvesSpec,
    #[serde(default)]
    pub force: Option<Force>,
    #[serde(default)]
    pub nu: Option<usize>,
    #[serde(default)]
    pub nv: Option<usize>,
}

/// Builds the surface of a spec.
pub fn build(spec: &Spec) -> anyhow::Result<Ode6Surface> {
    let basis = Basis::new(spec.params)?;
    let curves = match &spec.curves {
        CurvesSpec::Approach1 { c1, c4, w } => {
            BoundaryCurves::approach1(c1.build()?, c4.build()?, *w)?
        }
        CurvesSpec::Approach2 {
            c1,
            controls,
            c4,
            u,
            formula,
        } => {
            let [a, b, c, d] = controls;
            let a2 = Approach2 {
                u2: u[0],
                u3: u[1],
                u5: u[2],
                u6: u[3],
                formula: *formula,
            };
            BoundaryCurves::approach2(
                c1.build()?,
                [a.build()?, b.build()?, c.build()?, d.build()?],
                c4.build()?,
                &a2,
            )?
        }
        CurvesSpec::Direct(cs) => {
            let [a, b, c, d, e, f] = cs;
            BoundaryCurves::direct([
                a.build()?,
                b.build()?,
                c.build()?,
                d.build()?,
                e.build()?,
                f.build()?,
            ])?
        }
    };
    let s = Ode6Surface::new(basis, curves);
    Ok(match &spec.force {
        Some(f) => s.with_force(f)?,
        None => s,
    })
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
            let text = std::fs::read_to_string(&spec)
                .with_context(|| format!("reading {}", spec.display()))?;
            let sp: Spec = serde_json::from_str(&text)
                .with_context(|| format!("parsing spec {}", spec.display()))?;
            let s = build(&sp)?;
            let nu = nu.or(sp.nu).unwrap_or(32);
            let nv = nv.or(sp.nv).unwrap_or(64);
            anyhow::ensure!(
                (1..=4096).contains(&nu) && (3..=4096).contains(&nv),
                "nu (intervals in u) must be in 1..=4096 and nv in 3..=4096 (got {nu}, {nv})"
            );
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
            anyhow::ensure!(
                bc.len() == 6,
                "--bc needs six values c1,...,c6 (got {})",
                bc.len()
            );
            anyhow::ensure!(!at.is_empty(), "--at needs at least one u");
            anyhow::ensure!(
                bc.iter().chain(&at).all(|x| x.is_finite()),
                "--bc and --at must be finite"
            );
            if let Some(u) = at.iter().find(|u| !(0.0..=1.0).contains(*u)) {
                anyhow::bail!(
                    "--at {u}: must lie in [0, 1] (the parameter of the iso-parametric line)"
                );
            }
            let c: [f64; 6] = [bc[0], bc[1], bc[2], bc[3], bc[4], bc[5]];
            let b = Basis::new(Params::new(rho, eta, lambda))?;
            let points: Vec<serde_json::Value> = at
                .iter()
                .map(|&u| {
                    let s = b.line(Jet::<7, 1>::var_u(u), &c);
                    let res = rho * s.deriv(6, 0) + eta * s.deriv(4, 0) + lambda * s.deriv(2, 0);
                    serde_json::json!({"u": u, "s": s.deriv(0, 0), "s_u": s.deriv(1, 0), "s_uu": s.deriv(2, 0), "residual": res})
                })
                .collect();
            let finite = |v: &serde_json::Value| v.as_f64().is_some_and(f64::is_finite);
            if let Some(p) = points.iter().find(|p| {
                !["s", "s_u", "s_uu", "residual"]
                    .iter()
                    .all(|k| finite(&p[k]))
            }) {
                anyhow::bail!(
                    "S(u = {}) is not finite in double precision for --rho {rho} --eta {eta} --lambda {lambda} and these --bc (scale the boundary values or the parameters down)",
                    p["u"]
                );
            }
            if json {
                super::print_json(
                    &serde_json::json!({"case": b.case.name(), "rcond": b.rcond, "points": points}),
                )?;
            } else {
                println!("case: {}", b.case.name());
                for p in &points {
                    println!(
                        "u = {}  S = {}  S' = {}  S'' = {}  residual = {:.3e}",
                        p["u"],
                        p["s"],
                        p["s_u"],
                        p["s_uu"],
                        p["residual"].as_f64().unwrap_or(f64::NAN)
                    );
                }
            }
            Ok(0)
        }
    }
}
