//! Longer fuzzing on demand (the same harness as `cargo test`'s fuzz tests):
//!
//! ```text
//! cargo build --release
//! cargo run --release --example fuzz -- --cases 2000 [--command-cases 200] [--seed 18] [--limit-secs 10]
//! ```
//!
//! Targets: every parser and command of the harness, including the new
//! surfaces of issue 35 (SVG drawings, character documents, edits, and
//! `character edit` through the binary). `.ci/run` runs it for a fixed
//! budget with a fixed seed.
//!
//! Prints a markdown table (inputs, accepted, panics, hangs, non-finite
//! outputs per parser and per command) and the first failing input of each
//! target; exits 1 if any case failed. Commands run the release binary
//! beside this example (target/release/pdesculpt).

#[path = "../tests/it/fuzz_harness.rs"]
mod fuzz_harness;

use std::time::Duration;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let get = |flag: &str, default: u64| -> u64 {
        match args.iter().position(|a| a == flag) {
            Some(i) => match args.get(i + 1).and_then(|v| v.parse().ok()) {
                Some(v) => v,
                None => {
                    eprintln!("error: {flag} needs a non-negative integer");
                    std::process::exit(2)
                }
            },
            None => default,
        }
    };
    let cases = get("--cases", 1000) as usize;
    let command_cases = get("--command-cases", (cases / 10).max(1) as u64) as usize;
    let seed = get("--seed", 18);
    let limit = Duration::from_secs(get("--limit-secs", 10));
    let exe = std::env::current_exe()
        .ok()
        .and_then(|p| p.parent()?.parent().map(|d| d.join("pdesculpt")))
        .filter(|p| p.exists());
    let mut tallies = fuzz_harness::run_parsers(cases, seed, limit);
    match exe {
        Some(exe) => {
            let scratch = std::env::temp_dir().join(format!("pdesculpt-fuzz-{}", std::process::id()));
            tallies.extend(fuzz_harness::run_commands(&exe, &scratch, command_cases, seed, limit));
            // the heavy targets (a character build per case) with a tenth of the cases
            tallies.extend(fuzz_harness::run_command_targets(
                fuzz_harness::heavy_command_targets(),
                &exe,
                &scratch,
                (command_cases / 10).max(1),
                seed,
                limit,
            ));
            let _ = std::fs::remove_dir_all(&scratch);
        }
        None => eprintln!("warning: no pdesculpt binary beside the example; run `cargo build --release` first (commands skipped)"),
    }
    println!("seed {seed}, {cases} cases per parser, {command_cases} per command, limit {limit:?} per case\n");
    print!("{}", fuzz_harness::table(&tallies));
    let total: usize = tallies.iter().map(|t| t.cases).sum();
    let failed: usize = tallies.iter().map(|t| t.failures()).sum();
    println!("\ntotal inputs {total}, failures {failed}");
    for t in &tallies {
        if let Some(f) = &t.first_failure {
            println!("\n{}: {f}", t.name);
        }
    }
    std::process::exit(i32::from(failed > 0));
}
