//! The high level (000 sec 4.2.3): key cross-section curves at chosen
//! heights, GEC-fitted, pull the medium-level model's sections onto them.
//!
//! Each sketched loop (points in the horizontal plane, `(x, z)`) is fitted by
//! a generalized elliptic curve ([`crate::curve::gec::fit`]) and sampled; the
//! model is sliced at the same height ([`crate::mesh::slice`]); each sketched
//! loop is paired with the model loop whose centroid is nearest. Points
//! correspond ([`SectionMatch`]) either radially (default: each model point
//! moves along the ray from its loop's centroid to where that ray crosses
//! the sketched loop, so a bulge moves the skin outwards instead of sliding
//! it around the loop) or by arc-length fraction from each loop's front-most
//! point (largest z). Two 3D biharmonic splines ($\varphi = r$, linear part)
//! carry the x and z displacements of the section points to every vertex,
//! with zero x displacement at vertices on the front silhouette and zero z
//! displacement at vertices on the side silhouette (away from the
//! sections), so the primary and secondary profiles stay where the lower
//! levels put them, and zero displacement at vertices more than
//! [`BAND_MARGIN`] of the height above or below the outermost sections, so
//! the key sections only reshape the part they cut (the biharmonic spline
//! is global: without these anchors a torso section moves head and feet).

use super::options::{FitOptions, Level, LevelReport, Template};
pub use super::options::{SectionMatch, SectionSketch};
use super::polygon::{boundary_distance, cumulative, point_at, validated};
use super::rbf::Rbf;
use super::TemplateError;
use crate::curve::gec::{self, Frame};
use crate::mesh::slice::slice;

/// Vertices within this fraction of the height from an outline are on the
/// silhouette (anchors).
pub const ANCHOR_BAND: f64 = 3e-3;
/// Anchors closer than this fraction of the height to a section's height
/// are dropped (the section decides there).
pub const SECTION_CLEARANCE: f64 = 0.01;
/// Vertices farther than this fraction of the height below the lowest or
/// above the highest section do not move at the high level.
pub const BAND_MARGIN: f64 = 0.04;

/// Where the ray from `c` through `p` crosses the closed polygon `poly`
/// (the crossing nearest to `p` along the ray); the nearest point of the
/// polygon when the ray misses it.
pub fn ray_partner(poly: &[[f64; 2]], c: [f64; 2], p: [f64; 2]) -> [f64; 2] {
    let d = [p[0] - c[0], p[1] - c[1]];
    let n = poly.len();
    let mut best: Option<(f64, [f64; 2])> = None;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let den = d[0] * e[1] - d[1] * e[0];
        if den.abs() <= f64::EPSILON * (d[0].hypot(d[1]) * e[0].hypot(e[1])) {
            continue;
        }
        let w = [a[0] - c[0], a[1] - c[1]];
        let t = (w[0] * e[1] - w[1] * e[0]) / den;
        let u = (w[0] * d[1] - w[1] * d[0]) / den;
        if t > 0.0
            && (0.0..=1.0).contains(&u)
            && best.is_none_or(|(bt, _)| (t - 1.0).abs() < (bt - 1.0).abs())
        {
            best = Some((t, [c[0] + t * d[0], c[1] + t * d[1]]));
        }
    }
    if let Some((_, q)) = best {
        return q;
    }
    let mut near = (f64::INFINITY, p);
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let l2 = (e[0] * e[0] + e[1] * e[1]).max(f64::MIN_POSITIVE);
        let t = (((p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1]) / l2).clamp(0.0, 1.0);
        let q = [a[0] + t * e[0], a[1] + t * e[1]];
        let dd = (q[0] - p[0]).hypot(q[1] - p[1]);
        if dd < near.0 {
            near = (dd, q);
        }
    }
    near.1
}

/// A loop GEC-fitted with `terms` terms and sampled at `m` points.
pub fn gec_loop(
    y: f64,
    points: &[[f64; 2]],
    terms: usize,
    m: usize,
) -> Result<Vec<[f64; 2]>, TemplateError> {
    let err = |problem: String| TemplateError::Section { y, problem };
    let frame = Frame::new([0.0, y, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0])
        .map_err(|e| err(e.to_string()))?;
    let pts: Vec<[f64; 3]> = points.iter().map(|p| [p[0], y, p[1]]).collect();
    let mut opts = gec::fit::FitOptions::new(terms.min(points.len().saturating_sub(1) / 2).max(1));
    opts.frame = gec::fit::FrameChoice::Given(frame);
    let rep = gec::fit::fit(&pts, &opts).map_err(|e| err(format!("GEC fit: {e}")))?;
    Ok(rep.gec.sample_plane(m))
}

