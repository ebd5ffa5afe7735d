//! Integration tests of the pde4 family.

use pdesculpt::check::tol;
use pdesculpt::pde4::check::{
    checks, plate_centre, rel, sample_boundary, sample_forces, two_sided_boundary,
    two_sided_residual, PLATE_SQUARE_UNIFORM_PRECISE,
};
use pdesculpt::pde4::four_sided::{self, FourSided};
use pdesculpt::pde4::two_sided::{self, TwoSided};
use pdesculpt::pde4::{Force, ForceKind, Pde4Error, ShapeParams};
use pdesculpt::surface::Surface;
use proptest::prelude::*;

/// Lowest acceptable observed convergence order of the Galerkin centre deflection.
const MIN_ORDER: f64 = 2.5;

#[test]
fn pde4_checks_pass() {
    let cs = checks();
    assert!(cs.len() >= 20);
    for c in &cs {
        assert!(
            c.passed,
            "{} measured {:e} tol {:e}: {}",
            c.name, c.measured, c.tolerance, c.note
        );
    }
}

#[test]
fn galerkin_convergence_order() {
    // uniformly loaded clamped square: error vs 0.00126532 at M = N = 8, 12, 16
    let errs: Vec<(f64, f64)> = [8usize, 12, 16]
        .iter()
        .map(|&t| {
            let w = plate_centre(
                ShapeParams::PLATE,
                ForceKind::Uniform,
                t,
                four_sided::Method::Galerkin,
            );
            (t as f64, rel(w, PLATE_SQUARE_UNIFORM_PRECISE))
        })
        .collect();
    for w in errs.windows(2) {
        let order = (w[0].1 / w[1].1).ln() / (w[1].0 / w[0].0).ln();
        eprintln!("order between M = {} and {}: {order:.2}", w[0].0, w[1].0);
        assert!(order > MIN_ORDER, "order {order}");
    }
    assert!(errs[2].1 < tol::TABLE_4_DIGITS);
}

#[test]
fn bad_input_is_rejected() {
    let f = [Force {
        kind: ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
        p: [1.0; 3],
    }];
    let ok = [ShapeParams::PLATE; 3];
    let e = |p: [ShapeParams; 3], f: &[Force], m, n| {
        TwoSided::new(p, f, m, n, two_sided::Method::Exact, None).err()
    };
    assert!(matches!(
        e(
            [ShapeParams {
                a1: 0.0,
                a2: 1.0,
                a3: 1.0
            }; 3],
            &f,
            4,
            4
        ),
        Some(Pde4Error::NonPositiveA1(_))
    ));
    assert!(matches!(
        e(
            [ShapeParams {
                a1: 1.0,
                a2: -3.0,
                a3: 1.0
            }; 3],
            &f,
            4,
            4
        ),
        Some(Pde4Error::NotElliptic { .. })
    ));
    assert!(matches!(
        e(
            [ShapeParams {
                a1: 1.0,
                a2: 1.0,
                a3: 0.0
            }; 3],
            &f,
            4,
            4
        ),
        Some(Pde4Error::NotElliptic { .. })
    ));
    assert!(matches!(
        e(
            [ShapeParams {
                a1: f64::NAN,
                a2: 1.0,
                a3: 1.0
            }; 3],
            &f,
            4,
            4
        ),
        Some(Pde4Error::NonFinite { .. })
    ));
    assert!(matches!(e(ok, &f, 0, 4), Some(Pde4Error::Terms { .. })));
    assert!(matches!(e(ok, &[], 4, 4), Some(Pde4Error::NoForces)));
    let line = [Force {
        kind: ForceKind::Line {
            u0: 0.6,
            u1: 0.4,
            v0: 0.5,
        },
        p: [1.0; 3],
    }];
    assert!(matches!(
        e(ok, &line, 4, 4),
        Some(Pde4Error::EmptyRange { .. })
    ));
    let out = [Force {
        kind: ForceKind::Concentrated { u0: 1.5, v0: 0.5 },
        p: [1.0; 3],
    }];
    assert!(matches!(
        e(ok, &out, 4, 4),
        Some(Pde4Error::OutsidePatch { .. })
    ));
    let nan = [Force {
        kind: ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
        p: [f64::NAN, 0.0, 0.0],
    }];
    assert!(matches!(
        e(ok, &nan, 4, 4),
        Some(Pde4Error::NonFinite { .. })
    ));
    assert!(FourSided::new(ok, &f, 4, 0, four_sided::Method::Galerkin).is_err());
    assert!(FourSided::new(ok, &out, 4, 4, four_sided::Method::Galerkin).is_err());
}

