//! The gallery: `paper_figures/out/index.html`, one static page (no server,
//! no network at view time) with, per paper, every figure beside its caption
//! (figure number and what it shows), the numbers of its data JSON in a
//! table and the checks it relies on (rows of `verify --json`, pass/fail),
//! and the models (GLB, metres) in a small dependency-free WebGL viewer
//! (`gallery/viewer.js`: GLB parser, orbit, per-part toggles).
//!
//! A `file://` page may not `fetch` files or import modules, so each model's
//! GLB is also written as `gallery/<name>.glb.js`, a classic script that
//! registers the bytes (base64) with the viewer. `verify/gallery/test.mjs`
//! opens the page in headless Chromium and checks it.

use crate::common::{Ctx, Figure};
use pdesculpt::check::Check;
use pdesculpt::mesh::unit;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

#[path = "gallery/checks.rs"]
mod checks;

/// The viewer script (written beside the page).
const VIEWER_JS: &str = include_str!("gallery/viewer.js");
/// The page's style sheet (inlined).
const STYLE_CSS: &str = include_str!("gallery/style.css");

/// The figure that writes the demo's models into the gallery: the demo
/// character (MakeHuman body, chest and belly edits, skirt, teddy) and its
/// C2 PDE6 reconstruction, both GLB in metres.
pub fn figures() -> Vec<Figure> {
    vec![Figure {
        id: "demo-models",
        paper: "all",
        title:
            "The demo character and its PDE6 reconstruction as GLB (metres) for the gallery viewer",
        run: demo_models,
    }]
}

fn demo_models(ctx: &Ctx) -> anyhow::Result<()> {
    use pdesculpt::mesh::io::{write_scene_in_unit, Layout, Scene};
    let d = pdesculpt::demo::build()?;
    // the same models and parts as `pdesculpt demo` writes
    let scene = Scene::single("body", d.sculpted.clone())
        .with("skirt", d.skirt.clone())
        .with("teddy", d.prop.clone());
    let recon = Scene::single("reconstruction", d.reconstruction.clone());
    for (name, s) in [("demo.glb", &scene), ("demo-pde6.glb", &recon)] {
        let p = ctx.path(name);
        write_scene_in_unit(s, &p, d.unit, unit::GLB, Layout::Parts)?;
        eprintln!("  wrote {}", p.display());
    }
    Ok(())
}

/// The papers, for the section headings.
const PAPERS: [(&str, &str); 5] = [
    ("000", "You et al., Fast character modeling with sketch-based PDE surfaces (2020)"),
    ("001", "Wang et al., Real-time surface manipulation with C1 continuity through simple and efficient physics-based deformations (2021)"),
    ("002", "Fu et al., 3D Modelling with C2 Continuous PDE Surface Patches (2022)"),
    ("003", "Kukelova, A User Interface for Freeform Modeling Based on Convolution Surfaces from Sketched Silhouette Curves (SketchCo)"),
    ("004", "Bian et al., Efficient C2 Continuous Surface Creation Technique Based on Ordinary Differential Equation (2020)"),
];

