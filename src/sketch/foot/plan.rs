//! How a foot's sections are shared out and where they go along the bend
//! and the foot ([`super`]'s module docs).

use super::{vertical_slice, Foot, PathPoint};
use crate::sketch::section_place::{Sample, GRADE_RATIO, SECTIONS_PER_PART};

/// How a leg's sections are shared out: the samples above the bend, the
/// sections placed on them, and the foot's own (after the bend's three):
/// its full sections' distances from the bend's end along the toe's
/// direction ([`foot_stations`]), then the toe.
pub(in crate::sketch) struct Plan {
    pub(in crate::sketch) n_upper: usize,
    pub(in crate::sketch) m_upper: usize,
    pub(in crate::sketch) stations: Vec<f64>,
}

/// The leg above the bend keeps its [`SECTIONS_PER_PART`]; the foot gets its
/// share of the leg's path length (spaced like the leg's sections, 2 to 4,
/// the last its toe), or more where its full sections, spaced from the
/// bend's step growing by at most [`GRADE_RATIO`] per span as above the
/// bend, need more to reach the toe's cap ([`graded_count`]); the chain's
/// count stays `3 P + 1`.
pub(in crate::sketch) fn plan(s: &[Sample], foot: Option<&Foot>, side: &[[f64; 2]]) -> Plan {
    let Some(f) = foot else {
        return Plan {
            n_upper: s.len(),
            m_upper: SECTIONS_PER_PART,
            stations: Vec::new(),
        };
    };
    let up: f64 = s[..=f.last_upper]
        .windows(2)
        .map(|w| (w[1].y - w[0].y).hypot(w[1].c - w[0].c))
        .sum();
    let bend = std::f64::consts::FRAC_PI_2 * f.radius;
    let along = (f.toe[0] - f.start[0]).abs() - f.radius;
    let share = (SECTIONS_PER_PART - 1) as f64 * along / (up + bend + along);
    let z0 = f.start[0] + f.dir * f.radius;
    let len = f.dir * (toe_cap(side, f, z0) - z0);
    let m_foot = (share.round() as usize)
        .clamp(2, 4)
        .max(graded_count(len, bend_step(f)) + 1);
    let lower = 3 + m_foot;
    Plan {
        n_upper: f.last_upper + 1,
        m_upper: (SECTIONS_PER_PART + lower - 1).div_ceil(3) * 3 + 1 - lower,
        stations: foot_stations(len, bend_step(f), m_foot - 1),
    }
}

/// Bend sections (at a sixth, a third and a half of pi) followed by a
/// point at each of the foot's `stations` ([`Plan`]) and the toe.
pub(in crate::sketch) fn path(side: &[[f64; 2]], f: &Foot, stations: &[f64]) -> Vec<PathPoint> {
    let (r, d) = (f.radius, f.dir);
    let c = [f.start[0] + d * r, f.start[1]];
    let mut out = Vec::with_capacity(4 + stations.len());
    for k in 1..=3 {
        let th = k as f64 * std::f64::consts::FRAC_PI_6;
        let p = [c[0] - d * r * th.cos(), c[1] - r * th.sin()];
        // e2 turns from +z (down the leg) with the tangent
        let n = [th.cos(), d * th.sin()];
        // the bend's centre lies at p + d r n
        out.push(PathPoint { p, n, inner: d });
    }
    for &x in stations {
        let z = c[0] + d * x;
        let y = vertical_slice(side, z, f.ankle_y)
            .map(|iv| 0.5 * (iv[0] + iv[1]))
            .unwrap_or(c[1] - r);
        out.push(PathPoint {
            p: [z, y],
            n: [0.0, d],
            inner: 0.0,
        });
    }
    out.push(PathPoint {
        p: f.toe,
        n: [0.0, d],
        inner: 0.0,
    });
    out
}

/// The arc length between the bend's sections (side units): a sixth of pi
/// of its radius.
fn bend_step(f: &Foot) -> f64 {
    std::f64::consts::FRAC_PI_6 * f.radius
}

/// How many full sections a foot `len` long needs (at least 1) so that
/// spacings growing from the bend's `step` by [`GRADE_RATIO`] per span
/// (`step r, step r^2, ...`) reach its end; at most
/// [`SECTIONS_PER_PART`].
fn graded_count(len: f64, step: f64) -> usize {
    let (mut m, mut d, mut gap) = (0, 0.0, step);
    while m < SECTIONS_PER_PART && (m == 0 || d < len) && step > 0.0 {
        gap *= GRADE_RATIO;
        d += gap;
        m += 1;
    }
    m.max(1)
}

/// Where the foot's `m` full sections go, as distances from the bend's
/// end `len` long (the last at `len`): spacings growing by one ratio `q`
/// from the bend's own step, `step q, step q^2, ...`, whose sum is `len`
/// (so the chain's spacing changes by the same factor from span to span,
/// as above the bend); uniform when the foot is no longer than `m`
/// steps (or not a finite positive length). The ratio is found by
/// bisection from `[1, GRADE_RATIO]`, widened only when `m` was capped
/// below [`graded_count`]'s need.
fn foot_stations(len: f64, step: f64, m: usize) -> Vec<f64> {
    if m == 0 {
        return Vec::new();
    }
    let sum = |q: f64| (1..=m).map(|k| step * q.powi(k as i32)).sum::<f64>();
    if !(len.is_finite() && len > 0.0 && step > 0.0) || sum(1.0) >= len {
        return (1..=m).map(|k| len * k as f64 / m as f64).collect();
    }
    let (mut a, mut b) = (1.0, GRADE_RATIO);
    while sum(b) < len {
        b *= 2.0;
    }
    for _ in 0..60 {
        let q = 0.5 * (a + b);
        if sum(q) < len {
            a = q;
        } else {
            b = q;
        }
    }
    let q = 0.5 * (a + b);
    let mut d = 0.0;
    let mut out: Vec<f64> = (1..=m)
        .map(|k| {
            d += step * q.powi(k as i32);
            d
        })
        .collect();
    out[m - 1] = len;
    out
}