fn params() -> impl Strategy<Value = ShapeParams> {
    (0.05f64..5.0, 0.05f64..5.0, -0.95f64..4.0).prop_map(|(a1, a3, t)| ShapeParams {
        a1,
        a2: t * 2.0 * (a1 * a3).sqrt(),
        a3,
    })
}

fn force() -> impl Strategy<Value = Force> {
    (
        0usize..3,
        0.0f64..1.0,
        0.0f64..1.0,
        0.02f64..1.0,
        0.02f64..1.0,
        -2.0f64..2.0,
    )
        .prop_map(|(k, a, b, la, lb, p)| {
            let (u0, v0) = (a * (1.0 - la), b * (1.0 - lb));
            let kind = match k {
                0 => ForceKind::Concentrated { u0: a, v0: b },
                1 => ForceKind::Line {
                    u0,
                    u1: u0 + la,
                    v0: b,
                },
                _ => ForceKind::Area {
                    u0,
                    u1: u0 + la,
                    v0,
                    v1: v0 + lb,
                },
            };
            Force {
                kind,
                p: [p, 0.5 * p, -p],
            }
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn two_sided_exact_holds(p in params(), fs in prop::collection::vec(force(), 1..4), m in 1usize..10, n in 0usize..6) {
        let t = TwoSided::new([p; 3], &fs, m, n, two_sided::Method::Exact, None).unwrap();
        prop_assert!(two_sided_residual(&t, 6) < tol::SOLVE);
        let scale = t.grid(&[0.25, 0.5], &[0.0, 0.5]).iter().flatten().fold(1.0f64, |a, b| a.max(b.abs()));
        prop_assert!(two_sided_boundary(&t, None, 8) < tol::scaled(tol::SOLVE, scale));
        for q in t.grid(&[0.0, 0.3, 0.7, 1.0], &[0.1, 0.9]) {
            prop_assert!(q.iter().all(|x| x.is_finite()));
        }
        for meth in [two_sided::Method::Paper, two_sided::Method::LeastSquares] {
            if let Ok(s) = TwoSided::new([p; 3], &fs, m, n, meth, None) {
                prop_assert!(s.point(0.4, 0.3).iter().all(|x| x.is_finite()));
            }
        }
    }

    #[test]
    fn two_sided_boundary_curves_hold(p in params(), m in 1usize..8) {
        let b = sample_boundary();
        let t = TwoSided::new([p; 3], &sample_forces(), m, 3, two_sided::Method::Exact, Some(&b)).unwrap();
        prop_assert!(two_sided_boundary(&t, Some(&b), 8) < tol::SOLVE);
    }

    #[test]
    fn four_sided_galerkin_is_finite_and_clamped(p in params(), fs in prop::collection::vec(force(), 1..3), m in 1usize..7, n in 1usize..7) {
        let s = FourSided::new([p; 3], &fs, m, n, four_sided::Method::Galerkin).unwrap();
        let g = s.grid(&[0.0, 0.3, 0.5, 1.0], &[0.0, 0.2, 0.5, 1.0]);
        prop_assert!(g.iter().flatten().all(|x| x.is_finite()));
        prop_assert!(s.point(0.0, 0.4).iter().chain(s.point(0.6, 1.0).iter()).all(|x| x.abs() < tol::ROUNDING));
    }
}
