//! Integration tests of the ode6 family (paper 004).

use pdesculpt::check::tol;
use pdesculpt::jet::Jet;
use pdesculpt::ode6::basis::{solve_line, RCOND_MIN};
use pdesculpt::ode6::check::test_curve;
use pdesculpt::ode6::{
    Approach2, Basis, BoundaryCurves, Curve, DiffFormula, Force, Ode6Error, Ode6Surface, Params,
};
use pdesculpt::surface::{tessellate, Surface, Tessellation};
use proptest::prelude::*;

/// Every ode6 check passes.
#[test]
fn ode6_checks_pass() {
    let checks = pdesculpt::ode6::check::checks();
    assert!(checks.len() > 60);
    let failed: Vec<_> = checks
        .iter()
        .filter(|c| !c.passed)
        .map(|c| format!("{} = {:e}", c.name, c.measured))
        .collect();
    assert!(failed.is_empty(), "failed: {failed:?}");
}

/// The paper's Fig 6b parameters (rho = eta = 1, lambda = 3, outside the
/// case the paper solves) give a valid basis.
#[test]
fn fig6b_parameters_work() {
    for p in [Params::new(1.0, 1.0, 3.0), Params::new(0.1, 0.1, 3.0)] {
        let b = Basis::new(p).expect("fig 6b basis");
        assert!(b.boundary_error() < tol::SOLVE);
        assert!(b.residual_error(10) < tol::SOLVE);
    }
}

/// The per-line 6x6 solve (bench baseline) equals the precomputed basis.
#[test]
fn solve_line_equals_basis() {
    let us: Vec<f64> = (0..=10).map(|i| i as f64 / 10.0).collect();
    let c = [0.3, -1.0, 2.0, 1.0, 0.5, -4.0];
    for p in [
        Params::new(1.0, 3.0, 1.0),
        Params::new(1e-4, 3.0, 1e-4),
        Params::new(1.0, 1.0, 3.0),
        Params::new(1.0, -40.0, 100.0),
    ] {
        let b = Basis::new(p).unwrap();
        let line = solve_line(p, &c, &us).unwrap();
        for (u, l) in us.iter().zip(&line) {
            assert!(
                (b.line(*u, &c) - l).abs() < tol::SOLVE * 10.0,
                "{p:?} u = {u}"
            );
        }
    }
}

/// Sampled polylines are interpolated at their vertices (closed: exact
/// trigonometric interpolation; open: natural cubic spline), and a patch from
/// polylines meets eq 1 at every vertex.
#[test]
fn polylines_interpolate_vertices() {
    for m in [5usize, 8] {
        let pts: Vec<[f64; 3]> = (0..m)
            .map(|k| [k as f64, (k * k) as f64 * 0.1, (k as f64).sin()])
            .collect();
        for closed in [true, false] {
            let c = Curve::from_polyline(&pts, closed).unwrap();
            for (k, p) in pts.iter().enumerate() {
                let v = if closed {
                    k as f64 / m as f64
                } else {
                    k as f64 / (m - 1) as f64
                };
                let q = c.eval(v);
                for d in 0..3 {
                    assert!(
                        (q[d] - p[d]).abs() < tol::SOLVE,
                        "m={m} closed={closed} k={k}"
                    );
                }
            }
        }
    }
    assert!(matches!(
        Curve::from_polyline(&[[0.0; 3]; 2], true),
        Err(Ode6Error::BadData(_))
    ));
    assert!(matches!(
        Curve::from_polyline(&[[f64::NAN, 0.0, 0.0]; 4], false),
        Err(Ode6Error::BadData(_))
    ));
}