/// Where the foot's last full section goes: as far from the toe as the
/// foot is half high there, so the chain closes the toe like a round cap
/// of that radius (a section spaced like the others left a cone, a spike
/// at the toe). Found by bisection between the bend's end `z0` and the
/// toe; halfway when the foot is no longer than it is high.
fn toe_cap(side: &[[f64; 2]], f: &Foot, z0: f64) -> f64 {
    let d = f.dir;
    let g = |z: f64| {
        let h = vertical_slice(side, z, f.ankle_y).map_or(0.0, |iv| 0.5 * (iv[1] - iv[0]));
        h - d * (f.toe[0] - z)
    };
    let (mut a, mut b) = (z0, f.toe[0]);
    if g(a) >= 0.0 {
        return 0.5 * (z0 + f.toe[0]);
    }
    for _ in 0..48 {
        let m = 0.5 * (a + b);
        if g(m) < 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::super::find;
    use super::super::tests::{boot, leg_samples};
    use super::*;

    /// The last full section sits as far from the toe as the foot is half
    /// high there: the boot's foot is 0.1 high with its toe at z = 0.3, so
    /// at z = 0.25; a foot no longer than it is high gets the midpoint.
    #[test]
    fn the_toe_cap_is_a_half_height_from_the_toe() {
        let f = Foot {
            last_upper: 0,
            dir: 1.0,
            radius: 0.05,
            start: [0.0, 0.15],
            toe: [0.3, 0.05],
            ankle_y: 0.2,
        };
        let z = toe_cap(&boot(), &f, 0.1);
        assert!((z - 0.25).abs() < crate::check::tol::SOLVE, "{z}");
        let near = toe_cap(&boot(), &f, 0.27);
        assert!((near - 0.285).abs() < crate::check::tol::ROUNDING, "{near}");
    }

    #[test]
    fn the_path_bends_from_down_to_forward_and_ends_at_the_toe() {
        let side = boot();
        let (s, d) = leg_samples(&side);
        let f = find(&side, [0.0, 1.0], &s, &d, 10).expect("a foot");
        let stations = plan(&s, Some(&f), &side).stations;
        let p = path(&side, &f, &stations);
        assert_eq!(p.len(), 4 + stations.len());
        assert!(
            p[2].n[0].abs() < crate::check::tol::ROUNDING
                && (p[2].n[1] - 1.0).abs() < crate::check::tol::ROUNDING
        );
        assert_eq!(p[p.len() - 1].p, f.toe);
        for w in p.windows(2) {
            assert!(w[1].p[0] > w[0].p[0] && w[1].p[1] <= w[0].p[1] + crate::check::tol::ROUNDING);
        }
    }

    /// A foot 1 long from a bend step of 0.1: 0.15 + 0.225 + 0.3375 =
    /// 0.7125 falls short, a fourth span (0.506) reaches past it; four
    /// full sections. A foot no longer than one graded span needs one; a
    /// degenerate step gives one.
    #[test]
    fn a_foot_takes_as_many_sections_as_spans_graded_from_the_bend_need() {
        assert_eq!(graded_count(1.0, 0.1), 4);
        assert_eq!(graded_count(0.7, 0.1), 3);
        assert_eq!(graded_count(0.1, 0.1), 1);
        assert_eq!(graded_count(1.0, 0.0), 1);
        assert_eq!(graded_count(f64::NAN, 0.1), 1);
        // a foot hundreds of steps long is capped
        assert_eq!(graded_count(1e9, 1.0), SECTIONS_PER_PART);
    }

    /// The stations' spacings grow by one ratio from the bend's step, at
    /// most GRADE_RATIO when the count is the graded one, and the last is
    /// the foot's end; a foot too short for growth is spaced evenly.
    #[test]
    fn the_foot_stations_grow_by_one_ratio_from_the_bend_step_to_its_end() {
        let (len, step) = (1.0, 0.1);
        let m = graded_count(len, step);
        let at = foot_stations(len, step, m);
        assert_eq!(at.len(), m);
        assert_eq!(at[m - 1], len);
        let gaps: Vec<f64> = std::iter::once(at[0])
            .chain(at.windows(2).map(|w| w[1] - w[0]))
            .collect();
        let q = gaps[0] / step;
        assert!(gaps[0] > step && q <= GRADE_RATIO, "first ratio {q}");
        for w in gaps.windows(2) {
            let r = w[1] / w[0];
            assert!(
                (r - q).abs() < crate::check::tol::ROUNDING,
                "ratios {q} and {r}: {gaps:?}"
            );
        }
        let even = foot_stations(0.2, 0.1, 4);
        for (k, z) in even.iter().enumerate() {
            assert!(
                (z - 0.05 * (k + 1) as f64).abs() < crate::check::tol::ROUNDING,
                "{even:?}"
            );
        }
        assert!(foot_stations(1.0, 0.1, 0).is_empty());
    }
}
