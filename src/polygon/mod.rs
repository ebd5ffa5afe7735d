//! Planar polygons, the 2D geometry every modeling module shares: signed
//! area and orientation, point in polygon, segment intersection, the
//! simple-polygon test, bounds, the validated [`Outline`], arc length,
//! distances, and the [`View`] a drawing is made in. Points are
//! `[f64; 2]`; a polygon's closing segment is implicit (edge `i` joins
//! point `i` to point `i + 1 mod n`). Names nothing of the crate (the
//! ground, beside `vec3`).

mod outline;
mod simple;
#[cfg(test)]
mod tests;
mod view;

pub use outline::{validate, Outline, OutlineError, DUPLICATE_REL};
pub use simple::{is_simple, self_intersection};
pub use view::{UnknownView, View};

/// Signed area of the closed polygon (positive when counter-clockwise;
/// zero for fewer than 3 points), summed as triangles fanned from the
/// first point, which keeps the rounding relative to the polygon's size
/// rather than to its distance from the origin.
pub fn signed_area(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    if n < 3 {
        return 0.0;
    }
    let o = p[0];
    let mut a = 0.0;
    for i in 1..n - 1 {
        let (q, r) = (p[i], p[i + 1]);
        a += (q[0] - o[0]) * (r[1] - o[1]) - (r[0] - o[0]) * (q[1] - o[1]);
    }
    0.5 * a
}

/// Twice the signed area of the triangle `a b c`: positive when it turns
/// counter-clockwise (c left of the line a -> b), zero when collinear.
pub fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Which way a closed polygon turns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Orientation {
    CounterClockwise,
    Clockwise,
}

/// The polygon's orientation by the sign of its [`signed_area`]; `None`
/// when the area is zero (fewer than 3 points, all collinear, or a
/// figure eight whose lobes cancel) or not a number.
pub fn orientation(p: &[[f64; 2]]) -> Option<Orientation> {
    let a = signed_area(p);
    if a > 0.0 {
        Some(Orientation::CounterClockwise)
    } else if a < 0.0 {
        Some(Orientation::Clockwise)
    } else {
        None
    }
}

/// Whether `q` is inside the closed polygon `p`, by the even-odd rule
/// (crossings of the ray from `q` towards +x), for any polygon, simple or
/// not. An edge counts when it spans `q`'s height half-open (one end
/// strictly above `q`, the other at or below) and `q` is strictly on its
/// inner side (decided by the sign of [`orient`], without a division).
/// On the boundary this makes a deterministic choice: a point on an edge
/// or a vertex is inside when the polygon lies to its right or above
/// (the left and bottom sides of a square are in, the right and top
/// out), so polygons tiling the plane share their boundary points out
/// exactly once.
pub fn point_in_polygon(p: &[[f64; 2]], q: [f64; 2]) -> bool {
    let n = p.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] > q[1]) != (b[1] > q[1]) {
            // the crossing is right of q when q is left of the edge taken
            // upwards
            let o = orient(a, b, q);
            if (b[1] > a[1] && o > 0.0) || (b[1] < a[1] && o < 0.0) {
                inside = !inside;
            }
        }
    }
    inside
}

/// Whether `s` and `t` have strictly opposite signs.
fn straddles(s: f64, t: f64) -> bool {
    (s > 0.0 && t < 0.0) || (s < 0.0 && t > 0.0)
}

/// Where the line `p + t d` meets the line through the segment
/// `a + s (b - a)`: `(t, s)` (the segment is hit for `s` in [0, 1]); None
/// when the two are parallel (`d x (b - a) = 0`). Shared by the rays of the
/// plate's disk mapping, the sketch's cut crossings and the foot's section
/// lines.
pub fn line_segment_params(
    p: [f64; 2],
    d: [f64; 2],
    a: [f64; 2],
    b: [f64; 2],
) -> Option<(f64, f64)> {
    let e = [b[0] - a[0], b[1] - a[1]];
    let den = d[0] * e[1] - d[1] * e[0];
    if den == 0.0 {
        return None;
    }
    let w = [a[0] - p[0], a[1] - p[1]];
    Some((
        (w[0] * e[1] - w[1] * e[0]) / den,
        (w[0] * d[1] - w[1] * d[0]) / den,
    ))
}

/// Whether the closed segments `a b` and `c d` cross properly: they meet
/// in one point interior to both, each having its ends strictly on
/// opposite sides of the other's line. Touching (an end on the other
/// segment) and collinear overlap are not proper crossings.
pub fn segments_cross(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    straddles(orient(c, d, a), orient(c, d, b)) && straddles(orient(a, b, c), orient(a, b, d))
}

/// A point shared by the closed segments `a b` and `c d`, if any: a
/// proper crossing (the crossing point), or touching (an end of one on
/// the other, including shared ends and collinear overlap: that end).
pub fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<[f64; 2]> {
    let d1 = orient(c, d, a);
    let d2 = orient(c, d, b);
    let d3 = orient(a, b, c);
    let d4 = orient(a, b, d);
    if straddles(d1, d2) && straddles(d3, d4) {
        let t = d1 / (d1 - d2);
        return Some([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
    }
    let within = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        r[0] >= p[0].min(q[0])
            && r[0] <= p[0].max(q[0])
            && r[1] >= p[1].min(q[1])
            && r[1] <= p[1].max(q[1])
    };
    [(d1, c, d, a), (d2, c, d, b), (d3, a, b, c), (d4, a, b, d)]
        .into_iter()
        .find(|&(o, p, q, r)| o == 0.0 && within(p, q, r))
        .map(|(_, _, _, r)| r)
}

/// Whether the closed segments `a b` and `c d` share a point: proper
/// crossings and touching both count ([`segments_meet`]; for proper
/// crossings only, [`segments_cross`]).
pub fn segments_intersect(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    segments_meet(a, b, c, d).is_some()
}

/// Axis-aligned bounds `(lo, hi)`; for no points the empty box
/// (`lo` +infinity, `hi` -infinity). NaN coordinates are skipped.
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

/// The range `[min, max]` of coordinate `k` (0: horizontal, 1: vertical)
/// over the points ([`bbox`]'s side `k`).
pub fn span(p: &[[f64; 2]], k: usize) -> [f64; 2] {
    let (lo, hi) = bbox(p);
    [lo[k], hi[k]]
}

/// The length of the diagonal of the [`bbox`] (0 for no points).
pub fn diagonal(p: &[[f64; 2]]) -> f64 {
    if p.is_empty() {
        return 0.0;
    }
    let (lo, hi) = bbox(p);
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
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

/// Every crossing (first coordinate) of the horizontal line at height `y`
/// with the closed polygon `p`, sorted. An edge counts when its ends are
/// not on one side of the line and it is not horizontal, so a vertex on
/// the line is counted by both its edges (unlike `sketch::poly`'s slices,
/// whose half-open rule counts it once for the even-odd intervals).
pub fn line_crossings(p: &[[f64; 2]], y: f64) -> Vec<f64> {
    let n = p.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] - y) * (b[1] - y) > 0.0 || a[1] == b[1] {
            continue;
        }
        out.push(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
    }
    out.sort_by(f64::total_cmp);
    out
}

/// The smallest and largest crossing of the horizontal line at height `y`
/// with the closed polygon `p` (first coordinate), if it crosses.
pub fn depth_span(p: &[[f64; 2]], y: f64) -> Option<(f64, f64)> {
    let c = line_crossings(p, y);
    Some((*c.first()?, *c.last()?))
}
