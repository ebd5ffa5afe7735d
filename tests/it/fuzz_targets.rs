//! Fuzz targets of the new surfaces (issue 35): SVG drawings, character
//! documents and edits, in-process and through the binary. A child module
//! of the harness (`fuzz_harness.rs`), so `cargo test` and
//! `examples/fuzz.rs` run the same targets.
//!
//! * SVG drawings: paths, circles and transforms built from hostile
//!   numbers, images and cuts, at hostile tolerances, through
//!   `profile::parse_svg`;
//! * character documents: the bundled male with numeric fields replaced
//!   by hostile values and lists blown up, through `CharacterDoc::parse`;
//!   an accepted document's parts are solved and sampled: finite;
//! * edits: every op with hostile parameters pushed on that document
//!   (`CharacterDoc::push_edit`), the edited part solved and sampled.

use super::Pick;
use pdesculpt::character::doc::{CharacterDoc, Level};
use serde_json::Value;
use std::path::Path;
use std::sync::OnceLock;

/// The bundled male at the intermediate level with its parts stored (the
/// document the document and edit targets mutate), built once.
pub fn base_doc() -> &'static CharacterDoc {
    static DOC: OnceLock<CharacterDoc> = OnceLock::new();
    DOC.get_or_init(|| {
        let d = pdesculpt::sketch::check::bundled("male", Level::Intermediate).expect("bundled");
        let res = pdesculpt::character::Resolution {
            rings_per_height: 40.0,
            transition_rows: 4,
        };
        pdesculpt::pipeline::build_document(&d, Path::new("."), res, true)
            .expect("the bundled male builds")
            .doc
    })
}

/// A number for a JSON document: ordinary or hostile (JSON has no NaN:
/// those become the text `NaN`, which must be refused as a parse error).
fn json_num(p: &mut Pick) -> String {
    let x = p.num();
    if x.parse::<f64>().is_ok() {
        x
    } else {
        (*p.of(&["1e308", "-1e308", "NaN", "1e400", "\"x\"", "null"])).to_string()
    }
}

pub fn gen_svg(p: &mut Pick) -> Vec<u8> {
    let mut body = String::new();
    for _ in 0..(1 + p.below(4)) {
        let id = *p.of(&["o", "cut_a", "cut", "", "x"]);
        let id = if id.is_empty() {
            String::new()
        } else {
            format!(r#" id="{id}""#)
        };
        let shape = match p.below(5) {
            0 => format!(
                r#"<path{id} d="M {} {} C {} {} {} {} {} {} Z"/>"#,
                p.num(),
                p.num(),
                p.num(),
                p.num(),
                p.num(),
                p.num(),
                p.num(),
                p.num()
            ),
            1 => format!(
                r#"<circle{id} cx="{}" cy="{}" r="{}"/>"#,
                p.num(),
                p.num(),
                p.num()
            ),
            2 => format!(
                r#"<path{id} d="M 0 0 A {} {} 0 1 1 {} 0 Z"/>"#,
                p.num(),
                p.num(),
                p.num()
            ),
            3 => format!(
                r#"<polyline{id} points="0,0 {},{} 1,{}"/>"#,
                p.num(),
                p.num(),
                p.num()
            ),
            _ => {
                r#"<path id="o" d="M 0 0 C 0.3 -0.5 0.7 -0.5 1 0 C 0.7 0.5 0.3 0.5 0 0 Z"/>"#.into()
            }
        };
        body += &match p.below(4) {
            0 => format!(
                r#"<g transform="scale({}) translate({} 0)">{shape}</g>"#,
                p.num(),
                p.num()
            ),
            1 => format!(
                r#"<image xlink:href="{}" width="1" height="1"/>{shape}"#,
                p.of(&["/etc/passwd", "/dev/zero", "x.png"])
            ),
            _ => shape,
        };
    }
    let tol = p.num();
    format!(
        r#"{tol}
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">{body}</svg>"#
    )
    .into_bytes()
}

/// First line: the tolerance; the rest: the SVG.
pub fn parse_svg(b: &[u8]) -> Result<Vec<f64>, String> {
    let text = String::from_utf8_lossy(b);
    let (tol, svg) = text.split_once('\n').ok_or("no tolerance line")?;
    let tol: f64 = tol.trim().parse().map_err(|_| "tolerance")?;
    let s = pdesculpt::profile::parse_svg(svg, pdesculpt::profile::View::Front, tol)
        .map_err(|e| e.to_string())?;
    let mut out: Vec<f64> = s.outline.points().iter().flatten().copied().collect();
    out.extend(s.cuts.iter().flat_map(|c| c.points.iter().flatten()));
    Ok(out)
}

/// Paths of every number in `v`.
fn number_paths(v: &Value, at: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match v {
        Value::Number(_) => out.push(at.clone()),
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                at.push(i.to_string());
                number_paths(x, at, out);
                at.pop();
            }
        }
        Value::Object(o) => {
            for (k, x) in o {
                at.push(k.clone());
                number_paths(x, at, out);
                at.pop();
            }
        }
        _ => {}
    }
}

/// The value at `path`, if an earlier mutation (a list cut short) has not
/// removed it.
fn at_path<'a>(v: &'a mut Value, path: &[String]) -> Option<&'a mut Value> {
    path.iter().try_fold(v, |v, k| match v {
        Value::Array(a) => a.get_mut(k.parse::<usize>().ok()?),
        Value::Object(o) => o.get_mut(k.as_str()),
        _ => None,
    })
}

