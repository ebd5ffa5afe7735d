//! An animal body's depth from the head-on view: ellipses of the view's
//! widest depth over the body's heights ([`body_depth`]), each no deeper
//! than fits the view ([`inscribed_depth`]); or each cross section the
//! visual hull of both views ([`hull_section`]): a section across the body
//! spans its lateral outline's width along `e1`, and at each height it
//! reaches as far in depth as the head-on outline does there. An ellipse
//! narrows toward the belly and the back, where a head-on drawing may be
//! as wide as the body: the corpus dog missed its head-on outline by
//! 5.55 % of the height beside the legs' tops (3.93 % with the hull). The
//! build is offered both ([`super::shells::alternatives`]) and keeps the
//! one that misses the drawing least: the hull's fit ripples along a
//! straight side (the corpus horse: 1.7 % of the height out, against its
//! ellipses' 1.37 %).
//!
//! Below the head-on view's gap between the legs (whose top the two views
//! may place differently: a lateral belly line below it), the hull has no
//! depth at the body's middle; a section reaching there is closed by a
//! quarter ellipse from the gap's top to its end, a convex end rather
//! than a keel the fit rings at. The gap's top is found once per outline
//! ([`HeadOn::new`]), so neighbouring sections agree on it.
//!
//! The hull's section is a box where the head-on outline is straight;
//! clipped by the ellipse of the section's extent and `SQRT_2` times its
//! widest depth (the ellipse through the box's corners at `e1 = ± r /
//! SQRT_2`: the hull's width kept over the middle `1 / SQRT_2` of the
//! section, rounded beyond), it is fitted by a GEC of
//! [`super::super::keysection::GEC_TERMS`] terms at the ellipse's angles,
//! so neighbouring sections share their parameter and the chain does not
//! twist.

use super::super::poly::slice;
use crate::character::doc::{SectionShape, SectionSpec};

/// How the body's sections take their depth from the head-on view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodyDepth {
    /// Ellipses of the widest depth, scaled by each section's height.
    Ellipse,
    /// Each section the visual hull of both views
    /// (this module).
    Hull,
}

/// Heights sampled across a section to fit its depth in the head-on view.
const DEPTH_SAMPLES: usize = 16;

/// The largest half depth of an ellipse section centred at height `c`
/// with vertical half axis `r` that stays inside the head-on outline
/// `side` at every sampled height within `band` (infinite when none is).
pub(super) fn inscribed_depth(side: &[[f64; 2]], c: f64, r: f64, band: [f64; 2]) -> f64 {
    (0..DEPTH_SAMPLES)
        .filter_map(|k| {
            let t = -1.0 + 2.0 * (k as f64 + 0.5) / DEPTH_SAMPLES as f64;
            let y = c + t * r;
            if !(band[0]..=band[1]).contains(&y) {
                return None;
            }
            let sl = slice(side, y);
            let w = 0.5 * (sl.last()?[1] - sl.first()?[0]);
            Some(w / (1.0 - t * t).sqrt())
        })
        .fold(f64::INFINITY, f64::min)
}

/// Half the head-on outline's widest span (first interval to last) over
/// heights in `band` (the body's, between the legs' joins and the parts'
/// above), and its middle: the body's half depth and z.
pub fn body_depth(side: &[[f64; 2]], band: [f64; 2]) -> Option<(f64, f64)> {
    const SLICES: usize = 64;
    (0..=SLICES)
        .filter_map(|k| {
            let y = band[0] + (band[1] - band[0]) * k as f64 / SLICES as f64;
            let s = slice(side, y);
            Some((s.first()?[0], s.last()?[1]))
        })
        .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)))
        .map(|(z0, z1)| (0.5 * (z1 - z0), 0.5 * (z0 + z1)))
}

/// Points sampled around a section for its fit.
const HULL_SAMPLES: usize = 64;
/// Heights scanned over the head-on outline for its gaps' ends, each then
/// bisected to the outline's rounding.
const GAP_SCAN: usize = 256;
const GAP_BISECT: usize = 40;

/// The head-on outline about the body's middle depth `z`: the heights
/// `held` over which a slice of it holds `z` (from the body's band
/// middle up and down to the first gap).
pub struct HeadOn<'a> {
    side: &'a [[f64; 2]],
    z: f64,
    held: [f64; 2],
}

