//! Paper 002's printed derivative and linear-system formulas, implemented as
//! printed, to be measured against the jets of the project's closed form.
//!
//! The extraction of the paper text drops every minus sign of these
//! formulas (leading minus signs, the minus of $e^{-q_{1n}u}$ and the minus
//! between terms); each function below restores them and changes nothing
//! else, so what is compared is the printed term structure. Where the
//! printed text differs by more than a lost sign, a flag builds the printed
//! variant too (ERRATA.md):
//!
//! * eq 11, A24, A29: the $b_{wn,1}$ term of $\partial B_{wn}/\partial u$ is
//!   printed $2 b_{wn,1} q_{2n} \cos q_{2n}u$ where the $A_{wn}$ line (and the
//!   derivative of $\sin 2q_{2n}u$) has $\cos 2q_{2n}u$.
//!
//! Coefficients are in the paper's basis: $u^k$ for eq 6 and
//! $(\cos 2q_2u, \sin 2q_2u, e^{q_1u}\cos q_2u, e^{q_1u}\sin q_2u,
//! e^{-q_1u}\cos q_2u, e^{-q_1u}\sin q_2u)$ for eq 8 ([`ModeBasis::eval_paper`]),
//! with $q_{1n} = \frac{\sqrt3}{2} n|a|^{1/6}$, $q_{2n} = \frac12 n|a|^{1/6}$.

use super::*;
use nalgebra::{Matrix6, Vector6};

/// The basis of harmonic `n` as the paper prints it, independent of the
/// project's [`ModeBasis::new`]: $q_{0n} = n|a|^{1/6}$ (eq A11) and the
/// regime by the sign of a (eq 7 for a > 0, eq 8 for a < 0, the quintic of
/// eq 6 for a = 0 or n = 0). Its [`ModeBasis::eval_paper`] is the printed
/// basis the `pde6.printed.*` checks hold the project's functions against.
pub fn printed_basis(a: f64, n: usize) -> ModeBasis {
    let q = n as f64 * a.abs().powf(1.0 / 6.0);
    let regime = if a == 0.0 || n == 0 {
        Regime::Quintic
    } else if a < 0.0 {
        Regime::Oscillatory
    } else {
        Regime::Exponential
    };
    let q = if regime == Regime::Quintic { 0.0 } else { q };
    ModeBasis { regime, q }
}

/// One harmonic's basis twice: the project's ([`ModeBasis::new`], scaled,
/// what the patch was solved in) and the paper's ([`printed_basis`]), so
/// that a printed formula is never measured against the project's own
/// exponents.
#[derive(Clone, Copy, Debug)]
pub struct FnBasis {
    pub project: ModeBasis,
    pub printed: ModeBasis,
}

/// $(q_{1n}, q_{2n})$ of eq A15 from the printed $q_{0n}$ ([`printed_basis`]).
pub fn q12(b: &FnBasis) -> (f64, f64) {
    let q = b.printed.q;
    (0.5 * 3f64.sqrt() * q, 0.5 * q)
}

/// Eq 10 as printed: $A'_{w0}(u) = a_1 + 2a_2u + 3a_3u^2 + 4a_4u^3 + 5a_5u^4$.
pub fn eq10(c: &[f64; 6], u: f64) -> f64 {
    c[1] + 2.0 * c[2] * u + 3.0 * c[3] * u * u + 4.0 * c[4] * u.powi(3) + 5.0 * c[5] * u.powi(4)
}

/// Eq 12 as printed: $A''_{w0}(u) = 2a_2 + 6a_3u + 12a_4u^2 + 20a_5u^3$.
pub fn eq12(c: &[f64; 6], u: f64) -> f64 {
    2.0 * c[2] + 6.0 * c[3] * u + 12.0 * c[4] * u * u + 20.0 * c[5] * u.powi(3)
}

