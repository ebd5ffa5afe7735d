//! Two-sided patch checks (eqs 5-10): residual, boundary, root cases, paper-literal forms.

use super::*;
use crate::check::Worst;

/// Max PDE (1) residual of a 2-sided patch against its eq 4 force series,
/// relative to the largest force-series value seen.
pub fn two_sided_residual(t: &TwoSided, samples: usize) -> f64 {
    let mut worst = 0.0f64;
    let mut scale = 0.0f64;
    for iu in 0..=samples {
        for iv in 0..samples {
            let (u, v) = (iu as f64 / samples as f64, iv as f64 / samples as f64);
            let x = Surface::eval(t, Jet::<5, 5>::var_u(u), Jet::<5, 5>::var_v(v));
            for k in 0..3 {
                let p = &t.comps[k].params;
                let l = p.a1 * x[k].deriv(4, 0) + p.a2 * x[k].deriv(2, 2) + p.a3 * x[k].deriv(0, 4);
                let f = t.force_series(k, u, v);
                worst = worst.worst((l - f).abs());
                scale = scale.worst(f.abs());
            }
        }
    }
    worst / scale.worst(1.0)
}

/// Max of `|t|`, `|t_u|` at `u = 0, 1` minus the prescribed boundary data.
pub fn two_sided_boundary(t: &TwoSided, b: Option<&Boundary>, samples: usize) -> f64 {
    let mut worst = 0.0f64;
    for iv in 0..samples {
        let v = iv as f64 / samples as f64;
        for (u, curve, tangent) in [
            (0.0, b.map(|b| &b.curve0), b.map(|b| &b.tangent0)),
            (1.0, b.map(|b| &b.curve1), b.map(|b| &b.tangent1)),
        ] {
            let x = Surface::eval(t, Jet::<2, 1>::var_u(u), Jet::<2, 1>::constant(v));
            let c = curve.map_or([0.0; 3], |c| c.eval(2.0 * PI * v));
            let d = tangent.map_or([0.0; 3], |c| c.eval(2.0 * PI * v));
            for k in 0..3 {
                worst = worst
                    .worst((x[k].c[0][0] - c[k]).abs())
                    .worst((x[k].c[1][0] - d[k]).abs());
            }
        }
    }
    worst
}

/// Modes (m) and harmonics (n) of the two-sided checks' solutions.
const SIZE: (usize, usize) = (8, 6);

pub(super) fn two_sided_checks(out: &mut Vec<Check>) {
    mode_check(out);
    exact_checks(out);
    printed_checks(out);
    grid_check(out);
}

/// Eq 1's exact clamped modes against mpmath.
fn mode_check(out: &mut Vec<Check>) {
    let g = golden();
    let modes = g["mode_solutions"].as_array().cloned().unwrap_or_default();
    let mut worst = if modes.is_empty() { f64::NAN } else { 0.0f64 };
    for md in &modes {
        let p = ShapeParams {
            a1: md["a1"].as_f64().unwrap_or(f64::NAN),
            a2: md["a2"].as_f64().unwrap_or(f64::NAN),
            a3: md["a3"].as_f64().unwrap_or(f64::NAN),
        };
        let n = md["n"].as_u64().unwrap_or(0) as usize;
        let k = md["k"].as_u64().unwrap_or(1) as usize;
        let mut f = vec![0.0; k];
        f[k - 1] = 1.0;
        match Mode::exact(&p, 2.0 * PI * n as f64, &f, [0.0; 4]) {
            Ok(mode) => {
                let ws = arr(&md["w"]);
                let sc = ws.iter().fold(0.0f64, |a, b| a.worst(b.abs()));
                for (u, w) in arr(&md["u"]).iter().zip(&ws) {
                    worst = worst.worst((mode.eval(*u) - w).abs() / sc);
                }
            }
            Err(_) => worst = f64::NAN,
        }
    }
    out.push(
        Check::new(F, P, "eq 1 modes", "pde4.two_sided.mode_vs_mpmath", Kind::Reference, worst, tol::SOLVE)
            .note("exact clamped mode solutions (distinct, double, complex roots, omega = 0) vs mpmath root-based solutions"),
    );
}

