//! The 12-section, 3-patch chain of paper 002 Fig 4 with N = 10 harmonics,
//! solved (method 2: 6x6 solves harmonic by harmonic, one factorisation per
//! harmonic) and tessellated (fast tensor-product grid), against a generic
//! dense solve of the same interpolation problem (all 3 x 6 x 3 x (2N + 1) =
//! 1134 unknowns in one LU) followed by point-by-point generic evaluation.

use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{DMatrix, DVector};
use pdesculpt::curve::Fourier3;
use pdesculpt::pde6::mode::ModeBasis;
use pdesculpt::pde6::samples::synthetic_sections;
use pdesculpt::pde6::{Chain, Method, Patch, Piece, Section};
use pdesculpt::surface::{tessellate, tessellate_grid, Surface, Tessellation};
use std::hint::black_box;

const A: f64 = -0.5;
/// The closed form and the dense LU agree to a dense solve's rounding,
/// amplified by the 1134-unknown system's conditioning.
const AGREE: f64 = 10.0 * pdesculpt::check::tol::SOLVE;
const N: usize = 10;
const TESS: Tessellation = Tessellation { nu: 48, nv: 64 };

/// Row of the basis values (d-th derivative) at local u.
fn row(b: &ModeBasis, u: f64, d: usize) -> [f64; 6] {
    b.jet2(u)[d]
}

/// The method-2 conditions of the Fig 4 chain (patch 1 through sections
/// 3..=8, patch 2 through 0..=3 with slope/curvature of patch 1 at its start,
/// patch 3 through 8..=11 with those at its end), every harmonic and
/// coordinate, as one dense system.
fn dense_chain(s: &[Section]) -> Chain {
    let blocks: Vec<(usize, usize, usize)> = (0..=N)
        .flat_map(|n| {
            (0..3).flat_map(move |k| (0..if n == 0 { 1 } else { 2 }).map(move |cs| (n, k, cs)))
        })
        .collect();
    let size = 18 * blocks.len();
    let mut m = DMatrix::<f64>::zeros(size, size);
    let mut rhs = DVector::<f64>::zeros(size);
    let geo = [
        (s[0].u, s[3].u - s[0].u, 0usize),
        (s[3].u, s[8].u - s[3].u, 3),
        (s[8].u, s[11].u - s[8].u, 8),
    ];
    let pick = |f: &Fourier3, n: usize, k: usize, cs: usize| {
        let (x, y) = f.harmonic(n, k);
        if cs == 0 {
            x
        } else {
            y
        }
    };
    for (bi, &(n, k, cs)) in blocks.iter().enumerate() {
        let b = ModeBasis::new(A, n);
        let o = 18 * bi;
        let mut r = o;
        // patch 1 (middle, columns o+6..o+12): six values
        for i in 0..6 {
            let t = (s[3 + i].u - geo[1].0) / geo[1].1;
            m.view_mut((r, o + 6), (1, 6))
                .copy_from_slice(&row(&b, t, 0));
            rhs[r] = pick(&s[3 + i].curve, n, k, cs);
            r += 1;
        }
        // patch 2 (columns o..o+6) and patch 3 (columns o+12..o+18): four values
        for (p, first) in [(0usize, 0usize), (2, 8)] {
            for i in 0..4 {
                let t = (s[first + i].u - geo[p].0) / geo[p].1;
                m.view_mut((r, o + 6 * p), (1, 6))
                    .copy_from_slice(&row(&b, t, 0));
                rhs[r] = pick(&s[first + i].curve, n, k, cs);
                r += 1;
            }
        }
        // C1, C2 at both joins (global u)
        for (left, right) in [(0usize, 1usize), (1, 2)] {
            for d in 1..=2 {
                let (ra, rb) = (row(&b, 1.0, d), row(&b, 0.0, d));
                for j in 0..6 {
                    m[(r, o + 6 * left + j)] = ra[j] / geo[left].1.powi(d as i32);
                    m[(r, o + 6 * right + j)] = -rb[j] / geo[right].1.powi(d as i32);
                }
                r += 1;
            }
        }
    }
    let x = m.lu().solve(&rhs).expect("dense system is regular");
    let basis: Vec<ModeBasis> = (0..=N).map(|n| ModeBasis::new(A, n)).collect();
    let mut pieces: Vec<Piece> = Vec::new();
    for (p, &(origin, length, _)) in geo.iter().enumerate() {
        let mut piece = Piece {
            patch: Patch {
                a: A,
                basis: basis.clone(),
                coef: vec![[[[0.0; 6]; 2]; 3]; N + 1],
                max_condition: 0.0,
            },
            origin,
            length,
            start: origin,
            end: origin + length,
        };
        for (bi, &(n, k, cs)) in blocks.iter().enumerate() {
            for j in 0..6 {
                piece.patch.coef[n][k][cs][j] = x[18 * bi + 6 * p + j];
            }
        }
        pieces.push(piece);
    }
    Chain {
        method: Method::CarriedDerivatives,
        pieces,
    }
}

/// Tessellation with the generic point-by-point evaluation.
fn tessellate_generic(c: &Chain) -> pdesculpt::mesh::Mesh {
    let d = c.domain();
    let us: Vec<f64> = (0..=TESS.nu)
        .map(|i| d.u.0 + (d.u.1 - d.u.0) * i as f64 / TESS.nu as f64)
        .collect();
    let vs: Vec<f64> = (0..TESS.nv)
        .map(|j| d.v.1 * j as f64 / TESS.nv as f64)
        .collect();
    let pts: Vec<[f64; 3]> = us
        .iter()
        .flat_map(|&u| vs.iter().map(move |&v| c.point(u, v)))
        .collect();
    tessellate_grid(pts, us.len(), vs.len(), d)
}

fn bench(c: &mut Criterion) {
    let s = synthetic_sections(12, N);
    // the two constructions agree
    let fast = Chain::method2(A, &s, 3).expect("chain");
    let dense = dense_chain(&s);
    let (mf, md) = (tessellate(&fast, TESS), tessellate_generic(&dense));
    let diff = mf
        .positions
        .iter()
        .zip(&md.positions)
        .map(|(a, b)| pdesculpt::mesh::dist(*a, *b))
        .fold(0.0, f64::max);
    assert!(
        diff < AGREE,
        "closed-form and dense chains differ by {diff}"
    );
    let mut g = c.benchmark_group("pde6_fig4_chain_n10");
    g.sample_size(10);
    g.bench_function("closed_form_6x6_and_fast_grid", |b| {
        b.iter(|| {
            let ch = Chain::method2(A, black_box(&s), 3).expect("chain");
            black_box(tessellate(&ch, TESS))
        })
    });
    g.bench_function("dense_1134_and_generic_eval", |b| {
        b.iter(|| {
            let ch = dense_chain(black_box(&s));
            black_box(tessellate_generic(&ch))
        })
    });
    g.bench_function("solve_only_closed_form", |b| {
        b.iter(|| black_box(Chain::method2(A, black_box(&s), 3)))
    });
    g.bench_function("solve_only_dense", |b| {
        b.iter(|| black_box(dense_chain(black_box(&s))))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
