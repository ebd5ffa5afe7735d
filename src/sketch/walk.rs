//! Prefix sums along an open walk of an outline, shared by the hand's
//! mitten (`limb`: notches closed) and the thumb (`thumb`: a protrusion
//! cut off).

use super::poly::dist;

/// Prefix sums along an open walk (part of a closed outline), so that a
/// bridge between two of its points is judged in O(1) but for its
/// crossings: the walk's length between them and the signed area of the
/// loop the walk and the bridge make, from the walk's first point.
pub struct WalkSums<'a> {
    walk: &'a [[f64; 2]],
    cum: Vec<f64>,
    twice_area: Vec<f64>,
    /// +1 when the outline's material lies left of the walk, else -1.
    material: f64,
}

impl<'a> WalkSums<'a> {
    pub fn new(walk: &'a [[f64; 2]], inside_left: bool) -> Self {
        let m = walk.len();
        let (mut cum, mut twice_area) = (vec![0.0; m], vec![0.0; m]);
        let mut sums = WalkSums {
            walk,
            cum: Vec::new(),
            twice_area: Vec::new(),
            material: if inside_left { 1.0 } else { -1.0 },
        };
        for k in 1..m {
            cum[k] = cum[k - 1] + dist(walk[k - 1], walk[k]);
            twice_area[k] = twice_area[k - 1] + sums.cross(k - 1, k);
        }
        sums.cum = cum;
        sums.twice_area = twice_area;
        sums
    }

    fn cross(&self, a: usize, b: usize) -> f64 {
        let (o, p, q) = (self.walk[0], self.walk[a], self.walk[b]);
        (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
    }

    /// The walk's length from point `i` to point `j`.
    pub fn run(&self, i: usize, j: usize) -> f64 {
        self.cum[j] - self.cum[i]
    }

    /// Twice the signed area of the loop (walk from `i` to `j`, bridge
    /// back), positive when it encloses the outline's material (a
    /// protrusion), negative when a gap (a notch).
    pub fn material_area(&self, i: usize, j: usize) -> f64 {
        self.material * (self.twice_area[j] - self.twice_area[i] + self.cross(j, i))
    }

    /// Whether the bridge from `i` to `j` crosses no edge of the walk
    /// between them.
    pub fn clear(&self, i: usize, j: usize) -> bool {
        let w = self.walk;
        (i + 1..j.saturating_sub(1))
            .all(|k| !crate::polygon::segments_cross(w[i], w[j], w[k], w[k + 1]))
    }
}
