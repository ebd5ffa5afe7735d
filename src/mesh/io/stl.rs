//! STL: binary write; binary and ASCII read (vertices merged by exact
//! position).

use crate::mesh::{Mesh, MeshError};
use std::collections::HashMap;

/// Encodes binary STL (80-byte header, facet normals from the triangles).
pub fn encode_stl(m: &Mesh) -> Vec<u8> {
    let mut out = Vec::with_capacity(84 + 50 * m.triangles.len());
    let mut header = [0u8; 80];
    let text = b"pdesculpt binary STL";
    header[..text.len()].copy_from_slice(text);
    out.extend_from_slice(&header);
    out.extend_from_slice(&(m.triangles.len() as u32).to_le_bytes());
    for t in 0..m.triangles.len() {
        let n = crate::vec3::normalize(m.face_normal_area(t));
        for x in n {
            out.extend_from_slice(&(x as f32).to_le_bytes());
        }
        for p in m.corners(t) {
            for x in p {
                out.extend_from_slice(&(x as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&[0, 0]);
    }
    out
}

struct Welder {
    mesh: Mesh,
    map: HashMap<[u64; 3], u32>,
}

impl Welder {
    fn vertex(&mut self, p: [f64; 3]) -> u32 {
        let key = [p[0].to_bits(), p[1].to_bits(), p[2].to_bits()];
        *self.map.entry(key).or_insert_with(|| {
            self.mesh.positions.push(p);
            (self.mesh.positions.len() - 1) as u32
        })
    }
    fn triangle(&mut self, c: [[f64; 3]; 3]) {
        let t = [self.vertex(c[0]), self.vertex(c[1]), self.vertex(c[2])];
        self.mesh.triangles.push(t);
        self.mesh.tri_group.push(0);
    }
}

/// Parses binary or ASCII STL.
pub fn parse_stl(bytes: &[u8], path: &str) -> Result<Mesh, MeshError> {
    let mut w = Welder {
        mesh: Mesh::new(Vec::new(), Vec::new()),
        map: HashMap::new(),
    };
    let perr = |line: usize, message: String| MeshError::Parse {
        path: path.to_string(),
        line,
        message,
    };
    let is_binary = bytes.len() >= 84 && {
        let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        84 + 50 * n == bytes.len()
    };
    if is_binary {
        let n = (bytes.len() - 84) / 50;
        for t in 0..n {
            let base = 84 + 50 * t + 12;
            let mut c = [[0.0; 3]; 3];
            for (k, corner) in c.iter_mut().enumerate() {
                for (j, x) in corner.iter_mut().enumerate() {
                    let o = base + 12 * k + 4 * j;
                    *x = f32::from_le_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]])
                        as f64;
                    if !x.is_finite() {
                        return Err(MeshError::ParseAt {
                            path: path.to_string(),
                            offset: o,
                            message: format!("triangle {t}: non-finite coordinate {x}"),
                        });
                    }
                }
            }
            w.triangle(c);
        }
    } else {
        let text = std::str::from_utf8(bytes)
            .map_err(|_| perr(0, "neither binary STL (size mismatch) nor ASCII STL".into()))?;
        if !text.trim_start().starts_with("solid") {
            return Err(perr(1, "ASCII STL must start with 'solid'".into()));
        }
        let mut corners = Vec::with_capacity(3);
        for (ln, line) in text.lines().enumerate() {
            let mut it = line.split_whitespace();
            if it.next() == Some("vertex") {
                let mut p = [0.0; 3];
                for x in p.iter_mut() {
                    let s = it
                        .next()
                        .ok_or_else(|| perr(ln + 1, "vertex needs 3 coordinates".into()))?;
                    *x = s
                        .parse::<f64>()
                        .ok()
                        .filter(|v| v.is_finite())
                        .ok_or_else(|| perr(ln + 1, format!("bad coordinate {s:?}")))?;
                }
                corners.push(p);
                if corners.len() == 3 {
                    w.triangle([corners[0], corners[1], corners[2]]);
                    corners.clear();
                }
            }
        }
        if !corners.is_empty() {
            return Err(perr(
                text.lines().count(),
                format!(
                    "the file ends inside a facet ({} of 3 vertices)",
                    corners.len()
                ),
            ));
        }
    }
    Ok(w.mesh)
}
