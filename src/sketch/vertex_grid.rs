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
        let c = Self::cell_of(self.o, self.h, self.n, q);
        let mut best: Option<(f64, usize)> = None;
        for r in 0..self.n[0].max(self.n[1]) {
            let (x0, x1) = (c[0].saturating_sub(r), (c[0] + r).min(self.n[0] - 1));
            let (y0, y1) = (c[1].saturating_sub(r), (c[1] + r).min(self.n[1] - 1));
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let ring = x == x0 || x == x1 || y == y0 || y == y1;
                    if !ring {
                        continue;
                    }
                    for &i in &self.cells[y * self.n[0] + x] {
                        let p = self.pts[i as usize];
                        let d = (p[0] - q[0]).hypot(p[1] - q[1]);
                        if best.is_none_or(|b| d < b.0) {
                            best = Some((d, i as usize));
                        }
                    }
                }
            }
            // every point within r * h of q has been seen
            if let Some((d, _)) = best {
                if d <= r as f64 * self.h {
                    break;
                }
            }
        }
        best.map(|b| b.1)
    }

    /// Distance to the nearest point; infinite when the grid is empty.
    pub(crate) fn distance(&self, q: [f64; 2]) -> f64 {
        self.nearest(q).map_or(f64::INFINITY, |i| {
            let p = self.pts[i];
            (p[0] - q[0]).hypot(p[1] - q[1])
        })
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
                .map(|p| (p[0] - q[0]).hypot(p[1] - q[1]))
                .fold(f64::INFINITY, f64::min);
            assert_eq!(g.distance(q), brute, "query {q:?}");
        }
        assert_eq!(
            VertexGrid::new(Vec::new()).distance([0.0, 0.0]),
            f64::INFINITY
        );
    }
}
