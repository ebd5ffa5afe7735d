//! Where the largest errors of a closed body sit: the sample of the
//! reconstruction farthest from the skin and the skin vertex farthest from
//! the reconstruction, each named by the part or transition (the mesh group
//! of its triangle), the nearest key section of that part, its height above
//! the sole (relative to the body height) and the point itself.

use super::layout::Layout;
use crate::character::doc::PartSpec;
use crate::mesh::metrics::TriangleBvh;
use crate::mesh::{dist, Mesh};

/// One located error.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ErrorSite {
    /// Distance relative to the body height.
    pub distance_rel: f64,
    /// The sample (on the reconstruction for recon->skin, a skin vertex for
    /// skin->recon).
    pub point: [f64; 3],
    /// Its closest point on the other mesh.
    pub closest: [f64; 3],
    /// The part or transition of the reconstruction there (its group).
    pub group: String,
    /// Index of the nearest key section of that part (by section centre);
    /// `None` on a transition.
    pub section: Option<usize>,
    /// Height of `point` above the sole, relative to the body height.
    pub height_rel: f64,
}

/// A sample's closest point on the other mesh, its distance and the
/// closest triangle (as [`TriangleBvh::closest`]).
pub type Hit = Option<([f64; 3], f64, usize)>;

/// The closest point on `to` of every one of `points` (one BVH).
pub fn closest_hits(points: &[[f64; 3]], to: &Mesh) -> Vec<Hit> {
    let bvh = TriangleBvh::new(to);
    points.iter().map(|&p| bvh.closest(p)).collect()
}

/// The distances of `hits` (infinite where `to` had no triangle), as
/// [`crate::mesh::metrics::point_distances`] gives them.
pub fn hit_distances(hits: &[Hit]) -> Vec<f64> {
    hits.iter()
        .map(|c| c.map_or(f64::INFINITY, |c| c.1))
        .collect()
}

/// Index of the first farthest hit.
fn farthest(hits: &[Hit]) -> Option<usize> {
    let mut best: Option<(usize, f64)> = None;
    for (i, h) in hits.iter().enumerate() {
        if let Some((_, d, _)) = *h {
            if best.is_none_or(|b| d > b.1) {
                best = Some((i, d));
            }
        }
    }
    best.map(|b| b.0)
}

/// The name of triangle `t`'s group (empty when the mesh has none).
pub fn group_of(m: &Mesh, t: usize) -> String {
    let g = m.tri_group.get(t).copied().unwrap_or(0) as usize;
    m.groups.get(g).cloned().unwrap_or_default()
}

fn site(
    group: String,
    point: [f64; 3],
    closest: [f64; 3],
    d: f64,
    specs: &[PartSpec],
    sole: f64,
    h: f64,
) -> ErrorSite {
    let section = specs.iter().find(|p| p.name == group).and_then(|p| {
        p.sections
            .iter()
            .enumerate()
            .min_by(|a, b| dist(a.1.centre, point).total_cmp(&dist(b.1.centre, point)))
            .map(|(i, _)| i)
    });
    ErrorSite {
        distance_rel: d / h,
        point,
        closest,
        group,
        section,
        height_rel: (point[1] - sole) / h,
    }
}

/// (recon -> skin, skin -> recon) maxima of `recon` against the skin, from
/// the hits already measured: `r2s` of `r2s_points` (the recon's vertices,
/// then its triangle centroids, [`crate::mesh::metrics::sample_points`]) on
/// the skin, `s2r` of the skin vertices on `recon`; heights from `lay`.
pub fn error_sites(
    recon: &Mesh,
    r2s_points: &[[f64; 3]],
    r2s: &[Hit],
    s2r: &[Hit],
    skin: &Mesh,
    specs: &[PartSpec],
    lay: &Layout,
) -> (Option<ErrorSite>, Option<ErrorSite>) {
    let (sole, h) = (lay.sole, lay.height());
    let r2s_at = farthest(r2s).and_then(|i| {
        let (q, d, _) = r2s[i]?;
        // a vertex sample: the first triangle using it; a centroid: its own
        let t = if i < recon.positions.len() {
            recon
                .triangles
                .iter()
                .position(|tr| tr.contains(&(i as u32)))
                .unwrap_or(0)
        } else {
            i - recon.positions.len()
        };
        Some(site(
            group_of(recon, t),
            r2s_points[i],
            q,
            d,
            specs,
            sole,
            h,
        ))
    });
    let s2r_at = farthest(s2r).and_then(|i| {
        let (q, d, t) = s2r[i]?;
        Some(site(
            group_of(recon, t),
            skin.positions[i],
            q,
            d,
            specs,
            sole,
            h,
        ))
    });
    (r2s_at, s2r_at)
}

impl ErrorSite {
    /// One line: `1.234 % at torso section 5 (height 0.512) (x, y, z)`.
    pub fn line(&self) -> String {
        let sec = self
            .section
            .map_or(String::new(), |s| format!(" section {s}"));
        format!(
            "{:.3} % at {}{} (height {:.3} of the body) ({:.3}, {:.3}, {:.3})",
            100.0 * self.distance_rel,
            self.group,
            sec,
            self.height_rel,
            self.point[0],
            self.point[1],
            self.point[2]
        )
    }
}