impl<'a> HeadOn<'a> {
    /// None when the slice at `mid` (the body's band middle) does not
    /// hold `z`.
    pub fn new(side: &'a [[f64; 2]], z: f64, mid: f64) -> Option<HeadOn<'a>> {
        let holds = |y: f64| match slice(side, y)[..] {
            [iv] => iv[0] <= z && z <= iv[1],
            _ => false,
        };
        if !holds(mid) {
            return None;
        }
        let yr = crate::polygon::span(side, 1);
        let step = (yr[1] - yr[0]) / GAP_SCAN as f64;
        // at most GAP_SCAN steps reach either end from inside the span
        let end = |dir: f64| {
            let mut inside = mid;
            for _ in 0..=GAP_SCAN {
                let next = inside + dir * step;
                if !(yr[0]..=yr[1]).contains(&next) {
                    break;
                }
                if !holds(next) {
                    let mut out = next;
                    for _ in 0..GAP_BISECT {
                        let m = 0.5 * (inside + out);
                        if holds(m) {
                            inside = m;
                        } else {
                            out = m;
                        }
                    }
                    return inside;
                }
                inside = next;
            }
            if dir < 0.0 {
                yr[0]
            } else {
                yr[1]
            }
        };
        Some(HeadOn {
            side,
            z,
            held: [end(-1.0), end(1.0)],
        })
    }

    /// The half depths `(below z, above z)` at height `y` within the held
    /// heights: the slice's whole span (a thin dip of the gap's top is no
    /// narrowing of the body above it).
    fn depth(&self, y: f64) -> [f64; 2] {
        let sl = slice(self.side, y.clamp(self.held[0], self.held[1]));
        match (sl.first(), sl.last()) {
            (Some(a), Some(b)) => [(self.z - a[0]).max(0.0), (b[1] - self.z).max(0.0)],
            _ => [0.0, 0.0],
        }
    }
}

/// The section `s` (a circle of radius `r` across the body, its centre at
/// the body's middle depth) as the GEC of its visual hull with the
/// head-on outline (module docs); None when the head-on outline has no
/// depth across it or the fit fails (the section is left as is).
pub fn hull_section(s: &SectionSpec, r: f64, head_on: &HeadOn) -> Option<SectionShape> {
    let n = HULL_SAMPLES;
    let thetas: Vec<f64> = (0..n)
        .map(|k| std::f64::consts::TAU * k as f64 / n as f64)
        .collect();
    let (c, k) = (s.centre[1], s.e1[1]);
    // the held heights as a range of s (e1 may point down)
    let held = head_on.held.map(|y| (y - c) / k);
    let (lo, hi) = if k.abs() < f64::EPSILON {
        (-r, r)
    } else {
        (held[0].min(held[1]).max(-r), held[0].max(held[1]).min(r))
    };
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return None;
    }
    let at = |t: f64| head_on.depth(c + t * k);
    let (d_lo, d_hi) = (at(lo), at(hi));
    let depths: Vec<[f64; 2]> = thetas
        .iter()
        .map(|t| {
            let t = r * t.cos();
            // from the last held point `edge` to the section's end `end`
            let fall = |edge: f64, end: f64, d: [f64; 2]| {
                let u = ((t - edge) / (end - edge)).abs().min(1.0);
                let q = (1.0 - u * u).sqrt();
                [q * d[0], q * d[1]]
            };
            if t < lo {
                fall(lo, -r, d_lo)
            } else if t > hi {
                fall(hi, r, d_hi)
            } else {
                at(t)
            }
        })
        .collect();
    let widest = depths.iter().flatten().copied().fold(0.0, f64::max);
    if !(r > 0.0 && widest > 0.0) {
        return None;
    }
    let round = std::f64::consts::SQRT_2 * widest;
    let pts: Vec<[f64; 2]> = thetas
        .iter()
        .zip(&depths)
        .map(|(t, d)| {
            let (sn, cs) = t.sin_cos();
            // e2 along +z or -z: which side of z this angle's half lies on
            let hull = if (sn >= 0.0) == (s.e2[2] >= 0.0) {
                d[1]
            } else {
                d[0]
            };
            [r * cs, sn.signum() * hull.min(round * sn.abs())]
        })
        .collect();
    let terms = super::super::keysection::GEC_TERMS;
    let (centre, x, y) =
        crate::curve::gec::fit::solve(&pts, &thetas, terms, Default::default()).ok()?;
    Some(SectionShape::Gec { centre, x, y })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::gec::{Frame, Gec};

