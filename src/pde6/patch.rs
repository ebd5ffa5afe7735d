//! PDE6 surface patches (paper 002 eqs 3-5, 14-27): every Fourier
//! coefficient of the cross sections becomes a function of u that solves the
//! harmonic ODE of [`super::mode`] and meets six conditions.

use super::mode::{Condition, ModeBasis, ModeSolver};
use super::Pde6Error;
use crate::curve::Fourier3;
use crate::jet::Real;
use crate::surface::{Domain, Surface};
use std::f64::consts::PI;

/// Coefficient functions of harmonic n: `[k][0]` multiplies `cos n v` in
/// coordinate k, `[k][1]` multiplies `sin n v` (for n = 0 only `[k][0]`).
pub type HarmonicCoef = [[[f64; 6]; 2]; 3];

/// One PDE6 patch on $u \in [0, 1]$, $v \in [0, 2\pi)$:
/// $S(u, v) = \sum_{n=0}^{N} \sum_j \phi^{(n)}_j(u) \left(\mathbf{c}_{nj} \cos nv + \mathbf{s}_{nj} \sin nv\right)$.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Patch {
    /// The PDE parameter a of eq 2.
    pub a: f64,
    /// `basis[n]`, n = 0..=N.
    pub basis: Vec<ModeBasis>,
    /// `coef[n]`.
    pub coef: Vec<HarmonicCoef>,
    /// 1-norm condition number of the worst harmonic's 6x6 solve.
    pub max_condition: f64,
}

/// Checks the curves: finite, and all with the same number of harmonics.
pub fn validate_curves(curves: &[&Fourier3]) -> Result<usize, Pde6Error> {
    let n = curves.first().map_or(0, |c| c.harmonics());
    for (i, c) in curves.iter().enumerate() {
        if !c.is_finite() {
            return Err(Pde6Error::NotFinite(format!("curve {i}")));
        }
        if c.harmonics() != n || c.cos.len() != c.sin.len() {
            return Err(Pde6Error::DifferentHarmonics {
                index: i,
                expected: n,
                found: c.harmonics(),
            });
        }
    }
    Ok(n)
}

impl Patch {
    /// The patch that meets `conditions[i]` with the data curve `data[i]`
    /// (a section, or a u-derivative of one, as a Fourier series in v).
    pub fn solve(
        a: f64,
        conditions: [Condition; 6],
        data: [&Fourier3; 6],
    ) -> Result<Patch, Pde6Error> {
        super::validate_a(a)?;
        let big_n = validate_curves(&data)?;
        let mut basis = Vec::with_capacity(big_n + 1);
        let mut coef = Vec::with_capacity(big_n + 1);
        let mut max_condition: f64 = 0.0;
        for n in 0..=big_n {
            let s = ModeSolver::new(ModeBasis::new(a, n), conditions)?;
            max_condition = max_condition.max(s.condition_number);
            let mut c: HarmonicCoef = [[[0.0; 6]; 2]; 3];
            for (k, ck) in c.iter_mut().enumerate() {
                let mut rc = [0.0; 6];
                let mut rs = [0.0; 6];
                for i in 0..6 {
                    let (x, y) = data[i].harmonic(n, k);
                    rc[i] = x;
                    rs[i] = y;
                }
                ck[0] = s.solve(rc);
                if n > 0 {
                    ck[1] = s.solve(rs);
                }
            }
            basis.push(s.basis);
            coef.push(c);
        }
        Ok(Patch {
            a,
            basis,
            coef,
            max_condition,
        })
    }

    /// Method 1 (eqs 15-23): the patch through six curves at local
    /// parameters `nodes` (the paper: 0, 0.2, ..., 1).
    pub fn through_curves(
        a: f64,
        curves: [&Fourier3; 6],
        nodes: [f64; 6],
    ) -> Result<Patch, Pde6Error> {
        check_nodes(&nodes)?;
        Patch::solve(a, nodes.map(Condition::Value), curves)
    }

