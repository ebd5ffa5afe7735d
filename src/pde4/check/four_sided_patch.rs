//! Four-sided patch checks (eqs 11-16): Galerkin plate values against Timoshenko, boundary, paper-literal forms.

use super::*;
use crate::check::Worst;

/// Galerkin plate centre deflection (component 0) for one force and params.
pub fn plate_centre(
    p: ShapeParams,
    kind: ForceKind,
    terms: usize,
    method: four_sided::Method,
) -> f64 {
    let f = [Force {
        kind,
        p: [1.0, 0.0, 0.0],
    }];
    FourSided::new([p; 3], &f, terms, terms, method).map_or(f64::NAN, |s| s.point(0.5, 0.5)[0])
}

pub(super) fn four_sided_checks(out: &mut Vec<Check>) {
    table_checks(out);
    fd_checks(out);
    printed_check(out);
    clamped_checks(out);
}

/// Galerkin plate deflections against the published tables (Timoshenko,
/// Taylor & Govindjee).
fn table_checks(out: &mut Vec<Check>) {
    let t = PLATE_TERMS;
    let gal = four_sided::Method::Galerkin;
    let sq = plate_centre(ShapeParams::PLATE, ForceKind::Uniform, t, gal);
    let cases = [
        (
            "pde4.four_sided.plate_square_uniform",
            sq,
            PLATE_SQUARE_UNIFORM,
            "uniform load, square: w_max / (q a^4 / D) vs 0.00126 (Timoshenko table 35)",
        ),
        (
            "pde4.four_sided.plate_rect_1_5_uniform",
            plate_centre(
                ShapeParams::plate_ratio(1.0 / 1.5),
                ForceKind::Uniform,
                t,
                gal,
            ),
            PLATE_RECT_15_UNIFORM,
            "uniform load, b/a = 1.5 vs 0.00220 (table 35)",
        ),
        (
            "pde4.four_sided.plate_rect_2_uniform",
            plate_centre(ShapeParams::plate_ratio(0.5), ForceKind::Uniform, t, gal),
            PLATE_RECT_2_UNIFORM,
            "uniform load, b/a = 2 vs 0.00254 (table 35)",
        ),
        (
            "pde4.four_sided.plate_square_point",
            plate_centre(
                ShapeParams::PLATE,
                ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
                t,
                gal,
            ),
            PLATE_SQUARE_POINT,
            "central point load, square: w_max / (P a^2 / D) vs 0.00560",
        ),
    ];
    for (name, got, want, note) in cases {
        out.push(
            Check::new(
                F,
                P,
                "eqs 10-13 (Galerkin)",
                name,
                Kind::Reference,
                rel(got, want),
                tol::PLATE_THEORY,
            )
            .note(format!("{note}; M = N = {t}, got {got:.7}")),
        );
    }
    out.push(
        Check::new(
            F,
            P,
            "eqs 10-13 (Galerkin)",
            "pde4.four_sided.plate_square_uniform_precise",
            Kind::Reference,
            rel(sq, PLATE_SQUARE_UNIFORM_PRECISE),
            tol::TABLE_4_DIGITS,
        )
        .note(format!(
            "uniform square vs 0.00126532 (Taylor & Govindjee); M = N = {t}, got {sq:.8}"
        )),
    );
}

