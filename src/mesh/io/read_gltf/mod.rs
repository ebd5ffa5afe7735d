//! glTF 2.0 input, binary (GLB) or JSON (`.gltf`, buffers embedded as
//! `data:` URIs or external files beside it), parsed and validated with
//! the `gltf` crate; every accessor bound is checked here before a read
//! ([`accessor`]), so a malformed file is a [`GltfError`], never a panic.
//!
//! What is read: the default scene (else the first, else every root
//! node), each mesh node's triangle primitives (`TRIANGLES`, strips and
//! fans) with the node transforms applied (a mirroring transform flips
//! the triangles so they stay counter-clockwise). One [`Model`] per root
//! node, named after it; its parts (mesh groups) are the mesh nodes below
//! it, named after the node (or, for a node whose mesh has several
//! primitives, after each primitive's material, which is how one mesh with
//! one material per part arrives). Units are metres, as glTF says. With
//! `weld` (the default), vertices with bit-identical coordinates in one
//! model become one vertex: parts written as separate meshes, and
//! exporters that split vertices at normal or UV seams, give back one
//! connected surface. Skins, morph targets, normals and UVs are ignored.
//! [`GltfOptions::select`] keeps the named nodes and everything below
//! them (in a path: `FILE.glb#arm_l,arm_r`).
//!
//! Refused, each by name: points and lines, Draco or meshopt compression,
//! quantised or sparse positions, buffers that are missing, short or
//! outside the file's folder, views and accessors past their data, indices
//! past the vertex count, coordinates that are not finite 32-bit floats
//! after the transforms.

mod accessor;
mod container;
mod error;

pub use error::GltfError;

use super::scene::{Model, Scene};
use crate::mesh::Mesh;
use ::gltf::mesh::Mode;
use ::gltf::{Document, Node};
use std::collections::HashMap;
use std::path::Path;

/// What to read from a glTF file. Outside the crate, start from
/// [`GltfOptions::default`] and change fields with the `with_*` setters (or
/// by assignment).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct GltfOptions {
    /// Node names to keep with everything below them; empty (the default):
    /// every node.
    pub select: Vec<String>,
    /// Merge vertices with bit-identical coordinates within a model
    /// (default true).
    pub weld: bool,
}

setters!(GltfOptions {
    with_select: select: Vec<String>,
    with_weld: weld: bool,
});

impl Default for GltfOptions {
    fn default() -> Self {
        GltfOptions {
            select: Vec::new(),
            weld: true,
        }
    }
}

/// A 4x4 matrix, column-major as glTF stores it (`m[col][row]`).
type Mat4 = [[f64; 4]; 4];

const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// Parses glTF bytes (GLB or JSON) into a scene; `dir` is the folder of
/// the file, where external buffers are looked up (`None` refuses them).
pub fn parse_gltf(
    bytes: &[u8],
    dir: Option<&Path>,
    opts: &GltfOptions,
) -> Result<Scene, GltfError> {
    let parsed = container::parse(bytes, dir)?;
    let placed = mesh_nodes(&parsed.doc, &opts.select)?;
    let mut scene = Scene::default();
    let mut model_of_root: HashMap<usize, usize> = HashMap::new();
    for p in &placed {
        let k = *model_of_root.entry(p.root).or_insert_with(|| {
            let root = parsed.doc.nodes().nth(p.root);
            let name = root.map(|r| node_name(&r)).unwrap_or_default();
            scene.models.push(Model {
                name,
                mesh: Mesh {
                    groups: Vec::new(),
                    ..Mesh::default()
                },
            });
            scene.models.len() - 1
        });
        add_node(&mut scene.models[k].mesh, p, &parsed.doc, &parsed.buffers)?;
    }
    scene.models.retain(|m| !m.mesh.triangles.is_empty());
    if scene.models.is_empty() {
        return Err(GltfError::NoMeshes);
    }
    for m in &mut scene.models {
        if opts.weld {
            weld(&mut m.mesh);
        }
    }
    Ok(scene)
}

/// A mesh node placed in the scene.
struct Placed {
    node: usize,
    root: usize,
    world: Mat4,
}

/// The name a node goes by: its own, its mesh's, or `node<i>`.
fn node_name(n: &Node) -> String {
    n.name()
        .or_else(|| n.mesh().and_then(|m| m.name()))
        .map(str::to_string)
        .unwrap_or_else(|| format!("node{}", n.index()))
}

/// The scene's root nodes: the default scene's, else the first scene's,
/// else every node that is nobody's child.
fn roots(doc: &Document) -> Vec<usize> {
    if let Some(s) = doc.default_scene().or_else(|| doc.scenes().next()) {
        return s.nodes().map(|n| n.index()).collect();
    }
    let mut child = vec![false; doc.nodes().len()];
    for n in doc.nodes() {
        for c in n.children() {
            child[c.index()] = true;
        }
    }
    (0..child.len()).filter(|&i| !child[i]).collect()
}

