//! Issue 35, documents and edits: limits before work, every value's range
//! checked on load with the field's path, edits and redos validated by
//! their effect, and builds that refuse a non-finite report.

use crate::edit::low;
use pdesculpt::character::doc::{CharacterDoc, Level};
use pdesculpt::character::log::Edit;
use pdesculpt::pipeline::build_document;
use pdesculpt::pipeline::{push_checked, redo_checked, BuildOptions};
use pdesculpt::sketch::check::bundled;
use serde_json::{json, Value};
use std::path::Path;
use std::sync::OnceLock;

/// The bundled male (intermediate level) with its parts stored, as JSON.
fn male() -> &'static Value {
    static DOC: OnceLock<Value> = OnceLock::new();
    DOC.get_or_init(|| {
        let doc = bundled("male", Level::Intermediate).expect("bundled");
        let d = build_document(&doc, Path::new("."), low(), true)
            .expect("builds")
            .doc;
        serde_json::to_value(&d).expect("json")
    })
}

/// The male document changed by `f`, parsed: the error message, if any.
fn parsed(f: impl FnOnce(&mut Value)) -> Result<CharacterDoc, String> {
    let mut v = male().clone();
    f(&mut v);
    let text = serde_json::to_string(&v).expect("text");
    CharacterDoc::parse(&text, Path::new("doc.json")).map_err(|e| e.to_string())
}

/// The error of `r` (a success fails the test without printing the
/// value, a whole built model).
fn error_of<T, E: std::fmt::Display>(r: Result<T, E>, what: &str) -> String {
    match r {
        Ok(_) => panic!("{what}: accepted"),
        Err(e) => e.to_string(),
    }
}

fn part(v: &mut Value, name: &str) -> usize {
    v["parts"]
        .as_array()
        .expect("parts")
        .iter()
        .position(|p| p["name"] == name)
        .expect("part")
}

fn refused(f: impl FnOnce(&mut Value), needles: &[&str]) {
    let e = error_of(parsed(f), "refused on load");
    for n in needles {
        assert!(e.contains(n), "missing {n:?} in: {e}");
    }
}

#[test]
fn the_stored_male_document_is_in_range() {
    parsed(|_| ()).expect("the derived document passes its own ranges");
    // a UTF-8 byte-order mark is not an error
    let text = format!("\u{feff}{}", male());
    CharacterDoc::parse(&text, Path::new("bom.json")).expect("BOM accepted");
}

#[test]
fn counts_are_limited_before_any_work() {
    for n in [100_000, 1000] {
        refused(
            |v| {
                let k = part(v, "head");
                let s = v["parts"][k]["sections"][1].clone();
                v["parts"][k]["sections"] = Value::Array(vec![s; n]);
            },
            &[&format!("sections (count) = {n}"), "from 2 to 256"],
        );
    }
    refused(
        |v| {
            let k = part(v, "head");
            let mut x = vec![json!([0.0, 0.0]); 5000];
            x[0] = json!([0.05, 0.0]);
            v["parts"][k]["sections"][5]["shape"] =
                json!({"gec": {"centre": [0, 0], "x": x.clone(), "y": x}});
        },
        &["shape.gec.x (count) = 5000", "to 256"],
    );
    refused(
        |v| {
            let pts = vec![json!([0.1, 0.0]); 200_000];
            v["inputs"]["sections"] = json!([{"part": "torso", "y": 1.2, "points": pts}]);
        },
        &["inputs.sections[0].points (count) = 200000", "to 20000"],
    );
    refused(
        |v| {
            let e = json!({"op": "shape_parameter", "part": "torso", "a": 0.3});
            v["edits"] = Value::Array(vec![e; 100_000]);
            v["cursor"] = json!(100_000);
        },
        &["edits (count) = 100000", "to 4096"],
    );
}

#[test]
fn every_value_is_range_checked_with_its_field_path() {
    let arm = |v: &mut Value| part(v, "arm_l");
    refused(
        |v| {
            let k = arm(v);
            v["parts"][k]["sections"][5]["shape"] = json!({"circle": {"r": 1e30}});
        },
        &["parts[2] ('arm_l').sections[5].shape.circle.r = 1e30"],
    );
    refused(
        |v| {
            let k = arm(v);
            v["parts"][k]["sections"][5]["shape"] =
                json!({"ellipse": {"a": 0.0, "b": 0.0, "offset": 0.0}});
        },
        &["sections[5].shape", "only the first section"],
    );
    refused(
        |v| {
            let k = arm(v);
            v["parts"][k]["sections"][5]["e1"] = json!([0.0, 0.0, 0.0]);
        },
        &["sections[5].e1, e2", "orthonormal"],
    );
    refused(
        |v| {
            let k = arm(v);
            let e2 = v["parts"][k]["sections"][5]["e2"].clone();
            v["parts"][k]["sections"][5]["e1"] = e2;
        },
        &["sections[5].e1, e2", "orthonormal"],
    );
    refused(
        |v| {
            let k = arm(v);
            v["parts"][k]["sections"][5]["centre"] = json!([1e308, 0.0, 0.0]);
        },
        &["sections[5].centre[0] = 1e308"],
    );
    refused(
        |v| {
            // a removed part shares its name with the part derived from it
            // (stored in `parts`), never with a transition or a prop
            v["removed_parts"] =
                json!([{"name": "hips", "front": {"points": [[0, 0], [1, 0], [0, 1]]}}]);
        },
        &[
            "removed_parts[0].name = \"hips\"",
            ".name is \"hips\" already",
        ],
    );
    refused(
        |v| v["inputs"]["tolerance"] = json!(1e300),
        &["inputs.tolerance = 1e300"],
    );
}