/// The exact solution: residual and boundary conditions, zero and
/// non-zero boundary curves.
fn exact_checks(out: &mut Vec<Check>) {
    let forces = sample_forces();
    let (m, n) = SIZE;
    let mut res = 0.0f64;
    let mut bnd = 0.0f64;
    for (_, p) in root_cases() {
        match TwoSided::new([p; 3], &forces, m, n, two_sided::Method::Exact, None) {
            Ok(t) => {
                res = res.worst(two_sided_residual(&t, 6));
                bnd = bnd.worst(two_sided_boundary(&t, None, 24));
            }
            Err(_) => res = f64::NAN,
        }
    }
    out.push(
        Check::new(F, P, "eqs 1, 4", "pde4.two_sided.exact_residual", Kind::Residual, res, tol::SOLVE)
            .note("max |L t - eq 4 force series| / max |force| on a 7x6 grid, jets, five shape-parameter root cases, 3 force types"),
    );
    out.push(
        Check::new(
            F,
            P,
            "eq 5",
            "pde4.two_sided.exact_boundary",
            Kind::Boundary,
            bnd,
            tol::SOLVE,
        )
        .note("max |t|, |t_u| at u = 0, 1, five root cases"),
    );
    let b = sample_boundary();
    let (r2, b2) = match TwoSided::new(
        mixed_shapes(),
        &forces,
        m,
        n,
        two_sided::Method::Exact,
        Some(&b),
    ) {
        Ok(t) => (
            two_sided_residual(&t, 12),
            two_sided_boundary(&t, Some(&b), 24),
        ),
        Err(_) => (f64::NAN, f64::NAN),
    };
    out.push(
        Check::new(
            F,
            P,
            "sec 5.1",
            "pde4.two_sided.boundary_curves",
            Kind::Boundary,
            b2,
            tol::SOLVE,
        )
        .note(
            "non-zero boundary curves and tangents: max |t - curve|, |t_u - tangent| at u = 0, 1",
        ),
    );
    out.push(
        Check::new(
            F,
            P,
            "sec 5.1",
            "pde4.two_sided.boundary_curves_residual",
            Kind::Residual,
            r2,
            tol::SOLVE,
        )
        .note("PDE residual with non-zero boundary curves and tangents"),
    );
}