/// The papers' own captions, from the extracted texts in
/// `shared/papers/` (paper 001's captions are not in its extraction).
const PAPER_CAPTIONS: &[(&str, &str)] = &[
    ("000-fig1", "First type of deformations. a Original model. b A concentrated sculpting force acts at the tail. c A line distribution force acts at the neck. d An area distribution force acts at the back. e Combination of deformations in (b), (c) and (d)"),
    ("000-fig2", "Second type of deformations. a Nose deformation in a small region caused by a concentrated sculpting force. b Arm deformation in a very narrow curved band region caused by a line distribution sculpting force. c Chest deformation in a local region with an irregular boundary shape caused by an area distribution sculpting force"),
    ("000-fig3", "Comparison among original key cross-section profile curves (red), generalized elliptic curves (green), and standard ellipses (blue)"),
    ("000-fig5", "Our proposed sketch-guided modeling quickly creates an initial global model from a profile curve in (a), uses a secondary profile curve in (b) to generate an improved intermediate global model in (c), and introduces key cross-section profile sketches in (d) to obtain a fine detailed global model in (e)"),
    ("000-fig6", "Sketch-guided global modeling. a Primary profile curve. b Segmentation of primary profile curves and central curves. c Initial global model. d Secondary profile curves. e Secondary profile curves are applied on the initial global model. f, g Intermediate global model. h One key cross-section profile curve of the female is applied on the intermediate global model. i Breast of the female is created from the key cross-section profile curve. j Final global model is obtained by introducing more key cross-section profile curves"),
    ("000-fig8", "PDE based surface manipulation of a pig torso. a Original model. b Deformation with shape parameters 1.0. c Deformation with shape parameters 0.3. d Shape variation by changing boundary curves. e Shape variation by changing boundary tangents"),
    ("000-fig14", "Comparison of shape manipulation between sculpting force-based method of PDE deformation surfaces and vertex-based method of polygon models. (a) Undeformed shape. (b) Deformed shape achieved by sculpting force-based shape manipulation. (c) Deformed shape achieved by vertex-based shape manipulation"),
    ("002-table1", "Errors of curve fitting."),
    ("002-fig5", "The cross section curves and created human body parts."),
    ("002-fig6", "The cross section curves of the human body and the created human body model in front and side views using C2 continuous PDE method."),
    ("002-fig7a", "Surface shape generation from cross section curves by using the method proposed in this paper. (a) a smooth vase model, ..."),
    ("003-fig2", "Process of generating convolution surface from silhouette curve."),
    ("003-fig4", "Convolution surface without (resp. with) global interpolation."),
    ("003-fig5", "Results of tested non-linear least squares minimization methods."),
    ("003-fig7", "Example of merging operation"),
    ("003-fig8", "Silhouette curves with convolution surfaces."),
    ("004-fig2-3", "Figure 2. Closed surface modelling by using two boundary curves. Figure 3. Open surface modelling by using two boundary curves."),
    ("004-fig4-5", "Figure 4. Closed surface modelling by using two boundary and four control curves. Figure 5. Open surface modelling by using two boundary and four control curves."),
    ("004-fig6", "(a-c) illustrate that our approach can connect surface patches with up to C2 continuities in both u and v parametric directions. (d) shows the comparison between C1 and C2 continuity; our approach can achieve better continuity between patches."),
    ("004-fig7", "Creation of surface models by patches."),
    ("004-fig8", "Creation of surface model by sketch."),
    ("004-fig9", "Global comparison between the face model (red golden) created by the curve network with the proposed method and the original polygon face model (silver)."),
    ("004-fig11-12", "Figure 11. Mathematical representation of Facial Action Coding System (FACS). Figure 12. One face curve network template which can be used to represent and reconstruct different face shapes by our algorithm."),
    ("004-fig13", "Reconstruct the surface of different Action Units from few curves by the proposed approach, and compare the realism between reconstructed surfaces and polygon surface."),
    ("004-fig10", "(a) shows the patch surface generated by default shape control values, (b) shows changing the values of shape control parameters will generate different surfaces."),
    ("004-table1", "The data size comparison between variables of polygon model and our approach."),
];

/// Models shown in viewers, in page order: file, title.
const MODELS: [(&str, &str); 3] = [
    ("demo.glb", "Demo character: MakeHuman body with the chest (000) and belly (001) edits, the ODE6 skirt (004) and the sketched teddy (003)"),
    ("demo-pde6.glb", "The demo body's C2 sixth-order PDE reconstruction (002), one part per colour"),
    ("002-fig6-body.glb", "002 Fig 6: the MakeHuman body reconstructed from its cross sections"),
];

/// Rows of the data table of one figure; longer JSONs are cut with a note.
const MAX_ROWS: usize = 40;
/// Columns of a records table.
const MAX_COLUMNS: usize = 10;
/// Arrays of numbers longer than this are summarised (count, min, max).
const MAX_INLINE: usize = 6;

/// "Fig. 11", "Table 1", "Figs 2-3" from a figure id; `None` for figures of
/// our own (not in the paper).
pub fn figure_number(id: &str) -> Option<String> {
    let tail = id.split_once('-')?.1;
    let (kind, rest) = if let Some(r) = tail.strip_prefix("fig") {
        ("Fig.", r)
    } else if let Some(r) = tail.strip_prefix("table") {
        ("Table", r)
    } else {
        return None;
    };
    if rest.is_empty() || !rest.starts_with(|c: char| c.is_ascii_digit()) {
        return None;
    }
    let kind = if rest.contains('-') && kind == "Fig." {
        "Figs"
    } else {
        kind
    };
    Some(format!("{kind} {rest}"))
}

/// Whether `file` belongs to figure `id`: its name starts with the id and
/// the id is not the prefix of a longer number (`001-fig1` owns
/// `001-fig1a-teapot.png`, not `001-fig11.json`).
fn belongs(file: &str, id: &str) -> bool {
    match file.strip_prefix(id) {
        Some(rest) => !rest.starts_with(|c: char| c.is_ascii_digit()),
        None => false,
    }
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn fmt_num(x: f64) -> String {
    if x == x.trunc() && x.abs() < 1e9 {
        format!("{x:.0}")
    } else if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e6) {
        format!("{x:.3e}")
    } else {
        format!("{x:.4}")
    }
}

