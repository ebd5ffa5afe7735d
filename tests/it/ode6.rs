//! Integration tests of the ode6 family (paper 004).

use pdesculpt::check::tol;
use pdesculpt::jet::Jet;
use pdesculpt::ode6::basis::{solve_line, RCOND_MIN};
use pdesculpt::ode6::samples::test_curve;
use pdesculpt::ode6::{
    Approach2, Basis, BoundaryCurves, Curve, DiffFormula, Force, Ode6Error, Ode6Surface, Params,
};
use pdesculpt::surface::{tessellate, Joined, Surface, Tessellation};
use proptest::prelude::*;

/// Boundary rows sum basis coefficients as large as `amp` (the basis'
/// largest), which cancel: the boundary tolerance grows with `amp` once
/// `amp` passes `1 / BOUNDARY_PER_AMP` (below that, the SOLVE level).
const BOUNDARY_PER_AMP: f64 = 1e-3;
/// Fig 6b: different parameters on the two sides of a v-join leave a jump
/// in S_vv below a broken curve's (`tol::DETECTED`) but three orders above
/// the rounding of a join (`tol::JOIN`).
const PARAM_MISMATCH_SEEN: f64 = 1e-4;

/// Every ode6 check passes.
#[test]
fn ode6_checks_pass() {
    let checks = crate::shared::family_checks("ode6");
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
        Err(Ode6Error::TooFewVertices {
            closed: true,
            min: 3,
            got: 2
        })
    ));
    assert!(matches!(
        Curve::from_polyline(&[[f64::NAN, 0.0, 0.0]; 4], false),
        Err(Ode6Error::NotFinite { .. })
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
                (ours[k] - want[k]).abs() < tol::CENTRAL_DIFFERENCE,
                "u = {u}: {ours:?} vs {want:?}"
            );
        }
    }
}

