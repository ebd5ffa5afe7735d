//! The equation index (`docs/equations.md`): every numbered equation of the
//! papers, the function that implements it, the checks that measure it and
//! its ERRATA.md entries, generated from the check registry.
//!
//! The checks come from [`crate::verify::run`] (their `equation` fields),
//! the ERRATA entries from ERRATA.md (parsed: an entry names its equations
//! in its title and cites its checks), and the implementing functions from
//! [`IMPLEMENTATIONS`], the one hand-written table here (its rows are
//! tested: every numbered equation has one, every named item exists in its
//! file). `pdesculpt verify --index docs/equations.md` writes the file;
//! `tests/it/equations.rs` fails when the committed file differs from what
//! the registry generates now.

use crate::check::Check;
use std::fmt::Write as _;

/// ERRATA.md as compiled in.
pub const ERRATA: &str = include_str!("../ERRATA.md");

/// The function (or type) that implements a range of equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Implementation {
    /// Paper number, `"000"`..`"004"`.
    pub paper: &'static str,
    /// The equations: numbers and ranges separated by commas (`"3-8"`,
    /// `"A1-A5"`, `"16"`), parsed like a check's `equation` field.
    pub equations: &'static str,
    /// The item's path in the crate (`pde6::mode::ModeBasis::new`).
    pub item: &'static str,
    /// The file that defines it, from the crate root (`src/pde6/mode.rs`).
    pub file: &'static str,
}

macro_rules! imp {
    ($p:literal, $e:literal, $i:literal, $f:literal) => {
        Implementation {
            paper: $p,
            equations: $e,
            item: $i,
            file: $f,
        }
    };
}

/// Which function implements which equations (the first row covering an
/// equation is its implementation in the index).
#[rustfmt::skip]
pub const IMPLEMENTATIONS: &[Implementation] = &[
    imp!("000", "1", "pde4::ShapeParams", "src/pde4/mod.rs"),
    imp!("000", "2-3", "pde4::force::Force::profile", "src/pde4/force.rs"),
    imp!("000", "4", "pde4::force::Force::two_sided", "src/pde4/force.rs"),
    imp!("000", "5-9", "pde4::two_sided::mode::Mode::exact", "src/pde4/two_sided/mode.rs"),
    imp!("000", "10-11", "pde4::force::Force::four_sided", "src/pde4/force.rs"),
    imp!("000", "12-15", "pde4::four_sided::FourSided::new", "src/pde4/four_sided.rs"),
    imp!("000", "16", "curve::gec::Gec::eval", "src/curve/gec/mod.rs"),
    imp!("000", "A1-A5", "pde4::force::Force::two_sided", "src/pde4/force.rs"),
    imp!("000", "B1-B3", "pde4::force::Force::four_sided", "src/pde4/force.rs"),
    imp!("001", "1-2", "plate::disk_solution", "src/plate/mod.rs"),
    imp!("001", "3", "plate::Material::rigidity", "src/plate/mod.rs"),
    imp!("001", "4-12", "plate::disk_solution", "src/plate/mod.rs"),
    imp!("001", "13", "plate::projection::ViewPlane::project", "src/plate/projection.rs"),
    imp!("001", "14", "plate::projection::LocalFrame::to_local", "src/plate/projection.rs"),
    imp!("001", "15", "plate::boundary::alpha_shape", "src/plate/boundary.rs"),
    imp!("001", "16", "plate::mapping::DiskMapping::map_point", "src/plate/mapping.rs"),
    imp!("002", "1", "curve::gec::fit", "src/curve/gec/fit.rs"),
    imp!("002", "2", "pde6::patch::Patch::solve", "src/pde6/patch.rs"),
    imp!("002", "3-5", "pde6::patch::Patch::solve", "src/pde6/patch.rs"),
    imp!("002", "6-8", "pde6::mode::ModeBasis::new", "src/pde6/mode.rs"),
    imp!("002", "9-13", "pde6::mode::ModeSolver::new", "src/pde6/mode.rs"),
    imp!("002", "14", "pde6::patch::Patch::section", "src/pde6/patch.rs"),
    imp!("002", "15-23", "pde6::patch::Patch::through_curves", "src/pde6/patch.rs"),
    imp!("002", "24-27", "pde6::patch::Patch::carried_over", "src/pde6/patch.rs"),
    imp!("002", "A1-A3", "pde6::patch::Patch::solve", "src/pde6/patch.rs"),
    imp!("002", "A4-A16", "pde6::mode::ModeBasis::new", "src/pde6/mode.rs"),
    imp!("002", "A17-A36", "pde6::mode::method2_conditions", "src/pde6/mode.rs"),
    imp!("004", "1", "ode6::boundary::BoundaryCurves::direct", "src/ode6/boundary.rs"),
    imp!("004", "2", "ode6::basis::Basis::new", "src/ode6/basis/mod.rs"),
    imp!("004", "3-7", "ode6::boundary::Approach2::weights", "src/ode6/boundary.rs"),
    imp!("004", "8-18", "ode6::basis::Basis::new", "src/ode6/basis/mod.rs"),
    imp!("004", "19", "ode6::surface::Ode6Surface::new", "src/ode6/surface.rs"),
    imp!("004", "20-22", "ode6::basis::Basis::g", "src/ode6/basis/mod.rs"),
    imp!("004", "23-25", "ode6::surface::Chain::from_sections", "src/ode6/surface.rs"),
    imp!("004", "26", "ode6::surface::Grid::from_knots", "src/ode6/surface.rs"),
];

