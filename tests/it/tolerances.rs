//! Tolerances in test assertions are named (`check::tol` or a documented
//! constant), never bare literals (house rule, issue 19).
//!
//! The scan reads the condition of every `assert!` / `prop_assert!` /
//! `debug_assert!` (up to its first top-level comma) in every test file: all
//! of `tests/` and `benches/`, `tests.rs` unit-test files, and the
//! `#[cfg(test)]` part of every other file under `src/` and
//! `paper_figures/src/`. It refuses a bound written as a literal:
//! - a non-zero float literal right after a comparison, upper or lower
//!   (`< 1e-9`, `<= 5e-3 * s`, `> 0.99 * n`, `>= 0.5`), unless it only scales
//!   a named tolerance (`< 2.0 * PROFILE_REL`);
//! - a non-zero float literal standing alone before a comparison
//!   (`0.99 < frac`, `1e-9 > err`);
//! - a literal with a negative exponent anywhere in a comparison (a slack
//!   such as `(1.0 + 1e-9)` or `+ 1e-12`).
//!
//! Sign statements (`> 0.0`, `>= 0.0`), integer counts (`len() < 3`), and
//! literals that only scale or shift a named tolerance or the data
//! (`tol::SOLVE * 10.0`, `tol::JOIN * (1.0 + v.abs())`) are allowed.

use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    if dir.extension().is_some_and(|e| e == "rs") {
        out.push(dir.to_path_buf());
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries {
        let p = e.expect("directory entry").path();
        if p.is_dir() || p.extension().is_some_and(|e| e == "rs") {
            rust_files(&p, out);
        }
    }
}

/// The test code of a file: all of it under `tests/` and `benches/` and in a
/// `tests.rs`, else what follows its first `#[cfg(test)]` (none: `None`).
fn test_code<'a>(rel: &str, text: &'a str) -> Option<&'a str> {
    if rel.starts_with("tests/") || rel.starts_with("benches/") || rel.ends_with("/tests.rs") {
        return Some(text);
    }
    text.find("#[cfg(test)]").map(|k| &text[k..])
}

/// `(line, condition)` of every `assert!(` / `prop_assert!(` in `text`,
/// with string and char literals emptied and whitespace collapsed.
fn assertion_conditions(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    for (start, _) in text.match_indices("assert!(") {
        let open = start + "assert!(".len();
        let mut depth = 0i32;
        let mut cond = String::new();
        let mut chars = text[open..].chars().peekable();
        while let Some(c) = chars.next() {
            match c {
                '"' => {
                    // a string literal: skip to its closing quote
                    let mut esc = false;
                    for s in chars.by_ref() {
                        if s == '"' && !esc {
                            break;
                        }
                        esc = s == '\\' && !esc;
                    }
                    cond.push_str("\"\"");
                }
                '\'' => {
                    // a char literal ('"', '\\', 'x'); a lifetime has no closing quote
                    let rest: String = chars.clone().take(4).collect();
                    let len = if rest.starts_with('\\') {
                        rest.char_indices()
                            .skip(2)
                            .find(|&(_, q)| q == '\'')
                            .map(|(k, _)| k)
                    } else {
                        rest.char_indices()
                            .nth(1)
                            .filter(|&(_, q)| q == '\'')
                            .map(|_| 1)
                    };
                    match len {
                        Some(n) => {
                            for _ in 0..=n {
                                chars.next();
                            }
                            cond.push_str("' '");
                        }
                        None => cond.push(c),
                    }
                }
                '(' | '[' | '{' => {
                    depth += 1;
                    cond.push(c);
                }
                ')' | ']' | '}' if depth == 0 => break,
                ')' | ']' | '}' => {
                    depth -= 1;
                    cond.push(c);
                }
                ',' if depth == 0 => break,
                _ => cond.push(c),
            }
        }
        let line = text[..start].matches('\n').count() + 1;
        out.push((line, cond.split_whitespace().collect::<Vec<_>>().join(" ")));
    }
    out
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    /// A number literal: its text and whether it is a non-zero float.
    Num(String, bool),
    /// An identifier or path (`tol::SOLVE`, `x`).
    Name(String),
    /// A comparison `<`, `<=`, `>`, `>=` (written with spaces around it):
    /// `<` or `>`.
    Cmp(char),
    /// Any other punctuation.
    Punct(char),
}

