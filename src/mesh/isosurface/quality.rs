//! Triangle quality statistics of a polygonised mesh.

use super::*;

/// Triangle shape statistics.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct TriangleQuality {
    pub triangles: usize,
    /// Smallest interior angle over all triangles (degrees).
    pub min_angle_deg: f64,
    /// Mean of the per-triangle smallest angle (degrees).
    pub mean_min_angle_deg: f64,
    /// Fraction of triangles whose smallest angle is below 10 degrees.
    pub frac_below_10deg: f64,
    /// Mean aspect ratio $\ell_{max}(a+b+c)/(4\sqrt3 A)$ (1 for an
    /// equilateral triangle; degenerate triangles excluded).
    pub mean_aspect: f64,
    /// Largest finite aspect ratio.
    pub max_aspect: f64,
    /// Triangles of zero area (aspect ratio infinite).
    pub degenerate: usize,
}

/// Angle statistics of `m`.
pub fn triangle_quality(m: &Mesh) -> TriangleQuality {
    let mut q = TriangleQuality {
        triangles: m.triangles.len(),
        min_angle_deg: 180.0,
        ..Default::default()
    };
    let mut below = 0usize;
    for t in &m.triangles {
        let p = t.map(|i| m.positions[i as usize]);
        let mn = smallest_angle_deg(p);
        q.min_angle_deg = q.min_angle_deg.min(mn);
        q.mean_min_angle_deg += mn;
        let l = [0, 1, 2].map(|c| {
            let (a, b) = (p[c], p[(c + 1) % 3]);
            crate::vec3::norm([b[0] - a[0], b[1] - a[1], b[2] - a[2]])
        });
        let e1 = [p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]];
        let e2 = [p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]];
        let area = 0.5
            * crate::vec3::norm([
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ]);
        let lmax = l[0].max(l[1]).max(l[2]);
        if area > 1e-14 * lmax * lmax && area > 0.0 {
            let ar = lmax * (l[0] + l[1] + l[2]) / (4.0 * 3f64.sqrt() * area);
            q.mean_aspect += ar;
            q.max_aspect = q.max_aspect.max(ar);
        } else {
            q.degenerate += 1;
        }
        if mn < 10.0 {
            below += 1;
        }
    }
    if q.triangles > 0 {
        q.mean_min_angle_deg /= q.triangles as f64;
        q.frac_below_10deg = below as f64 / q.triangles as f64;
        let good = q.triangles - q.degenerate;
        if good > 0 {
            q.mean_aspect /= good as f64;
        }
    } else {
        q.min_angle_deg = 0.0;
    }
    q
}

/// The smallest interior angle (degrees) of every triangle of `m`, in
/// triangle order (0 for a triangle with a repeated corner).
pub fn smallest_angles_deg(m: &Mesh) -> Vec<f64> {
    m.triangles
        .iter()
        .map(|t| smallest_angle_deg(t.map(|i| m.positions[i as usize])))
        .collect()
}

/// The smallest interior angle (degrees) of the triangle `p`.
fn smallest_angle_deg(p: [[f64; 3]; 3]) -> f64 {
    let mut mn: f64 = 180.0;
    for c in 0..3 {
        let (a, b, o) = (p[(c + 1) % 3], p[(c + 2) % 3], p[c]);
        let u = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
        let v = [b[0] - o[0], b[1] - o[1], b[2] - o[2]];
        let nu = crate::vec3::norm(u);
        let nv = crate::vec3::norm(v);
        let ang = if nu > 0.0 && nv > 0.0 {
            (crate::vec3::dot(u, v) / (nu * nv))
                .clamp(-1.0, 1.0)
                .acos()
                .to_degrees()
        } else {
            0.0
        };
        mn = mn.min(ang);
    }
    mn
}