/// Every numbered equation of the five papers: 000 eqs 1-16 with appendix
/// eqs A1-A5 and B1-B3; 001 eqs 1-16; 002 eqs 1-27 with appendix eqs
/// A1-A36; 003 none (its displayed definitions are checked under
/// "sec 3.x"); 004 eqs 1-26.
pub fn numbered_equations() -> Vec<(&'static str, Vec<String>)> {
    let range = |prefix: &str, a: usize, b: usize| -> Vec<String> {
        (a..=b).map(|i| format!("{prefix}{i}")).collect()
    };
    vec![
        (
            "000",
            [range("", 1, 16), range("A", 1, 5), range("B", 1, 3)].concat(),
        ),
        ("001", range("", 1, 16)),
        ("002", [range("", 1, 27), range("A", 1, 36)].concat()),
        ("003", Vec::new()),
        ("004", range("", 1, 26)),
    ]
}

/// `field` with parenthesised qualifiers removed.
fn strip_parens(field: &str) -> String {
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
}

/// An equation label: digits with an optional `A`/`B` prefix.
fn label(item: &str) -> Option<String> {
    let digits = item.trim_start_matches(['A', 'B']);
    (!digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit())).then(|| item.to_string())
}

/// The comma-separated items of `field` with a leading "eq"/"eqs"/"app"
/// dropped (case-insensitive "Eqs" too).
fn items(field: &str) -> Vec<String> {
    strip_parens(field)
        .replace(" and ", ", ")
        .replace(" / ", ", ")
        .split([',', ';'])
        .map(|item| {
            let item = item.trim();
            [
                "eqs ",
                "eq ",
                "Eqs ",
                "Eq ",
                "app ",
                "appendix ",
                "equations ",
            ]
            .iter()
            .find_map(|p| item.strip_prefix(p))
            .unwrap_or(item)
            .trim()
            .to_string()
        })
        .collect()
}

/// The equations a check's `equation` field names alone: items separated
/// by commas, parenthesised qualifiers dropped, a leading "eq"/"eqs"/"app"
/// dropped; ranges ("eqs 8-19") name no equation alone.
pub fn named_alone(field: &str) -> Vec<String> {
    items(field).iter().filter_map(|i| label(i)).collect()
}

