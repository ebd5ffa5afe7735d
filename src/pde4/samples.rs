//! Named test problems of the fourth-order family (paper 000): shape
//! parameters for every root case, sample forces and a sample boundary,
//! shared by the checks, tests, benches and figures.

use super::two_sided::Boundary;
use super::{Force, ForceKind, ShapeParams};
use crate::curve::Fourier3;
use std::f64::consts::PI;

/// The sinusoidal load `sin(pi u) sin(pi v)` (an area force over the whole patch).
pub const SINE_LOAD: ForceKind = ForceKind::Area {
    u0: 0.0,
    u1: 1.0,
    v0: 0.0,
    v1: 1.0,
};

/// Shape parameters covering every root case of the mode ODE.
pub fn root_cases() -> Vec<(&'static str, ShapeParams)> {
    vec![
        ("double", ShapeParams::PLATE),
        (
            "distinct",
            ShapeParams {
                a1: 1.0,
                a2: 3.0,
                a3: 1.0,
            },
        ),
        (
            "complex",
            ShapeParams {
                a1: 1.0,
                a2: 0.5,
                a3: 1.0,
            },
        ),
        (
            "negative-a2",
            ShapeParams {
                a1: 2.0,
                a2: -1.0,
                a3: 1.0,
            },
        ),
        ("paper-0.3", ShapeParams::uniform(0.3)),
    ]
}

/// A combination of a concentrated, a line and an area force.
pub fn sample_forces() -> Vec<Force> {
    vec![
        Force {
            kind: ForceKind::Concentrated { u0: 0.3, v0: 0.2 },
            p: [0.0, 0.0, 1.0],
        },
        Force {
            kind: ForceKind::Line {
                u0: 0.2,
                u1: 0.7,
                v0: 0.6,
            },
            p: [0.5, 0.0, 0.3],
        },
        Force {
            kind: ForceKind::Area {
                u0: 0.35,
                u1: 0.85,
                v0: 0.4,
                v1: 0.9,
            },
            p: [0.0, 1.0, 0.5],
        },
    ]
}

/// A sample boundary (curves and tangents) for the non-zero-boundary checks.
pub fn sample_boundary() -> Boundary {
    let ring = |r: f64, y: f64| Fourier3 {
        c0: [0.0, y, 0.0],
        cos: vec![[r, 0.0, 0.0], [0.0, 0.0, 0.05]],
        sin: vec![[0.0, 0.0, r]],
    };
    Boundary {
        curve0: ring(1.0, 0.0),
        curve1: ring(0.7, 1.0),
        tangent0: Fourier3 {
            c0: [0.0, 1.0, 0.0],
            cos: vec![[0.3, 0.0, 0.0]],
            sin: vec![[0.0, 0.0, 0.3]],
        },
        tangent1: Fourier3 {
            c0: [0.0, 1.0, 0.0],
            cos: vec![[-0.2, 0.0, 0.0]],
            sin: vec![[0.0, 0.0, -0.2]],
        },
    }
}

/// Three different shape parameters (the plate, uniform 0.3, and
/// `a = (1, 0.5, 1)`), one per component: the two-sided checks' mix.
pub fn mixed_shapes() -> [ShapeParams; 3] {
    [
        ShapeParams::PLATE,
        ShapeParams::uniform(0.3),
        ShapeParams {
            a1: 1.0,
            a2: 0.5,
            a3: 1.0,
        },
    ]
}

/// The two-sided patch of the non-zero-boundary checks: three different
/// shape parameters, the sample forces, 8 x 8 terms, [`sample_boundary`].
pub fn two_sided() -> Result<super::TwoSided, super::Pde4Error> {
    super::TwoSided::new(
        mixed_shapes(),
        &sample_forces(),
        8,
        8,
        super::two_sided::Method::Exact,
        Some(&sample_boundary()),
    )
}

/// The four-sided Galerkin patch of the clamped-edge check (8 x 8 terms).
pub fn four_sided() -> Result<super::FourSided, super::Pde4Error> {
    super::FourSided::new(
        [ShapeParams::uniform(0.3); 3],
        &sample_forces(),
        8,
        8,
        super::four_sided::Method::Galerkin,
    )
}

/// [`four_sided`] applied to a surface of revolution (radii 1 and 0.3) on
/// the window `u in [0.1, 0.9]`, `v in [0.05, 0.98]`, scaled by 0.5: the
/// sample of the derivative check `derivatives.pde4.deformed_revolution`.
pub fn deformed_revolution(
) -> Result<super::apply::Deformed<crate::surface::Revolution, super::FourSided>, super::Pde4Error>
{
    super::apply::Deformed::new(
        crate::surface::Revolution { r0: 1.0, r1: 0.3 },
        four_sided()?,
        (0.1, 0.9),
        (0.05, 0.98),
        0.5,
    )
}

/// A closed curve drawn in the front view around a region to deform
/// (paper 000 sec 5.1, the input of [`super::apply::deform_region`]): `k`
/// points of the ellipse of half-axes `rx`, `ry` about `centre` in the plane
/// `z = centre[2]`, its radius modulated by `1 + wobble sin 3a` (an
/// irregular outline for `wobble > 0`).
pub fn drawn_ellipse(centre: [f64; 3], rx: f64, ry: f64, k: usize, wobble: f64) -> Vec<[f64; 3]> {
    (0..k)
        .map(|i| {
            let a = 2.0 * PI * i as f64 / k as f64;
            let r = 1.0 + wobble * (3.0 * a).sin();
            [
                centre[0] + rx * r * a.cos(),
                centre[1] + ry * r * a.sin(),
                centre[2],
            ]
        })
        .collect()
}

/// The chest outline of paper 000 Fig 14 on the MakeHuman base body
/// (decimetres), on the side `side` = +1 or -1: 40 points of
/// [`drawn_ellipse`] about `(0.75 side, 3.75, 1.6)`. The demo's chest sculpt
/// draws it plain (`wobble = 0`), the figure irregular (`wobble = 0.12`).
pub fn chest_curve(side: f64, wobble: f64) -> Vec<[f64; 3]> {
    drawn_ellipse([side * 0.75, 3.75, 1.6], 0.6, 0.7, 40, wobble)
}
