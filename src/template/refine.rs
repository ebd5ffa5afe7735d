//! The fit checks its own result (issue 12: "profiles of the fitted mesh
//! match the sketched ones within 0.5 % of height, at every level").
//!
//! After each level the fitted skin's outline is extracted again (with the
//! same outline function the fit used for the template) and compared with
//! the sketch by [`crate::profile::profile_distance`] (symmetric, sampled
//! Hausdorff distance divided by the sketch's height). While a view misses
//! the tolerance, a *correction pass* repeats that level's warp from the
//! fitted state: landmarks on the fitted outline and the sketch,
//! arc-length correspondence, a thin-plate warp of the residual (front:
//! both plane coordinates; side: depth only), applied to every vertex. The
//! residual warps are small, so the passes converge quickly when the warp
//! is one-to-one. A view still off after [`FitOptions::passes`] passes is
//! an error ([`OnMiss::Fail`], the default) or reported in the level's
//! [`ViewFit`] ([`OnMiss::Report`]). A fitted outline that is not a simple
//! closed polygon (the warp folded the silhouette) is always an error.

use super::landmarks::correspond;
use super::options::{level_partner, matched_landmarks, FitOptions, Level, Template, STEEP};
pub use super::options::{DepthMap, OnMiss, SidePartner, ViewFit, DEPTH_FALLOFF};
pub use super::outlines::{arm_mask, side_outlines, SideOutlines, ARM_MARGIN};
use super::rbf::Rbf;
use super::{OutlineFn, TemplateError, View};
pub use crate::polygon::depth_span;
use crate::profile::{profile_distance, Profile};

/// The fitted skin's outline in `view` against the sketched profile:
/// max distance / sketch height. Errors when the fitted outline is not a
/// simple closed polygon.
pub fn measure(
    template: &Template,
    positions: &[[f64; 3]],
    view: View,
    sketch: &[[f64; 2]],
    outline: &OutlineFn,
) -> Result<f64, TemplateError> {
    let fitted = outline(&template.skin_at(positions), view)?;
    let fitted = Profile::new(view, fitted).map_err(|e| TemplateError::BadProfile {
        what: format!("the fitted mesh's {} outline", view.name()),
        problem: format!("{e} (the warp folded the silhouette)"),
    })?;
    let sketched = Profile::new(view, sketch.to_vec()).map_err(|e| TemplateError::BadProfile {
        what: format!("the sketched {} profile", view.name()),
        problem: e.to_string(),
    })?;
    Ok(profile_distance(&fitted, &sketched).max_rel)
}

/// A measured view, checked against the tolerance.
pub fn view_fit(view: View, max_rel: f64, opts: &FitOptions) -> ViewFit {
    ViewFit {
        view,
        max_rel,
        within: max_rel <= opts.tolerance,
    }
}

/// The error (or nothing) for the level's measured views.
pub fn enforce(
    level: Level,
    fits: &[ViewFit],
    passes: usize,
    opts: &FitOptions,
) -> Result<(), TemplateError> {
    if opts.on_miss == OnMiss::Report {
        return Ok(());
    }
    match fits.iter().find(|f| !f.within) {
        None => Ok(()),
        Some(f) => Err(TemplateError::ProfileMiss {
            level: level.name(),
            view: f.view.name().into(),
            percent: 100.0 * f.max_rel,
            tolerance: 100.0 * opts.tolerance,
            passes,
        }),
    }
}

/// Statistics of the warps of one level (first pass and corrections).
#[derive(Clone, Copy, Debug, Default)]
pub struct WarpStats {
    pub centres: usize,
    pub condition: Option<f64>,
    pub residual: f64,
}

impl WarpStats {
    pub fn add<const D: usize, const M: usize>(&mut self, r: &Rbf<D, M>) {
        self.centres += r.len();
        self.residual = self.residual.max(r.residual);
        self.condition = match (self.condition, r.condition) {
            (Some(a), Some(b)) => Some(a.max(b)),
            (a, b) => a.or(b),
        };
    }
}

/// The front thin-plate warp taking the corresponded points `ca` to `cb`,
/// applied to the (x, y) of every position.
pub fn front_warp(
    positions: &mut [[f64; 3]],
    ca: &[[f64; 2]],
    cb: &[[f64; 2]],
    opts: &FitOptions,
    stats: &mut WarpStats,
) -> Result<(), TemplateError> {
    let values: Vec<[f64; 2]> = ca
        .iter()
        .zip(cb)
        .map(|(a, b)| [b[0] - a[0], b[1] - a[1]])
        .collect();
    let warp =
        Rbf::<2, 2>::fit(ca, &values, opts.condition).map_err(|source| TemplateError::Rbf {
            stage: "front warp",
            source,
        })?;
    for p in positions.iter_mut() {
        let d = warp.eval(&[p[0], p[1]]);
        p[0] += d[0];
        p[1] += d[1];
    }
    stats.add(&warp);
    Ok(())
}

