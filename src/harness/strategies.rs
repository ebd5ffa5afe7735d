//! Proptest strategies for surface solvers: curves, cross sections, shape
//! parameters, forces; and the fixed-seed configuration every property test
//! of the kit uses.
//!
//! Every strategy draws inside the documented range of the parameter it
//! feeds (the ranges are stated on each function and come from the family
//! modules' docs), so a failure is a solver bug, not an out-of-range input.

use crate::curve::gec::{Frame, Gec};
use crate::curve::Fourier3;
use crate::mesh::Mesh;
use crate::surface::{tessellate, Revolution, Tessellation};
use proptest::prelude::*;

/// A finite coordinate in `[-r, r]`.
pub fn coord(r: f64) -> impl Strategy<Value = f64> {
    -r..r
}

/// A point in the cube `[-r, r]^3`.
pub fn point3(r: f64) -> impl Strategy<Value = [f64; 3]> {
    (coord(r), coord(r), coord(r)).prop_map(|(x, y, z)| [x, y, z])
}

/// Harmonic amplitudes of at most 5 % of the radius: with the ellipse's
/// radii in [0.5, 2] the curve stays regular and free of
/// self-intersections (the GEC module's tested range).
const HARMONIC: f64 = 0.05;

/// A star-shaped closed curve in the plane z = `z`: an ellipse with radii in
/// [0.5, 2] plus up to `n` small harmonics (non-self-intersecting).
pub fn star_curve(n: usize, z: f64) -> impl Strategy<Value = Fourier3> {
    (
        0.5f64..2.0,
        0.5f64..2.0,
        prop::collection::vec((-HARMONIC..HARMONIC, -HARMONIC..HARMONIC), n),
    )
        .prop_map(move |(a, b, h)| {
            let mut cos = vec![[a, 0.0, 0.0]];
            let mut sin = vec![[0.0, b, 0.0]];
            for (c, s) in h {
                cos.push([c * a, s * b, 0.0]);
                sin.push([s * a, c * b, 0.0]);
            }
            Fourier3 {
                c0: [0.0, 0.0, z],
                cos,
                sin,
            }
        })
}

/// A boundary curve of a tube along y: the closed curve of [`star_curve`]
/// turned into the horizontal plane at height `y` (x stays x, the curve's y
/// becomes z), with exactly `n + 1` harmonics, its centre moved by up to
/// 0.2 in x and z.
pub fn ring_curve(n: usize, y: f64) -> impl Strategy<Value = Fourier3> {
    (star_curve(n, 0.0), coord(0.2), coord(0.2)).prop_map(move |(c, dx, dz)| {
        let turn = |p: &[f64; 3]| [p[0], p[2], p[1]];
        Fourier3 {
            c0: [dx, y, dz],
            cos: c.cos.iter().map(turn).collect(),
            sin: c.sin.iter().map(turn).collect(),
        }
    })
}

/// A unit vector (uniform on the sphere, by normalising a Gaussian-like
/// draw away from zero).
pub fn unit_vector() -> impl Strategy<Value = [f64; 3]> {
    point3(1.0)
        .prop_filter("away from zero", |p| crate::vec3::norm(*p) > 0.1)
        .prop_map(crate::vec3::normalize)
}

/// A generalized elliptic curve (paper 000 eq 16, 002 eq 1) with `1..=terms`
/// terms placed in a random plane through a point of `[-10, 10]^3`: an
/// ellipse with semi-axes in [0.5, 2] plus harmonics n >= 2 of at most
/// 5 %/n^2 of the radius (regular, not self-intersecting).
pub fn gec_section(terms: usize) -> impl Strategy<Value = Gec> {
    let terms = terms.max(1);
    (
        point3(10.0),
        unit_vector(),
        0.5f64..2.0,
        0.5f64..2.0,
        prop::collection::vec(point3(1.0), terms - 1),
    )
        .prop_map(|(origin, normal, a, b, extra)| {
            let frame =
                Frame::from_normal(origin, normal, [1.0, 0.0, 0.0]).unwrap_or(Frame::z_plane(0.0));
            let mut x = vec![[a, 0.0]];
            let mut y = vec![[b, 0.0]];
            for (i, h) in extra.iter().enumerate() {
                let s = HARMONIC * a.min(b) / ((i + 2) * (i + 2)) as f64;
                x.push([s * h[0], s * h[1]]);
                y.push([s * h[2], s * h[0] * h[1]]);
            }
            Gec {
                frame,
                centre: [0.0, 0.0],
                x,
                y,
            }
        })
}

