//! Integration tests of the gec family.

use pdesculpt::check::tol;
use pdesculpt::curve::gec::{
    self, fit, fit_auto, fit_fft, FitOptions, Frame, FrameChoice, Gec, GecError, Param, Solver,
};
use proptest::prelude::*;

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
        let opts = FitOptions {
            param: Param::Uniform,
            theta0: Some(0.0),
            solver,
            ..FitOptions::new(3)
        };
        let r = fit(&pts, &opts).unwrap();
        assert!(coeff_diff(&g, &r.gec) < tol::SOLVE, "{solver:?}");
        assert!(r.errors.erm < tol::SOLVE);
    }
    let opts = FitOptions {
        param: Param::Uniform,
        theta0: Some(0.0),
        ..FitOptions::new(3)
    };
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
    let opts = FitOptions {
        frame: FrameChoice::Given(Frame::z_plane(1.5)),
        param: Param::Uniform,
        theta0: Some(0.0),
        ..FitOptions::new(2)
    };
    let r = fit(&pts, &opts).unwrap();
    assert!(coeff_diff(&g, &r.gec) < tol::SOLVE);
    assert_eq!(r.gec.frame, Frame::z_plane(1.5));
}

#[test]
fn auto_terms_reaches_tolerance() {
    let g = sample_gec();
    let pts = g.sample(80);
    let opts = FitOptions {
        param: Param::Uniform,
        ..FitOptions::new(1)
    };
    let r = fit_auto(&pts, 1e-6, 10, &opts).unwrap();
    assert!(r.errors.erm_rel <= 1e-6);
    assert!(r.gec.terms() <= 3);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
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
        let opts = FitOptions { param: Param::ALL[p], ..FitOptions::new(j) };
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
