//! Checks of the projection and mapping equations of paper 001 (eqs 13-16):
//! the view-plane projection against SymPy and its printed form, the local
//! frame's matrix form, the alpha shape of a grid, and eq 16's componentwise
//! and radial forms with the crease it leaves inside a square.

use super::*;
use crate::check::Worst;

/// The eq 13-16 checks (`c`: the golden projection case).
pub(super) fn projection_checks(out: &mut Vec<Check>, c: &Eq13) {
    eq13_checks(out, c);
    // eq 14
    let frame = LocalFrame::new([0.3, -1.0, 2.0], [0.2, 0.9, -0.4]);
    let e14 = frame
        .map(|f| {
            let p = [1.5, 0.25, -0.75];
            max_abs_diff(&f.to_local(p), &f.to_local_matrix(p))
        })
        .unwrap_or(f64::NAN);
    out.push(
        Check::new(
            F,
            P,
            "eq 14",
            "plate.eq14.matrix_form",
            Kind::Reference,
            e14,
            tol::ROUNDING,
        )
        .note("dot-product frame coordinates equal the printed row-vector [T][R] product"),
    );
    eq16_map_checks(out);
    // eq 15: the alpha shape of a k x k grid is its perimeter (4 (k - 1)
    // vertices), enclosing the full square
    let k = 12usize;
    let grid: Vec<[f64; 2]> = (0..k * k)
        .map(|i| [(i % k) as f64 * 0.1, (i / k) as f64 * 0.1])
        .collect();
    let e15 = crate::plate::boundary::alpha_shape(&grid, crate::plate::boundary::ALPHA0_DEFAULT)
        .map(|b| {
            let poly: Vec<[f64; 2]> = b.loop_indices.iter().map(|&i| grid[i]).collect();
            let side = 0.1 * (k - 1) as f64;
            (b.loop_indices.len() as f64 - 4.0 * (k - 1) as f64).abs()
                + (crate::polygon::signed_area(&poly) - side * side).abs() / (side * side)
        })
        .unwrap_or(f64::NAN);
    out.push(Check::new(F, P, "eq 15", "plate.eq15.alpha_shape_grid", Kind::Reference, e15, tol::ROUNDING)
        .note("alpha shape (alpha_0 = 0.86) of a 12x12 grid: |#loop - 44| + relative area error of the loop"));
    // eq 16 is only C0 inside: on the square of half-side a the map is
    // rho = max(|x|, |y|)/a, so the normalised deflection (1 - rho^2)^2 has
    // an x-slope jump 4 rho (1 - rho^2)/a across the diagonal
    out.push(
        Check::new(F, P, "eq 16", "plate.eq16.interior_slope_jump", Kind::Reference,
            square_slope_jump().unwrap_or(f64::NAN), SLOPE_JUMP_TOL)
        .note("finite-difference x-slope jump of (1-rho^2)^2 across the diagonal of a square at (0.3a, 0.3a) vs 4 rho (1-rho^2)/a: eq 16 creases the surface along rays through corners"),
    );
}

/// Eq 13: the corrected and printed projections against SymPy.
fn eq13_checks(out: &mut Vec<Check>, c: &Eq13) {
    let plane = ViewPlane {
        normal: [c.plane[0], c.plane[1], c.plane[2]],
        d: c.plane[3],
    };
    let pc = project(&plane, c.p);
    let pl = project_paper_literal(&plane, c.p);
    out.push(
        Check::new(
            F,
            P,
            "eq 13",
            "plate.eq13.projection",
            Kind::Reference,
            max_abs_diff(&pc, &c.correct).worst(max_abs_diff(&pl, &c.printed)),
            tol::ROUNDING,
        )
        .note("corrected and printed projections against SymPy"),
    );
    let on_plane =
        (plane.normal[0] * pc[0] + plane.normal[1] * pc[1] + plane.normal[2] * pc[2] + plane.d)
            .abs();
    out.push(
        Check::new(
            F,
            P,
            "eq 13",
            "plate.eq13.on_plane",
            Kind::Residual,
            on_plane,
            tol::ROUNDING,
        )
        .note("the corrected projection lies on the view plane"),
    );
    out.push(Check::paper_literal(F, P, "eq 13", "plate.eq13.paper_literal", max_abs_diff(&pc, &pl), tol::ROUNDING, true)
        .note("printed 'b p_x' instead of 'b p_y': distance between printed and orthogonal projection"));
}

/// Eq 16: the componentwise map equals the radial one off the axes; the
/// printed form is 0/0 on them.
fn eq16_map_checks(out: &mut Vec<Check>) {
    let (cc, dpt, dt) = ([0.1, -0.2], [1.3, 0.7], [0.6, 0.8]);
    let tpar = 0.37;
    let b = [
        cc[0] + tpar * (dpt[0] - cc[0]),
        cc[1] + tpar * (dpt[1] - cc[1]),
    ];
    let lit = eq16_paper_literal(b, cc, dpt, dt);
    out.push(
        Check::paper_literal(
            F,
            P,
            "eq 16",
            "plate.eq16.componentwise_generic",
            max_abs_diff(&lit, &[tpar * dt[0], tpar * dt[1]]),
            tol::ROUNDING,
            false,
        )
        .note("componentwise ratios equal the radial ratio |CB|/|CD| for B on segment CD"),
    );
    let dv = [0.1, 1.4];
    let bv = [0.1, 0.5];
    let litv = eq16_paper_literal(bv, cc, dv, [0.0, 1.0]);
    let rad = [0.0, 0.7 / 1.6];
    // the printed form's failure is measured as a count, so the check itself
    // stays finite: the number of printed components that are undefined
    // (0/0), or, when all are defined, their difference from the radial map
    let undefined = litv.iter().filter(|x| !x.is_finite()).count();
    let m16 = if undefined > 0 {
        undefined as f64
    } else {
        max_abs_diff(&litv, &rad)
    };
    out.push(
        Check::paper_literal(
            F,
            P,
            "eq 16",
            "plate.eq16.paper_literal_axis",
            m16,
            tol::ROUNDING,
            true,
        )
        .note("B straight above C: number of printed components that are 0/0 (the u-ratio; measured 1), while the radial ratio is finite"),
    );
}

/// Relative tolerance of the finite-difference slope jump (step 1e-6).
pub const SLOPE_JUMP_TOL: f64 = 1e-4;

/// Relative difference between the measured and the predicted x-slope
/// jump of the eq-16 deflection across the diagonal of a square.
pub fn square_slope_jump() -> Result<f64, PlateError> {
    use crate::plate::mapping::DiskMapping;
    let a = 1.0;
    let sq = vec![[-a, -a], [a, -a], [a, a], [-a, a]];
    let mut m = DiskMapping::new(sq, [0.0, 0.0])?;
    let mut w = |x: f64, y: f64| {
        let d = m.map_point([x, y], None);
        64.0 * disk_profile(d.rho)
    };
    let (t, h) = (0.3 * a, 1e-6);
    // x-slope just right of the diagonal (|x| > |y|) and just left of it
    let right = (w(t + 2.0 * h, t) - w(t + h, t)) / h;
    let left = (w(t - h, t) - w(t - 2.0 * h, t)) / h;
    let rho = t / a;
    let predicted = 4.0 * rho * (1.0 - rho * rho) / a;
    Ok(((left - right).abs() - predicted).abs() / predicted)
}