/// One front correction pass from the fitted state `positions`.
pub fn front_pass(
    template: &Template,
    positions: &mut [[f64; 3]],
    front: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
    stats: &mut WarpStats,
) -> Result<(), TemplateError> {
    let o = outline(&template.skin_at(positions), View::Front)?;
    let o = super::polygon::validated("the fitted front outline", &o)?;
    let (lo, ls) = matched_landmarks(View::Front, opts.front_scheme, &o, front)?;
    let (ca, cb) = correspond(&o, &lo, front, &ls, opts.front_centres);
    front_warp(positions, &ca, &cb, opts, stats)
}

/// One side (depth-only) pass from `positions`: the side outline of the
/// fitted skin onto the sketched side profile. Only points where the
/// outline is steep (|dy/ds| >= [`STEEP`]) are centres, each moving in
/// depth to a crossing of the sketch at the same height
/// ([`FitOptions::side_partner`]: heading the same way and nearest to the
/// point, or nearest to its arc-length partner). Shallow stretches (soles, the top of the head, under
/// the chin or a belly) take the interpolated depth change of their steep
/// neighbours: with only three side landmarks (head, heel, toe) their
/// arc-length partners can be on another part of the body (a boy's chin
/// partnered with the template's neck), which moved vertices by up to 10 %
/// of the height in the MakeHuman study. The depth change is an affine
/// map of depth (the body's overall thickness and offset,
/// [`FitOptions::depth_map`]) plus the partners' residuals, interpolated
/// along the outline by a thin-plate spline and applied with
/// [`FitOptions::depth_falloff`] weights of the
/// vertex's relative depth in its part's depth span at its height, smoothed
/// over heights so the weights are continuous ([`super::weights`]).
pub fn side_pass(
    template: &Template,
    positions: &mut [[f64; 3]],
    side: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
    stats: &mut WarpStats,
) -> Result<(), TemplateError> {
    // with the envelope partners and `side_trunk`, the trunk's outline
    // (arms left out: a forearm in front of the belly hides it in the side
    // view)
    if opts.side_landmarks {
        super::weights::remap_heights(template, positions, side, opts, outline)?;
    }
    let trunk = opts.side_partner == SidePartner::Envelope && opts.side_trunk;
    let (o, arms) = side_outlines(template, positions, trunk, opts, outline)?;
    let ot: &[[f64; 2]] = arms.as_ref().map_or(&o, |(_, t)| t);
    let (lo, ls) = matched_landmarks(View::Side, opts.side_scheme, ot, side)?;
    let (ca, cb) = correspond(ot, &lo, side, &ls, opts.side_centres);
    let m = ca.len();
    let eps = ENVELOPE_EPS * template.height().max(f64::MIN_POSITIVE);
    let (mut centres, mut values) = (Vec::with_capacity(m), Vec::with_capacity(m));
    for i in 0..m {
        let (a, b) = (ca[i], cb[i]);
        let (p, q) = (ca[(i + m - 1) % m], ca[(i + 1) % m]);
        let len = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2))
            .sqrt()
            .max(f64::MIN_POSITIVE);
        let dy = (q[1] - p[1]) / len;
        if dy.abs() < STEEP {
            continue;
        }
        let z = match opts.side_partner {
            SidePartner::ArcLength => Some(level_partner(side, a[1], b[0])),
            SidePartner::Heading => Some(heading_partner(side, a[1], a[0], dy > 0.0)),
            SidePartner::Envelope => envelope_partner(&o, ot, side, a, eps, false),
        };
        if let Some(z) = z {
            centres.push(a);
            values.push([z - a[0]]);
        }
    }
    // an affine depth map z -> k z + c of the partners first (global
    // thickness and offset), then the residuals as a thin-plate field
    // applied with the vertex's relative depth at its height
    let (k, c) = match opts.depth_map {
        DepthMap::None => (1.0, 0.0),
        DepthMap::LeastSquares => affine_fit(&centres, &values, &vec![1.0; centres.len()]),
        DepthMap::Robust => robust_affine(&centres, &values),
    };
    let affine = |z: f64| k * z + c - z;
    let residual: Vec<[f64; 1]> = centres
        .iter()
        .zip(&values)
        .map(|(c, v)| [v[0] - affine(c[0])])
        .collect();
    let depth = Rbf::<2, 1>::fit(&centres, &residual, opts.condition).map_err(|source| {
        TemplateError::Rbf {
            stage: "side depth warp",
            source,
        }
    })?;
    // the vertex's part's span, smoothed over heights (continuous weights:
    // [`super::weights`])
    let spans = super::weights::DepthSpans::new(template, positions, &o, opts, outline)?;
    for (i, p) in positions.iter_mut().enumerate() {
        let (y, z) = (p[1], p[2]);
        if arms.as_ref().is_some_and(|(a, _)| a[i]) {
            // arms take the body's overall depth map only
            p[2] += affine(z);
            continue;
        }
        let r = match spans.at(i, y) {
            Some((zb, zf)) if zf > zb => {
                let s = super::weights::relative_depth(z, (zb, zf));
                // read at the vertex's own depth when it lies beyond the
                // smoothed span (on the outline: its partner's residual)
                let (ef, eb) = (zf.max(z), zb.min(z));
                s.powi(opts.depth_falloff) * depth.eval(&[ef, y])[0]
                    + (1.0 - s).powi(opts.depth_falloff) * depth.eval(&[eb, y])[0]
            }
            _ => depth.eval(&[z, y])[0],
        };
        p[2] += affine(z) + r;
    }
    stats.add(&depth);
    Ok(())
}

