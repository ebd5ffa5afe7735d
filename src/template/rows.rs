//! The side outline row by row ([`super::envelope`]): crossings of a row
//! with a polygon, per-row values smoothed and filled, and the remap of
//! paired crossings near a row.

/// Half-width (rows) of the box filter smoothing the row corrections.
pub const SMOOTH_ROWS: usize = 2;
/// The arm is the front-most (back-most) part at a height when it is this
/// fraction of the height beyond the trunk.
pub const ARM_EPS: f64 = 1e-3;

pub(super) fn smooth(v: &mut [f64], known: &[bool]) {
    let src = v.to_vec();
    let n = v.len();
    for i in 0..n {
        if !known[i] {
            continue;
        }
        let (lo, hi) = (i.saturating_sub(SMOOTH_ROWS), (i + SMOOTH_ROWS).min(n - 1));
        let (mut s, mut w) = (0.0, 0.0);
        for j in lo..=hi {
            if known[j] {
                s += src[j];
                w += 1.0;
            }
        }
        v[i] = s / w;
    }
}

/// Replaces each NaN by the nearest finite value (0 when there is none).
pub(super) fn fill_nearest(v: &mut [f64]) {
    let src = v.to_vec();
    let n = v.len();
    for i in 0..n {
        if src[i].is_nan() {
            v[i] = (1..n)
                .find_map(|d| {
                    let a = i.checked_sub(d).map(|j| src[j]).filter(|x| !x.is_nan());
                    let b = src.get(i + d).copied().filter(|x| !x.is_nan());
                    a.or(b)
                })
                .unwrap_or(0.0);
        }
    }
}

/// Half-width (rows) of the triangle window over which an arm vertex
/// averages the paired rows' remaps ([`remap_near`]).
pub const PAIR_ROWS: usize = 4;

/// The depth change at depth `z` of one paired row: the arm's fitted
/// crossings `c` moved onto the sketched ones `d` (paired in order),
/// linear between them and constant beyond the first and last (0 for no
/// pairs).
pub fn remap(pairs: &[(f64, f64)], z: f64) -> f64 {
    let (Some(&first), Some(&last)) = (pairs.first(), pairs.last()) else {
        return 0.0;
    };
    if z <= first.0 {
        return first.1 - first.0;
    }
    for w in pairs.windows(2) {
        let ((c0, d0), (c1, d1)) = (w[0], w[1]);
        if z <= c1 {
            let t = if c1 > c0 { (z - c0) / (c1 - c0) } else { 0.0 };
            return (1.0 - t) * (d0 - c0) + t * (d1 - c1);
        }
    }
    last.1 - last.0
}

/// Rows over which a paired row's remap carries to rows that do not pair
/// (a finger's web or tip where the fitted outline and the sketch cross a
/// row a different number of times), fading linearly.
pub const PAIR_REACH: usize = 16;

/// Per row, the nearest paired row and its distance (rows), within
/// [`PAIR_REACH`].
pub(super) fn nearest_paired(paired: &[Option<Vec<(f64, f64)>>]) -> Vec<Option<(usize, usize)>> {
    let n = paired.len();
    (0..n)
        .map(|r| {
            (0..PAIR_REACH).find_map(|d| {
                let below = r.checked_sub(d).filter(|&j| paired[j].is_some());
                let above = Some(r + d).filter(|&j| j < n && paired[j].is_some());
                below.or(above).map(|j| (j, d))
            })
        })
        .collect()
}

/// An arm vertex's remap at fractional row `r`, depth `z`: over a triangle
/// window of [`PAIR_ROWS`] rows, each row's nearest paired row's remap,
/// weighted by the window and by its fading with the distance to that
/// row; with the share `w` of the window's weight it carries (the vertex
/// blends `w` of it with the envelope correction, so the remap fades out
/// continuously away from the paired rows).
pub(super) fn remap_near(
    paired: &[Option<Vec<(f64, f64)>>],
    nearest: &[Option<(usize, usize)>],
    r: f64,
    z: f64,
) -> Option<(f64, f64)> {
    let k = PAIR_ROWS as f64 + 1.0;
    let lo = (r - k).ceil().max(0.0) as usize;
    let hi = ((r + k).floor().max(0.0) as usize).min(paired.len() - 1);
    let (mut all, mut wp, mut sum) = (0.0, 0.0, 0.0);
    for (j, near) in nearest.iter().enumerate().take(hi + 1).skip(lo) {
        let w = 1.0 - (j as f64 - r).abs() / k;
        if w <= 0.0 {
            continue;
        }
        all += w;
        let Some((jj, d)) = *near else {
            continue;
        };
        let Some(p) = paired[jj].as_deref().filter(|p| !p.is_empty()) else {
            continue;
        };
        let w = w * (1.0 - d as f64 / PAIR_REACH as f64);
        wp += w;
        sum += w * remap(p, z);
    }
    (wp > 0.0).then(|| (wp / all, sum / wp))
}

/// Linear interpolation of a per-row value at fractional row `r`.
pub(super) fn at(v: &[f64], r: f64) -> f64 {
    let n = v.len();
    let r = r.clamp(0.0, (n - 1) as f64);
    let i = (r.floor() as usize).min(n - 2);
    let t = r - i as f64;
    (1.0 - t) * v[i] + t * v[i + 1]
}
