//! Sizes (issue 29): a file in `src/` has at most [`FILE_LINES`] lines, a
//! function at most [`FUNCTION_LINES`]. The files and functions over the
//! limits when this test was written are listed with their sizes then
//! ([`FILES_OVER`], [`FUNCTIONS_OVER`]); a listed one may not grow, and
//! one back within the limit must leave the list (it fails as stale), so
//! the lists only shrink. A function is counted from its `fn` line to its
//! closing brace (braces in strings, chars and line comments ignored).

use std::path::{Path, PathBuf};

/// Most lines of a file in `src/`.
const FILE_LINES: usize = 500;
/// Most lines of a function in `src/`.
const FUNCTION_LINES: usize = 100;

const FILES_OVER: &[(&str, usize)] = &[];

const FUNCTIONS_OVER: &[(&str, &str, usize)] = &[
    // none left (issue 29: the last six split 2026-11-29)
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

/// A line with string and char literals emptied and its line comment cut.
fn code(line: &str) -> String {
    let mut out = String::new();
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                out.push('"');
                while let Some(d) = chars.next() {
                    if d == '\\' {
                        chars.next();
                    } else if d == '"' {
                        break;
                    }
                }
                out.push('"');
            }
            '\'' => {
                // a char literal ('x', '\n', '{'), not a lifetime
                let rest: String = chars.clone().take(3).collect();
                let lit = rest.chars().nth(1) == Some('\'')
                    || (rest.starts_with('\\') && rest.chars().nth(2) == Some('\''));
                if lit {
                    let skip = if rest.starts_with('\\') { 3 } else { 2 };
                    for _ in 0..skip {
                        chars.next();
                    }
                    out.push_str("''");
                } else {
                    out.push('\'');
                }
            }
            '/' if chars.peek() == Some(&'/') => break,
            _ => out.push(c),
        }
    }
    out
}

/// The name after `fn` when `line` starts a function.
fn fn_name(line: &str) -> Option<&str> {
    let mut t = line.trim_start();
    for prefix in [
        "pub(crate) ",
        "pub(super) ",
        "pub ",
        "const ",
        "unsafe ",
        "async ",
    ] {
        t = t.strip_prefix(prefix).unwrap_or(t);
    }
    let rest = t.strip_prefix("fn ")?;
    let end = rest
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    (end > 0).then(|| &rest[..end])
}

/// `(name, lines)` of every function in `text`.
fn functions(text: &str) -> Vec<(String, usize)> {
    let lines: Vec<String> = text.lines().map(code).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let Some(name) = fn_name(&lines[i]) else {
            i += 1;
            continue;
        };
        let (mut depth, mut started, mut j) = (0i64, false, i);
        while j < lines.len() {
            let l = &lines[j];
            depth += l.matches('{').count() as i64 - l.matches('}').count() as i64;
            started |= l.contains('{');
            if (started && depth <= 0) || (!started && l.trim_end().ends_with(';')) {
                break;
            }
            j += 1;
        }
        out.push((name.to_string(), j - i + 1));
        // nested functions are counted inside their parent
        i = if started { j + 1 } else { i + 1 };
    }
    out
}

/// `(file, lines)` of every file and `(file, function, lines)` of every
/// function in `src/`.
type Sizes = (Vec<(String, usize)>, Vec<(String, String, usize)>);

fn sizes() -> Sizes {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut paths = Vec::new();
    rust_files(&root.join("src"), &mut paths);
    paths.sort();
    let (mut files, mut fns) = (Vec::new(), Vec::new());
    for p in paths {
        let rel = p
            .strip_prefix(root)
            .expect("under the crate")
            .to_string_lossy()
            .replace('\\', "/");
        let text = std::fs::read_to_string(&p).expect("readable source");
        files.push((rel.clone(), text.lines().count()));
        for (name, n) in functions(&text) {
            fns.push((rel.clone(), name, n));
        }
    }
    (files, fns)
}

#[test]
fn files_and_functions_keep_their_size() {
    let (files, fns) = sizes();
    let mut bad = Vec::new();
    for (f, n) in &files {
        let allowed = FILES_OVER
            .iter()
            .find(|(a, _)| a == f)
            .map_or(FILE_LINES, |&(_, m)| m);
        if *n > allowed {
            bad.push(format!("{f}: {n} lines (at most {allowed})"));
        }
    }
    for (f, name, n) in &fns {
        let allowed = FUNCTIONS_OVER
            .iter()
            .filter(|(a, b, _)| a == f && b == name)
            .map(|&(_, _, m)| m)
            .max()
            .unwrap_or(FUNCTION_LINES);
        if *n > allowed {
            bad.push(format!("{f}: fn {name}: {n} lines (at most {allowed})"));
        }
    }
    assert!(bad.is_empty(), "too long:\n{}", bad.join("\n"));
}

#[test]
fn the_lists_of_oversize_code_only_shrink() {
    let (files, fns) = sizes();
    let mut stale = Vec::new();
    for (f, _) in FILES_OVER {
        if !files.iter().any(|(g, n)| g == f && *n > FILE_LINES) {
            stale.push(format!("FILES_OVER {f}"));
        }
    }
    for (f, name, _) in FUNCTIONS_OVER {
        if !fns
            .iter()
            .any(|(g, m, n)| g == f && m == name && *n > FUNCTION_LINES)
        {
            stale.push(format!("FUNCTIONS_OVER {f} {name}"));
        }
    }
    assert!(
        stale.is_empty(),
        "within the limits now, delete from the lists: {stale:?}"
    );
}

#[test]
fn the_counter_sees_functions_and_skips_braces_in_strings() {
    let text = "pub fn a() {\n    let s = \"}}}\";\n    let c = '{';\n    // }\n}\nfn b();\npub(crate) fn c<'x>(v: &'x str) -> &'x str {\n    v\n}\n";
    assert_eq!(
        functions(text),
        vec![("a".into(), 5), ("b".into(), 1), ("c".into(), 3)]
    );
}
