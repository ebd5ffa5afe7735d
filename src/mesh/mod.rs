//! Triangle meshes: the common output of every family.
//!
//! Positions are `f64` (the families deform them numerically); conversion to
//! `f32` happens only in export and rendering. Triangles carry a group index
//! (a character's parts: `torso`, `l-arm`, ...), kept through export (OBJ
//! groups, GLB primitives).
//!
//! Submodules: [`io`] (OBJ, GLB, STL, PLY; atomic writes), [`metrics`]
//! (point-to-triangle distance with a bounding-volume hierarchy, RMS and
//! Hausdorff distances), [`topology`] (watertight, manifold, oriented),
//! [`slice`](mod@slice) (plane cross sections as closed polylines).

pub mod check;
pub mod io;
pub mod isosurface;
pub mod metrics;
pub mod samples;
pub mod slice;
pub mod topology;
pub mod unit;

use thiserror::Error;

/// Errors of mesh construction, reading and writing.
#[derive(Debug, Error)]
pub enum MeshError {
    #[error("{path}: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}:{line}: {message}")]
    Parse {
        path: String,
        line: usize,
        message: String,
    },
    #[error("{path}: unknown mesh format {ext:?} (expected .obj, .glb, .stl or .ply)")]
    UnknownFormat { path: String, ext: String },
    #[error("vertex {index} has a non-finite coordinate {value:?}")]
    NonFinite { index: usize, value: [f64; 3] },
    #[error("triangle {triangle} refers to vertex {index}, but the mesh has {count} vertices")]
    IndexOutOfRange {
        triangle: usize,
        index: u32,
        count: usize,
    },
    #[error("vertex {index} = {value:?} is outside the range of the 32-bit floats mesh files store (|x| <= 3.4e38); scale the mesh down")]
    OutOfF32Range { index: usize, value: [f64; 3] },
    #[error("{path}: byte {offset}: {message}")]
    ParseAt {
        path: String,
        offset: usize,
        message: String,
    },
    #[error("{path}: {source}")]
    Gltf {
        path: String,
        #[source]
        source: io::GltfError,
    },
    #[error("the mesh has no triangles")]
    Empty,
    #[error("{path}: the {what} is {kind}, not a regular file")]
    NotAFile {
        path: String,
        what: String,
        kind: &'static str,
    },
    #[error(
        "{path}: the {what} has {bytes} bytes, over the limit of {limit} bytes for one input file"
    )]
    InputTooLarge {
        path: String,
        what: String,
        bytes: u64,
        limit: u64,
    },
    #[error("{0}")]
    Invalid(String),
}

/// An indexed triangle mesh with per-triangle groups.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub positions: Vec<[f64; 3]>,
    /// Counter-clockwise (outward normal by the right-hand rule).
    pub triangles: Vec<[u32; 3]>,
    /// Group index of each triangle (into `groups`).
    pub tri_group: Vec<u32>,
    /// Group names; at least one.
    pub groups: Vec<String>,
}

impl Mesh {
    /// A mesh with one group, `"mesh"`.
    pub fn new(positions: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>) -> Self {
        Self::with_group(positions, triangles, "mesh")
    }

    /// A mesh whose triangles all belong to the group `name`.
    pub fn with_group(positions: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>, name: &str) -> Self {
        let n = triangles.len();
        Mesh {
            positions,
            triangles,
            tri_group: vec![0; n],
            groups: vec![name.to_string()],
        }
    }

    /// Two triangles per cell of a row-major grid of points (`nu x nv`,
    /// index `iu * nv + iv`), cut along the diagonal from `(iu, iv)` to
    /// `(iu + 1, iv + 1)`. A closed direction (`closed = [u, v]`) wraps: its
    /// last cells join the last row of points to the first. Fewer than two
    /// rows in an open direction (or none in a closed one) make no
    /// triangles.
    pub fn grid(positions: Vec<[f64; 3]>, nu: usize, nv: usize, closed: [bool; 2]) -> Self {
        let cells_u = if closed[0] { nu } else { nu.saturating_sub(1) };
        let cells_v = if closed[1] { nv } else { nv.saturating_sub(1) };
        let idx = |i: usize, j: usize| ((i % nu) * nv + (j % nv)) as u32;
        let mut tris = Vec::with_capacity(2 * cells_u * cells_v);
        for i in 0..cells_u {
            for j in 0..cells_v {
                let (a, b, c, e) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
                tris.push([a, b, c]);
                tris.push([a, c, e]);
            }
        }
        Mesh::new(positions, tris)
    }

