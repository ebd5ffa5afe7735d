//! Planar polygons, the 2D geometry every modeling module shares: signed
//! area, edge crossings, bounds, arc length, distances. Points are
//! `[f64; 2]`; a polygon's closing segment is implicit. Names nothing of
//! the crate (the ground, beside `vec3`).

/// Twice the signed area (positive for counter-clockwise).
pub fn signed_area2(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n)
        .map(|i| {
            let a = p[i];
            let b = p[(i + 1) % n];
            a[0] * b[1] - a[1] * b[0]
        })
        .sum()
}

fn cross(o: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

fn segments_cross(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let d1 = cross(c, d, a);
    let d2 = cross(c, d, b);
    let d3 = cross(a, b, c);
    let d4 = cross(a, b, d);
    ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
}

/// The first pair of crossing edges, sorted sweep over x (edges `i` from
/// point `i` to `i + 1`).
pub fn self_intersection(p: &[[f64; 2]]) -> Option<(usize, usize)> {
    let n = p.len();
    let mut edges: Vec<(f64, f64, usize)> = (0..n)
        .map(|i| {
            let a = p[i][0];
            let b = p[(i + 1) % n][0];
            (a.min(b), a.max(b), i)
        })
        .collect();
    edges.sort_by(|a, b| a.0.total_cmp(&b.0));
    for s in 0..n {
        let (_, hi, i) = edges[s];
        for &(lo2, _, j) in &edges[s + 1..] {
            if lo2 > hi {
                break;
            }
            let adjacent = (i + 1) % n == j || (j + 1) % n == i;
            if adjacent {
                continue;
            }
            if segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]) {
                return Some((i.min(j), i.max(j)));
            }
        }
    }
    None
}

/// Axis-aligned bounds.
pub fn bbox(p: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for q in p {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    (lo, hi)
}

/// Cumulative arc length at each vertex; the last entry is the perimeter.
pub fn cumulative(p: &[[f64; 2]]) -> Vec<f64> {
    let n = p.len();
    let mut s = Vec::with_capacity(n + 1);
    s.push(0.0);
    for i in 0..n {
        let a = p[i];
        let b = p[(i + 1) % n];
        let l = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        s.push(s[i] + l);
    }
    s
}

/// The point at arc length `t` (taken modulo the perimeter).
pub fn point_at(p: &[[f64; 2]], cum: &[f64], t: f64) -> [f64; 2] {
    let n = p.len();
    let per = cum[n];
    let t = t.rem_euclid(per);
    let i = match cum.binary_search_by(|c| c.total_cmp(&t)) {
        Ok(i) => i.min(n - 1),
        Err(i) => (i - 1).min(n - 1),
    };
    let l = cum[i + 1] - cum[i];
    let f = if l > 0.0 { (t - cum[i]) / l } else { 0.0 };
    let a = p[i];
    let b = p[(i + 1) % n];
    [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
}

/// Distance from `q` to the segment `a b`.
pub fn seg_dist(q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 > 0.0 {
        (((q[0] - a[0]) * d[0] + (q[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((q[0] - a[0] - t * d[0]).powi(2) + (q[1] - a[1] - t * d[1]).powi(2)).sqrt()
}

/// Distance from `q` to the closed polygon's boundary.
pub fn boundary_distance(p: &[[f64; 2]], q: [f64; 2]) -> f64 {
    let n = p.len();
    (0..n)
        .map(|i| seg_dist(q, p[i], p[(i + 1) % n]))
        .fold(f64::INFINITY, f64::min)
}

/// Symmetric Hausdorff distance between two closed polygons' boundaries,
/// each sampled every `step` along its arc length (plus its vertices).
pub fn hausdorff(a: &[[f64; 2]], b: &[[f64; 2]], step: f64) -> f64 {
    let one = |p: &[[f64; 2]], q: &[[f64; 2]]| {
        let cum = cumulative(p);
        let per = cum[p.len()];
        let m = ((per / step).ceil() as usize).clamp(p.len(), 200_000);
        (0..m)
            .map(|k| point_at(p, &cum, per * k as f64 / m as f64))
            .chain(p.iter().copied())
            .map(|x| boundary_distance(q, x))
            .fold(0.0f64, f64::max)
    };
    one(a, b).max(one(b, a))
}

/// The smallest and largest crossing of the horizontal line at height `y`
/// with the closed polygon `p` (first coordinate), if it crosses.
pub fn depth_span(p: &[[f64; 2]], y: f64) -> Option<(f64, f64)> {
    let n = p.len();
    let mut span: Option<(f64, f64)> = None;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] - y) * (b[1] - y) > 0.0 || a[1] == b[1] {
            continue;
        }
        let x = a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
        span = Some(span.map_or((x, x), |(l, h)| (l.min(x), h.max(x))));
    }
    span
}
