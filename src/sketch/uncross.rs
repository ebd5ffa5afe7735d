//! Sections of a traced limb that do not cross (issue 28 item 4: no
//! folds).
//!
//! A limb's sections are discs perpendicular to its central curve. Where
//! the curve turns within less than a section's radius (a thumb standing
//! out of a real body's hand, a wrist drawn with a kink), two neighbouring
//! discs cut through each other, and the surface through them folds (the
//! MakeHuman base body's silhouettes: 174 degrees at the wrist). Three
//! measures, from the drawing's own scales:
//!
//! - [`tangent`]: the curve's direction at a sample is taken over an arc
//!   at least the limb's half width long on each side, not over the
//!   neighbouring samples: a tube of radius `r` cannot turn on a scale
//!   shorter than `r` without folding, so wiggles of the traced midpoints
//!   below that scale say nothing about its direction.
//! - [`uncross`]: each pair of neighbouring sections is turned toward the
//!   normal of the chord between their centres until, on both sides of the
//!   curve, their rims stay at least [`RIM_GAP`] of the centres' spacing
//!   apart along that chord. A section that no turn parts from its
//!   neighbour (a big one between two close ones where the curve turns) is
//!   replaced by the mean of its two neighbours.
//! - [`rim_arc_lengths`]: the chain's parameter measured along the
//!   sections' rims, so that a section growing or turning where the curve
//!   hardly moves does not make the surface overshoot.

/// Least spacing of two neighbouring sections' rims along the chord
/// between their centres, as a fraction of the centres' spacing. Any value
/// in (0, 1) keeps the discs apart; half leaves the inner side of a bend at
/// least half the outer side's room. Not tuned on the bundled drawings
/// (they have no thumbs and are hardly moved); on the six real bodies of
/// docs/drawing-corpus.md, 0.25 and 0.75 also keep every arm within
/// issue 28's 120 degrees (largest 96 and 51), and trade the front error
/// (0.98-1.56 % and 1.90-2.24 %, against 1.34-1.72 % at 0.5) for
/// smoothness; half is the middle, not a fitted value.
pub const RIM_GAP: f64 = 0.5;

/// Sweeps of [`uncross`]'s turns over the pairs before it replaces a
/// section (a pair's turn can push its neighbour's pair under the margin
/// again). A bound, not a tuned value (no other was tried): a pair still
/// short after it is parted by the replacement.
const SWEEPS: usize = 8;

fn unit(v: [f64; 2]) -> Option<[f64; 2]> {
    let n = v[0].hypot(v[1]);
    (n > 0.0 && n.is_finite()).then(|| [v[0] / n, v[1] / n])
}

/// Unit direction of the polyline `centre` at sample `i`: from the point
/// `h` of arc length before it to the point `h` after it (clamped to the
/// ends), `h` the larger of `half_width` and the arc over two samples.
pub fn tangent(centre: &[[f64; 2]], i: usize, half_width: f64) -> [f64; 2] {
    let n = centre.len();
    let d = |a: usize, b: usize| (centre[a][0] - centre[b][0]).hypot(centre[a][1] - centre[b][1]);
    let two = d(i.saturating_sub(2), i).max(d(i, (i + 2).min(n - 1)));
    let h = half_width.max(two);
    let walk = |step: isize| {
        let mut j = i;
        let mut s = 0.0;
        while s < h {
            let k = j as isize + step;
            if k < 0 || k >= n as isize {
                break;
            }
            s += d(j, k as usize);
            j = k as usize;
        }
        j
    };
    let (a, b) = (walk(-1), walk(1));
    unit([centre[b][0] - centre[a][0], centre[b][1] - centre[a][1]]).unwrap_or([1.0, 0.0])
}

/// A disc section of a limb in its drawing's plane: centre, unit direction
/// across the limb (`e1`, the same side of the curve all along) and radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disc {
    pub centre: [f64; 2],
    pub e1: [f64; 2],
    pub r: f64,
}

