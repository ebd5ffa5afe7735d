//! One page holding both views (the drawing template's A4 page): each view
//! read from its own layer, the side taken from the front's page when no
//! `--side` is given, and clear errors when a layer is missing or empty.

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use std::path::{Path, PathBuf};

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

/// The corpus t_pose's two files (Inkscape A4 pages in mm) as the layers
/// `front` and `side` of one such page (the template's layout).
fn page_text() -> String {
    let path_of = |view: &str| {
        let f = data(&format!("data/sketch/corpus/t_pose_{view}.svg"));
        let text = std::fs::read_to_string(&f).expect("corpus file");
        let at = text.find("<path").expect("its outline");
        let end = at + text[at..].find("/>").expect("its end") + 2;
        text[at..end].to_string()
    };
    format!(
        concat!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" ",
            "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" ",
            "width=\"210mm\" height=\"297mm\" viewBox=\"0 0 210 297\">\n",
            "<g inkscape:groupmode=\"layer\" id=\"layer_front\" inkscape:label=\"front\">{}</g>\n",
            "<g inkscape:groupmode=\"layer\" id=\"layer_side\" inkscape:label=\"side\">{}</g>\n",
            "</svg>\n"
        ),
        path_of("front"),
        path_of("side")
    )
}

/// An OBJ's lines without its `# model` name line.
fn obj_body(p: &Path) -> Vec<String> {
    std::fs::read_to_string(p)
        .expect("the OBJ is written")
        .lines()
        .filter(|l| !l.starts_with("# model"))
        .map(str::to_string)
        .collect()
}

#[test]
fn a_page_with_both_views_builds_as_its_two_files() {
    let d = tmpdir("page-both");
    let (a, b) = (d.join("page.obj"), d.join("files.obj"));
    let page = d.join("page.svg");
    std::fs::write(&page, page_text()).expect("write the page");
    let out = pdesculpt(&[
        "--json",
        "sketch",
        "build",
        "--front",
        page.to_str().unwrap(),
        "--level",
        "intermediate",
        "-o",
        a.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("reading the side view from"), "{err}");
    let front = data("data/sketch/corpus/t_pose_front.svg");
    let side = data("data/sketch/corpus/t_pose_side.svg");
    let out = pdesculpt(&[
        "--json",
        "sketch",
        "build",
        "--front",
        front.to_str().unwrap(),
        "--side",
        side.to_str().unwrap(),
        "--level",
        "intermediate",
        "-o",
        b.to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (pa, pb) = (obj_body(&a), obj_body(&b));
    assert!(pa.len() > 1000, "a model: {} lines", pa.len());
    assert!(pa == pb, "the page's model differs from the two files'");
}

#[test]
fn a_page_missing_or_emptying_a_view_s_layer_is_refused_naming_it() {
    let d = tmpdir("page-bad");
    let page = page_text();
    let side_at = page
        .find("<g inkscape:groupmode=\"layer\" id=\"layer_side\"")
        .expect("side layer");
    let side_end = side_at + page[side_at..].find("</g>").expect("its end") + 4;
    let side_path = side_at + page[side_at..].find("<path").expect("its path");
    let cases = [
        (
            "front_only",
            format!("{}{}", &page[..side_at], &page[side_end..]),
            "none labelled side",
        ),
        (
            "empty_side",
            format!("{}</g>{}", &page[..side_path], &page[side_end..]),
            "the layer \"side\" has no closed outline",
        ),
        (
            "no_layers",
            page.replace("inkscape:groupmode=\"layer\"", ""),
            "put each in its own layer",
        ),
    ];
    for (name, text, needle) in cases {
        let f = d.join(format!("{name}.svg"));
        std::fs::write(&f, text).expect("write");
        let o = d.join(format!("{name}.obj"));
        let out = pdesculpt(&[
            "sketch",
            "build",
            "--front",
            f.to_str().unwrap(),
            "--side",
            f.to_str().unwrap(),
            "-o",
            o.to_str().unwrap(),
        ]);
        assert_clear_error(&out, needle);
        assert!(!o.exists(), "{name}: no file is written");
    }
}