    /// Method 2 (eqs 24-27, appendix B): through four curves at local
    /// `nodes` (the paper: 0, 1/3, 2/3, 1) with the u-slope and u-curvature
    /// sections `slope`, `curvature` imposed at the end `join` (0 or 1).
    pub fn carried_over(
        a: f64,
        curves: [&Fourier3; 4],
        nodes: [f64; 4],
        join: f64,
        slope: &Fourier3,
        curvature: &Fourier3,
    ) -> Result<Patch, Pde6Error> {
        check_nodes(&nodes)?;
        let conditions = [
            Condition::Value(nodes[0]),
            Condition::Value(nodes[1]),
            Condition::Value(nodes[2]),
            Condition::Value(nodes[3]),
            Condition::Slope(join),
            Condition::Curvature(join),
        ];
        let [c0, c1, c2, c3] = curves;
        Patch::solve(a, conditions, [c0, c1, c2, c3, slope, curvature])
    }

    /// Number of harmonics N.
    pub fn harmonics(&self) -> usize {
        self.coef.len().saturating_sub(1)
    }

    /// Number of stored coefficients (the data size of the patch).
    pub fn coefficient_count(&self) -> usize {
        // 3 coordinates x 6 for n = 0, 3 x 2 x 6 per harmonic
        18 + 36 * self.harmonics()
    }

    /// The d-th u-derivative (d <= 2) of the section at local `u`, as a
    /// Fourier series in v.
    pub fn section(&self, u: f64, d: usize) -> Fourier3 {
        let big_n = self.harmonics();
        let mut f = Fourier3 {
            c0: [0.0; 3],
            cos: vec![[0.0; 3]; big_n],
            sin: vec![[0.0; 3]; big_n],
        };
        for n in 0..=big_n {
            let b = self.basis[n].jet2(u)[d.min(2)];
            for k in 0..3 {
                let dot = |c: &[f64; 6]| (0..6).map(|j| c[j] * b[j]).sum::<f64>();
                let (x, y) = (dot(&self.coef[n][k][0]), dot(&self.coef[n][k][1]));
                if n == 0 {
                    f.c0[k] = x;
                } else {
                    f.cos[n - 1][k] = x;
                    f.sin[n - 1][k] = y;
                }
            }
        }
        f
    }

    /// Fast tensor-product evaluation on `us x vs` (row-major in u), local u.
    pub fn grid_local(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let big_n = self.harmonics();
        // trig[iv][n] = (cos n v, sin n v)
        let trig: Vec<Vec<(f64, f64)>> = vs
            .iter()
            .map(|&v| {
                (0..=big_n)
                    .map(|n| ((n as f64 * v).cos(), (n as f64 * v).sin()))
                    .collect()
            })
            .collect();
        let mut out = Vec::with_capacity(us.len() * vs.len());
        let mut amp = vec![[[0.0; 2]; 3]; big_n + 1];
        for &u in us {
            for n in 0..=big_n {
                let b: [f64; 6] = self.basis[n].eval(u);
                for k in 0..3 {
                    for cs in 0..2 {
                        let c = &self.coef[n][k][cs];
                        amp[n][k][cs] = c[0] * b[0]
                            + c[1] * b[1]
                            + c[2] * b[2]
                            + c[3] * b[3]
                            + c[4] * b[4]
                            + c[5] * b[5];
                    }
                }
            }
            for t in &trig {
                let mut p = [0.0; 3];
                for n in 0..=big_n {
                    let (c, s) = t[n];
                    for k in 0..3 {
                        p[k] += amp[n][k][0] * c + amp[n][k][1] * s;
                    }
                }
                out.push(p);
            }
        }
        out
    }
}

fn check_nodes(nodes: &[f64]) -> Result<(), Pde6Error> {
    for (i, w) in nodes.windows(2).enumerate() {
        if w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater) {
            return Err(Pde6Error::NonIncreasing {
                index: i + 1,
                previous: w[0],
                next: w[1],
            });
        }
    }
    if nodes.iter().any(|x| !x.is_finite()) {
        return Err(Pde6Error::NotFinite("u positions".into()));
    }
    Ok(())
}

