//! Where the largest errors of a closed body sit: the sample of the
//! reconstruction farthest from the skin and the skin vertex farthest from
//! the reconstruction, each named by the part or transition (the mesh group
//! of its triangle), the nearest key section of that part, its height above
//! the sole (relative to the body height) and the point itself.

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

/// (sample index, point, closest point, closest triangle, distance).
type Farthest = (usize, [f64; 3], [f64; 3], usize, f64);

/// The farthest sample of `from` (vertices, then triangle centroids when
/// `centroids`) from `to`: (sample index, point, closest point on `to`,
/// closest triangle of `to`, distance).
fn farthest(from: &Mesh, to: &Mesh, centroids: bool) -> Option<Farthest> {
    let bvh = TriangleBvh::new(to);
    let mut pts = from.positions.clone();
    if centroids {
        pts.extend((0..from.triangles.len()).map(|t| {
            let [a, b, c] = from.corners(t);
            std::array::from_fn(|k| (a[k] + b[k] + c[k]) / 3.0)
        }));
    }
    let mut best: Option<Farthest> = None;
    for (i, p) in pts.into_iter().enumerate() {
        if let Some((q, d, t)) = bvh.closest(p) {
            if best.as_ref().is_none_or(|b| d > b.4) {
                best = Some((i, p, q, t, d));
            }
        }
    }
    best
}

fn group_of(m: &Mesh, t: usize) -> String {
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

/// (recon -> skin, skin -> recon) maxima of `recon` against `skin`; `sole`
/// and `h` the layout's sole height and body height.
pub fn error_sites(
    recon: &Mesh,
    skin: &Mesh,
    specs: &[PartSpec],
    sole: f64,
    h: f64,
) -> (Option<ErrorSite>, Option<ErrorSite>) {
    let r2s = farthest(recon, skin, true).map(|(i, p, q, _, d)| {
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
        site(group_of(recon, t), p, q, d, specs, sole, h)
    });
    let s2r = farthest(skin, recon, false)
        .map(|(_, p, q, t, d)| site(group_of(recon, t), p, q, d, specs, sole, h));
    (r2s, s2r)
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