/// The equations `field` covers: those it names alone and every equation of
/// its ranges (`"8-19"`, `"A17-A36"`; a range's ends share their prefix).
pub fn covered(field: &str) -> Vec<String> {
    let mut out = Vec::new();
    for item in items(field) {
        if let Some(l) = label(&item) {
            out.push(l);
        } else if let Some((a, b)) = item.split_once(['-', '\u{2013}']) {
            let (a, b) = (a.trim(), b.trim());
            let prefix = &a[..a.len() - a.trim_start_matches(['A', 'B']).len()];
            let num = |s: &str| s.trim_start_matches(['A', 'B']).parse::<usize>().ok();
            if let (Some(x), Some(y)) = (num(a), num(b)) {
                if x <= y && y - x < 100 {
                    out.extend((x..=y).map(|i| format!("{prefix}{i}")));
                }
            }
        }
    }
    out
}

/// One ERRATA.md entry: a `###` heading or a top-level bullet with a bold
/// title, in the section of one paper.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrataEntry {
    pub paper: String,
    pub title: String,
    /// The anchor of the entry's heading, or of its paper's section for a
    /// bullet entry.
    pub anchor: String,
    /// The equations its title covers.
    pub equations: Vec<String>,
    /// The check names it cites (backticked names with a dot).
    pub checks: Vec<String>,
}

/// GitHub's heading anchor: lower case, letters, digits, `-` and `_` kept,
/// spaces to `-`, everything else dropped.
pub fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The backticked names containing a dot in `text` (check names).
fn cited_checks(text: &str) -> Vec<String> {
    text.split('`')
        .skip(1)
        .step_by(2)
        .filter(|s| s.contains('.') && !s.contains(' ') && !s.contains('/'))
        .map(str::to_string)
        .collect()
}

/// The entries of ERRATA.md (see [`ErrataEntry`]).
pub fn errata_entries(text: &str) -> Vec<ErrataEntry> {
    let mut out: Vec<ErrataEntry> = Vec::new();
    let (mut paper, mut section) = (String::new(), String::new());
    for line in text.lines() {
        if let Some(h) = line.strip_prefix("## ") {
            section = anchor(h);
            paper = h
                .split_whitespace()
                .find(|w| w.len() == 3 && w.chars().all(|c| c.is_ascii_digit()))
                .unwrap_or("")
                .to_string();
            continue;
        }
        if paper.is_empty() {
            continue; // the introduction before the first paper's section
        }
        let title = if let Some(h) = line.strip_prefix("### ") {
            Some((h.trim().to_string(), anchor(h)))
        } else if let Some(rest) = line.strip_prefix("- **") {
            rest.split_once("**")
                .map(|(t, _)| (t.trim_end_matches('.').to_string(), section.clone()))
        } else {
            None
        };
        if let Some((title, anchor)) = title {
            // the title's own paper prefix ("000 eq 9") is dropped before parsing
            let eqs = title
                .strip_prefix(paper.as_str())
                .unwrap_or(&title)
                .trim()
                .to_string();
            let eqs = eqs.replace("appendix A, ", "").replace("appendix B, ", "");
            out.push(ErrataEntry {
                paper: paper.clone(),
                title: title.clone(),
                anchor,
                equations: covered(&eqs),
                checks: cited_checks(&title),
            });
        } else if let Some(e) = out.last_mut() {
            if !line.starts_with('#') {
                e.checks.extend(cited_checks(line));
            }
        }
    }
    out
}

/// The implementation row of `(paper, equation)`.
pub fn implementation(paper: &str, equation: &str) -> Option<&'static Implementation> {
    IMPLEMENTATIONS
        .iter()
        .find(|i| i.paper == paper && covered(i.equations).iter().any(|e| e == equation))
}

