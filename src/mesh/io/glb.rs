//! glTF 2.0 output: binary (GLB) or JSON with the buffer embedded as a
//! base64 data URI (`.gltf`). Layouts are in [`super::scene`]: one node
//! and mesh per part under a root node per model, or one mesh with one
//! primitive per part. Every primitive has f32 POSITION (with min/max),
//! unit NORMAL and u32 indices; every part its material (named after it,
//! a distinct colour). Checked with the Khronos glTF validator by
//! `verify/validate_glb.mjs` (run in CI, 0 errors and 0 warnings).

use super::scene::{Layout, Model, Scene};
use crate::mesh::Mesh;
use serde_json::{json, Value};

/// A distinct colour for group `g` (golden-angle hues, pastel).
pub fn group_colour(g: usize) -> [f32; 3] {
    let h = (g as f32 * 0.618_034) % 1.0;
    let (s, v) = (0.45f32, 0.9f32);
    let i = (h * 6.0).floor();
    let f = h * 6.0 - i;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - f * s), v * (1.0 - (1.0 - f) * s));
    match i as i32 % 6 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        _ => [v, p, q],
    }
}

/// Encodes `m` (already validated, non-empty) as a one-node GLB (the
/// [`Layout::SingleMesh`] layout of a scene of `m` alone).
pub fn encode_glb(m: &Mesh) -> Vec<u8> {
    encode_glb_scene(&Scene::single("pdesculpt", m.clone()), Layout::SingleMesh)
}

/// Encodes a validated scene as GLB bytes.
pub fn encode_glb_scene(scene: &Scene, layout: Layout) -> Vec<u8> {
    let (doc, bin) = document(scene, layout);
    glb_container(&doc, bin)
}

/// Encodes a validated scene as glTF JSON with its buffer embedded.
pub fn encode_gltf_scene(scene: &Scene, layout: Layout) -> Vec<u8> {
    use base64::Engine;
    let (mut doc, bin) = document(scene, layout);
    let uri = format!(
        "data:application/octet-stream;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(&bin)
    );
    doc["buffers"] = json!([{"byteLength": bin.len(), "uri": uri}]);
    serde_json::to_vec_pretty(&doc).unwrap_or_default()
}

/// The glTF JSON document and its binary buffer.
fn document(scene: &Scene, layout: Layout) -> (Value, Vec<u8>) {
    let mut b = Builder::default();
    let roots = match layout {
        Layout::Parts => scene
            .models
            .iter()
            .filter(|m| !m.mesh.triangles.is_empty())
            .map(|m| b.model_parts(m))
            .collect(),
        Layout::SingleMesh => {
            let m = scene.flatten();
            let mesh = b.shared_mesh(&m, &scene.joined_name());
            vec![b.node(json!({"name": scene.joined_name(), "mesh": mesh}))]
        }
    };
    let doc = json!({
        "asset": {"version": "2.0", "generator": concat!("pdesculpt ", env!("CARGO_PKG_VERSION"))},
        "scene": 0,
        "scenes": [{"nodes": roots}],
        "nodes": b.nodes,
        "meshes": b.meshes,
        "materials": b.materials,
        "accessors": b.accessors,
        "bufferViews": b.views,
        "buffers": [{"byteLength": b.bin.len()}],
    });
    (doc, b.bin)
}

/// The GLB container: header, JSON chunk (space padded), BIN chunk.
fn glb_container(doc: &Value, mut bin: Vec<u8>) -> Vec<u8> {
    let mut json_bytes = serde_json::to_vec(doc).unwrap_or_default();
    while json_bytes.len() % 4 != 0 {
        json_bytes.push(b' ');
    }
    while bin.len() % 4 != 0 {
        bin.push(0);
    }
    let total = 12 + 8 + json_bytes.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json_bytes.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json_bytes);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(&bin);
    out
}

/// The arrays of a glTF document as they are filled.
#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    materials: Vec<Value>,
    material_names: Vec<String>,
    meshes: Vec<Value>,
    nodes: Vec<Value>,
}

/// `ELEMENT_ARRAY_BUFFER` and `ARRAY_BUFFER` buffer-view targets.
const TARGET_INDICES: u32 = 34963;
const TARGET_VERTICES: u32 = 34962;

impl Builder {
    /// One model as a root node with one child per part (or one node when
    /// the model has a single part); returns the root's index.
    fn model_parts(&mut self, model: &Model) -> usize {
        let m = &model.mesh;
        let normals = m.vertex_normals();
        let parts: Vec<usize> = (0..m.groups.len())
            .filter(|&g| m.tri_group.iter().any(|&x| x as usize == g))
            .collect();
        let mut children = Vec::with_capacity(parts.len());
        for &g in &parts {
            let mesh = self.part_mesh(m, &normals, g);
            if parts.len() == 1 {
                return self.node(json!({"name": model.name, "mesh": mesh}));
            }
            children.push(self.node(json!({"name": m.groups[g], "mesh": mesh})));
        }
        self.node(json!({"name": model.name, "children": children}))
    }