/// The printed forms: eq 7's basis clamped, eq 8 for n = 0, eq 9 against
/// least squares and the exact solution.
fn printed_checks(out: &mut Vec<Check>) {
    let forces = sample_forces();
    let (m, n) = SIZE;
    // printed basis eq 7: clamped
    let mut cl = 0.0f64;
    for mi in 1..=12 {
        for u in [0.0, 1.0] {
            let j = basis_b(mi, Jet::<2, 1>::var_u(u));
            cl = cl
                .worst(j.c[0][0].abs())
                .worst(j.c[1][0].abs() / (PI * mi as f64));
        }
    }
    out.push(
        Check::new(
            F,
            P,
            "eq 7",
            "pde4.two_sided.eq7_basis_clamped",
            Kind::Boundary,
            cl,
            tol::ROUNDING,
        )
        .note("max |B_m|, |B_m'|/(m pi) at u = 0, 1, m <= 12"),
    );
    // eq 8 for n = 0 equals the exact mode-0 solution (a force uniform in v)
    let fu = [Force {
        kind: ForceKind::Line {
            u0: 0.1,
            u1: 0.8,
            v0: 0.0,
        },
        p: [1.0, 0.5, 0.0],
    }];
    let ps = mixed_shapes();
    let grid: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
    let mode0 =
        |t: &TwoSided| -> Vec<f64> { grid.iter().map(|&u| t.comps[0].mode(0).eval(u)).collect() };
    let d8 = match (
        TwoSided::new(ps, &fu, m, n, two_sided::Method::Paper, None),
        TwoSided::new(ps, &fu, m, n, two_sided::Method::Exact, None),
    ) {
        (Ok(a), Ok(b)) => {
            crate::check::max_abs_diff(&mode0(&a), &mode0(&b))
                / mode0(&b).iter().fold(0.0f64, |x, y| x.worst(y.abs()))
        }
        _ => f64::NAN,
    };
    out.push(
        Check::paper_literal(
            F,
            P,
            "eq 8 (n = 0)",
            "pde4.two_sided.eq8_mode0",
            d8,
            tol::SOLVE,
            false,
        )
        .note("printed c_m vs exact v-constant mode, relative"),
    );
    // eq 9 vs least squares and vs exact
    let (mut d9, mut dpe) = (0.0f64, 0.0f64);
    for p in ps {
        let (Ok(pa), Ok(ls), Ok(ex)) = (
            TwoSided::new([p; 3], &forces, m, n, two_sided::Method::Paper, None),
            TwoSided::new([p; 3], &forces, m, n, two_sided::Method::LeastSquares, None),
            TwoSided::new([p; 3], &forces, m, n, two_sided::Method::Exact, None),
        ) else {
            d9 = f64::NAN;
            continue;
        };
        let us: Vec<f64> = (0..=16).map(|i| i as f64 / 16.0).collect();
        let vs: Vec<f64> = (0..32).map(|i| i as f64 / 32.0).collect();
        let (gp, gl, ge) = (pa.grid(&us, &vs), ls.grid(&us, &vs), ex.grid(&us, &vs));
        let flat = |g: &[[f64; 3]]| g.iter().flatten().copied().collect::<Vec<_>>();
        let sc = flat(&ge).iter().fold(0.0f64, |a, b| a.worst(b.abs()));
        d9 = d9.worst(crate::check::max_abs_diff(&flat(&gp), &flat(&gl)) / sc);
        dpe = dpe.worst(crate::check::max_abs_diff(&flat(&gp), &flat(&ge)) / sc);
    }
    out.push(Check::paper_literal(F, P, "eq 9", "pde4.two_sided.eq9_vs_least_squares", d9, tol::PLATE_THEORY, true).note("max |printed-coefficient surface - residual-minimising surface (same eq 7 basis)| / max |exact|, 3 parameter sets"));
    out.push(
        Check::paper_literal(
            F,
            P,
            "eqs 7-9",
            "pde4.two_sided.paper_vs_exact",
            dpe,
            tol::PLATE_THEORY,
            true,
        )
        .note("max |printed solution - exact solution| / max |exact|, 3 parameter sets"),
    );
}

/// The separable grid evaluation against the direct double sum.
fn grid_check(out: &mut Vec<Check>) {
    let forces = sample_forces();
    let (m, n) = SIZE;
    let gd = match TwoSided::new(
        [ShapeParams::uniform(0.3); 3],
        &forces,
        m,
        n,
        two_sided::Method::Exact,
        None,
    ) {
        Ok(t) => {
            let us: Vec<f64> = (0..=9).map(|i| i as f64 / 9.0).collect();
            let vs: Vec<f64> = (0..11).map(|i| i as f64 / 11.0).collect();
            let a: Vec<f64> = t.grid(&us, &vs).into_iter().flatten().collect();
            let b: Vec<f64> = t.grid_naive(&us, &vs).into_iter().flatten().collect();
            crate::check::max_abs_diff(&a, &b)
                / b.iter()
                    .fold(0.0f64, |x, y| x.worst(y.abs()))
                    .worst(f64::MIN_POSITIVE)
        }
        Err(_) => f64::NAN,
    };
    out.push(
        Check::new(
            F,
            P,
            "eq 6",
            "pde4.two_sided.grid_separable",
            Kind::Reference,
            gd,
            tol::ROUNDING * 100.0,
        )
        .note("separable grid vs direct double sum, relative"),
    );
}
