//! `pdesculpt verify [--family F] [--json]`: run the check registry.

use pdesculpt::verify as check;

/// Arguments of `pdesculpt verify`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Only this family: jet, mesh, surface, gec, pde4, plate, pde6, ode6,
    /// conv, profile, sketch, template, edit, sasm, body, derivatives.
    #[arg(long)]
    pub family: Option<String>,
    /// Print only failing checks in the table.
    #[arg(long)]
    pub failures: bool,
    /// Write the equation index (markdown: paper, equation, implementing
    /// function, checks, ERRATA entries) generated from every family's
    /// checks to this file, e.g. docs/equations.md, instead of the table.
    #[arg(long, value_name = "FILE", conflicts_with = "family")]
    pub index: Option<std::path::PathBuf>,
}

/// Runs the checks; exit code 1 when any fails.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    if let Some(f) = &args.family {
        if !check::families().iter().any(|x| x.name == f) {
            let names: Vec<&str> = check::families().iter().map(|x| x.name).collect();
            anyhow::bail!(
                "unknown family {f:?} (expected one of {})",
                names.join(", ")
            );
        }
    }
    let progress = pdesculpt::progress::Progress::spinner("verify: running the checks", json);
    let checks = check::run(args.family.as_deref());
    progress.finish();
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
        println!(
            "{:<8} {:<5} {:<16} {:<14} {:<48} {:>11} {:>9}  result",
            "family", "paper", "equation", "kind", "name", "measured", "tol"
        );
        for c in checks.iter().filter(|c| !args.failures || !c.passed) {
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
    Ok(if failed == 0 { 0 } else { 1 })
}
