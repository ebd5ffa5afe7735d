//! Fitting errors ErM and ErA (paper 002 Table 1), defined precisely.
//!
//! Paper 002 reports "average and maximum errors" without defining them.
//! Here, for original points $\mathbf{p}_k$ ($k = 1..K$, the vertices of the
//! cross-section polyline, in the curve's plane) and the fitted GEC
//! $\mathbf{C}(\theta)$:
//!
//! * point-to-curve distance $d_k = \min_\theta |\mathbf{p}_k -
//!   \mathbf{C}(\theta)|$, the global minimum over the whole curve, found by
//!   dense sampling (`SAMPLES_PER_TERM` $\cdot J$, at least `MIN_SAMPLES`) and
//!   Newton polishing of $\tfrac12|\mathbf{C}-\mathbf{p}|^2$ (exact
//!   derivatives by jets);
//! * $\mathrm{ErM} = \max_k d_k$, $\mathrm{ErA} = \frac1K \sum_k d_k$
//!   (one-sided: original to fitted, in the units of the data);
//! * `erm_rel`, `era_rel`: the same divided by $D$, the diagonal of the
//!   original points' in-plane bounding box (so numbers compare across body
//!   parts and scales);
//! * `hausdorff`: the symmetric Hausdorff distance between the original
//!   polyline (segments) and the fitted curve (sampled), which also catches
//!   fitted loops that no original point is near.

use super::Gec;
use crate::check::{Measure, Worst};
use crate::jet::Jet;
use std::f64::consts::PI;

/// Dense samples per term for the global search.
pub const SAMPLES_PER_TERM: usize = 64;
/// Minimum number of dense samples.
pub const MIN_SAMPLES: usize = 1024;
/// Newton iterations of the polish.
const NEWTON_ITERS: usize = 8;

/// ErM / ErA and companions (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FitErrors {
    pub erm: f64,
    pub era: f64,
    pub erm_rel: f64,
    pub era_rel: f64,
    pub hausdorff: f64,
    pub hausdorff_rel: f64,
    /// The normaliser D (bounding-box diagonal of the original points).
    pub scale: f64,
}

/// Dense samples of a GEC for distance queries.
pub struct Sampled<'a> {
    gec: &'a Gec,
    pts: Vec<[f64; 2]>,
}

impl<'a> Sampled<'a> {
    /// Samples `gec` densely.
    pub fn new(gec: &'a Gec) -> Sampled<'a> {
        let m = (SAMPLES_PER_TERM * gec.terms()).max(MIN_SAMPLES);
        Sampled {
            gec,
            pts: gec.sample_plane(m),
        }
    }

    /// `(distance, theta)` of the closest curve point to in-plane `p`.
    pub fn closest(&self, p: [f64; 2]) -> (f64, f64) {
        let m = self.pts.len();
        let h = 2.0 * PI / m as f64;
        let (mut best_i, mut best_d) = (0, f64::INFINITY);
        for (i, q) in self.pts.iter().enumerate() {
            let d = (q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2);
            if d < best_d {
                best_d = d;
                best_i = i;
            }
        }
        let mut t = h * best_i as f64;
        let mut best_t = t;
        for _ in 0..NEWTON_ITERS {
            let c = self.gec.eval_plane(Jet::<3, 1>::var_u(t));
            let r = [c[0].value() - p[0], c[1].value() - p[1]];
            let d1 = [c[0].deriv(1, 0), c[1].deriv(1, 0)];
            let d2 = [c[0].deriv(2, 0), c[1].deriv(2, 0)];
            let g = r[0] * d1[0] + r[1] * d1[1];
            let hss = d1[0] * d1[0] + d1[1] * d1[1] + r[0] * d2[0] + r[1] * d2[1];
            let dist = r[0] * r[0] + r[1] * r[1];
            if dist < best_d {
                best_d = dist;
                best_t = t;
            }
            if hss.is_nan() || hss <= 0.0 {
                break;
            }
            let step = (g / hss).clamp(-h, h);
            if step.abs() < 1e-15 {
                break;
            }
            t -= step;
        }
        // the last step is not measured: from the nearest of at least
        // `MIN_SAMPLES` samples Newton has converged by
        // `NEWTON_ITERS` (a final measurement never improved on 160,000
        // points around a 3:1 ellipse, its evolute included; it was dead
        // code, and two mutants of it survived as equivalent)
        (best_d.sqrt(), best_t)
    }

    /// The dense samples.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.pts
    }
}

