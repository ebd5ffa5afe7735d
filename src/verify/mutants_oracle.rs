//! The oracle of mutation testing (`scripts/mutants.sh`, issue 31): one
//! family's checks, run inside the library's unit-test binary so that each
//! mutant costs one incremental build of the library in test mode.
//!
//! Ignored in the normal suite (the registry test in `tests/it/registry.rs`
//! already asserts that every check passes); `scripts/mutants.sh` runs it
//! with `--include-ignored` and the family in `PDESCULPT_MUTANTS_FAMILY`,
//! together with the family's own unit tests.

#[test]
#[ignore = "mutation-testing oracle: scripts/mutants.sh sets PDESCULPT_MUTANTS_FAMILY"]
fn family_checks_pass() {
    let family = std::env::var("PDESCULPT_MUTANTS_FAMILY")
        .expect("PDESCULPT_MUTANTS_FAMILY names the family whose checks are the oracle");
    let checks = super::run(Some(&family));
    assert!(!checks.is_empty(), "no checks in family {family}");
    let failed: Vec<String> = checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| {
            format!(
                "{} (measured {:e}, tolerance {:e})",
                c.name, c.measured, c.tolerance
            )
        })
        .collect();
    assert!(failed.is_empty(), "failing checks:\n{}", failed.join("\n"));
}
