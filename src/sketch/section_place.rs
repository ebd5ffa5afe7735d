//! Where a part's key sections go along its slices (paper 000 sec 4.1.2):
//! shared by the slice-based parts (`derive`) and the arms traced along
//! their axis (`limb`).

use super::region::{candidates, choose};
use super::segment::Region;
use super::tube::{connected_run, Slice};

/// Dense samples of a region's profile used to place sections.
const PROFILE_SAMPLES: usize = 240;

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
    let cap = share_cap(&inc, VARIATION_CAP);
    let mut var = vec![0.0; n];
    for i in 1..n {
        var[i] = var[i - 1] + inc[i].min(cap);
    }
    let (lt, vt) = (len[n - 1], var[n - 1]);
    // a profile that does not vary at all (a straight tube of constant
    // width) is placed by arc length alone: half of the share would
    // otherwise never be reached, and the sections bunched at its end
    let wv = if vt > 0.0 { 0.5 } else { 0.0 };
    let f: Vec<f64> = (0..n)
        .map(|i| (1.0 - wv) * len[i] / lt + wv * var[i] / vt.max(f64::MIN_POSITIVE))
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

/// No slice may hold more than this many times the mean slice's share of
/// the profile variation ([`share_cap`]), so no slice attracts more than a
/// few sections: with half of each part's sections placed by arc length,
/// the sections are at most `(1 + VARIATION_CAP) / 2` = 2.5 times denser
/// anywhere than they would be evenly spaced. The factor is the earlier
/// rule's (which clipped at 4 times the unclipped mean), kept; 3 and 6
/// were measured, not chosen (docs/drawing-corpus.md, seventh
/// measurement: 11 and 13 corpus drawings pass against 12, and random_8
/// creases at both).
const VARIATION_CAP: f64 = 4.0;

/// The level `c` at which no value of `inc` clipped to `c` exceeds `k`
/// times the mean of the clipped values (water filling; `k >= 1`). The
/// mean of the unclipped values is not the right scale: where one step of
/// the outline holds nearly all the variation (random_8's torso narrowing
/// by 30 % just under the armpits), that step dominates the mean, the cap
/// clipped nothing, and six of the torso's thirteen sections fell within
/// 1/13 of its length: its C2 chain rang (dihedral turns of 180 degrees).
fn share_cap(inc: &[f64], k: f64) -> f64 {
    let n = inc.len() as f64;
    let mut sorted: Vec<f64> = inc.iter().copied().filter(|v| v.is_finite()).collect();
    sorted.sort_by(|a, b| b.total_cmp(a));
    // with the j largest clipped to c: c = k (j c + rest) / n
    let mut rest: f64 = sorted.iter().sum();
    for (j, &v) in sorted.iter().enumerate() {
        rest -= v;
        let c = k * rest / (n - k * (j + 1) as f64);
        let next = sorted.get(j + 1).copied().unwrap_or(0.0);
        if n > k * (j + 1) as f64 && c >= next && c <= v {
            return c;
        }
    }
    f64::INFINITY
}

/// The slices of region `r` of the front outline, dense
/// ([`PROFILE_SAMPLES`]), kept to their connected run ([`connected_run`]:
/// one tube, followed through the branch that goes on at a split).
pub(super) fn samples(front: &[[f64; 2]], r: &Region) -> Vec<Sample> {
    let n = PROFILE_SAMPLES;
    // stay a hair inside the tip so the slice exists
    let eps = 1e-4 * (r.y1 - r.y0);
    let s = (0..=n)
        .filter_map(|k| {
            let t = k as f64 / n as f64;
            let y = if r.downward {
                r.y1 - t * (r.y1 - r.y0 - if r.tip { eps } else { 0.0 })
            } else {
                r.y0 + t * (r.y1 - r.y0 - if r.tip { eps } else { 0.0 })
            };
            let c = candidates(front, r.pick, y);
            let iv = choose(r.pick, &c)?;
            Some(Slice { y, iv, admitted: c })
        })
        .collect::<Vec<_>>();
    connected_run(s)
        .into_iter()
        .map(|q| Sample {
            y: q.y,
            c: 0.5 * (q.iv[0] + q.iv[1]),
            w: 0.5 * (q.iv[1] - q.iv[0]),
        })
        .collect()
}