/// The tokens of a collapsed condition.
fn tokens(cond: &str) -> Vec<Tok> {
    let b: Vec<char> = cond.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c == ' ' {
            i += 1;
        } else if c.is_ascii_digit() {
            let s = i;
            while i < b.len() {
                let d = b[i];
                let exp_sign = matches!(d, '-' | '+') && matches!(b[i - 1], 'e' | 'E');
                let point = d == '.' && b.get(i + 1).is_some_and(|n| n.is_ascii_digit());
                let trailing_point = d == '.' && !b.get(i + 1).is_some_and(|n| n.is_alphabetic());
                if d.is_ascii_alphanumeric() || d == '_' || exp_sign || point || trailing_point {
                    i += 1;
                } else {
                    break;
                }
            }
            let text: String = b[s..i].iter().collect();
            let digits: String = text.chars().filter(|&d| d != '_').collect();
            let float = digits.contains('.')
                || digits.contains("f64")
                || digits.contains("f32")
                || (digits.contains(['e', 'E']) && !digits.starts_with("0x"));
            let mantissa = digits
                .trim_end_matches("f64")
                .trim_end_matches("f32")
                .split(['e', 'E'])
                .next()
                .unwrap_or("");
            let nonzero = mantissa.chars().any(|d| ('1'..='9').contains(&d));
            out.push(Tok::Num(text, float && nonzero));
        } else if c.is_alphabetic() || c == '_' {
            let s = i;
            while i < b.len()
                && (b[i].is_alphanumeric()
                    || b[i] == '_'
                    || (b[i] == ':' && b.get(i + 1) == Some(&':'))
                    || (b[i] == ':' && i > 0 && b[i - 1] == ':'))
            {
                i += 1;
            }
            out.push(Tok::Name(b[s..i].iter().collect()));
        } else if matches!(c, '<' | '>') {
            let eq = b.get(i + 1) == Some(&'=');
            let spaced_before = i > 0 && b[i - 1] == ' ';
            let after = i + 1 + usize::from(eq);
            let spaced_after = b.get(after) == Some(&' ');
            let doubled = b.get(i + 1) == Some(&c) || (i > 0 && matches!(b[i - 1], '-' | '='));
            if spaced_before && spaced_after && !doubled {
                out.push(Tok::Cmp(c));
            } else {
                out.push(Tok::Punct(c));
            }
            i = after;
        } else {
            out.push(Tok::Punct(c));
            i += 1;
        }
    }
    out
}

/// Whether `name` names a tolerance: `tol::…`, a SCREAMING_CASE constant, or
/// a local whose name says so (`tol`, `slack`).
fn names_tolerance(name: &str) -> bool {
    let last = name.rsplit("::").next().unwrap_or(name);
    name.starts_with("tol::")
        || name.contains("::tol::")
        || last.to_ascii_lowercase().contains("tol")
        || last.to_ascii_lowercase().contains("slack")
        || (last.len() > 1
            && last
                .chars()
                .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
            && last.chars().any(|c| c.is_ascii_uppercase()))
}

/// The bare literal bounds in a condition (empty: clean).
fn bare_bounds(cond: &str) -> Vec<String> {
    let t = tokens(cond);
    if !t.iter().any(|x| matches!(x, Tok::Cmp(_))) {
        return Vec::new();
    }
    let mut bad = Vec::new();
    for (k, tok) in t.iter().enumerate() {
        let Tok::Num(lit, true) = tok else {
            continue;
        };
        // a slack with a negative exponent, anywhere
        if lit.contains("e-") || lit.contains("E-") {
            bad.push(format!("slack {lit}"));
            continue;
        }
        // right after a comparison (past `(` and a unary minus)
        let mut j = k;
        while j > 0 && matches!(t[j - 1], Tok::Punct('(') | Tok::Punct('-')) {
            j -= 1;
        }
        if j > 0 && matches!(t[j - 1], Tok::Cmp(_)) {
            let scales_named = t.get(k + 1) == Some(&Tok::Punct('*'))
                && matches!(t.get(k + 2), Some(Tok::Name(n)) if names_tolerance(n));
            if !scales_named {
                bad.push(format!("bound {lit}"));
            }
            continue;
        }
        // standing alone before a comparison
        let before_ok =
            k == 0 || matches!(t[k - 1], Tok::Punct('(' | '|' | '&' | '{') | Tok::Cmp(_));
        if before_ok && matches!(t.get(k + 1), Some(Tok::Cmp(_))) {
            bad.push(format!("bound {lit}"));
        }
    }
    bad
}

