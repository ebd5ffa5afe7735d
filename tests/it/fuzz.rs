//! The fuzz harness (tests/it/fuzz_harness.rs) for a fixed number of cases
//! from a fixed seed: no panic, no hang, no non-finite output. More cases:
//! `cargo run --release --example fuzz -- --cases N [--seed S]`.

use super::fuzz_harness::{run_commands, run_parsers, table};
use std::path::PathBuf;
use std::time::Duration;

/// Cases per target in `cargo test` (a few seconds in total).
const PARSER_CASES: usize = 150;
const COMMAND_CASES: usize = 12;
const SEED: u64 = 18;
/// Per-case time limit (debug build of the library, busy machine).
const LIMIT: Duration = Duration::from_secs(20);

#[test]
fn parsers_never_panic_hang_or_return_non_finite_numbers() {
    let t = run_parsers(PARSER_CASES, SEED, LIMIT);
    let failures: Vec<_> = t.iter().filter(|t| t.failures() > 0).collect();
    assert!(failures.is_empty(), "{}\n{failures:#?}", table(&t));
    // the generators reach the accepting paths, not only the errors
    for name in [
        "OBJ documents",
        "PLY documents",
        "STL documents",
        "GLB documents",
        "pde4 spec JSON",
        "GEC JSON",
        "SVG drawings",
        "character documents",
        "edits",
    ] {
        let x = t.iter().find(|x| x.name == name).expect("target");
        assert!(x.accepted > 0, "{name} never accepted: {}", table(&t));
    }
}

#[test]
fn commands_never_panic_hang_or_print_non_finite_numbers() {
    let exe = PathBuf::from(env!("CARGO_BIN_EXE_pdesculpt"));
    let scratch = std::env::temp_dir().join(format!("pdesculpt-fuzz-{}", std::process::id()));
    let t = run_commands(&exe, &scratch, COMMAND_CASES, SEED, LIMIT);
    let _ = std::fs::remove_dir_all(&scratch);
    let failures: Vec<_> = t.iter().filter(|t| t.failures() > 0).collect();
    assert!(failures.is_empty(), "{}\n{failures:#?}", table(&t));
}
