//! Distance between profiles: symmetric, sampled densely by arc length,
//! exact point-to-segment distances accelerated by a segment grid.

use super::grid::{Segment, SegmentGrid};
use super::Profile;
use serde::Serialize;

/// Fewest arc-length samples per profile in [`profile_distance`].
pub const MIN_SAMPLES: usize = 4000;
/// Arc-length samples per profile vertex in [`profile_distance`].
pub const SAMPLES_PER_VERTEX: usize = 4;
/// Most arc-length samples per profile in [`profile_distance`].
pub const MAX_SAMPLES: usize = 400_000;

/// A profile's edges in a grid, for many distance queries.
#[derive(Clone, Debug)]
pub struct ProfileIndex {
    grid: SegmentGrid,
}

impl ProfileIndex {
    /// Indexes the edges of `p` (near-linear time).
    pub fn new(p: &Profile) -> ProfileIndex {
        let segs: Vec<Segment> = (0..p.len()).map(|i| p.edge(i)).collect();
        ProfileIndex {
            grid: SegmentGrid::new(segs),
        }
    }

    /// Distance from `q` to the boundary.
    pub fn distance(&self, q: [f64; 2]) -> f64 {
        self.nearest(q).0
    }

    /// Nearest boundary point: (distance, edge index, parameter t in [0, 1]
    /// along the edge, the point).
    pub fn nearest(&self, q: [f64; 2]) -> (f64, usize, f64, [f64; 2]) {
        match self.grid.nearest(q) {
            Some((d, e, t)) => {
                let [a, b] = self.grid.segs[e];
                (
                    d,
                    e,
                    t,
                    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])],
                )
            }
            None => (f64::INFINITY, 0, 0.0, q),
        }
    }
}

/// Distance between two profiles. `max` is the symmetric Hausdorff
/// distance of the sampled boundaries, `rms` the root mean square over all
/// arc-length samples of both; `*_rel` divide by the reference's
/// (`b`'s) height.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ProfileDistance {
    pub max: f64,
    pub rms: f64,
    pub max_rel: f64,
    pub rms_rel: f64,
}

/// Symmetric distance between the boundaries of `a` and `b` (`b` is the
/// reference, e.g. the sketch). Each boundary is sampled at
/// `clamp(SAMPLES_PER_VERTEX * (na + nb), MIN_SAMPLES, MAX_SAMPLES)` points
/// equally spaced by arc length; the exact distance of every sample to the
/// other boundary enters the RMS; the maximum is taken over those samples
/// and every vertex of both (so corners are not missed). The views are not
/// compared: the caller decides which profiles are comparable.
pub fn profile_distance(a: &Profile, b: &Profile) -> ProfileDistance {
    let n = (SAMPLES_PER_VERTEX * (a.len() + b.len())).clamp(MIN_SAMPLES, MAX_SAMPLES);
    let (ia, ib) = (ProfileIndex::new(a), ProfileIndex::new(b));
    let mut max: f64 = 0.0;
    let mut sum2 = 0.0;
    for (from, to) in [(a, &ib), (b, &ia)] {
        for q in from.resample_arclength(n) {
            let d = to.distance(q);
            sum2 += d * d;
            max = max.max(d);
        }
        for &q in from.points() {
            max = max.max(to.distance(q));
        }
    }
    let rms = (sum2 / (2 * n) as f64).sqrt();
    let h = b.height();
    ProfileDistance {
        max,
        rms,
        max_rel: max / h,
        rms_rel: rms / h,
    }
}
