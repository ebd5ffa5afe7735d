//! Silhouette correction of a feature's height field (000 sec 5.3): the
//! profiles are outlines, so the edited part's greatest depth over each
//! chord of the region must follow the profile stroke.
//!
//! The angular blend of the ray heights reproduces a profile only on its
//! own ray; off the ray, over a host that curves towards the viewer (a
//! chest next to the sternum), host depth plus blended height rises above
//! the stroke (18.6 % of the peak for the bundled breast's side profile).
//! The cause is that the outline is a maximum over the chord while the
//! blend only knows the ray. The correction multiplies the height by one
//! factor per profile, a function of the profile's shared coordinate `s`:
//! $$h'(q) = h(q)\,\prod_k c_k(q_{s_k}),$$
//! with $c_k(s)$ the root of $\max_{q \in \text{chord}(s)} [z_h(q) + c\,
//! g(q)] = z_k(s)$ ($g$ the height with the other factors, $z_k$ the stroke's
//! depth), found by bisection on a grid of the region (the left side is
//! convex in $c$ and increasing where the chord's maximum has $g > 0$). The factors are solved in turn, a few
//! sweeps (the second profile's factor changes the first's chord maxima a
//! little), sampled at [`GRID`] points and interpolated by Catmull-Rom
//! cubics, so the factor is C1 in `s` and the corrected height keeps the
//! zero value and zero gradient on the curve (`h` and `grad h` vanish
//! there, the factor is bounded and Lipschitz; `Feature::height` also
//! fades the factor to 1 over the blend band, so next to the curve the
//! height is the uncorrected one). Where the host alone is
//! already deeper than the stroke, the factor is 0 (the outline cannot be
//! met by a raised feature); factors are capped at [`FACTOR_MAX`]. A
//! feature whose height at the peak is negative (a dent) is left
//! uncorrected.

use super::region::Region;
use super::{axis_name, clean, depth_axis, SasmError, Stroke};
use crate::profile::View;

/// A profile stroke read as the upper envelope of depth over the shared
/// axis.
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileCurve {
    pub view: View,
    pub points: Vec<[f64; 2]>,
    /// Index (0, 1) of the depth coordinate in the profile's points.
    pub kd: usize,
    /// Index (0, 1) of the shared axis in the region view's points.
    pub ri: usize,
}

impl ProfileCurve {
    pub(super) fn new(s: &Stroke, region: View, n: usize) -> Result<ProfileCurve, SasmError> {
        let what = format!("profile {n} ({} view)", s.view);
        let d = depth_axis(region);
        let (ph, pv) = s.view.axes();
        let kd = if ph == d {
            0
        } else if pv == d {
            1
        } else {
            return Err(SasmError::View {
                what,
                found: s.view,
                expected: format!(
                    "a profile must show the {} axis, the depth of the curve's {} view",
                    axis_name(d),
                    region
                ),
            });
        };
        let shared = if kd == 0 { pv } else { ph };
        let (rh, _) = region.axes();
        let points = clean(&what, &s.points, 2)?;
        Ok(ProfileCurve {
            view: s.view,
            points,
            kd,
            ri: if shared == rh { 0 } else { 1 },
        })
    }

    /// Shared-axis range covered.
    pub fn range(&self) -> [f64; 2] {
        let ks = 1 - self.kd;
        self.points
            .iter()
            .fold([f64::INFINITY, f64::NEG_INFINITY], |r, p| {
                [r[0].min(p[ks]), r[1].max(p[ks])]
            })
    }

    /// The greatest depth of the stroke at shared coordinate `s`.
    pub fn depth_at(&self, s: f64) -> Option<f64> {
        let (ks, kd) = (1 - self.kd, self.kd);
        let mut best: Option<f64> = None;
        for w in self.points.windows(2) {
            let (a, b) = (w[0], w[1]);
            let (lo, hi) = (a[ks].min(b[ks]), a[ks].max(b[ks]));
            if s < lo || s > hi {
                continue;
            }
            let z = if hi > lo {
                let t = (s - a[ks]) / (b[ks] - a[ks]);
                a[kd] + t * (b[kd] - a[kd])
            } else {
                a[kd].max(b[kd])
            };
            best = Some(best.map_or(z, |x: f64| x.max(z)));
        }
        best
    }
}

/// Grid samples per direction over the region's bounding box.
pub const GRID: usize = 65;
/// Sweeps over the profiles.
pub const SWEEPS: usize = 16;
/// Largest factor.
pub const FACTOR_MAX: f64 = 4.0;
/// Bisection steps.
const BISECT: usize = 50;

