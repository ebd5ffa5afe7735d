//! `pdesculpt pde4`: fourth-order sculpting deformations (paper 000 sec 3.1).
//!
//! ## The JSON spec
//! ```json
//! {
//!   "patch": "two-sided",            // or "four-sided"
//!   "method": "exact",               // two-sided: exact | paper | least-squares; four-sided: galerkin | paper
//!   "shape": {"a1": 1.0, "a2": 2.0, "a3": 1.0},   // or a list of three, one per x, y, z
//!   "terms": [16, 8],                // [M, N], 1..=256 (N may be 0 for two-sided)
//!   "forces": [
//!     {"type": "concentrated", "u0": 0.5, "v0": 0.25, "p": [0, 0, 1]},
//!     {"type": "line", "u0": 0.2, "u1": 0.7, "v0": 0.5, "p": [0, 1, 0]},
//!     {"type": "area", "u0": 0.2, "u1": 0.7, "v0": 0.1, "v1": 0.4, "p": [1, 0, 0]},
//!     {"type": "uniform", "p": [0, 0, 1]}
//!   ],
//!   "boundary": null                 // two-sided exact only: {"curve0", "curve1", "tangent0", "tangent1"},
//!                                    // each {"c0": [x,y,z], "cos": [[..]..], "sin": [[..]..]} in theta = 2 pi v
//! }
//! ```
//! Parameters are patch-local in `[0, 1]`; the output is the displacement
//! `(x, y, z)(u, v)` of PDE (1).
//!
//! `eval SPEC --at u,v ...` prints displacements.
//!
//! `apply SPEC (--mesh IN | --makehuman) --out OUT --drag D` deforms a mesh
//! with the first component `w` of the spec (each moved vertex goes `s w d`,
//! `d` the vertex normal or `--direction`, `s` making the largest move `D`):
//! * `--curve CURVE.json` (four-sided spec): the region enclosed by a closed
//!   curve (a JSON list of `[x, y, z]`), re-parameterised onto the unit square
//!   (000 Fig 14);
//! * `--axis x0,y0,z0,x1,y1,z1 [--u-range a,b] [--radius R]` (two-sided spec):
//!   a part closed in v (a limb, a torso), parameterised cylindrically about
//!   the axis (u along it, v the angle), deformed over the u-range.

use anyhow::{bail, Context};
use pdesculpt::pde4::apply::{deform_part, deform_region, Direction};
use pdesculpt::pde4::spec::{Patch, PatchKind, Spec};
use pdesculpt::surface::Surface;
use std::path::PathBuf;

/// Arguments of `pdesculpt pde4`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(clap::Subcommand, Debug)]
enum Cmd {
    /// Evaluate a deformation spec at parameter points.
    Eval {
        /// The JSON spec (see `pdesculpt pde4 --help` and src/cli/pde4.rs).
        spec: PathBuf,
        /// A parameter point `u,v` (repeatable).
        #[arg(long = "at", required = true, allow_hyphen_values = true)]
        at: Vec<String>,
    },
    /// Deform a mesh: the region enclosed by a closed curve (four-sided
    /// spec, --curve) or a u-range of a part closed in v (two-sided spec, --axis).
    Apply {
        /// The JSON spec (its x component is the profile).
        spec: PathBuf,
        /// JSON list of `[x, y, z]` points of the closed curve (four-sided spec).
        #[arg(long, required_unless_present = "axis", conflicts_with = "axis")]
        curve: Option<PathBuf>,
        /// Part axis `x0,y0,z0,x1,y1,z1` (two-sided spec): u runs from the first point to the second.
        #[arg(long, allow_hyphen_values = true)]
        axis: Option<String>,
        /// Range `a,b` of the axis fraction deformed (with --axis; default
        /// 0,1: the whole axis).
        #[arg(long, requires = "axis", allow_hyphen_values = true)]
        u_range: Option<String>,
        /// Move only vertices within this distance of the axis (with --axis).
        #[arg(
            long,
            default_value_t = pdesculpt::pde4::apply::RADIUS_DEFAULT,
            requires = "axis",
            allow_hyphen_values = true
        )]
        radius: f64,
        /// Input mesh (OBJ/GLB/glTF/STL/PLY).
        #[arg(long, conflicts_with = "makehuman")]
        mesh: Option<PathBuf>,
        /// Use the MakeHuman base body.
        #[arg(long)]
        makehuman: bool,
        /// Output mesh (format from the extension).
        #[arg(long)]
        out: PathBuf,
        /// Largest displacement (the drag distance; negative: inward).
        #[arg(long, allow_hyphen_values = true)]
        drag: f64,
        /// Move only vertices within this distance of the curve plane (with --curve).
        #[arg(long, default_value_t = pdesculpt::pde4::apply::DEPTH_DEFAULT, allow_hyphen_values = true)]
        depth: f64,
        /// Direction `x,y,z`; default the vertex normals.
        #[arg(long, allow_hyphen_values = true)]
        direction: Option<String>,
        #[command(flatten)]
        units: super::units::UnitArgs,
    },
}

fn parse_list(s: &str, n: usize, what: &str) -> anyhow::Result<Vec<f64>> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .with_context(|| format!("{what} '{s}' is not a comma-separated list of numbers"))?;
    if v.len() != n || v.iter().any(|x| !x.is_finite()) {
        bail!("{what} '{s}' needs {n} finite numbers");
    }
    Ok(v)
}

