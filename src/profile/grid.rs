//! A uniform grid over line segments: each cell lists the segments that pass
//! through it (a conservative superset). Used for nearest-segment queries,
//! so they stay near-linear in the number of segments (the self-intersection
//! test is `crate::polygon::self_intersection`'s sweep).

/// Segment `[p, q]`.
pub(crate) type Segment = [[f64; 2]; 2];

/// Most cells per segment in the grid (the grid has at most this many times
/// as many cells as segments).
const CELLS_PER_SEGMENT: f64 = 4.0;

/// Segments bucketed by the grid cells they pass through (CSR layout).
#[derive(Clone, Debug)]
pub(crate) struct SegmentGrid {
    pub segs: Vec<Segment>,
    origin: [f64; 2],
    cell: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    items: Vec<u32>,
}

impl SegmentGrid {
    /// Builds the grid; segments must be finite.
    pub fn new(segs: Vec<Segment>) -> SegmentGrid {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let mut total_len = 0.0;
        for s in &segs {
            for p in s {
                for k in 0..2 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
            total_len += len(s[0], s[1]);
        }
        let n = segs.len().max(1) as f64;
        if segs.is_empty() {
            lo = [0.0; 2];
            hi = [1.0; 2];
        }
        let w = (hi[0] - lo[0]).max(0.0);
        let h = (hi[1] - lo[1]).max(0.0);
        let extent = w.max(h).max(f64::MIN_POSITIVE);
        // Cells about twice the mean segment length, but not more than
        // CELLS_PER_SEGMENT * n of them.
        let mut cell = 2.0 * total_len / n;
        let area_cell =
            (w.max(extent * 1e-6) * h.max(extent * 1e-6) / (CELLS_PER_SEGMENT * n)).sqrt();
        cell = cell.max(area_cell).max(extent / (CELLS_PER_SEGMENT * n));
        if !(cell.is_finite() && cell > 0.0) {
            cell = 1.0;
        }
        let nx = ((w / cell).floor() as usize + 1).max(1);
        let ny = ((h / cell).floor() as usize + 1).max(1);
        let mut g = SegmentGrid {
            segs,
            origin: lo,
            cell,
            nx,
            ny,
            start: vec![0; nx * ny + 1],
            items: Vec::new(),
        };
        let mut counts = vec![0u32; nx * ny];
        for s in &g.segs {
            g.for_each_cell(s, |c| counts[c] += 1);
        }
        let mut acc = 0u32;
        for (c, k) in counts.iter().enumerate() {
            g.start[c] = acc;
            acc += k;
        }
        g.start[nx * ny] = acc;
        let mut fill: Vec<u32> = g.start[..nx * ny].to_vec();
        let mut items = vec![0u32; acc as usize];
        for (i, s) in g.segs.iter().enumerate() {
            g.for_each_cell(s, |c| {
                items[fill[c] as usize] = i as u32;
                fill[c] += 1;
            });
        }
        g.items = items;
        g
    }

    /// Segment indices listed in cell `c`.
    pub fn cell_items(&self, c: usize) -> &[u32] {
        &self.items[self.start[c] as usize..self.start[c + 1] as usize]
    }

    fn col(&self, x: f64) -> usize {
        (((x - self.origin[0]) / self.cell).floor().max(0.0) as usize).min(self.nx - 1)
    }

    fn row(&self, y: f64) -> usize {
        (((y - self.origin[1]) / self.cell).floor().max(0.0) as usize).min(self.ny - 1)
    }

    /// Calls `f` with every cell the segment passes through (a slightly
    /// widened superset, so that segments meeting on a cell border share
    /// a cell).
    fn for_each_cell(&self, s: &Segment, mut f: impl FnMut(usize)) {
        let eps = 1e-9 * self.cell;
        let [p, q] = *s;
        let (a, b) = if p[0] <= q[0] { (p, q) } else { (q, p) };
        let c0 = self.col(a[0] - eps);
        let c1 = self.col(b[0] + eps);
        let dx = b[0] - a[0];
        for c in c0..=c1 {
            let xa = (self.origin[0] + c as f64 * self.cell).max(a[0]);
            let xb = (self.origin[0] + (c + 1) as f64 * self.cell).min(b[0]);
            let (ya, yb) = if dx > 0.0 {
                let t = |x: f64| a[1] + (b[1] - a[1]) * ((x - a[0]) / dx).clamp(0.0, 1.0);
                (t(xa), t(xb))
            } else {
                (a[1], b[1])
            };
            let r0 = self.row(ya.min(yb) - eps);
            let r1 = self.row(ya.max(yb) + eps);
            for r in r0..=r1 {
                f(r * self.nx + c);
            }
        }
    }

    /// The nearest segment to `p`: (distance, segment index, parameter t in
    /// [0, 1] along it). `None` when there are no segments.
    pub fn nearest(&self, p: [f64; 2]) -> Option<(f64, usize, f64)> {
        if self.segs.is_empty() {
            return None;
        }
        let (ci, cj) = (self.col(p[0]) as isize, self.row(p[1]) as isize);
        let mut best: Option<(f64, usize, f64)> = None;
        let (nx, ny) = (self.nx as isize, self.ny as isize);
        // Rings around p's (clamped) cell until a non-empty cell is seen.
        let max_r = nx.max(ny);
        let mut r = 0isize;
        while best.is_none() && r <= max_r {
            for j in (cj - r)..=(cj + r) {
                for i in (ci - r)..=(ci + r) {
                    let ring = (i - ci).abs() == r || (j - cj).abs() == r;
                    if !ring || i < 0 || j < 0 || i >= nx || j >= ny {
                        continue;
                    }
                    self.visit(p, (j * nx + i) as usize, &mut best);
                }
            }
            r += 1;
        }
        // Then every cell within the best distance so far.
        let d = best?.0;
        let i0 = self.col(p[0] - d);
        let i1 = self.col(p[0] + d);
        let j0 = self.row(p[1] - d);
        let j1 = self.row(p[1] + d);
        for j in j0..=j1 {
            for i in i0..=i1 {
                self.visit(p, j * self.nx + i, &mut best);
            }
        }
        best
    }

    fn visit(&self, p: [f64; 2], c: usize, best: &mut Option<(f64, usize, f64)>) {
        for &s in self.cell_items(c) {
            let seg = &self.segs[s as usize];
            let (d, t) = point_segment(p, seg[0], seg[1]);
            let better = match best {
                None => true,
                Some((bd, bs, _)) => d < *bd || (d == *bd && (s as usize) < *bs),
            };
            if better {
                *best = Some((d, s as usize, t));
            }
        }
    }
}

/// Euclidean length of `q - p`.
pub(crate) fn len(p: [f64; 2], q: [f64; 2]) -> f64 {
    (q[0] - p[0]).hypot(q[1] - p[1])
}

/// Distance from `p` to segment `[a, b]` and the parameter of the nearest
/// point.
pub(crate) fn point_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> (f64, f64) {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = [a[0] + t * d[0], a[1] + t * d[1]];
    (len(p, x), t)
}