/// One factor per profile: samples at uniform shared coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Factor {
    /// Index (0, 1) of the shared axis in the region view's points.
    pub ri: usize,
    pub lo: f64,
    pub hi: f64,
    pub samples: Vec<f64>,
}

impl Factor {
    /// The factor at shared coordinate `s` (Catmull-Rom, constant beyond
    /// the ends).
    pub fn at(&self, s: f64) -> f64 {
        let y = &self.samples;
        let n = y.len() - 1;
        let x = ((s - self.lo) / (self.hi - self.lo)).clamp(0.0, 1.0) * n as f64;
        let i = (x.floor() as usize).min(n - 1);
        let t = x - i as f64;
        let m = |j: usize| -> f64 {
            if j == 0 || j == n {
                0.0
            } else {
                0.5 * (y[j + 1] - y[j - 1])
            }
        };
        cubic_hermite(t, y[i], m(i), y[i + 1], m(i + 1))
    }
}

/// The factors of `profiles` for a height field `h` (uncorrected) over
/// `region`, host depth `depth` (None where the ray misses the part).
pub fn factors(
    region: &Region,
    profiles: &[ProfileCurve],
    h: impl Fn([f64; 2]) -> f64,
    depth: impl Fn([f64; 2]) -> Option<f64>,
) -> Vec<Factor> {
    let r = region.max_radius();
    let (c, n) = (region.centre, GRID);
    let coord = |k: usize, axis: usize| c[axis] - r + 2.0 * r * k as f64 / (n - 1) as f64;
    // grid: (host depth, height) inside the region
    let mut cells: Vec<Option<(f64, f64)>> = vec![None; n * n];
    let negative = h(c) < 0.0;
    for i in 0..n {
        for j in 0..n {
            let q = [coord(i, 0), coord(j, 1)];
            if region.polar(q).0.partial_cmp(&1.0) != Some(std::cmp::Ordering::Less) {
                continue;
            }
            if let Some(z) = depth(q) {
                cells[i * n + j] = Some((z, h(q)));
            }
        }
    }
    let mut out: Vec<Factor> = profiles
        .iter()
        .map(|pc| Factor {
            ri: pc.ri,
            lo: coord(0, pc.ri),
            hi: coord(n - 1, pc.ri),
            samples: vec![1.0; n],
        })
        .collect();
    if negative {
        return out;
    }
    for _ in 0..SWEEPS {
        for k in 0..profiles.len() {
            let ri = profiles[k].ri;
            for a in 0..n {
                let s = coord(a, ri);
                let Some(zp) = profiles[k].depth_at(s) else {
                    continue;
                };
                // the chord: cells with shared coordinate index a
                let chord: Vec<(f64, f64)> = (0..n)
                    .filter_map(|b| {
                        let (i, j) = if ri == 0 { (a, b) } else { (b, a) };
                        let (z, g) = cells[i * n + j]?;
                        let q = [coord(i, 0), coord(j, 1)];
                        let other: f64 = out
                            .iter()
                            .enumerate()
                            .filter(|(m, _)| *m != k)
                            .map(|(_, f)| f.samples_at(q))
                            .product();
                        Some((z, g * other))
                    })
                    .collect();
                if chord.is_empty() {
                    continue;
                }
                let top = |c: f64| {
                    chord
                        .iter()
                        .map(|(z, g)| z + c * g)
                        .fold(f64::MIN, f64::max)
                };
                out[k].samples[a] = if top(0.0) >= zp {
                    0.0
                } else if top(FACTOR_MAX) <= zp {
                    FACTOR_MAX
                } else {
                    let (mut lo, mut hi) = (0.0, FACTOR_MAX);
                    for _ in 0..BISECT {
                        let mid = 0.5 * (lo + hi);
                        if top(mid) < zp {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                    0.5 * (lo + hi)
                };
            }
        }
    }
    out
}

impl Factor {
    fn samples_at(&self, q: [f64; 2]) -> f64 {
        self.at(q[self.ri])
    }

    /// The product of `factors` at `q`.
    pub fn product(factors: &[Factor], q: [f64; 2]) -> f64 {
        factors.iter().map(|f| f.samples_at(q)).product()
    }
}

/// The cubic Hermite interpolant on `t` in [0, 1] from values `y0`, `y1`
/// and slopes `m0`, `m1` (per unit of `t`).
pub(crate) fn cubic_hermite(t: f64, y0: f64, m0: f64, y1: f64, m1: f64) -> f64 {
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * y0
        + (t3 - 2.0 * t2 + t) * m0
        + (-2.0 * t3 + 3.0 * t2) * y1
        + (t3 - t2) * m1
}