/// Eq 11 as printed, minus signs restored. `b_as_printed` takes the
/// printed $B_{wn}$ line's $\cos q_{2n}u$ in the $c_1$ term (the $A_{wn}$
/// line has $\cos 2q_{2n}u$).
pub fn eq11(c: &[f64; 6], q1: f64, q2: f64, u: f64, b_as_printed: bool) -> f64 {
    let (ep, em) = ((q1 * u).exp(), (-q1 * u).exp());
    let (co, si) = ((q2 * u).cos(), (q2 * u).sin());
    let c1_arg = if b_as_printed { q2 * u } else { 2.0 * q2 * u };
    -2.0 * c[0] * q2 * (2.0 * q2 * u).sin()
        + 2.0 * c[1] * q2 * c1_arg.cos()
        + c[2] * (q1 * ep * co - q2 * ep * si)
        + c[3] * (q1 * ep * si + q2 * ep * co)
        - c[4] * (q1 * em * co + q2 * em * si)
        + c[5] * (-q1 * em * si + q2 * em * co)
}

/// Eq 13 as printed, minus signs restored.
pub fn eq13(c: &[f64; 6], q1: f64, q2: f64, u: f64) -> f64 {
    let (ep, em) = ((q1 * u).exp(), (-q1 * u).exp());
    let (co, si) = ((q2 * u).cos(), (q2 * u).sin());
    let (a, b, d) = (q1 * q1, 2.0 * q1 * q2, q2 * q2);
    -4.0 * c[0] * d * (2.0 * q2 * u).cos() - 4.0 * c[1] * d * (2.0 * q2 * u).sin()
        + c[2] * (a * ep * co - b * ep * si - d * ep * co)
        + c[3] * (a * ep * si + b * ep * co - d * ep * si)
        + c[4] * (a * em * co + b * em * si - d * em * co)
        + c[5] * (a * em * si - b * em * co - d * em * si)
}

/// Eq A19: $A'_{w0}(0) = a_1$.
pub fn a19(c: &[f64; 6]) -> f64 {
    c[1]
}

/// Eq A20 as printed (signs restored): $A'_{wn}(0) = 2a_1q_2 + a_2q_1 + a_3q_2 - a_4q_1 + a_5q_2$.
pub fn a20(c: &[f64; 6], q1: f64, q2: f64) -> f64 {
    2.0 * c[1] * q2 + c[2] * q1 + c[3] * q2 - c[4] * q1 + c[5] * q2
}

/// Eq A21: $A''_{w0}(0) = 2a_2$.
pub fn a21(c: &[f64; 6]) -> f64 {
    2.0 * c[2]
}

/// Eq A22 as printed (signs restored; the printed $e^{q_{1n}u}$ left in the
/// $a_2$ term is 1 at u = 0): $-4a_0q_2^2 + a_2(q_1^2-q_2^2) + 2a_3q_1q_2 +
/// a_4(q_1^2-q_2^2) - 2a_5q_1q_2$.
pub fn a22(c: &[f64; 6], q1: f64, q2: f64) -> f64 {
    let d = q1 * q1 - q2 * q2;
    -4.0 * c[0] * q2 * q2 + c[2] * d + 2.0 * c[3] * q1 * q2 + c[4] * d - 2.0 * c[5] * q1 * q2
}

/// Eq A23: $A'_{w0}(1) = a_1 + 2a_2 + 3a_3 + 4a_4 + 5a_5$.
pub fn a23(c: &[f64; 6]) -> f64 {
    c[1] + 2.0 * c[2] + 3.0 * c[3] + 4.0 * c[4] + 5.0 * c[5]
}

/// Eq A25: $A''_{w0}(1) = 2a_2 + 6a_3 + 12a_4 + 20a_5$.
pub fn a25(c: &[f64; 6]) -> f64 {
    2.0 * c[2] + 6.0 * c[3] + 12.0 * c[4] + 20.0 * c[5]
}

