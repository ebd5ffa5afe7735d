//! Outline queries used by the segmentation: horizontal slices of a simple
//! closed polygon and the tops of the gaps between its limbs.

/// The inside intervals `[x0, x1]` of the horizontal line at height `y`,
/// sorted by x (even-odd rule; the polygon is simple, closure implied).
pub fn slice(points: &[[f64; 2]], y: f64) -> Vec<[f64; 2]> {
    crossings(points, 1, y)
        .chunks_exact(2)
        .map(|c| [c[0], c[1]])
        .collect()
}

/// Where the line `p[axis] = at` crosses the polygon's edges: the other
/// coordinate of each crossing, sorted (an edge counts when `at` is in
/// `[min, max)` of its ends along `axis`: each crossing once, even-odd).
fn crossings(points: &[[f64; 2]], axis: usize, at: f64) -> Vec<f64> {
    let other = 1 - axis;
    let n = points.len();
    let mut out = Vec::new();
    for i in 0..n {
        let a = points[i];
        let b = points[(i + 1) % n];
        let (lo, hi) = if a[axis] < b[axis] { (a, b) } else { (b, a) };
        if at >= lo[axis] && at < hi[axis] {
            let t = (at - lo[axis]) / (hi[axis] - lo[axis]);
            out.push(lo[other] + t * (hi[other] - lo[other]));
        }
    }
    out.sort_by(f64::total_cmp);
    out
}

/// A gap between two limbs closing at its top: the point where, going up,
/// two consecutive slice intervals merge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GapTop {
    pub x: f64,
    pub y: f64,
}

/// The tops of all gaps, found on `n` slices and refined by bisection.
///
/// Near the top of a leaning gap, narrower there than the sideways move
/// of its middle from one slice to the next, the middle of a slice's gap
/// lies inside a limb one slice higher, so the gap is reported on each of
/// its last few slices: callers merge those with [`merge_repeats`].
pub fn gap_tops(points: &[[f64; 2]], n: usize) -> Vec<GapTop> {
    let yr = crate::polygon::span(points, 1);
    let h = yr[1] - yr[0];
    let ys: Vec<f64> = (0..n)
        .map(|k| yr[0] + h * (k as f64 + 0.5) / n as f64)
        .collect();
    let mut out = Vec::new();
    for k in 0..n - 1 {
        let lo = slice(points, ys[k]);
        let hi = slice(points, ys[k + 1]);
        for w in lo.windows(2) {
            let gx = 0.5 * (w[0][1] + w[1][0]);
            // the gap is closed above when one interval of `hi` covers gx
            if hi.iter().any(|iv| iv[0] <= gx && gx <= iv[1]) {
                let (mut a, mut b) = (ys[k], ys[k + 1]);
                for _ in 0..40 {
                    let m = 0.5 * (a + b);
                    if slice(points, m).iter().any(|iv| iv[0] <= gx && gx <= iv[1]) {
                        b = m;
                    } else {
                        a = m;
                    }
                }
                out.push(GapTop { x: gx, y: a });
            }
        }
    }
    out
}

/// Slices a gap is followed down over ([`gap_below`]: the crotch's walk
/// to the ground in `segment`, [`crotch_gap`]): a quarter of the
/// segmentation's `LANDMARK_SLICES`.
pub const GAP_WALK_SLICES: usize = 150;

/// The middle, at height `y_end` below `t`, of the gap whose top is `t`,
/// followed down over `n` slices between the two intervals beside it; None
/// when the gap opens to the outside on the way (no interval on one side).
pub fn gap_below(front: &[[f64; 2]], t: &GapTop, y_end: f64, n: usize) -> Option<f64> {
    let mut x = t.x;
    for k in 1..=n {
        let y = t.y - (t.y - y_end) * k as f64 / n as f64;
        let s = slice(front, y);
        let left = s
            .iter()
            .filter(|iv| iv[1] <= x)
            .map(|iv| iv[1])
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |a| a.max(v))));
        let right = s
            .iter()
            .filter(|iv| iv[0] >= x)
            .map(|iv| iv[0])
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |a| a.min(v))));
        match (left, right) {
            (Some(a), Some(b)) => x = 0.5 * (a + b),
            _ => return None,
        }
    }
    Some(x)
}

/// Whether the gap topped by `t` is the crotch's own gap (a square or
/// uneven crotch's other corner, whose top lies beside the crotch's):
/// followed down to a join band `g` below the lower of the two tops, both
/// gaps end between the same two intervals. A gap between an arm and the
/// body opens to the outside below the hand; one between an arm hanging
/// to the ground and a leg has that leg between it and the crotch's; a
/// tooth of a wavy crotch's edge between two of its tops (seed 4242's
/// random_0: 1e-4 of the height) is gone a join band below them. (It
/// replaces the test of no interval between the two tops a join band
/// below them: a leg reaching out past a hanging arm's armpit spans both
/// tops' x there, and the armpit scan took the crotch's corner for an
/// arm's.)
pub fn crotch_gap(front: &[[f64; 2]], t: &GapTop, crotch: &GapTop, g: f64) -> bool {
    let y_end = t.y.min(crotch.y) - g;
    let (Some(a), Some(b)) = (
        gap_below(front, t, y_end, GAP_WALK_SLICES),
        gap_below(front, crotch, y_end, GAP_WALK_SLICES),
    ) else {
        return false;
    };
    let (lo, hi) = (a.min(b), a.max(b));
    !slice(front, y_end)
        .iter()
        .any(|iv| lo < iv[1] && iv[0] < hi)
}