impl Surface for Patch {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let mut p = [T::zero(); 3];
        for (n, (b, c)) in self.basis.iter().zip(&self.coef).enumerate() {
            let phi = b.eval(u);
            let (cn, sn) = if n == 0 {
                (T::one(), T::zero())
            } else {
                ((v * n as f64).cos(), (v * n as f64).sin())
            };
            for k in 0..3 {
                let mut ac = T::zero();
                let mut as_ = T::zero();
                for j in 0..6 {
                    ac += phi[j] * c[k][0][j];
                    as_ += phi[j] * c[k][1][j];
                }
                p[k] += ac * cn + as_ * sn;
            }
        }
        p
    }

    fn domain(&self) -> Domain {
        Domain {
            u: (0.0, 1.0),
            v: (0.0, 2.0 * PI),
            closed_u: false,
            closed_v: true,
        }
    }

    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        self.grid_local(us, vs)
    }
}

#[cfg(test)]
mod tests {
    //! Input validation, here so that the mutation oracle (the library's
    //! unit tests plus `verify`) sees it (`scripts/mutants.sh`).
    use super::*;

    fn circle(harmonics: usize) -> Fourier3 {
        Fourier3 {
            c0: [0.0; 3],
            cos: vec![[1.0, 0.0, 0.0]; harmonics],
            sin: vec![[0.0, 1.0, 0.0]; harmonics],
        }
    }

    #[test]
    fn curves_with_different_harmonic_counts_are_refused_by_index() {
        let (a, b) = (circle(2), circle(3));
        assert!(matches!(validate_curves(&[&a, &a]), Ok(2)));
        // equal cos and sin lengths, a different count: refused
        let e = validate_curves(&[&a, &b]);
        assert!(
            matches!(
                e,
                Err(Pde6Error::DifferentHarmonics {
                    index: 1,
                    expected: 2,
                    found: 3
                })
            ),
            "{e:?}"
        );
        // the same count, cos and sin of different lengths: refused
        let mut c = circle(2);
        c.sin.pop();
        let e = validate_curves(&[&a, &c]);
        assert!(
            matches!(e, Err(Pde6Error::DifferentHarmonics { index: 1, .. })),
            "{e:?}"
        );
    }

    #[test]
    fn the_data_size_counts_six_coefficients_per_coordinate_and_term() {
        // a patch of N harmonics stores 6 coefficients per coordinate for
        // n = 0 and for each of cos and sin of n = 1..N
        let sections = crate::pde6::samples::synthetic_sections(12, 3);
        let chain = crate::pde6::Chain::method2(-0.5, &sections, 0).expect("chain");
        let patch = &chain.pieces[0].patch;
        assert_eq!(patch.harmonics(), 3);
        assert_eq!(patch.coefficient_count(), 6 * 3 * (1 + 2 * 3));
    }

    #[test]
    fn the_patch_grid_equals_its_pointwise_evaluation() {
        // the Surface trait's grid (tessellation, meshes) takes the fast
        // path grid_local: it must be the patch, point for point
        let sections = crate::pde6::samples::synthetic_sections(12, 3);
        let chain = crate::pde6::Chain::method2(-0.5, &sections, 0).expect("chain");
        let patch = &chain.pieces[0].patch;
        let us = [0.0, 0.3, 0.75, 1.0];
        let vs = [0.0, 1.0, 2.5, 6.0];
        let g = Surface::grid(patch, &us, &vs);
        assert_eq!(g.len(), us.len() * vs.len());
        let size =
            crate::check::tol::SOLVE * g.iter().map(|p| crate::vec3::norm(*p)).fold(1.0, f64::max);
        for (i, &u) in us.iter().enumerate() {
            for (j, &v) in vs.iter().enumerate() {
                let d = crate::vec3::dist(g[i * vs.len() + j], patch.point(u, v));
                assert!(d <= size, "({u}, {v}): {d}");
            }
        }
    }

    #[test]
    fn a_non_increasing_node_is_named_by_its_index() {
        assert!(check_nodes(&[0.0, 0.5, 1.0]).is_ok());
        let e = check_nodes(&[0.0, 0.5, 0.5, 1.0]);
        assert!(
            matches!(e, Err(Pde6Error::NonIncreasing { index: 2, .. })),
            "{e:?}"
        );
        let e = check_nodes(&[0.0, f64::NAN]);
        assert!(
            matches!(e, Err(Pde6Error::NonIncreasing { index: 1, .. })),
            "{e:?}"
        );
    }
}
