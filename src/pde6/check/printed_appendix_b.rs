//! Checks of paper 002 appendix B (A17-A36): the method-2 conditions of
//! patch 2 written out (the equalised C2 conditions A17-A18, the printed end
//! derivatives A19-A26, the substituted conditions A27-A29, patch 2 through
//! C1-C4 A30-A33) and its linear systems A34-A36, each built as printed
//! (signs restored, see [`super::printed`]) against the project's patch.
//! The numbering is fixed in [`super::printed_appendix`].

use super::printed::*;
use super::printed_checks::{node_error, rel, solved_rows_error, PRINTED_TOL};
use super::*;
use crate::check::{worst, Worst};

/// Linear rows of a printed end-derivative formula: f(e_j) for unit vectors.
fn rows_of(f: impl Fn(&[f64; 6]) -> f64) -> [f64; 6] {
    std::array::from_fn(|j| {
        let mut e = [0.0; 6];
        e[j] = 1.0;
        f(&e)
    })
}

/// The printed end slope and curvature (A19-A26) of a function in the
/// paper's basis at u = 0 (`at_one = false`) or u = 1.
fn printed_ends(
    role: Role,
    b: &FnBasis,
    c: &[f64; 6],
    at_one: bool,
    b_as_printed: bool,
) -> [f64; 2] {
    let (q1, q2) = q12(b);
    match (role, at_one) {
        (Role::W0, false) => [a19(c), a21(c)],
        (Role::W0, true) => [a23(c), a25(c)],
        (_, false) => [a20(c, q1, q2), a22(c, q1, q2)],
        (r, true) => [a24(c, q1, q2, b_as_printed && r == Role::B), a26(c, q1, q2)],
    }
}

/// The project's functions of patches 1 and 2, and patch 1's in the
/// paper's basis, shared by the appendix B checks.
struct Fns {
    f1: Vec<(Role, usize, usize, FnBasis, [f64; 6])>,
    f2: Vec<(Role, usize, usize, FnBasis, [f64; 6])>,
    paper1: Vec<Option<[f64; 6]>>,
}

impl Fns {
    fn new(p2: &Piece, p1: &Piece) -> Fns {
        let f1 = functions(&p1.patch);
        let f2 = functions(&p2.patch);
        let paper1 = f1
            .iter()
            .map(|(_, _, _, b, c)| to_paper_basis(b, c))
            .collect();
        Fns { f1, f2, paper1 }
    }

    /// Index of patch 1's function (role, n, k).
    fn find1(&self, role: Role, n: usize, k: usize) -> Option<usize> {
        self.f1
            .iter()
            .position(|f| f.0 == role && f.1 == n && f.2 == k)
    }
}

pub(super) fn appendix_b_checks(out: &mut Vec<Check>, p2: &Piece, p1: &Piece, sec: &[Section]) {
    let fns = Fns::new(p2, p1);
    equalised_checks(&fns, out);
    end_derivative_checks(&fns, out);
    substituted_checks(&fns, out);
    patch2_checks(&fns, p2, sec, out);
}

/// A17, A18: the equalised conditions, jets of the project functions.
fn equalised_checks(fns: &Fns, out: &mut Vec<Check>) {
    let (f1, f2) = (&fns.f1, &fns.f2);
    let find1 = |role: Role, n: usize, k: usize| fns.find1(role, n, k);
    // A17, A18: the equalised conditions, jets of the project functions
    let (mut e17, mut e18) = (0.0f64, 0.0f64);
    for (role, n, k, b, c) in f2 {
        let Some(i1) = find1(*role, *n, *k) else {
            e17 = f64::NAN;
            continue;
        };
        let (_, _, _, b1, c1) = &f1[i1];
        for d in 1..=2 {
            let e = rel(
                project_function(b, c, 1.0, d),
                project_function(b1, c1, 0.0, d),
            );
            if *role == Role::W0 {
                e17 = worst(e17, e);
            } else {
                e18 = worst(e18, e);
            }
        }
    }
    out.push(Check::new(FAMILY, PAPER, "eq A17", "pde6.printed.a17_c2_a_w0", Kind::Continuity, e17, SOLVE_TOL)
        .note("A17: dA_w0^P2(1)/du = dA_w0^P1(0)/du and the same for d2/du2 (w = x, y, z), jets, paper-layout method-2 chain, a = -0.5"));
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq A18",
            "pde6.printed.a18_c2_a_b_wn",
            Kind::Continuity,
            e18,
            SOLVE_TOL,
        )
        .note("A18: the same for A_wn and B_wn (w = x, y; n = 1..6)"),
    );
}

