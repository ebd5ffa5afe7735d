//! Tolerances in test assertions are named (`check::tol` or a documented
//! constant), never bare literals (house rule, issue 19). The scan reads the
//! condition of every `assert!` / `prop_assert!` (up to its first top-level
//! comma) in the files cleaned so far and refuses an upper bound written as
//! a literal: `< 1e-9`, `<= 5e-3 * scale`, `< 0.003`. Lower bounds
//! (`> 0.0`) and literals elsewhere (`.max(1.0)`, `2.0 * x`) are allowed.

use std::path::Path;

/// Files whose assertions name every tolerance (paths from the crate root).
const CLEANED: &[&str] = &[
    "tests/it/ode6.rs",
    "tests/it/pde4.rs",
    "tests/it/pde6.rs",
    "tests/it/plate.rs",
    "tests/it/infra.rs",
    "tests/it/conv.rs",
    "tests/it/gec.rs",
    "tests/it/tolerances.rs",
    "src/mesh/isosurface/tests.rs",
];

/// `(line, condition)` of every `assert!(` / `prop_assert!(` in `text`.
fn assertion_conditions(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (start, _) in text.match_indices("assert!(") {
        let open = start + "assert!(".len();
        let (mut depth, mut in_str, mut prev) = (0i32, false, ' ');
        let mut end = text.len();
        for (k, c) in text[open..].char_indices() {
            if in_str {
                if c == '"' && prev != '\\' {
                    in_str = false;
                }
            } else {
                match c {
                    '"' => in_str = true,
                    '(' | '[' | '{' => depth += 1,
                    ')' | ']' | '}' if depth == 0 => {
                        end = open + k;
                        break;
                    }
                    ')' | ']' | '}' => depth -= 1,
                    ',' if depth == 0 => {
                        end = open + k;
                        break;
                    }
                    _ => {}
                }
            }
            prev = c;
        }
        let line = text[..start].matches('\n').count() + 1;
        out.push((
            line,
            text[open..end]
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" "),
        ));
    }
    out
}

/// Whether `cond` has an upper bound `<` / `<=` followed by a float literal
/// (`1e-9`, `0.003`, `5e-3 *`).
fn bare_upper_bound(cond: &str) -> bool {
    let b = cond.as_bytes();
    let mut i = 0;
    while i < b.len() {
        // `<` as a comparison: not `<<`, not `<-`, and not a generic (`Vec<f64>`):
        // comparisons in these files are written with spaces around them.
        if b[i] == b'<' && i > 0 && b[i - 1] == b' ' {
            let mut j = i + 1;
            if j < b.len() && b[j] == b'=' {
                j += 1;
            }
            while j < b.len() && (b[j] == b' ' || b[j] == b'(') {
                j += 1;
            }
            let lit: String = cond[j..]
                .chars()
                .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | '-' | '_'))
                .collect();
            let numeric = lit.starts_with(|c: char| c.is_ascii_digit());
            if numeric && (lit.contains('.') || lit.contains('e')) {
                return true;
            }
        }
        i += 1;
    }
    false
}

#[test]
fn cleaned_files_name_their_tolerances() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut bad = Vec::new();
    for f in CLEANED {
        let text = std::fs::read_to_string(root.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        for (line, cond) in assertion_conditions(&text) {
            if bare_upper_bound(&cond) {
                bad.push(format!("{f}:{line}: {cond}"));
            }
        }
    }
    assert!(bad.is_empty(), "bare tolerances:\n{}", bad.join("\n"));
}

#[test]
fn the_scan_sees_a_bare_tolerance() {
    // Probes are assembled at run time so that this file stays clean.
    let lt = "<";
    let probes = [
        (format!("assert!((a - b).abs() {lt} 1e-9);"), true),
        (format!("prop_assert!(x {lt}= 5e-3 * s, \"{{x}}\");"), true),
        (
            format!("assert!(\n    r.rms {lt} 0.003,\n    \"msg\"\n);"),
            true,
        ),
        (format!("assert!(x {lt} tol::SOLVE * y.max(1.0));"), false),
        ("assert!(x > 0.5 * y);".to_string(), false),
        (format!("assert!(v.len() {lt} 3, \"a {lt} 1e-9\");"), false),
        ("assert!(f::<Vec<f64>>(1.0).is_ok());".to_string(), false),
    ];
    for (text, want) in probes {
        let conds = assertion_conditions(&text);
        assert_eq!(conds.len(), 1, "{text}");
        assert_eq!(
            bare_upper_bound(&conds[0].1),
            want,
            "{text}: {:?}",
            conds[0]
        );
    }
}
