//! Bad glTF input: each case is refused by `convert` with an error naming
//! the problem, a non-zero exit and no output file, and by the library
//! with its own `GltfError` variant.

use super::cli::{assert_clear_error, pdesculpt};
use super::gltf::{glb_bin, glb_bytes, glb_json, three_part_torus, tmpdir};
use pdesculpt::mesh::io::{self, Format, GltfError};
use pdesculpt::mesh::MeshError;
use serde_json::{json, Value};
use std::path::Path;

/// A valid GLB of the three-part torus: (document, binary chunk).
fn good() -> (Value, Vec<u8>) {
    let b = io::encode(&three_part_torus(), Format::Glb).expect("encodes");
    (glb_json(&b), glb_bin(&b))
}

/// Byte offset in the binary chunk of accessor `a`'s first element.
fn offset_of(doc: &Value, a: u64) -> usize {
    let acc = &doc["accessors"][a as usize];
    let view = &doc["bufferViews"][acc["bufferView"].as_u64().expect("view") as usize];
    (view["byteOffset"].as_u64().unwrap_or(0) + acc["byteOffset"].as_u64().unwrap_or(0)) as usize
}

/// Writes `bytes` as `name` in a fresh folder, runs `convert` on it and
/// checks the error names `needle` and no output was written; returns the
/// library's error for the same file.
fn refused(case: &str, name: &str, bytes: &[u8], needle: &str) -> GltfError {
    let d = tmpdir(&format!("bad-{case}"));
    let input = d.join(name);
    std::fs::write(&input, bytes).expect("write input");
    refused_file(&input, needle)
}

fn refused_file(input: &Path, needle: &str) -> GltfError {
    let out_path = input.with_file_name("out.obj");
    let out = pdesculpt(&[
        "convert",
        input.to_str().expect("utf-8"),
        "-o",
        out_path.to_str().expect("utf-8"),
    ]);
    assert_clear_error(&out, needle);
    assert!(!out_path.exists(), "no output file for a bad input");
    let err = io::read(input).expect_err("the library refuses it too");
    if let Some(d) = input.parent() {
        std::fs::remove_dir_all(d).ok();
    }
    match err {
        MeshError::Gltf { source, .. } => source,
        other => panic!("expected a glTF error, got {other}"),
    }
}

#[test]
fn truncated_glb_is_refused() {
    let (doc, bin) = good();
    let b = glb_bytes(&doc, &bin);
    let e = refused("trunc", "t.glb", &b[..b.len() / 2], "truncated");
    assert!(matches!(e, GltfError::Truncated { .. }), "{e}");
    let e = refused("trunc-head", "h.glb", &b[..10], "truncated");
    assert!(matches!(e, GltfError::Truncated { .. }), "{e}");
}

#[test]
fn wrong_magic_is_refused() {
    let (doc, bin) = good();
    let mut b = glb_bytes(&doc, &bin);
    b[..4].copy_from_slice(b"GLTX");
    let e = refused("magic", "m.glb", &b, "not a GLB file");
    assert!(matches!(e, GltfError::Magic { .. }), "{e}");
}

#[test]
fn buffer_view_past_the_buffer_is_refused() {
    let (mut doc, bin) = good();
    doc["bufferViews"][0]["byteOffset"] = json!(bin.len() - 8);
    let e = refused(
        "view",
        "v.glb",
        &glb_bytes(&doc, &bin),
        "past the end of buffer 0",
    );
    assert!(
        matches!(e, GltfError::ViewPastBuffer { view: 0, .. }),
        "{e}"
    );
}