/// Approach 2 with control curves cut from a surface quadratic in u: the
/// three-point derivatives are exact, so the ODE patch reproduces the
/// boundary derivatives of that surface.
#[test]
fn approach2_three_point_on_quadratic_surface() {
    let a = test_curve(1.0, 0.0, 0.0);
    let target = |u: f64, v: f64| {
        let p = a.eval(2.0 * std::f64::consts::PI * v);
        [p[0] * (1.0 + u * u), p[1] * (1.0 - 0.5 * u), p[2] + 2.0 * u]
    };
    let curve_at = |u: f64| {
        Curve::from_polyline(
            &(0..16)
                .map(|k| target(u, k as f64 / 16.0))
                .collect::<Vec<_>>(),
            true,
        )
        .unwrap()
    };
    let ap = Approach2 {
        u2: 0.1,
        u3: 0.3,
        u5: 0.75,
        u6: 0.9,
        formula: DiffFormula::ThreePoint,
    };
    let bc = BoundaryCurves::approach2(
        curve_at(0.0),
        [curve_at(0.1), curve_at(0.3), curve_at(0.75), curve_at(0.9)],
        curve_at(1.0),
        &ap,
    )
    .unwrap();
    let s = Ode6Surface::new(Basis::new(Params::new(1.0, 3.0, 1.0)).unwrap(), bc);
    let v = 3.0 / 16.0;
    let h = 1e-5;
    let d_target = |u: f64| {
        let (p, m) = (target(u + h, v), target(u - h, v));
        [
            (p[0] - m[0]) / (2.0 * h),
            (p[1] - m[1]) / (2.0 * h),
            (p[2] - m[2]) / (2.0 * h),
        ]
    };
    for u in [0.0, 1.0] {
        let ours = s.derivative(u, v, 1, 0);
        let want = d_target(u);
        for k in 0..3 {
            assert!(
                (ours[k] - want[k]).abs() < 1e-6,
                "u = {u}: {ours:?} vs {want:?}"
            );
        }
    }
}