/// The sketched loop GEC-fitted ([`gec_loop`]) when the fitted curve is a
/// simple loop; otherwise (a deep notch, e.g. the cleft of a section just
/// above the crotch, makes the truncated Fourier series ring into a
/// self-intersection) the sketched loop itself, `m` points by arc length.
pub fn gec_or_sketched(
    y: f64,
    lp: &[[f64; 2]],
    terms: usize,
    m: usize,
) -> Result<Vec<[f64; 2]>, TemplateError> {
    let what = format!("cross-section at y = {y}");
    match validated(&what, &gec_loop(y, lp, terms, m)?) {
        Ok(t) => Ok(t),
        Err(_) => {
            let cum = cumulative(lp);
            let per = cum[lp.len()];
            validated(
                &what,
                &(0..m)
                    .map(|k| point_at(lp, &cum, per * k as f64 / m as f64))
                    .collect::<Vec<_>>(),
            )
        }
    }
}

fn centroid(p: &[[f64; 2]]) -> [f64; 2] {
    let n = p.len() as f64;
    p.iter()
        .fold([0.0; 2], |c, q| [c[0] + q[0] / n, c[1] + q[1] / n])
}

/// `m` points by arc length from the point of largest second coordinate.
fn from_front(p: &[[f64; 2]], m: usize) -> Vec<[f64; 2]> {
    let start = (0..p.len())
        .max_by(|&a, &b| p[a][1].total_cmp(&p[b][1]))
        .unwrap_or(0);
    let cum = cumulative(p);
    let per = cum[p.len()];
    (0..m)
        .map(|k| point_at(p, &cum, cum[start] + per * k as f64 / m as f64))
        .collect()
}

/// A model point in 3D and its target `(x, z)`.
pub type SectionPair = ([f64; 3], [f64; 2]);

