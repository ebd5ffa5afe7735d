//! The equation index `docs/equations.md` is what the registry generates
//! now, and its hand-written part (which function implements which
//! equation) covers every numbered equation with items that exist.

use pdesculpt::equations::{
    covered, errata_entries, implementation, index_markdown, named_alone, numbered_equations,
    ERRATA, IMPLEMENTATIONS,
};
use std::path::Path;

const REGENERATE: &str = "cargo run --release -- verify --index docs/equations.md";

#[test]
fn equation_index_is_current() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/equations.md");
    let committed = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (generate it: {REGENERATE})", path.display()));
    let generated = index_markdown(crate::registry::all_checks(), ERRATA);
    if committed != generated {
        let (line, (c, g)) = committed
            .lines()
            .zip(generated.lines())
            .enumerate()
            .find(|(_, (c, g))| c != g)
            .unwrap_or((
                committed.lines().count().min(generated.lines().count()),
                ("(end of file)", "(end of file)"),
            ));
        panic!(
            "docs/equations.md is out of date (first difference at line {}):\n  committed: {c}\n  generated: {g}\nregenerate it: {REGENERATE}",
            line + 1
        );
    }
}

#[test]
fn every_numbered_equation_has_an_implementation() {
    let missing: Vec<String> = numbered_equations()
        .into_iter()
        .flat_map(|(p, eqs)| eqs.into_iter().map(move |e| (p, e)))
        .filter(|(p, e)| implementation(p, e).is_none())
        .map(|(p, e)| format!("{p} eq {e}"))
        .collect();
    assert!(missing.is_empty(), "no implementation row: {missing:?}");
}

#[test]
fn implementations_name_items_that_exist() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for i in IMPLEMENTATIONS {
        let text = std::fs::read_to_string(root.join(i.file))
            .unwrap_or_else(|e| panic!("{}: {} ({e})", i.item, i.file));
        let name = i.item.rsplit("::").next().unwrap_or(i.item);
        let defined = ["fn", "struct", "enum", "const", "trait"]
            .iter()
            .any(|k| text.contains(&format!("{k} {name}")));
        assert!(defined, "{} is not defined in {}", i.item, i.file);
        assert!(
            !covered(i.equations).is_empty(),
            "{}: no equations in {:?}",
            i.item,
            i.equations
        );
    }
}

#[test]
fn equation_fields_parse_into_labels_and_ranges() {
    assert_eq!(named_alone("eq 7, A9-A12"), vec!["7"]);
    assert_eq!(named_alone("eqs 8-19"), Vec::<String>::new());
    assert_eq!(
        covered("eq 7, A9-A12"),
        vec!["7", "A9", "A10", "A11", "A12"]
    );
    assert_eq!(covered("eqs 24-25 (global)"), vec!["24", "25"]);
    assert_eq!(covered("app A5, B3"), vec!["A5", "B3"]);
    assert!(covered("sec 3.1 (kernel)").is_empty());
    assert!(covered("Fig 6b").is_empty());
    assert_eq!(covered("Eqs 5 and 7"), vec!["5", "7"]);
    assert_eq!(covered("eq 7 / eqs A9-A10"), vec!["7", "A9", "A10"]);
}

#[test]
fn errata_entries_carry_their_paper_equations_and_checks() {
    let entries = errata_entries(ERRATA);
    assert!(!entries.is_empty(), "no ERRATA entries parsed");
    for e in &entries {
        assert_eq!(e.paper.len(), 3, "entry without a paper: {}", e.title);
    }
    // every paper with errata has at least one entry naming equations
    for paper in ["000", "001", "002", "004"] {
        assert!(
            entries
                .iter()
                .any(|e| e.paper == paper && !e.equations.is_empty()),
            "paper {paper}: no ERRATA entry names an equation"
        );
    }
    // and the entries cite checks
    assert!(entries.iter().any(|e| !e.checks.is_empty()));
}
