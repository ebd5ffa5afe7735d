//! Pure speedups (issue 30) give the bits the slower code gave: each test
//! here runs the fast path and the path it replaced on the same input and
//! asserts equality, not closeness.

use pdesculpt::jet::Jet;
use pdesculpt::surface::Surface;

/// `f64` equality that also holds between two NaNs (a surface that is not
/// finite somewhere must be so on both paths).
fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

/// Every derivative of order (i, j) <= (2, 2) through
/// [`Surface::derivative`] (the smallest jet that holds it) against the
/// `Jet<7, 7>` evaluation it replaced, on a 5 x 5 grid of the domain.
/// Returns the first mismatch.
fn derivative_mismatch<S: Surface>(s: &S) -> Option<String> {
    let d = s.domain();
    for a in 0..5 {
        for b in 0..5 {
            let (u, v) = d.at(0.05 + 0.225 * a as f64, 0.05 + 0.225 * b as f64);
            let p = s.eval(Jet::<7, 7>::var_u(u), Jet::<7, 7>::var_v(v));
            for i in 0..=2 {
                for j in 0..=2 {
                    let fast = s.derivative(u, v, i, j);
                    let slow = [p[0].deriv(i, j), p[1].deriv(i, j), p[2].deriv(i, j)];
                    if !(0..3).all(|k| same(fast[k], slow[k])) {
                        return Some(format!("d({i},{j}) at ({u}, {v}): {fast:?} != {slow:?}"));
                    }
                }
            }
        }
    }
    None
}

#[test]
fn surface_derivative_jet_size_is_bit_identical() {
    use pdesculpt::{ode6, pde4, pde6};
    let mut bad = Vec::new();
    let mut run = |name: &str, m: Option<String>| {
        if let Some(m) = m {
            bad.push(format!("{name}: {m}"));
        }
    };
    run(
        "revolution",
        derivative_mismatch(&pdesculpt::surface::Revolution { r0: 1.0, r1: 0.3 }),
    );
    run(
        "pde4 two-sided",
        derivative_mismatch(&pde4::samples::two_sided().expect("sample")),
    );
    run(
        "pde4 four-sided",
        derivative_mismatch(&pde4::samples::four_sided().expect("sample")),
    );
    run(
        "pde4 deformed revolution",
        derivative_mismatch(&pde4::samples::deformed_revolution().expect("sample")),
    );
    run(
        "ode6 patch",
        derivative_mismatch(&ode6::samples::patch().expect("sample")),
    );
    run(
        "ode6 paper chain",
        derivative_mismatch(&ode6::samples::paper_chain().expect("sample")),
    );
    for (name, a) in pde6::samples::SIGNS {
        run(
            &format!("pde6 chain {name}"),
            derivative_mismatch(&pde6::samples::chain(a).expect("sample")),
        );
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