    /// Appends `other` (its groups are kept, renamed into this mesh's group
    /// list; groups with equal names merge).
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend_from_slice(&other.positions);
        let map: Vec<u32> = other.groups.iter().map(|g| self.group_index(g)).collect();
        for (t, &g) in other.triangles.iter().zip(&other.tri_group) {
            self.triangles.push([t[0] + base, t[1] + base, t[2] + base]);
            self.tri_group.push(map[g as usize]);
        }
    }

    /// Index of group `name`, created if absent.
    pub fn group_index(&mut self, name: &str) -> u32 {
        if let Some(i) = self.groups.iter().position(|g| g == name) {
            return i as u32;
        }
        self.groups.push(name.to_string());
        (self.groups.len() - 1) as u32
    }

    /// Renames every triangle into the single group `name`.
    pub fn set_single_group(&mut self, name: &str) {
        self.groups = vec![name.to_string()];
        self.tri_group = vec![0; self.triangles.len()];
    }

    /// Finite coordinates, indices in range, consistent group table.
    pub fn validate(&self) -> Result<(), MeshError> {
        for (index, p) in self.positions.iter().enumerate() {
            if !p.iter().all(|x| x.is_finite()) {
                return Err(MeshError::NonFinite { index, value: *p });
            }
        }
        let count = self.positions.len();
        for (triangle, t) in self.triangles.iter().enumerate() {
            for &index in t {
                if index as usize >= count {
                    return Err(MeshError::IndexOutOfRange {
                        triangle,
                        index,
                        count,
                    });
                }
            }
        }
        if self.tri_group.len() != self.triangles.len()
            || self
                .tri_group
                .iter()
                .any(|&g| g as usize >= self.groups.len())
        {
            return Err(MeshError::Invalid(
                "triangle group table does not match the triangles".into(),
            ));
        }
        Ok(())
    }

    /// Axis-aligned bounding box `(min, max)` (infinite for an empty mesh).
    pub fn bbox(&self) -> ([f64; 3], [f64; 3]) {
        crate::vec3::bounds(&self.positions).unwrap_or(([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]))
    }

    /// Length of the bounding-box diagonal.
    pub fn diagonal(&self) -> f64 {
        let (lo, hi) = self.bbox();
        ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2) + (hi[2] - lo[2]).powi(2)).sqrt()
    }

    /// The three corners of triangle `t`.
    pub fn corners(&self, t: usize) -> [[f64; 3]; 3] {
        let [a, b, c] = self.triangles[t];
        [
            self.positions[a as usize],
            self.positions[b as usize],
            self.positions[c as usize],
        ]
    }

    /// Unnormalised face normal (twice the area times the unit normal).
    pub fn face_normal_area(&self, t: usize) -> [f64; 3] {
        let [a, b, c] = self.corners(t);
        crate::vec3::cross(sub(b, a), sub(c, a))
    }

    /// Area-weighted unit vertex normals (zero for isolated vertices).
    pub fn vertex_normals(&self) -> Vec<[f64; 3]> {
        let mut n = vec![[0.0; 3]; self.positions.len()];
        for (t, tri) in self.triangles.iter().enumerate() {
            let f = self.face_normal_area(t);
            for &i in tri {
                for k in 0..3 {
                    n[i as usize][k] += f[k];
                }
            }
        }
        n.into_iter().map(crate::vec3::normalize).collect()
    }

    /// Total surface area.
    pub fn area(&self) -> f64 {
        (0..self.triangles.len())
            .map(|t| norm(self.face_normal_area(t)) * 0.5)
            .sum()
    }

    /// Signed enclosed volume (divergence theorem; meaningful when closed).
    pub fn signed_volume(&self) -> f64 {
        (0..self.triangles.len())
            .map(|t| {
                let [a, b, c] = self.corners(t);
                dot(a, crate::vec3::cross(b, c)) / 6.0
            })
            .sum()
    }

    /// The triangles of group `name` with only the vertices they use
    /// (`None` when no such group). The second value maps each new vertex to
    /// its index in `self`.
    pub fn group_submesh(&self, name: &str) -> Option<(Mesh, Vec<u32>)> {
        let g = self.groups.iter().position(|x| x == name)? as u32;
        let keep: Vec<bool> = self.tri_group.iter().map(|&x| x == g).collect();
        let (mut m, map) = self.filter_triangles(&keep);
        m.set_single_group(name);
        Some((m, map))
    }

    /// The triangles with `keep[t]`, compacted, with the new-to-old vertex map.
    pub fn filter_triangles(&self, keep: &[bool]) -> (Mesh, Vec<u32>) {
        let mut new_index = vec![u32::MAX; self.positions.len()];
        let mut old_index = Vec::new();
        let mut out = Mesh {
            groups: self.groups.clone(),
            ..Mesh::default()
        };
        for (t, tri) in self.triangles.iter().enumerate() {
            if !keep[t] {
                continue;
            }
            let mut nt = [0u32; 3];
            for (k, &i) in tri.iter().enumerate() {
                if new_index[i as usize] == u32::MAX {
                    new_index[i as usize] = old_index.len() as u32;
                    old_index.push(i);
                    out.positions.push(self.positions[i as usize]);
                }
                nt[k] = new_index[i as usize];
            }
            out.triangles.push(nt);
            out.tri_group.push(self.tri_group[t]);
        }
        (out, old_index)
    }

    /// Applies `f` to every position.
    pub fn map_positions(&mut self, mut f: impl FnMut([f64; 3]) -> [f64; 3]) {
        for p in &mut self.positions {
            *p = f(*p);
        }
    }
}

pub use crate::vec3::{add, dist, dot, norm, scale, sub};

#[cfg(test)]
mod tests {
    use super::Mesh;

    #[test]
    fn grid_with_too_few_rows_has_no_triangles() {
        // an open direction needs two rows of points for one row of cells;
        // fewer (or no points at all) is an empty mesh, not an underflow
        let p = vec![[0.0, 0.0, 0.0]];
        assert!(Mesh::grid(Vec::new(), 0, 0, [false, false])
            .triangles
            .is_empty());
        assert!(Mesh::grid(Vec::new(), 0, 0, [true, true])
            .triangles
            .is_empty());
        assert!(Mesh::grid(p.clone(), 1, 1, [false, false])
            .triangles
            .is_empty());
        assert!(Mesh::grid(p, 1, 1, [true, false]).triangles.is_empty());
        let square = vec![[0.0; 3], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
        assert_eq!(Mesh::grid(square, 2, 2, [false, false]).triangles.len(), 2);
    }
}
