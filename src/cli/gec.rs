//! `pdesculpt gec`: fit closed cross sections by generalized elliptic curves
//! (paper 000 eq 16, paper 002 eq 1) and evaluate fitted curves.
//!
//! * `gec fit --input FILE [--terms J | --tol E] [--param P] [--solver S] [-o GEC.json]`
//! * `gec eval --gec GEC.json (--at T ... | --samples N) [--derivative K] [--turns]`
//!
//! `fit`: with the global `--json` the report goes to stdout as JSON;
//! without it a human summary goes to stderr and nothing to stdout. `eval`
//! prints its values on stdout (one `t x y z` line per parameter, or JSON).

use anyhow::{bail, Context};
use pdesculpt::curve::gec::fit::{
    check_scale, fit, fit_auto, fit_fft, FitOptions, FitReport, FrameChoice,
};
use pdesculpt::curve::gec::input::{check_magnitudes, parse_points, PointsFile as Input};
use pdesculpt::curve::gec::{
    check_closed, repeated_points, strip_closing_copy, Frame, Gec, GecError, Param, Solver,
};
use pdesculpt::limits;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

const FORMATS: &str = "\
INPUT FORMATS (--input; JSON if the file starts with '[' or '{', CSV otherwise):
  CSV   one point per line, 'x,y' or 'x,y,z' (commas, or blanks/tabs/semicolons);
        every row has the same number of fields; an optional header line of
        names (e.g. 'x,y,z') as the first row; blank lines and lines starting
        with '#' are ignored, except that a line '# open' declares the
        polyline open (rejected).
  JSON  an array of points [[x, y], ...] or [[x, y, z], ...], or an object
        {\"points\": [...], \"closed\": true|false}; \"closed\": false declares
        the polyline open (rejected).
  2-column points lie in the plane z = 0.

THE POLYLINE must be closed, planar, with distinct points, in order along the
curve; the first point is not repeated at the end (a closing copy is dropped).
It is taken as OPEN, and rejected, when declared open or when the gap from
the last point back to the first is more than 10 times the median segment
and longer than every other segment (e.g. an arc missing a piece);
--assume-closed skips that test. Needs at least 2J+1 points.

PLANE: with --frame z (the default when every point has the same z) the
coefficients are in the input's x, y coordinates, as in the papers (z = z_c);
with --frame auto (default otherwise) the plane is fitted (Newell normal,
origin at the area centroid, e1 along the projection of X).

OUTPUT: ErM = max over input points of the distance to the fitted curve, ErA
= its mean (units of the input; *_rel: divided by the in-plane bounding-box
diagonal). -o writes the fitted curve as JSON {\"frame\": {\"origin\", \"e1\",
\"e2\"}, \"centre\": [x0, y0], \"x\": [[a_xn, b_xn], ...], \"y\": [[a_yn, b_yn],
...]} (x takes (cos, sin) pairs, y (sin, cos) pairs, angle theta in [0, 2 pi)),
the input of 'gec eval --gec' and of 'pde6 patch' sections.";

const EVAL_FORMATS: &str = "\
GEC.json: the file written by 'gec fit -o', or the JSON report of 'gec fit
--json' (its \"gec\" field). The parameter is the angle theta in [0, 2 pi)
(paper 002's v); with --turns it is paper 000's v in [0, 1] (theta = 2 pi v),
and derivatives are taken with respect to v.
Output: one line 't x y z' per parameter on stdout, or with --json
{\"derivative\": k, \"unit\": \"rad\"|\"turn\", \"points\": [{\"t\": t, \"value\": [x, y, z]}, ...]}.";

/// Arguments of `pdesculpt gec`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: Command,
}

/// Least-squares solver.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum SolverArg {
    /// Householder QR of the design matrix (default).
    Qr,
    /// Cholesky of the normal equations.
    Normal,
    /// Uniform resampling in the parameter, then a truncated FFT.
    Fft,
}

/// Plane of the curve.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameArg {
    /// Fitted plane.
    Auto,
    /// The plane z = z of the points (all z must be equal), axes X and Y.
    Z,
}

