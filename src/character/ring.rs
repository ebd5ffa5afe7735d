//! The ring a transition meets: the parent's end ring sampled at
//! [`RING_VERTICES`] angles, where the seams between children cut it
//! ([`cut_indices`], [`cut_table`]), and the cubic Hermite basis the
//! transitions and seams blend with. Shared by [`super::transition`] and
//! [`super::seam`].

use std::f64::consts::PI;

/// Vertices on the parent's end ring (divisible by 4 and 6).
pub const RING_VERTICES: usize = 48;
/// Interior vertices per seam.
pub const SEAM_VERTICES: usize = 8;

/// The ring indices of the front and back cuts of seam j (1-based) among
/// k children: `cuts[j - 1]` when given ([`cut_table`]), else the fixed
/// angles `pi - j pi / k`.
pub fn cut_indices(j: usize, k: usize, cuts: &[(usize, usize)]) -> (usize, usize) {
    if let Some(c) = cuts.get(j - 1) {
        return *c;
    }
    let n = RING_VERTICES;
    let f = n / 2 - j * n / (2 * k);
    let b = n / 2 + j * n / (2 * k);
    (f % n, b % n)
}

/// Ring indices of the cuts at the given angles: either one front angle
/// per seam (radians in (0, pi), decreasing; the back cut mirrors it,
/// `2 pi - angle`), or one front angle per seam followed by one back angle
/// per seam (in (pi, 2 pi), increasing), for a ring whose front and back
/// differ. Rounded to ring vertices, kept strictly monotonic and inside
/// (0, pi) (fronts) or (pi, 2 pi) (backs). Empty when `angles` has neither
/// length (the fixed angles are used).
pub fn cut_table(k: usize, angles: &[f64]) -> Vec<(usize, usize)> {
    let n = RING_VERTICES;
    if k < 2
        || (angles.len() != k - 1 && angles.len() != 2 * (k - 1))
        || angles.iter().any(|a| !a.is_finite())
    {
        return Vec::new();
    }
    let (front, back) = angles.split_at(k - 1);
    let Some(f) = front_indices(front) else {
        return Vec::new();
    };
    let b = if back.is_empty() {
        f.clone()
    } else {
        let mirrored: Vec<f64> = back.iter().map(|a| 2.0 * PI - a).collect();
        match front_indices(&mirrored) {
            Some(b) => b,
            None => return Vec::new(),
        }
    };
    f.into_iter().zip(b).map(|(x, y)| (x, n - y)).collect()
}

/// Ring indices of front angles in (0, pi), decreasing: rounded, kept
/// strictly decreasing, each at least 1 and below n / 2 (angles outside
/// (0, pi) are clamped there).
fn front_indices(angles: &[f64]) -> Option<Vec<usize>> {
    let n = RING_VERTICES;
    let mut f: Vec<usize> = angles
        .iter()
        .map(|a| ((a / (2.0 * PI) * n as f64).round() as usize).clamp(1, n / 2 - 1))
        .collect();
    for j in 1..f.len() {
        if f[j] >= f[j - 1] {
            f[j] = f[j - 1].saturating_sub(1);
        }
    }
    if f.last().is_some_and(|&x| x < 1) || f[0] >= n / 2 {
        return None;
    }
    Some(f)
}

/// Cubic Hermite basis values and derivatives (d = 0, 1, 2) at s:
/// `[h00, h10, h01, h11]`.
pub fn hermite(s: f64, d: usize) -> [f64; 4] {
    match d {
        0 => [
            2.0 * s * s * s - 3.0 * s * s + 1.0,
            s * s * s - 2.0 * s * s + s,
            -2.0 * s * s * s + 3.0 * s * s,
            s * s * s - s * s,
        ],
        1 => [
            6.0 * s * s - 6.0 * s,
            3.0 * s * s - 4.0 * s + 1.0,
            -6.0 * s * s + 6.0 * s,
            3.0 * s * s - 2.0 * s,
        ],
        _ => [
            12.0 * s - 6.0,
            6.0 * s - 4.0,
            -12.0 * s + 6.0,
            6.0 * s - 2.0,
        ],
    }
}

/// Quintic Hermite basis values and derivatives (d = 0, 1, 2) at s:
/// `[H0, H1, H2, H3, H4, H5]`, the weights of the value, first and second
/// derivative at s = 0 and at s = 1 (each is 1 in its own condition, 0 in
/// the other five).
pub fn quintic(s: f64, d: usize) -> [f64; 6] {
    let (s2, s3) = (s * s, s * s * s);
    let (s4, s5) = (s3 * s, s3 * s2);
    match d {
        0 => [
            1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5,
            s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5,
            0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5,
            10.0 * s3 - 15.0 * s4 + 6.0 * s5,
            -4.0 * s3 + 7.0 * s4 - 3.0 * s5,
            0.5 * s3 - s4 + 0.5 * s5,
        ],
        1 => [
            -30.0 * s2 + 60.0 * s3 - 30.0 * s4,
            1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4,
            s - 4.5 * s2 + 6.0 * s3 - 2.5 * s4,
            30.0 * s2 - 60.0 * s3 + 30.0 * s4,
            -12.0 * s2 + 28.0 * s3 - 15.0 * s4,
            1.5 * s2 - 4.0 * s3 + 2.5 * s4,
        ],
        _ => [
            -60.0 * s + 180.0 * s2 - 120.0 * s3,
            -36.0 * s + 96.0 * s2 - 60.0 * s3,
            1.0 - 9.0 * s + 18.0 * s2 - 10.0 * s3,
            60.0 * s - 180.0 * s2 + 120.0 * s3,
            -24.0 * s + 84.0 * s2 - 60.0 * s3,
            3.0 * s - 12.0 * s2 + 10.0 * s3,
        ],
    }
}