/// The least spacing, over the two sides, of the rims of `a` and `b` along
/// the chord `t` between their centres, relative to the centres' spacing
/// `d`.
fn rim_gap(a: &Disc, b: &Disc, t: [f64; 2], d: f64) -> f64 {
    [-1.0, 1.0]
        .iter()
        .map(|s| {
            let pa = [
                a.centre[0] + s * a.r * a.e1[0],
                a.centre[1] + s * a.r * a.e1[1],
            ];
            let pb = [
                b.centre[0] + s * b.r * b.e1[0],
                b.centre[1] + s * b.r * b.e1[1],
            ];
            ((pb[0] - pa[0]) * t[0] + (pb[1] - pa[1]) * t[1]) / d
        })
        .fold(f64::INFINITY, f64::min)
}

/// What [`uncross`] did to a section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fix {
    Kept,
    /// Its direction turned toward a chord's normal.
    Turned,
    /// It could not be turned apart from a neighbour (a big section between
    /// two close ones where the curve turns): replaced by the mean of its
    /// two neighbours (centre, direction and radius).
    Replaced,
}

/// One pass of turns: each pair of `discs[from..]` whose rims keep less than
/// [`RIM_GAP`] of their spacing turned toward its chord's normal just
/// enough (both sections by the same blend, bisected: at the normal itself
/// the rims are exactly one spacing apart). Returns whether any turned.
fn turn_pairs(discs: &mut [Disc], from: usize, fix: &mut [Fix]) -> bool {
    let mut any = false;
    for j in from..discs.len().saturating_sub(1) {
        let (a, b) = (discs[j], discs[j + 1]);
        let c = [b.centre[0] - a.centre[0], b.centre[1] - a.centre[1]];
        let d = c[0].hypot(c[1]);
        let Some(t) = unit(c) else { continue };
        if rim_gap(&a, &b, t, d) >= RIM_GAP {
            continue;
        }
        // the chord's normal on the sections' side
        let mut nrm = [t[1], -t[0]];
        if nrm[0] * (a.e1[0] + b.e1[0]) + nrm[1] * (a.e1[1] + b.e1[1]) < 0.0 {
            nrm = [-nrm[0], -nrm[1]];
        }
        let turn = |e: [f64; 2], f: f64| {
            unit([e[0] * (1.0 - f) + nrm[0] * f, e[1] * (1.0 - f) + nrm[1] * f]).unwrap_or(nrm)
        };
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..30 {
            let f = 0.5 * (lo + hi);
            let ta = Disc {
                e1: turn(a.e1, f),
                ..a
            };
            let tb = Disc {
                e1: turn(b.e1, f),
                ..b
            };
            if rim_gap(&ta, &tb, t, d) >= RIM_GAP {
                hi = f;
            } else {
                lo = f;
            }
        }
        for (k, e) in [(j, a.e1), (j + 1, b.e1)] {
            discs[k].e1 = turn(e, hi);
            if fix[k] == Fix::Kept && (discs[k].e1[0] - e[0]).hypot(discs[k].e1[1] - e[1]) > 1e-12 {
                fix[k] = Fix::Turned;
            }
        }
        any = true;
    }
    any
}

/// The first pair of `discs[from..]` whose rims keep less than [`RIM_GAP`]
/// of their spacing (turning leaves a parted pair at the margin, to
/// rounding).
fn crossing(discs: &[Disc], from: usize) -> Option<usize> {
    (from..discs.len().saturating_sub(1)).find(|&j| {
        let (a, b) = (&discs[j], &discs[j + 1]);
        let c = [b.centre[0] - a.centre[0], b.centre[1] - a.centre[1]];
        let d = c[0].hypot(c[1]);
        unit(c).is_some_and(|t| rim_gap(a, b, t, d) < RIM_GAP - 1e-9)
    })
}

