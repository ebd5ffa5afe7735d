//! `pdesculpt verify [--family F]... [--timings] [--json]`: run the check
//! registry.

use pdesculpt::check::Check;
use pdesculpt::verify as check;

/// Arguments of `pdesculpt verify`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Only these families (repeatable): jet, mesh, surface, gec, pde4,
    /// plate, pde6, ode6, conv, profile, sketch, template, edit, sasm, body,
    /// derivatives. The studies that used to run here (every MakeHuman
    /// morph's body, the template study's other cases, the data-size study)
    /// are `pdesculpt study NAME`.
    #[arg(long)]
    pub family: Vec<String>,
    /// Print only failing checks in the table.
    #[arg(long)]
    pub failures: bool,
    /// Print each family's wall time on stderr (families run in parallel).
    #[arg(long)]
    pub timings: bool,
    /// Write the equation index (markdown: paper, equation, implementing
    /// function, checks, ERRATA entries) generated from every family's
    /// checks to this file, e.g. docs/equations.md, instead of the table.
    #[arg(long, value_name = "FILE", conflicts_with = "family")]
    pub index: Option<std::path::PathBuf>,
}

/// Runs the checks; exit code 1 when any fails.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    for f in &args.family {
        if !check::families().iter().any(|x| x.name == f) {
            let names: Vec<&str> = check::families().iter().map(|x| x.name).collect();
            anyhow::bail!(
                "unknown family {f:?} (expected one of {})",
                names.join(", ")
            );
        }
    }
    let names: Vec<&str> = args.family.iter().map(String::as_str).collect();
    let progress = pdesculpt::progress::Progress::spinner("verify: running the checks", json);
    let (checks, times) = check::run_timed(&names);
    progress.finish();
    if args.timings {
        for (name, s) in &times {
            eprintln!("verify: {name:<12} {s:7.3} s");
        }
    }
    let failed = checks.iter().filter(|c| !c.passed).count();
    if let Some(path) = &args.index {
        let text = pdesculpt::equations::index_markdown(&checks, pdesculpt::equations::ERRATA);
        pdesculpt::mesh::io::write_atomic(path, text.as_bytes())?;
        eprintln!("wrote {} ({} checks)", path.display(), checks.len());
        if json {
            super::print_json(&serde_json::json!({
                "index": path.display().to_string(),
                "total": checks.len(),
                "failed": failed,
            }))?;
        }
        return Ok(if failed == 0 { 0 } else { 1 });
    }
    if json {
        super::print_json(&serde_json::json!({
            "checks": checks,
            "total": checks.len(),
            "failed": failed,
        }))?;
    } else {
        print_table(&checks, args.failures);
    }
    Ok(if failed == 0 { 0 } else { 1 })
}

/// The table of checks on stdout (only the failing ones with `failures`)
/// and the count line.
pub fn print_table(checks: &[Check], failures: bool) {
    let failed = checks.iter().filter(|c| !c.passed).count();
    println!(
        "{:<8} {:<5} {:<16} {:<14} {:<48} {:>11} {:>9}  result",
        "family", "paper", "equation", "kind", "name", "measured", "tol"
    );
    for c in checks.iter().filter(|c| !failures || !c.passed) {
        let verdict = match (c.passed, c.paper_differs) {
            (true, true) => "ok (differs, as ERRATA.md records)",
            (true, false) => "ok",
            (false, _) => "FAILED",
        };
        println!(
            "{:<8} {:<5} {:<16} {:<14} {:<48} {:>11.3e} {:>9.1e}  {}",
            c.family, c.paper, c.equation, c.kind, c.name, c.measured, c.tolerance, verdict
        );
    }
    println!("{} checks, {} failed", checks.len(), failed);
}
