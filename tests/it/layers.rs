//! The import graph has no arrow from a lower layer to a higher one
//! (issue 19): the ground (`vec3`, `check`, `jet`, `mesh`, `surface`) names
//! no equation family, no character module and no CLI; `vec3` names nothing
//! of the crate at all; an equation family (`pde4`, `pde6`, `ode6`, `plate`,
//! `conv`, `profile`) names no other family and nothing of the modeling layer
//! above it (the whole-body reconstruction lives in `body`, not in `pde6`).
//! Doc comments may link anywhere. The whole file graph (no loop, no
//! upward arrow between any two files) is [`graph`].

mod graph;

use std::path::{Path, PathBuf};

/// Modules above the ground.
const UPPER: &[&str] = &[
    "curve",
    "pde4",
    "pde6",
    "ode6",
    "plate",
    "conv",
    "profile",
    "sketch",
    "template",
    "sasm",
    "body",
    "face",
    "character",
    "edit",
    "pipeline",
    "demo",
    "tui",
    "render",
    "makehuman",
    "verify",
    "study",
    "cli",
    "progress",
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    if dir.extension().is_some_and(|e| e == "rs") {
        out.push(dir.to_path_buf());
        return;
    }
    for e in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let p = e.expect("directory entry").path();
        if p.is_dir() || p.extension().is_some_and(|e| e == "rs") {
            rust_files(&p, out);
        }
    }
}

/// `(file, line)` of every non-comment line of the files under `roots`
/// naming `crate::<m>` for one of `modules`.
fn arrows(roots: &[&str], modules: &[&str]) -> Vec<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    for r in roots {
        rust_files(&src.join(r), &mut files);
    }
    assert!(!files.is_empty(), "no files under {roots:?}");
    arrows_in(&files, modules)
}

const PREFIXES: [&str; 3] = ["crate::", "pdesculpt::", "super::super::"];

fn arrows_in(files: &[PathBuf], modules: &[&str]) -> Vec<String> {
    let mut found = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).expect("readable source");
        let lines: Vec<&str> = text
            .lines()
            .map(|l| {
                if l.trim_start().starts_with("//") {
                    ""
                } else {
                    l
                }
            })
            .collect();
        for (i, line) in lines.iter().enumerate() {
            let code = line.trim_start();
            for m in modules {
                for prefix in PREFIXES {
                    let needle = format!("{prefix}{m}");
                    let hit = code.match_indices(&needle).any(|(k, _)| {
                        !code[k + needle.len()..]
                            .starts_with(|c: char| c.is_alphanumeric() || c == '_')
                    });
                    if hit {
                        found.push(format!("{}:{}: {code}", f.display(), i + 1));
                    }
                }
            }
        }
        // grouped imports: `use crate::{pde6::Chain, mesh}` (one line or many)
        let code = lines.join("\n");
        for prefix in PREFIXES {
            for (k, _) in code.match_indices(&format!("{prefix}{{")) {
                for (at, head) in group_heads(&code[k + prefix.len()..]) {
                    if modules.contains(&head) {
                        let line = code[..k + prefix.len() + at].matches('\n').count();
                        found.push(format!(
                            "{}:{}: {} (in a grouped import)",
                            f.display(),
                            line + 1,
                            lines[line].trim_start()
                        ));
                    }
                }
            }
        }
    }
    found
}

/// The first path segment of every top-level item of the group `{...}` at
/// the start of `s`, with its byte offset in `s`.
fn group_heads(s: &str) -> Vec<(usize, &str)> {
    let mut ends = Vec::new();
    let mut depth = 0usize;
    for (k, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' if depth == 1 => {
                ends.push(k);
                break;
            }
            '}' => depth -= 1,
            ',' if depth == 1 => ends.push(k),
            _ => {}
        }
    }
    let mut out = Vec::new();
    let mut start = 1;
    for end in ends {
        let item = &s[start..end];
        let trimmed = item.trim_start();
        let head = trimmed
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .next()
            .unwrap_or("");
        if !head.is_empty() {
            out.push((start + item.len() - trimmed.len(), head));
        }
        start = end + 1;
    }
    out
}

#[test]
fn ground_names_no_upper_module() {
    let bad = arrows(&["vec3.rs", "check", "jet", "mesh", "surface"], UPPER);
    assert!(bad.is_empty(), "upward imports:\n{}", bad.join("\n"));
}

/// The equation families: each sits beside the others, below modeling.
const FAMILIES: &[&str] = &["pde4", "pde6", "ode6", "plate", "conv", "profile"];

#[test]
fn families_name_no_modeling_module_nor_each_other() {
    let above = [
        "sketch",
        "template",
        "sasm",
        "body",
        "face",
        "character",
        "edit",
        "pipeline",
        "demo",
        "makehuman",
        "render",
        "tui",
        "verify",
        "study",
        "cli",
    ];
    let mut bad = Vec::new();
    for f in FAMILIES {
        let mut named: Vec<&str> = above.to_vec();
        named.extend(FAMILIES.iter().filter(|g| *g != f));
        bad.extend(arrows(&[f], &named));
    }
    assert!(
        bad.is_empty(),
        "upward or sideways imports:\n{}",
        bad.join("\n")
    );
}

#[test]
fn mesh_is_below_surface() {
    // surface tessellates into meshes; mesh never names surface back.
    let bad = arrows(&["mesh"], &["surface"]);
    assert!(bad.is_empty(), "mesh imports surface:\n{}", bad.join("\n"));
}

#[test]
fn vec3_is_the_bottom() {
    let mut all: Vec<&str> = UPPER.to_vec();
    all.extend(["check", "jet", "mesh", "surface", "limits"]);
    let bad = arrows(&["vec3.rs"], &all);
    assert!(bad.is_empty(), "vec3 imports:\n{}", bad.join("\n"));
}

#[test]
fn the_scan_sees_an_upward_import() {
    // The scanner itself: a line naming a family is found, also inside a
    // grouped import; a doc comment and a longer name (`crate::pde4x`) are
    // not.
    let dir = std::env::temp_dir().join(format!("pdesculpt-layers-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let f = dir.join("probe.rs");
    std::fs::write(
        &f,
        "//! [`crate::pde4`]\nuse crate::pde4x::A;\nuse crate::pde6::B;\n\
         use crate::{jet::Jet, ode6::C};\nuse crate::{\n    mesh,\n    plate::{D, E},\n};\n",
    )
    .expect("write probe");
    let hits = arrows_in(std::slice::from_ref(&f), UPPER);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(hits.len(), 3, "{hits:?}");
    assert!(hits[0].contains(":3: use crate::pde6::B;"), "{hits:?}");
    // grouped imports, on one line and over several
    assert!(
        hits[1].contains(":4: use crate::{jet::Jet, ode6::C};"),
        "{hits:?}"
    );
    assert!(hits[2].contains(":7: plate::{D, E},"), "{hits:?}");
}
