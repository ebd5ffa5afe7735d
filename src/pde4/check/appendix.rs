//! Paper 000 eq 12 and appendix A2-A4 one at a time (issue 17): the
//! boundary conditions that turn eq 12's ansatz into eq 13, and the line
//! force coefficients of A3 with A4's $c_1$ against the projections, with
//! A2's $f_3$ as printed and as it must read.

use super::*;
use crate::check::Worst;

/// The $f_3$ that A3 needs: $(\sin k\pi r_{p1} + \sin k\pi r_{p0})/(k^2L^2 - 1)$,
/// $L = r_{p1} - r_{p0}$ (so that $c_1 f_3 = 2\int \sin\frac{\pi(u-u_{p0})}{L}\sin k\pi u\,du$).
pub fn f3_right(rp0: f64, rp1: f64, k: f64) -> f64 {
    let l = rp1 - rp0;
    ((k * PI * rp1).sin() + (k * PI * rp0).sin()) / (k * k * l * l - 1.0)
}

/// A2's $f_3$ as printed (with its $r_0..r_3$): the implementation the
/// paper-literal force checks use (`pde4::force::f3`).
pub fn f3_printed(rp0: f64, rp1: f64, k: f64) -> f64 {
    crate::pde4::force::f3(rp0, rp1, k)
}

/// Eq 12 imposed on BCs (5): the 4x4 system for $(G_0..G_3)$ per unit
/// $d_{mn}$ (rows t and t_u at u = 0 and 1), against eq 13's printed
/// $(0, -\pi m, \pi m(2 + (-1)^m), -\pi m(1 + (-1)^m))$; and BCs (10) of the
/// resulting function at v = 0, 1 (jets).
fn eq12_error() -> f64 {
    let mut e = 0.0f64;
    for m in 1..=6 {
        let mf = m as f64;
        let w = mf * PI;
        // rows: coefficients of (G0, G1, G2, G3) and the sine term's value
        let rows = [
            ([1.0, 0.0, 0.0, 0.0], 0.0),
            ([0.0, 1.0, 0.0, 0.0], w),
            ([1.0, 1.0, 1.0, 1.0], w.sin()),
            ([0.0, 1.0, 2.0, 3.0], w * w.cos()),
        ];
        let a = nalgebra::Matrix4::from_fn(|i, j| rows[i].0[j]);
        let b = nalgebra::Vector4::from_fn(|i, _| -rows[i].1);
        let Some(g) = a.lu().solve(&b) else {
            return f64::NAN;
        };
        let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
        let printed = [0.0, -w, w * (2.0 + sign), -w * (1.0 + sign)];
        for k in 0..4 {
            e = e.worst((g[k] - printed[k]).abs() / w);
        }
        // BCs (10): t = t_v = 0 at v = 0, 1 for the eq 13 mode, n = 1..4
        for n in 1..=4 {
            for v in [0.0, 1.0] {
                for u in [0.2, 0.5, 0.7] {
                    let vj = Jet::<2, 1>::var_u(v);
                    let pu = g[1] * u + g[2] * u * u + g[3] * u * u * u + (w * u).sin();
                    let t = vj * (-vj + 1.0) * ((vj * (n as f64 * PI)).sin() * pu);
                    e = e.worst(t.value().abs()).worst(t.deriv(1, 0).abs());
                }
            }
        }
    }
    e
}

/// SymPy's line force projections and f3 (`verify/printed_forms.py`).
const PRINTED_GOLDEN: &str = include_str!("../../../verify/golden/printed_forms.json");

/// (f3_right and c1 f3_right against SymPy's f3 and integral; printed f3
/// against SymPy's printed f3), NaN when the golden is missing.
fn f3_vs_sympy() -> (f64, f64) {
    let g: Value = serde_json::from_str(PRINTED_GOLDEN).unwrap_or_default();
    let Some(forces) = g["pde4_line_f3"].as_array() else {
        return (f64::NAN, f64::NAN);
    };
    let (mut right, mut printed) = if forces.is_empty() {
        (f64::NAN, f64::NAN)
    } else {
        (0.0f64, 0.0f64)
    };
    for f in forces {
        let (u0, u1) = (
            f["u0"].as_f64().unwrap_or(f64::NAN),
            f["u1"].as_f64().unwrap_or(f64::NAN),
        );
        let c1 = -2.0 * (u1 - u0) / PI;
        for row in f["rows"].as_array().into_iter().flatten() {
            let x = |k: &str| row[k].as_f64().unwrap_or(f64::NAN);
            let k = x("k");
            let g = f3_right(u0, u1, k);
            let e = (g - x("f3_right"))
                .abs()
                .worst((c1 * g - x("integral")).abs());
            right = if e.is_nan() { f64::NAN } else { right.worst(e) };
            let e = (f3_printed(u0, u1, k) - x("f3_printed"))
                .abs()
                .worst((crate::pde4::force::f1(u0, u1, k) - x("f1_printed")).abs())
                .worst((crate::pde4::force::f2(u0, u1, k) - x("f2_printed")).abs());
            printed = if e.is_nan() {
                f64::NAN
            } else {
                printed.worst(e)
            };
        }
    }
    (right, printed)
}

