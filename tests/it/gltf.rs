//! glTF output (one node per part under a root per model, or one mesh) and
//! glTF input (GLB and JSON, embedded and external buffers, node
//! transforms, selection by name), with the round trip GLB -> OBJ -> GLB.

use pdesculpt::mesh::io::{self, Format, Layout, Scene};
use pdesculpt::mesh::samples::torus_mesh;
use pdesculpt::mesh::{topology, Mesh};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A round trip through files keeps every vertex within this distance
/// (metres; the bar, far above the f32 rounding of a 2.5 m torus,
/// about 1.2e-7 m).
const ROUND_TRIP_M: f64 = 1e-6;

/// Positions moved by a node transform are compared within f32 rounding of
/// coordinates below 10 (2^-20 ~ 1e-6 relative, times 10).
const TRANSFORM_ROUNDING: f64 = 1e-5;

pub fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("pdesculpt-gltf-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// A watertight torus in three parts (`crown`, `belt`, `rest`) that share
/// their seam vertices.
pub fn three_part_torus() -> Mesh {
    let mut m = torus_mesh(12);
    m.groups = vec!["crown".into(), "belt".into(), "rest".into()];
    let n = m.triangles.len();
    m.tri_group = (0..n).map(|t| (3 * t / n) as u32).collect();
    m
}

/// The JSON chunk of a GLB.
pub fn glb_json(b: &[u8]) -> Value {
    let len = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
    serde_json::from_slice(&b[20..20 + len]).expect("json chunk")
}

/// A GLB from a JSON document and a binary chunk.
pub fn glb_bytes(doc: &Value, bin: &[u8]) -> Vec<u8> {
    let mut j = serde_json::to_vec(doc).expect("json");
    while j.len() % 4 != 0 {
        j.push(b' ');
    }
    let mut bin = bin.to_vec();
    while bin.len() % 4 != 0 {
        bin.push(0);
    }
    let total = 28 + j.len() + bin.len();
    let mut out = b"glTF".to_vec();
    for x in [2u32, total as u32, j.len() as u32] {
        out.extend_from_slice(&x.to_le_bytes());
    }
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&j);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

/// The BIN chunk of a GLB.
pub fn glb_bin(b: &[u8]) -> Vec<u8> {
    let len = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
    b[28 + len..].to_vec()
}

/// Largest distance from a vertex of one mesh to the nearest vertex of the
/// other, both ways (the meshes have the same number of vertices).
fn max_vertex_gap(a: &Mesh, b: &Mesh) -> f64 {
    assert_eq!(a.positions.len(), b.positions.len(), "vertex counts");
    let one_way = |x: &Mesh, y: &Mesh| {
        x.positions
            .iter()
            .map(|p| {
                y.positions
                    .iter()
                    .map(|q| pdesculpt::mesh::dist(*p, *q))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    };
    one_way(a, b).max(one_way(b, a))
}

fn names(v: &Value) -> Vec<String> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x["name"].as_str().unwrap_or("").to_string())
        .collect()
}

#[test]
fn parts_layout_is_one_node_and_mesh_per_part_under_one_root() {
    let m = three_part_torus();
    let b = io::encode_scene(
        &Scene::single("ring", m.clone()),
        Format::Glb,
        Layout::Parts,
    )
    .expect("encodes");
    let doc = glb_json(&b);
    let roots = doc["scenes"][0]["nodes"].as_array().expect("roots").clone();
    assert_eq!(roots.len(), 1, "one root per model");
    let root = &doc["nodes"][roots[0].as_u64().expect("index") as usize];
    assert_eq!(root["name"], "ring");
    assert!(root.get("mesh").is_none(), "the root holds no geometry");
    let children: Vec<String> = root["children"]
        .as_array()
        .expect("children")
        .iter()
        .map(|c| doc["nodes"][c.as_u64().expect("index") as usize]["name"].to_string())
        .collect();
    assert_eq!(children, ["\"crown\"", "\"belt\"", "\"rest\""]);
    assert_eq!(names(&doc["meshes"]), ["crown", "belt", "rest"]);
    assert_eq!(names(&doc["materials"]), ["crown", "belt", "rest"]);
    // each part has its own vertices: more in all than the shared whole
    let counts: u64 = doc["meshes"]
        .as_array()
        .expect("meshes")
        .iter()
        .map(|mesh| {
            let a = mesh["primitives"][0]["attributes"]["POSITION"]
                .as_u64()
                .expect("acc");
            doc["accessors"][a as usize]["count"]
                .as_u64()
                .expect("count")
        })
        .sum();
    assert!(
        counts as usize > m.positions.len(),
        "seams written in both parts"
    );
    // read back and welded: the same watertight torus, groups as parts
    let d = tmpdir("parts");
    let path = d.join("ring.glb");
    std::fs::write(&path, &b).expect("write");
    let back = io::read(&path).expect("reads");
    assert_eq!(back.groups, ["crown", "belt", "rest"]);
    assert_eq!(back.triangles.len(), m.triangles.len());
    assert!(max_vertex_gap(&back, &m) < ROUND_TRIP_M);
    let t = topology::report(&back);
    assert!(t.watertight && t.manifold && t.oriented, "{t:?}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn single_mesh_layout_is_one_node_whose_materials_name_the_parts() {
    let m = three_part_torus();
    let b = io::encode_scene(
        &Scene::single("ring", m.clone()),
        Format::Glb,
        Layout::SingleMesh,
    )
    .expect("encodes");
    let doc = glb_json(&b);
    assert_eq!(names(&doc["nodes"]), ["ring"]);
    assert_eq!(doc["meshes"].as_array().expect("meshes").len(), 1);
    let prims = doc["meshes"][0]["primitives"].as_array().expect("prims");
    assert_eq!(prims.len(), 3);
    assert!(
        prims.iter().all(|p| p["attributes"]["POSITION"] == 0),
        "one shared vertex buffer"
    );
    let d = tmpdir("single");
    let path = d.join("ring.glb");
    std::fs::write(&path, &b).expect("write");
    let back = io::read(&path).expect("reads");
    assert_eq!(
        back.groups,
        ["crown", "belt", "rest"],
        "parts from the materials"
    );
    assert_eq!(back.positions.len(), m.positions.len());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn models_are_root_nodes_and_a_one_part_model_is_one_node() {
    let body = three_part_torus();
    let mut prop = torus_mesh(4);
    prop.set_single_group("teddy");
    prop.map_positions(|p| [p[0] + 5.0, p[1], p[2]]);
    let scene = Scene::single("female", body).with("teddy", prop);
    let b = io::encode_scene(&scene, Format::Glb, Layout::Parts).expect("encodes");
    let doc = glb_json(&b);
    let roots: Vec<String> = doc["scenes"][0]["nodes"]
        .as_array()
        .expect("roots")
        .iter()
        .map(|r| doc["nodes"][r.as_u64().expect("i") as usize]["name"].to_string())
        .collect();
    assert_eq!(roots, ["\"female\"", "\"teddy\""]);
    let d = tmpdir("models");
    let path = d.join("scene.glb");
    std::fs::write(&path, &b).expect("write");
    let back = io::read_scene(&path).expect("reads");
    let got: Vec<(&str, Vec<String>)> = back
        .models
        .iter()
        .map(|m| (m.name.as_str(), m.mesh.groups.clone()))
        .collect();
    assert_eq!(
        got,
        [
            ("female", vec!["crown".into(), "belt".into(), "rest".into()]),
            ("teddy", vec!["teddy".to_string()])
        ]
    );
    // one part by name, and a name that is not there
    let arm = io::read(Path::new(&format!("{}#belt", path.display()))).expect("selects");
    assert_eq!(arm.groups, ["belt"]);
    let err = io::read(Path::new(&format!("{}#tail", path.display()))).expect_err("no tail");
    let msg = err.to_string();
    assert!(msg.contains("\"tail\"") && msg.contains("belt"), "{msg}");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn glb_obj_glb_round_trip_keeps_vertices_and_parts() {
    let d = tmpdir("round");
    let m = three_part_torus();
    let (a, o, b) = (d.join("a.glb"), d.join("a.obj"), d.join("b.glb"));
    io::write(&m, &a).expect("glb");
    let first = io::read_scene(&a).expect("reads glb");
    io::write_scene(&first, &o, Layout::Parts).expect("obj");
    let obj_text = std::fs::read_to_string(&o).expect("obj text");
    assert_eq!(obj_text.matches("\no ").count(), 3, "one o per part");
    let mid = io::read_scene(&o).expect("reads obj");
    io::write_scene(&mid, &b, Layout::Parts).expect("glb again");
    let last = io::read(&b).expect("reads glb again");
    assert!(max_vertex_gap(&last, &m) < ROUND_TRIP_M);
    assert_eq!(last.groups, m.groups);
    assert_eq!(last.triangles.len(), m.triangles.len());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn gltf_json_reads_with_embedded_and_external_buffers() {
    let d = tmpdir("json");
    let m = three_part_torus();
    let embedded = d.join("e.gltf");
    io::write(&m, &embedded).expect("gltf");
    let e = io::read(&embedded).expect("reads embedded");
    assert!(max_vertex_gap(&e, &m) < ROUND_TRIP_M);
    // the same document with its buffer in a file beside it
    let glb = io::encode(&m, Format::Glb).expect("glb");
    let mut doc = glb_json(&glb);
    doc["buffers"][0]["uri"] = "ring%20data.bin".into();
    std::fs::write(d.join("ring data.bin"), glb_bin(&glb)).expect("bin");
    let external = d.join("x.gltf");
    std::fs::write(&external, serde_json::to_vec(&doc).expect("json")).expect("gltf");
    let x = io::read(&external).expect("reads external");
    assert!(max_vertex_gap(&x, &m) < ROUND_TRIP_M);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn node_transforms_are_applied_and_mirrors_keep_triangles_outward() {
    let m = three_part_torus();
    let glb = io::encode_scene(
        &Scene::single("ring", m.clone()),
        Format::Glb,
        Layout::Parts,
    )
    .expect("glb");
    let mut doc = glb_json(&glb);
    let root = doc["scenes"][0]["nodes"][0].as_u64().expect("root") as usize;
    // root: scale 2 and a move up; the mirror x -> -x on the root too
    doc["nodes"][root]["scale"] = serde_json::json!([-2.0, 2.0, 2.0]);
    doc["nodes"][root]["translation"] = serde_json::json!([0.0, 3.0, 0.0]);
    let d = tmpdir("transform");
    let path = d.join("t.glb");
    std::fs::write(&path, glb_bytes(&doc, &glb_bin(&glb))).expect("write");
    let back = io::read(&path).expect("reads");
    let mut want = m.clone();
    want.map_positions(|p| [-2.0 * p[0], 2.0 * p[1] + 3.0, 2.0 * p[2]]);
    assert!(max_vertex_gap(&back, &want) < TRANSFORM_ROUNDING);
    assert!(
        back.signed_volume() > 0.0,
        "a mirror flips the triangles back outward"
    );
    assert!(m.signed_volume() > 0.0);
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn demo_sketch_glb_has_one_node_per_document_part_and_transition() {
    let (mesh, step) = pdesculpt::demo::sketched_female().expect("builds");
    let scene = Scene::single("female", mesh.clone());
    let b = io::encode_scene(&scene, Format::Glb, Layout::Parts).expect("encodes");
    let doc = glb_json(&b);
    let root = &doc["nodes"][doc["scenes"][0]["nodes"][0].as_u64().expect("root") as usize];
    assert_eq!(root["name"], "female");
    let mut children: Vec<String> = root["children"]
        .as_array()
        .expect("children")
        .iter()
        .map(|c| {
            let n = &doc["nodes"][c.as_u64().expect("index") as usize];
            n["name"].as_str().expect("name").to_string()
        })
        .collect();
    let mut parts = step.parts.clone();
    children.sort();
    parts.sort();
    assert_eq!(
        children, parts,
        "one node per part, transition and removed part"
    );
    // welded back, the whole is the watertight shared-vertex mesh
    let d = tmpdir("sketch");
    let path = d.join("demo-sketch.glb");
    std::fs::write(&path, &b).expect("write");
    let back = io::read(&path).expect("reads");
    assert_eq!(back.positions.len(), mesh.positions.len());
    let t = topology::report(&back);
    assert_eq!(t.watertight, topology::report(&mesh).watertight, "{t:?}");
    std::fs::remove_dir_all(&d).ok();
}