/// Flattens a JSON value into (path, value) rows of numbers and short
/// strings; long numeric arrays become one summary row.
fn flatten(v: &Value, path: &str, rows: &mut Vec<(String, String)>) {
    match v {
        Value::Number(n) => rows.push((path.into(), fmt_num(n.as_f64().unwrap_or(f64::NAN)))),
        Value::Bool(b) => rows.push((path.into(), b.to_string())),
        Value::String(s) if s.len() <= 80 => rows.push((path.into(), s.clone())),
        Value::String(_) | Value::Null => {}
        Value::Array(a) => {
            let nums: Option<Vec<f64>> = a.iter().map(Value::as_f64).collect();
            match nums {
                Some(n) if n.len() > MAX_INLINE => {
                    let lo = n.iter().cloned().fold(f64::INFINITY, f64::min);
                    let hi = n.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
                    rows.push((
                        path.into(),
                        format!("{} numbers in [{}, {}]", n.len(), fmt_num(lo), fmt_num(hi)),
                    ));
                }
                Some(n) => rows.push((
                    path.into(),
                    n.iter().map(|x| fmt_num(*x)).collect::<Vec<_>>().join(", "),
                )),
                None => {
                    for (i, x) in a.iter().enumerate() {
                        flatten(x, &format!("{path}[{i}]"), rows);
                    }
                }
            }
        }
        Value::Object(o) => {
            for (k, x) in o {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                flatten(x, &p, rows);
            }
        }
    }
}

/// A list of records (objects) as one table: a row per record, a column
/// per flattened field (first `MAX_COLUMNS` fields in order of appearance).
fn records_table(name: &str, records: &[Value], h: &mut String) {
    let rows: Vec<Vec<(String, String)>> = records
        .iter()
        .map(|r| {
            let mut kv = Vec::new();
            flatten(r, "", &mut kv);
            kv
        })
        .collect();
    let mut cols: Vec<&str> = Vec::new();
    for kv in &rows {
        for (k, _) in kv {
            if !cols.contains(&k.as_str()) && cols.len() < MAX_COLUMNS {
                cols.push(k);
            }
        }
    }
    let _ = write!(
        h,
        "<table class=\"data\"><caption>{}</caption><tr>",
        esc(name)
    );
    for c in &cols {
        let _ = write!(h, "<th>{}</th>", esc(c));
    }
    h.push_str("</tr>");
    for kv in rows.iter().take(MAX_ROWS) {
        h.push_str("<tr>");
        for c in &cols {
            let x = kv
                .iter()
                .find(|(k, _)| k == c)
                .map_or("", |(_, x)| x.as_str());
            let _ = write!(h, "<td>{}</td>", esc(x));
        }
        h.push_str("</tr>");
    }
    h.push_str("</table>");
    if rows.len() > MAX_ROWS {
        let _ = write!(
            h,
            "<p class=\"more\">{} more rows</p>",
            rows.len() - MAX_ROWS
        );
    }
}

/// Whether `v` is a list of at least two objects.
fn is_records(v: &Value) -> Option<&[Value]> {
    let a = v.as_array()?;
    (a.len() >= 2 && a.iter().all(Value::is_object)).then_some(a.as_slice())
}

/// The numbers of a data JSON: lists of records as tables, every other
/// field as quantity/value rows.
fn data_table(json: &Path) -> anyhow::Result<String> {
    let v: Value = serde_json::from_slice(&std::fs::read(json)?)?;
    let mut h = String::new();
    let mut rows = Vec::new();
    if let Some(records) = is_records(&v) {
        records_table("", records, &mut h);
    } else if let Some(o) = v.as_object() {
        for (k, x) in o {
            match is_records(x) {
                Some(records) => records_table(k, records, &mut h),
                None => flatten(x, k, &mut rows),
            }
        }
    } else {
        flatten(&v, "", &mut rows);
    }
    if !rows.is_empty() {
        h.push_str("<table class=\"data\"><tr><th>quantity</th><th>value</th></tr>");
        for (k, x) in rows.iter().take(MAX_ROWS) {
            let _ = write!(h, "<tr><td>{}</td><td>{}</td></tr>", esc(k), esc(x));
        }
        h.push_str("</table>");
    }
    if rows.len() > MAX_ROWS {
        let _ = write!(
            h,
            "<p class=\"more\">{} more rows in <a href=\"{n}\">{n}</a></p>",
            rows.len() - MAX_ROWS,
            n = esc(&file_name(json))
        );
    }
    Ok(h)
}