/// A19-A26: the printed end derivatives against jets.
fn end_derivative_checks(fns: &Fns, out: &mut Vec<Check>) {
    let (f1, f2) = (&fns.f1, &fns.f2);
    // A19-A26: printed end derivatives against jets
    let mut errs = [0.0f64; 8];
    for (patch_fns, at_one) in [(f1, false), (f2, true)] {
        for (role, _, _, b, c) in patch_fns.iter() {
            let Some(pc) = to_paper_basis(b, c) else {
                errs = [f64::NAN; 8];
                continue;
            };
            let u = if at_one { 1.0 } else { 0.0 };
            let printed = printed_ends(*role, b, &pc, at_one, false);
            let slot = match (role, at_one) {
                (Role::W0, false) => [0, 2],
                (_, false) => [1, 3],
                (Role::W0, true) => [4, 6],
                (_, true) => [5, 7],
            };
            for d in 0..2 {
                errs[slot[d]] = worst(
                    errs[slot[d]],
                    rel(printed[d], project_function(b, c, u, d + 1)),
                );
            }
        }
    }
    let labels = [
        ("A19", "dA_w0^P1(0)/du = a_w0,1"),
        ("A20", "dA_wn^P1(0)/du, dB_wn^P1(0)/du = 2 a1 q2n + a2 q1n + a3 q2n - a4 q1n + a5 q2n"),
        ("A21", "d2A_w0^P1(0)/du2 = 2 a_w0,2"),
        ("A22", "d2A_wn^P1(0)/du2 = -4 a0 q2n^2 + a2 (q1n^2 - q2n^2) + 2 a3 q1n q2n + a4 (q1n^2 - q2n^2) - 2 a5 q1n q2n"),
        ("A23", "dA_w0^P2(1)/du = a1 + 2 a2 + 3 a3 + 4 a4 + 5 a5"),
        ("A24", "dA_wn^P2(1)/du, dB_wn^P2(1)/du (eq 11 at u = 1; B's cos q2n read as cos 2 q2n)"),
        ("A25", "d2A_w0^P2(1)/du2 = 2 a2 + 6 a3 + 12 a4 + 20 a5"),
        ("A26", "d2A_wn^P2(1)/du2, d2B_wn^P2(1)/du2 (eq 13 at u = 1)"),
    ];
    for (i, (eq, what)) in labels.iter().enumerate() {
        out.push(Check::new(FAMILY, PAPER, &format!("eq {eq}"), &format!("pde6.printed.{}_end_derivative", eq.to_lowercase()), Kind::Reference, errs[i], PRINTED_TOL)
            .note(format!("{eq} as printed (minus signs restored), {what}: the function converted to the paper's basis against the jets of the project's closed form")));
    }
}