/// Pairs of (model point in 3D, target `(x, z)`) for every sketched loop.
pub fn section_pairs(
    skin: &crate::mesh::Mesh,
    s: &super::sections::SectionSketch,
    opts: &FitOptions,
) -> Result<Vec<SectionPair>, TemplateError> {
    let err = |problem: String| TemplateError::Section { y: s.y, problem };
    let model: Vec<Vec<[f64; 2]>> = slice(skin, [0.0, s.y, 0.0], [0.0, 1.0, 0.0])
        .into_iter()
        .filter(|l| l.closed && l.points.len() >= 3)
        .filter_map(|l| {
            validated(
                "model section",
                &l.points.iter().map(|p| [p[0], p[2]]).collect::<Vec<_>>(),
            )
            .ok()
        })
        .collect();
    if model.is_empty() {
        return Err(err(
            "the model has no closed cross-section at this height".into()
        ));
    }
    if s.loops.is_empty() {
        return Err(err("no loops given".into()));
    }
    let mut out = Vec::new();
    let mut used = vec![false; model.len()];
    for (k, lp) in s.loops.iter().enumerate() {
        let what = format!("cross-section at y = {}, loop {k}", s.y);
        let lp = validated(&what, lp)?;
        let target = gec_or_sketched(s.y, &lp, opts.gec_terms, 4 * opts.section_points)?;
        let c = centroid(&target);
        let (best, _) = model
            .iter()
            .enumerate()
            .map(|(i, m)| {
                let d = centroid(m);
                (i, (d[0] - c[0]).powi(2) + (d[1] - c[1]).powi(2))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .ok_or_else(|| err("no model loop".into()))?;
        if used[best] {
            return Err(err(format!(
                "loop {k} pairs with a model loop already paired with another sketched loop"
            )));
        }
        used[best] = true;
        let a = from_front(&model[best], opts.section_points);
        let b = match opts.section_match {
            SectionMatch::ArcLength => from_front(&target, opts.section_points),
            SectionMatch::Radial => {
                let c = centroid(&model[best]);
                a.iter().map(|&p| ray_partner(&target, c, p)).collect()
            }
        };
        out.extend(a.iter().zip(&b).map(|(p, q)| ([p[0], s.y, p[1]], *q)));
    }
    Ok(out)
}

/// The high level: moves `medium` (every template vertex) so its sections
/// at the sketched heights land on the sketched loops.
pub fn fit_sections(
    template: &Template,
    medium: &[[f64; 3]],
    front: &[[f64; 2]],
    side: &[[f64; 2]],
    sections: &[SectionSketch],
    opts: &FitOptions,
) -> Result<(LevelReport, Vec<[f64; 3]>), TemplateError> {
    let skin = template.skin_at(medium);
    let h = template.height().max(f64::MIN_POSITIVE);
    let mut pairs = Vec::new();
    for s in sections {
        if !s.y.is_finite() {
            return Err(TemplateError::Section {
                y: s.y,
                problem: "height is not finite".into(),
            });
        }
        pairs.extend(section_pairs(&skin, s, opts)?);
    }
    let (ylo, yhi) = sections
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, u), s| {
            (l.min(s.y), u.max(s.y))
        });
    let banded = opts.band_anchors > 0;
    let in_band = |y: f64| !banded || (y > ylo - BAND_MARGIN * h && y < yhi + BAND_MARGIN * h);
    let clear = |y: f64| {
        in_band(y)
            && sections
                .iter()
                .all(|s| (y - s.y).abs() > SECTION_CLEARANCE * h)
    };
    let band = if banded {
        out_of_band(&skin.positions, in_band, opts.band_anchors)
    } else {
        Vec::new()
    };
    let anchors = |outline: &[[f64; 2]], proj: fn(&[f64; 3]) -> [f64; 2]| -> Vec<[f64; 3]> {
        let all: Vec<[f64; 3]> = skin
            .positions
            .iter()
            .filter(|p| clear(p[1]) && boundary_distance(outline, proj(p)) < ANCHOR_BAND * h)
            .copied()
            .collect();
        let step = all.len().div_ceil(opts.anchors.max(1)).max(1);
        all.into_iter().step_by(step).collect()
    };
    let mut fa = anchors(front, |p| [p[0], p[1]]);
    let mut sa = anchors(side, |p| [p[2], p[1]]);
    fa.extend_from_slice(&band);
    sa.extend_from_slice(&band);
    let field =
        |comp: usize, anch: &[[f64; 3]], stage: &'static str| -> Result<Rbf<3, 1>, TemplateError> {
            let mut c: Vec<[f64; 3]> = pairs.iter().map(|(p, _)| *p).collect();
            let mut v: Vec<[f64; 1]> = pairs
                .iter()
                .map(|(p, q)| [q[comp] - if comp == 0 { p[0] } else { p[2] }])
                .collect();
            c.extend_from_slice(anch);
            v.extend(anch.iter().map(|_| [0.0]));
            Rbf::<3, 1>::fit(&c, &v, opts.condition)
                .map_err(|source| TemplateError::Rbf { stage, source })
        };
    let dx = field(0, &fa, "cross-section x field")?;
    let dz = field(1, &sa, "cross-section z field")?;
    let high: Vec<[f64; 3]> = medium
        .iter()
        .map(|p| [p[0] + dx.eval(p)[0], p[1], p[2] + dz.eval(p)[0]])
        .collect();
    let maxd = medium
        .iter()
        .zip(&high)
        .map(|(a, b)| ((a[0] - b[0]).powi(2) + (a[2] - b[2]).powi(2)).sqrt())
        .fold(0.0, f64::max);
    let condition = match (dx.condition, dz.condition) {
        (Some(a), Some(b)) => Some(a.max(b)),
        _ => None,
    };
    Ok((
        LevelReport {
            level: Level::High,
            centres: dx.len() + dz.len(),
            condition,
            residual: dx.residual.max(dz.residual),
            max_displacement: maxd,
            passes: 0,
            profiles: Vec::new(),
            seconds: 0.0,
        },
        high,
    ))
}

/// About `n` distinct skin points outside the sections' band (every
/// k-th of them), held in place by the fit.
fn out_of_band(positions: &[[f64; 3]], in_band: impl Fn(f64) -> bool, n: usize) -> Vec<[f64; 3]> {
    let mut seen = std::collections::HashSet::new();
    let all: Vec<[f64; 3]> = positions
        .iter()
        .filter(|p| !in_band(p[1]))
        .filter(|p| seen.insert(p.map(f64::to_bits)))
        .copied()
        .collect();
    let step = all.len().div_ceil(n).max(1);
    all.into_iter().step_by(step).collect()
}