/// Eq A24 as printed: eq 11 written out at u = 1 (same `b_as_printed`).
pub fn a24(c: &[f64; 6], q1: f64, q2: f64, b_as_printed: bool) -> f64 {
    let (e, ei) = (q1.exp(), (-q1).exp());
    let (co, si) = (q2.cos(), q2.sin());
    let c1_arg = if b_as_printed { q2 } else { 2.0 * q2 };
    -2.0 * c[0] * q2 * (2.0 * q2).sin()
        + 2.0 * c[1] * q2 * c1_arg.cos()
        + c[2] * (q1 * e * co - q2 * e * si)
        + c[3] * (q1 * e * si + q2 * e * co)
        - c[4] * (q1 * ei * co + q2 * ei * si)
        + c[5] * (-q1 * ei * si + q2 * ei * co)
}

/// Eq A26 as printed: eq 13 written out at u = 1.
pub fn a26(c: &[f64; 6], q1: f64, q2: f64) -> f64 {
    let (e, ei) = (q1.exp(), (-q1).exp());
    let (co, si) = (q2.cos(), q2.sin());
    let (a, b, d) = (q1 * q1, 2.0 * q1 * q2, q2 * q2);
    -4.0 * c[0] * d * (2.0 * q2).cos() - 4.0 * c[1] * d * (2.0 * q2).sin()
        + c[2] * (a * e * co - b * e * si - d * e * co)
        + c[3] * (a * e * si + b * e * co - d * e * si)
        + c[4] * (a * ei * co + b * ei * si - d * ei * co)
        + c[5] * (a * ei * si - b * ei * co - d * ei * si)
}

/// One row of eq 21 (i = 0..5, nodes 0.2 i) as printed:
/// $(1, 0.2i, 0.04i^2, 0.008i^3, 0.0016i^4, 0.00032i^5)$.
pub fn eq21_row(i: usize) -> [f64; 6] {
    let t = i as f64;
    [
        1.0,
        0.2 * t,
        0.04 * t * t,
        0.008 * t.powi(3),
        0.0016 * t.powi(4),
        0.00032 * t.powi(5),
    ]
}

/// One row of eqs 22-23 as printed (minus of $e^{-0.2iq_{1n}}$ restored):
/// $(\cos 0.4iq_2, \sin 0.4iq_2, e^{0.2iq_1}\cos 0.2iq_2, e^{0.2iq_1}\sin 0.2iq_2,
/// e^{-0.2iq_1}\cos 0.2iq_2, e^{-0.2iq_1}\sin 0.2iq_2)$.
pub fn eq22_row(i: usize, q1: f64, q2: f64) -> [f64; 6] {
    let t = i as f64;
    let (ep, em) = ((0.2 * t * q1).exp(), (-0.2 * t * q1).exp());
    let (co, si) = ((0.2 * t * q2).cos(), (0.2 * t * q2).sin());
    [
        (0.4 * t * q2).cos(),
        (0.4 * t * q2).sin(),
        ep * co,
        ep * si,
        em * co,
        em * si,
    ]
}

/// One row of eq A34 as printed (nodes i/3, i = 0..3):
/// $(1, i/3, i^2/9, i^3/27, i^4/81, i^5/243)$.
pub fn a34_row(i: usize) -> [f64; 6] {
    let t = i as f64;
    [
        1.0,
        t / 3.0,
        t * t / 9.0,
        t.powi(3) / 27.0,
        t.powi(4) / 81.0,
        t.powi(5) / 243.0,
    ]
}

/// One row of eqs A35-A36 as printed (the minus of $e^{-iq_1/3}$ and the
/// fraction bars of $\sin(iq_2/3)$ restored).
pub fn a35_row(i: usize, q1: f64, q2: f64) -> [f64; 6] {
    let t = i as f64 / 3.0;
    let (ep, em) = ((t * q1).exp(), (-t * q1).exp());
    let (co, si) = ((t * q2).cos(), (t * q2).sin());
    [
        (2.0 * t * q2).cos(),
        (2.0 * t * q2).sin(),
        ep * co,
        ep * si,
        em * co,
        em * si,
    ]
}

