//! An independent reference solver for the clamped 4-sided problem: the
//! standard 13-point finite-difference stencil of
//! $a_1 t_{uuuu} + a_2 t_{uuvv} + a_3 t_{vvvv} = P$ on an $N \times N$ grid of
//! the unit square, clamped through mirrored ghost nodes ($t = 0$ on the
//! edge, $t_{-1} = t_1$ so the central first difference vanishes), solved with
//! a sparse Cholesky factorisation (faer). The scheme is second order, so two
//! grids give a Richardson-extrapolated value $(4 t_{h/2} - t_h)/3$.
//!
//! It shares nothing with the Galerkin solver (no basis, no quadrature, no
//! dense solve), which makes it a reference for loads that have no trusted
//! published plate value (the sinusoidal load on a clamped plate). Its own
//! accuracy is checked against the published uniform-load value
//! (`pde4.four_sided.fd_reference_uniform`).

use super::{Pde4Error, ShapeParams};
use faer::prelude::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::Side;

/// Centre value `t(1/2, 1/2)` of the FD solution on an `n x n` grid (`n`
/// even, `n >= 4`) for the load `p(u, v)` sampled at the nodes.
pub fn fd_centre(
    params: ShapeParams,
    n: usize,
    load: impl Fn(f64, f64) -> f64,
) -> Result<f64, Pde4Error> {
    params.validate()?;
    if n < 4 || n % 2 == 1 || n > 1024 {
        return Err(Pde4Error::Solve {
            system: "FD grid",
            reason: format!("n = {n} must be even and in 4..=1024"),
        });
    }
    let h = 1.0 / n as f64;
    // multiplied out, as `plate_ratio`'s rho^4: the same bits in every build
    let h4 = (h * h) * (h * h);
    let m = n - 1; // interior nodes per direction, indices 1..=m
    let id = |i: usize, j: usize| (i - 1) * m + (j - 1);
    // node index after the clamped ghost mirror: 0 and n are zero, -1 -> 1, n+1 -> n-1
    let fold = |k: isize| -> Option<usize> {
        let k = if k == -1 {
            1
        } else if k == n as isize + 1 {
            n as isize - 1
        } else {
            k
        };
        (k >= 1 && k <= m as isize).then_some(k as usize)
    };
    let d4 = [1.0, -4.0, 6.0, -4.0, 1.0];
    let d2 = [1.0, -2.0, 1.0];
    let mut trip = Vec::with_capacity(m * m * 13);
    let mut rhs = faer::Mat::<f64>::zeros(m * m, 1);
    for i in 1..=m {
        for j in 1..=m {
            let row = id(i, j);
            rhs[(row, 0)] = load(i as f64 * h, j as f64 * h);
            for (k, c) in d4.iter().enumerate() {
                let di = k as isize - 2;
                if let Some(ii) = fold(i as isize + di) {
                    trip.push(Triplet::new(row, id(ii, j), params.a1 * c / h4));
                }
                if let Some(jj) = fold(j as isize + di) {
                    trip.push(Triplet::new(row, id(i, jj), params.a3 * c / h4));
                }
            }
            for (ki, ci) in d2.iter().enumerate() {
                for (kj, cj) in d2.iter().enumerate() {
                    let (ii, jj) = (i + ki, j + kj); // offset by one
                    if ii >= 2 && ii <= m + 1 && jj >= 2 && jj <= m + 1 {
                        trip.push(Triplet::new(
                            row,
                            id(ii - 1, jj - 1),
                            params.a2 * ci * cj / h4,
                        ));
                    }
                }
            }
        }
    }
    let k =
        SparseColMat::<usize, f64>::try_new_from_triplets(m * m, m * m, &trip).map_err(|e| {
            Pde4Error::Solve {
                system: "FD matrix",
                reason: format!("{e:?}"),
            }
        })?;
    let llt = k.sp_cholesky(Side::Lower).map_err(|e| Pde4Error::Solve {
        system: "FD Cholesky",
        reason: format!("{e:?}"),
    })?;
    llt.solve_in_place(rhs.as_mut());
    let c = rhs[(id(n / 2, n / 2), 0)];
    if !c.is_finite() {
        return Err(Pde4Error::Solve {
            system: "FD solve",
            reason: "the solution is not finite".into(),
        });
    }
    Ok(c)
}

/// Richardson extrapolation of [`fd_centre`] on grids `n` and `2n`:
/// `(extrapolated, coarse, fine)`.
pub fn fd_centre_extrapolated(
    params: ShapeParams,
    n: usize,
    load: impl Fn(f64, f64) -> f64 + Copy,
) -> Result<(f64, f64, f64), Pde4Error> {
    let coarse = fd_centre(params, n, load)?;
    let fine = fd_centre(params, 2 * n, load)?;
    Ok(((4.0 * fine - coarse) / 3.0, coarse, fine))
}