    /// A head-on view (z, y): a body 2 wide from y = 1 to 3 over two legs
    /// with a gap between them up to y = 1.
    fn head_on() -> Vec<[f64; 2]> {
        vec![
            [-1.0, 0.0],
            [-0.2, 0.0],
            [-0.2, 1.0],
            [0.2, 1.0],
            [0.2, 0.0],
            [1.0, 0.0],
            [1.0, 3.0],
            [-1.0, 3.0],
        ]
    }

    /// A vertical section of radius `r` about height `c`, e2 along +z.
    fn section(c: f64, r: f64) -> SectionSpec {
        SectionSpec {
            u: 0.0,
            centre: [0.0, c, 0.0],
            e1: [0.0, 1.0, 0.0],
            e2: [0.0, 0.0, 1.0],
            shape: SectionShape::Circle { r },
        }
    }

    /// The fitted section's largest half depth at height `y` (its points
    /// within `tol` of that height).
    fn depth_near(g: &SectionShape, c: f64, y: f64, tol: f64) -> f64 {
        let SectionShape::Gec { centre, x, y: gy } = g else {
            panic!("a GEC: {g:?}");
        };
        let frame = Frame::new([0.0, c, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).expect("frame");
        let gec = Gec::new(frame, *centre, x.clone(), gy.clone()).expect("gec");
        const N: usize = 4096;
        (0..N)
            .map(|k| gec.eval(std::f64::consts::TAU * k as f64 / N as f64))
            .filter(|p| (p[1] - y).abs() < tol)
            .map(|p| p[2].abs())
            .fold(0.0, f64::max)
    }

    /// How far the fitted GEC may miss its target depth, relative to the
    /// box's half depth (1): a GEC of `GEC_TERMS` terms rounds a box's
    /// corners; an ellipse misses by 0.2 at 0.6 of its half height.
    const FIT: f64 = 0.05;

    #[test]
    fn the_held_heights_end_at_the_gap_between_the_legs() {
        let side = head_on();
        let h = HeadOn::new(&side, 0.0, 2.0).expect("held at the middle");
        let tol = crate::check::tol::ROUNDING;
        assert!((h.held[0] - 1.0).abs() < tol, "gap top: {:?}", h.held);
        assert!((h.held[1] - 3.0).abs() < tol, "outline top: {:?}", h.held);
        // a middle in the gap holds nothing
        assert!(HeadOn::new(&side, 0.0, 0.5).is_none());
    }

    /// Where the head-on outline is as wide as the body all the way down
    /// (a box), the section keeps that width far below its middle, where
    /// an ellipse of the same depth has narrowed: at 0.6 of its half
    /// height an ellipse is 0.8 as deep.
    #[test]
    fn a_box_head_on_gives_a_section_as_deep_as_the_box_below_its_middle() {
        let side = head_on();
        let h = HeadOn::new(&side, 0.0, 2.0).expect("held");
        let (c, r) = (2.0, 0.9);
        let g = hull_section(&section(c, r), r, &h).expect("a hull section");
        let at = |t: f64| depth_near(&g, c, c + t * r, FIT * r);
        for t in [-0.6, 0.0, 0.6] {
            assert!(
                (at(t) - 1.0).abs() < FIT,
                "at {t} of the half height: {}",
                at(t)
            );
        }
    }

    /// A section reaching below the gap's top (y = 1) is closed there by
    /// a quarter ellipse to its end: not as deep as the legs' span (1)
    /// the slice there has.
    #[test]
    fn a_section_below_the_gap_closes_toward_its_end() {
        let side = head_on();
        let h = HeadOn::new(&side, 0.0, 2.0).expect("held");
        let (c, r) = (1.5, 0.9);
        let g = hull_section(&section(c, r), r, &h).expect("a hull section");
        // a thin band of heights: the depth changes fast below the gap
        let at = |y: f64| depth_near(&g, c, y, 0.1 * FIT * r);
        assert!((at(1.2) - 1.0).abs() < FIT, "above the gap: {}", at(1.2));
        let end = c - r;
        for y in [0.9, 0.8, 0.7, 0.65] {
            let u: f64 = (1.0 - y) / (1.0 - end);
            let quarter = (1.0 - u * u).sqrt();
            assert!(
                at(y) < quarter + FIT,
                "at y = {y}: {} over {quarter}",
                at(y)
            );
        }
    }
}