/// Merges the repeated tops of one leaning gap ([`gap_tops`]): sorted by
/// x, a run of tops each closer than `g` to the one before is one gap,
/// kept as its highest top (its true top: each repeat is found where the
/// middle of a lower slice's gap is covered, below where the gap closes).
pub fn merge_repeats(tops: &mut Vec<GapTop>, g: f64) {
    tops.sort_by(|a, b| a.x.total_cmp(&b.x));
    let mut out: Vec<GapTop> = Vec::with_capacity(tops.len());
    let mut prev: Option<GapTop> = None;
    for &t in tops.iter() {
        match (prev, out.last_mut()) {
            (Some(p), Some(kept)) if (t.x - p.x).hypot(t.y - p.y) < g => {
                if t.y > kept.y {
                    *kept = t;
                }
            }
            _ => out.push(t),
        }
        prev = Some(t);
    }
    *tops = out;
}

/// The highest top, below `y_max`, of the outline's vertical intervals at
/// `x` (even-odd rule), or None. Unlike [`top_at`], a part wholly above
/// `y_max` over `x` (a head wider than its neck) is not taken for the top.
pub fn top_below(points: &[[f64; 2]], x: f64, y_max: f64) -> Option<f64> {
    crossings(points, 0, x)
        .chunks_exact(2)
        .map(|c| c[1])
        .rev()
        .find(|&y| y < y_max)
}

