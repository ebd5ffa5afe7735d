//! Integration tests of the gec family.

use pdesculpt::check::tol;
use pdesculpt::curve::gec::{
    self, fit, fit_auto, fit_fft, Correction, FitOptions, Frame, FrameChoice, Gec, GecError, Param,
    Solver,
};
use proptest::prelude::*;

/// The relative error target given to `fit_auto` / `gec fit --tol` (1e-6).
const AUTO_TARGET: f64 = 1e-6;
/// Normal equations square the condition number: they agree with QR to
/// this fraction of the curve's scale, not to `tol::SOLVE`.
const NORMAL_EQUATIONS: f64 = 1e-7;
/// A curve sampled from a GEC is recovered to this relative error.
const EXACT_RECOVERY: f64 = 1e-8;
/// Derivative values printed to JSON and read back.
const JSON_ROUND_TRIP: f64 = 1e-11;
/// The three solvers' coefficients on the same data.
const SAME_FIT: f64 = 1e-10;
/// A tilted 3-term GEC refitted with 3 terms from 50 samples (relative ErM).
const TILTED_FIT: f64 = 0.05;

fn sample_gec() -> Gec {
    let frame = Frame::from_normal([0.3, 8.0, -0.2], [0.2, 1.0, 0.1], [1.0, 0.0, 0.0]).unwrap();
    Gec::new(
        frame,
        [0.1, -0.05],
        vec![[1.2, 0.1], [0.1, -0.05], [0.02, 0.03]],
        vec![[0.8, 0.05], [-0.04, 0.06], [0.01, -0.02]],
    )
    .unwrap()
}

fn coeff_diff(a: &Gec, b: &Gec) -> f64 {
    let fa = a.to_fourier3().with_harmonics(a.terms().max(b.terms()));
    let fb = b.to_fourier3().with_harmonics(a.terms().max(b.terms()));
    let mut d: f64 = 0.0;
    for k in 0..3 {
        d = d.max((fa.c0[k] - fb.c0[k]).abs());
        for n in 0..fa.cos.len() {
            d = d.max((fa.cos[n][k] - fb.cos[n][k]).abs());
            d = d.max((fa.sin[n][k] - fb.sin[n][k]).abs());
        }
    }
    d
}

#[test]
fn refit_reproduces_coefficients_qr_normal_fft() {
    let g = sample_gec();
    let pts = g.sample(64);
    for solver in [Solver::Qr, Solver::NormalEquations] {
        let opts = FitOptions::new(3)
            .with_param(Param::Uniform)
            .with_theta0(Some(0.0))
            .with_solver(solver);
        let r = fit(&pts, &opts).unwrap();
        assert!(coeff_diff(&g, &r.gec) < tol::SOLVE, "{solver:?}");
        assert!(r.errors.erm < tol::SOLVE);
    }
    let opts = FitOptions::new(3)
        .with_param(Param::Uniform)
        .with_theta0(Some(0.0));
    let r = fit_fft(&pts, &opts, 64).unwrap();
    assert!(coeff_diff(&g, &r.gec) < tol::SOLVE);
}

#[test]
fn fourier3_conversion_matches_eval() {
    let g = sample_gec();
    let f = g.to_fourier3();
    for k in 0..17 {
        let t = 0.37 * k as f64;
        let a = g.eval(t);
        let b = f.eval(t);
        for i in 0..3 {
            assert!((a[i] - b[i]).abs() < tol::ROUNDING);
        }
    }
}

#[test]
fn paper_orderings_round_trip() {
    let g = Gec::new(
        Frame::z_plane(2.5),
        [0.1, 0.2],
        vec![[1.0, 0.2], [0.05, 0.01]],
        vec![[0.7, 0.1], [0.02, -0.03]],
    )
    .unwrap();
    let (xs, ys) = g.to_paper_000();
    assert_eq!(
        Gec::from_paper_000(Frame::z_plane(2.5), &xs, &ys).unwrap(),
        g
    );
    let [ax, bx, ay, by] = g.to_paper_002();
    assert_eq!(
        Gec::from_paper_002(Frame::z_plane(2.5), &ax, &bx, &ay, &by).unwrap(),
        g
    );
    for k in 0..11 {
        let v = k as f64 / 10.0;
        let p = gec::paper_000_literal(&xs, &ys, 2.5, v);
        let q = gec::paper_002_literal(&ax, &bx, &ay, &by, 2.5, 2.0 * std::f64::consts::PI * v);
        let e = g.eval_v(v);
        for i in 0..3 {
            assert!((p[i] - e[i]).abs() < tol::ROUNDING);
            assert!((q[i] - e[i]).abs() < tol::ROUNDING);
        }
    }
}

