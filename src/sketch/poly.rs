//! Outline queries used by the segmentation: horizontal slices of a simple
//! closed polygon and the tops of the gaps between its limbs.

use super::SketchError;

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

/// Vertical extent `(ymin, ymax)` and horizontal `(xmin, xmax)`.
pub fn bounds(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let mut x = [f64::INFINITY, f64::NEG_INFINITY];
    let mut y = [f64::INFINITY, f64::NEG_INFINITY];
    for p in points {
        x = [x[0].min(p[0]), x[1].max(p[0])];
        y = [y[0].min(p[1]), y[1].max(p[1])];
    }
    (y, x)
}

/// Twice the signed area (positive: counter-clockwise).
pub fn signed_area2(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum()
}

fn cross(o: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// Whether segments `ab` and `cd` properly intersect or touch.
pub fn segments_intersect(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let d1 = cross(c, d, a);
    let d2 = cross(c, d, b);
    let d3 = cross(a, b, c);
    let d4 = cross(a, b, d);
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let on = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        cross(p, q, r) == 0.0
            && r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    on(c, d, a) || on(c, d, b) || on(a, b, c) || on(a, b, d)
}

/// Validates a closed outline (finite, at least 3 distinct points, simple)
/// and returns it counter-clockwise without a closing copy of the first
/// point.
pub fn validate_outline(what: &str, pts: &[[f64; 2]]) -> Result<Vec<[f64; 2]>, SketchError> {
    let mut p: Vec<[f64; 2]> = Vec::with_capacity(pts.len());
    for (i, q) in pts.iter().enumerate() {
        if !(q[0].is_finite() && q[1].is_finite()) {
            return Err(SketchError::Outline {
                what: what.into(),
                message: format!("point {i} is not finite"),
            });
        }
        if p.last() != Some(q) {
            p.push(*q);
        }
    }
    if p.len() > 1 && p.first() == p.last() {
        p.pop();
    }
    if p.len() < 3 {
        return Err(SketchError::Outline {
            what: what.into(),
            message: format!("needs at least 3 distinct points, got {}", p.len()),
        });
    }
    let n = p.len();
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            if segments_intersect(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]) {
                return Err(SketchError::Outline {
                    what: what.into(),
                    message: format!("self-intersecting: edge {i} crosses edge {j}"),
                });
            }
        }
    }
    let a = signed_area2(&p);
    if a.abs() <= 1e-12 * bounds_diag(&p).powi(2) {
        return Err(SketchError::Outline {
            what: what.into(),
            message: "zero area".into(),
        });
    }
    if a < 0.0 {
        p.reverse();
    }
    Ok(p)
}

fn bounds_diag(p: &[[f64; 2]]) -> f64 {
    let (y, x) = bounds(p);
    (y[1] - y[0]).hypot(x[1] - x[0])
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
    let (yr, _) = bounds(points);
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