#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Fits a closed planar polyline by a GEC with J terms (least squares).
    #[command(after_long_help = FORMATS)]
    Fit {
        /// Points file (CSV or JSON, see below).
        #[arg(long, short)]
        input: PathBuf,
        /// Number of terms J (>= 1); the default is 10 unless --tol is given.
        #[arg(long, conflicts_with = "tol")]
        terms: Option<usize>,
        /// Smallest J whose relative ErM (ErM / bounding-box diagonal) is <= E.
        #[arg(long, allow_hyphen_values = true)]
        tol: Option<f64>,
        /// Largest J tried with --tol.
        #[arg(long, default_value_t = 30)]
        max_terms: usize,
        /// How points get their angle: uniform (index), chord (length),
        /// centripetal, polar (angle about the centroid; star-shaped only).
        #[arg(long, default_value = "chord")]
        param: String,
        /// Angle (radians) given to the first point by uniform, chord and
        /// centripetal (default: its polar angle about the area centroid).
        #[arg(long, allow_hyphen_values = true)]
        theta0: Option<f64>,
        #[arg(long, value_enum, default_value_t = SolverArg::Qr)]
        solver: SolverArg,
        /// Plane: auto or z (default: z when all points share their z).
        #[arg(long, value_enum)]
        frame: Option<FrameArg>,
        /// Do not reject a polyline whose closing gap looks like an opening.
        #[arg(long)]
        assume_closed: bool,
        /// Writes the fitted GEC (JSON) here, atomically.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Evaluates a fitted GEC (points or derivatives) at given parameters.
    #[command(after_long_help = EVAL_FORMATS)]
    Eval {
        /// GEC JSON (from 'gec fit -o').
        #[arg(long)]
        gec: PathBuf,
        /// Parameter values (repeatable): theta in radians, or v in turns with --turns.
        #[arg(long, allow_hyphen_values = true, required_unless_present = "samples")]
        at: Vec<f64>,
        /// Instead of --at: N points at theta = 2 pi k / N (a closed polyline).
        #[arg(long, conflicts_with = "at")]
        samples: Option<usize>,
        /// Order of the derivative (0..=8).
        #[arg(long, default_value_t = 0)]
        derivative: usize,
        /// Parameters are paper 000's v in [0, 1] (one turn) instead of radians.
        #[arg(long)]
        turns: bool,
    },
}

fn read_input(path: &Path) -> anyhow::Result<Input> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    parse_points(&text).with_context(|| format!("parsing {}", path.display()))
}

/// "point i" or "point i (line L)".
fn locate(input: &Input, i: usize) -> String {
    match &input.lines {
        Some(l) if i < l.len() => format!("point {i} (line {})", l[i]),
        _ => format!("point {i}"),
    }
}

