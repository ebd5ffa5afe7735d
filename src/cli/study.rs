//! `pdesculpt study NAME [--json]`: run a study (an experiment over many
//! inputs; [`pdesculpt::study`]) and print its table and checks.

use pdesculpt::study;

/// Arguments of `pdesculpt study`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The study: bodies (every checked MakeHuman morph reconstructed
    /// closed), template (the MakeHuman template study's other cases),
    /// data-size (000 Fig 13's table); `list` prints them.
    pub name: String,
    /// Print only failing checks in the check table.
    #[arg(long)]
    pub failures: bool,
}

/// Runs the study; exit code 1 when any of its checks fails.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    if args.name == "list" {
        for s in study::studies() {
            println!("{:<10} {}", s.name, s.about);
        }
        return Ok(0);
    }
    let Some(s) = study::studies().iter().find(|s| s.name == args.name) else {
        let names: Vec<&str> = study::studies().iter().map(|s| s.name).collect();
        anyhow::bail!(
            "unknown study {:?} (expected one of {}, or list)",
            args.name,
            names.join(", ")
        );
    };
    eprintln!("study {}: {}", s.name, s.about);
    let t0 = std::time::Instant::now();
    let r = (s.run)();
    eprintln!("study {}: {:.1} s", s.name, t0.elapsed().as_secs_f64());
    let failed = r.checks.iter().filter(|c| !c.passed).count();
    if json {
        super::print_json(&serde_json::json!({
            "study": s.name,
            "columns": r.columns,
            "rows": r.rows,
            "checks": r.checks,
            "total": r.checks.len(),
            "failed": failed,
        }))?;
    } else {
        println!("{}", r.columns.join("\t"));
        for row in &r.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|v| match v {
                    serde_json::Value::Number(n) => match n.as_f64() {
                        Some(x) if n.is_f64() => format!("{x:.4e}"),
                        _ => n.to_string(),
                    },
                    serde_json::Value::String(s) => s.clone(),
                    other => other.to_string(),
                })
                .collect();
            println!("{}", cells.join("\t"));
        }
        println!();
        super::verify::print_table(&r.checks, args.failures);
    }
    Ok(if failed == 0 { 0 } else { 1 })
}