#[test]
fn a_conv_spacing_inside_its_old_range_is_refused_by_the_fit_work() {
    let model =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/conv/blob.json"))
            .expect("blob");
    let m = pdesculpt::conv::model::Model::from_json(&model).expect("model");
    let mut opts = m.options;
    opts.stroke.spacing = 1.0001e-4;
    let e = error_of(
        pdesculpt::conv::sketch::build(&m.components[0].stroke, &opts),
        "refused",
    );
    assert!(e.to_string().contains("raise stroke.spacing"), "{e}");
}

fn stored() -> CharacterDoc {
    parsed(|_| ()).expect("doc")
}

fn edit(v: Value) -> Edit {
    serde_json::from_value(v).expect("an edit")
}

#[test]
fn edits_out_of_range_are_refused_by_their_parameter() {
    let cases = [
        (
            json!({"op": "boundary", "part": "arm_l", "end": "end", "tangent": [1e30, 0, 0]}),
            "tangent[0] = 1e30",
        ),
        (
            json!({"op": "plate", "part": "torso", "centre": [0.0, 1.1, 0.1], "radius": 0.05, "d": [0, 0, 1e30]}),
            "d[2] = 1e30",
        ),
        (
            json!({"op": "gec_transform", "part": "arm_l", "transform": {"kind": "translate", "d": [1e308, 0, 0]}}),
            "d[0] = 1e308",
        ),
    ];
    for (e, needle) in cases {
        let mut d = stored();
        let before = d.clone();
        let err = error_of(
            push_checked(&mut d, edit(e), &BuildOptions::new(Path::new(".")), None),
            needle,
        );
        assert!(err.to_string().contains(needle), "{err}");
        assert_eq!(d, before, "a refused edit leaves the document as it was");
    }
}

#[test]
fn edits_are_validated_by_their_effect() {
    let cases = [
        json!({"op": "force", "part": "arm_l", "u": [0.1, 0.4], "force": {"type": "uniform", "p": [1e30, 0, 0]}}),
        json!({"op": "gec_transform", "part": "arm_l", "transform": {"kind": "translate", "d": [9e4, 0, 0]}}),
    ];
    for e in cases {
        let mut d = stored();
        let err = error_of(
            push_checked(
                &mut d,
                edit(e.clone()),
                &BuildOptions::new(Path::new(".")),
                None,
            ),
            "refused",
        );
        let s = err.to_string();
        assert!(
            s.contains("model sizes outside")
                || s.contains("non-finite")
                || s.contains("does not build"),
            "{e}: {s}"
        );
        assert!(d.edits().is_empty());
    }
    // an ordinary edit passes and its build is returned
    let mut d = stored();
    let ok = json!({"op": "shape_parameter", "part": "torso", "a": 0.3});
    push_checked(&mut d, edit(ok), &BuildOptions::new(Path::new(".")), None)
        .expect("an ordinary edit");
    assert_eq!(d.cursor(), 1);
}

/// `doc` with its edit log replaced by `edits` of which the first `cursor`
/// are active, as a document written by hand and loaded would have it
/// (the JSON goes through `CharacterDoc::parse`, the load's own checks;
/// nothing judges the edits against the parts): the library changes a log
/// only through its API.
pub fn with_hand_written_log(doc: &CharacterDoc, edits: Vec<Edit>, cursor: usize) -> CharacterDoc {
    let mut v = serde_json::to_value(doc).expect("a document serialises");
    v["edits"] = serde_json::to_value(edits).expect("edits serialise");
    v["cursor"] = cursor.into();
    CharacterDoc::parse(&v.to_string(), Path::new("hand-written.json"))
        .expect("the hand-written log loads")
}

#[test]
fn redo_validates_the_edit_it_re_applies() {
    // an unbuildable edit written into the log by hand, undone
    let unbuildable = edit(json!({"op": "force", "part": "arm_l", "u": [0.1, 0.4],
        "force": {"type": "uniform", "p": [1e30, 0, 0]}}));
    let mut d = with_hand_written_log(&stored(), vec![unbuildable], 0);
    let before = d.clone();
    let err = error_of(
        redo_checked(&mut d, &BuildOptions::new(Path::new(".")), None),
        "refused",
    );
    assert!(err.to_string().contains("redo of edit 0"), "{err}");
    assert_eq!(d, before);
}

#[test]
fn a_build_with_a_non_finite_vertex_names_its_part() {
    let mut m = pdesculpt::mesh::Mesh::with_group(
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, f64::NAN, 0.0]],
        vec![[0, 1, 2]],
        "arm_l",
    );
    let built = {
        let doc = stored();
        build_document(&doc, Path::new("."), low(), false).expect("builds")
    };
    let e = pdesculpt::pipeline::effect::finite_result(&m, &built.report).expect_err("NaN");
    assert!(e.to_string().contains("part 'arm_l'"), "{e}");
    m.positions[2][1] = 1.0;
    pdesculpt::pipeline::effect::finite_result(&m, &built.report).expect("finite");
}
