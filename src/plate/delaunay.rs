//! Delaunay triangulation of planar points (spade), shared by the reference
//! solver and the figure shapes (below both: neither imports the other for it).

use super::PlateError;
use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};

#[derive(Clone, Copy)]
struct Site([f64; 2]);
impl HasPosition for Site {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        Point2::new(self.0[0], self.0[1])
    }
}

/// Delaunay triangles (counter-clockwise) of distinct points, indices
/// into `points`.
pub fn delaunay(points: &[[f64; 2]]) -> Result<Vec<[usize; 3]>, PlateError> {
    let mut dt = DelaunayTriangulation::<Site>::new();
    let mut handle_to_index = Vec::new();
    for (i, &p) in points.iter().enumerate() {
        let h = dt.insert(Site(p)).map_err(PlateError::Insertion)?;
        if h.index() != handle_to_index.len() {
            return Err(PlateError::DegenerateProjection(format!(
                "duplicate point {i}"
            )));
        }
        handle_to_index.push(i);
    }
    Ok(dt
        .inner_faces()
        .map(|f| f.vertices().map(|v| handle_to_index[v.fix().index()]))
        .collect())
}