/// The independent FD reference: first its own accuracy on the published
/// uniform value, then the sinusoidal load (no trusted published
/// clamped-plate value found).
fn fd_checks(out: &mut Vec<Check>) {
    let t = PLATE_TERMS;
    let gal = four_sided::Method::Galerkin;
    let fd_u = super::super::fd::fd_centre_extrapolated(ShapeParams::PLATE, FD_GRID, |_, _| 1.0)
        .map_or(f64::NAN, |r| r.0);
    out.push(
        Check::new(
            F,
            P,
            "eqs 10-13 (FD reference)",
            "pde4.four_sided.fd_reference_uniform",
            Kind::Reference,
            rel(fd_u, PLATE_SQUARE_UNIFORM_PRECISE),
            tol::TABLE_4_DIGITS,
        )
        .note(format!(
            "13-point FD, clamped by ghost mirror, Richardson n = {FD_GRID}, {}: {fd_u:.9} vs 0.00126532 (Taylor & Govindjee)",
            2 * FD_GRID
        )),
    );
    let sine = |u: f64, v: f64| (PI * u).sin() * (PI * v).sin();
    for (name, rho, what) in [
        ("pde4.four_sided.plate_square_sine", 1.0, "square"),
        (
            "pde4.four_sided.plate_rect_1_5_sine",
            1.0 / 1.5,
            "b/a = 1.5",
        ),
        ("pde4.four_sided.plate_rect_2_sine", 0.5, "b/a = 2"),
    ] {
        let p = ShapeParams::plate_ratio(rho);
        let reference =
            super::super::fd::fd_centre_extrapolated(p, FD_GRID, sine).map_or(f64::NAN, |r| r.0);
        let got = plate_centre(p, SINE_LOAD, t, gal);
        out.push(
            Check::new(
                F,
                P,
                "eqs 10-13 (Galerkin)",
                name,
                Kind::Reference,
                rel(got, reference),
                tol::TABLE_4_DIGITS,
            )
            .note(format!(
                "load q0 sin(pi x/a) sin(pi y/b), {what}: Galerkin M = N = {t} {got:.9} vs FD reference {reference:.9} (Richardson n = {FD_GRID}, {}), w / (q0 a^4 / D)",
                2 * FD_GRID
            )),
        );
    }
}

/// Eqs 14-15 as printed against the plate value.
fn printed_check(out: &mut Vec<Check>) {
    let t = PLATE_TERMS;
    let pr = plate_centre(
        ShapeParams::PLATE,
        ForceKind::Uniform,
        t,
        four_sided::Method::Paper,
    );
    out.push(
        Check::paper_literal(
            F,
            P,
            "eqs 14, 15",
            "pde4.four_sided.eq14_15_vs_plate",
            rel(pr, PLATE_SQUARE_UNIFORM_PRECISE),
            tol::PLATE_THEORY,
            true,
        )
        .note(format!(
            "printed d_mn, uniform square, centre: {pr:.6} vs 0.00126532"
        )),
    );
}

/// The clamped edges of the Galerkin patch and its separable grid.
fn clamped_checks(out: &mut Vec<Check>) {
    let gal = four_sided::Method::Galerkin;
    let forces = sample_forces();
    let (bd, gd) = match FourSided::new([ShapeParams::uniform(0.3); 3], &forces, 8, 8, gal) {
        Ok(s) => {
            let mut w = 0.0f64;
            for i in 0..=16 {
                let s_ = i as f64 / 16.0;
                for (u, v) in [(0.0, s_), (1.0, s_), (s_, 0.0), (s_, 1.0)] {
                    let x = Surface::eval(&s, Jet::<2, 2>::var_u(u), Jet::<2, 2>::var_v(v));
                    for k in 0..3 {
                        w = w
                            .worst(x[k].c[0][0].abs())
                            .worst(x[k].c[1][0].abs())
                            .worst(x[k].c[0][1].abs());
                    }
                }
            }
            let us: Vec<f64> = (0..=9).map(|i| i as f64 / 9.0).collect();
            let a: Vec<f64> = s.grid(&us, &us).into_iter().flatten().collect();
            let b: Vec<f64> = s.grid_naive(&us, &us).into_iter().flatten().collect();
            (
                w,
                crate::check::max_abs_diff(&a, &b)
                    / b.iter()
                        .fold(0.0f64, |x, y| x.worst(y.abs()))
                        .worst(f64::MIN_POSITIVE),
            )
        }
        Err(_) => (f64::NAN, f64::NAN),
    };
    out.push(
        Check::new(
            F,
            P,
            "eqs 5, 10",
            "pde4.four_sided.galerkin_clamped",
            Kind::Boundary,
            bd,
            tol::ROUNDING,
        )
        .note("max |t|, |t_u|, |t_v| on the four edges, Galerkin M = N = 8"),
    );
    out.push(
        Check::new(
            F,
            P,
            "eq 13",
            "pde4.four_sided.grid_separable",
            Kind::Reference,
            gd,
            tol::ROUNDING * 100.0,
        )
        .note("separable grid vs direct double sum, relative"),
    );
}
