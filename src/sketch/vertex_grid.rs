//! Nearest-point queries on projected points (a model's vertices in one
//! view): a uniform grid of about one point per cell, searched in rings of
//! cells until the nearest is proven. Shared by the quality report
//! ([`super::quality`]) and the tangent fit ([`super::tangent_fit`]).

/// Points in a uniform grid of square cells sized to their count.
pub(crate) struct VertexGrid {
    o: [f64; 2],
    h: f64,
    n: [usize; 2],
    cells: Vec<Vec<u32>>,
    pts: Vec<[f64; 2]>,
}

impl VertexGrid {
    pub(crate) fn new(pts: Vec<[f64; 2]>) -> VertexGrid {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &pts {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let ext = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE);
        let side = ((pts.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let h = ext / side as f64;
        let n = [
            (((hi[0] - lo[0]) / h) as usize + 1).min(4096),
            (((hi[1] - lo[1]) / h) as usize + 1).min(4096),
        ];
        let mut cells = vec![Vec::new(); n[0] * n[1]];
        for (i, p) in pts.iter().enumerate() {
            let c = Self::cell_of(lo, h, n, *p);
            cells[c[1] * n[0] + c[0]].push(i as u32);
        }
        VertexGrid {
            o: lo,
            h,
            n,
            cells,
            pts,
        }
    }

    fn cell_of(o: [f64; 2], h: f64, n: [usize; 2], p: [f64; 2]) -> [usize; 2] {
        let f = |k: usize| (((p[k] - o[k]) / h).max(0.0) as usize).min(n[k] - 1);
        [f(0), f(1)]
    }

    /// Index of the nearest point (rings of cells until the best is
    /// proven); `None` when the grid is empty.
    pub(crate) fn nearest(&self, q: [f64; 2]) -> Option<usize> {
        self.search(q, 0.0, f64::INFINITY).map(|b| b.1)
    }

    /// The nearest distance `d` clamped for a caller that keeps only
    /// `max(floor, min(d, cap))`: `d` itself between `floor` and `cap`, at
    /// most `floor` when `d <= floor` (the search stops at the first point
    /// that close), `cap` when `d >= cap` (it stops once every point
    /// within `cap` is proven absent). Exact for that use, and cheaper:
    /// a drawn sample far from a transition's points but near another
    /// part (`cap`), or already beaten (`floor`), ends in a ring or two.
    pub(crate) fn distance_within(&self, q: [f64; 2], floor: f64, cap: f64) -> f64 {
        self.search(q, floor, cap)
            .map_or(cap, |b| b.0.sqrt().min(cap))
    }

    /// The nearest point as (squared distance, index), searched ring by
    /// ring of cells around `q`'s cell; stops once a point within `floor`
    /// is found, or once every point within the best distance found (or
    /// within `cap`) has been seen. `None`: no point within `cap`.
    fn search(&self, q: [f64; 2], floor: f64, cap: f64) -> Option<(f64, usize)> {
        let c = Self::cell_of(self.o, self.h, self.n, q);
        let (floor2, cap2) = (floor * floor, cap * cap);
        let mut best: Option<(f64, usize)> = None;
        let visit = |x: usize, y: usize, best: &mut Option<(f64, usize)>| {
            for &i in &self.cells[y * self.n[0] + x] {
                let p = self.pts[i as usize];
                let d2 = (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2);
                if best.is_none_or(|b| d2 < b.0) {
                    *best = Some((d2, i as usize));
                }
            }
        };
        for r in 0..self.n[0].max(self.n[1]) {
            let (x0, x1) = (c[0].saturating_sub(r), (c[0] + r).min(self.n[0] - 1));
            let (y0, y1) = (c[1].saturating_sub(r), (c[1] + r).min(self.n[1] - 1));
            // the cells of ring r only: whole rows r away from q's cell,
            // the two columns r away on the rows between
            for y in y0..=y1 {
                if y.abs_diff(c[1]) == r {
                    (x0..=x1).for_each(|x| visit(x, y, &mut best));
                } else {
                    // (x0 == x1 only when both are q's column, never r away)
                    for x in [x0, x1] {
                        if x.abs_diff(c[0]) == r {
                            visit(x, y, &mut best);
                        }
                    }
                }
            }
            if best.is_some_and(|b| b.0 <= floor2) {
                break;
            }
            // every point within r h of q has been seen
            let seen = (r as f64 * self.h).powi(2);
            if best.is_some_and(|b| b.0 <= seen) || seen >= cap2 {
                break;
            }
            if x0 == 0 && y0 == 0 && x1 == self.n[0] - 1 && y1 == self.n[1] - 1 {
                break;
            }
        }
        best.filter(|b| b.0 < cap2 || cap2.is_infinite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_is_the_brute_force_nearest_inside_and_outside_the_points() {
        // a deterministic scatter (a low-discrepancy walk); queries reach
        // past the points' box on every side
        let pts: Vec<[f64; 2]> = (0..500)
            .map(|i| {
                let t = i as f64;
                [
                    (t * 0.618_033_99).fract() * 3.0 - 1.0,
                    (t * 0.414_213_56).fract() * 2.0,
                ]
            })
            .collect();
        let g = VertexGrid::new(pts.clone());
        for k in 0..200 {
            let t = k as f64;
            let q = [
                (t * 0.732_050_8).fract() * 7.0 - 3.0,
                (t * 0.236_068).fract() * 6.0 - 2.0,
            ];
            let brute = pts
                .iter()
                .map(|p| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt())
                .fold(f64::INFINITY, f64::min);
            assert_eq!(
                g.distance_within(q, 0.0, f64::INFINITY),
                brute,
                "query {q:?}"
            );
            // clamped as a running maximum of capped distances uses it
            for (floor, cap) in [(0.0, 0.05), (0.3, 1.0), (brute, 2.0 * brute), (0.0, brute)] {
                let got = g.distance_within(q, floor, cap);
                let want = brute.min(cap);
                assert_eq!(
                    got.max(floor),
                    want.max(floor),
                    "query {q:?} in [{floor}, {cap}]"
                );
            }
        }
        assert_eq!(
            VertexGrid::new(Vec::new()).distance_within([0.0, 0.0], 0.0, f64::INFINITY),
            f64::INFINITY
        );
    }
}