/// Turns neighbouring sections of `discs[from..]` apart until every pair's
/// rims keep [`RIM_GAP`] of their spacing (`discs[..from]` are left as they
/// are: sections placed by another rule, such as an arm's first ones
/// tilted toward its shoulder). A pair already apart is not touched. Where
/// turning cannot part a pair (after [`SWEEPS`] sweeps its rims are still
/// nearer than the margin), the pair's interior section with the larger radius is replaced
/// by the mean of its neighbours, and the turns run again.
pub fn uncross(discs: &mut [Disc], from: usize) -> Vec<Fix> {
    let n = discs.len();
    let mut fix = vec![Fix::Kept; n];
    for _ in 0..n {
        for _ in 0..SWEEPS {
            if !turn_pairs(discs, from, &mut fix) {
                break;
            }
        }
        let Some(j) = crossing(discs, from) else {
            break;
        };
        let interior = |k: usize| k >= from.max(1) && k + 1 < n;
        let k = match (interior(j), interior(j + 1)) {
            (true, true) if discs[j].r >= discs[j + 1].r => j,
            (true, true) | (false, true) => j + 1,
            (true, false) => j,
            (false, false) => break,
        };
        let (p, q) = (discs[k - 1], discs[k + 1]);
        discs[k] = Disc {
            centre: [
                0.5 * (p.centre[0] + q.centre[0]),
                0.5 * (p.centre[1] + q.centre[1]),
            ],
            e1: unit([p.e1[0] + q.e1[0], p.e1[1] + q.e1[1]]).unwrap_or(discs[k].e1),
            r: 0.5 * (p.r + q.r),
        };
        fix[k] = Fix::Replaced;
    }
    fix
}

/// [`uncross`] on a limb's circular sections past `from` (their planes
/// hold z); a turned section keeps its centre and takes the radius
/// `radius(j, e1)` for its new direction (the rule that placed it); a
/// replaced one takes its neighbours' mean. The sections' arc lengths `u`
/// follow their centres. The tip's zero radius stays zero.
pub fn sections(
    sections: &mut [crate::character::doc::SectionSpec],
    from: usize,
    radius: impl Fn(usize, [f64; 2]) -> f64,
) {
    use crate::character::doc::SectionShape;
    let r_of = |s: &crate::character::doc::SectionSpec| match s.shape {
        SectionShape::Circle { r } => r,
        // a tilted shoulder section: its extent in the drawing's plane
        SectionShape::Ellipse { a, .. } => a,
        _ => 0.0,
    };
    let mut discs: Vec<Disc> = sections
        .iter()
        .map(|s| Disc {
            centre: [s.centre[0], s.centre[1]],
            e1: [s.e1[0], s.e1[1]],
            r: r_of(s),
        })
        .collect();
    let fix = uncross(&mut discs, from);
    if fix.iter().all(|f| *f == Fix::Kept) {
        return;
    }
    for (j, (s, d)) in sections.iter_mut().zip(&discs).enumerate() {
        let r = match fix[j] {
            Fix::Kept => continue,
            Fix::Turned => radius(j, d.e1),
            Fix::Replaced => d.r,
        };
        s.centre = [d.centre[0], d.centre[1], s.centre[2]];
        s.e1 = [d.e1[0], d.e1[1], 0.0];
        if let SectionShape::Circle { r: sr } = &mut s.shape {
            if *sr > 0.0 {
                *sr = r;
            }
        }
    }
    for j in 1..sections.len() {
        sections[j].u =
            sections[j - 1].u + crate::mesh::dist(sections[j - 1].centre, sections[j].centre);
    }
}

