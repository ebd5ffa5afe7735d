//! The feature's height field over its region, from the profile strokes.

use super::project::Projector;
use super::region::{centroid, Region};
use super::silhouette::cubic_hermite;
pub use super::silhouette::ProfileCurve;
use super::{axis_name, SasmError, Stroke};
use crate::character::part::PartSurface;
use crate::profile::View;
use std::f64::consts::PI;

/// Fraction of each radius (next to the curve) over which the height is
/// blended to zero with zero slope.
pub const BLEND: f64 = 0.2;
/// Samples of the height along each ray (rho from 0 to 1).
pub const RAY_SAMPLES: usize = 65;
/// Samples across the region when locating the peak.
const PEAK_SAMPLES: usize = 257;
/// Two profiles must agree on the height at the peak to this fraction.
pub const PEAK_AGREEMENT: f64 = 0.25;

/// A feature ready to apply: region and height along four rays.
#[derive(Clone, Debug, PartialEq)]
pub struct Feature {
    pub part: String,
    pub view: View,
    pub region: Region,
    /// Height samples on the rays right (phi = 0), up, left, down.
    pub rays: [Vec<f64>; 4],
    /// Largest |height| on the rays.
    pub peak: f64,
    pub profiles: Vec<ProfileCurve>,
    /// Silhouette correction factors, one per profile
    /// ([`super::silhouette`]).
    pub factors: Vec<super::silhouette::Factor>,
}

/// The profile curves of one or two `profiles` strokes, after checking
/// that the region `poly` projects onto the part (`pr`); refuses another
/// count of profiles and two profiles along the same axis.
fn profile_curves(
    pr: &Projector,
    view: View,
    poly: &[[f64; 2]],
    profiles: &[Stroke],
) -> Result<Vec<ProfileCurve>, SasmError> {
    if profiles.is_empty() || profiles.len() > 2 {
        return Err(SasmError::Shape {
            what: "profiles".into(),
            message: format!(
                "expected one or two profile strokes, got {}",
                profiles.len()
            ),
        });
    }
    super::project::project_stroke(pr, "curve", poly)?;
    let curves: Vec<ProfileCurve> = profiles
        .iter()
        .enumerate()
        .map(|(i, s)| ProfileCurve::new(s, view, i + 1))
        .collect::<Result<_, _>>()?;
    if curves.len() == 2 && curves[0].ri == curves[1].ri {
        return Err(SasmError::Shape {
            what: "profiles".into(),
            message: format!(
                "both profiles are drawn in views sharing the same axis with the {} view; use two different views",
                view
            ),
        });
    }
    Ok(curves)
}

/// The peak: along each profile's axis through the region's centroid (its
/// horizontal coordinate `axis` when given, then kept), the largest height
/// of the profile over the part (`depth`).
fn peak_centre(
    poly: &[[f64; 2]],
    axis: Option<f64>,
    curves: &[ProfileCurve],
    depth: &impl Fn([f64; 2]) -> Option<f64>,
) -> [f64; 2] {
    let mut c = centroid(poly);
    if let Some(a) = axis {
        c[0] = a;
    }
    let (lo, hi) = poly
        .iter()
        .fold(([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]), |(l, h), p| {
            (
                [l[0].min(p[0]), l[1].min(p[1])],
                [h[0].max(p[0]), h[1].max(p[1])],
            )
        });
    let c_start = c;
    for pc in curves {
        let ri = pc.ri;
        let mut best = (f64::NEG_INFINITY, c_start[ri]);
        for k in 1..PEAK_SAMPLES - 1 {
            let mut q = c_start;
            q[ri] = lo[ri] + (hi[ri] - lo[ri]) * k as f64 / (PEAK_SAMPLES - 1) as f64;
            if !crate::polygon::point_in_polygon(poly, q) {
                continue;
            }
            if let (Some(zp), Some(zh)) = (pc.depth_at(q[ri]), depth(q)) {
                if zp - zh > best.0 {
                    best = (zp - zh, q[ri]);
                }
            }
        }
        if ri == 0 && axis.is_some() {
            continue;
        }
        c[ri] = best.1;
    }
    c
}