/// A27-A29: the printed substituted conditions on the built chain.
fn substituted_checks(fns: &Fns, out: &mut Vec<Check>) {
    let (f2, paper1) = (&fns.f2, &fns.paper1);
    let find1 = |role: Role, n: usize, k: usize| fns.find1(role, n, k);
    // A27-A29: the printed substituted conditions on the built chain
    let (mut e27, mut e28, mut e29, mut e29p) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (role, n, k, b, c) in f2 {
        let (Some(pc2), Some(i1)) = (to_paper_basis(b, c), find1(*role, *n, *k)) else {
            e27 = f64::NAN;
            continue;
        };
        let Some(pc1) = paper1[i1] else {
            e27 = f64::NAN;
            continue;
        };
        let lhs = printed_ends(*role, b, &pc2, true, false);
        let rhs = printed_ends(*role, b, &pc1, false, false);
        let e = rel(lhs[0], rhs[0]).worst(rel(lhs[1], rhs[1]));
        match role {
            Role::W0 => e27 = worst(e27, e),
            Role::A => e28 = worst(e28, e),
            Role::B => {
                e29 = worst(e29, e);
                let lp = printed_ends(*role, b, &pc2, true, true);
                e29p = worst(e29p, rel(lp[0], rhs[0]));
            }
        }
    }
    for (eq, e, what) in [
        ("A27", e27, "a_w0"),
        ("A28", e28, "a_wn"),
        ("A29", e29, "b_wn"),
    ] {
        out.push(Check::new(FAMILY, PAPER, &format!("eq {eq}"), &format!("pde6.printed.{}_conditions_{what}", eq.to_lowercase()), Kind::Reference, e, PRINTED_TOL)
            .note(format!("{eq} as printed: the P2 end slope/curvature in {what}^P2 equal the P1 start slope/curvature in {what}^P1, residual on the built chain (coefficients converted to the paper's basis)")));
    }
    out.push(Check::paper_literal(FAMILY, PAPER, "eqs 11, A24, A29", "pde6.paper_literal.a29_b_cos_argument", e29p, PRINTED_TOL, true)
        .note("A29 (and A24) with the printed 2 b_wn,1 q2n cos q2n: residual of the printed slope condition on the chain that satisfies the corrected one (misprint, ERRATA)"));
}

/// A31-A33 (patch 2 through C1-C4 per group) and A34-A36 with A27-A29
/// (the 6x6 systems of patch 2 as printed).
fn patch2_checks(fns: &Fns, p2: &Piece, sec: &[Section], out: &mut Vec<Check>) {
    let (f1, paper1) = (&fns.f1, &fns.paper1);
    let find1 = |role: Role, n: usize, k: usize| fns.find1(role, n, k);
    // A31-A33: patch 2 through C1-C4 per group
    let nodes = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
    let curves: Vec<&Fourier3> = sec[0..4].iter().map(|s| &s.curve).collect();
    for (eq, role, what) in [
        ("A31", Role::W0, "a_w0"),
        ("A32", Role::A, "a_wn"),
        ("A33", Role::B, "b_wn"),
    ] {
        out.push(
            Check::new(
                FAMILY,
                PAPER,
                &format!("eq {eq}"),
                &format!("pde6.printed.{}_group_{what}", eq.to_lowercase()),
                Kind::Boundary,
                node_error(&p2.patch, &nodes, &curves, role),
                SOLVE_TOL,
            )
            .note(format!(
                "{eq}: patch 2's functions at u = i/3 equal the curves C_{{i+1}}'s {what}"
            )),
        );
    }
    // A34-A36 with A27-A29: the 6x6 systems of patch 2 as printed
    for (eq, role, what) in [
        ("A34", Role::W0, "a_w0"),
        ("A35", Role::A, "a_wn"),
        ("A36", Role::B, "b_wn"),
    ] {
        let e = solved_rows_error(
            &p2.patch,
            role,
            |b| {
                let (q1, q2) = q12(b);
                let ends = [0, 1].map(|d| rows_of(|c| printed_ends(role, b, c, true, false)[d]));
                std::array::from_fn(|i| match (i, role) {
                    (4 | 5, _) => ends[i - 4],
                    (_, Role::W0) => a34_row(i),
                    _ => a35_row(i, q1, q2),
                })
            },
            |n, k| {
                let ends = find1(role, n, k).and_then(|i| {
                    paper1[i].map(|c| printed_ends(role, &f1[i].3, &c, false, false))
                });
                let [s, c] = ends.unwrap_or([f64::NAN; 2]);
                let cc = |i: usize| {
                    let (cn, sn) = curves[i].harmonic(n, k);
                    match (role, k) {
                        (Role::W0, _) | (Role::A, 0) | (Role::B, 1) => cn,
                        _ => sn,
                    }
                };
                [cc(0), cc(1), cc(2), cc(3), s, c]
            },
        );
        out.push(Check::new(FAMILY, PAPER, &format!("eq {eq}"), &format!("pde6.printed.{}_system_{what}", eq.to_lowercase()), Kind::Reference, e, PRINTED_TOL)
            .note(format!("{eq}'s four rows as printed (signs and fraction bars restored) with the two rows of the matching A27-A29, solved for {what}^P2 with P1's printed end derivatives: the function against patch 2's (value, slope, curvature)")));
    }
}