fn file_name(p: &Path) -> String {
    p.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

fn checks_table(rows: &[&Check]) -> String {
    if rows.is_empty() {
        return "<p class=\"nochecks\">no registered check for this figure</p>".into();
    }
    let mut h = String::from(
        "<table class=\"checks\"><tr><th></th><th>check</th><th>equation</th><th>kind</th><th>measured</th><th>tolerance</th></tr>",
    );
    for c in rows {
        let _ = write!(
            h,
            "<tr class=\"{cls}\"><td>{mark}</td><td title=\"{note}\">{name}</td><td>{eq}</td><td>{kind}</td><td>{m:.2e}</td><td>{t:.1e}{differs}</td></tr>",
            cls = if c.passed { "pass" } else { "fail" },
            mark = if c.passed { "pass" } else { "FAIL" },
            note = esc(&c.note),
            name = esc(&c.name),
            eq = esc(&c.equation),
            kind = c.kind,
            m = c.measured,
            t = c.tolerance,
            differs = if c.paper_differs { " <abbr title=\"ERRATA.md: the printed form is wrong; passes while the measured difference exceeds the tolerance\">erratum</abbr>" } else { "" },
        );
    }
    h.push_str("</table>");
    h
}

/// The figures' files in `out`, by figure (longest matching id wins).
fn files_by_figure(out: &Path, figures: &[Figure]) -> anyhow::Result<Vec<Vec<String>>> {
    let mut names: Vec<String> = std::fs::read_dir(out)?
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let mut by = vec![Vec::new(); figures.len()];
    for n in names {
        let best = figures
            .iter()
            .enumerate()
            .filter(|(_, f)| belongs(&n, f.id))
            .max_by_key(|(_, f)| f.id.len());
        if let Some((i, _)) = best {
            by[i].push(n);
        }
    }
    Ok(by)
}

/// Primitives (three.js meshes) in a GLB, from its JSON chunk.
fn glb_primitives(bytes: &[u8]) -> anyhow::Result<usize> {
    anyhow::ensure!(bytes.len() >= 20 && &bytes[0..4] == b"glTF", "not a GLB");
    let n = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]) as usize;
    anyhow::ensure!(bytes.len() >= 20 + n, "truncated GLB");
    let doc: Value = serde_json::from_slice(&bytes[20..20 + n])?;
    Ok(doc["meshes"]
        .as_array()
        .map(|ms| {
            ms.iter()
                .map(|m| m["primitives"].as_array().map_or(0, |p| p.len()))
                .sum()
        })
        .unwrap_or(0))
}