/// The sections' arc lengths `u` from how far their rims move: each step
/// the mean of the chords between corresponding rim points `centre +- r
/// e1` and `centre +- r e2` of the two sections (a circle of radius `r`;
/// an ellipse's semi-axes about its offset centre; a GEC counts as its
/// centre alone), not the chord between their centres alone.
///
/// The pde6 chain interpolates each rim point as a function of `u`. Where
/// a section grows, shrinks or turns while its centre hardly moves (a
/// hand's sections at the thumb: the inner rim moves twice as far as the
/// centre), a centre-length `u` makes the rim's curve speed up abruptly,
/// and the interpolant overshoots beyond the drawn outline (the MakeHuman
/// base body: 1.1 % of the height past its thumb). Measuring `u` along the
/// rims is the chord-length parametrisation of the curves actually
/// interpolated. Where sections only slide along a straight tube, the rim
/// chords equal the centre chord and nothing changes.
pub fn rim_arc_lengths(sections: &mut [crate::character::doc::SectionSpec]) {
    use crate::character::doc::{SectionShape, SectionSpec};
    let rims = |s: &SectionSpec| {
        // semi-axes along e1 and e2, and the centre's offset along e2
        let (a, b, off) = match s.shape {
            SectionShape::Circle { r } => (r, r, 0.0),
            SectionShape::Ellipse { a, b, offset } => (a, b, offset),
            SectionShape::Gec { .. } => (0.0, 0.0, 0.0),
        };
        let at = |k1: f64, k2: f64| {
            let f = |i: usize| s.centre[i] + k1 * s.e1[i] + k2 * s.e2[i];
            [f(0), f(1), f(2)]
        };
        [at(a, off), at(-a, off), at(0.0, off + b), at(0.0, off - b)]
    };
    for j in 1..sections.len() {
        let (a, b) = (rims(&sections[j - 1]), rims(&sections[j]));
        let step = a
            .iter()
            .zip(&b)
            .map(|(p, q)| crate::mesh::dist(*p, *q))
            .sum::<f64>()
            / 4.0;
        sections[j].u = sections[j - 1].u + step;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding left by the 30 halvings of the turn's bisection.
    const BISECTION_SLACK: f64 = 1e-6;
    /// The wave's mean direction is along x; over a period the endpoints'
    /// phases differ a little (measured 0.065).
    const MEAN_SLOPE_MAX: f64 = 0.1;
    /// Over neighbouring samples the wave's slope at its zero crossing
    /// (0.43 for 4 samples of a 10-sample period).
    const LOCAL_SLOPE_MIN: f64 = 0.3;

    fn disc(c: [f64; 2], angle_deg: f64, r: f64) -> Disc {
        let a = angle_deg.to_radians();
        Disc {
            centre: c,
            e1: [a.cos(), a.sin()],
            r,
        }
    }

    /// Rounding of sums of a few unit-scale chords.
    const ROUNDING: f64 = 1e-12;

    fn ring(c: [f64; 3], r: f64) -> crate::character::doc::SectionSpec {
        crate::character::doc::SectionSpec {
            u: 0.0,
            centre: c,
            e1: [0.0, 1.0, 0.0],
            e2: [0.0, 0.0, 1.0],
            shape: crate::character::doc::SectionShape::Circle { r },
        }
    }

    /// Along a straight tube the rims move as far as the centres; a ring
    /// that doubles in place (radius 1 to 2) moves each of its four rim
    /// points by 1, where its centre does not move at all; an ellipse's
    /// depth offset of 0.4 moves all four of its rim points by 0.4.
    #[test]
    fn arc_lengths_follow_the_rims_not_only_the_centres() {
        use crate::character::doc::SectionShape;
        let mut s = vec![
            ring([0.0, 0.0, 0.0], 1.0),
            ring([0.5, 0.0, 0.0], 1.0),
            ring([0.5, 0.0, 0.0], 2.0),
        ];
        rim_arc_lengths(&mut s);
        let u: Vec<f64> = s.iter().map(|q| q.u).collect();
        assert!(
            (u[1] - 0.5).abs() < ROUNDING && (u[2] - 1.5).abs() < ROUNDING,
            "{u:?}"
        );
        let mut e = vec![ring([0.0; 3], 1.0), ring([0.0; 3], 1.0)];
        e[1].shape = SectionShape::Ellipse {
            a: 1.0,
            b: 1.0,
            offset: 0.4,
        };
        rim_arc_lengths(&mut e);
        // the two e1 rim points move by 0.4 in depth, the two e2 ones too
        assert!((e[1].u - 0.4).abs() < ROUNDING, "{}", e[1].u);
    }

    /// Three sections along x (e1 along -y): the middle one turned by 80
    /// degrees cuts through both neighbours (radius 1, spacing 0.5); after
    /// `uncross` every pair keeps half its spacing on both sides, and the
    /// straight pair far away is not touched.
    #[test]
    fn crossing_sections_are_turned_apart_and_straight_ones_kept() {
        let mut d = vec![
            disc([0.0, 0.0], -90.0, 1.0),
            disc([0.5, 0.0], -10.0, 1.0),
            disc([1.0, 0.0], -90.0, 1.0),
            disc([5.0, 0.0], -90.0, 1.0),
            disc([6.0, 0.0], -90.0, 1.0),
        ];
        let t = [1.0, 0.0];
        assert!(rim_gap(&d[0], &d[1], t, 0.5) < 0.0, "the example crosses");
        let fix = uncross(&mut d, 0);
        // the middle one turns; its neighbours are the chord's normal
        // already
        assert_eq!(
            fix,
            [Fix::Kept, Fix::Turned, Fix::Kept, Fix::Kept, Fix::Kept]
        );
        for j in 0..2 {
            let g = rim_gap(&d[j], &d[j + 1], t, 0.5);
            assert!(g >= RIM_GAP - BISECTION_SLACK, "pair {j}: {g}");
        }
        assert_eq!(d[3].e1, disc([5.0, 0.0], -90.0, 1.0).e1);
        assert_eq!(d[4].e1, disc([6.0, 0.0], -90.0, 1.0).e1);
    }

    /// Four sections of a real body's wrist (MakeHuman's caucasian male,
    /// front silhouette: a big section between two close ones where the
    /// traced curve turns 60 degrees): no turn parts the middle pair, so
    /// one of them is replaced by its neighbours' mean, and then no pair
    /// crosses.
    #[test]
    fn a_section_that_no_turn_parts_is_replaced() {
        let mut d: Vec<Disc> = [
            ([-0.4705, 1.1006], [-0.908, 0.42], 0.0204),
            ([-0.4717, 1.0768], [-0.952, 0.305], 0.0317),
            ([-0.4778, 1.0578], [-0.54, 0.842], 0.0405),
            ([-0.5043, 1.0512], [-0.24, 0.971], 0.0112),
        ]
        .into_iter()
        .map(|(centre, e1, r)| Disc { centre, e1, r })
        .collect();
        assert!(crossing(&d, 0).is_some());
        let fix = uncross(&mut d, 0);
        assert!(fix.contains(&Fix::Replaced), "{fix:?}");
        assert_eq!(crossing(&d, 0), None);
        assert!(
            fix[0] != Fix::Replaced && fix[3] != Fix::Replaced,
            "the ends are never replaced"
        );
    }

    /// Sections before `from` stay as placed even when they cross.
    #[test]
    fn sections_before_from_are_kept() {
        let mut d = vec![disc([0.0, 0.0], -10.0, 1.0), disc([0.5, 0.0], -90.0, 1.0)];
        let before = d.clone();
        assert!(uncross(&mut d, 1).iter().all(|f| *f == Fix::Kept));
        assert_eq!(d, before);
    }

    /// A wave of midpoints (period 10 samples, slope up to 0.63): the
    /// tangent over the half width (a period) follows its mean direction,
    /// the one over neighbouring samples its slope.
    #[test]
    fn the_tangent_ignores_wiggles_below_the_half_width() {
        let c: Vec<[f64; 2]> = (0..200)
            .map(|i| {
                let x = i as f64 * 0.01;
                [x, 0.01 * (std::f64::consts::TAU * i as f64 / 10.0).sin()]
            })
            .collect();
        let t = tangent(&c, 100, 0.1);
        assert!(t[1].abs() < MEAN_SLOPE_MAX, "{t:?}");
        let short = tangent(&c, 100, 0.0);
        assert!(short[1].abs() > LOCAL_SLOPE_MIN, "{short:?}");
    }
}