#[test]
fn bad_input_errors() {
    let g = sample_gec();
    let pts = g.sample(20);
    assert_eq!(
        fit(&pts, &FitOptions::new(0)).unwrap_err(),
        GecError::ZeroTerms
    );
    assert!(matches!(
        fit(&pts[..6], &FitOptions::new(3)),
        Err(GecError::TooFewPoints {
            needed: 7,
            got: 6,
            ..
        })
    ));
    let mut nan = pts.clone();
    nan[4][1] = f64::NAN;
    assert!(matches!(
        fit(&nan, &FitOptions::new(2)),
        Err(GecError::NonFinite { index: 4, .. })
    ));
    let mut rep = pts.clone();
    rep.push(pts[0]);
    assert!(matches!(
        fit(&rep, &FitOptions::new(2)),
        Err(GecError::RepeatedPoint { .. })
    ));
    let line: Vec<[f64; 3]> = (0..10).map(|i| [i as f64, 0.0, 0.0]).collect();
    assert!(matches!(
        fit(&line, &FitOptions::new(2)),
        Err(GecError::Degenerate(_))
    ));
    let mut bent = pts.clone();
    bent[3][1] += 0.5;
    assert!(matches!(
        fit(&bent, &FitOptions::new(2)),
        Err(GecError::NotPlanar { .. })
    ));
    assert!(matches!(
        fit_auto(&pts, f64::NAN, 5, &FitOptions::new(1)),
        Err(GecError::InvalidParameter(_))
    ));
}

#[test]
fn given_frame_z_plane() {
    let g = Gec::new(
        Frame::z_plane(1.5),
        [0.0, 0.0],
        vec![[1.0, 0.0], [0.1, 0.0]],
        vec![[0.5, 0.0], [0.0, 0.05]],
    )
    .unwrap();
    let pts = g.sample(40);
    let opts = FitOptions::new(2)
        .with_frame(FrameChoice::Given(Frame::z_plane(1.5)))
        .with_param(Param::Uniform)
        .with_theta0(Some(0.0));
    let r = fit(&pts, &opts).unwrap();
    assert!(coeff_diff(&g, &r.gec) < tol::SOLVE);
    assert_eq!(r.gec.frame, Frame::z_plane(1.5));
}

#[test]
fn auto_terms_reaches_tolerance() {
    let g = sample_gec();
    let pts = g.sample(80);
    let opts = FitOptions::new(1).with_param(Param::Uniform);
    let r = fit_auto(&pts, AUTO_TARGET, 10, &opts).unwrap();
    assert!(r.errors.erm_rel <= AUTO_TARGET);
    assert!(r.gec.terms() <= 3);
}

proptest! {
    #![proptest_config(crate::strategies::config(32))]
    #[test]
    fn fit_never_panics_or_nans(
        a in 0.2f64..3.0, b in 0.2f64..3.0, w in -0.15f64..0.15,
        n in 8usize..120, j in 1usize..12, p in 0usize..4,
        nx in -1.0f64..1.0, ny in -1.0f64..1.0, nz in 0.1f64..1.0,
    ) {
        let frame = Frame::from_normal([1.0, 2.0, 3.0], [nx, ny, nz], [1.0, 0.0, 0.0]).unwrap();
        let g = Gec::new(frame, [0.0, 0.0], vec![[a, 0.0], [w * a, 0.0], [0.0, w * b]],
            vec![[b, 0.0], [0.0, w * b], [w * a, 0.0]]).unwrap();
        let pts = g.sample(n);
        let opts = FitOptions::new(j).with_param(Param::ALL[p]);
        match fit(&pts, &opts) {
            Ok(r) => {
                prop_assert!(r.gec.is_finite());
                prop_assert!(r.errors.erm.is_finite() && r.errors.era.is_finite());
                prop_assert!(r.errors.era <= r.errors.erm + tol::ROUNDING);
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
    }
}

// ---------------------------------------------------------------------------
// Property tests over the documented ranges (module doc of `curve::gec`,
// "Tested ranges"): J in 1..=12, 2J+1..=300 points, size (largest radius)
// 1e-3..1e3, centre and plane origin up to 1e3 away, any plane orientation,
// harmonic n up to 5 % / n^2 of the radius (regular, non-self-intersecting).

/// A GEC with `j` terms: an ellipse of radii `(a, b) * size` plus small
/// harmonics, in the plane through `origin` with normal `normal`.
fn gec_strategy(jmax: usize) -> impl Strategy<Value = Gec> {
    (
        1usize..=jmax,
        -3.0f64..3.0,
        0.3f64..1.0,
        0.3f64..1.0,
        prop::array::uniform3(-1e3f64..1e3),
        prop::array::uniform3(-1.0f64..1.0),
        prop::array::uniform2(-1.0f64..1.0),
        prop::collection::vec(prop::array::uniform4(-0.05f64..0.05), 12),
    )
        .prop_filter_map(
            "normal too short",
            |(j, lsize, a, b, origin, normal, centre, h)| {
                if normal.iter().map(|v| v * v).sum::<f64>() < 0.01 {
                    return None;
                }
                let size = 10f64.powf(lsize);
                let frame = Frame::from_normal(origin, normal, [1.0, 0.0, 0.0]).ok()?;
                let mut x = vec![[a * size, 0.1 * h[0][0] * size]];
                let mut y = vec![[b * size, 0.1 * h[0][1] * size]];
                for n in 1..j {
                    // amplitude 5 % / n^2: the speed stays positive (no cusps)
                    let q = h[n];
                    let w = size / ((n + 1) * (n + 1)) as f64;
                    x.push([q[0] * a * w, q[1] * a * w]);
                    y.push([q[2] * b * w, q[3] * b * w]);
                }
                Gec::new(frame, [centre[0] * size, centre[1] * size], x, y).ok()
            },
        )
}

fn max_dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max)
}

