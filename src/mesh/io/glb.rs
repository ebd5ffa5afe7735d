//! Binary glTF 2.0 (GLB): one mesh, one primitive per group (its own
//! material colour), shared f32 POSITION (with min/max) and unit NORMAL
//! accessors, u32 indices. Checked with the Khronos glTF validator by
//! `verify/validate_glb.sh` (run in CI).

use crate::mesh::Mesh;
use serde_json::json;

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

/// Encodes `m` (already validated, non-empty) as GLB bytes.
pub fn encode_glb(m: &Mesh) -> Vec<u8> {
    let nv = m.positions.len();
    let mut bin: Vec<u8> = Vec::with_capacity(nv * 24 + m.triangles.len() * 12);
    // f32 rounding is monotone: the f32 box is the f64 box rounded
    let (lo, hi) = m.bbox();
    let (lo, hi) = (lo.map(|x| x as f32), hi.map(|x| x as f32));
    for p in &m.positions {
        for x in p {
            bin.extend_from_slice(&(*x as f32).to_le_bytes());
        }
    }
    let normals_offset = bin.len();
    for n in m.vertex_normals() {
        // the validator requires unit normals: give isolated or degenerate
        // vertices an arbitrary unit vector
        let n32 = [n[0] as f32, n[1] as f32, n[2] as f32];
        let len = (n32[0] * n32[0] + n32[1] * n32[1] + n32[2] * n32[2]).sqrt();
        let n32 = if (len - 1.0).abs() < 1e-3 {
            [n32[0] / len, n32[1] / len, n32[2] / len]
        } else {
            [0.0, 1.0, 0.0]
        };
        for x in n32 {
            bin.extend_from_slice(&x.to_le_bytes());
        }
    }
    let indices_offset = bin.len();
    let mut buffer_views = vec![
        json!({"buffer": 0, "byteOffset": 0, "byteLength": nv * 12, "target": 34962}),
        json!({"buffer": 0, "byteOffset": normals_offset, "byteLength": nv * 12, "target": 34962}),
    ];
    let mut accessors = vec![
        json!({"bufferView": 0, "componentType": 5126, "count": nv, "type": "VEC3",
               "min": lo, "max": hi}),
        json!({"bufferView": 1, "componentType": 5126, "count": nv, "type": "VEC3"}),
    ];
    let mut primitives = Vec::new();
    let mut materials = Vec::new();
    for g in 0..m.groups.len() {
        let start = bin.len();
        let mut count = 0usize;
        for (t, tri) in m.triangles.iter().enumerate() {
            if m.tri_group[t] as usize == g {
                for &i in tri {
                    bin.extend_from_slice(&i.to_le_bytes());
                }
                count += 3;
            }
        }
        if count == 0 {
            continue;
        }
        buffer_views.push(json!({"buffer": 0, "byteOffset": start,
            "byteLength": count * 4, "target": 34963}));
        accessors.push(
            json!({"bufferView": buffer_views.len() - 1, "componentType": 5125,
            "count": count, "type": "SCALAR"}),
        );
        let c = group_colour(g);
        materials.push(json!({"name": m.groups[g],
            "pbrMetallicRoughness": {"baseColorFactor": [c[0], c[1], c[2], 1.0],
                "metallicFactor": 0.0, "roughnessFactor": 0.8},
            "doubleSided": true}));
        primitives.push(json!({"attributes": {"POSITION": 0, "NORMAL": 1},
            "indices": accessors.len() - 1, "material": materials.len() - 1, "mode": 4}));
    }
    let _ = indices_offset;
    let doc = json!({
        "asset": {"version": "2.0", "generator": concat!("pdesculpt ", env!("CARGO_PKG_VERSION"))},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "pdesculpt"}],
        "meshes": [{"name": m.groups.join("+"), "primitives": primitives}],
        "materials": materials,
        "accessors": accessors,
        "bufferViews": buffer_views,
        "buffers": [{"byteLength": bin.len()}],
    });
    let mut json_bytes = serde_json::to_vec(&doc).unwrap_or_default();
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
