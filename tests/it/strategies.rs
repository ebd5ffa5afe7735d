//! Proptest strategies shared by every family's property tests: points,
//! closed planar curves, surfaces and meshes.

#![allow(dead_code)]

use pdesculpt::curve::Fourier3;
use pdesculpt::mesh::Mesh;
use pdesculpt::surface::{tessellate, Revolution, Tessellation};
use proptest::prelude::*;

/// A finite coordinate in `[-r, r]`.
pub fn coord(r: f64) -> impl Strategy<Value = f64> {
    -r..r
}

/// A point in the cube `[-r, r]^3`.
pub fn point3(r: f64) -> impl Strategy<Value = [f64; 3]> {
    (coord(r), coord(r), coord(r)).prop_map(|(x, y, z)| [x, y, z])
}

/// A star-shaped closed curve in the plane z = `z`: an ellipse with radii in
/// [0.5, 2] plus up to `n` small harmonics (non-self-intersecting).
pub fn star_curve(n: usize, z: f64) -> impl Strategy<Value = Fourier3> {
    (
        0.5f64..2.0,
        0.5f64..2.0,
        prop::collection::vec((-0.05f64..0.05, -0.05f64..0.05), n),
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

/// A tessellated tube of revolution (open in u, closed in v).
pub fn tube_mesh() -> impl Strategy<Value = Mesh> {
    (0.5f64..2.0, -0.4f64..0.4, 3usize..12, 3usize..24)
        .prop_map(|(r0, r1, nu, nv)| tessellate(&Revolution { r0, r1 }, Tessellation { nu, nv }))
}

/// The proptest configuration every property test uses: `cases` cases drawn
/// from a fixed seed, so that `cargo test` and CI draw the same cases on every
/// run. Failures found are persisted under `tests/proptest-regressions/` (commit
/// them) and replayed first.
///
/// Exploration with fresh seeds is a separate command (README, "Exploring"):
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