/// Standard base64 (RFC 4648, with padding).
pub fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16
            | (*c.get(1).unwrap_or(&0) as u32) << 8
            | *c.get(2).unwrap_or(&0) as u32;
        for k in 0..4 {
            if k <= c.len() {
                s.push(A[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

/// Writes each model's `.glb.js` and returns the viewers' HTML.
fn models_html(ctx: &Ctx) -> anyhow::Result<String> {
    let mut h = String::new();
    for (file, title) in MODELS {
        let p = ctx.path(file);
        let Ok(bytes) = std::fs::read(&p) else {
            eprintln!("  gallery: {file} not built (run its figure); left out");
            continue;
        };
        let meshes = glb_primitives(&bytes)?;
        let b64 = base64(&bytes);
        let js = format!("pdesculptGallery.register({file:?}, \"{b64}\");\n");
        ctx.write_bytes(&format!("gallery/{file}.js"), js.as_bytes())?;
        let _ = write!(
            h,
            "<figure class=\"model\"><div class=\"viewer\" data-model=\"{f}\" data-status=\"loading\" data-expected-meshes=\"{meshes}\"></div>\
             <figcaption><b>{f}</b> ({meshes} parts, metres; drag to orbit, wheel to zoom). {t} <a href=\"{f}\">download</a></figcaption>\
             <script src=\"gallery/{f}.js\"></script></figure>",
            f = esc(file),
            t = esc(title),
        );
    }
    Ok(h)
}

/// Writes `index.html` (and `gallery/viewer.js`) for the figures whose
/// files are in `ctx.out`; `checks` are the rows of `verify --json`.
pub fn write_index(ctx: &Ctx, figures: &[Figure], checks: &[Check]) -> anyhow::Result<PathBuf> {
    let stale = checks::stale(figures, checks);
    anyhow::ensure!(
        stale.is_empty(),
        "gallery/checks.rs is out of date: {}",
        stale.join("; ")
    );
    ctx.write_bytes("gallery/viewer.js", VIEWER_JS.as_bytes())?;
    let files = files_by_figure(&ctx.out, figures)?;
    let passed = checks.iter().filter(|c| c.passed).count();
    let mut body = String::new();
    let _ = write!(
        body,
        "<header><h1>pdesculpt: figures and models</h1><p>Every figure regenerated by \
         <code>cargo run --release -p paper_figures -- all</code>, beside the checks it relies on \
         ({passed} of {} registered checks pass). Models are GLB in metres.</p><nav>",
        checks.len()
    );
    for (p, _) in PAPERS {
        let _ = write!(body, "<a href=\"#paper-{p}\">{p}</a> ");
    }
    body.push_str("<a href=\"#models\">models</a></nav></header>");
    body.push_str("<section id=\"models\"><h2>Models</h2>");
    body.push_str(&models_html(ctx)?);
    body.push_str("</section>");
    for (paper, title) in PAPERS {
        let _ = write!(
            body,
            "<section id=\"paper-{paper}\"><h2>{paper}: {}</h2>",
            esc(title)
        );
        for (i, f) in figures.iter().enumerate().filter(|(_, f)| f.paper == paper) {
            let mine = &files[i];
            if mine.is_empty() {
                continue;
            }
            let number = figure_number(f.id)
                .map(|n| format!("{n}. "))
                .unwrap_or_else(|| "Not in the paper: ".into());
            let _ = write!(
                body,
                "<article class=\"figure\" id=\"{id}\"><h3>{number}{t} <span class=\"id\">{id}</span></h3>",
                id = esc(f.id),
                t = esc(f.title)
            );
            if let Some((_, c)) = PAPER_CAPTIONS.iter().find(|(id, _)| *id == f.id) {
                let _ = write!(
                    body,
                    "<p class=\"caption\"><b>Paper's caption:</b> {}</p>",
                    esc(c)
                );
            }
            body.push_str("<div class=\"row\">");
            let images: Vec<&String> = mine
                .iter()
                .filter(|n| n.ends_with(".png") || n.ends_with(".svg"))
                .collect();
            if !images.is_empty() {
                body.push_str("<div class=\"images\">");
            }
            for n in &images {
                let _ = write!(
                    body,
                    "<a href=\"{n}\"><img src=\"{n}\" alt=\"{id} {n}\"></a>",
                    n = esc(n),
                    id = esc(f.id)
                );
            }
            if !images.is_empty() {
                body.push_str("</div>");
            }
            body.push_str("<div class=\"numbers\"><h4>checks it relies on</h4>");
            body.push_str(&checks_table(&checks::for_figure(f, checks)));
            for n in mine.iter().filter(|n| n.ends_with(".json")) {
                let _ = write!(
                    body,
                    "<h4>numbers: <a href=\"{n}\">{n}</a></h4>",
                    n = esc(n)
                );
                body.push_str(&data_table(&ctx.path(n))?);
            }
            body.push_str("</div></div></article>");
        }
        body.push_str("</section>");
    }
    let html = format!(
        "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>pdesculpt gallery</title>\
         <style>{STYLE_CSS}</style><script src=\"gallery/viewer.js\"></script></head><body>{body}</body></html>\n"
    );
    let p = ctx.write_bytes("index.html", html.as_bytes())?;
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc4648_vectors() {
        let v = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, enc) in v {
            assert_eq!(base64(plain.as_bytes()), enc, "{plain:?}");
        }
    }

    #[test]
    fn files_belong_to_the_longest_figure_id() {
        assert!(belongs("001-fig1a-teapot.png", "001-fig1"));
        assert!(belongs("001-fig1.json", "001-fig1"));
        assert!(!belongs("001-fig11.json", "001-fig1"));
        assert!(belongs("002-fig6-body.glb", "002-fig6"));
        assert!(!belongs("003-fig2.json", "002-fig2"));
    }

    #[test]
    fn figure_numbers_come_from_ids() {
        assert_eq!(figure_number("001-fig11").as_deref(), Some("Fig. 11"));
        assert_eq!(figure_number("002-fig7a").as_deref(), Some("Fig. 7a"));
        assert_eq!(figure_number("004-fig2-3").as_deref(), Some("Figs 2-3"));
        assert_eq!(figure_number("002-table1").as_deref(), Some("Table 1"));
        assert_eq!(figure_number("001-table-errors"), None);
        assert_eq!(figure_number("003-polygonizers"), None);
    }
}