pub fn gen_doc(p: &mut Pick) -> Vec<u8> {
    let mut v = serde_json::to_value(base_doc()).expect("json");
    let mut paths = Vec::new();
    number_paths(&v, &mut Vec::new(), &mut paths);
    for _ in 0..(1 + p.below(3)) {
        match p.below(5) {
            0 => {
                // blow a list up: sections of a part, or the edit log
                let k = p.below(6);
                let n = *p.of(&[0usize, 1, 2, 300, 5000]);
                let s = v["parts"][k]["sections"][1].clone();
                v["parts"][k]["sections"] = Value::Array(vec![s; n]);
            }
            _ => {
                let path = p.of(&paths).clone();
                let text = json_num(p);
                let Some(at) = at_path(&mut v, &path) else {
                    continue;
                };
                *at = serde_json::from_str(&text).unwrap_or(Value::Null);
                if text == "NaN" {
                    // not JSON: the text itself must be refused
                    return v.to_string().replacen("null", "NaN", 1).into_bytes();
                }
            }
        }
    }
    v.to_string().into_bytes()
}

/// A document that parses must solve every part to finite points.
pub fn parse_doc(b: &[u8]) -> Result<Vec<f64>, String> {
    let text = String::from_utf8_lossy(b);
    let d = CharacterDoc::parse(&text, Path::new("fuzz.json")).map_err(|e| e.to_string())?;
    parts_numbers(d.parts())
}

fn parts_numbers(parts: &[pdesculpt::character::spec::PartSpec]) -> Result<Vec<f64>, String> {
    let mut out = Vec::new();
    for p in parts {
        let s = pdesculpt::character::part::build_part(p).map_err(|e| e.to_string())?;
        for k in 0..=4 {
            let u = s.u0 + (s.u1 - s.u0) * k as f64 / 4.0;
            out.extend(s.section(u, 0).eval(0.7f64));
        }
    }
    Ok(out)
}

pub fn gen_edit(p: &mut Pick) -> Vec<u8> {
    let part = *p.of(&["torso", "head", "arm_l", "leg_r", "tail"]);
    let n = |p: &mut Pick| json_num(p);
    let e = match p.below(7) {
        0 => format!(
            r#"{{"op": "shape_parameter", "part": "{part}", "a": {}}}"#,
            n(p)
        ),
        1 => format!(
            r#"{{"op": "gec_transform", "part": "{part}", "transform": {{"kind": "translate", "d": [{}, {}, {}]}}}}"#,
            n(p),
            n(p),
            n(p)
        ),
        2 => format!(
            r#"{{"op": "gec_transform", "part": "{part}", "section": {}, "transform": {{"kind": "bump", "h": {}, "theta": {}, "sigma": {}}}}}"#,
            p.count(),
            n(p),
            n(p),
            n(p)
        ),
        3 => format!(
            r#"{{"op": "force", "part": "{part}", "u": [{}, {}], "force": {{"type": "uniform", "p": [{}, 0, 0]}}}}"#,
            n(p),
            n(p),
            n(p)
        ),
        4 => format!(
            r#"{{"op": "boundary", "part": "{part}", "end": "end", "tangent": [{}, {}, 0]}}"#,
            n(p),
            n(p)
        ),
        5 => format!(
            r#"{{"op": "plate", "part": "{part}", "centre": [{}, 1.1, 0.1], "radius": {}, "d": [0, 0, {}]}}"#,
            n(p),
            n(p),
            n(p)
        ),
        _ => format!(
            r#"{{"op": "gec_transform", "part": "{part}", "transform": {{"kind": "scale", "sx": {}, "sy": {}}}}}"#,
            n(p),
            n(p)
        ),
    };
    e.into_bytes()
}

/// An edit that is accepted must leave every edited part finite.
pub fn apply_edit(b: &[u8]) -> Result<Vec<f64>, String> {
    let e: pdesculpt::character::log::Edit =
        serde_json::from_slice(b).map_err(|e| e.to_string())?;
    let mut d = base_doc().clone();
    d.push_edit(e).map_err(|e| e.to_string())?;
    let parts =
        pdesculpt::edit::apply_to_parts(d.parts(), d.active_edits()).map_err(|e| e.to_string())?;
    parts_numbers(&parts)
}

/// A command target's files: `profile check` of a generated SVG.
pub fn cmd_profile_check(p: &mut Pick, d: &Path) -> Vec<String> {
    let text = String::from_utf8(gen_svg(p)).expect("utf8");
    let (tol, svg) = text.split_once('\n').expect("two parts");
    let f = d.join("in.svg");
    std::fs::write(&f, svg).expect("write");
    vec![
        "profile".into(),
        "check".into(),
        f.display().to_string(),
        "--view".into(),
        "front".into(),
        "--tolerance".into(),
        tol.into(),
    ]
}

/// `character edit` of a generated edit on the stored male document (heavy:
/// each accepted edit builds the character).
pub fn cmd_character_edit(p: &mut Pick, d: &Path) -> Vec<String> {
    let doc = d.join("doc.json");
    base_doc().save(&doc).expect("save");
    let op = d.join("op.json");
    std::fs::write(&op, gen_edit(p)).expect("write");
    vec![
        "character".into(),
        "edit".into(),
        doc.display().to_string(),
        "--op".into(),
        op.display().to_string(),
    ]
}