/// Slope `dc/dy` of the part's centre line at sample `i`: the
/// least-squares line through the samples within the slice's half width
/// of it (at least two on each side). A section of half width `w` tilted
/// by an angle sweeps `w sin(angle)` up and down: centre-line wiggles
/// shorter than `w` cannot be followed by the section planes without
/// neighbouring sections crossing (a fold), so the planes follow the
/// centre line as seen at the section's own scale. (Two samples on each
/// side, as before, let a slice-to-slice jitter of the centre tilt a
/// torso section by up to 70 degrees: corpus random_0 and random_8.)
pub(super) fn centre_slope(s: &[Sample], i: usize) -> f64 {
    let reach = s[i].w;
    let (mut a, mut b) = (i.saturating_sub(2), (i + 2).min(s.len() - 1));
    while a > 0 && (s[i].y - s[a - 1].y).abs() <= reach {
        a -= 1;
    }
    while b + 1 < s.len() && (s[b + 1].y - s[i].y).abs() <= reach {
        b += 1;
    }
    let win = &s[a..=b];
    let n = win.len() as f64;
    let (my, mc) = (
        win.iter().map(|q| q.y).sum::<f64>() / n,
        win.iter().map(|q| q.c).sum::<f64>() / n,
    );
    let (mut syy, mut syc) = (0.0, 0.0);
    for q in win {
        syy += (q.y - my) * (q.y - my);
        syc += (q.y - my) * (q.c - mc);
    }
    if syy > 0.0 {
        syc / syy
    } else {
        0.0
    }
}

/// The samples with each slice's midpoint replaced by the median of the
/// midpoints within its half width, the same number of slices on each side
/// ([`centre_median`]): placement and sections both read these.
pub(super) fn on_centre_line(s: Vec<Sample>) -> Vec<Sample> {
    let c: Vec<f64> = (0..s.len()).map(|i| centre_median(&s, i)).collect();
    s.into_iter()
        .zip(c)
        .map(|(q, c)| Sample { c, ..q })
        .collect()
}

/// The median of the slice midpoints within sample `i`'s half width, over
/// a window with as many slices below as above (so it shrinks to the
/// sample itself at a part's ends). Where the two sides of a tube step at
/// heights a hair apart (random_0's hip shelves, drawn 1 % of the height
/// apart on the left and right), the midpoint jumps by half the shelf's
/// width for that hair; one section there, 1.1 mm off its neighbours, made
/// the C2 chain zigzag the whole torso (creased length 2.06 heights; 0.38
/// with that one centre put back by hand), and the jump lengthened the
/// part's arc length and attracted sections ([`place`]). A pulse shorter
/// than the half width is no feature of a centre line the sections can
/// follow (see [`centre_slope`]); the median removes it and leaves a centre
/// line that moves one way (a leaning leg) exactly as drawn, where a
/// least-squares line would round a bend.
fn centre_median(s: &[Sample], i: usize) -> f64 {
    let reach = s[i].w;
    let mut k = 0;
    while i > k
        && i + k + 1 < s.len()
        && (s[i].y - s[i - k - 1].y).abs() <= reach
        && (s[i + k + 1].y - s[i].y).abs() <= reach
    {
        k += 1;
    }
    let mut c: Vec<f64> = s[i - k..=i + k].iter().map(|q| q.c).collect();
    c.sort_by(f64::total_cmp);
    c[k]
}

/// The samples' direction along y at sample `i` (a part's samples run one
/// way: +1 up, -1 down).
pub(super) fn direction(s: &[Sample], i: usize) -> f64 {
    let (a, b) = (i.saturating_sub(2), (i + 2).min(s.len() - 1));
    (s[b].y - s[a].y).signum()
}

/// Ratio of consecutive graded spacings above the bend ([`graded_place`]).
/// Chosen between 2 and 1.5 on the corpus's development drawings: at 2 the
/// chain still rang behind long_legs' ankles (side error 2.26 % of the
/// height, a dent), at 1.5 no development drawing's leg is over 1.64 %.
pub(super) const GRADE_RATIO: f64 = 1.5;