/// The height samples on the rays along each profile's axis (both
/// directions): the profile's depth less the part's (`depth`), the last
/// profile depth carried into the blend zone where the profile ends early.
/// Which rays have samples (a missing pair's do not).
fn profile_rays(
    part: &PartSurface,
    view: View,
    region: &Region,
    curves: &[ProfileCurve],
    depth: &impl Fn([f64; 2]) -> Option<f64>,
) -> Result<([Vec<f64>; 4], [bool; 4]), SasmError> {
    let mut rays: [Vec<f64>; 4] = Default::default();
    let mut have = [false; 4];
    for pc in curves {
        let cov = pc.range();
        for k in [pc.ri, pc.ri + 2] {
            let phi = k as f64 * PI / 2.0;
            let mut e = Vec::with_capacity(RAY_SAMPLES);
            let mut last = None;
            for j in 0..RAY_SAMPLES {
                let rho = j as f64 / (RAY_SAMPLES - 1) as f64;
                let q = region.at(rho, phi);
                let zh = depth(q).ok_or_else(|| SasmError::Misses {
                    what: "the region's interior".into(),
                    part: part.name.clone(),
                    view,
                    index: j,
                    at: q,
                })?;
                let zp = match pc.depth_at(q[pc.ri]) {
                    Some(z) => z,
                    None if rho > 1.0 - BLEND => last.unwrap_or(zh),
                    None => {
                        let r0 = region.at(1.0 - BLEND, PI / 2.0 * pc.ri as f64);
                        let r1 = region.at(1.0 - BLEND, PI / 2.0 * (pc.ri + 2) as f64);
                        let (a, b) = (r0[pc.ri].min(r1[pc.ri]), r0[pc.ri].max(r1[pc.ri]));
                        return Err(SasmError::ProfileShort {
                            view: pc.view,
                            axis: axis_name([view.axes().0, view.axes().1][pc.ri]),
                            covered: cov,
                            needed: [a, b],
                        });
                    }
                };
                last = Some(zp);
                e.push(zp - zh);
            }
            rays[k] = e;
            have[k] = true;
        }
    }
    Ok((rays, have))
}

/// Fills a missing pair of rays (not `have`) with the mean of the other
/// pair, refuses pairs disagreeing at the peak by more than
/// [`PEAK_AGREEMENT`], and tilts the horizontal pair to meet the vertical
/// one there.
fn level_rays(rays: &mut [Vec<f64>; 4], have: [bool; 4]) -> Result<(), SasmError> {
    // a missing pair: the mean of the other pair
    for k in 0..2 {
        if !have[k] {
            let (a, b) = (&rays[k + 1], &rays[(k + 3) % 4]);
            let m: Vec<f64> = a.iter().zip(b).map(|(x, y)| 0.5 * (x + y)).collect();
            rays[k] = m.clone();
            rays[k + 2] = m;
        }
    }
    // both pairs must agree at the peak (the same point)
    let (e_v, e_h) = (rays[1][0], rays[0][0]);
    let scale = e_v.abs().max(e_h.abs());
    if (e_v - e_h).abs() > PEAK_AGREEMENT * scale {
        return Err(SasmError::Shape {
            what: "profiles".into(),
            message: format!(
                "the two profiles disagree on the feature's height at its peak ({e_v:.4} vs {e_h:.4})"
            ),
        });
    }
    for k in [0, 2] {
        for (j, v) in rays[k].iter_mut().enumerate() {
            let rho = j as f64 / (RAY_SAMPLES - 1) as f64;
            *v += (e_v - e_h) * (1.0 - rho);
        }
    }
    Ok(())
}

impl Feature {
    /// Builds a feature on `part` from a closed region polygon (already
    /// validated) in `view` and one or two profiles. `axis`: a fixed
    /// horizontal coordinate of the peak (the mirror axis of an auxiliary
    /// line).
    pub fn new(
        part: &PartSurface,
        view: View,
        poly: &[[f64; 2]],
        profiles: &[Stroke],
        axis: Option<f64>,
    ) -> Result<Feature, SasmError> {
        let pr = Projector::new(part, view);
        let curves = profile_curves(&pr, view, poly, profiles)?;
        let depth = |q: [f64; 2]| pr.cast(q).map(|h| pr.depth(h.point));
        let c = peak_centre(poly, axis, &curves, &depth);
        let region = Region::new(poly, c)?;
        let (mut rays, have) = profile_rays(part, view, &region, &curves, &depth)?;
        level_rays(&mut rays, have)?;
        let peak = rays.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        if peak.is_nan() || peak <= 0.0 {
            return Err(SasmError::Shape {
                what: "profiles".into(),
                message: "the profiles lie on the part: the feature has zero height".into(),
            });
        }
        let mut f = Feature {
            part: part.name.clone(),
            view,
            region,
            rays,
            peak,
            profiles: curves,
            factors: Vec::new(),
        };
        f.factors =
            super::silhouette::factors(&f.region, &f.profiles, |q| f.blended_height(q), depth);
        Ok(f)
    }

