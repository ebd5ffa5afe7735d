//! The file-level import graph of `src/` (issue 29): no import loop, and no
//! arrow from a lower layer to a higher one.
//!
//! An arrow `a -> b` is a path in `a` (outside its `#[cfg(test)]` part and
//! its comments) that names an item of file `b`: `crate::m::...`,
//! `super::...`, `self::...`, also inside grouped imports. A name a folder's
//! `mod.rs` re-exports (`pub use child::Name`) leads to the file that
//! defines it, so importing through a folder's face is an arrow to the
//! file behind it. A `mod.rs` naming its own children (declaring,
//! re-exporting, calling them) holds them: that is no arrow.
//!
//! Layers ([`layer`]), bottom up: the ground, the equation families, then
//! the modeling layer in three steps (the character document and its
//! assembly; the modeling operations, which never name each other; the one
//! build), the verification of the modeling operations (their `check` and
//! `demo` files, which build bundled characters), and the top.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A module path (`["sketch", "derive"]`) and the file holding it.
struct File {
    module: Vec<String>,
    path: PathBuf,
    is_face: bool,
    code: String,
}

/// Loops that existed when this test was written, in files other
/// developers own; each must disappear (an entry that no longer matches a
/// loop fails [`no_import_loop`]), none may be added. Sorted file lists.
const KNOWN_LOOPS: &[&[&str]] = &[];

