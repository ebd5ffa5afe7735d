//! NaN never passes a check (issue 31).
//!
//! `f64::max`/`f64::min` return the other argument when one is NaN, so a fold
//! over a computation that failed everywhere measures 0 and passes. The scan
//! below reads every file of check code (`src/check/`, every `check.rs`,
//! `check_*.rs` and `check/` folder) up to its `#[cfg(test)]` part and
//! refuses `f64::max`/`f64::min` paths and every `.max(` / `.min(` call with
//! an argument: measured values reduce through `check::Worst`
//! (`a.worst(b)`, `a.least(b)`) and `check::Measure` (`max_nan`, `max_abs`,
//! `min_nan`, `rms`), which keep NaN. Integer maxima are written
//! `usize::max(a, b)` / `std::cmp::max`, which the scan allows (they cannot
//! hold NaN). The second half feeds NaN into each check kind's measurement
//! path and sees the check fail.

use pdesculpt::check::{self, Check, Kind, Measure, Worst};
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries {
        let p = e.expect("directory entry").path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// Check code: `src/check/`, `check.rs`, `check_*.rs`, anything under a
/// `check/` folder.
fn is_check_code(rel: &str) -> bool {
    let name = rel.rsplit('/').next().unwrap_or("");
    // the reductions themselves are built on f64::max
    if rel == "src/check/reduce.rs" {
        return false;
    }
    rel.starts_with("src/check/")
        || rel.contains("/check/")
        || name == "check.rs"
        || name.starts_with("check_")
}

/// The code of a line: string literals emptied, `//` comment cut.
fn code_of(line: &str) -> String {
    let mut out = String::new();
    let mut in_str = false;
    let mut prev = ' ';
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        if in_str {
            if c == '"' && prev != '\\' {
                in_str = false;
                out.push('"');
            }
            prev = if prev == '\\' && c == '\\' { ' ' } else { c };
            continue;
        }
        if c == '"' {
            in_str = true;
            out.push('"');
        } else if c == '/' && chars.peek() == Some(&'/') {
            break;
        } else {
            out.push(c);
        }
        prev = c;
    }
    out
}

/// Every NaN-dropping reduction in one line of code.
fn offences(code: &str) -> Vec<&'static str> {
    let mut out = Vec::new();
    if code.contains("f64::max") || code.contains("f64::min") {
        out.push("f64::max/f64::min path (drops NaN)");
    }
    for pat in [".max(", ".min("] {
        let mut rest = code;
        while let Some(k) = rest.find(pat) {
            let after = &rest[k + pat.len()..];
            if !after.starts_with(')') {
                out.push("bare .max(x)/.min(x) (drops NaN): use check::Worst");
            }
            rest = after;
        }
    }
    out
}

#[test]
fn check_code_has_no_nan_dropping_reductions() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    let mut found = Vec::new();
    let mut scanned = 0;
    for f in files {
        let rel = f
            .strip_prefix(root)
            .expect("under the root")
            .to_string_lossy()
            .replace('\\', "/");
        if !is_check_code(&rel) {
            continue;
        }
        scanned += 1;
        let text = std::fs::read_to_string(&f).expect("readable source");
        for (i, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("#[cfg(test)]") {
                break;
            }
            for o in offences(&code_of(line)) {
                found.push(format!("{rel}:{}: {o}: {}", i + 1, line.trim()));
            }
        }
    }
    assert!(scanned > 0, "no check code found");
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn the_scan_sees_what_it_must() {
    assert_eq!(offences("e = e.max(x);").len(), 1);
    assert_eq!(offences(".fold(0.0, f64::max)").len(), 1);
    assert_eq!(offences("a.min(b).max(c)").len(), 2);
    assert!(offences("v.iter().max()").is_empty());
    assert!(offences("usize::max(a, b)").is_empty());
    assert!(offences(&code_of("x // e.max(y)")).is_empty());
    assert!(offences(&code_of("\"f64::max\"")).is_empty());
    assert!(is_check_code("src/pde6/check/measure.rs"));
    assert!(is_check_code("src/conv/check_fast.rs"));
    assert!(!is_check_code("src/pde6/chain.rs"));
}

/// Every reduction a measurement may use, each fed one NaN among finite
/// errors.
fn nan_measurements() -> Vec<(&'static str, f64)> {
    let errors = [1e-3, f64::NAN, 2e-3];
    vec![
        ("max_nan", errors.iter().copied().max_nan()),
        ("max_abs", errors.iter().copied().max_abs()),
        ("min_nan", errors.iter().copied().min_nan()),
        ("rms", errors.iter().copied().rms()),
        ("max_abs_diff", check::max_abs_diff(&errors, &[0.0; 3])),
        ("worst fold", errors.iter().fold(0.0, |a, &e| a.worst(e))),
        ("least fold", errors.iter().fold(1.0, |a, &e| a.least(e))),
        ("rel_err", check::rel_err(f64::NAN, 1.0)),
    ]
}

#[test]
fn nan_fails_every_check_kind() {
    let kinds = [
        Kind::Boundary,
        Kind::Residual,
        Kind::Continuity,
        Kind::Threshold,
        Kind::Reference,
    ];
    for (what, m) in nan_measurements() {
        assert!(m.is_nan(), "{what} dropped the NaN: {m}");
        for kind in kinds {
            let c = Check::new("nan", "-", "eq 0", "nan.probe", kind, m, f64::INFINITY);
            assert!(!c.passed, "{kind} check passed on NaN through {what}");
        }
        for differs in [false, true] {
            let c = Check::paper_literal("nan", "-", "eq 0", "nan.probe", m, 0.0, differs);
            assert!(
                !c.passed,
                "paper-literal (differs = {differs}) passed on NaN through {what}"
            );
        }
    }
}

/// NaN through the library's own measurement functions that checks call:
/// mesh distance statistics, GEC fit errors, ODE6 grid join jumps.
#[test]
fn nan_survives_the_library_measurements() {
    let s = pdesculpt::mesh::metrics::stats(&[0.1, f64::NAN, 0.2]);
    assert!(
        s.max.is_nan() && s.rms.is_nan(),
        "mesh stats dropped NaN: {s:?}"
    );
    let jumps = pdesculpt::ode6::GridJumps {
        u: [0.0, f64::NAN, 0.0],
        v: [0.0; 3],
        u_magnitude: [1.0; 3],
        v_magnitude: [1.0; 3],
    };
    assert!(jumps.relative(0.0).is_nan(), "grid jumps dropped NaN");
}

/// The adaptive quadrature the conv closed forms are checked against
/// returns NaN at once for a NaN integrand or tolerance: refining to its
/// depth limit would take 2^40 Gauss-Kronrod rules (scripts/nan_inject.sh
/// with NaN in `conv::kernel::f1` hung there before).
#[test]
fn the_reference_quadrature_returns_nan_at_once() {
    use pdesculpt::conv::kernel::integrate;
    let q = check::tol::QUADRATURE;
    // NaN on the last part of the interval only
    let nan_after = |t: f64| if t > 0.75 { f64::NAN } else { t };
    assert!(integrate(&|_| f64::NAN, 0.0, 1.0, q).is_nan());
    assert!(integrate(&nan_after, 0.0, 1.0, q).is_nan());
    assert!(integrate(&|t| t * t, 0.0, 1.0, f64::NAN).is_nan());
    let third = integrate(&|t| t * t, 0.0, 1.0, q);
    assert!((third - 1.0 / 3.0).abs() <= q, "{third}");
}