    /// Height along ray `k` at `rho` (cubic Hermite with Catmull-Rom
    /// slopes: C1 in rho).
    pub fn ray(&self, k: usize, rho: f64) -> f64 {
        let y = &self.rays[k];
        let n = y.len() - 1;
        let x = (rho.clamp(0.0, 1.0)) * n as f64;
        let i = (x.floor() as usize).min(n - 1);
        let t = x - i as f64;
        let m = |j: usize| -> f64 {
            if j == 0 {
                y[1] - y[0]
            } else if j == n {
                y[n] - y[n - 1]
            } else {
                0.5 * (y[j + 1] - y[j - 1])
            }
        };
        cubic_hermite(t, y[i], m(i), y[i + 1], m(i + 1))
    }

    /// The height at a view-plane point (0 outside the region): the
    /// blended height times the silhouette factors, which fade to 1 over
    /// the blend band (the same smoothstep), so that next to the curve the
    /// height is the blended one and the join stays C1.
    pub fn height(&self, q: [f64; 2]) -> f64 {
        let h = self.blended_height(q);
        if h == 0.0 {
            return 0.0;
        }
        let w = smooth((1.0 - self.region.polar(q).0) / BLEND);
        h * (1.0 + (super::silhouette::Factor::product(&self.factors, q) - 1.0) * w)
    }

    /// The height before the silhouette correction: the rays blended in
    /// angle, brought to zero with zero slope at the curve.
    pub fn blended_height(&self, q: [f64; 2]) -> f64 {
        let (rho, phi) = self.region.polar(q);
        if rho.is_nan() || rho >= 1.0 {
            return 0.0;
        }
        let (c, s) = (phi.cos(), phi.sin());
        let (c2, s2) = (c * c, s * s);
        let w = [
            if c > 0.0 { c2 } else { 0.0 },
            if s > 0.0 { s2 } else { 0.0 },
            if c < 0.0 { c2 } else { 0.0 },
            if s < 0.0 { s2 } else { 0.0 },
        ];
        let v: f64 = (0..4)
            .filter(|&k| w[k] > 0.0)
            .map(|k| w[k] * self.ray(k, rho))
            .sum();
        v * smooth((1.0 - rho) / BLEND)
    }

    /// Builds a feature from a [`super::SasmSpec`].
    pub fn from_spec(part: &PartSurface, s: &super::SasmSpec) -> Result<Feature, SasmError> {
        check_part(part, &s.part)?;
        let poly = super::closed_polygon("curve", &s.curve.points)?;
        Feature::new(part, s.curve.view, &poly, &s.profiles, None)
    }

    /// Builds a feature from an [`super::AuxSpec`].
    pub fn from_aux(part: &PartSurface, s: &super::AuxSpec) -> Result<Feature, SasmError> {
        check_part(part, &s.part)?;
        let poly = super::mirrored_polygon("auxiliary line", &s.line.points, s.mirror)?;
        Feature::new(
            part,
            s.line.view,
            &poly,
            std::slice::from_ref(&s.profile),
            Some(s.mirror),
        )
    }
}

/// `3 t^2 - 2 t^3` on `[0, 1]`, 1 beyond (0 below).
fn smooth(t: f64) -> f64 {
    if t >= 1.0 {
        1.0
    } else if t <= 0.0 {
        0.0
    } else {
        t * t * (3.0 - 2.0 * t)
    }
}

fn check_part(part: &PartSurface, name: &str) -> Result<(), SasmError> {
    if part.name != name {
        return Err(SasmError::UnknownPart(name.into()));
    }
    Ok(())
}