/// Coefficient difference relative to the curve's size (origin excluded).
fn rel_coeff_diff(a: &Gec, b: &Gec) -> f64 {
    let s = a.scale() - a.centre[0].abs() - a.centre[1].abs();
    coeff_diff(a, b) / s.max(1e-300)
}

proptest! {
    #![proptest_config(crate::strategies::config(48))]

    #[test]
    fn transforms_equal_transformed_points(
        g in gec_strategy(8),
        d in prop::array::uniform3(-10.0f64..10.0),
        sx in -3.0f64..3.0, sy in -3.0f64..3.0,
        c in prop::array::uniform2(-2.0f64..2.0),
        phi in -7.0f64..7.0,
        axis in prop::array::uniform3(-1.0f64..1.0),
        h in -0.5f64..0.5, tc in -7.0f64..7.0, sigma in 0.05f64..2.0,
        t in 0.0f64..6.3,
    ) {
        let size = g.scale();
        let tol = tol::SOLVE * (size + 10.0);
        let f = g.frame;
        let p = g.eval_plane(t);
        // translate
        let q = g.translated(d).eval(t);
        let e = g.eval(t);
        prop_assert!(max_dist(q, [e[0] + d[0], e[1] + d[1], e[2] + d[2]]) < tol);
        // scale about c in the frame
        let q = g.scaled(sx, sy, c).eval(t);
        let want = f.place(c[0] + sx * (p[0] - c[0]), c[1] + sy * (p[1] - c[1]));
        prop_assert!(max_dist(q, want) < tol * 3.0);
        // rotate about c in the plane
        let q = g.rotated(phi, c).eval(t);
        let (s, co) = phi.sin_cos();
        let r = [p[0] - c[0], p[1] - c[1]];
        let want = f.place(c[0] + co * r[0] - s * r[1], c[1] + s * r[0] + co * r[1]);
        prop_assert!(max_dist(q, want) < tol);
        // rigid motion in space
        let n = (axis.iter().map(|v| v * v).sum::<f64>()).sqrt();
        if n > 0.1 {
            let k = [axis[0] / n, axis[1] / n, axis[2] / n];
            let q = g.rigid(c3(c), k, phi, d).eval(t);
            let rot = gec::transform::rotate(
                [e[0] - c[0], e[1] - c[1], e[2]], k, phi);
            let want = [rot[0] + c[0] + d[0], rot[1] + c[1] + d[1], rot[2] + d[2]];
            prop_assert!(max_dist(q, want) < tol);
        }
        // bump: the curve moves by h b(theta) along (cos tc, sin tc), b(tc) = 1
        let bumped = g.with_bump(h, tc, sigma).unwrap();
        let moved = bumped.eval_plane(tc);
        let orig = g.eval_plane(tc);
        prop_assert!(((moved[0] - orig[0]) - h * tc.cos()).abs() < tol);
        prop_assert!(((moved[1] - orig[1]) - h * tc.sin()).abs() < tol);
        let mv = bumped.eval_plane(t);
        let cross = (mv[0] - p[0]) * tc.sin() - (mv[1] - p[1]) * tc.cos();
        prop_assert!(cross.abs() < tol, "bump moves along its direction only");
    }

    #[test]
    fn bend_of_perpendicular_sections_equals_bent_points(
        kappa in -0.5f64..0.5,
        zs in prop::collection::vec(-3.0f64..3.0, 1..6),
        t in 0.0f64..6.3,
        a in 0.3f64..2.0,
    ) {
        let bend = gec::transform::Bend::new([0.1, -0.2, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], kappa).unwrap();
        let chain: Vec<Gec> = zs.iter().map(|&z| {
            Gec::new(Frame::z_plane(z), [0.1, 0.0], vec![[a, 0.1], [0.05, 0.0]], vec![[0.7, 0.0], [0.0, 0.03]]).unwrap()
        }).collect();
        for (g, b) in chain.iter().zip(bend.apply_chain(&chain)) {
            prop_assert!(max_dist(b.eval(t), bend.apply(g.eval(t))) < tol::SOLVE);
        }
    }

    #[test]
    fn fft_fit_equals_least_squares_on_uniform_samples(
        g in gec_strategy(12), j in 1usize..=12, extra in 1usize..200, p in 0usize..3,
    ) {
        // M > 2J uniform samples: the truncated DFT is the least-squares solution,
        // whether or not the curve has more harmonics than J (discrete orthogonality)
        let m = 2 * j + extra;
        let pts = g.sample(m);
        // the least squares at the rule's angles (no parameter correction:
        // this compares solvers at the same angles)
        let opts = FitOptions::new(j).with_param(Param::Uniform).with_theta0(Some(0.0)).with_correction(Correction::None);
        let qr = fit(&pts, &opts).unwrap();
        let ne = fit(&pts, &opts.with_solver(Solver::NormalEquations)).unwrap();
        let ff = fit_fft(&pts, &opts, m).unwrap();
        prop_assert!(rel_coeff_diff(&g, &ff.gec).is_finite());
        prop_assert!(coeff_diff(&qr.gec, &ff.gec) / g.scale() < tol::SOLVE,
            "fft vs qr {:e}", coeff_diff(&qr.gec, &ff.gec) / g.scale());
        prop_assert!(coeff_diff(&qr.gec, &ne.gec) / g.scale() < NORMAL_EQUATIONS,
            "normal equations vs qr {:e}", coeff_diff(&qr.gec, &ne.gec) / g.scale());
        // other parameterisations resample first: still a valid, close fit
        let opts = FitOptions::new(j).with_param(Param::ALL[p]);
        let r = gec::fit_fft(&pts, &opts, 4 * m).unwrap();
        prop_assert!(r.gec.is_finite() && r.errors.erm.is_finite());
    }

    #[test]
    fn refit_reproduces_coefficients(g in gec_strategy(12), extra in 1usize..100, solver in 0usize..2) {
        let j = g.terms();
        let pts = g.sample(2 * j + extra);
        let opts = FitOptions::new(j).with_param(Param::Uniform).with_theta0(Some(0.0)).with_solver([Solver::Qr, Solver::NormalEquations][solver]);
        let r = fit(&pts, &opts).unwrap();
        let d = rel_coeff_diff(&g, &r.gec);
        prop_assert!(d < EXACT_RECOVERY, "relative coefficient error {d:e}");
        prop_assert!(r.errors.erm_rel < EXACT_RECOVERY);
        // and the fitted curve passes through the same points
        for (k, q) in pts.iter().enumerate().step_by(7) {
            let t = 2.0 * std::f64::consts::PI * k as f64 / pts.len() as f64;
            prop_assert!(max_dist(r.gec.eval(t), *q) < EXACT_RECOVERY * g.scale());
        }
    }

    #[test]
    fn noisy_star_polygons_fit_finite(
        n in 7usize..300,
        radii in prop::collection::vec(0.5f64..1.5, 300),
        lsize in -3.0f64..3.0,
        j in 1usize..=12, p in 0usize..4, s in 0usize..3,
        z in -1e3f64..1e3,
    ) {
        // any star-shaped polygon (random radius per angle): Ok with finite
        // output, or a clear error (too few points for J, rank deficiency)
        let size = 10f64.powf(lsize);
        let pts: Vec<[f64; 3]> = (0..n).map(|k| {
            let t = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            [size * radii[k] * t.cos(), z, size * radii[k] * t.sin()]
        }).collect();
        let opts = FitOptions::new(j).with_param(Param::ALL[p]);
        let r = match s {
            0 => fit(&pts, &opts),
            1 => fit(&pts, &opts.with_solver(Solver::NormalEquations)),
            _ => fit_fft(&pts, &opts, n.max(4 * j + 2)),
        };
        match r {
            Ok(r) => {
                prop_assert!(r.gec.is_finite());
                prop_assert!(r.thetas.iter().all(|t| t.is_finite()));
                let e = r.errors;
                for v in [e.erm, e.era, e.erm_rel, e.era_rel, e.hausdorff, e.hausdorff_rel] {
                    prop_assert!(v.is_finite() && v >= 0.0);
                }
                prop_assert!(e.era <= e.erm + tol::ROUNDING * size);
                prop_assert!(e.erm <= e.hausdorff + tol::ROUNDING * size);
            }
            Err(e) => {
                // too few points for J, rank deficiency, or (FFT path, polar
                // angle) a polygon that is not star-shaped about its centroid
                let polar_fft = s == 2 && Param::ALL[p] == Param::PolarAngle;
                prop_assert!(n < 2 * j + 1
                    || matches!(e, GecError::RankDeficient { .. })
                    || (polar_fft && matches!(e, GecError::InvalidParameter(_))), "{e}");
            }
        }
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic(
        pts in prop::collection::vec(prop::array::uniform3(prop_oneof![
            4 => -2.0f64..2.0,
            1 => Just(0.0),
            1 => Just(f64::NAN),
            1 => Just(f64::INFINITY),
            1 => Just(1e308),
        ]), 0..40),
        j in 0usize..8, p in 0usize..4, s in 0usize..3, tol_e in prop_oneof![Just(-1.0), Just(0.0), Just(1e-3), Just(f64::NAN)],
    ) {
        let opts = FitOptions::new(j).with_param(Param::ALL[p]);
        let results = [
            match s {
                0 => fit(&pts, &opts),
                1 => fit(&pts, &opts.with_solver(Solver::NormalEquations)),
                _ => fit_fft(&pts, &opts, pts.len()),
            },
            fit_auto(&pts, tol_e, j, &opts),
        ];
        for r in results {
            match r {
                Ok(r) => {
                    prop_assert!(r.gec.is_finite());
                    prop_assert!(r.errors.erm.is_finite() && r.errors.era.is_finite());
                }
                Err(e) => prop_assert!(!e.to_string().is_empty()),
            }
        }
        let _ = gec::check_closed(&pts);
        let _ = gec::repeated_points(&pts);
        let mut v = pts.clone();
        let _ = gec::strip_closing_copy(&mut v);
    }

    #[test]
    fn open_arcs_are_rejected_closed_curves_accepted(
        n in 12usize..200, frac in 0.1f64..0.85, a in 0.5f64..2.0, b in 0.5f64..2.0,
    ) {
        let arc: Vec<[f64; 3]> = (0..n).map(|k| {
            let t = 2.0 * std::f64::consts::PI * frac * k as f64 / (n - 1) as f64;
            [a * t.cos(), b * t.sin(), 0.0]
        }).collect();
        // lower bound of the gap (diag(a, b) maps the unit circle: chords shrink
        // by at most min(a, b)) against an upper bound of every segment
        let step = 2.0 * std::f64::consts::PI * frac / (n - 1) as f64;
        let missing = (1.0 - frac) * 2.0 * std::f64::consts::PI;
        let gap_lo = a.min(b) * 2.0 * (0.5 * missing.min(2.0 * std::f64::consts::PI - missing)).sin();
        if gap_lo > 10.0 * a.max(b) * step * 1.01 {
            let open = matches!(gec::check_closed(&arc), Err(GecError::OpenPolyline { .. }));
            prop_assert!(open, "arc of {} points, fraction {}, not rejected", n, frac);
        }
        let closed = Gec::ellipse(Frame::z_plane(0.0), [0.0, 0.0], a, b).sample(n);
        prop_assert!(gec::check_closed(&closed).is_ok());
    }
}

fn c3(c: [f64; 2]) -> [f64; 3] {
    [c[0], c[1], 0.0]
}

#[test]
fn closing_copy_and_repeated_points() {
    let g = sample_gec();
    let mut pts = g.sample(30);
    assert!(gec::repeated_points(&pts).is_none());
    pts.push(pts[0]);
    assert!(gec::strip_closing_copy(&mut pts));
    assert_eq!(pts.len(), 30);
    assert!(!gec::strip_closing_copy(&mut pts));
    // a repeated point far from its twin in the order
    let mut rep = pts.clone();
    rep.insert(20, pts[5]);
    assert_eq!(gec::repeated_points(&rep), Some((5, 20)));
    // dense on one side, sparse on the other: closed
    let mut uneven: Vec<[f64; 3]> = (0..50)
        .map(|k| {
            let t = std::f64::consts::PI * k as f64 / 50.0;
            [t.cos(), t.sin(), 0.0]
        })
        .collect();
    uneven.extend((0..3).map(|k| {
        let t = std::f64::consts::PI * (1.0 + 0.4 * k as f64);
        [t.cos(), t.sin(), 0.0]
    }));
    assert!(gec::check_closed(&uneven).is_ok());
    let open: Vec<[f64; 3]> = uneven[..40].to_vec();
    assert!(matches!(
        gec::check_closed(&open),
        Err(GecError::OpenPolyline { .. })
    ));
    assert!(gec::check_closed(&open)
        .unwrap_err()
        .to_string()
        .contains("open"));
}

// ---------------------------------------------------------------------------
// The command line: `pdesculpt gec fit` and `pdesculpt gec eval`.

mod cli {
    use super::*;
    use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
    use std::path::Path;

    fn s(p: &Path) -> &str {
        p.to_str().expect("utf8 path")
    }

    fn json_out(out: &std::process::Output) -> serde_json::Value {
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).expect("json on stdout")
    }

    /// An ellipse with two extra harmonics in the plane z = 0.5, as CSV rows.
    fn curve() -> Gec {
        Gec::new(
            Frame::z_plane(0.5),
            [0.3, -0.2],
            vec![[1.5, 0.0], [0.05, -0.02], [0.01, 0.0]],
            vec![[0.9, 0.0], [0.03, 0.04], [0.0, -0.01]],
        )
        .unwrap()
    }

    fn csv(points: &[[f64; 3]], header: bool, dims: usize) -> String {
        let mut t = String::new();
        if header {
            t.push_str(if dims == 3 { "x,y,z\n" } else { "x,y\n" });
        }
        for p in points {
            let row: Vec<String> = p[..dims].iter().map(|v| format!("{v:.17e}")).collect();
            t.push_str(&row.join(","));
            t.push('\n');
        }
        t
    }

    #[test]
    fn fit_csv_json_and_eval_round_trip() {
        let d = tmpdir("gec-fit");
        let g = curve();
        let pts = g.sample(64);
        let file = d.join("pts.csv");
        std::fs::write(&file, csv(&pts, true, 3)).unwrap();
        let gec_json = d.join("fit.json");
        let v = json_out(&pdesculpt(&[
            "--json",
            "gec",
            "fit",
            "--input",
            s(&file),
            "--terms",
            "3",
            "--param",
            "uniform",
            "--theta0",
            "0",
            "-o",
            s(&gec_json),
        ]));
        assert_eq!(v["terms"], 3);
        assert_eq!(v["points"], 64);
        assert_eq!(v["param"], "uniform");
        // all points at z = 0.5: the paper's placement, coefficients in x, y
        let fitted: Gec = serde_json::from_value(v["gec"].clone()).unwrap();
        assert_eq!(fitted.frame, Frame::z_plane(0.5));
        assert!(
            coeff_diff(&g, &fitted) < tol::SOLVE,
            "{}",
            coeff_diff(&g, &fitted)
        );
        assert!(v["errors"]["erm"].as_f64().unwrap() < tol::SOLVE);
        assert!(v["errors"]["era"].as_f64().unwrap() <= v["errors"]["erm"].as_f64().unwrap());
        // the paper orderings are printed too
        assert_eq!(v["paper_000"]["x"].as_array().unwrap().len(), 7);
        assert_eq!(v["paper_002"]["b_y"].as_array().unwrap().len(), 3);
        // -o wrote the same GEC
        let written: Gec =
            serde_json::from_str(&std::fs::read_to_string(&gec_json).unwrap()).unwrap();
        assert_eq!(written, fitted);
        // same result from the library
        let lib = fit(
            &pts,
            &FitOptions::new(3)
                .with_param(Param::Uniform)
                .with_theta0(Some(0.0))
                .with_frame(gec::FrameChoice::Given(Frame::z_plane(0.5))),
        )
        .unwrap();
        assert!(coeff_diff(&lib.gec, &fitted) < tol::ROUNDING);

        // eval: values and derivatives at angles, in radians and in turns
        let v = json_out(&pdesculpt(&[
            "--json",
            "gec",
            "eval",
            "--gec",
            s(&gec_json),
            "--at",
            "0.3",
            "--at",
            "-1.2",
            "--derivative",
            "2",
        ]));
        let list = v["points"].as_array().unwrap();
        assert_eq!(list.len(), 2);
        for (item, t) in list.iter().zip([0.3, -1.2]) {
            let want = fitted.derivative(t, 2);
            for k in 0..3 {
                assert!((item["value"][k].as_f64().unwrap() - want[k]).abs() < tol::ROUNDING);
            }
        }
        let v = json_out(&pdesculpt(&[
            "--json",
            "gec",
            "eval",
            "--gec",
            s(&gec_json),
            "--at",
            "0.25",
            "--turns",
            "--derivative",
            "1",
        ]));
        let want = fitted.derivative(std::f64::consts::FRAC_PI_2, 1);
        for k in 0..3 {
            let got = v["points"][0]["value"][k].as_f64().unwrap();
            assert!((got - 2.0 * std::f64::consts::PI * want[k]).abs() < JSON_ROUND_TRIP);
        }
        // --samples resamples a closed polyline; plain output is "t x y z" lines
        let out = pdesculpt(&["gec", "eval", "--gec", s(&gec_json), "--samples", "16"]);
        assert!(out.status.success());
        let text = String::from_utf8_lossy(&out.stdout);
        let rows: Vec<Vec<f64>> = text
            .lines()
            .map(|l| l.split_whitespace().map(|f| f.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), 16);
        for (k, r) in rows.iter().enumerate() {
            let p = fitted.sample(16)[k];
            assert_eq!(r.len(), 4);
            for i in 0..3 {
                assert!((r[i + 1] - p[i]).abs() < tol::ROUNDING);
            }
        }
        // eval also reads the --json report of fit (its "gec" field)
        let report = d.join("report.json");
        std::fs::write(&report, serde_json::to_string(&v).unwrap()).unwrap();
        let out = pdesculpt(&["gec", "eval", "--gec", s(&report), "--at", "0"]);
        assert_clear_error(&out, "expected a GEC");
        let full = pdesculpt(&["--json", "gec", "fit", "--input", s(&file), "--terms", "3"]);
        std::fs::write(&report, &full.stdout).unwrap();
        assert!(
            pdesculpt(&["gec", "eval", "--gec", s(&report), "--at", "0"])
                .status
                .success()
        );
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn fit_json_inputs_solvers_tolerance_and_quiet_mode() {
        let d = tmpdir("gec-fit-json");
        let g = curve();
        let pts = g.sample(128);
        // 2-column array, first point repeated at the end (dropped)
        let mut arr: Vec<[f64; 2]> = pts.iter().map(|p| [p[0], p[1]]).collect();
        arr.push(arr[0]);
        let file = d.join("pts.json");
        std::fs::write(&file, serde_json::to_string(&arr).unwrap()).unwrap();
        let qr = json_out(&pdesculpt(&[
            "--json",
            "gec",
            "fit",
            "-i",
            s(&file),
            "--terms",
            "3",
        ]));
        assert_eq!(qr["dropped_closing_copy"], true);
        assert_eq!(qr["points"], 128);
        assert_eq!(qr["columns"], 2);
        assert_eq!(qr["gec"]["frame"]["origin"][2], 0.0);
        // {"points": [...]} object, three solvers agree (uniform samples)
        let obj = d.join("obj.json");
        std::fs::write(
            &obj,
            serde_json::json!({"points": pts, "closed": true}).to_string(),
        )
        .unwrap();
        let mut fits = Vec::new();
        for solver in ["qr", "normal", "fft"] {
            let v = json_out(&pdesculpt(&[
                "--json",
                "gec",
                "fit",
                "-i",
                s(&obj),
                "--terms",
                "4",
                "--param",
                "uniform",
                "--solver",
                solver,
            ]));
            fits.push(serde_json::from_value::<Gec>(v["gec"].clone()).unwrap());
        }
        assert!(coeff_diff(&fits[0], &fits[1]) < SAME_FIT);
        assert!(coeff_diff(&fits[0], &fits[2]) < SAME_FIT);
        // --tol: smallest J reaching the relative ErM
        let v = json_out(&pdesculpt(&[
            "--json",
            "gec",
            "fit",
            "-i",
            s(&obj),
            "--tol",
            "1e-6",
            "--param",
            "uniform",
        ]));
        assert_eq!(v["terms"], 3);
        assert!(v["errors"]["erm_rel"].as_f64().unwrap() <= AUTO_TARGET);
        let out = pdesculpt(&[
            "gec",
            "fit",
            "-i",
            s(&obj),
            "--tol",
            "1e-14",
            "--max-terms",
            "2",
        ]);
        assert_clear_error(&out, "not reached with J <= 2");
        // a tilted plane (3 columns, varying z): fitted frame
        let tilted = gec::samples::tilted_gec().sample(50);
        let tf = d.join("tilted.csv");
        std::fs::write(&tf, csv(&tilted, false, 3)).unwrap();
        let v = json_out(&pdesculpt(&[
            "--json",
            "gec",
            "fit",
            "-i",
            s(&tf),
            "--terms",
            "3",
        ]));
        assert!(v["errors"]["erm_rel"].as_f64().unwrap() < TILTED_FIT);
        assert!(v["off_plane"].as_f64().unwrap() < tol::ROUNDING);
        assert_clear_error(
            &pdesculpt(&["gec", "fit", "-i", s(&tf), "--frame", "z"]),
            "same z",
        );
        // without --json: nothing on stdout, summary with ErM/ErA on stderr
        let out = pdesculpt(&["gec", "fit", "-i", s(&file), "--terms", "2"]);
        assert!(out.status.success());
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("ErM") && err.contains("ErA") && err.contains("a_xn"),
            "{err}"
        );
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn bad_inputs_get_clear_errors_and_no_output_file() {
        let d = tmpdir("gec-bad");
        let out_json = d.join("out.json");
        let o = s(&out_json).to_string();
        let fit_file = |name: &str, body: &str, extra: &[&str]| {
            let f = d.join(name);
            std::fs::write(&f, body).unwrap();
            let mut args = vec!["gec", "fit", "-i", s(&f), "-o", &o];
            args.extend_from_slice(extra);
            let out = pdesculpt(&args);
            assert!(
                out.status.success() || !out_json.exists(),
                "{name}: no output on error"
            );
            out
        };
        let g = curve();
        let good = csv(&g.sample(40), false, 2);
        // missing file
        assert_clear_error(
            &pdesculpt(&["gec", "fit", "-i", "/no/such/points.csv"]),
            "/no/such/points.csv",
        );
        // malformed csv: line number
        let mut bad = good.clone();
        bad.push_str("1.0,abc\n");
        assert_clear_error(&fit_file("bad.csv", &bad, &[]), "line 41");
        assert_clear_error(&fit_file("bad.csv", &bad, &[]), "\"abc\" is not a number");
        assert_clear_error(
            &fit_file("cols.csv", "0,0\n1,0,2\n", &[]),
            "line 2: 3 fields, but earlier rows have 2",
        );
        assert_clear_error(
            &fit_file("four.csv", "0 0 0 0\n", &[]),
            "line 1: expected 2 or 3",
        );
        assert_clear_error(&fit_file("empty.csv", "# nothing\n\n", &[]), "no points");
        // NaN (csv: line number; json has no NaN literal)
        let nan = good.replacen('\n', "\nnan,0.5\n", 3);
        assert_clear_error(
            &fit_file("nan.csv", &nan, &[]),
            "line 2: coordinate 1 is nan",
        );
        assert_clear_error(
            &fit_file("nan.json", "[[0, 0], [NaN, 1]]", &[]),
            "invalid JSON",
        );
        assert_clear_error(
            &fit_file("str.json", "[[0, 0], [\"a\", 1], [1, 1]]", &[]),
            "point 1: coordinate \"a\" is not a finite number",
        );
        assert_clear_error(
            &fit_file("obj.json", "{\"pts\": []}", &[]),
            "\"points\" array",
        );
        // fewer than 2J+1 points
        let few = csv(&g.sample(6), false, 2);
        assert_clear_error(
            &fit_file("few.csv", &few, &["--terms", "3"]),
            "J = 3 needs at least 7 points (2J+1), got 6",
        );
        // J = 0
        assert_clear_error(
            &fit_file("good.csv", &good, &["--terms", "0"]),
            "at least 1",
        );
        // repeated points (not the closing copy), with their lines
        let mut rows: Vec<&str> = good.lines().collect();
        rows.insert(30, rows[4]);
        let rep = rows.join("\n");
        assert_clear_error(
            &fit_file("rep.csv", &format!("x,y\n{rep}\n"), &[]),
            "point 4 (line 6) and point 30 (line 32) coincide",
        );
        // open polylines: declared (json, csv) or a large closing gap
        let arc: Vec<[f64; 3]> = g.sample(40)[..20].to_vec();
        let arc_csv = csv(&arc, false, 2);
        let out = fit_file("arc.csv", &arc_csv, &["--terms", "3"]);
        assert_clear_error(&out, "the polyline is open");
        assert_clear_error(&out, "--assume-closed");
        let out = fit_file("arc.csv", &arc_csv, &["--terms", "3", "--assume-closed"]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        std::fs::remove_file(&out_json).unwrap();
        let declared = serde_json::json!({"points": g.sample(40), "closed": false}).to_string();
        assert_clear_error(
            &fit_file("open.json", &declared, &[]),
            "declares the polyline open",
        );
        assert_clear_error(
            &fit_file("open.csv", &format!("# open\n{good}"), &[]),
            "declares the polyline open",
        );
        // bad options
        assert_clear_error(
            &fit_file("good.csv", &good, &["--param", "spiral"]),
            "unknown parameterisation 'spiral'",
        );
        assert_clear_error(&fit_file("good.csv", &good, &["--tol", "-1"]), "tolerance");
        assert_clear_error(
            &fit_file("good.csv", &good, &["--tol", "1e-3", "--solver", "fft"]),
            "--solver fft needs --terms",
        );
        // usage error (clap): --terms with --tol
        let out = fit_file("good.csv", &good, &["--terms", "2", "--tol", "1e-3"]);
        assert_eq!(out.status.code(), Some(2));
        // eval errors
        let gj = d.join("g.json");
        std::fs::write(&gj, serde_json::to_string(&g).unwrap()).unwrap();
        assert_clear_error(
            &pdesculpt(&[
                "gec",
                "eval",
                "--gec",
                s(&gj),
                "--at",
                "0",
                "--derivative",
                "9",
            ]),
            "at most 8",
        );
        assert_clear_error(
            &pdesculpt(&["gec", "eval", "--gec", s(&gj), "--at", "inf"]),
            "must be finite",
        );
        assert_clear_error(
            &pdesculpt(&["gec", "eval", "--gec", s(&gj), "--samples", "0"]),
            "at least 1",
        );
        assert_clear_error(
            &pdesculpt(&["gec", "eval", "--gec", "/no/such/gec.json", "--at", "0"]),
            "/no/such/gec.json",
        );
        let mut broken = serde_json::to_value(&g).unwrap();
        broken["y"] = serde_json::json!([[1.0, 0.0]]);
        std::fs::write(&gj, broken.to_string()).unwrap();
        assert_clear_error(
            &pdesculpt(&["gec", "eval", "--gec", s(&gj), "--at", "0"]),
            "x has 3 pairs, y has 1",
        );
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn help_documents_the_formats() {
        let out = pdesculpt(&["gec", "fit", "--help"]);
        assert!(out.status.success());
        let h = String::from_utf8_lossy(&out.stdout);
        for needle in [
            "INPUT FORMATS",
            "CSV",
            "JSON",
            "OPEN",
            "--assume-closed",
            "2J+1",
            "ErM",
        ] {
            assert!(h.contains(needle), "help mentions {needle}");
        }
        let out = pdesculpt(&["gec", "eval", "--help"]);
        assert!(String::from_utf8_lossy(&out.stdout).contains("--turns"));
    }
}

/// `Gec::sample_plane` reads its sines and cosines from one table of `m`
/// angles; it agrees with `eval_plane` at each angle to rounding.
#[test]
fn sample_plane_equals_eval_plane() {
    let g = sample_gec();
    for m in [1, 2, 7, 1024] {
        let pts = g.sample_plane(m);
        assert_eq!(pts.len(), m);
        for (k, p) in pts.iter().enumerate() {
            let q = g.eval_plane(2.0 * std::f64::consts::PI * k as f64 / m as f64);
            let d = (p[0] - q[0]).hypot(p[1] - q[1]);
            assert!(d <= tol::ROUNDING, "m {m} k {k}: {p:?} vs {q:?}");
        }
    }
    assert!(g.sample_plane(0).is_empty());
}