/// The CLI evaluates a line and refuses rho = 0 with the named case.
#[test]
fn cli_eval_and_errors() {
    let bin = env!("CARGO_BIN_EXE_pdesculpt");
    let out = std::process::Command::new(bin)
        .args([
            "--json",
            "ode6",
            "eval",
            "--rho",
            "1",
            "--eta",
            "1",
            "--lambda",
            "3",
            "--bc",
            "1,0,0,2,0.5,-1",
            "--at",
            "0,1",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!((v["points"][1]["s"].as_f64().unwrap() - 2.0).abs() < tol::SOLVE);
    assert!((v["points"][1]["s_uu"].as_f64().unwrap() + 1.0).abs() < tol::SOLVE);
    let out = std::process::Command::new(bin)
        .args([
            "ode6",
            "eval",
            "--rho",
            "0",
            "--eta",
            "1",
            "--lambda",
            "3",
            "--bc",
            "1,0,0,2,0.5,-1",
            "--at",
            "0.5",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("rho = 0"));
}

/// `ode6 surface` writes a mesh from a JSON spec.
#[test]
fn cli_surface_writes_mesh() {
    let dir = std::env::temp_dir().join(format!("ode6_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let spec = dir.join("spec.json");
    std::fs::write(
        &spec,
        r#"{"params": {"rho": 1, "eta": 3, "lambda": 1},
            "curves": {"approach1": {"c1": {"fourier": {"c0": [0,0,0], "cos": [[1,0,0]], "sin": [[0,1,0]]}},
                                     "c4": {"polyline": {"points": [[0.5,0,1],[0,0.5,1],[-0.5,0,1],[0,-0.5,1]], "closed": true}},
                                     "w": [1, 0, 10, 0]}},
            "force": {"Polynomial": {"coef": [[0, 0, 1]]}}}"#,
    )
    .unwrap();
    let out_mesh = dir.join("s.obj");
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_pdesculpt"))
        .args([
            "ode6",
            "surface",
            spec.to_str().unwrap(),
            "-o",
            out_mesh.to_str().unwrap(),
            "--nu",
            "8",
            "--nv",
            "12",
        ])
        .status()
        .unwrap();
    assert!(st.success());
    let m = pdesculpt::mesh::io::read(&out_mesh).unwrap();
    assert_eq!(m.positions.len(), (8 + 1) * 12);
    std::fs::write(&spec, r#"{"params": {"rho": 1, "eta": 3}}"#).unwrap();
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_pdesculpt"))
        .args([
            "ode6",
            "surface",
            spec.to_str().unwrap(),
            "-o",
            out_mesh.to_str().unwrap(),
        ])
        .status()
        .unwrap();
    assert_eq!(st.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A shape parameter: zero, or +- 10^e with e in [-3, 3].
fn param() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        6 => (-3.0f64..3.0, any::<bool>()).prop_map(|(e, s)| if s { 10f64.powf(e) } else { -(10f64.powf(e)) }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Over |rho|, |eta|, |lambda| in {0} U [1e-3, 1e3] with any signs: a
    /// basis meets eq 1 and eq 8, or a named error comes back; never NaN.
    #[test]
    fn bases_meet_constraints_or_fail_by_name(rho in param(), eta in param(), lambda in param()) {
        let p = Params::new(rho, eta, lambda);
        match Basis::new(p) {
            Ok(b) => {
                prop_assert!(b.rcond >= RCOND_MIN);
                let amp = b.coef_magnitude();
                prop_assert!(b.boundary_error() <= tol::scaled(tol::SOLVE, amp * 1e-3) * 10.0, "{p:?} {} boundary {:e} amp {:e}", b.case.name(), b.boundary_error(), amp);
                prop_assert!(b.residual_error(6) <= tol::SOLVE * 10.0, "{p:?} {} residual {:e}", b.case.name(), b.residual_error(6));
                for i in 0..=8 {
                    prop_assert!(b.g(i as f64 / 8.0).iter().all(|x| x.is_finite()));
                }
            }
            Err(Ode6Error::RhoZero { .. }) => prop_assert!(rho == 0.0),
            Err(Ode6Error::AllZero) => prop_assert!(rho == 0.0 && eta == 0.0 && lambda == 0.0),
            Err(Ode6Error::Singular { case, .. }) => prop_assert!(!case.is_empty()),
            Err(e) => prop_assert!(false, "unexpected error {e}"),
        }
        if rho == 0.0 && !(eta == 0.0 && lambda == 0.0) {
            let b = Basis::reduced(p);
            if let Ok(b) = b {
                prop_assert!(b.boundary_error() <= tol::scaled(tol::SOLVE, b.coef_magnitude() * 1e-3) * 10.0);
            }
        }
    }

    /// Surfaces from random approach-1 coefficients, forces and parameters
    /// tessellate to finite meshes that meet eq 1.
    #[test]
    fn surfaces_are_finite(w in prop::array::uniform4(-10.0f64..10.0), e in 0.1f64..10.0, l in -5.0f64..5.0, kappa in 0.5f64..6.0) {
        let Ok(b) = Basis::new(Params::new(1.0, e, l)) else { return Ok(()); };
        let bc = BoundaryCurves::approach1(Curve::Fourier(test_curve(1.0, 0.0, 0.0)), Curve::Fourier(test_curve(0.5, 1.0, 1.0)), w).unwrap();
        let s = match Ode6Surface::new(b, bc).with_force(&Force::Sine { amp: [0.0, 0.0, 1.0], kappa, phase: 0.0 }) {
            Ok(s) => s,
            Err(Ode6Error::Resonance { .. }) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        let m = tessellate(&s, Tessellation { nu: 6, nv: 8 });
        prop_assert!(m.positions.iter().flatten().all(|x| x.is_finite()));
        for v in [0.0, 0.3] {
            let p = s.eval(Jet::<3, 1>::var_u(1.0), Jet::<3, 1>::constant(v));
            let c = s.curves.c(4, v);
            for k in 0..3 {
                prop_assert!((p[k].deriv(1, 0) - c[k]).abs() <= tol::scaled(tol::SOLVE, c[k]) * 100.0);
            }
        }
    }
}

/// Forcing a case that does not belong to the parameters is refused.
#[test]
fn mismatched_case_is_refused() {
    use pdesculpt::ode6::RootCase;
    let p = Params::new(1.0, 3.0, 1.0);
    let r = Basis::with_case(
        p,
        RootCase::Complex {
            alpha: 0.5,
            beta: 2.0,
        },
    );
    assert!(matches!(r, Err(Ode6Error::BadData(_))));
}
