//! Length units (issue 20): conversion factors, the SVG length rule, and
//! every written GLB read back in metres by a reader independent of the
//! writer (it decodes the POSITION accessor from the binary chunk).

use crate::cli::{pdesculpt, tmpdir};
use pdesculpt::check::tol;
use pdesculpt::mesh::io::{self, write_in_unit};
use pdesculpt::mesh::unit::{self, svg_length_metres, Unit, UnitError};
use std::path::Path;

/// The MakeHuman base body (hm08, default proportions) is 1.67 m tall; a
/// unit mistake is a factor of ten, so a 5 % band cannot hide one.
const BODY_HEIGHT_M: f64 = 1.67;
const BODY_HEIGHT_BAND: f64 = 0.05;
/// f32 storage in GLB: relative rounding of one coordinate.
const F32_REL: f64 = 1e-6;

/// Positions and primitive count of a GLB, decoded without the writer's
/// code: header, JSON chunk, BIN chunk, accessor 0 via its buffer view.
fn read_glb(path: &Path) -> (Vec<[f64; 3]>, usize, serde_json::Value) {
    let b = std::fs::read(path).expect("GLB exists");
    let u32_at = |o: usize| u32::from_le_bytes(b[o..o + 4].try_into().expect("4 bytes")) as usize;
    assert_eq!(&b[0..4], b"glTF", "magic");
    assert_eq!(u32_at(4), 2, "version");
    assert_eq!(u32_at(8), b.len(), "declared length");
    let json_len = u32_at(12);
    assert_eq!(&b[16..20], b"JSON");
    let doc: serde_json::Value = serde_json::from_slice(&b[20..20 + json_len]).expect("JSON chunk");
    let bin_at = 20 + json_len;
    assert_eq!(&b[bin_at + 4..bin_at + 8], b"BIN\0");
    let bin = &b[bin_at + 8..bin_at + 8 + u32_at(bin_at)];
    // every primitive of every mesh (one mesh per part), each POSITION
    // accessor read once
    let prims: Vec<&serde_json::Value> = doc["meshes"]
        .as_array()
        .expect("meshes")
        .iter()
        .flat_map(|m| m["primitives"].as_array().expect("primitives"))
        .collect();
    let mut seen = std::collections::BTreeSet::new();
    let mut pos = Vec::new();
    for p in &prims {
        let pos_acc = p["attributes"]["POSITION"].as_u64().expect("POSITION") as usize;
        if !seen.insert(pos_acc) {
            continue;
        }
        let acc = &doc["accessors"][pos_acc];
        let view = &doc["bufferViews"][acc["bufferView"].as_u64().expect("view") as usize];
        let off = view["byteOffset"].as_u64().unwrap_or(0) as usize;
        let count = acc["count"].as_u64().expect("count") as usize;
        let f = |i: usize| {
            f32::from_le_bytes(bin[off + 4 * i..off + 4 * i + 4].try_into().expect("f32")) as f64
        };
        pos.extend((0..count).map(|v| [f(3 * v), f(3 * v + 1), f(3 * v + 2)]));
    }
    let n = prims.len();
    (pos, n, doc)
}

fn height(pos: &[[f64; 3]]) -> f64 {
    let ys = pos.iter().map(|p| p[1]);
    ys.clone().fold(f64::NEG_INFINITY, f64::max) - ys.fold(f64::INFINITY, f64::min)
}

fn assert_body_metres(h: f64, what: &str) {
    assert!(
        (h - BODY_HEIGHT_M).abs() <= BODY_HEIGHT_BAND * BODY_HEIGHT_M,
        "{what}: body height {h} m, expected about {BODY_HEIGHT_M} m"
    );
}

#[test]
fn factors_are_consistent_powers_of_ten() {
    for a in Unit::ALL {
        assert_eq!(a.factor_to(a), 1.0, "{a} to itself");
        for b in Unit::ALL {
            let k = a.factor_to(b);
            assert!((k * b.factor_to(a) - 1.0).abs() <= tol::ROUNDING, "{a} {b}");
            assert!(
                (k - a.metres() / b.metres()).abs() <= tol::ROUNDING * k,
                "{a} {b}"
            );
        }
    }
    assert_eq!(Unit::Dm.factor_to(Unit::M), 0.1);
    assert_eq!(Unit::M.factor_to(Unit::Mm), 1000.0);
}

#[test]
fn unit_names_parse_and_unknown_ones_are_named() {
    for u in Unit::ALL {
        assert_eq!(u.symbol().parse::<Unit>(), Ok(u));
        assert_eq!(u.to_string().to_uppercase().parse::<Unit>(), Ok(u));
    }
    let e = "feet".parse::<Unit>().unwrap_err();
    assert!(e.to_string().contains("feet"), "{e}");
}

