//! One sketched component, end to end: stroke -> filtered polygon ->
//! skeleton -> weighted segments -> global interpolation (paper 003, sec 3).
//!
//! The component lives in its stroke's plane coordinates (the plane $z = 0$,
//! normal $+z$); [`super::model`] places it in the world.

use super::fit::{self, FitReport, RawSegment, Solver, WeightMode};
use super::kernel::{total_field, Segment};
use super::skeleton::{self, Skeleton, SkeletonOptions};
use super::stroke::{self, StrokeOptions};
use super::ConvError;

/// All options of the reconstruction (paper defaults). Outside the crate,
/// start from [`ConvOptions::default`] and change fields with the `with_*`
/// setters (or by assignment).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
#[non_exhaustive]
pub struct ConvOptions {
    /// Stroke filtering (default [`StrokeOptions::default`]).
    pub stroke: StrokeOptions,
    /// Skeleton extraction (default [`SkeletonOptions::default`]).
    pub skeleton: SkeletonOptions,
    /// Implicit surface threshold $T$ (default 1).
    pub threshold: f64,
    /// Kernel width $s$; `None` (the default): `s_scale` / mean skeleton
    /// radius.
    pub s: Option<f64>,
    /// Scale of the kernel width when `s` is `None` (default 1).
    pub s_scale: f64,
    /// Factor on the circle radii (default 0.8, the paper's).
    pub radius_factor: f64,
    /// How the segment weights are fitted (default [`WeightMode::Paper`]).
    pub weights: WeightMode,
    /// Divide endpoint weights by the number of segments meeting there
    /// (default true).
    pub divide_at_joints: bool,
    /// The weight solver (default [`Solver::HildrethDEsopo`]).
    pub solver: Solver,
}

setters!(ConvOptions {
    with_stroke: stroke: StrokeOptions,
    with_skeleton: skeleton: SkeletonOptions,
    with_threshold: threshold: f64,
    with_s: s: Option<f64>,
    with_s_scale: s_scale: f64,
    with_radius_factor: radius_factor: f64,
    with_weights: weights: WeightMode,
    with_divide_at_joints: divide_at_joints: bool,
    with_solver: solver: Solver,
});

impl Default for ConvOptions {
    fn default() -> Self {
        ConvOptions {
            stroke: StrokeOptions::default(),
            skeleton: SkeletonOptions::default(),
            threshold: 1.0,
            s: None,
            s_scale: 1.0,
            radius_factor: 0.8,
            weights: WeightMode::Paper,
            divide_at_joints: true,
            solver: Solver::HildrethDEsopo,
        }
    }
}

impl ConvOptions {
    /// Validates every option against its documented range (threshold and
    /// $s$ positive and finite, `s_scale` positive, `radius_factor` in
    /// (0, 2], `skeleton.overlap` in [0, 1], `skeleton.tiny` in [0, 1),
    /// `skeleton.area_samples` in 4..=1024, `stroke.dp_tolerance` in
    /// [0, 0.5), `stroke.spacing` in (1e-4, 0.25]) before any work.
    pub fn validate(&self) -> Result<(), ConvError> {
        // `{v:?}`: 1e300 as "1e300", not 301 digits
        let bad = |what: &str, v: f64| Err(ConvError::Parameter(format!("{what} {v:?}")));
        if !(self.threshold.is_finite() && self.threshold > 0.0) {
            return bad("threshold must be positive and finite, got", self.threshold);
        }
        if let Some(s) = self.s {
            if !(s.is_finite() && s > 0.0) {
                return bad("s must be positive and finite, got", s);
            }
        }
        if !(self.s_scale.is_finite() && self.s_scale > 0.0) {
            return bad("s_scale must be positive and finite, got", self.s_scale);
        }
        if !(self.radius_factor > 0.0 && self.radius_factor <= 2.0) {
            return bad("radius_factor must lie in (0, 2], got", self.radius_factor);
        }
        let sk = &self.skeleton;
        if !(0.0..=1.0).contains(&sk.overlap) {
            return bad("skeleton.overlap must lie in [0, 1], got", sk.overlap);
        }
        if !(0.0..1.0).contains(&sk.tiny) {
            return bad("skeleton.tiny must lie in [0, 1), got", sk.tiny);
        }
        if !(MIN_AREA_SAMPLES..=MAX_AREA_SAMPLES).contains(&sk.area_samples) {
            return Err(ConvError::Parameter(format!(
                "skeleton.area_samples must lie in {MIN_AREA_SAMPLES}..={MAX_AREA_SAMPLES}, got {}",
                sk.area_samples
            )));
        }
        let st = &self.stroke;
        if !(0.0..0.5).contains(&st.dp_tolerance) {
            return bad(
                "stroke.dp_tolerance must lie in [0, 0.5), got",
                st.dp_tolerance,
            );
        }
        if !(st.spacing > 1e-4 && st.spacing <= 0.25) {
            return bad("stroke.spacing must lie in (1e-4, 0.25], got", st.spacing);
        }
        Ok(())
    }
}

