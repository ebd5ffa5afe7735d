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

/// A failed computation fails its check, for every constructor: NaN and
/// infinite measurements never pass, whatever the tolerance and whether the
/// printed form is expected to differ.
#[test]
fn non_finite_measurements_fail_every_constructor() {
    use pdesculpt::check::{parse_golden, Check, Kind};
    let kinds = [
        Kind::Boundary,
        Kind::Residual,
        Kind::Continuity,
        Kind::Threshold,
        Kind::Reference,
        Kind::PaperLiteral,
    ];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for kind in kinds {
            for tolerance in [0.0, 1.0, f64::INFINITY] {
                let c = Check::new("f", "-", "eq 1", "f.nan", kind, bad, tolerance);
                assert!(!c.passed, "Check::new({kind}) passed on {bad}");
            }
        }
        for differs in [false, true] {
            for tolerance in [0.0, 1.0, f64::INFINITY] {
                let c = Check::paper_literal("f", "-", "eq 1", "f.nan", bad, tolerance, differs);
                assert!(
                    !c.passed,
                    "paper_literal(differs = {differs}) passed on {bad}"
                );
            }
        }
    }
    let golden = parse_golden::<serde_json::Value>("{ not json", "f", "-", "eq 1", "f.golden");
    let c = golden.expect_err("malformed golden must not parse");
    assert!(c.measured.is_nan() && !c.passed);
    // the constructors still pass and fail on finite values as documented
    assert!(Check::new("f", "-", "eq 1", "f.ok", Kind::Residual, 0.5, 1.0).passed);
    assert!(Check::paper_literal("f", "-", "eq 1", "f.ok", 2.0, 1.0, true).passed);
    assert!(!Check::paper_literal("f", "-", "eq 1", "f.ok", 0.5, 1.0, true).passed);
}

/// The layers: nothing below the families names a family or the registry
/// (`check`, `jet`, `surface` and `mesh` sit below every family; `verify` is
/// the top). Comment lines are skipped.
#[test]
fn lower_layers_name_no_family() {
    let families = [
        "pde4",
        "pde6",
        "ode6",
        "conv",
        "plate",
        "curve",
        "character",
        "verify",
        "makehuman",
    ];
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut offenders = Vec::new();
    for dir in ["check", "jet", "surface", "mesh"] {
        let mut stack = vec![root.join(dir)];
        while let Some(d) = stack.pop() {
            for e in std::fs::read_dir(&d).expect("src dir").flatten() {
                let p = e.path();
                if p.is_dir() {
                    stack.push(p);
                    continue;
                }
                let text = std::fs::read_to_string(&p).expect("source file");
                for (i, line) in text.lines().enumerate() {
                    let code = line.trim_start();
                    if code.starts_with("//") {
                        continue;
                    }
                    for f in families {
                        if code.contains(&format!("crate::{f}::"))
                            || code.contains(&format!("crate::{f};"))
                        {
                            offenders.push(format!("{}:{}: {}", p.display(), i + 1, line.trim()));
                        }
                    }
                }
            }
        }
    }
    assert!(
        offenders.is_empty(),
        "lower layer names a family:\n{}",
        offenders.join("\n")
    );
}