/// Eq 9's `f_mn`, eq 15's `dbar_mn` and the force coefficients of A1, A3-A4
/// and A5 as
/// implemented for the paper-literal checks, against SymPy's evaluation of
/// the printed text (`verify/printed_forms.py`): the largest relative
/// difference, NaN when the golden is missing.
fn printed_vs_sympy() -> f64 {
    let g: Value = serde_json::from_str(PRINTED_GOLDEN).unwrap_or_default();
    let p = &g["pde4_printed"];
    let num = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    // relative to |want| above 1 (a NaN want stays NaN through got - want)
    let rel = |got: f64, want: f64| {
        let scale = if want.abs() > 1.0 { want.abs() } else { 1.0 };
        (got - want).abs() / scale
    };
    let mut e = f64::NAN;
    let mut seen = |x: f64| {
        e = if e.is_nan() && !x.is_nan() {
            x
        } else {
            e.worst(x)
        }
    };
    for c in p["params"].as_array().into_iter().flatten() {
        let sp = ShapeParams {
            a1: num(&c["a1"]),
            a2: num(&c["a2"]),
            a3: num(&c["a3"]),
        };
        for r in c["rows"].as_array().into_iter().flatten() {
            let (m, n) = (num(&r["m"]) as usize, num(&r["n"]) as usize);
            seen(rel(
                crate::pde4::two_sided::printed_f(&sp, m, n),
                num(&r["f"]),
            ));
            seen(rel(
                crate::pde4::four_sided::printed_dbar(&sp, m, n),
                num(&r["dbar"]),
            ));
        }
    }
    let a = &p["area_force"];
    let kind = ForceKind::Area {
        u0: num(&a[0]),
        u1: num(&a[1]),
        v0: num(&a[2]),
        v1: num(&a[3]),
    };
    let (l, c) = (&p["line_force"], &p["concentrated_force"]);
    let line = ForceKind::Line {
        u0: num(&l[0]),
        u1: num(&l[1]),
        v0: num(&l[2]),
    };
    let conc = ForceKind::Concentrated {
        u0: num(&c[0]),
        v0: num(&c[1]),
    };
    // A1 (area), A3-A4 (line), A5 (concentrated); a missing table is NaN
    for (rows, kind) in [("area", kind), ("line", line), ("concentrated", conc)] {
        let rows = p[rows].as_array().filter(|r| !r.is_empty());
        if rows.is_none() {
            seen(f64::NAN);
        }
        for r in rows.into_iter().flatten() {
            let (m, n) = (num(&r["m"]) as usize, num(&r["n"]) as usize);
            match printed_two_sided(&kind, m, n) {
                Some((x, y, z)) => {
                    for (got, k) in [(x, 0), (y, 1), (z, 2)] {
                        seen(rel(got, num(&r["p"][k])));
                    }
                }
                None => seen(f64::NAN),
            }
        }
    }
    e
}

