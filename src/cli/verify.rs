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
