//! Tutorial chapter 9 (docs/tutorial/09_verify.md): verifying a surface
//! solver with the property-testing harness (`pdesculpt::harness`).
//!
//! The solver (`solver.rs`) blends two closed curves and their u-tangents
//! by cubic Hermite functions: each line v = const solves S_uuuu = 0. The
//! harness measures four properties on random boundary curves drawn by its
//! strategies, for the solver and two broken copies, and prints which
//! property catches which bug.
//!
//! Run: `cargo run --release --example 09_verify`

mod solver;

use pdesculpt::check::tol;
use pdesculpt::harness::properties::{
    boundary_gap, derivatives_vs_finite_differences, interior_points, residual,
};
use pdesculpt::harness::strategies::ring_curve;
use pdesculpt::surface::check::FD_TOL;
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;
use solver::{HermiteTube, Variant};

/// The curve `c` as a function of `v` in [0, 1] (theta = 2 pi v).
fn at(c: &pdesculpt::curve::Fourier3) -> impl Fn(f64) -> [f64; 3] + '_ {
    move |v| c.eval(std::f64::consts::TAU * v)
}

fn main() -> anyhow::Result<()> {
    // four random closed curves from the harness's strategies (fixed seed)
    let mut runner = TestRunner::deterministic();
    let mut draw = |y: f64| ring_curve(3, y).new_tree(&mut runner).map(|t| t.current());
    let (c0, c1, t0, t1) = (draw(0.0), draw(1.5), draw(1.0), draw(1.0));
    let (c0, c1, t0, t1) = (
        c0.map_err(anyhow::Error::msg)?,
        c1.map_err(anyhow::Error::msg)?,
        t0.map_err(anyhow::Error::msg)?,
        t1.map_err(anyhow::Error::msg)?,
    );

    println!(
        "{:<9} {:>11} {:>11} {:>11} {:>11}",
        "variant", "S(0) = c0", "S_u(0) = t0", "S_uuuu = 0", "jets = FD"
    );
    for variant in [Variant::Correct, Variant::SignSlip, Variant::LostJet] {
        let s = HermiteTube {
            c0: c0.clone(),
            c1: c1.clone(),
            t0: t0.clone(),
            t1: t1.clone(),
            variant,
        };
        let position = boundary_gap(&s, 0.0, 0, at(&c0), 64);
        let tangent = boundary_gap(&s, 0.0, 1, at(&t0), 64);
        let ode = residual(&s, &interior_points(&s, 5), |d, _, _| (d.get(4, 0), 1.0));
        let fd = derivatives_vs_finite_differences(&s);
        let mark = |m: f64, t: f64| format!("{m:>9.1e}{}", if m <= t { "  " } else { " X" });
        println!(
            "{:<9} {} {} {} {}",
            format!("{variant:?}"),
            mark(position, tol::ROUNDING),
            mark(tangent, tol::ROUNDING),
            mark(ode, tol::ROUNDING),
            mark(fd, FD_TOL)
        );
    }
    println!("X: the property fails (measured above its tolerance)");
    Ok(())
}
