//! The whole verification registry passes.

#[test]
fn every_check_passes() {
    let checks = pdesculpt::verify::run(None);
    assert!(!checks.is_empty());
    let failed: Vec<String> = checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| {
            format!(
                "{} ({}: measured {:e}, tol {:e})",
                c.name, c.kind, c.measured, c.tolerance
            )
        })
        .collect();
    assert!(failed.is_empty(), "failing checks:\n{}", failed.join("\n"));
}

#[test]
fn check_names_are_unique() {
    let checks = pdesculpt::verify::run(None);
    let mut names: Vec<&str> = checks.iter().map(|c| c.name.as_str()).collect();
    names.sort_unstable();
    let before = names.len();
    names.dedup();
    assert_eq!(before, names.len(), "duplicate check names");
}
