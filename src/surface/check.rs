//! Checks of the surface infrastructure: jet derivatives of a surface
//! against finite differences, and seam sharing in tessellation.

use super::{tessellate, Revolution, Surface, Tessellation};
use crate::check::Worst;
use crate::check::{Check, Kind};
use crate::mesh::topology;

/// Step and tolerance of the central-difference comparison: the truncation
/// error is O(h^2) times the third derivative (here below 1e3).
pub const FD_STEP: f64 = 1e-4;
pub const FD_TOL: f64 = 1e-5;
/// Step (fraction of the domain) of [`jet_vs_fd`], which extrapolates the
/// central differences at `h` and `h/2` (Richardson: truncation O(h^4), so
/// rounding `eps |S| / h^2` stays small too).
pub const FD_STEP_RICHARDSON: f64 = 1e-3;

/// All checks of the surface family.
pub fn checks() -> Vec<Check> {
    let s = Revolution { r0: 1.0, r1: 0.3 };
    let mut worst: f64 = 0.0;
    for &(u, v) in &[(0.2, 0.1), (0.5, 0.7), (0.9, 0.35)] {
        for (i, j) in [(1, 0), (0, 1), (2, 0), (1, 1), (0, 2)] {
            let d = s.derivative(u, v, i, j);
            let fd = central(&s, u, v, i, j);
            for k in 0..3 {
                worst = worst.worst((d[k] - fd[k]).abs() / d[k].abs().worst(1.0));
            }
        }
    }
    let m = tessellate(&s, Tessellation { nu: 10, nv: 16 });
    let r = topology::report(&m);
    // open in u (two boundary loops of 16 edges), closed in v: 11 x 16 vertices
    let seam_err = (m.positions.len() as f64 - 176.0).abs()
        + (r.boundary_edges as f64 - 32.0).abs()
        + (!r.oriented) as u32 as f64
        + (r.nonmanifold_edges as f64);
    vec![
        Check::new(
            "surface",
            "-",
            "derivatives",
            "surface.jet-vs-finite-differences",
            Kind::Reference,
            worst,
            FD_TOL,
        )
        .note("S_u, S_v, S_uu, S_uv, S_vv of a surface of revolution: jets vs central differences (h = 1e-4)"),
        Check::new(
            "surface",
            "-",
            "tessellation",
            "surface.closed-seam-shared",
            Kind::Reference,
            seam_err,
            0.0,
        )
        .note("a tube closed in v tessellates with shared seam vertices: 11x16 vertices, only the two end loops are boundary"),
    ]
}

/// Domain fractions where [`jet_vs_fd`] compares (away from the edges and
/// from integer joins of chains).
pub const FD_FRACTIONS: [(f64, f64); 4] = [(0.23, 0.11), (0.47, 0.71), (0.62, 0.37), (0.81, 0.93)];

/// Largest difference between the jet derivatives `S_u, S_v, S_uu, S_uv,
/// S_vv` of any surface and central differences, relative to
/// `max(|derivative|, 1)`, at [`FD_FRACTIONS`] of its domain. The steps are
/// [`FD_STEP_RICHARDSON`] times the domain widths (Richardson-extrapolated),
/// and the derivatives are compared in
/// those fraction units (chain rule) so the tolerance does not depend on the
/// parametrisation's scale.
pub fn jet_vs_fd<S: Surface>(s: &S) -> f64 {
    let d = s.domain();
    let (wu, wv) = (d.u.1 - d.u.0, d.v.1 - d.v.0);
    let mut worst: f64 = 0.0;
    for &(fu, fv) in &FD_FRACTIONS {
        let (u, v) = d.at(fu, fv);
        for (i, j) in [(1, 0), (0, 1), (2, 0), (1, 1), (0, 2)] {
            let scale = wu.powi(i as i32) * wv.powi(j as i32);
            let jet = s.derivative(u, v, i, j);
            let h = FD_STEP_RICHARDSON;
            let coarse = central_steps(s, u, v, i, j, h * wu, h * wv);
            let fine = central_steps(s, u, v, i, j, 0.5 * h * wu, 0.5 * h * wv);
            let fd: [f64; 3] = std::array::from_fn(|k| (4.0 * fine[k] - coarse[k]) / 3.0);
            for k in 0..3 {
                let (a, b) = (jet[k] * scale, fd[k] * scale);
                let e = (a - b).abs() / a.abs().worst(1.0);
                worst = if e.is_nan() { f64::NAN } else { worst.worst(e) };
            }
        }
    }
    worst
}

/// [`jet_vs_fd`] as a check named `derivatives.<sample>`.
pub fn derivative_check<S: Surface>(sample: &str, paper: &str, s: &S) -> Check {
    Check::new(
        "derivatives",
        paper,
        "derivatives",
        &format!("derivatives.{sample}"),
        Kind::Reference,
        jet_vs_fd(s),
        FD_TOL,
    )
    .note(format!(
        "{sample}: jet S_u, S_v, S_uu, S_uv, S_vv vs central differences (step 1e-4 of the domain) at four interior points, relative"
    ))
    .loose_because(
        "one central-difference tolerance for every sample, so that no sample's bound is tuned \
         to its own output: the second differences carry rounding eps / h^2 of about 2e-8 times \
         the data scale, and the worst sample (derivatives.ode6.grid_3x2_column) measures 7.4e-7",
    )
}

fn central<S: Surface>(s: &S, u: f64, v: f64, i: usize, j: usize) -> [f64; 3] {
    central_steps(s, u, v, i, j, FD_STEP, FD_STEP)
}

fn central_steps<S: Surface>(
    s: &S,
    u: f64,
    v: f64,
    i: usize,
    j: usize,
    hu: f64,
    hv: f64,
) -> [f64; 3] {
    let f = |du: f64, dv: f64| s.point(u + du, v + dv);
    let comb = |terms: &[(f64, f64, f64)], div: f64| {
        let mut out = [0.0; 3];
        for &(du, dv, w) in terms {
            let p = f(du, dv);
            for k in 0..3 {
                out[k] += w * p[k] / div;
            }
        }
        out
    };
    match (i, j) {
        (1, 0) => comb(&[(hu, 0.0, 1.0), (-hu, 0.0, -1.0)], 2.0 * hu),
        (0, 1) => comb(&[(0.0, hv, 1.0), (0.0, -hv, -1.0)], 2.0 * hv),
        (2, 0) => comb(
            &[(hu, 0.0, 1.0), (0.0, 0.0, -2.0), (-hu, 0.0, 1.0)],
            hu * hu,
        ),
        (0, 2) => comb(
            &[(0.0, hv, 1.0), (0.0, 0.0, -2.0), (0.0, -hv, 1.0)],
            hv * hv,
        ),
        _ => comb(
            &[
                (hu, hv, 1.0),
                (hu, -hv, -1.0),
                (-hu, hv, -1.0),
                (-hu, -hv, 1.0),
            ],
            4.0 * hu * hv,
        ),
    }
}