pub(super) fn appendix_checks(out: &mut Vec<Check>) {
    let (sym_right, sym_printed) = f3_vs_sympy();
    out.push(
        Check::new(F, P, "eqs 9, 15, app A1", "pde4.printed_forms_vs_sympy", Kind::Reference, printed_vs_sympy(), tol::scaled(tol::ROUNDING, 10.0))
            .note("eq 9's f_mn, eq 15's dbar_mn (3 shape parameters, 3 (m, n)) and the area (A1), line (A3-A4) and concentrated (A5) force coefficients (m, n <= 3) as implemented for the paper-literal checks against SymPy's evaluation of the printed text (verify/printed_forms.py), relative: pins the printed forms the paper-literal checks measure"),
    );
    out.push(
        Check::new(F, P, "app A3, A4", "pde4.force.line_f3_vs_sympy", Kind::Reference, sym_right, tol::scaled(tol::ROUNDING, 10.0))
            .note("c1 (A4) times the right f3 against SymPy's exact 2 int sin(pi (u - u_p0)/L) sin k pi u du, 3 forces, k <= 4 (verify/printed_forms.py)"),
    );
    out.push(
        Check::new(F, P, "app A2", "pde4.force.a2_f3_printed_vs_sympy", Kind::Reference, sym_printed, tol::scaled(tol::ROUNDING, 10.0))
            .note("A2's printed f3, f1 and f2 (pde4::force, as the paper-literal checks use them) against SymPy's evaluation of the printed text (f3 reduces to sin(2 k pi c)/(k^2 L^2 - 1))"),
    );
    let (mut e3, mut e4) = (0.0f64, 0.0f64);
    for (u0, u1, v0) in [(0.2, 0.7, 0.3), (0.35, 0.85, 0.6), (0.1, 0.4, 0.45)] {
        let f = Force {
            kind: ForceKind::Line { u0, u1, v0 },
            p: [1.0; 3],
        };
        let c1 = -2.0 * (u1 - u0) / PI;
        for m in 1..=6 {
            let mf = m as f64;
            if (mf * (u1 - u0) - 1.0).abs() < 1e-6 {
                continue;
            }
            let g = f3_right(u0, u1, mf);
            let (pm, _, _) = f.two_sided(m, 0);
            e4 = e4.worst((c1 * g - pm).abs());
            for n in 1..=4 {
                let (_, pc, ps) = f.two_sided(m, n);
                let w = 2.0 * n as f64 * PI * v0;
                e3 = e3
                    .worst((2.0 * c1 * g * w.cos() - pc).abs())
                    .worst((2.0 * c1 * g * w.sin() - ps).abs());
            }
        }
    }
    let mut e2max = 0.0f64;
    for (u0, u1) in [(0.2, 0.7), (0.35, 0.85), (0.1, 0.4)] {
        for m in 1..=6 {
            let mf = m as f64;
            if (mf * (u1 - u0) - 1.0).abs() < 1e-6 {
                continue;
            }
            let g = f3_right(u0, u1, mf);
            e2max = e2max.worst((f3_printed(u0, u1, mf) - g).abs());
        }
    }
    out.push(
        Check::new(F, P, "eq 12", "pde4.four_sided.eq12_ansatz_to_eq13", Kind::Boundary, eq12_error(), tol::ROUNDING)
            .note("eq 12's v(1-v)[G0 + u G1 + u^2 G2 + u^3 G3 + d sin m pi u sin n pi v] with BCs (5) imposed (4x4 solve per m <= 6) gives eq 13's printed G's (0, -pi m, pi m (2 + (-1)^m), -pi m (1 + (-1)^m)), relative to pi m; and meets BCs (10) at v = 0, 1 (jets)"),
    );
    out.push(
        Check::new(F, P, "app A4", "pde4.force.a4_c1_prefactor", Kind::Reference, e4, tol::ROUNDING)
            .note("A4's c1 = -2 (u_p1 - u_p0)/pi times f3 as it must read ((sin m pi u_p1 + sin m pi u_p0)/(m^2 L^2 - 1)) is the projection p_m of a unit line force (3 forces, m <= 6, m L != 1): A4 is right"),
    );
    out.push(
        Check::new(F, P, "app A3", "pde4.force.a3_line_coefficients", Kind::Reference, e3, tol::ROUNDING)
            .note("A3's p_m, pbar_mn = 2 c1 f3 cos 2 n pi v_p0, pbarbar_mn = 2 c1 f3 sin 2 n pi v_p0 with the f3 above against the projections (n <= 4): A3's structure is right, the error of the printed coefficients sits in A2's f3"),
    );
    out.push(
        Check::paper_literal(F, P, "app A2", "pde4.force.a2_f3_printed", e2max, tol::ROUNDING, true)
            .note("A2's f3 = 0.5 (r0 sin 2k pi r1 - r2 sin 2k pi r3) as printed against the f3 that makes A3 right: max difference (it reduces to sin(2k pi c)/(k^2 L^2 - 1); misprint, ERRATA)"),
    );
}