/// Outline points within this fraction of the height of their height's
/// front-most (back-most) crossing are on the envelope.
pub const ENVELOPE_EPS: f64 = 1e-3;

/// The sketch's front-most (back-most) crossing at `a`'s height when `a` is
/// the front-most (back-most) crossing of the trunk's outline `trunk` at
/// that height (within `eps`) and either also of the whole outline `full`
/// or (with `hidden`) hidden behind an arm that the sketch's crossing lies
/// beyond; `None` otherwise (points inside the span, hidden points). The
/// side pass does not partner hidden points: a sketch's crossing beyond
/// the model's arm can be the sketch's arm (a fat man's hands) as well as
/// a bulge (a pregnant belly), and the first moved the MakeHuman male->fat
/// belly by 10 % of the height.
pub fn envelope_partner(
    full: &[[f64; 2]],
    trunk: &[[f64; 2]],
    side: &[[f64; 2]],
    a: [f64; 2],
    eps: f64,
    hidden: bool,
) -> Option<f64> {
    let (zb, zf) = depth_span(trunk, a[1])?;
    let (fb, ff) = depth_span(full, a[1]).unwrap_or((zb, zf));
    let (sb, sf) = depth_span(side, a[1])?;
    if zf - zb <= eps {
        None
    } else if zf - a[0] <= eps {
        (ff - zf <= eps || (hidden && sf > ff + eps)).then_some(sf)
    } else if a[0] - zb <= eps {
        (zb - fb <= eps || (hidden && sb < fb - eps)).then_some(sb)
    } else {
        None
    }
}

/// The crossing of the horizontal line at height `y` with the closed
/// counter-clockwise polygon `p` on an edge heading up (`up`) or down,
/// nearest to `near`; [`level_partner`] when there is none.
pub fn heading_partner(p: &[[f64; 2]], y: f64, near: f64, up: bool) -> f64 {
    let n = p.len();
    let mut best: Option<(f64, f64)> = None;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] - y) * (b[1] - y) > 0.0 || a[1] == b[1] || (b[1] > a[1]) != up {
            continue;
        }
        let x = a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
        if best.is_none_or(|(d, _)| (x - near).abs() < d) {
            best = Some(((x - near).abs(), x));
        }
    }
    best.map_or_else(|| level_partner(p, y, near), |(_, x)| x)
}

/// Weighted least-squares `(k, c)` of `z + v = k z + c` over the centres'
/// depths `z` and values `v`.
pub fn affine_fit(centres: &[[f64; 2]], values: &[[f64; 1]], w: &[f64]) -> (f64, f64) {
    let sw: f64 = w.iter().sum();
    if sw <= 0.0 {
        return (1.0, 0.0);
    }
    let (mut mz, mut mt) = (0.0, 0.0);
    for ((c, v), w) in centres.iter().zip(values).zip(w) {
        mz += w * c[0] / sw;
        mt += w * (c[0] + v[0]) / sw;
    }
    let (mut szz, mut szt) = (0.0, 0.0);
    for ((c, v), w) in centres.iter().zip(values).zip(w) {
        szz += w * (c[0] - mz).powi(2);
        szt += w * (c[0] - mz) * (c[0] + v[0] - mt);
    }
    let k = if szz > 0.0 { szt / szz } else { 1.0 };
    (k, mt - k * mz)
}

/// Tukey's biweight tuning constant (95 % efficiency).
const TUKEY: f64 = 4.685;

/// [`affine_fit`] reweighted by Tukey's biweight of the residuals (scale
/// from their median absolute deviation), 10 iterations.
pub fn robust_affine(centres: &[[f64; 2]], values: &[[f64; 1]]) -> (f64, f64) {
    let n = centres.len();
    let mut w = vec![1.0; n];
    let (mut k, mut c) = affine_fit(centres, values, &w);
    let span = centres
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[1]), h.max(p[1]))
        });
    let floor = 1e-4 * (span.1 - span.0).abs().max(f64::MIN_POSITIVE);
    for _ in 0..10 {
        let r: Vec<f64> = centres
            .iter()
            .zip(values)
            .map(|(p, v)| p[0] + v[0] - (k * p[0] + c))
            .collect();
        let mut a: Vec<f64> = r.iter().map(|x| x.abs()).collect();
        a.sort_by(f64::total_cmp);
        let mad = a.get(n / 2).copied().unwrap_or(0.0);
        let scale = (1.4826 * mad).max(floor) * TUKEY;
        for (w, r) in w.iter_mut().zip(&r) {
            let u = r / scale;
            *w = if u.abs() < 1.0 {
                (1.0 - u * u).powi(2)
            } else {
                0.0
            };
        }
        (k, c) = affine_fit(centres, values, &w);
    }
    (k, c)
}
