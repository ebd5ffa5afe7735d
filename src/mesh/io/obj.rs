//! Wavefront OBJ: `v`, `f` (any polygon, fan-triangulated; `v/vt/vn`
//! references; negative indices), `g`/`o` groups (a group is made when its
//! first face arrives, so an `o` followed by `g`s makes no empty group).
//! Other statements are ignored. Errors name the line. Written with one `o`
//! per part over one shared vertex list ([`super::scene`]).

use super::scene::{Layout, Scene};
use crate::mesh::{Mesh, MeshError};
use std::fmt::Write;

/// Parses OBJ text. `path` is only used in error messages.
pub fn parse_obj(text: &str, path: &str) -> Result<Mesh, MeshError> {
    let mut m = Mesh {
        groups: Vec::new(),
        ..Mesh::default()
    };
    let mut group: Option<u32> = None;
    let mut pending: Option<String> = None;
    let err = |line: usize, message: String| MeshError::Parse {
        path: path.to_string(),
        line,
        message,
    };
    for (ln, raw) in text.lines().enumerate() {
        let line_no = ln + 1;
        let line = raw.split('#').next().unwrap_or("").trim();
        let mut it = line.split_whitespace();
        let Some(tag) = it.next() else { continue };
        match tag {
            "v" => {
                let mut p = [0.0; 3];
                for (k, slot) in p.iter_mut().enumerate() {
                    let s = it.next().ok_or_else(|| {
                        err(line_no, format!("vertex has {k} coordinates, needs 3"))
                    })?;
                    *slot = s
                        .parse::<f64>()
                        .map_err(|_| err(line_no, format!("bad vertex coordinate {s:?}")))?;
                    if !slot.is_finite() {
                        return Err(err(line_no, format!("non-finite vertex coordinate {s:?}")));
                    }
                }
                m.positions.push(p);
            }
            "f" => {
                let n = m.positions.len() as i64;
                let mut idx = Vec::with_capacity(4);
                for tok in it {
                    let first = tok.split('/').next().unwrap_or("");
                    let i: i64 = first
                        .parse()
                        .map_err(|_| err(line_no, format!("bad face index {tok:?}")))?;
                    let resolved = if i > 0 { i - 1 } else { n + i };
                    if i == 0 || resolved < 0 || resolved >= n {
                        return Err(err(
                            line_no,
                            format!("face index {i} out of range (there are {n} vertices so far)"),
                        ));
                    }
                    idx.push(resolved as u32);
                }
                if idx.len() < 3 {
                    return Err(err(
                        line_no,
                        format!("face has {} vertices, needs 3", idx.len()),
                    ));
                }
                let g = match (pending.take(), group) {
                    (Some(name), _) => m.group_index(&name),
                    (None, Some(g)) => g,
                    (None, None) => m.group_index("default"),
                };
                group = Some(g);
                for k in 1..idx.len() - 1 {
                    m.triangles.push([idx[0], idx[k], idx[k + 1]]);
                    m.tri_group.push(g);
                }
            }
            "g" | "o" => {
                let name = it.collect::<Vec<_>>().join(" ");
                let name = if name.is_empty() {
                    "default".to_string()
                } else {
                    name
                };
                pending = Some(name);
            }
            _ => {}
        }
    }
    if m.groups.is_empty() {
        m.groups.push("default".into());
    }
    Ok(m)
}

/// Encodes a mesh as OBJ text with vertex normals and one `o` per group.
pub fn encode_obj(m: &Mesh) -> String {
    encode_obj_scene(&Scene::single("pdesculpt", m.clone()), Layout::Parts)
}

/// Encodes a scene as OBJ text: every model's vertices and normals (one
/// list, seams shared), then per model a `# model NAME` comment and one
/// `o PART` per part ([`Layout::Parts`]), or one `o` named after the
/// models with one `g PART` per part ([`Layout::SingleMesh`]).
pub fn encode_obj_scene(scene: &Scene, layout: Layout) -> String {
    let nv: usize = scene.models.iter().map(|m| m.mesh.positions.len()).sum();
    let nt: usize = scene.models.iter().map(|m| m.mesh.triangles.len()).sum();
    let mut s = String::with_capacity(nv * 64 + nt * 32);
    let _ = writeln!(s, "# written by pdesculpt {}", env!("CARGO_PKG_VERSION"));
    for model in &scene.models {
        for p in &model.mesh.positions {
            let _ = writeln!(s, "v {} {} {}", p[0] as f32, p[1] as f32, p[2] as f32);
        }
    }
    for model in &scene.models {
        for n in model.mesh.vertex_normals() {
            let _ = writeln!(s, "vn {} {} {}", n[0] as f32, n[1] as f32, n[2] as f32);
        }
    }
    if layout == Layout::SingleMesh {
        let _ = writeln!(s, "o {}", scene.joined_name());
    }
    let mut base = 1u64;
    for model in &scene.models {
        let m = &model.mesh;
        let _ = writeln!(s, "# model {}", model.name);
        for (g, name) in m.groups.iter().enumerate() {
            let mut header = false;
            for (t, tri) in m.triangles.iter().enumerate() {
                if m.tri_group[t] as usize != g {
                    continue;
                }
                if !header {
                    let tag = if layout == Layout::Parts { "o" } else { "g" };
                    let _ = writeln!(s, "{tag} {name}");
                    header = true;
                }
                let [a, b, c] = tri.map(|i| i as u64 + base);
                let _ = writeln!(s, "f {a}//{a} {b}//{b} {c}//{c}");
            }
        }
        base += m.positions.len() as u64;
    }
    s
}