/// The CLI evaluates a line and refuses rho = 0 with the named case.
#[test]
fn cli_eval_and_errors() {
    let out = crate::cli::pdesculpt(&[
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
    ]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!((v["points"][1]["s"].as_f64().unwrap() - 2.0).abs() < tol::SOLVE);
    assert!((v["points"][1]["s_uu"].as_f64().unwrap() + 1.0).abs() < tol::SOLVE);
    let out = crate::cli::pdesculpt(&[
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
    ]);
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
    let st = ode6_surface(&spec, &out_mesh, &["--nu", "8", "--nv", "12"]).status;
    assert!(st.success());
    let m = pdesculpt::mesh::io::read(&out_mesh).unwrap();
    assert_eq!(m.positions.len(), (8 + 1) * 12);
    std::fs::write(&spec, r#"{"params": {"rho": 1, "eta": 3}}"#).unwrap();
    let st = ode6_surface(&spec, &out_mesh, &[]).status;
    assert_eq!(st.code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Runs `pdesculpt ode6 surface SPEC -o OUT EXTRA...`.
fn ode6_surface(
    spec: &std::path::Path,
    out: &std::path::Path,
    extra: &[&str],
) -> std::process::Output {
    let mut args = vec![
        "ode6",
        "surface",
        spec.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    crate::cli::pdesculpt(&args)
}

/// A shape parameter: zero, or +- 10^e with e in [-3, 3].
fn param() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        6 => (-3.0f64..3.0, any::<bool>()).prop_map(|(e, s)| if s { 10f64.powf(e) } else { -(10f64.powf(e)) }),
    ]
}

proptest! {
    #![proptest_config(crate::strategies::config(64))]

    /// Over |rho|, |eta|, |lambda| in {0} U [1e-3, 1e3] with any signs: a
    /// basis meets eq 1 and eq 8, or a named error comes back; never NaN.
    #[test]
    fn bases_meet_constraints_or_fail_by_name(rho in param(), eta in param(), lambda in param()) {
        let p = Params::new(rho, eta, lambda);
        match Basis::new(p) {
            Ok(b) => {
                prop_assert!(b.rcond >= RCOND_MIN);
                let amp = b.coef_magnitude();
                prop_assert!(b.boundary_error() <= tol::scaled(tol::SOLVE, amp * BOUNDARY_PER_AMP) * 10.0, "{p:?} {} boundary {:e} amp {:e}", b.case.name(), b.boundary_error(), amp);
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
                prop_assert!(b.boundary_error() <= tol::scaled(tol::SOLVE, b.coef_magnitude() * BOUNDARY_PER_AMP) * 10.0);
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

/// The quintic Hermite segment takes its end data: position, first and
/// second derivative at v = 0 and v = 1 (jets).
#[test]
fn hermite_segment_meets_end_data() {
    let knots = pdesculpt::ode6::samples::grid_knots();
    let (a, b) = (knots[1][2][0], knots[1][2][1]);
    let c = Curve::hermite(a, b).unwrap();
    for (v, want) in [(0.0, a), (1.0, b)] {
        let p = c.eval(Jet::<3, 1>::var_u(v));
        for i in 0..3 {
            for k in 0..3 {
                assert!(
                    (p[k].deriv(i, 0) - want[i][k]).abs() < tol::ROUNDING,
                    "v = {v} i = {i}"
                );
            }
        }
    }
    let mut bad = a;
    bad[1][0] = f64::NAN;
    assert!(matches!(
        Curve::hermite(bad, b),
        Err(Ode6Error::NotFinite { .. })
    ));
}

/// The 3 x 2 grid check is not vacuous: the registered measure is small on
/// the real grid and exceeds the tolerance on three deliberately broken
/// variants (a v-knot's second derivative perturbed on one side, Fig 6b's
/// differing parameters within a column, a u-section's curvature curve
/// perturbed on one side), and on a grid whose curves are all zero.
#[test]
fn grid_continuity_check_can_fail() {
    use pdesculpt::ode6::check::GRID_MAGNITUDE_FLOOR;
    use pdesculpt::ode6::samples::grid_3x2;
    let measure = |g: &pdesculpt::ode6::Grid| g.join_jumps(16).relative(GRID_MAGNITUDE_FLOOR);
    let good = grid_3x2().unwrap();
    assert!(measure(&good) < tol::SOLVE, "{:?}", good.join_jumps(16));
    let j = good.join_jumps(16);
    assert!(j
        .u_magnitude
        .iter()
        .chain(&j.v_magnitude)
        .all(|m| *m > GRID_MAGNITUDE_FLOOR));

    // (1) v-join: S_vv of patch (1, 1)'s c1 curve at its v = 0 end.
    let mut g = good.clone();
    if let Curve::Hermite { ends } = &mut g.patches[1][1].curves.keys[0] {
        ends[0][2][0] += 0.5;
    } else {
        panic!("grid curves are Hermite segments");
    }
    let jb = g.join_jumps(16);
    assert!(measure(&g) > tol::DETECTED, "{jb:?}");
    assert!(jb.v[2] > tol::DETECTED && jb.v[0] < tol::SOLVE && jb.v[1] < tol::SOLVE);

    // (2) Fig 6b: different parameters on the two sides of a v-join.
    let mut g = good.clone();
    g.patches[2][1].basis = Basis::new(Params::new(0.1, 0.1, 3.0)).unwrap();
    let jb = g.join_jumps(16);
    assert!(jb.v[0] > PARAM_MISMATCH_SEEN, "{jb:?}");
    assert!(measure(&g) > tol::DETECTED);

    // (3) u-join: the S_uu curve (c6) of patch (0, 0) at the join with (1, 0).
    let mut g = good.clone();
    if let Curve::Hermite { ends } = &mut g.patches[0][0].curves.keys[5] {
        ends[1][0][2] += 0.3;
    }
    let jb = g.join_jumps(16);
    assert!(jb.u[2] > tol::DETECTED && jb.u[0] < tol::SOLVE, "{jb:?}");
    assert!(measure(&g) > tol::DETECTED);

    // (4) Vacuous: all curves zero -> no derivative to compare -> fails.
    let mut g = good;
    for col in &mut g.patches {
        for p in col {
            for k in &mut p.curves.keys {
                *k = k.scaled(0.0);
            }
        }
    }
    assert!(measure(&g).is_infinite());
}

/// Boundary curves as GECs: a patch meets eq 1 against `Gec::eval_v`
/// itself, for closed tilted curves; non-finite GECs are refused.
#[test]
fn gec_boundary_curves() {
    use pdesculpt::ode6::check::gec_boundary_error;
    use pdesculpt::ode6::samples::test_gecs;
    for p in [Params::new(1.0, 3.0, 1.0), Params::new(1.0, -20.0, 50.0)] {
        let e = gec_boundary_error(p, [1.5, -2.0, 0.5, 4.0]).unwrap();
        assert!(e < tol::SOLVE, "{p:?}: {e:e}");
    }
    let (mut g, _) = test_gecs();
    g.x[0][1] = f64::INFINITY;
    assert!(matches!(
        Curve::from_gec(&g),
        Err(Ode6Error::NotFinite { .. })
    ));
}

/// `ode6 surface` takes GEC and Hermite curves; a singular parameter set
/// gets a clear error naming the case, with exit 1 and no file.
#[test]
fn cli_gec_spec_and_singular_error() {
    let dir = std::env::temp_dir().join(format!("ode6_cli_gec_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (ga, gb) = pdesculpt::ode6::samples::test_gecs();
    let spec = |params: serde_json::Value| {
        serde_json::json!({"params": params,
            "curves": {"approach1": {"c1": {"gec": ga}, "c4": {"gec": gb}, "w": [1, 0, -1, 0]}}})
    };
    let path = dir.join("spec.json");
    let out_mesh = dir.join("g.obj");
    std::fs::write(
        &path,
        spec(serde_json::json!({"rho": 1, "eta": 3, "lambda": 1})).to_string(),
    )
    .unwrap();
    let st = ode6_surface(&path, &out_mesh, &["--nu", "4", "--nv", "16"]).status;
    assert!(st.success());
    let m = pdesculpt::mesh::io::read(&out_mesh).unwrap();
    let p0 = ga.eval_v(0.0);
    assert!(m
        .positions
        .iter()
        .any(|q| pdesculpt::mesh::dist(*q, p0) < tol::SOLVE));
    // Hermite (open) curves.
    let h = serde_json::json!({"hermite": {"start": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "end": [[1, 0, 0], [1, 0.5, 0], [0, 0, 0]]}});
    let hs = serde_json::json!({"params": {"rho": 1, "eta": 1, "lambda": 3},
        "curves": {"approach1": {"c1": h, "c4": h, "w": [0, 0, 0, 0]}}});
    std::fs::write(&path, hs.to_string()).unwrap();
    let st = ode6_surface(&path, &out_mesh, &[]).status;
    assert!(st.success());
    // The singular parameter set of the golden file.
    let golden: serde_json::Value = serde_json::from_str(pdesculpt::ode6::check::GOLDEN).unwrap();
    let s = &golden["singular"];
    std::fs::write(
        &path,
        spec(serde_json::json!({"rho": s["rho"], "eta": s["eta"], "lambda": s["lambda"]}))
            .to_string(),
    )
    .unwrap();
    let bad_mesh = dir.join("bad.obj");
    let out = ode6_surface(&path, &bad_mesh, &[]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("singular boundary system"), "{err}");
    // The case by name (the golden's q = -1, -w^2 are distinct real roots of eq 13).
    assert!(err.contains("distinct real roots q ="), "{err}");
    assert!(!bad_mesh.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A valid shape-parameter set for the grid sweep: eta, lambda any sign.
fn column_params() -> impl Strategy<Value = Params> {
    (-2.0f64..1.0, -30.0f64..30.0, -60.0f64..60.0)
        .prop_map(|(lr, e, l)| Params::new(10f64.powf(lr), e, l))
}

proptest! {
    #![proptest_config(crate::strategies::config(24))]

    /// Grids with random parameters per column and random knot data stay
    /// C2 across every join (relative jumps below 1e-7), or the basis fails
    /// by name; nothing non-finite reaches a tessellation.
    #[test]
    fn grids_are_c2(ps in prop::array::uniform3(column_params()), shift in prop::array::uniform3(-2.0f64..2.0)) {
        let bases: Result<Vec<Basis>, Ode6Error> = ps.iter().map(|p| Basis::new(*p)).collect();
        let bases = match bases {
            Ok(b) => b,
            Err(Ode6Error::Singular { case, .. }) => { prop_assert!(!case.is_empty()); return Ok(()); }
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        let mut knots = pdesculpt::ode6::samples::grid_knots();
        for (s, sec) in knots.iter_mut().enumerate() {
            for (k, curve) in sec.iter_mut().enumerate() {
                for (t, knot) in curve.iter_mut().enumerate() {
                    knot[1][k] += shift[(s + t) % 3];
                    knot[2][(k + 1) % 3] -= shift[(s + 2 * t) % 3];
                }
            }
        }
        let g = pdesculpt::ode6::Grid::from_knots(&knots, bases).unwrap();
        let j = g.join_jumps(6);
        for d in 0..3 {
            prop_assert!(j.u[d] <= tol::JOIN * j.u_magnitude[d].max(1.0), "{ps:?} {j:?}");
            prop_assert!(j.v[d] <= tol::JOIN * j.v_magnitude[d].max(1.0), "{ps:?} {j:?}");
        }
        for col in &g.patches {
            for p in col {
                let m = tessellate(p, Tessellation { nu: 4, nv: 4 });
                prop_assert!(m.positions.iter().flatten().all(|x| x.is_finite()));
            }
        }
    }

    /// Patches from random GECs (any frame) meet eq 1 against `Gec::eval_v`.
    #[test]
    fn gec_patches_meet_constraints(
        a in prop::collection::vec(prop::array::uniform2(-1.0f64..1.0), 1..4),
        b in prop::collection::vec(prop::array::uniform2(-1.0f64..1.0), 1..4),
        n in crate::strategies::point3(1.0),
        w in prop::array::uniform4(-5.0f64..5.0),
    ) {
        use pdesculpt::curve::gec::{Frame, Gec};
        let Ok(frame) = Frame::from_normal([0.0, 0.0, 1.0], [n[0], n[1], n[2] + 1.5], [1.0, 0.0, 0.0]) else { return Ok(()); };
        let ga = Gec::new(frame, [0.1, 0.0], a.clone(), a.iter().map(|p| [p[1], p[0]]).collect()).unwrap();
        let gb = Gec::new(Frame::z_plane(1.0), [0.0, 0.2], b.clone(), b.iter().rev().cloned().collect()).unwrap();
        let s = Ode6Surface::new(
            Basis::new(Params::new(1.0, 3.0, 1.0)).unwrap(),
            BoundaryCurves::approach1(Curve::from_gec(&ga).unwrap(), Curve::from_gec(&gb).unwrap(), w).unwrap(),
        );
        for i in 0..8 {
            let v = i as f64 / 8.0;
            for (g, u, sc) in [(&ga, 0.0, [1.0, w[0], w[1]]), (&gb, 1.0, [1.0, w[2], w[3]])] {
                let pt = s.eval(Jet::<3, 1>::var_u(u), Jet::<3, 1>::constant(v));
                let q = g.eval_v(v);
                for k in 0..3 {
                    for (du, c) in sc.iter().enumerate() {
                        prop_assert!((pt[k].deriv(du, 0) - c * q[k]).abs() <= tol::SOLVE * (1.0 + (c * q[k]).abs()));
                    }
                }
            }
        }
    }
}

/// The natural cubic spline on uneven knots: it passes through the values,
/// reproduces a straight line exactly, is C2 at the interior knots and has
/// zero curvature at both ends (jets of each interval's cubic); bad knots
/// are refused by name.
#[test]
fn natural_spline_identities() {
    use pdesculpt::ode6::spline::{segment, NaturalSpline};
    let t = [0.0, 0.15, 0.4, 0.45, 0.8, 1.0];
    let y = [1.0, -0.5, 2.0, 0.3, 0.9, -1.2];
    let s = NaturalSpline::new(&t, &y).unwrap();
    let m2 = s.second_derivatives();
    for (ti, yi) in t.iter().zip(&y) {
        assert!((s.eval(*ti) - yi).abs() < tol::ROUNDING, "t = {ti}");
    }
    let piece = |i: usize, u: f64| {
        segment(
            [t[i], t[i + 1]],
            [y[i], y[i + 1]],
            [m2[i], m2[i + 1]],
            Jet::<3, 1>::var_u(u),
        )
    };
    for i in 1..t.len() - 1 {
        let (left, right) = (piece(i - 1, t[i]), piece(i, t[i]));
        for d in 0..3 {
            let (a, b) = (left.deriv(d, 0), right.deriv(d, 0));
            assert!(
                (a - b).abs() < tol::scaled(tol::SOLVE, a),
                "knot {i} derivative {d}"
            );
        }
    }
    assert!(piece(0, t[0]).deriv(2, 0).abs() < tol::SOLVE);
    assert!(piece(t.len() - 2, t[t.len() - 1]).deriv(2, 0).abs() < tol::SOLVE);
    let line: Vec<f64> = t.iter().map(|x| 3.0 * x - 1.0).collect();
    let s = NaturalSpline::new(&t, &line).unwrap();
    for u in [0.05, 0.3, 0.42, 0.7, 0.99] {
        assert!(
            (s.eval(u) - (3.0 * u - 1.0)).abs() < tol::ROUNDING,
            "u = {u}"
        );
    }
    assert!(matches!(
        NaturalSpline::new(&[0.0, 0.5, 0.5], &[1.0, 2.0, 3.0]),
        Err(Ode6Error::KnotsNotIncreasing { index: 2, .. })
    ));
    assert!(matches!(
        NaturalSpline::new(&[0.0], &[1.0]),
        Err(Ode6Error::SplineSize {
            knots: 1,
            values: 1
        })
    ));
    assert!(matches!(
        NaturalSpline::new(&[0.0, 1.0], &[1.0, f64::NAN]),
        Err(Ode6Error::NonFiniteValue { .. })
    ));
}