fn files_under(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let p = e.expect("directory entry").path();
        if p.is_dir() {
            files_under(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Code without comments and without the `#[cfg(test)]` tail.
fn code_of(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .map(|l| match l.find("//") {
            Some(k) if !l[..k].contains('"') => &l[..k],
            _ => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn load(src: &Path) -> Vec<File> {
    let mut paths = Vec::new();
    files_under(src, &mut paths);
    paths.sort();
    paths
        .into_iter()
        .filter(|p| !p.ends_with("main.rs") || p.parent() != Some(src))
        .map(|p| {
            let rel = p.strip_prefix(src).expect("under src");
            let mut module: Vec<String> = rel
                .with_extension("")
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            let is_face = module.last().is_some_and(|m| m == "mod");
            if is_face || module == ["lib"] {
                module.pop();
            }
            let text = std::fs::read_to_string(&p).expect("readable source");
            File {
                module,
                path: p,
                is_face,
                code: code_of(&text),
            }
        })
        .collect()
}

fn ident(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

/// The items of the group `{...}` at the start of `s`, each as path
/// segments (nested groups flattened).
fn group_items(s: &str) -> Vec<Vec<String>> {
    let mut depth = 0usize;
    let mut end = s.len();
    for (k, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    end = k;
                    break;
                }
            }
            _ => {}
        }
    }
    let inner = &s[1..end];
    let mut out = Vec::new();
    let (mut depth, mut start) = (0usize, 0usize);
    for (k, c) in inner
        .char_indices()
        .chain(std::iter::once((inner.len(), ',')))
    {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                let item = inner[start..k.min(inner.len())].trim();
                start = k + 1;
                if item.is_empty() {
                    continue;
                }
                match item.find("::{") {
                    Some(g) => {
                        let head: Vec<String> = item[..g].split("::").map(Into::into).collect();
                        for tail in group_items(&item[g + 2..]) {
                            out.push(head.iter().cloned().chain(tail).collect());
                        }
                    }
                    None => out.push(
                        item.split("::")
                            .map(|x| ident(x.trim()).to_string())
                            .filter(|x| !x.is_empty())
                            .collect(),
                    ),
                }
            }
            _ => {}
        }
    }
    out
}

/// Every path in `code` that starts at `crate`, `super` or `self`, as
/// absolute segments (`module` is the file's own module).
fn paths(module: &[String], code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    for head in ["crate::", "super::", "self::", "pdesculpt::"] {
        for (k, _) in code.match_indices(head) {
            if k > 0
                && (bytes[k - 1].is_ascii_alphanumeric()
                    || bytes[k - 1] == b'_'
                    || bytes[k - 1] == b':')
            {
                continue;
            }
            let mut base: Vec<String> = match head {
                "crate::" | "pdesculpt::" => Vec::new(),
                "self::" => module.to_vec(),
                _ => module[..module.len().saturating_sub(1)].to_vec(),
            };
            let mut rest = &code[k + head.len()..];
            while let Some(r) = rest.strip_prefix("super::") {
                base.pop();
                rest = r;
            }
            let mut segs = base;
            loop {
                if rest.starts_with('{') {
                    for tail in group_items(rest) {
                        out.push(segs.iter().cloned().chain(tail).collect());
                    }
                    break;
                }
                let id = ident(rest);
                if id.is_empty() {
                    out.push(segs.clone());
                    break;
                }
                segs.push(id.to_string());
                rest = &rest[id.len()..];
                match rest.strip_prefix("::") {
                    Some(r) => rest = r,
                    None => {
                        out.push(segs.clone());
                        break;
                    }
                }
            }
        }
    }
    out
}

/// `pub use` statements of a file: (statement text, is the whole line).
fn pub_uses(code: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(k) = rest.find("pub") {
        let after = &rest[k..];
        let stmt_start =
            after
                .strip_prefix("pub")
                .map(|a| a.trim_start())
                .map(|a| match a.strip_prefix('(') {
                    Some(b) => b.split_once(')').map_or(b, |(_, c)| c).trim_start(),
                    None => a,
                });
        let word_ok = k == 0 || !rest.as_bytes()[k - 1].is_ascii_alphanumeric();
        match stmt_start {
            Some(s) if word_ok && s.starts_with("use ") => {
                let end = s.find(';').unwrap_or(s.len());
                out.push(&s[4..end]);
                let consumed = rest.len() - s.len() + end;
                rest = &rest[consumed.min(rest.len())..];
            }
            _ => rest = &rest[k + 3..],
        }
    }
    out
}

/// The import graph: file index -> (file index -> the path that names it).
struct Graph {
    files: Vec<File>,
    edges: Vec<BTreeMap<usize, String>>,
}

fn graph(src: &Path) -> Graph {
    let files = load(src);
    let index: BTreeMap<Vec<String>, usize> = files
        .iter()
        .enumerate()
        .map(|(i, f)| (f.module.clone(), i))
        .collect();
    // re-exports: (module, name) -> the absolute path it stands for
    let mut reexports: BTreeMap<(Vec<String>, String), Vec<String>> = BTreeMap::new();
    for f in &files {
        for stmt in pub_uses(&f.code) {
            let stmt = stmt.trim();
            let full = if stmt.starts_with(|c: char| c.is_alphanumeric() || c == '_')
                && !["crate", "super", "self", "pdesculpt"].contains(&ident(stmt))
            {
                format!("self::{stmt}")
            } else {
                stmt.to_string()
            };
            for p in paths(&f.module, &full) {
                if let Some(last) = p.last() {
                    reexports.insert((f.module.clone(), last.clone()), p);
                }
            }
        }
    }
    let resolve = |segs: &[String]| -> Option<usize> {
        let mut segs = segs.to_vec();
        for _ in 0..16 {
            let k = (0..=segs.len())
                .rev()
                .find(|&k| index.contains_key(&segs[..k]))?;
            let m = segs[..k].to_vec();
            match segs.get(k) {
                Some(name) if reexports.contains_key(&(m.clone(), name.clone())) => {
                    let target = &reexports[&(m, name.clone())];
                    let mut next = target.clone();
                    next.extend(segs[k + 1..].iter().cloned());
                    if next == segs {
                        return index.get(&segs[..k]).copied();
                    }
                    segs = next;
                }
                _ => return index.get(&m).copied(),
            }
        }
        None
    };
    let mut edges = vec![BTreeMap::new(); files.len()];
    for (i, f) in files.iter().enumerate() {
        for p in paths(&f.module, &f.code) {
            let Some(j) = resolve(&p) else { continue };
            let holds = f.is_face && files[j].module.starts_with(&f.module);
            if j != i && !files[j].module.is_empty() && !holds {
                edges[i].entry(j).or_insert_with(|| p.join("::"));
            }
        }
    }
    Graph { files, edges }
}

/// Strongly connected components with more than one file (Tarjan,
/// iterative), each as sorted module names.
fn loops(g: &Graph) -> Vec<Vec<String>> {
    let n = g.files.len();
    let (mut index, mut low) = (vec![usize::MAX; n], vec![0; n]);
    let (mut on, mut stack, mut out, mut next) = (vec![false; n], Vec::new(), Vec::new(), 0);
    for root in 0..n {
        if index[root] != usize::MAX {
            continue;
        }
        let mut work: Vec<(usize, Vec<usize>)> = Vec::new();
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root);
        on[root] = true;
        work.push((root, g.edges[root].keys().copied().collect()));
        while let Some((v, todo)) = work.last_mut() {
            let v = *v;
            if let Some(w) = todo.pop() {
                if index[w] == usize::MAX {
                    index[w] = next;
                    low[w] = next;
                    next += 1;
                    stack.push(w);
                    on[w] = true;
                    work.push((w, g.edges[w].keys().copied().collect()));
                } else if on[w] {
                    low[v] = low[v].min(index[w]);
                }
                continue;
            }
            work.pop();
            if let Some((u, _)) = work.last() {
                low[*u] = low[*u].min(low[v]);
            }
            if low[v] == index[v] {
                let mut comp = Vec::new();
                while let Some(w) = stack.pop() {
                    on[w] = false;
                    comp.push(g.files[w].module.join("::"));
                    if w == v {
                        break;
                    }
                }
                if comp.len() > 1 {
                    comp.sort();
                    out.push(comp);
                }
            }
        }
    }
    out.sort();
    out
}

/// Top-level modules by layer, bottom up. An arrow may only point to a
/// lower layer or stay inside its own top-level module (where it may not
/// point from a file of a lower layer to one of a higher, see
/// [`layer`]). Modules on one layer never name each other: the equation
/// families, and the modeling operations (sketch-guided global modeling,
/// template modeling, local edits, SASM, the body reconstruction).
const LAYERS: &[&[&str]] = &[
    &["vec3", "polygon"],
    &["check", "limits", "progress"],
    &["jet"],
    &["mesh"],
    &["surface", "makehuman", "render"],
    &["curve"],
    &["pde4", "pde6", "ode6", "plate", "conv", "profile"],
    &["character"],
    &["sketch", "template", "edit", "sasm", "body", "face"],
    &["pipeline"],
    &[],
    &["demo"],
    &["verify", "study", "tui", "equations", "harness"],
    &["cli", "main"],
];

/// The layer of the modeling operations' verification: their `check` and
/// `demo` files, which build bundled characters through the pipeline.
const CHECKS: usize = 10;

/// The layer of the modeling operations.
const OPERATIONS: usize = 8;

/// A file's layer: its top-level module's, except a modeling operation's
/// `check.rs`, `check_*.rs`, `check/` and `demo.rs`, which are [`CHECKS`].
fn layer(module: &[String]) -> Option<usize> {
    let top = module.first().map_or("lib", String::as_str);
    if top == "lib" {
        return Some(LAYERS.len());
    }
    let l = LAYERS.iter().position(|ms| ms.contains(&top))?;
    let verification = module[1..]
        .iter()
        .any(|m| m == "check" || m.starts_with("check_") || m == "demo");
    if l == OPERATIONS && verification {
        return Some(CHECKS);
    }
    Some(l)
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn no_import_loop() {
    let g = graph(&src());
    let found = loops(&g);
    let known: Vec<Vec<String>> = KNOWN_LOOPS
        .iter()
        .map(|l| l.iter().map(|s| s.to_string()).collect())
        .collect();
    let new: Vec<String> = found
        .iter()
        .filter(|l| !known.contains(l))
        .map(|l| {
            let mut why = Vec::new();
            for a in l {
                let i = g.files.iter().position(|f| &f.module.join("::") == a);
                for (j, p) in i.map(|i| &g.edges[i]).into_iter().flatten() {
                    if l.contains(&g.files[*j].module.join("::")) {
                        why.push(format!(
                            "    {a} -> {} ({p})",
                            g.files[*j].module.join("::")
                        ));
                    }
                }
            }
            format!("{}\n{}", l.join(", "), why.join("\n"))
        })
        .collect();
    assert!(new.is_empty(), "import loops:\n{}", new.join("\n"));
    let stale: Vec<&Vec<String>> = known.iter().filter(|l| !found.contains(l)).collect();
    assert!(
        stale.is_empty(),
        "KNOWN_LOOPS lists loops that are gone (delete them): {stale:?}"
    );
}

#[test]
fn no_upward_import() {
    let g = graph(&src());
    let mut bad = Vec::new();
    for (i, f) in g.files.iter().enumerate() {
        let from = layer(&f.module);
        for (&j, p) in &g.edges[i] {
            let t = &g.files[j];
            let to = layer(&t.module);
            let same = f.module.first() == t.module.first();
            // the verification of the modeling operations may share
            // fixtures (the bundled characters of `sketch::check`)
            let ok = match (from, to) {
                (Some(a), Some(b)) => b < a || ((same || a == CHECKS) && b <= a),
                _ => false,
            };
            if !ok {
                bad.push(format!(
                    "{} (layer {from:?}) -> {} (layer {to:?}): {p}",
                    f.path.display(),
                    t.module.join("::")
                ));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "upward or sideways imports:\n{}",
        bad.join("\n")
    );
}

#[test]
fn every_module_has_a_layer() {
    let g = graph(&src());
    let missing: Vec<String> = g
        .files
        .iter()
        .filter(|f| layer(&f.module).is_none())
        .map(|f| f.path.display().to_string())
        .collect();
    assert!(missing.is_empty(), "files of no layer: {missing:?}");
}

#[test]
fn the_graph_sees_loops_and_upward_arrows() {
    // A small tree: a face re-exporting its child, a loop through the
    // face, an upward arrow from the ground, a grouped import, a doc
    // comment and a test module that name nothing.
    let dir = std::env::temp_dir().join(format!("pdesculpt-graph-{}", std::process::id()));
    let write = |rel: &str, text: &str| {
        let p = dir.join(rel);
        std::fs::create_dir_all(p.parent().expect("parent")).expect("dir");
        std::fs::write(p, text).expect("write");
    };
    write("lib.rs", "pub mod vec3;\npub mod sketch;\n");
    write(
        "vec3.rs",
        "//! [`crate::sketch`]\npub fn f() {}\n#[cfg(test)]\nmod t { use crate::sketch::a::A; }\n",
    );
    write("sketch/mod.rs", "mod a;\nmod b;\npub use a::A;\n");
    write("sketch/a.rs", "use super::b::{self, B};\npub struct A;\n");
    write(
        "sketch/b.rs",
        "use crate::{sketch::A, vec3::f};\npub struct B;\n",
    );
    let g = graph(&dir);
    let found = loops(&g);
    write("vec3.rs", "pub fn f() { crate::sketch::b::g() }\n");
    let up = graph(&dir);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(
        found,
        vec![vec!["sketch::a".to_string(), "sketch::b".to_string()]]
    );
    let vec3 = g
        .files
        .iter()
        .position(|f| f.module == ["vec3"])
        .expect("vec3");
    assert!(g.edges[vec3].is_empty(), "{:?}", g.edges[vec3]);
    let vec3 = up
        .files
        .iter()
        .position(|f| f.module == ["vec3"])
        .expect("vec3");
    let b = up
        .files
        .iter()
        .position(|f| f.module == ["sketch", "b"])
        .expect("b");
    assert!(up.edges[vec3].contains_key(&b), "{:?}", up.edges[vec3]);
    assert!(layer(&["sketch".into(), "check".into()]) > layer(&["pipeline".into()]));
}