/// A reconstructed component in its plane coordinates.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Sketch {
    /// The filtered counter-clockwise polygon.
    pub polygon: Vec<[f64; 2]>,
    pub skeleton: Skeleton,
    /// Weighted segments (plane $z=0$), `lambda` from the global fit.
    pub segments: Vec<Segment>,
    pub s: f64,
    pub threshold: f64,
    pub fit: FitReport,
}

/// Documented range of [`SkeletonOptions::area_samples`].
pub const MIN_AREA_SAMPLES: usize = 4;
/// Upper end of the range of [`SkeletonOptions::area_samples`].
pub const MAX_AREA_SAMPLES: usize = 1024;

/// Nodes closer than this fraction of the smaller of their radii merge.
const MERGE_FRACTION: f64 = 0.1;
/// Half-length of the stand-in segment of a one-node skeleton, relative to
/// its radius.
const POINT_SEGMENT_HALF: f64 = 0.05;

/// Raw segments of a skeleton: coincident nodes merged, radii scaled.
pub fn raw_segments(sk: &Skeleton, radius_factor: f64) -> Vec<RawSegment> {
    let n = sk.nodes.len();
    // merge coincident nodes
    let mut rep: Vec<usize> = (0..n).collect();
    for i in 0..n {
        for j in 0..i {
            let near = MERGE_FRACTION * sk.radii[i].min(sk.radii[j]);
            if rep[j] == j && stroke::dist2(sk.nodes[i], sk.nodes[j]) <= near {
                rep[i] = j;
                break;
            }
        }
    }
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for e in &sk.edges {
        let (a, b) = (rep[e[0]], rep[e[1]]);
        if a != b && !edges.contains(&[a.min(b), a.max(b)]) {
            edges.push([a.min(b), a.max(b)]);
        }
    }
    let p3 = |i: usize| [sk.nodes[i][0], sk.nodes[i][1], 0.0];
    if edges.is_empty() {
        let i = (0..n)
            .max_by(|&a, &b| sk.radii[a].total_cmp(&sk.radii[b]))
            .unwrap_or(0);
        let (c, r) = (sk.nodes[i], sk.radii[i]);
        let d = POINT_SEGMENT_HALF * r;
        return vec![RawSegment {
            p: [c[0] - d, c[1], 0.0],
            q: [c[0] + d, c[1], 0.0],
            rp: r * radius_factor,
            rq: r * radius_factor,
            degree: [1, 1],
        }];
    }
    let mut degree = vec![0usize; n];
    for e in &edges {
        degree[e[0]] += 1;
        degree[e[1]] += 1;
    }
    edges
        .iter()
        .map(|e| RawSegment {
            p: p3(e[0]),
            q: p3(e[1]),
            rp: sk.radii[e[0]] * radius_factor,
            rq: sk.radii[e[1]] * radius_factor,
            degree: [degree[e[0]], degree[e[1]]],
        })
        .collect()
}