fn load_spec(path: &std::path::Path) -> anyhow::Result<Spec> {
    let text = pdesculpt::mesh::io::read_input_text(path, "spec")
        .with_context(|| format!("reading {}", path.display()))?;
    serde_json::from_str(&text).with_context(|| format!("parsing spec {}", path.display()))
}

/// Runs `pdesculpt pde4`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.cmd {
        Cmd::Eval { spec, at } => eval(&spec, &at, json),
        Cmd::Apply {
            spec,
            curve,
            axis,
            u_range,
            radius,
            mesh,
            makehuman,
            out,
            drag,
            depth,
            direction,
            units,
        } => {
            pdesculpt::mesh::io::Format::from_path(&out)?;
            let inputs: Vec<&std::path::Path> = [Some(&spec), curve.as_ref(), mesh.as_ref()]
                .into_iter()
                .flatten()
                .map(|p| p.as_path())
                .collect();
            pdesculpt::mesh::io::refuse_overwriting_input(&inputs, &out)?;
            let sp = load_spec(&spec)?;
            let want = if curve.is_some() {
                PatchKind::FourSided
            } else {
                PatchKind::TwoSided
            };
            if sp.patch != want {
                bail!(
                    "'apply --curve' needs a four-sided spec (the region is re-parameterised onto the unit square); 'apply --axis' needs a two-sided spec (the part is closed in v)"
                );
            }
            let patch: Patch = sp.solve()?;
            let base = match (mesh, makehuman) {
                (Some(p), false) => pdesculpt::mesh::io::read(&p)?,
                (None, true) => pdesculpt::makehuman::base_body()?.mesh,
                _ => bail!("give --mesh PATH or --makehuman"),
            };
            let dir = match direction {
                Some(d) => {
                    let v = parse_list(&d, 3, "--direction")?;
                    Direction::Vector([v[0], v[1], v[2]])
                }
                None => Direction::Normal,
            };
            let r = deform(
                &base, curve, axis, u_range, radius, &patch, dir, drag, depth,
            )?;
            let source = match makehuman {
                true => pdesculpt::mesh::unit::MAKEHUMAN,
                false => units.input_unit,
            };
            let unit = units.write(&r.mesh, &out, source)?;
            eprintln!(
                "moved {} vertices, magnitude {:.6e}",
                r.region.len(),
                r.magnitude
            );
            if json {
                super::print_json(
                    &serde_json::json!({"moved": r.region.len(), "magnitude": r.magnitude, "out": out, "unit": unit}),
                )?;
            }
            Ok(0)
        }
    }
}

/// `pde4 eval`: the patch's displacement at each `--at u,v`.
fn eval(spec: &std::path::Path, at: &[String], json: bool) -> anyhow::Result<i32> {
    let sp = load_spec(spec)?;
    let patch = sp.solve()?;
    let mut rows = Vec::new();
    for a in at {
        let uv = parse_list(a, 2, "--at")?;
        if !(0.0..=1.0).contains(&uv[0]) || !(0.0..=1.0).contains(&uv[1]) {
            bail!("--at {a}: u and v must lie in [0, 1]");
        }
        let p = patch.point(uv[0], uv[1]);
        if p.iter().any(|x| !x.is_finite()) {
            bail!("non-finite displacement at {a} (printed coefficients singular for these parameters?)");
        }
        rows.push(serde_json::json!({"u": uv[0], "v": uv[1], "t": p}));
        if !json {
            println!(
                "u={} v={}  t=({:.9e}, {:.9e}, {:.9e})",
                uv[0], uv[1], p[0], p[1], p[2]
            );
        }
    }
    if json {
        super::print_json(&serde_json::json!({"spec": sp, "points": rows}))?;
    }
    Ok(0)
}

/// `pde4 apply`'s deformation: a region inside `--curve` (four-sided spec)
/// or a part along `--axis` (two-sided spec).
fn deform(
    base: &pdesculpt::mesh::Mesh,
    curve: Option<PathBuf>,
    axis: Option<String>,
    u_range: Option<String>,
    radius: f64,
    patch: &Patch,
    dir: Direction,
    drag: f64,
    depth: f64,
) -> anyhow::Result<pdesculpt::pde4::apply::RegionDeformation> {
    Ok(match (curve, axis) {
        (Some(curve), _) => {
            let text = pdesculpt::mesh::io::read_input_text(&curve, "curve file")
                .with_context(|| format!("reading {}", curve.display()))?;
            let pts: Vec<[f64; 3]> = serde_json::from_str(&text).with_context(|| {
                format!("parsing curve {} (a list of [x, y, z])", curve.display())
            })?;
            deform_region(base, &pts, patch, dir, drag, depth)?
        }
        (None, Some(axis)) => {
            let a = parse_list(&axis, 6, "--axis")?;
            let r = match &u_range {
                Some(t) => parse_list(t, 2, "--u-range").map(|r| (r[0], r[1]))?,
                None => pdesculpt::pde4::apply::U_RANGE_DEFAULT,
            };
            deform_part(
                base,
                ([a[0], a[1], a[2]], [a[3], a[4], a[5]]),
                r,
                radius,
                patch,
                dir,
                drag,
            )?
        }
        (None, None) => bail!("give --curve CURVE.json or --axis x0,y0,z0,x1,y1,z1"),
    })
}
