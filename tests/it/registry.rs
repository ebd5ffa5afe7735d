//! The whole verification registry passes.

use pdesculpt::check::Check;
use std::sync::OnceLock;

/// Every family's checks, run once per test process and shared by the tests
/// that read the whole registry (each family's from `crate::shared`, so a
/// family test and the registry tests compute it once between them).
pub fn all_checks() -> &'static [Check] {
    static CHECKS: OnceLock<Vec<Check>> = OnceLock::new();
    CHECKS.get_or_init(crate::shared::all_checks)
}

#[test]
fn every_check_passes() {
    let checks = all_checks();
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

/// Issue 31: a tolerance within about 10x of what is measured, or a stated
/// reason. A check whose tolerance is more than `LOOSE_RATIO` (1000) times
/// its measured value names why (`Check::loose_because`), unless it
/// measures at the level of f64 rounding (`verify` then gives it
/// `ROUNDING_REASON`).
#[test]
fn every_loose_tolerance_states_its_reason() {
    let loose: Vec<String> = all_checks()
        .iter()
        .filter(|c| c.is_loose() && c.tolerance_reason.is_empty())
        .map(|c| {
            format!(
                "{}: measured {:e}, tolerance {:e}",
                c.name, c.measured, c.tolerance
            )
        })
        .collect();
    assert!(
        loose.is_empty(),
        "tolerances over 1000x the measured value with no reason (tighten them or call \
         Check::loose_because):\n{}",
        loose.join("\n")
    );
}

#[test]
fn the_loose_rule_sees_a_loose_tolerance_and_not_a_paper_floor() {
    use pdesculpt::check::{Check, Kind, ROUNDING_REASON};
    let loose = Check::new("f", "-", "-", "f.loose", Kind::Reference, 1e-6, 1e-2);
    assert!(loose.is_loose());
    assert!(
        loose
            .clone()
            .with_loose_reason()
            .tolerance_reason
            .is_empty(),
        "1e-6 is not rounding"
    );
    let tight = Check::new("f", "-", "-", "f.tight", Kind::Reference, 1e-6, 1e-5);
    assert!(!tight.is_loose());
    let rounding = Check::new("f", "-", "-", "f.rounding", Kind::Reference, 0.0, 1e-12);
    assert_eq!(
        rounding.with_loose_reason().tolerance_reason,
        ROUNDING_REASON
    );
    let floor = Check::paper_literal("f", "-", "-", "f.floor", 5.0, 1e-3, true);
    assert!(
        !floor.is_loose(),
        "a differing paper form's tolerance is a floor"
    );
    let nan = Check::new("f", "-", "-", "f.nan", Kind::Reference, f64::NAN, 1.0);
    assert!(!nan.is_loose());
}

#[test]
fn check_names_are_unique() {
    let checks = all_checks();
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
        "study",
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

/// Every numbered equation of the five papers: the one list the equation
/// index uses ([`pdesculpt::equations::numbered_equations`]).
fn numbered_equations() -> Vec<(&'static str, Vec<String>)> {
    pdesculpt::equations::numbered_equations()
}

/// Equations that still have no check naming them alone (issue 17). This
/// list must stay exact: the test fails when an equation outside it has no
/// check, and when one inside it gains a check (then remove it here).
const NOT_YET_CHECKED: &[(&str, &[&str])] = &[
    ("000", &[]),
    ("001", &[]),
    ("002", &[]),
    ("003", &[]),
    ("004", &[]),
];

/// The equations a check's `equation` field names alone: items separated by
/// commas, parenthesised qualifiers dropped, a leading "eq"/"eqs"/"app"
/// dropped; ranges ("eqs 8-19", "A17-A36") name no equation alone.
fn named_alone(field: &str) -> Vec<String> {
    let mut clean = String::new();
    let mut depth = 0usize;
    for ch in field.chars() {
        match ch {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            _ if depth == 0 => clean.push(ch),
            _ => {}
        }
    }
    clean
        .split(',')
        .filter_map(|item| {
            let item = item.trim();
            let item = ["eqs ", "eq ", "app ", "appendix "]
                .iter()
                .find_map(|p| item.strip_prefix(p))
                .unwrap_or(item)
                .trim();
            let digits = item.trim_start_matches(['A', 'B']);
            (!digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit()))
                .then(|| item.to_string())
        })
        .collect()
}

#[test]
fn named_alone_parses_labels() {
    assert_eq!(named_alone("eq 7, A9-A12"), vec!["7"]);
    assert_eq!(named_alone("eqs 1, 4"), vec!["1", "4"]);
    assert_eq!(named_alone("eqs 8-19"), Vec::<String>::new());
    assert_eq!(named_alone("eq 8 (n = 0)"), vec!["8"]);
    assert_eq!(named_alone("app A5, B3"), vec!["A5", "B3"]);
    assert_eq!(named_alone("eq 26, Fig 6b"), vec!["26"]);
}

#[test]
fn every_numbered_equation_has_a_check() {
    let checks = all_checks();
    let mut unchecked_new = Vec::new();
    let mut now_checked = Vec::new();
    for (paper, eqs) in numbered_equations() {
        let named: std::collections::HashSet<String> = checks
            .iter()
            .filter(|c| c.paper == paper)
            .flat_map(|c| named_alone(&c.equation))
            .collect();
        let gap: &[&str] = NOT_YET_CHECKED
            .iter()
            .find(|(p, _)| *p == paper)
            .map_or(&[], |(_, g)| g);
        for e in eqs {
            match (named.contains(&e), gap.contains(&e.as_str())) {
                (false, false) => unchecked_new.push(format!("{paper} eq {e}")),
                (true, true) => now_checked.push(format!("{paper} eq {e}")),
                _ => {}
            }
        }
    }
    assert!(
        unchecked_new.is_empty(),
        "numbered equations with no check naming them alone: {unchecked_new:?}"
    );
    assert!(
        now_checked.is_empty(),
        "now checked, remove from NOT_YET_CHECKED: {now_checked:?}"
    );
}