/// Shape parameters of the fourth-order family (paper 000 eq 1) in its
/// documented range: `a1, a3` in [0.05, 5], `a2 = tau 2 sqrt(a1 a3)` with
/// `tau` in (-0.95, 4) (elliptic).
pub fn pde4_shape() -> impl Strategy<Value = crate::pde4::ShapeParams> {
    (0.05f64..5.0, 0.05f64..5.0, -0.95f64..4.0).prop_map(|(a1, a3, tau)| crate::pde4::ShapeParams {
        a1,
        a2: tau * 2.0 * (a1 * a3).sqrt(),
        a3,
    })
}

/// The shape parameter `a` of the sixth-order PDE (paper 002 eq 2), in
/// [-1, 1]: both signs and zero's neighbourhood, where the six-point
/// interpolation of a patch is well conditioned for the first harmonics.
pub fn pde6_shape() -> impl Strategy<Value = f64> {
    -1.0f64..1.0
}

/// Shape parameters `(rho, eta, lambda)` of the sixth-order ODE (paper 004
/// eq 2), each in [0.2, 5]: the paper's case and the root cases around it.
pub fn ode6_shape() -> impl Strategy<Value = crate::ode6::Params> {
    (0.2f64..5.0, 0.2f64..5.0, 0.2f64..5.0)
        .prop_map(|(rho, eta, lambda)| crate::ode6::Params::new(rho, eta, lambda))
}

/// A sculpting force of paper 000 (eqs 2-3): concentrated, line or area, at
/// positions in [0.05, 0.95] with ranges at least 0.1 wide, magnitude
/// components in [-2, 2].
pub fn pde4_force() -> impl Strategy<Value = crate::pde4::Force> {
    use crate::pde4::{Force, ForceKind};
    let range = (0.05f64..0.5, 0.1f64..0.45).prop_map(|(a, w)| (a, a + w));
    let kind = prop_oneof![
        (0.05f64..0.95, 0.05f64..0.95).prop_map(|(u0, v0)| ForceKind::Concentrated { u0, v0 }),
        (range.clone(), 0.05f64..0.95).prop_map(|((u0, u1), v0)| ForceKind::Line { u0, u1, v0 }),
        (range.clone(), range).prop_map(|((u0, u1), (v0, v1))| ForceKind::Area { u0, u1, v0, v1 }),
    ];
    (kind, point3(2.0)).prop_map(|(kind, p)| Force { kind, p })
}

/// A tessellated tube of revolution (open in u, closed in v).
pub fn tube_mesh() -> impl Strategy<Value = Mesh> {
    (0.5f64..2.0, -0.4f64..0.4, 3usize..12, 3usize..24)
        .prop_map(|(r0, r1, nu, nv)| tessellate(&Revolution { r0, r1 }, Tessellation { nu, nv }))
}

/// The proptest configuration every property test uses: `cases` cases drawn
/// from a fixed seed, so that `cargo test` and CI draw the same cases on every
/// run. Failures found are persisted beside the test file under
/// `proptest-regressions/` (commit them) and replayed first.
///
/// Exploration with fresh seeds is a separate command:
/// `PDESCULPT_EXPLORE=1 cargo test --test it` draws random seeds and
/// `PDESCULPT_EXPLORE_CASES_FACTOR` (default 8) times as many cases. A
/// failure found that way is a library bug: fix it, then keep the case as a
/// named test.
pub fn config(cases: u32) -> ProptestConfig {
    use proptest::test_runner::{FileFailurePersistence, RngSeed};
    let explore = std::env::var_os("PDESCULPT_EXPLORE").is_some();
    let factor = std::env::var("PDESCULPT_EXPLORE_CASES_FACTOR")
        .ok()
        .and_then(|s| s.parse::<u32>().ok())
        .unwrap_or(8);
    ProptestConfig {
        cases: if explore {
            cases.saturating_mul(factor)
        } else {
            cases
        },
        rng_seed: if explore {
            RngSeed::Random
        } else {
            RngSeed::Fixed(0x7064_6573_6375_6c70) // "pdesculp"
        },
        // tests/it/conv.rs -> tests/proptest-regressions/conv.txt
        failure_persistence: Some(Box::new(FileFailurePersistence::SourceParallel(
            "proptest-regressions",
        ))),
        ..ProptestConfig::default()
    }
}
