//! An arm's two traced sides paired into its central curve, and that
//! curve continued up the arm's root to the shoulder's corner
//! ([`super::limb::TracedArm::from_corner`]); arc-length resampling.

use super::poly::dist;

/// Rounding allowed in counting the steps along a root run.
const STEP_ROUNDING: f64 = 1e-9;

/// An arm's central curve points, half widths and unit chords (inner
/// side to outer side), pair by pair.
pub(super) type Sides = (Vec<[f64; 2]>, Vec<f64>, Vec<[f64; 2]>);

/// The walk from the shoulder point (`walk[0]`) on to its point nearest
/// the shoulder's corner `c`: the arm's root beyond its shortest cut.
pub(super) fn run_to(walk: &[[f64; 2]], c: [f64; 2]) -> Vec<[f64; 2]> {
    let ic = (0..walk.len())
        .min_by(|&i, &j| dist(walk[i], c).total_cmp(&dist(walk[j], c)))
        .unwrap_or(0);
    walk[..=ic].to_vec()
}

/// `n` points equally spaced by arc length along an open polyline.
pub(super) fn resample_open(p: &[[f64; 2]], n: usize) -> Vec<[f64; 2]> {
    let mut cum = vec![0.0; p.len()];
    for i in 1..p.len() {
        cum[i] = cum[i - 1] + dist(p[i - 1], p[i]);
    }
    let total = cum[p.len() - 1];
    let mut j = 0;
    (0..n)
        .map(|k| {
            let s = total * k as f64 / (n - 1) as f64;
            while j + 2 < p.len() && cum[j + 1] < s {
                j += 1;
            }
            let l = (cum[j + 1] - cum[j]).max(f64::MIN_POSITIVE);
            let t = ((s - cum[j]) / l).clamp(0.0, 1.0);
            [
                p[j][0] + t * (p[j + 1][0] - p[j][0]),
                p[j][1] + t * (p[j + 1][1] - p[j][1]),
            ]
        })
        .collect()
}

/// The arm's central curve, half widths and chords (`trace`, from the
/// shortest cut on) continued up its root to the shoulder's corner: along
/// `run` (the outline from the shoulder point to the corner, the arm's
/// outer side there; its inner side is hidden in the body), the arm keeps
/// the width it has at the cut, its centre that half width in from the
/// run, spaced as the trace's centres are, from a half width short of the
/// corner.
pub(super) fn rooted_at_corner(
    run: &[[f64; 2]],
    (centre, half_width, chord): (&[[f64; 2]], &[f64], &[[f64; 2]]),
) -> Sides {
    let len = |p: &[[f64; 2]]| p.windows(2).map(|w| dist(w[0], w[1])).sum::<f64>();
    let step = len(centre) / (centre.len().max(2) - 1) as f64;
    let (w0, out0) = (half_width[0], chord[0]);
    // corner first, ending one step short of the shoulder point; the
    // first centre a half width in from the corner, so that the dome
    // closing it (`quadruped::shells::cap_start`: a half width) ends there
    let mut run: Vec<[f64; 2]> = run.iter().rev().copied().collect();
    run.dedup();
    let mut walked = 0.0;
    while run.len() > 2 && walked + dist(run[0], run[1]) <= w0 {
        walked += dist(run[0], run[1]);
        run.remove(0);
    }
    // a whole number of steps up to rounding takes that many
    let k = (len(&run) / step.max(f64::MIN_POSITIVE) - STEP_ROUNDING).ceil() as usize;
    let mut c = Vec::new();
    let mut hw = Vec::new();
    let mut ch = Vec::new();
    if k >= 2 && run.len() >= 2 {
        let pts = resample_open(&run, k + 1);
        for i in 0..k {
            let t = [pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1]];
            let l = t[0].hypot(t[1]);
            if l <= 0.0 {
                continue;
            }
            // the run's normal on the outer side (the cut's chord's side)
            let mut n = [t[1] / l, -t[0] / l];
            if n[0] * out0[0] + n[1] * out0[1] < 0.0 {
                n = [-n[0], -n[1]];
            }
            c.push([pts[i][0] - w0 * n[0], pts[i][1] - w0 * n[1]]);
            hw.push(w0);
            ch.push(n);
        }
    }
    c.extend_from_slice(centre);
    hw.extend_from_slice(half_width);
    ch.extend_from_slice(chord);
    (c, hw, ch)
}

/// The arm's two sides, resampled alike, paired: each pair's midpoint
/// (the central curve), half its distance (the half width) and its unit
/// direction, inner side to outer side.
pub(super) fn pair_sides(inner: &[[f64; 2]], outer: &[[f64; 2]]) -> Sides {
    let mut centre = Vec::with_capacity(inner.len());
    let mut half_width = Vec::with_capacity(inner.len());
    let mut chord = Vec::with_capacity(inner.len());
    for (a, b) in inner.iter().zip(outer) {
        let l = dist(*a, *b);
        centre.push([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]);
        half_width.push(0.5 * l);
        chord.push(if l > 0.0 {
            [(b[0] - a[0]) / l, (b[1] - a[1]) / l]
        } else {
            [0.0, 0.0]
        });
    }
    (centre, half_width, chord)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An arm 0.2 wide hanging down x = 0.1 (its centre), its root run
    /// the outer side x = 0.2 from y = 0 (the shoulder point) up to the
    /// corner at y = 1: the continued curve runs up x = 0.1 (the half
    /// width in from the run), spaced as the trace's centres are, its
    /// first point a half width short of the corner, the trace's own
    /// points after it.
    #[test]
    fn the_root_is_continued_at_the_cut_s_width_a_half_width_short_of_the_corner() {
        let centre: Vec<[f64; 2]> = (0..11).map(|k| [0.1, -0.1 * k as f64]).collect();
        let half_width = vec![0.1; 11];
        let chord = vec![[1.0, 0.0]; 11];
        let run: Vec<[f64; 2]> = (0..=20).map(|k| [0.2, 0.05 * k as f64]).collect();
        let (c, w, ch) = rooted_at_corner(&run, (&centre, &half_width, &chord));
        assert_eq!(c.len(), w.len());
        assert_eq!(c.len(), ch.len());
        let added = c.len() - centre.len();
        // 0.9 of run left after the half width, at steps of 0.1
        assert_eq!(added, 9, "{c:?}");
        assert_eq!(&c[added..], &centre[..]);
        let tol = crate::check::tol::ROUNDING;
        assert!((c[0][1] - 0.9).abs() < tol, "{:?}", c[0]);
        for (k, p) in c[..added].iter().enumerate() {
            assert!((p[0] - 0.1).abs() < tol, "{p:?}");
            assert!((p[1] - (0.9 - 0.1 * k as f64)).abs() < tol, "{p:?}");
            assert!(
                (ch[k][0] - 1.0).abs() < tol && ch[k][1].abs() < tol,
                "{:?}",
                ch[k]
            );
        }
        // pairing: the midpoints and half distances of two straight sides
        let (pc, pw, pch) = pair_sides(&[[0.0, 0.0], [0.0, 1.0]], &[[0.4, 0.0], [0.2, 1.0]]);
        assert_eq!(pc, vec![[0.2, 0.0], [0.1, 1.0]]);
        assert!((pw[0] - 0.2).abs() < tol && (pw[1] - 0.1).abs() < tol);
        assert_eq!(pch[0], [1.0, 0.0]);
    }
}
