//! `pdesculpt gec fit`: parse, call `curve::gec::pipeline::fit_points`, print.

use super::{locate, read_input, FrameArg, SolverArg};
use pdesculpt::curve::gec::pipeline::{fit_points, FitFailure, FitRequest, Method, Plane};
use pdesculpt::curve::gec::{GecError, Param};
use pdesculpt::limits;
use std::path::PathBuf;

/// Arguments of `pdesculpt gec fit`.
#[derive(clap::Args, Debug)]
pub struct Args {
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
    #[arg(long, default_value_t = pdesculpt::curve::gec::pipeline::DEFAULT_MAX_TERMS)]
    max_terms: usize,
    /// How points get their angle: uniform (index), chord (length),
    /// centripetal, polar (angle about the centroid; star-shaped only).
    #[arg(long, default_value = FitRequest::default().param.name())]
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
}

/// Runs `pdesculpt gec fit`.
pub fn run(a: Args, json: bool) -> anyhow::Result<i32> {
    let Args {
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
    } = a;
    let param: Param = param.parse().map_err(|e: GecError| anyhow::anyhow!(e))?;
    if let Some(t) = terms {
        limits::check("--terms", t, limits::GEC_TERMS)?;
    }
    limits::check("--max-terms", max_terms, limits::GEC_TERMS)?;
    if let Some(out) = &output {
        pdesculpt::mesh::io::refuse_overwriting_input(&[&input], out)?;
    }
    let inp = read_input(&input)?;
    let name = input.display().to_string();
    let req = FitRequest {
        terms,
        tol,
        max_terms,
        param,
        theta0,
        method: match solver {
            SolverArg::Qr => Method::Qr,
            SolverArg::Normal => Method::Normal,
            SolverArg::Fft => Method::Fft,
        },
        plane: frame.map(|f| match f {
            FrameArg::Auto => Plane::Auto,
            FrameArg::Z => Plane::Z,
        }),
        assume_closed,
    };
    let outcome = fit_points(&inp, &req).map_err(|e| failure(e, &name, &inp))?;
    let report = &outcome.report;
    let dropped = outcome.dropped_closing_copy;
    let g = &report.gec;
    if let Some(out) = &output {
        let bytes = serde_json::to_vec_pretty(g)?;
        pdesculpt::mesh::io::write_atomic(out, &bytes)?;
    }
    let (x000, y000) = g.to_paper_000();
    let [ax, bx, ay, by] = g.to_paper_002();
    if json {
        crate::cli::print_json(&serde_json::json!({
            "input": name, "points": outcome.points, "columns": inp.columns,
            "dropped_closing_copy": dropped, "terms": g.terms(), "param": param.name(),
            "solver": format!("{solver:?}").to_lowercase(), "tol": tol, "theta0": theta0,
            "gec": g, "errors": report.errors, "off_plane": report.off_plane,
            "area": g.area(), "arc_length": g.arc_length(),
            "paper_000": {"x": x000, "y": y000},
            "paper_002": {"a_x": ax, "b_x": bx, "a_y": ay, "b_y": by},
            "output": output.as_ref().map(|o| o.display().to_string()),
        }))?;
    } else {
        print_table(&name, &outcome, param, solver, output.as_deref());
    }
    Ok(0)
}

/// The error `gec fit` reports for a failed fit, naming the input and the
/// point (with its line) where the failure is one point's.
fn failure(
    e: FitFailure,
    name: &str,
    inp: &pdesculpt::curve::gec::input::PointsFile,
) -> anyhow::Error {
    match e {
        FitFailure::Theta0(_) | FitFailure::NotFlat | FitFailure::FftNeedsTerms => {
            anyhow::anyhow!(e)
        }
        FitFailure::Open(e) => {
            anyhow::Error::from(e).context(format!("{name} (pass --assume-closed if it is closed)"))
        }
        FitFailure::Gec(GecError::NonFinite { index, .. }) => {
            anyhow::anyhow!("{name}: {} is not finite", locate(inp, index))
        }
        FitFailure::Gec(GecError::RepeatedPoint { first, second }) => anyhow::anyhow!(
            "{name}: {} and {} coincide; remove repeated points",
            locate(inp, first),
            locate(inp, second)
        ),
        other => anyhow::anyhow!("{name}: {other}"),
    }
}

/// The human-readable report of `gec fit` on stderr.
fn print_table(
    name: &str,
    outcome: &pdesculpt::curve::gec::pipeline::FitOutcome,
    param: Param,
    solver: SolverArg,
    output: Option<&std::path::Path>,
) {
    let report = &outcome.report;
    let dropped = outcome.dropped_closing_copy;
    let g = &report.gec;
    let e = &report.errors;
    eprintln!(
        "{name}: {} points{}, J = {}, param {}, solver {solver:?}",
        outcome.points,
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
    if let Some(out) = output {
        eprintln!("wrote {}", out.display());
    }
}
