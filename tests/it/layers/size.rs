//! Sizes in `src/` (issue 29, item 6): files at most [`FILE_LINES`] lines,
//! functions at most [`FN_LINES`] lines. The functions longer than that
//! when this test was written are listed in [`KNOWN_LONG`] with their
//! length then: each may only shrink, and an entry whose function is no
//! longer over the limit (or gone) fails, so the list only shortens.
//!
//! A function's length runs from its `fn` line to the closing brace at the
//! same indentation (rustfmt's layout), doc comments excluded.

use std::path::{Path, PathBuf};

/// Most lines in one file of `src/`.
const FILE_LINES: usize = 500;
/// Most lines in one function of `src/`.
const FN_LINES: usize = 100;

/// `(file, function, lines)` of the functions over [`FN_LINES`] on
/// 2026-11-28.
const KNOWN_LONG: &[(&str, &str, usize)] = &[
    ("src/template/envelope.rs", "envelope_pass", 279),
    ("src/template/fit.rs", "fit", 189),
    ("src/character/log/stroke.rs", "new", 157),
    ("src/character/log/validate.rs", "validate_params", 142),
    ("src/cli/template/mod.rs", "run_fit", 132),
    ("src/sketch/figure.rs", "contour", 130),
    ("src/sketch/figure_animal.rs", "figures", 122),
    ("src/conv/skeleton.rs", "prune_and_link", 121),
    ("src/conv/silhouette.rs", "silhouette_error_union", 121),
    ("src/sketch/corpus.rs", "path_data", 120),
    ("src/profile/svg.rs", "flattened_subpaths", 103),
    ("src/plate/mapping.rs", "harmonic_disk", 103),
    ("src/conv/skeleton.rs", "extract", 103),
    ("src/template/sections.rs", "fit_sections", 102),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let p = e.expect("directory entry").path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The name of the function a line declares, if it declares one with a
/// body on the following lines.
fn fn_name(line: &str) -> Option<&str> {
    let t = line.trim_start();
    let t = t
        .strip_prefix("pub(crate) ")
        .or_else(|| t.strip_prefix("pub(super) "))
        .or_else(|| t.strip_prefix("pub "))
        .unwrap_or(t);
    let t = t.strip_prefix("const ").unwrap_or(t);
    let t = t.strip_prefix("unsafe ").unwrap_or(t);
    let rest = t.strip_prefix("fn ")?;
    let end = rest
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    Some(&rest[..end])
}

/// `(function, lines)` of every function in `text` with a body.
fn functions(text: &str) -> Vec<(String, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let Some(name) = fn_name(lines[i]) else {
            i += 1;
            continue;
        };
        let indent = lines[i].len() - lines[i].trim_start().len();
        // the signature ends at `{` (a body) or `;` (a declaration)
        let mut j = i;
        while j < lines.len() && !lines[j].trim_end().ends_with('{') {
            let t = lines[j].trim_end();
            // a declaration, or a body on one line
            if t.ends_with(';') || (t.contains('{') && t.ends_with('}')) {
                break;
            }
            j += 1;
        }
        if j >= lines.len() || !lines[j].trim_end().ends_with('{') {
            i = j + 1;
            continue;
        }
        let close = format!("{}}}", " ".repeat(indent));
        let k = (j..lines.len())
            .find(|&k| lines[k] == close)
            .unwrap_or(lines.len() - 1);
        out.push((name.to_string(), k - i + 1));
        i += 1;
    }
    out
}

fn src_files() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    files.sort();
    files
        .iter()
        .map(|p| {
            let rel = p
                .strip_prefix(root)
                .expect("under the crate")
                .display()
                .to_string();
            let text = std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{rel}: {e}"));
            (rel, text)
        })
        .collect()
}

#[test]
fn no_file_in_src_is_over_500_lines() {
    let over: Vec<String> = src_files()
        .iter()
        .map(|(p, t)| (p, t.lines().count()))
        .filter(|(_, n)| *n > FILE_LINES)
        .map(|(p, n)| format!("{p}: {n} lines"))
        .collect();
    assert!(
        over.is_empty(),
        "over {FILE_LINES} lines:\n{}",
        over.join("\n")
    );
}

#[test]
fn no_function_in_src_grows_over_100_lines() {
    let mut problems = Vec::new();
    let mut seen = Vec::new();
    for (path, text) in src_files() {
        for (name, n) in functions(&text) {
            if n <= FN_LINES {
                continue;
            }
            match KNOWN_LONG.iter().find(|(p, f, _)| *p == path && *f == name) {
                Some(&(_, _, was)) if n <= was => seen.push((path.clone(), name.clone())),
                Some(&(_, _, was)) => {
                    problems.push(format!("{path}: {name} grew from {was} to {n} lines"))
                }
                None => problems.push(format!("{path}: {name} has {n} lines (at most {FN_LINES})")),
            }
        }
    }
    for (p, f, _) in KNOWN_LONG {
        if !seen.iter().any(|(sp, sf)| sp == p && sf == f) {
            problems.push(format!(
                "{p}: {f} is no longer over {FN_LINES} lines: remove it from KNOWN_LONG"
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The scan finds a long function and measures it from `fn` to its brace.
#[test]
fn the_scan_measures_a_function() {
    let body = "    let x = 1;\n".repeat(FN_LINES);
    let text = format!(
        "fn one() -> f64 {{ 1.0 }}\n/// doc\npub fn long(\n    a: f64,\n) -> f64 {{\n{body}    a\n}}\n\nfn decl();\nfn short() {{}}\n"
    );
    let f = functions(&text);
    assert_eq!(f, vec![("long".to_string(), FN_LINES + 5)], "{f:?}");
}
