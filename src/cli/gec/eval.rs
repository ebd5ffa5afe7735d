//! `pdesculpt gec eval`: parse, call `curve::gec::pipeline::derivatives`, print.

use anyhow::Context;
use pdesculpt::curve::gec::input::check_magnitudes;
use pdesculpt::curve::gec::pipeline::{derivatives, even_parameters};
use pdesculpt::curve::gec::Gec;
use pdesculpt::limits;
use std::path::PathBuf;

/// Arguments of `pdesculpt gec eval`.
#[derive(clap::Args, Debug)]
pub struct Args {
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
}

/// Runs `pdesculpt gec eval`.
pub fn run(a: Args, json: bool) -> anyhow::Result<i32> {
    let Args {
        gec,
        at,
        samples,
        derivative,
        turns,
    } = a;
    limits::check("--derivative", derivative, limits::GEC_DERIVATIVE)?;
    if let Some(n) = samples {
        limits::check("--samples", n, limits::GEC_SAMPLES)?;
    }
    let text = pdesculpt::mesh::io::read_input_text(&gec, "GEC file")
        .with_context(|| format!("reading {}", gec.display()))?;
    let v: serde_json::Value =
        serde_json::from_str(&text).with_context(|| format!("parsing {}", gec.display()))?;
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
        Some(n) => even_parameters(n, turns),
        None => at,
    };
    let pts = derivatives(&g, &ts, derivative, turns)?;
    if json {
        let list: Vec<serde_json::Value> = ts
            .iter()
            .zip(&pts)
            .map(|(t, p)| serde_json::json!({"t": t, "value": p}))
            .collect();
        crate::cli::print_json(&serde_json::json!({
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
