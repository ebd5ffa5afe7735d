//! `pdesculpt gec`: fit closed cross sections by generalized elliptic curves
//! (paper 000 eq 16, paper 002 eq 1) and evaluate fitted curves.
//!
//! * `gec fit --input FILE [--terms J | --tol E] [--param P] [--solver S] [-o GEC.json]`
//! * `gec eval --gec GEC.json (--at T ... | --samples N) [--derivative K] [--turns]`
//!
//! `fit`: with the global `--json` the report goes to stdout as JSON;
//! without it a human summary goes to stderr and nothing to stdout. `eval`
//! prints its values on stdout (one `t x y z` line per parameter, or JSON).

use anyhow::Context;
use pdesculpt::curve::gec::input::{parse_points, PointsFile as Input};
use std::path::Path;

mod eval;
mod fit;
mod help;
use help::{EVAL_FORMATS, FORMATS};

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
    Fit(fit::Args),
    /// Evaluates a fitted GEC (points or derivatives) at given parameters.
    #[command(after_long_help = EVAL_FORMATS)]
    Eval(eval::Args),
}

fn read_input(path: &Path) -> anyhow::Result<Input> {
    let text = pdesculpt::mesh::io::read_input_text(path, "points file")
        .with_context(|| format!("reading {}", path.display()))?;
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
        Command::Fit(a) => fit::run(a, json),
        Command::Eval(a) => eval::run(a, json),
    }
}