/// Every mesh node under the roots (depth first), with its world matrix,
/// keeping only the selected subtrees when `select` is not empty.
fn mesh_nodes(doc: &Document, select: &[String]) -> Result<Vec<Placed>, GltfError> {
    for name in select {
        if !doc.nodes().any(|n| n.name() == Some(name.as_str())) {
            let mut available: Vec<String> = doc.nodes().map(|n| node_name(&n)).collect();
            available.truncate(64);
            return Err(GltfError::NoSuchNode {
                name: name.clone(),
                available,
            });
        }
    }
    let nodes: Vec<Node> = doc.nodes().collect();
    let mut seen = vec![false; nodes.len()];
    let mut out = Vec::new();
    for root in roots(doc) {
        let mut stack = vec![(root, IDENTITY, select.is_empty())];
        while let Some((i, parent, chosen)) = stack.pop() {
            if std::mem::replace(&mut seen[i], true) {
                return Err(GltfError::NodeCycle { node: i });
            }
            let n = &nodes[i];
            let world = mul(&parent, &to_f64(n.transform().matrix()));
            let chosen = chosen || n.name().is_some_and(|x| select.iter().any(|s| s == x));
            if chosen && n.mesh().is_some() {
                out.push(Placed {
                    node: i,
                    root,
                    world,
                });
            }
            for c in n.children().collect::<Vec<_>>().into_iter().rev() {
                stack.push((c.index(), world, chosen));
            }
        }
    }
    Ok(out)
}

fn to_f64(m: [[f32; 4]; 4]) -> Mat4 {
    m.map(|c| c.map(f64::from))
}

fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut m = [[0.0; 4]; 4];
    for (c, col) in m.iter_mut().enumerate() {
        for (r, x) in col.iter_mut().enumerate() {
            *x = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    m
}

fn apply(m: &Mat4, p: [f32; 3]) -> [f64; 3] {
    let p = p.map(f64::from);
    [0, 1, 2].map(|r| m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r])
}

/// Determinant of the linear part: negative for a mirroring transform.
fn det3(m: &Mat4) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2])
        - m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2])
        + m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2])
}

/// Appends the triangle primitives of one placed mesh node to `out`.
fn add_node(
    out: &mut Mesh,
    p: &Placed,
    doc: &Document,
    buffers: &[Vec<u8>],
) -> Result<(), GltfError> {
    let Some(n) = doc.nodes().nth(p.node) else {
        return Ok(());
    };
    let Some(mesh) = n.mesh() else { return Ok(()) };
    let name = node_name(&n);
    let prims: Vec<_> = mesh.primitives().collect();
    let flip = det3(&p.world) < 0.0;
    for (k, prim) in prims.iter().enumerate() {
        let group = match prim.material().name() {
            Some(mat) if prims.len() > 1 => mat.to_string(),
            _ => name.clone(),
        };
        let pos_acc =
            prim.get(&::gltf::Semantic::Positions)
                .ok_or_else(|| GltfError::NoPositions {
                    node: name.clone(),
                    primitive: k,
                })?;
        let local = accessor::positions(&pos_acc, buffers)?;
        let count = local.len();
        let idx = match prim.indices() {
            Some(a) => accessor::indices(&a, buffers)?,
            None => (0..count as u32).collect(),
        };
        if let Some(&index) = idx.iter().find(|&&i| i as usize >= count) {
            return Err(GltfError::IndexOutOfRange {
                node: name.clone(),
                primitive: k,
                index,
                count,
            });
        }
        let tris = triangles(prim.mode(), &idx).map_err(|mode| match mode {
            Some(mode) => GltfError::NotTriangles {
                node: name.clone(),
                primitive: k,
                mode,
            },
            None => GltfError::PartialTriangle {
                node: name.clone(),
                primitive: k,
                count: idx.len(),
            },
        })?;
        let base = out.positions.len() as u32;
        for (vertex, q) in local.iter().enumerate() {
            let w = apply(&p.world, *q);
            if !w
                .iter()
                .all(|x| x.is_finite() && x.abs() <= f32::MAX as f64)
            {
                return Err(GltfError::NonFinite {
                    node: name.clone(),
                    vertex,
                    value: w,
                });
            }
            out.positions.push(w);
        }
        let g = out.group_index(&group);
        for [a, b, c] in tris {
            let t = if flip { [a, c, b] } else { [a, b, c] };
            out.triangles.push(t.map(|i| i + base));
            out.tri_group.push(g);
        }
    }
    Ok(())
}

/// The triangles a primitive draws; `Err(Some(mode))` for points and
/// lines, `Err(None)` for a `TRIANGLES` list that is not a multiple of 3.
fn triangles(mode: Mode, idx: &[u32]) -> Result<Vec<[u32; 3]>, Option<String>> {
    let n = idx.len();
    match mode {
        Mode::Triangles if n % 3 == 0 => {
            Ok(idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect())
        }
        Mode::Triangles => Err(None),
        Mode::TriangleStrip => Ok((0..n.saturating_sub(2))
            .map(|i| {
                if i % 2 == 0 {
                    [idx[i], idx[i + 1], idx[i + 2]]
                } else {
                    [idx[i + 1], idx[i], idx[i + 2]]
                }
            })
            .collect()),
        Mode::TriangleFan => Ok((1..n.saturating_sub(1))
            .map(|i| [idx[i], idx[i + 1], idx[0]])
            .collect()),
        other => Err(Some(format!("{other:?}"))),
    }
}

/// Merges vertices with bit-identical coordinates (`-0.0` equal to `0.0`),
/// keeping first-appearance order.
pub fn weld(m: &mut Mesh) {
    let mut first: HashMap<[u64; 3], u32> = HashMap::with_capacity(m.positions.len());
    let mut positions = Vec::with_capacity(m.positions.len());
    let remap: Vec<u32> = m
        .positions
        .iter()
        .map(|p| {
            let key = p.map(|x| (x + 0.0).to_bits());
            *first.entry(key).or_insert_with(|| {
                positions.push(*p);
                (positions.len() - 1) as u32
            })
        })
        .collect();
    m.positions = positions;
    for t in &mut m.triangles {
        *t = t.map(|i| remap[i as usize]);
    }
}
