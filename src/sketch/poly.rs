//! Outline queries used by the segmentation: horizontal slices of a simple
//! closed polygon and the tops of the gaps between its limbs.

/// The inside intervals `[x0, x1]` of the horizontal line at height `y`,
/// sorted by x (even-odd rule; the polygon is simple, closure implied).
pub fn slice(points: &[[f64; 2]], y: f64) -> Vec<[f64; 2]> {
    let n = points.len();
    let mut xs = Vec::new();
    for i in 0..n {
        let a = points[i];
        let b = points[(i + 1) % n];
        // half-open rule: count an edge when y is in [min, max)
        let (lo, hi) = if a[1] < b[1] { (a, b) } else { (b, a) };
        if y >= lo[1] && y < hi[1] {
            let t = (y - lo[1]) / (hi[1] - lo[1]);
            xs.push(lo[0] + t * (hi[0] - lo[0]));
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.chunks_exact(2).map(|c| [c[0], c[1]]).collect()
}

/// A gap between two limbs closing at its top: the point where, going up,
/// two consecutive slice intervals merge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GapTop {
    pub x: f64,
    pub y: f64,
}

/// The tops of all gaps, found on `n` slices and refined by bisection.
pub fn gap_tops(points: &[[f64; 2]], n: usize) -> Vec<GapTop> {
    let yr = crate::polygon::span(points, 1);
    let h = yr[1] - yr[0];
    let ys: Vec<f64> = (0..n)
        .map(|k| yr[0] + h * (k as f64 + 0.5) / n as f64)
        .collect();
    let mut out = Vec::new();
    for k in 0..n - 1 {
        let lo = slice(points, ys[k]);
        let hi = slice(points, ys[k + 1]);
        for w in lo.windows(2) {
            let gx = 0.5 * (w[0][1] + w[1][0]);
            // the gap is closed above when one interval of `hi` covers gx
            if hi.iter().any(|iv| iv[0] <= gx && gx <= iv[1]) {
                let (mut a, mut b) = (ys[k], ys[k + 1]);
                for _ in 0..40 {
                    let m = 0.5 * (a + b);
                    if slice(points, m).iter().any(|iv| iv[0] <= gx && gx <= iv[1]) {
                        b = m;
                    } else {
                        a = m;
                    }
                }
                out.push(GapTop { x: gx, y: a });
            }
        }
    }
    out
}

/// The top of the outline above `x` (largest y inside), if any.
pub fn top_at(points: &[[f64; 2]], x: f64) -> Option<f64> {
    let n = points.len();
    let mut best: Option<f64> = None;
    for i in 0..n {
        let a = points[i];
        let b = points[(i + 1) % n];
        let (lo, hi) = if a[0] < b[0] { (a, b) } else { (b, a) };
        if x >= lo[0] && x < hi[0] {
            let t = (x - lo[0]) / (hi[0] - lo[0]);
            let y = lo[1] + t * (hi[1] - lo[1]);
            best = Some(best.map_or(y, |v: f64| v.max(y)));
        }
    }
    best
}