/// The checks of one index row and the ERRATA entries that belong to it.
fn row_cells(paper: &str, eq: &str, checks: &[Check], errata: &[ErrataEntry]) -> (String, String) {
    let alone: Vec<&Check> = checks
        .iter()
        .filter(|c| c.paper == paper && named_alone(&c.equation).iter().any(|e| e == eq))
        .collect();
    let ranged: Vec<&Check> = checks
        .iter()
        .filter(|c| {
            c.paper == paper
                && !named_alone(&c.equation).iter().any(|e| e == eq)
                && covered(&c.equation).iter().any(|e| e == eq)
        })
        .collect();
    let name = |c: &&Check| format!("`{}` ({})", c.name, c.kind);
    let mut cell: Vec<String> = alone.iter().map(name).collect();
    if !ranged.is_empty() {
        let names: Vec<String> = ranged.iter().map(|c| format!("`{}`", c.name)).collect();
        cell.push(format!("over a range: {}", names.join(", ")));
    }
    let named: Vec<&str> = alone.iter().map(|c| c.name.as_str()).collect();
    let entries: Vec<String> = errata
        .iter()
        .filter(|e| {
            // an entry whose title names equations belongs to those; one
            // whose title names none (a section, a figure) to the
            // equations its cited checks name alone
            e.paper == paper
                && (e.equations.iter().any(|x| x == eq)
                    || (e.equations.is_empty()
                        && e.checks.iter().any(|c| named.contains(&c.as_str()))))
        })
        .map(|e| format!("[{}](../ERRATA.md#{})", e.title.replace('|', "/"), e.anchor))
        .collect();
    (cell.join(", "), entries.join("; "))
}

/// The markdown of `docs/equations.md` for `checks` (the registry's, in
/// its order) and the ERRATA.md text `errata`.
pub fn index_markdown(checks: &[Check], errata: &str) -> String {
    let entries = errata_entries(errata);
    let mut s = String::new();
    let _ = writeln!(s, "# Equation index\n");
    let _ = writeln!(
        s,
        "<!-- Generated by `pdesculpt verify --index docs/equations.md` from the check \
         registry and ERRATA.md; do not edit by hand. tests/it/equations.rs fails when \
         this file is out of date. -->\n"
    );
    let _ = writeln!(
        s,
        "Every numbered equation of the five papers ([papers.md](papers.md)), the function \
         that implements it, the checks that measure it (`pdesculpt verify` runs them; the \
         kind in brackets) and the [ERRATA.md](../ERRATA.md) entries about it. A check \
         \"over a range\" measures several equations at once. {} checks in all.\n",
        checks.len()
    );
    for (paper, eqs) in numbered_equations() {
        let _ = writeln!(s, "## Paper {paper}\n");
        if !eqs.is_empty() {
            let _ = writeln!(s, "| eq | implemented by | checks | ERRATA |");
            let _ = writeln!(s, "|---|---|---|---|");
            for eq in &eqs {
                let imp = implementation(paper, eq)
                    .map_or("-".to_string(), |i| format!("`{}` ({})", i.item, i.file));
                let (cell, errata) = row_cells(paper, eq, checks, &entries);
                let _ = writeln!(s, "| {eq} | {imp} | {cell} | {errata} |");
            }
            s.push('\n');
        }
        other_items(&mut s, paper, checks);
    }
    s
}

/// The checks of `paper` whose `equation` field names no numbered
/// equation (sections, figures, tables), grouped by that field.
fn other_items(s: &mut String, paper: &str, checks: &[Check]) {
    let mut groups: Vec<(&str, Vec<&Check>)> = Vec::new();
    for c in checks
        .iter()
        .filter(|c| c.paper == paper && covered(&c.equation).is_empty())
    {
        match groups.iter_mut().find(|(e, _)| *e == c.equation) {
            Some((_, v)) => v.push(c),
            None => groups.push((&c.equation, vec![c])),
        }
    }
    if groups.is_empty() {
        return;
    }
    let _ = writeln!(s, "Sections, figures and tables of paper {paper}:\n");
    let _ = writeln!(s, "| item | checks |");
    let _ = writeln!(s, "|---|---|");
    for (eq, cs) in groups {
        let names: Vec<String> = cs
            .iter()
            .map(|c| format!("`{}` ({})", c.name, c.kind))
            .collect();
        let _ = writeln!(s, "| {} | {} |", eq.replace('|', "/"), names.join(", "));
    }
    s.push('\n');
}