/// `max_q min_i dist(q, segment i)`: the distance from the samples `pts` to
/// the closed polyline `poly` (the back half of the Hausdorff distance; 0
/// for no samples, infinite for an empty polyline, NaN when a coordinate is
/// NaN).
///
/// Equal to the plain double loop, value for value: a sample whose distance
/// to some segment is already at most the running maximum cannot raise it,
/// so its search stops there, and the search of each sample starts at the
/// segment nearest the previous sample (neighbouring samples are near the
/// same segment), so most samples stop after a few segments instead of
/// visiting all of them.
pub fn back_distance(pts: &[[f64; 2]], poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    if pts.is_empty() {
        return 0.0;
    }
    if n == 0 {
        return f64::INFINITY;
    }
    if poly
        .iter()
        .chain(pts)
        .any(|p| p[0].is_nan() || p[1].is_nan())
    {
        return f64::NAN;
    }
    let seg = |q: [f64; 2], i: usize| point_segment(q, poly[i], poly[(i + 1) % n]);
    let mut back = 0.0f64;
    let mut start = 0;
    for &q in pts {
        let mut best = f64::INFINITY;
        let mut best_i = start;
        for k in 0..n {
            let i = (start + k) % n;
            let d = seg(q, i);
            if d < best {
                best = d;
                best_i = i;
            }
            if best <= back {
                break;
            }
        }
        start = best_i;
        back = back.max(best);
    }
    back
}

