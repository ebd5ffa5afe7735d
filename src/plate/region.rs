//! Choosing a region: the vertex indices of a region file (JSON or plain
//! text), or the vertices inside a lasso drawn in the view (paper 001 sec 5:
//! the user circles the part to deform).

use super::projection::LocalFrame;
use super::PlateError;
use crate::mesh::Mesh;
use crate::polygon::point_in_polygon as inside;

/// Region from a lasso polygon drawn in the view: the vertices facing the
/// view (`view` towards the viewer) whose projection in the frame
/// `LocalFrame::new([0,0,0], view)` lies inside `polygon`.
pub fn region_from_lasso(
    mesh: &Mesh,
    view: [f64; 3],
    polygon: &[[f64; 2]],
) -> Result<Vec<u32>, PlateError> {
    if polygon.len() < 3
        || polygon
            .iter()
            .any(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(PlateError::RegionFile(
            "lasso needs at least 3 finite points".into(),
        ));
    }
    let frame = LocalFrame::new([0.0; 3], view)?;
    let normals = mesh.vertex_normals();
    let mut out = Vec::new();
    for (i, p) in mesh.positions.iter().enumerate() {
        let l = frame.to_local(*p);
        if crate::mesh::dot(normals[i], frame.vz) > 0.0 && inside(polygon, [l[0], l[1]]) {
            out.push(i as u32);
        }
    }
    Ok(out)
}

/// A JSON region file (unknown keys refused).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RegionJson {
    #[serde(default)]
    vertices: Option<Vec<u32>>,
    #[serde(default)]
    lasso: Option<LassoJson>,
}

/// A lasso: the view direction and a polygon in the view plane.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct LassoJson {
    view: [f64; 3],
    polygon: Vec<[f64; 2]>,
}

/// Parses a region file: JSON `{"vertices": [i, ...]}` or
/// `{"lasso": {"view": [x, y, z], "polygon": [[x, y], ...]}}`, or plain text
/// vertex indices separated by whitespace or commas (`#` starts a comment).
pub fn parse_region(text: &str, mesh: &Mesh) -> Result<Vec<u32>, PlateError> {
    let t = text.trim_start();
    if t.starts_with('{') {
        let r: RegionJson = serde_json::from_str(t).map_err(PlateError::RegionJson)?;
        return match (r.vertices, r.lasso) {
            (Some(ids), None) => Ok(ids),
            (None, Some(l)) => region_from_lasso(mesh, l.view, &l.polygon),
            (Some(_), Some(_)) => Err(PlateError::RegionFile(
                "give either \"vertices\" or \"lasso\", not both".into(),
            )),
            (None, None) => Err(PlateError::RegionFile(
                "JSON region needs \"vertices\" or \"lasso\"".into(),
            )),
        };
    }
    let mut out = Vec::new();
    for line in text.lines() {
        let line = line.split('#').next().unwrap_or("");
        for tok in line.split(|c: char| c.is_whitespace() || c == ',') {
            if tok.is_empty() {
                continue;
            }
            out.push(
                tok.parse::<u32>()
                    .map_err(|_| PlateError::RegionFile(format!("not a vertex index: {tok:?}")))?,
            );
        }
    }
    Ok(out)
}