/// Refuses a skeleton extraction over the work budget before it starts:
/// each of the about `points` sleeve triangles weighs two circles by
/// `4 area_samples^2` point-in-polygon tests of `points` edges each, so
/// the work is about `8 area_samples^2 points^2`; the point count follows
/// from the stroke and `stroke.spacing` (a fraction of the perimeter): a
/// spacing of 1e-4 gives 10 000 points and 1e11 operations, minutes.
fn check_skeleton_work(points: usize, opts: &ConvOptions) -> Result<(), ConvError> {
    let (n, s) = (points as f64, opts.skeleton.area_samples as f64);
    let work = 8.0 * s * s * n * n;
    if work > crate::limits::CONV_WORK {
        return Err(ConvError::Parameter(format!(
            "the filtered stroke has {points} points: the skeleton's circle tests would need about {} operations (8 x area_samples^2 x points^2), over the budget of {}; raise stroke.spacing (now {}, a fraction of the perimeter) or lower skeleton.area_samples (now {})",
            crate::limits::Num(work),
            crate::limits::Num(crate::limits::CONV_WORK),
            crate::limits::Num(opts.stroke.spacing),
            opts.skeleton.area_samples
        )));
    }
    Ok(())
}

/// Refuses a global fit over the work budget before it starts: the fit
/// forms the normal equations of `points x segments` field values
/// (`points * segments^2`) and solves on the free face (`segments^3`); the
/// counts follow from the stroke and `stroke.spacing` (a fraction of the
/// perimeter), so a spacing at the bottom of its range on a long stroke
/// is refused by name instead of running for minutes.
fn check_fit_work(points: usize, segments: usize, opts: &ConvOptions) -> Result<(), ConvError> {
    let (m, n) = (points as f64, segments as f64);
    let work = m * n * n + n * n * n;
    if work > crate::limits::CONV_WORK {
        return Err(ConvError::Parameter(format!(
            "the filtered stroke has {points} points and {segments} skeleton segments: the global fit would need about {} operations, over the budget of {}; raise stroke.spacing (now {}, a fraction of the perimeter) or stroke.dp_tolerance",
            crate::limits::Num(work),
            crate::limits::Num(crate::limits::CONV_WORK),
            crate::limits::Num(opts.stroke.spacing)
        )));
    }
    Ok(())
}

/// Reconstructs a component from a raw closed stroke (plane coordinates).
pub fn build(raw_stroke: &[[f64; 2]], opts: &ConvOptions) -> Result<Sketch, ConvError> {
    opts.validate()?;
    let polygon = stroke::filter_stroke(raw_stroke, &opts.stroke)?;
    check_skeleton_work(polygon.len(), opts)?;
    let sk = skeleton::extract(&polygon, &opts.skeleton)?;
    let raws = raw_segments(&sk, opts.radius_factor);
    check_fit_work(polygon.len(), raws.len(), opts)?;
    let mean_r = raws.iter().map(|r| 0.5 * (r.rp + r.rq)).sum::<f64>() / raws.len() as f64;
    if !(mean_r.is_finite() && mean_r > 0.0) {
        return Err(ConvError::ZeroArea { area: 0.0 });
    }
    let s = opts.s.unwrap_or(opts.s_scale / mean_r);
    let mut segments = fit::weights(
        &raws,
        [0.0, 0.0, 1.0],
        opts.threshold,
        s,
        opts.weights,
        opts.divide_at_joints,
    )?;
    let points: Vec<[f64; 3]> = polygon.iter().map(|p| [p[0], p[1], 0.0]).collect();
    let report = fit::global_fit(&segments, &points, opts.threshold, s, opts.solver)?;
    if report.lambda.iter().all(|&l| l <= 0.0) {
        return Err(ConvError::Numerical(format!(
            "the global fit switched every segment off (lambda = 0; weights {:?}): no surface; \
             try the paper's weights or a larger s_scale",
            opts.weights
        )));
    }
    for (seg, l) in segments.iter_mut().zip(&report.lambda) {
        seg.lambda = *l;
    }
    Ok(Sketch {
        polygon,
        skeleton: sk,
        segments,
        s,
        threshold: opts.threshold,
        fit: report,
    })
}

impl Sketch {
    /// The field at a point of the plane coordinates.
    pub fn field(&self, r: [f64; 3]) -> f64 {
        total_field(&self.segments, r, self.s)
    }

    /// Size of the stroke (bounding-box diagonal of the polygon).
    pub fn size(&self) -> f64 {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &self.polygon {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        stroke::dist2(lo, hi)
    }
}