/// The distance between two points of a drawing.
pub fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// How far the ray from `origin` along the unit direction `d` runs before
/// it first crosses an edge of the closed outline `points` farther than
/// `min`; None when it crosses none.
pub fn ray_exit(points: &[[f64; 2]], origin: [f64; 2], d: [f64; 2], min: f64) -> Option<f64> {
    let n = points.len();
    let mut best: Option<f64> = None;
    for k in 0..n {
        let (a, b) = (points[k], points[(k + 1) % n]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let den = d[0] * e[1] - d[1] * e[0];
        if den.abs() < f64::MIN_POSITIVE {
            continue;
        }
        let q = [a[0] - origin[0], a[1] - origin[1]];
        let s = (q[0] * e[1] - q[1] * e[0]) / den;
        let u = (q[0] * d[1] - q[1] * d[0]) / den;
        if (0.0..=1.0).contains(&u) && s > min && best.is_none_or(|b| s < b) {
            best = Some(s);
        }
    }
    best
}

/// The top of the outline's vertical interval at `x` that holds height
/// `y` (even-odd rule), or None when `y` is outside the outline there.
pub fn top_through(points: &[[f64; 2]], x: f64, y: f64) -> Option<f64> {
    crossings(points, 0, x)
        .chunks_exact(2)
        .find(|c| c[0] <= y && y <= c[1])
        .map(|c| c[1])
}

/// The top of the outline above `x` (largest y inside), if any.
pub fn top_at(points: &[[f64; 2]], x: f64) -> Option<f64> {
    crossings(points, 0, x).last().copied()
}

/// Steps per armpit-to-top height in which the neck is followed down.
pub const NECK_STEPS: f64 = 400.0;

/// The neck base: the neck is followed down from its narrowest height
/// `top` in steps of `d` / [`NECK_STEPS`], not below `floor`, while it is
/// `narrow` (the segmentation's test: the width under
/// `segment::NECK_FLARE` times the neck's); where it stops, the crossing
/// is found by bisection and the base is put one step above it. The base
/// is then a continuous function of the drawing: the last whole step
/// above the crossing (the rule before) sat
/// anywhere from 0 to 1 step above it, and a base moved one step down
/// into the fillet where a drawn neck meets the shoulder line (0.06 % of
/// the height on the corpus drawings) turned t_pose's side error from
/// 1.51 to 2.14 % and tripled the creases of long_legs and arms_low
/// (docs/drawing-corpus.md, sixth measurement).
pub fn neck_base(narrow: impl Fn(f64) -> bool, top: f64, floor: f64, d: f64) -> f64 {
    let step = d / NECK_STEPS;
    let mut base = top;
    while base - step > floor {
        if !narrow(base - step) {
            let (mut lo, mut hi) = (base - step, base);
            for _ in 0..40 {
                let m = 0.5 * (lo + hi);
                if narrow(m) {
                    hi = m;
                } else {
                    lo = m;
                }
            }
            return (hi + step).min(top);
        }
        base -= step;
    }
    base
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Slices used by the tests: as many as the segmentation uses.
    const SLICES: usize = crate::sketch::segment::LANDMARK_SLICES;

    /// Two legs joined above y = 3, the gap between them a wedge 1 wide at
    /// the ground closing to a point at (1.5, 3), all leaning by `lean` in
    /// x per unit of height: the gap's top is at x = 1.5 + 3 lean.
    fn leaning_legs(lean: f64) -> Vec<[f64; 2]> {
        let at = |x: f64, y: f64| [x + lean * y, y];
        vec![
            at(0.0, 0.0),
            at(1.0, 0.0),
            at(1.5, 3.0),
            at(2.0, 0.0),
            at(3.0, 0.0),
            at(3.0, 4.0),
            at(0.0, 4.0),
        ]
    }

    #[test]
    fn an_upright_gap_has_one_top_at_its_corner() {
        let tops = gap_tops(&leaning_legs(0.0), SLICES);
        assert_eq!(tops.len(), 1, "{tops:?}");
        let spacing = 4.0 / SLICES as f64;
        assert!((tops[0].y - 3.0).abs() < spacing, "{tops:?}");
        assert!((tops[0].x - 1.5).abs() < spacing, "{tops:?}");
    }

    #[test]
    fn a_leaning_gaps_repeated_tops_merge_into_its_top() {
        for lean in [2.0, -2.0] {
            let mut tops = gap_tops(&leaning_legs(lean), SLICES);
            // the raw tops: one per slice near the wedge's top
            assert!(tops.len() > 1, "lean {lean}: {tops:?}");
            merge_repeats(&mut tops, 0.06);
            assert_eq!(tops.len(), 1, "lean {lean}: {tops:?}");
            let spacing = 4.0 / SLICES as f64;
            let top = tops[0];
            // the true top, to within a slice and its sideways move
            assert!((top.y - 3.0).abs() < spacing, "lean {lean}: {top:?}");
            let tol = spacing * (1.0 + lean.abs());
            assert!(
                (top.x - (1.5 + 3.0 * lean)).abs() < tol,
                "lean {lean}: {top:?}"
            );
        }
    }

    #[test]
    fn tops_of_separate_gaps_are_kept_apart() {
        let gt = |x: f64, y: f64| GapTop { x, y };
        // two runs (0.005 apart within each) 1 apart: two gaps; a chain
        // longer than `g` end to end is still one gap
        let mut tops = vec![
            gt(0.0, 1.0),
            gt(1.0, 2.0),
            gt(0.005, 1.004),
            gt(0.01, 1.008),
            gt(1.005, 1.996),
        ];
        merge_repeats(&mut tops, 0.0075);
        assert_eq!(tops, vec![gt(0.01, 1.008), gt(1.0, 2.0)]);
    }

    /// A neck of width 1 above `y_s`, 10 wide below: the base is one step
    /// above `y_s` wherever `y_s` falls between the steps (the last whole
    /// step above it moved by up to a step with the phase).
    #[test]
    fn the_neck_base_follows_the_shoulder_line_continuously() {
        let d = 1.0;
        let step = d / NECK_STEPS;
        for k in 0..10 {
            let y_s = 0.5 + step * k as f64 / 10.0;
            let base = neck_base(|y| y > y_s, 1.0, 0.0, d);
            let err = (base - (y_s + step)).abs();
            assert!(
                err < crate::check::tol::ROUNDING * d,
                "shoulder at {y_s}: base {base}, off by {err}"
            );
        }
        // no crossing above the floor: the base stops at the floor
        let floor = 0.5;
        let base = neck_base(|_| true, 1.0, floor, d);
        assert!(base > floor && base - floor <= step, "{base}");
    }

    /// A body 2 wide and 1 tall with a head 1.5 wide on a neck 0.5 wide
    /// above it: above x = 0.6 the body's top is at 1, the head's at 3.
    #[test]
    fn the_top_below_a_height_leaves_out_parts_above_it() {
        let pts = vec![
            [-1.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.25, 1.0],
            [0.25, 2.0],
            [0.75, 2.0],
            [0.75, 3.0],
            [-0.75, 3.0],
            [-0.75, 2.0],
            [-0.25, 2.0],
            [-0.25, 1.0],
            [-1.0, 1.0],
        ];
        assert_eq!(top_at(&pts, 0.6), Some(3.0));
        assert_eq!(top_below(&pts, 0.6, 2.5), Some(1.0));
        assert_eq!(top_below(&pts, 0.6, 3.5), Some(3.0));
        assert_eq!(top_below(&pts, 0.6, 0.5), None);
        assert_eq!(top_below(&pts, 1.5, 2.5), None);
    }

    #[test]
    fn no_gap_no_top() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert!(gap_tops(&square, SLICES).is_empty());
    }
}