/// Every test file (paths from the crate root, `/`-separated), sorted.
fn test_files() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["tests", "benches", "src", "paper_figures/src"] {
        rust_files(&root.join(dir), &mut files);
    }
    let mut rel: Vec<String> = files
        .iter()
        .filter_map(|f| f.strip_prefix(root).ok())
        .map(|p| {
            p.components()
                .map(|c| c.as_os_str().to_string_lossy())
                .collect::<Vec<_>>()
                .join("/")
        })
        .collect();
    rel.sort();
    rel
}

#[test]
fn test_files_name_their_tolerances() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (mut bad, mut scanned) = (Vec::new(), 0);
    for f in test_files() {
        let text = std::fs::read_to_string(root.join(&f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        let Some(code) = test_code(&f, &text) else {
            continue;
        };
        let offset = text[..text.len() - code.len()].matches('\n').count();
        scanned += 1;
        for (line, cond) in assertion_conditions(code) {
            let found = bare_bounds(&cond);
            if !found.is_empty() {
                bad.push(format!(
                    "{f}:{}: {cond}  ({})",
                    line + offset,
                    found.join(", ")
                ));
            }
        }
    }
    assert!(scanned >= 20, "the scan found only {scanned} test files");
    assert!(bad.is_empty(), "bare tolerances:\n{}", bad.join("\n"));
}

#[test]
fn the_scan_sees_a_bare_tolerance() {
    // Probes are assembled at run time so that this file stays clean.
    let (lt, gt) = ("<", ">");
    let bare = [
        format!("assert!((a - b).abs() {lt} 1e-9);"),
        format!("prop_assert!(x {lt}= 5e-3 * s, \"{{x}}\");"),
        format!("assert!(\n    r.rms {lt} 0.003,\n    \"msg\"\n);"),
        format!("assert!(frac {gt} 0.99 * n);"),
        format!("assert!(peak {gt}= 0.5);"),
        format!("assert!(d {gt} -2.5);"),
        format!("assert!(0.99 {lt} frac);"),
        format!("assert!(ok && 1e-9 {gt} err);"),
        format!("assert!(d {lt}= h * (1.0 + 1e-9) + t);"),
        format!("assert!(q.iter().all(|p| p[1] {gt} 150.0));"),
        format!("assert!(x {lt} 2f64);"),
    ];
    let clean = [
        format!("assert!(x {lt} tol::SOLVE * y.max(1.0));"),
        format!("assert!(x {gt} 0.0 && y {gt}= 0.0);"),
        format!("assert!(x {gt} 0.5 * FLOOR);"),
        format!("assert!(e {lt}= tol * 3.0);"),
        format!("assert!(v.len() {lt} 3, \"a {lt} 1e-9\");"),
        format!("assert!(s.contains(\"x {gt} 0.5\") && c != '\"');"),
        "assert!(f::<Vec<f64>>(1.0).is_ok());".to_string(),
        format!("assert!((x - 30.0).abs() {lt} tol::ROUNDING);"),
        format!("assert!(err {lt}= tol::JOIN * (1.0 + v.abs()));"),
        "assert!(x.map(|c| c * 2.0).is_some());".to_string(),
    ];
    for (text, want) in bare
        .iter()
        .map(|t| (t, true))
        .chain(clean.iter().map(|t| (t, false)))
    {
        let conds = assertion_conditions(text);
        assert_eq!(conds.len(), 1, "{text}");
        let found = bare_bounds(&conds[0].1);
        assert_eq!(!found.is_empty(), want, "{text}: {:?} {found:?}", conds[0]);
    }
}

#[test]
fn the_scan_covers_new_test_files() {
    // A test file added tomorrow is scanned without being listed here.
    let files = test_files();
    for f in [
        "tests/it/ode6.rs",
        "tests/it/tolerances.rs",
        "src/mesh/isosurface/tests.rs",
        "benches/pde6.rs",
    ] {
        assert!(files.iter().any(|x| x == f), "{f} not scanned: {files:?}");
    }
    assert_eq!(test_code("src/x.rs", "fn f() {}\n"), None);
    assert_eq!(
        test_code("src/x.rs", "a\n#[cfg(test)]\nb"),
        Some("#[cfg(test)]\nb")
    );
}