/// The upper leg's section indices among its samples `s` (the last one is
/// the ankle, where the bend starts), `m` of them: the last sections
/// before the bend are graded from the bend's own spacing `step` (front
/// units), growing by [`GRADE_RATIO`] (`step`, `1.5 step`, `2.25 step`,
/// ...) until the next would reach the leg's mean spacing; the rest are placed as for any part
/// ([`place`]). Placed freely, a section could
/// fall a fifth of a bend step above the ankle and the next one five bend
/// steps higher: the C2 chain rang across that jump in spacing, a bulge
/// behind the ankle up to 2 % of the height outside the drawn side outline.
pub(super) fn graded_place(
    s: &[Sample],
    depth: Option<&[(f64, f64)]>,
    m: usize,
    step: f64,
) -> Vec<usize> {
    let n = s.len();
    // arc length from each sample down to the ankle
    let mut to_end = vec![0.0; n];
    for i in (0..n.saturating_sub(1)).rev() {
        to_end[i] = to_end[i + 1] + (s[i + 1].y - s[i].y).hypot(s[i + 1].c - s[i].c);
    }
    let mean = to_end.first().copied().unwrap_or(0.0) / m.saturating_sub(1).max(1) as f64;
    let mut tail = vec![n - 1];
    let (mut d, mut gap) = (0.0, step);
    // keep at least four freely placed sections above the graded ones
    while step > 0.0 && gap < mean && tail.len() + 4 <= m {
        d += gap;
        let last = tail[tail.len() - 1];
        match (0..last).rev().find(|&k| to_end[k] >= d) {
            Some(k) if k >= 3 => tail.push(k),
            _ => break,
        }
        gap *= GRADE_RATIO;
    }
    let top = tail[tail.len() - 1];
    let mut idx = place(&s[..=top], depth.map(|d| &d[..=top]), m + 1 - tail.len());
    idx.extend(tail.iter().rev().skip(1));
    idx
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The water-filling cap: no clipped value exceeds `k` times the clipped
    /// mean, and where nothing dominates nothing is clipped.
    #[test]
    fn one_step_holding_all_the_variation_is_capped_at_its_share() {
        let mut inc = vec![1.0; 100];
        inc[50] = 1000.0;
        inc[51] = 500.0;
        let k = 4.0;
        let c = share_cap(&inc, k);
        let clipped: Vec<f64> = inc.iter().map(|v| v.min(c)).collect();
        let mean = clipped.iter().sum::<f64>() / clipped.len() as f64;
        assert!(
            (c - k * mean).abs() <= crate::check::tol::ROUNDING * c,
            "cap {c}, mean {mean}"
        );
        // 98 ones and two clipped: c = 4 (98 + 2c) / 100
        assert!(
            (c - 392.0 / 92.0).abs() <= crate::check::tol::ROUNDING * c,
            "cap {c}"
        );
        // the unclipped mean's rule (4 x 15.98) clipped neither step
        let value = 1.0;
        let even = vec![value; 100];
        assert!(
            share_cap(&even, k) >= value,
            "nothing dominates, nothing clipped"
        );
    }

    /// A one-sided pulse shorter than the half width is removed from the
    /// midpoints; a centre line moving one way is kept exactly, ends
    /// included.
    #[test]
    fn midpoint_pulses_go_and_a_leaning_centre_stays() {
        let n = 101;
        let lean: Vec<Sample> = (0..n)
            .map(|k| Sample {
                y: k as f64 * 0.01,
                c: 0.3 * k as f64 * 0.01 + if k > 80 { 0.05 } else { 0.0 },
                w: 0.1,
            })
            .collect();
        let kept = on_centre_line(lean);
        for (k, q) in kept.iter().enumerate() {
            let want = 0.3 * k as f64 * 0.01 + if k > 80 { 0.05 } else { 0.0 };
            assert!(
                (q.c - want).abs() <= crate::check::tol::ROUNDING * want.abs(),
                "sample {k}: {} for {want}",
                q.c
            );
        }
        let pulse: Vec<Sample> = (0..n)
            .map(|k| Sample {
                y: k as f64 * 0.01,
                c: if (40..44).contains(&k) { 0.02 } else { 0.0 },
                w: 0.1,
            })
            .collect();
        let smooth = on_centre_line(pulse);
        assert!(smooth.iter().all(|q| q.c == 0.0), "the pulse is gone");
    }

    /// A straight tube of constant width (no profile variation at all) gets
    /// its sections evenly along it, not bunched at its end.
    #[test]
    fn a_tube_that_does_not_vary_is_placed_by_length() {
        let n = 121;
        let s: Vec<Sample> = (0..n)
            .map(|k| Sample {
                y: -(k as f64),
                c: 0.0,
                w: 1.0,
            })
            .collect();
        let idx = place(&s, None, SECTIONS_PER_PART);
        let want: Vec<usize> = (0..SECTIONS_PER_PART).map(|j| 10 * j).collect();
        assert_eq!(idx, want);
    }

    /// Above the bend, the last sections are a bend step apart, then 1.5,
    /// 2.25, ... steps (to within a sample) while below the mean spacing, and the rest placed as any part's;
    /// a step as long as the leg's mean spacing changes nothing.
    #[test]
    fn the_last_sections_above_the_bend_are_graded_from_its_step() {
        let n = 400;
        let s: Vec<Sample> = (0..n)
            .map(|k| Sample {
                y: 1.0 - k as f64 / (n - 1) as f64,
                c: 0.0,
                w: 0.05,
            })
            .collect();
        let m = 13;
        let step = 0.01;
        let idx = graded_place(&s, None, m, step);
        assert_eq!(idx.len(), m);
        assert!(idx.windows(2).all(|w| w[0] < w[1]), "{idx:?}");
        assert_eq!(idx[m - 1], n - 1);
        let y = |j: usize| s[idx[j]].y;
        let dy = 1.0 / (n - 1) as f64;
        // mean spacing 1/12: steps 0.01 to 0.0759 (six), 0.114 is past it
        for k in 1..=6 {
            let want = step * GRADE_RATIO.powi(k as i32 - 1);
            let got = y(m - 1 - k) - y(m - k);
            assert!(
                (got - want).abs() <= dy,
                "interval {k}: {got} against {want}"
            );
        }
        // past the sixth graded step (GRADE_RATIO^5 = 7.6 steps) the
        // spacing is the free placement's, longer still
        assert!(y(m - 8) - y(m - 7) > GRADE_RATIO.powi(5) * step, "{idx:?}");
        let free = place(&s, None, m);
        assert_eq!(graded_place(&s, None, m, 1.0), free);
    }
}