/// Solves six printed rows against six right-hand sides.
pub fn solve_rows(rows: [[f64; 6]; 6], rhs: [f64; 6]) -> Option<[f64; 6]> {
    let m = Matrix6::from_fn(|i, j| rows[i][j]);
    m.full_piv_lu().solve(&Vector6::from(rhs)).map(Into::into)
}

/// The coefficients, in the paper's basis (eq 6 monomials or eq 8 with the
/// minus signs restored), of the project's function $\sum_j c_j\phi_j$ of
/// basis `b` (a <= 0 only: the printed a > 0 basis is wrong, ERRATA):
/// interpolation at u = 0, 0.2, ..., 1.
pub fn to_paper_basis(b: &FnBasis, coef: &[f64; 6]) -> Option<[f64; 6]> {
    let rows: [[f64; 6]; 6] = std::array::from_fn(|i| b.printed.eval_paper(0.2 * i as f64));
    let rhs: [f64; 6] = std::array::from_fn(|i| {
        let p = b.project.eval(0.2 * i as f64);
        (0..6).map(|j| p[j] * coef[j]).sum()
    });
    solve_rows(rows, rhs)
}

/// A function of the paper's basis at u (derivative order d <= 2, jets).
pub fn paper_function(b: &FnBasis, c: &[f64; 6], u: f64, d: usize) -> f64 {
    let p = b.printed.eval_paper(Jet::<3, 1>::var_u(u));
    (0..6).map(|j| p[j].deriv(d, 0) * c[j]).sum()
}

/// The project's function $\sum_j c_j\phi_j$ at u (order d <= 5, jets).
pub fn project_function(b: &FnBasis, c: &[f64; 6], u: f64, d: usize) -> f64 {
    let p = b.project.eval(Jet::<7, 1>::var_u(u));
    (0..6).map(|j| p[j].deriv(d, 0) * c[j]).sum()
}

/// The 12 synthetic sections placed as in the paper's Fig 4 layout with
/// unit-length local parameters: C1-C4 at u = -1, -2/3, -1/3, 0 (patch 2),
/// C4-C9 at 0, 0.2, ..., 1 (patch 1), C9-C12 at 1, 4/3, 5/3, 2 (patch 3), so
/// the chain's u is each patch's own u (shifted) and the appendix B
/// equations, written in local parameters, apply as printed.
pub fn paper_layout_sections() -> Vec<Section> {
    let us = [
        -1.0,
        -2.0 / 3.0,
        -1.0 / 3.0,
        0.0,
        0.2,
        0.4,
        0.6,
        0.8,
        1.0,
        4.0 / 3.0,
        5.0 / 3.0,
        2.0,
    ];
    synthetic_sections(12, 6)
        .into_iter()
        .zip(us)
        .map(|(mut s, u)| {
            s.u = u;
            s
        })
        .collect()
}

/// Which of the paper's functions a stored coefficient vector is:
/// $A_{w0}$ (n = 0), $A_{wn}$ or $B_{wn}$.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    W0,
    A,
    B,
}

/// Every coefficient function of a patch with its paper role, n and
/// coordinate k: x: $A_{xn}$ multiplies cos, $B_{xn}$ sin (eq 3); y:
/// $A_{yn}$ multiplies sin, $B_{yn}$ cos (eq 4); z: $A_{z0}$ only (eq 5).
pub fn functions(p: &Patch) -> Vec<(Role, usize, usize, FnBasis, [f64; 6])> {
    let mut out = Vec::new();
    for (n, (b, c)) in p.basis.iter().zip(&p.coef).enumerate() {
        let b = &FnBasis {
            project: *b,
            printed: printed_basis(p.a, n),
        };
        for k in 0..3 {
            if n == 0 {
                out.push((Role::W0, n, k, *b, c[k][0]));
            } else if k < 2 {
                let (a_part, b_part) = if k == 0 { (0, 1) } else { (1, 0) };
                out.push((Role::A, n, k, *b, c[k][a_part]));
                out.push((Role::B, n, k, *b, c[k][b_part]));
            }
        }
    }
    out
}
