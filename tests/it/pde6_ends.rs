//! The end conditions of the global C2 chain (`pde6::EndCurvature`): the
//! six-point curvature, a natural end, a chord (clamped) end, and the
//! guard that takes the chord end where the six-point curvature
//! overshoots.

use pdesculpt::curve::Fourier3;
use pdesculpt::pde6::{Chain, EndCurvature, Section, END_TURN_GUARD_DEG};
use std::f64::consts::PI;

/// Rounding of the global solve (its matrices' condition numbers stay
/// below 1e12, the data is of size 1).
const ZERO_CURVATURE_TOL: f64 = 1e-9;
/// A chord end's tangent along its chord (degrees): rounding of the
/// global solve seen through `acos` near 1, where a cosine 1e-16 short of
/// 1 is already 1e-6 degrees (measured 1.2e-6).
const CHORD_TURN_TOL_DEG: f64 = 1e-4;
/// A six-point end curvature of a wavy radius is far from zero.
const SIX_POINT_CURVATURE_MIN: f64 = 1e-2;

/// A circle of radius `r` in the plane y = `u`.
fn ring(u: f64, r: f64) -> Section {
    Section {
        u,
        curve: Fourier3 {
            c0: [0.0, u, 0.0],
            cos: vec![[r, 0.0, 0.0]],
            sin: vec![[0.0, 0.0, r]],
        },
    }
}

/// How far the chain misses its sections at their u: the largest
/// coefficient of the difference.
fn interpolation_miss(c: &Chain, s: &[Section]) -> f64 {
    s.iter()
        .map(|sec| {
            Fourier3::weighted_sum(&[(1.0, &section(c, sec.u, 0)), (-1.0, &sec.curve)])
                .max_abs_coef()
        })
        .fold(0.0, f64::max)
}

fn section(c: &Chain, u: f64, d: usize) -> Fourier3 {
    c.pieces[c.piece_at(u)].global_section(u, d)
}

/// The largest angle (degrees) over the ring between the chain's
/// u-derivative at section `at` and the chord from section `i` to `i + 1`.
fn turn_deg(c: &Chain, s: &[Section], i: usize, at: usize) -> f64 {
    let d = section(c, s[at].u, 1);
    (0..48)
        .map(|k| {
            let th = 2.0 * PI * k as f64 / 48.0;
            let (a, b, t) = (s[i].curve.eval(th), s[i + 1].curve.eval(th), d.eval(th));
            let ch = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let dot = ch[0] * t[0] + ch[1] * t[1] + ch[2] * t[2];
            let n = (ch.iter().map(|x| x * x).sum::<f64>() * t.iter().map(|x| x * x).sum::<f64>())
                .sqrt();
            (dot / n).clamp(-1.0, 1.0).acos().to_degrees()
        })
        .fold(0.0, f64::max)
}

/// [`turn_deg`] at the chain's first section.
fn start_turn_deg(c: &Chain, s: &[Section]) -> f64 {
    turn_deg(c, s, 0, 0)
}

fn same_surface(a: &Chain, b: &Chain, s: &[Section]) -> bool {
    let (u0, u1) = (s[0].u, s[s.len() - 1].u);
    (0..=20).all(|k| {
        let u = u0 + (u1 - u0) * k as f64 / 20.0;
        section(a, u, 0) == section(b, u, 0)
    })
}

/// A wavy radius on ten evenly spaced sections.
fn wavy() -> Vec<Section> {
    (0..10)
        .map(|i| {
            let u = i as f64 / 9.0;
            ring(u, 1.0 + 0.3 * (3.0 * u).sin())
        })
        .collect()
}

/// A smooth tube whose first gap is short and whose second section
/// narrows before the rest widens again: a torso's lowest sections where
/// a side view's thighs widen the lowest one.
fn overshooting_start() -> Vec<Section> {
    // in units of the radius, the MakeHuman girl's lowest torso sections
    // (docs/drawing-corpus.md, eighteenth measurement)
    let us = [0.0, 0.4, 0.7, 1.0, 1.4, 1.8, 2.2, 2.6, 3.0, 3.4];
    let rs = [1.0, 0.88, 1.03, 1.1, 1.12, 1.1, 1.05, 1.0, 0.95, 0.9];
    us.iter().zip(rs).map(|(&u, r)| ring(u, r)).collect()
}

#[test]
fn a_natural_end_has_no_u_curvature_and_the_six_point_one_has() {
    let s = wavy();
    let natural = Chain::c2_global_ends(0.0, &s, [EndCurvature::Natural; 2]).unwrap();
    let six = Chain::c2_global(0.0, &s).unwrap();
    for u in [s[0].u, s[9].u] {
        let k = section(&natural, u, 2).max_abs_coef();
        assert!(
            k <= ZERO_CURVATURE_TOL,
            "natural end at u = {u}: curvature {k}"
        );
        let k6 = section(&six, u, 2).max_abs_coef();
        assert!(
            k6 >= SIX_POINT_CURVATURE_MIN,
            "six-point end at u = {u}: curvature {k6}"
        );
    }
    // both interpolate every section
    for c in [&natural, &six] {
        let miss = interpolation_miss(c, &s);
        assert!(miss <= ZERO_CURVATURE_TOL, "a section missed by {miss}");
    }
}

#[test]
fn a_guarded_end_keeps_the_six_point_curvature_where_the_end_does_not_overshoot() {
    let s = wavy();
    let six = Chain::c2_global(0.0, &s).unwrap();
    assert!(start_turn_deg(&six, &s) <= END_TURN_GUARD_DEG);
    let guarded = Chain::c2_global_ends(0.0, &s, [EndCurvature::Guarded; 2]).unwrap();
    assert!(same_surface(&guarded, &six, &s));
}

#[test]
fn a_chord_end_leaves_along_its_chord_and_still_interpolates() {
    let s = overshooting_start();
    let chord = Chain::c2_global_ends(0.0, &s, [EndCurvature::Chord; 2]).unwrap();
    let turn = start_turn_deg(&chord, &s);
    assert!(
        turn <= CHORD_TURN_TOL_DEG,
        "the chord start turns {turn} degrees"
    );
    let m = s.len();
    let end_turn = turn_deg(&chord, &s, m - 2, m - 1);
    assert!(
        end_turn <= CHORD_TURN_TOL_DEG,
        "the chord end turns {end_turn} degrees"
    );
    let miss = interpolation_miss(&chord, &s);
    assert!(miss <= ZERO_CURVATURE_TOL, "a section missed by {miss}");
}

#[test]
fn a_guarded_end_takes_the_chord_where_the_six_point_end_overshoots() {
    let s = overshooting_start();
    let six = Chain::c2_global(0.0, &s).unwrap();
    let turn = start_turn_deg(&six, &s);
    assert!(
        turn > END_TURN_GUARD_DEG,
        "the test's start must overshoot: its six-point end tangent turns {turn} degrees from the chord"
    );
    let guarded = Chain::c2_global_ends(0.0, &s, [EndCurvature::Guarded; 2]).unwrap();
    let chord_start =
        Chain::c2_global_ends(0.0, &s, [EndCurvature::Chord, EndCurvature::SixPoint]).unwrap();
    assert!(same_surface(&guarded, &chord_start, &s));
    let after = start_turn_deg(&guarded, &s);
    assert!(
        after <= CHORD_TURN_TOL_DEG,
        "the guarded start turns {after} degrees, six-point {turn}"
    );
}