    /// Group `g` of `m` as its own mesh: the vertices its triangles use
    /// (in first-use order) with the whole model's normals.
    fn part_mesh(&mut self, m: &Mesh, normals: &[[f64; 3]], g: usize) -> usize {
        let mut new_index = vec![u32::MAX; m.positions.len()];
        let (mut pos, mut nor, mut idx) = (Vec::new(), Vec::new(), Vec::new());
        for (t, tri) in m.triangles.iter().enumerate() {
            if m.tri_group[t] as usize != g {
                continue;
            }
            for &i in tri {
                let i = i as usize;
                if new_index[i] == u32::MAX {
                    new_index[i] = pos.len() as u32;
                    pos.push(m.positions[i]);
                    nor.push(normals[i]);
                }
                idx.push(new_index[i]);
            }
        }
        let p = self.vertices(&pos, true);
        let n = self.vertices(&nor, false);
        let i = self.indices(&idx);
        let material = self.material(&m.groups[g]);
        self.meshes.push(json!({"name": m.groups[g], "primitives": [
            {"attributes": {"POSITION": p, "NORMAL": n}, "indices": i,
             "material": material, "mode": 4}]}));
        self.meshes.len() - 1
    }

    /// `m` as one mesh: shared POSITION and NORMAL, one primitive per group.
    fn shared_mesh(&mut self, m: &Mesh, name: &str) -> usize {
        let p = self.vertices(&m.positions, true);
        let n = self.vertices(&m.vertex_normals(), false);
        let mut primitives = Vec::new();
        for g in 0..m.groups.len() {
            let idx: Vec<u32> = m
                .triangles
                .iter()
                .zip(&m.tri_group)
                .filter(|(_, &x)| x as usize == g)
                .flat_map(|(t, _)| *t)
                .collect();
            if idx.is_empty() {
                continue;
            }
            let i = self.indices(&idx);
            let material = self.material(&m.groups[g]);
            primitives.push(json!({"attributes": {"POSITION": p, "NORMAL": n},
                "indices": i, "material": material, "mode": 4}));
        }
        self.meshes
            .push(json!({"name": name, "primitives": primitives}));
        self.meshes.len() - 1
    }

    fn node(&mut self, node: Value) -> usize {
        self.nodes.push(node);
        self.nodes.len() - 1
    }

    /// A buffer view of `bytes` (4-byte aligned: every element here is).
    fn view(&mut self, bytes: &[u8], target: u32) -> usize {
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.views.push(json!({"buffer": 0, "byteOffset": offset,
            "byteLength": bytes.len(), "target": target}));
        self.views.len() - 1
    }

    /// An f32 VEC3 accessor: positions (with min/max) or unit normals
    /// (isolated or degenerate vertices get an arbitrary unit vector, since
    /// the validator requires unit length).
    fn vertices(&mut self, v: &[[f64; 3]], positions: bool) -> usize {
        let mut bytes = Vec::with_capacity(v.len() * 12);
        for p in v {
            let mut q = p.map(|x| x as f32);
            if !positions {
                let len = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
                q = if (len - 1.0).abs() < 1e-3 {
                    q.map(|x| x / len)
                } else {
                    [0.0, 1.0, 0.0]
                };
            }
            for x in q {
                bytes.extend_from_slice(&x.to_le_bytes());
            }
        }
        let view = self.view(&bytes, TARGET_VERTICES);
        let mut acc = json!({"bufferView": view, "componentType": 5126,
            "count": v.len(), "type": "VEC3"});
        if positions {
            // f32 rounding is monotone: the f32 box is the f64 box rounded
            if let Some((lo, hi)) = crate::vec3::bounds(v) {
                acc["min"] = json!(lo.map(|x| x as f32));
                acc["max"] = json!(hi.map(|x| x as f32));
            }
        }
        self.accessors.push(acc);
        self.accessors.len() - 1
    }

    /// A u32 SCALAR index accessor.
    fn indices(&mut self, idx: &[u32]) -> usize {
        let bytes: Vec<u8> = idx.iter().flat_map(|i| i.to_le_bytes()).collect();
        let view = self.view(&bytes, TARGET_INDICES);
        self.accessors
            .push(json!({"bufferView": view, "componentType": 5125,
            "count": idx.len(), "type": "SCALAR"}));
        self.accessors.len() - 1
    }

    /// The material named `name` (made on first use, the next colour).
    fn material(&mut self, name: &str) -> usize {
        if let Some(i) = self.material_names.iter().position(|n| n == name) {
            return i;
        }
        let c = group_colour(self.materials.len());
        self.materials.push(json!({"name": name,
            "pbrMetallicRoughness": {"baseColorFactor": [c[0], c[1], c[2], 1.0],
                "metallicFactor": 0.0, "roughnessFactor": 0.8},
            "doubleSided": true}));
        self.material_names.push(name.to_string());
        self.materials.len() - 1
    }
}