/// Runs `pdesculpt gec`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Command::Fit {
            input,
            terms,
            tol,
            max_terms,
            param,
            theta0,
            solver,
            frame,
            assume_closed,
            output,
        } => {
            if let Some(t) = theta0.filter(|t| !t.is_finite()) {
                bail!("--theta0 {t}: must be finite");
            }
            let param: Param = param.parse().map_err(|e: GecError| anyhow::anyhow!(e))?;
            if let Some(t) = terms {
                limits::check("--terms", t, limits::GEC_TERMS)?;
            }
            limits::check("--max-terms", max_terms, limits::GEC_TERMS)?;
            if let Some(out) = &output {
                pdesculpt::mesh::io::refuse_overwriting_input(&[&input], out)?;
            }
            let mut inp = read_input(&input)?;
            let name = input.display().to_string();
            if inp.declared_open {
                bail!("{name}: the file declares the polyline open; a GEC needs a closed cross section");
            }
            let dropped = strip_closing_copy(&mut inp.points);
            check_scale(&inp.points).with_context(|| name.clone())?;
            if let Some((i, j)) = repeated_points(&inp.points) {
                bail!(
                    "{name}: {} and {} coincide; remove repeated points",
                    locate(&inp, i),
                    locate(&inp, j)
                );
            }
            if !assume_closed {
                check_closed(&inp.points)
                    .map_err(anyhow::Error::from)
                    .with_context(|| format!("{name} (pass --assume-closed if it is closed)"))?;
            }
            let z0 = inp.points[0][2];
            let flat = inp.points.iter().all(|p| p[2] == z0);
            let frame = match frame.unwrap_or(if flat { FrameArg::Z } else { FrameArg::Auto }) {
                FrameArg::Z if !flat => {
                    bail!("--frame z needs every point at the same z; use --frame auto")
                }
                FrameArg::Z => FrameChoice::Given(Frame::z_plane(z0)),
                FrameArg::Auto => FrameChoice::Auto,
            };
            let opts = FitOptions {
                param,
                frame,
                theta0,
                solver: if solver == SolverArg::Normal {
                    Solver::NormalEquations
                } else {
                    Solver::Qr
                },
                ..FitOptions::new(terms.unwrap_or(10))
            };
            let report: FitReport = match (tol, solver) {
                (Some(_), SolverArg::Fft) => {
                    bail!("--solver fft needs --terms (--tol uses least squares)")
                }
                (Some(e), _) => fit_auto(&inp.points, e, max_terms, &opts),
                (None, SolverArg::Fft) => {
                    let m = inp.points.len().max(4 * opts.terms + 2);
                    fit_fft(&inp.points, &opts, m)
                }
                (None, _) => fit(&inp.points, &opts),
            }
            .map_err(|e| match e {
                GecError::NonFinite { index, .. } => {
                    anyhow::anyhow!("{name}: {} is not finite", locate(&inp, index))
                }
                GecError::RepeatedPoint { first, second } => anyhow::anyhow!(
                    "{name}: {} and {} coincide",
                    locate(&inp, first),
                    locate(&inp, second)
                ),
                other => anyhow::Error::from(other).context(name.clone()),
            })?;
            let g = &report.gec;
            if !(g.is_finite() && report.errors.erm.is_finite() && report.errors.era.is_finite()) {
                bail!("{name}: the fit produced non-finite values");
            }
            if let Some(out) = &output {
                let bytes = serde_json::to_vec_pretty(g)?;
                pdesculpt::mesh::io::write_atomic(out, &bytes)?;
            }
            let (x000, y000) = g.to_paper_000();
            let [ax, bx, ay, by] = g.to_paper_002();
            if json {
                super::print_json(&serde_json::json!({
                    "input": name, "points": inp.points.len(), "columns": inp.columns,
                    "dropped_closing_copy": dropped, "terms": g.terms(), "param": param.name(),
                    "solver": format!("{solver:?}").to_lowercase(), "tol": tol, "theta0": theta0,
                    "gec": g, "errors": report.errors, "off_plane": report.off_plane,
                    "area": g.area(), "arc_length": g.arc_length(),
                    "paper_000": {"x": x000, "y": y000},
                    "paper_002": {"a_x": ax, "b_x": bx, "a_y": ay, "b_y": by},
                    "output": output.as_ref().map(|o| o.display().to_string()),
                }))?;
            } else {
                let e = &report.errors;
                eprintln!(
                    "{name}: {} points{}, J = {}, param {}, solver {solver:?}",
                    inp.points.len(),
                    if dropped {
                        " (closing copy dropped)"
                    } else {
                        ""
                    },
                    g.terms(),
                    param.name()
                );
                eprintln!(
                    "  ErM {:.6e}  ErA {:.6e}  (relative to diagonal {:.4e}: {:.3e}, {:.3e})",
                    e.erm, e.era, e.scale, e.erm_rel, e.era_rel
                );
                eprintln!(
                    "  centre (x0, y0) = ({:.9e}, {:.9e}); plane origin {:?}",
                    g.centre[0], g.centre[1], g.frame.origin
                );
                eprintln!("   n   a_xn (cos)       b_xn (sin)       a_yn (sin)       b_yn (cos)");
                for n in 0..g.terms() {
                    eprintln!(
                        "  {:>2} {:>16.9e} {:>16.9e} {:>16.9e} {:>16.9e}",
                        n + 1,
                        g.x[n][0],
                        g.x[n][1],
                        g.y[n][0],
                        g.y[n][1]
                    );
                }
                if let Some(out) = &output {
                    eprintln!("wrote {}", out.display());
                }
            }
            Ok(0)
        }
        Command::Eval {
            gec,
            at,
            samples,
            derivative,
            turns,
        } => {
            limits::check("--derivative", derivative, limits::GEC_DERIVATIVE)?;
            if let Some(n) = samples {
                limits::check("--samples", n, limits::GEC_SAMPLES)?;
            }
            let text = std::fs::read_to_string(&gec)
                .with_context(|| format!("reading {}", gec.display()))?;
            let v: serde_json::Value = serde_json::from_str(&text)
                .with_context(|| format!("parsing {}", gec.display()))?;
            let v = v.get("gec").cloned().unwrap_or(v);
            let g: Gec = serde_json::from_value(v).with_context(|| {
                format!(
                    "{}: expected a GEC {{\"frame\", \"centre\", \"x\", \"y\"}}",
                    gec.display()
                )
            })?;
            let g = Gec::new(g.frame, g.centre, g.x, g.y)
                .with_context(|| format!("{}: invalid GEC", gec.display()))?;
            check_magnitudes(&g).with_context(|| format!("{}: invalid GEC", gec.display()))?;
            let ts: Vec<f64> = match samples {
                Some(n) => (0..n)
                    .map(|k| {
                        let f = k as f64 / n as f64;
                        if turns {
                            f
                        } else {
                            2.0 * PI * f
                        }
                    })
                    .collect(),
                None => at,
            };
            if let Some(t) = ts.iter().find(|t| !t.is_finite()) {
                bail!("--at {t}: must be finite");
            }
            let factor = if turns {
                (2.0 * PI).powi(derivative as i32)
            } else {
                1.0
            };
            let pts: Vec<[f64; 3]> = ts
                .iter()
                .map(|&t| {
                    let theta = if turns { 2.0 * PI * t } else { t };
                    let d = g.derivative(theta, derivative);
                    [d[0] * factor, d[1] * factor, d[2] * factor]
                })
                .collect();
            if pts.iter().flatten().any(|x| !x.is_finite()) {
                bail!("non-finite value (parameter too large?)");
            }
            if json {
                let list: Vec<serde_json::Value> = ts
                    .iter()
                    .zip(&pts)
                    .map(|(t, p)| serde_json::json!({"t": t, "value": p}))
                    .collect();
                super::print_json(&serde_json::json!({
                    "derivative": derivative, "unit": if turns { "turn" } else { "rad" },
                    "terms": g.terms(), "points": list,
                }))?;
            } else {
                for (t, p) in ts.iter().zip(&pts) {
                    println!("{t:.17e} {:.17e} {:.17e} {:.17e}", p[0], p[1], p[2]);
                }
            }
            Ok(0)
        }
    }
}
