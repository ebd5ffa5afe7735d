//! `--overlay`: a picture of where the model misses its drawing, written
//! with the mesh or not at all.

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};

const CORPUS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/sketch/corpus");

/// The overlay measures over the report's own samples and prints its
/// number to two decimals (percent of the height): they agree to this.
const SAMPLING_PERCENT: f64 = 0.05;

/// The miss each panel states, in percent of the height.
fn stated_misses(svg: &str) -> Vec<f64> {
    svg.split("largest miss ")
        .skip(1)
        .map(|t| {
            t.split(' ')
                .next()
                .and_then(|x| x.parse().ok())
                .expect("a number")
        })
        .collect()
}

/// On a corpus drawing that misses its front outline at a shoulder
/// (arms_low), the overlay states each view's largest miss as the report
/// measures it, and `character build` of the saved document draws the same.
#[test]
fn the_overlay_states_the_reports_largest_miss() {
    let dir = tmpdir("overlay");
    let (out, ov, doc, ov2) = (
        dir.join("m.obj"),
        dir.join("m.svg"),
        dir.join("m.json"),
        dir.join("again.svg"),
    );
    let (f, s) = (
        format!("{CORPUS}/arms_low_front.svg"),
        format!("{CORPUS}/arms_low_side.svg"),
    );
    let o = pdesculpt(&[
        "--json",
        "sketch",
        "build",
        "--front",
        &f,
        "--side",
        &s,
        "-o",
        out.to_str().unwrap(),
        "--overlay",
        ov.to_str().unwrap(),
        "--save-doc",
        doc.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json report");
    let text = std::fs::read_to_string(&ov).expect("overlay written");
    usvg::Tree::from_str(&text, &usvg::Options::default()).expect("valid SVG");
    let stated = stated_misses(&text);
    let views = r["quality"]["whole"]["views"].as_array().expect("views");
    assert_eq!(stated.len(), views.len(), "{text}");
    for (v, got) in views.iter().zip(&stated) {
        let want = 100.0 * v["max_rel"].as_f64().expect("max_rel");
        assert!(
            (got - want).abs() <= SAMPLING_PERCENT,
            "{}: overlay {got} %, report {want} %",
            v["view"]
        );
    }
    let o = pdesculpt(&[
        "character",
        "build",
        doc.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--overlay",
        ov2.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        std::fs::read_to_string(&ov2).expect("overlay written"),
        text
    );
}

/// An overlay path that is not .svg, or that is the input drawing, is
/// refused before any work, and nothing is written (the drawing is left as
/// it was).
#[test]
fn a_bad_overlay_path_writes_nothing() {
    let dir = tmpdir("overlay-bad");
    let out = dir.join("m.obj");
    let f = dir.join("front.svg");
    std::fs::copy(format!("{CORPUS}/arms_low_front.svg"), &f).expect("copy");
    let before = std::fs::read(&f).expect("drawing");
    let png = dir.join("m.png");
    let (fs, os) = (f.to_str().unwrap(), out.to_str().unwrap());
    let o = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        fs,
        "-o",
        os,
        "--overlay",
        png.to_str().unwrap(),
    ]);
    assert_clear_error(&o, "give a path ending in .svg");
    let o = pdesculpt(&["sketch", "build", "--front", fs, "-o", os, "--overlay", fs]);
    assert_clear_error(&o, "--front");
    assert!(!out.exists() && !png.exists(), "a file was written");
    assert_eq!(
        std::fs::read(&f).expect("drawing"),
        before,
        "the drawing changed"
    );
}