#[test]
fn svg_lengths_follow_css_absolute_units() {
    let cases = [
        ("96", 0.0254),
        ("96px", 0.0254),
        ("1in", 0.0254),
        ("210mm", 0.21),
        ("29.7cm", 0.297),
        ("72pt", 0.0254),
        ("6pc", 0.0254),
    ];
    for (s, m) in cases {
        let got = svg_length_metres(s).expect(s);
        assert!(
            (got - m).abs() <= tol::ROUNDING * m,
            "{s}: {got} m, expected {m}"
        );
    }
    for bad in ["50%", "2em", "", "-3mm", "NaNmm", "3furlong"] {
        assert!(
            matches!(svg_length_metres(bad), Err(UnitError::SvgLength { .. })),
            "{bad:?} must be rejected"
        );
    }
}

#[test]
fn makehuman_body_written_as_glb_is_metres_and_obj_follows_the_request() {
    let body = pdesculpt::makehuman::base_body().expect("base body").mesh;
    let d = tmpdir("units-lib");
    let glb = d.join("body.glb");
    // GLB ignores the request: always metres
    let u = write_in_unit(&body, &glb, unit::MAKEHUMAN, Unit::Mm).expect("writes");
    assert_eq!(u, Unit::M);
    let (pos, prims, _) = read_glb(&glb);
    assert_eq!(prims, body.groups.len());
    assert_body_metres(height(&pos), "body.glb");
    for (p, q) in pos.iter().zip(&body.positions) {
        for k in 0..3 {
            let want = 0.1 * q[k];
            assert!(
                (p[k] - want).abs() <= F32_REL * want.abs().max(1.0),
                "{p:?} vs {q:?}"
            );
        }
    }
    // OBJ in centimetres: ten times the decimetre coordinates
    let obj = d.join("body.obj");
    assert_eq!(
        write_in_unit(&body, &obj, unit::MAKEHUMAN, Unit::Cm).expect("writes"),
        Unit::Cm
    );
    let back = io::read(&obj).expect("reads");
    let h_dm = height(&body.positions);
    assert!((height(&back.positions) - 10.0 * h_dm).abs() <= tol::SOLVE * 10.0 * h_dm);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn convert_scales_by_input_and_output_units() {
    let d = tmpdir("units-convert");
    let src = d.join("tri.obj");
    std::fs::write(&src, "v 0 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n").expect("write");
    let s = |p: &Path| p.to_str().expect("utf8").to_string();
    let (stl, glb) = (d.join("tri.stl"), d.join("tri.glb"));
    let out = pdesculpt(&[
        "--json",
        "convert",
        &s(&src),
        "-o",
        &s(&stl),
        "--input-unit",
        "cm",
        "--unit",
        "mm",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["unit"], "mm");
    assert_eq!(height(&io::read(&stl).expect("stl").positions), 20.0);
    let out = pdesculpt(&[
        "--json",
        "convert",
        &s(&src),
        "-o",
        &s(&glb),
        "--input-unit",
        "cm",
        "--unit",
        "mm",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["unit"], "m", "GLB is always metres");
    let (pos, _, _) = read_glb(&glb);
    assert!((height(&pos) - 0.02).abs() <= F32_REL);
    let bad = pdesculpt(&["convert", &s(&src), "-o", &s(&stl), "--unit", "furlong"]);
    assert_eq!(bad.status.code(), Some(2), "clap usage error");
    assert!(String::from_utf8_lossy(&bad.stderr).contains("furlong"));
    std::fs::remove_dir_all(&d).ok();
}

/// The demo in centimetres: both GLBs read back in metres at the body's
/// height, the OBJ in centimetres, and the JSON report states every unit.
#[test]
fn demo_glbs_are_metres_and_obj_follows_unit() {
    let d = tmpdir("units-demo");
    let out = pdesculpt(&[
        "--json",
        "demo",
        "--out",
        d.to_str().expect("utf8"),
        "--unit",
        "cm",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert_eq!(v["units"]["demo.glb"], "m");
    assert_eq!(v["units"]["demo-pde6.glb"], "m");
    assert_eq!(v["units"]["demo.obj"], "cm");
    assert_eq!(v["report"]["unit"], "dm");
    let (pos, prims, _) = read_glb(&d.join("demo.glb"));
    assert_eq!(prims, 3, "skin, skirt, teddy");
    assert_body_metres(height(&pos), "demo.glb");
    let (pos, prims, _) = read_glb(&d.join("demo-pde6.glb"));
    assert!(prims >= 1);
    // the closed reconstruction spans the whole body, soles to crown
    assert_body_metres(height(&pos), "demo-pde6.glb");
    let obj = io::read(&d.join("demo.obj")).expect("obj");
    assert_body_metres(height(&obj.positions) / 100.0, "demo.obj (cm)");
    std::fs::remove_dir_all(&d).ok();
}