/// Distance from `p` to the segment `a b` (2D).
pub fn point_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let ap = [p[0] - a[0], p[1] - a[1]];
    let l2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t = if l2 > 0.0 {
        ((ap[0] * ab[0] + ap[1] * ab[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (ap[0] - t * ab[0]).hypot(ap[1] - t * ab[1])
}

/// Bounding-box diagonal of in-plane points.
pub fn diagonal(points: &[[f64; 2]]) -> f64 {
    let (lo, hi) = crate::polygon::bbox(points);
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// ErM, ErA and the Hausdorff distance of `gec` against the original closed
/// polyline `original` (in-plane coordinates of the GEC's frame).
pub fn errors(gec: &Gec, original: &[[f64; 2]]) -> FitErrors {
    let s = Sampled::new(gec);
    let d: Vec<f64> = original.iter().map(|p| s.closest(*p).0).collect();
    let k = d.len().max(1) as f64;
    let erm = d.iter().copied().max_nan();
    let era = d.iter().sum::<f64>() / k;
    let back = back_distance(s.points(), original);
    let n = original.len();
    let hausdorff = if n == 0 { erm } else { erm.worst(back) };
    let scale = diagonal(original);
    let rel = |v: f64| if scale > 0.0 { v / scale } else { v };
    FitErrors {
        erm,
        era,
        erm_rel: rel(erm),
        era_rel: rel(era),
        hausdorff,
        hausdorff_rel: rel(hausdorff),
        scale,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain double loop `back_distance` replaces.
    fn plain(pts: &[[f64; 2]], poly: &[[f64; 2]]) -> f64 {
        let n = poly.len();
        pts.iter()
            .map(|q| {
                (0..n)
                    .map(|i| point_segment(*q, poly[i], poly[(i + 1) % n]))
                    .min_nan()
            })
            .max_nan()
    }

    /// A polyline of one repeated point has no size to divide by: its
    /// relative errors are the absolute ones, finite (a mutation sample
    /// found nothing checking the `scale > 0` guard; with `>=` they were
    /// infinite).
    #[test]
    fn a_polyline_without_size_gives_finite_relative_errors() {
        let gec = Gec::ellipse(crate::curve::gec::Frame::z_plane(0.0), [0.0, 0.0], 2.0, 1.0);
        let e = errors(&gec, &[[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]);
        assert_eq!(e.scale, 0.0);
        assert!(e.erm > 0.0 && e.erm.is_finite(), "{e:?}");
        assert_eq!(e.erm_rel, e.erm);
        assert_eq!(e.era_rel, e.era);
        assert_eq!(e.hausdorff_rel, e.hausdorff);
    }

    #[test]
    fn back_distance_equals_the_double_loop_bit_for_bit() {
        // a star polygon and a noisy ellipse sampled against it, and the
        // reverse, from a fixed linear congruential sequence
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut rand = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for n in [1, 2, 3, 7, 40] {
            let poly: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = 2.0 * PI * i as f64 / n as f64;
                    let r = if i % 2 == 0 { 1.0 } else { 0.4 + rand() };
                    [r * t.cos(), r * t.sin()]
                })
                .collect();
            let pts: Vec<[f64; 2]> = (0..300)
                .map(|i| {
                    let t = 2.0 * PI * i as f64 / 300.0;
                    [1.3 * t.cos() + 0.1 * rand(), 0.7 * t.sin() - 0.1 * rand()]
                })
                .collect();
            for (a, b) in [(&pts, &poly), (&poly, &pts)] {
                assert_eq!(
                    back_distance(a, b).to_bits(),
                    plain(a, b).to_bits(),
                    "n {n}"
                );
            }
        }
        assert_eq!(back_distance(&[], &[[0.0, 0.0]]), 0.0);
        assert_eq!(back_distance(&[[1.0, 0.0]], &[]), f64::INFINITY);
        assert!(back_distance(&[[f64::NAN, 0.0]], &[[0.0, 0.0], [1.0, 0.0]]).is_nan());
        assert!(back_distance(&[[1.0, 0.0]], &[[0.0, f64::NAN], [1.0, 0.0]]).is_nan());
    }
    /// A circle of radius `r` about the origin as a one-term GEC.
    fn circle(r: f64) -> Gec {
        Gec {
            frame: super::super::Frame {
                origin: [0.0; 3],
                e1: [1.0, 0.0, 0.0],
                e2: [0.0, 1.0, 0.0],
            },
            centre: [0.0, 0.0],
            x: vec![[r, 0.0]],
            y: vec![[r, 0.0]],
        }
    }

    #[test]
    fn point_segment_against_hand_computed_distances() {
        let (a, b) = ([0.0, 0.0], [2.0, 0.0]);
        assert_eq!(point_segment([1.0, 1.0], a, b), 1.0);
        assert_eq!(point_segment([0.5, -3.0], a, b), 3.0);
        // beyond the end: the distance to the end point
        assert!(
            (point_segment([3.0, 1.0], a, b) - 2f64.sqrt()).abs() <= crate::check::tol::ROUNDING
        );
        assert_eq!(point_segment([1.0, 1.0], a, a), 2f64.sqrt());
        // a slanted segment (3, 4): p projects at t = 24/25, 1.4 away (an
        // axis-aligned one leaves a wrong |ab|^2 in y unseen)
        assert!(
            (point_segment([4.0, 3.0], [0.0, 0.0], [3.0, 4.0]) - 1.4).abs()
                <= crate::check::tol::ROUNDING
        );
    }

    #[test]
    fn fit_errors_of_a_circle_against_a_concentric_polygon_are_the_radius_gap() {
        // every vertex of a 7-gon of radius 1.25 is 0.25 from the GEC
        // circle of radius 1 (closest: the refined, not the sampled, point)
        let poly: Vec<[f64; 2]> = (0..7)
            .map(|i| {
                let t = 2.0 * PI * (i as f64 + 0.3) / 7.0;
                [1.25 * t.cos(), 1.25 * t.sin()]
            })
            .collect();
        let g = circle(1.0);
        let s = Sampled::new(&g);
        for p in &poly {
            let (d, t) = s.closest(*p);
            assert!(
                (d - 0.25).abs() <= crate::check::tol::ROUNDING,
                "{p:?}: {d}"
            );
            let c = g.eval_plane(t);
            assert!((c[0].hypot(c[1]) - 1.0).abs() <= crate::check::tol::ROUNDING);
        }
        let e = errors(&g, &poly);
        assert!((e.erm - 0.25).abs() <= crate::check::tol::ROUNDING, "{e:?}");
        assert!((e.era - 0.25).abs() <= crate::check::tol::ROUNDING, "{e:?}");
        // relative to the polygon's bounding-box diagonal
        let ext = |k: usize| {
            let v = poly.iter().map(|p| p[k]);
            v.clone().fold(f64::NEG_INFINITY, f64::max) - v.fold(f64::INFINITY, f64::min)
        };
        let diag = ext(0).hypot(ext(1));
        assert!(
            (e.erm_rel - 0.25 / diag).abs() <= crate::check::tol::ROUNDING,
            "{e:?}"
        );
        assert!(
            (e.era_rel - 0.25 / diag).abs() <= crate::check::tol::ROUNDING,
            "{e:?}"
        );
    }
}
