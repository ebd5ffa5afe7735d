//! Where a part's key sections go along its slices (paper 000 sec 4.1.2):
//! shared by the slice-based parts (`derive`) and the arms traced along
//! their axis (`limb`).

/// Sections per part: `3 P + 1` (the C2 PDE chain's rule), P = 4.
pub const SECTIONS_PER_PART: usize = 13;

/// One slice of a region: height, centre and half width.
pub(super) struct Sample {
    pub(super) y: f64,
    pub(super) c: f64,
    pub(super) w: f64,
}

/// Indices of `m` samples: half arc length, half profile variation. The
/// variation is that of the front profile (squared half-width and centre)
/// plus, when `depth` is given (half depth and centre z from the side
/// profile at each sample's height), that of the side profile the same way:
/// key sections are placed where either profile's curvature changes (paper
/// 000 sec 4.1.2, "key sections are re-placed from the curvature of both").
pub(super) fn place(s: &[Sample], depth: Option<&[(f64, f64)]>, m: usize) -> Vec<usize> {
    let n = s.len();
    let mut len = vec![0.0; n];
    let mut inc = vec![0.0; n];
    let wmax = s.iter().map(|q| q.w).fold(f64::MIN_POSITIVE, f64::max);
    for i in 1..n {
        len[i] = len[i - 1] + (s[i].y - s[i - 1].y).hypot(s[i].c - s[i - 1].c);
        if i + 1 < n {
            // second differences of the squared half-width (smooth at a
            // round tip, where the half-width itself is not) and the centre
            let w2 = |k: usize| s[k].w * s[k].w / wmax;
            let d2w = w2(i + 1) - 2.0 * w2(i) + w2(i - 1);
            let d2c = s[i + 1].c - 2.0 * s[i].c + s[i - 1].c;
            inc[i] = d2w.abs() + d2c.abs();
            if let Some(d) = depth {
                let dmax = d.iter().map(|q| q.1).fold(f64::MIN_POSITIVE, f64::max);
                let b2 = |k: usize| d[k].1 * d[k].1 / dmax;
                let d2b = b2(i + 1) - 2.0 * b2(i) + b2(i - 1);
                let d2z = d[i + 1].0 - 2.0 * d[i].0 + d[i - 1].0;
                inc[i] += d2b.abs() + d2z.abs();
            }
        }
    }
    // no single slice may attract more than a few sections
    let mean = inc.iter().sum::<f64>() / n as f64;
    let mut var = vec![0.0; n];
    for i in 1..n {
        var[i] = var[i - 1] + inc[i].min(4.0 * mean);
    }
    let (lt, vt) = (len[n - 1], var[n - 1].max(f64::MIN_POSITIVE));
    let f: Vec<f64> = (0..n)
        .map(|i| 0.5 * len[i] / lt + 0.5 * var[i] / vt)
        .collect();
    let mut idx: Vec<usize> = (0..m)
        .map(|j| {
            let target = j as f64 / (m - 1) as f64;
            f.iter().position(|&v| v >= target - 1e-12).unwrap_or(n - 1)
        })
        .collect();
    idx[0] = 0;
    idx[m - 1] = n - 1;
    // strictly increasing, keeping the ends
    for j in 1..m {
        idx[j] = idx[j].max(idx[j - 1] + 1).min(n - m + j);
    }
    for j in (0..m - 1).rev() {
        if idx[j] >= idx[j + 1] {
            idx[j] = idx[j + 1] - 1;
        }
    }
    idx
}