#[test]
fn nan_position_is_refused() {
    let (doc, mut bin) = good();
    let p = doc["meshes"][1]["primitives"][0]["attributes"]["POSITION"]
        .as_u64()
        .expect("position accessor");
    let at = offset_of(&doc, p) + 4;
    bin[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
    let e = refused("nan", "n.glb", &glb_bytes(&doc, &bin), "not a finite");
    assert!(
        matches!(&e, GltfError::NonFinite { node, vertex: 0, .. } if node == "belt"),
        "{e}"
    );
}

#[test]
fn coordinates_of_1e300_are_refused() {
    let (mut doc, bin) = good();
    let root = doc["scenes"][0]["nodes"][0].as_u64().expect("root") as usize;
    doc["nodes"][root]["translation"] = json!([1e300, 0.0, 0.0]);
    // glTF's JSON numbers are f32: serde_json (with `float_roundtrip`, so
    // that documents round-trip exactly) refuses 1e300 as out of range
    // while parsing, before our own finiteness check sees an infinity
    let e = refused("huge", "h.glb", &glb_bytes(&doc, &bin), "out of range");
    assert!(matches!(e, GltfError::Json { .. }), "{e}");
}

#[test]
fn index_past_the_vertex_count_is_refused() {
    let (doc, mut bin) = good();
    let i = doc["meshes"][2]["primitives"][0]["indices"]
        .as_u64()
        .expect("index accessor");
    let at = offset_of(&doc, i) + 8;
    bin[at..at + 4].copy_from_slice(&999_999u32.to_le_bytes());
    let e = refused(
        "index",
        "i.glb",
        &glb_bytes(&doc, &bin),
        "past the vertex count",
    );
    assert!(
        matches!(&e, GltfError::IndexOutOfRange { index: 999_999, node, .. } if node == "rest"),
        "{e}"
    );
}

#[test]
fn external_uri_outside_the_folder_is_refused() {
    let (mut doc, bin) = good();
    let d = tmpdir("bad-uri");
    let inner = d.join("inner");
    std::fs::create_dir_all(&inner).expect("dir");
    // the file exists, one folder up: refused all the same
    std::fs::write(d.join("outside.bin"), &bin).expect("bin");
    doc["buffers"][0]["uri"] = "../outside.bin".into();
    let input = inner.join("u.gltf");
    std::fs::write(&input, serde_json::to_vec(&doc).expect("json")).expect("gltf");
    let e = refused_file(&input, "outside the file's folder");
    assert!(
        matches!(e, GltfError::UriOutsideFolder { buffer: 0, .. }),
        "{e}"
    );
    for uri in [
        "/etc/hostname",
        "file:///etc/hostname",
        "a/%2e%2e/%2e%2e/x.bin",
    ] {
        doc["buffers"][0]["uri"] = uri.into();
        let e = refused(
            "uri-abs",
            "a.gltf",
            &serde_json::to_vec(&doc).expect("json"),
            "outside",
        );
        assert!(
            matches!(e, GltfError::UriOutsideFolder { .. }),
            "{uri}: {e}"
        );
    }
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn compressed_points_and_missing_buffers_are_named() {
    let (mut doc, bin) = good();
    let mut draco = doc.clone();
    draco["extensionsUsed"] = json!(["KHR_draco_mesh_compression"]);
    draco["extensionsRequired"] = json!(["KHR_draco_mesh_compression"]);
    let e = refused(
        "draco",
        "d.glb",
        &glb_bytes(&draco, &bin),
        "KHR_draco_mesh_compression",
    );
    assert!(matches!(e, GltfError::Compressed { .. }), "{e}");
    let mut points = doc.clone();
    points["meshes"][0]["primitives"][0]["mode"] = json!(0);
    let e = refused(
        "points",
        "p.glb",
        &glb_bytes(&points, &bin),
        "not triangles",
    );
    assert!(matches!(e, GltfError::NotTriangles { .. }), "{e}");
    doc["buffers"][0]["uri"] = "nowhere.bin".into();
    let e = refused(
        "missing",
        "m.gltf",
        &serde_json::to_vec(&doc).expect("json"),
        "no data",
    );
    assert!(
        matches!(e, GltfError::MissingBuffer { buffer: 0, .. }),
        "{e}"
    );
}
