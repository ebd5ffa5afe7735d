//! ODE surface patches (eq 19), chains of patches in u (eqs 23-25) and
//! splits in v (eq 26).
//!
//! A patch is $S(u,v) = S_p(u) + \sum_m h_m(u) K_m(v) - \sum_j g_j(u) p_j$
//! with $h_m = \sum_j g_j W_{jm}$ (see [`super::boundary`]) and $p_j$ the
//! constraint values of the particular solution ($S_p = 0$ without force).
//! The grid evaluator precomputes $h_m(u_i)$ and $K_m(v_k)$ once: a grid costs
//! $O(n_u n_v n_{keys})$ multiply-adds, no solve per iso-parametric line.
//!
//! A [`Chain`] joins patches end to end in $u$: patch $i$ takes the position,
//! first and second derivative curves of section $i$ at $u=0$ and of section
//! $i+1$ at $u=1$, so positions, tangents and curvatures agree across every
//! join whatever the shape parameters of each patch (eqs 23-25). In $v$ two
//! patches cut from the same C2 curves at $v^*$ join C2 only if their
//! $g_j$ agree, i.e. if their shape parameters are equal (eq 26).

use super::force::Particular;
use super::{Basis, BoundaryCurves, Curve, Force, Ode6Error};
use crate::check::Worst;
use crate::jet::{Jet, Real};
use crate::surface::{Domain, Joined, Surface};

/// One ODE surface patch.
#[derive(Clone, Debug)]
pub struct Ode6Surface {
    pub basis: Basis,
    pub curves: BoundaryCurves,
    pub particular: Option<Particular>,
    /// The range of `v` the patch covers (a split of the curves).
    pub v_range: (f64, f64),
}

impl Ode6Surface {
    /// The complementary-solution patch of eq 19.
    pub fn new(basis: Basis, curves: BoundaryCurves) -> Ode6Surface {
        Ode6Surface {
            basis,
            curves,
            particular: None,
            v_range: (0.0, 1.0),
        }
    }

    /// Adds a sculpting force (eq 2 with `F != 0`).
    pub fn with_force(mut self, force: &Force) -> Result<Ode6Surface, Ode6Error> {
        self.particular = Some(Particular::new(self.basis.params, force)?);
        Ok(self)
    }

    /// The patch restricted to `v in [v0, v1]` (a split in `v`, eq 26).
    pub fn with_v_range(mut self, v0: f64, v1: f64) -> Result<Ode6Surface, Ode6Error> {
        if !(v0.is_finite() && v1.is_finite() && 0.0 <= v0 && v0 < v1 && v1 <= 1.0) {
            return Err(Ode6Error::VRange { v0, v1 });
        }
        self.v_range = (v0, v1);
        Ok(self)
    }

    /// Constraint values `p_j` of the particular solution.
    fn particular_constraints(&self) -> Option<[[f64; 3]; 6]> {
        let p = self.particular.as_ref()?;
        let a = p.eval(Jet::<3, 1>::var_u(0.0));
        let b = p.eval(Jet::<3, 1>::var_u(1.0));
        let mut out = [[0.0; 3]; 6];
        for i in 0..3 {
            for k in 0..3 {
                out[i][k] = a[k].deriv(i, 0);
                out[3 + i][k] = b[k].deriv(i, 0);
            }
        }
        Some(out)
    }

    /// `h_m(u)` for every key.
    fn h<T: Real>(&self, u: T) -> (Vec<T>, [T; 6]) {
        let g = self.basis.g(u);
        let h = self
            .curves
            .weights
            .iter()
            .map(|w| {
                let mut acc = T::zero();
                for j in 0..6 {
                    if w[j] != 0.0 {
                        acc += g[j] * w[j];
                    }
                }
                acc
            })
            .collect();
        (h, g)
    }

    /// Number of scalars stored by the representation (keys + 3 parameters).
    pub fn scalars(&self) -> usize {
        self.curves.keys.iter().map(Curve::scalars).sum::<usize>() + 3
    }
}

impl Surface for Ode6Surface {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let (h, g) = self.h(u);
        let mut p = [T::zero(); 3];
        for (key, hm) in self.curves.keys.iter().zip(&h) {
            let k = key.eval(v);
            for d in 0..3 {
                p[d] += *hm * k[d];
            }
        }
        if let (Some(part), Some(pc)) = (&self.particular, self.particular_constraints()) {
            let sp = part.eval(u);
            for d in 0..3 {
                p[d] += sp[d];
                for j in 0..6 {
                    p[d] -= g[j] * pc[j][d];
                }
            }
        }
        p
    }

    fn domain(&self) -> Domain {
        Domain {
            u: (0.0, 1.0),
            v: self.v_range,
            closed_u: false,
            closed_v: self.curves.closed() && self.v_range == (0.0, 1.0),
        }
    }

    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let nk = self.curves.keys.len();
        let kv: Vec<Vec<[f64; 3]>> = self
            .curves
            .keys
            .iter()
            .map(|k| vs.iter().map(|&v| k.eval(v)).collect())
            .collect();
        let pc = self.particular_constraints();
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &u in us {
            let (h, g) = self.h(u);
            let mut offset = [0.0; 3];
            if let (Some(part), Some(pc)) = (&self.particular, pc) {
                offset = part.eval(u);
                for d in 0..3 {
                    for j in 0..6 {
                        offset[d] -= g[j] * pc[j][d];
                    }
                }
            }
            for iv in 0..vs.len() {
                let mut p = offset;
                for m in 0..nk {
                    let k = kv[m][iv];
                    p[0] += h[m] * k[0];
                    p[1] += h[m] * k[1];
                    p[2] += h[m] * k[2];
                }
                out.push(p);
            }
        }
        out
    }
}

/// Patches joined end to end in `u` over global `u in [0, n]`.
#[derive(Clone, Debug)]
pub struct Chain {
    pub patches: Vec<Ode6Surface>,
}

impl Chain {
    /// `sections[i] = [position, first, second derivative]` curves; patch
    /// `i` spans sections `i` and `i+1` with basis `bases[i]`.
    pub fn from_sections(sections: &[[Curve; 3]], bases: Vec<Basis>) -> Result<Chain, Ode6Error> {
        if sections.len() < 2 || bases.len() + 1 != sections.len() {
            return Err(Ode6Error::ChainShape {
                sections: sections.len(),
                params: bases.len(),
            });
        }
        let patches = bases
            .into_iter()
            .enumerate()
            .map(|(i, b)| {
                let [a0, a1, a2] = sections[i].clone();
                let [b0, b1, b2] = sections[i + 1].clone();
                Ok(Ode6Surface::new(
                    b,
                    BoundaryCurves::direct([a0, a1, a2, b0, b1, b2])?,
                ))
            })
            .collect::<Result<Vec<_>, Ode6Error>>()?;
        Ok(Chain { patches })
    }
}

/// Jumps `[position, first, second]` of `d^i S/du^i` across every join,
/// maximised over `nv` samples of `v`.
impl Joined for Chain {
    type Jumps = [f64; 3];

    fn join_jumps(&self, nv: usize) -> [f64; 3] {
        let nv = nv.max(1);
        let mut out = [0.0f64; 3];
        for w in self.patches.windows(2) {
            for iv in 0..nv {
                let v = (iv as f64 + 0.5) / nv as f64;
                for i in 0..3 {
                    let a = w[0].derivative(1.0, v, i, 0);
                    let b = w[1].derivative(0.0, v, i, 0);
                    out[i] = out[i].worst(crate::mesh::dist(a, b));
                }
            }
        }
        out
    }
}

impl Surface for Chain {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let n = self.patches.len();
        let i = (u.value().floor().max(0.0) as usize).min(n - 1);
        self.patches[i].eval(u - i as f64, v)
    }

    fn domain(&self) -> Domain {
        let d = self.patches[0].domain();
        Domain {
            u: (0.0, self.patches.len() as f64),
            ..d
        }
    }

    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let n = self.patches.len();
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &u in us {
            let i = (u.floor().max(0.0) as usize).min(n - 1);
            out.extend(self.patches[i].grid(&[u - i as f64], vs));
        }
        out
    }
}

/// Two patches adjacent in `v`: `below` ends at `v*`, `above` starts there
/// (Fig 6b's split of one patch between two parameter sets).
#[derive(Clone, Copy, Debug)]
pub struct VSplit<'a> {
    pub below: &'a Ode6Surface,
    pub above: &'a Ode6Surface,
}

/// Jumps `[position, first, second]` of `d^j S/dv^j` across the join,
/// maximised over `nu + 1` samples of `u`.
impl Joined for VSplit<'_> {
    type Jumps = [f64; 3];

    fn join_jumps(&self, nu: usize) -> [f64; 3] {
        let (a, b) = (self.below, self.above);
        let nu = nu.max(1);
        let v = a.v_range.1;
        let mut out = [0.0f64; 3];
        for iu in 0..=nu {
            let u = iu as f64 / nu as f64;
            for j in 0..3 {
                let pa = a.derivative(u, v, 0, j);
                let pb = b.derivative(u, b.v_range.0, 0, j);
                out[j] = out[j].worst(crate::mesh::dist(pa, pb));
            }
        }
        out
    }
}

/// Curve data at a knot in `v`: `[P, P_v, P_vv]`.
pub type Knot = [[f64; 3]; 3];

/// A grid of patches, C2 in `u` and in `v`: `patches[i][r]` spans sections
/// `i`, `i + 1` in `u` and knots `r`, `r + 1` in `v`, each with its own six
/// constraint curves (quintic Hermite segments, see [`Grid::from_knots`]).
#[derive(Clone, Debug)]
pub struct Grid {
    pub patches: Vec<Vec<Ode6Surface>>,
}

/// Largest jumps of `d^j S/du^j` across the u-joins and of `d^j S/dv^j`
/// across the v-joins of a [`Grid`], `j = 0, 1, 2`, and the largest
/// magnitudes of those derivatives at the joins (so a check can tell a
/// continuous join from a vacuous one).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct GridJumps {
    pub u: [f64; 3],
    pub v: [f64; 3],
    pub u_magnitude: [f64; 3],
    pub v_magnitude: [f64; 3],
}

impl GridJumps {
    /// `max_j jump_j / magnitude_j` over both directions; infinite when a
    /// magnitude is below `floor` (the join would be vacuous), NaN when any
    /// entry is NaN.
    pub fn relative(&self, floor: f64) -> f64 {
        let mut out = 0.0f64;
        for (j, m) in self
            .u
            .iter()
            .zip(&self.u_magnitude)
            .chain(self.v.iter().zip(&self.v_magnitude))
        {
            if j.is_nan() || m.is_nan() {
                return f64::NAN;
            }
            if *m < floor {
                return f64::INFINITY;
            }
            out = out.max(j / m);
        }
        out
    }
}

impl Grid {
    /// `knots[s][k][t]`: constraint curve `k` (0: position, 1: first, 2:
    /// second u-derivative) of section `s` at v-knot `t`, as `[P, P_v,
    /// P_vv]` per unit of a row's own parameter. Patch `(i, r)` takes the
    /// Hermite segments between knots `r` and `r + 1` of sections `i` and
    /// `i + 1` and the basis `bases[i]` (one set of shape parameters per
    /// column: eq 26 needs equal `g_k` across a v-join).
    pub fn from_knots(knots: &[[Vec<Knot>; 3]], bases: Vec<Basis>) -> Result<Grid, Ode6Error> {
        let nt = knots.first().map(|s| s[0].len()).unwrap_or(0);
        if knots.len() < 2 || bases.len() + 1 != knots.len() || nt < 2 {
            return Err(Ode6Error::GridShape {
                sections: knots.len(),
                params: bases.len(),
                knots: nt,
            });
        }
        if knots.iter().flatten().any(|k| k.len() != nt) {
            return Err(Ode6Error::UnequalKnots);
        }
        let seg = |s: usize, k: usize, r: usize| Curve::hermite(knots[s][k][r], knots[s][k][r + 1]);
        let patches = bases
            .into_iter()
            .enumerate()
            .map(|(i, b)| {
                (0..nt - 1)
                    .map(|r| {
                        let curves = BoundaryCurves::direct([
                            seg(i, 0, r)?,
                            seg(i, 1, r)?,
                            seg(i, 2, r)?,
                            seg(i + 1, 0, r)?,
                            seg(i + 1, 1, r)?,
                            seg(i + 1, 2, r)?,
                        ])?;
                        Ok(Ode6Surface::new(b.clone(), curves))
                    })
                    .collect::<Result<Vec<_>, Ode6Error>>()
            })
            .collect::<Result<Vec<_>, Ode6Error>>()?;
        Ok(Grid { patches })
    }
}

/// Jumps across every u-join and v-join, `n + 1` samples along each.
impl Joined for Grid {
    type Jumps = GridJumps;

    fn join_jumps(&self, n: usize) -> GridJumps {
        let mut j = GridJumps {
            u: [0.0; 3],
            v: [0.0; 3],
            u_magnitude: [0.0; 3],
            v_magnitude: [0.0; 3],
        };
        let n = n.max(1);
        for (i, col) in self.patches.iter().enumerate() {
            for (r, p) in col.iter().enumerate() {
                for s in 0..=n {
                    let t = s as f64 / n as f64;
                    for d in 0..3 {
                        if let Some(q) = self.patches.get(i + 1).and_then(|c| c.get(r)) {
                            let (a, b) = (p.derivative(1.0, t, d, 0), q.derivative(0.0, t, d, 0));
                            j.u[d] = j.u[d].worst(crate::mesh::dist(a, b));
                            j.u_magnitude[d] = j.u_magnitude[d].worst(crate::mesh::norm(a));
                        }
                        if let Some(q) = col.get(r + 1) {
                            let (a, b) = (p.derivative(t, 1.0, 0, d), q.derivative(t, 0.0, 0, d));
                            j.v[d] = j.v[d].worst(crate::mesh::dist(a, b));
                            j.v_magnitude[d] = j.v_magnitude[d].worst(crate::mesh::norm(a));
                        }
                    }
                }
            }
        }
        j
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::tol;

    #[test]
    fn zero_join_samples_still_measure_a_broken_join() {
        // two pieces of one patch that do not meet: with `samples = 0` the
        // measurement must still see the jump, not report a perfect join
        let p = crate::ode6::samples::patch().expect("sample patch");
        let chain = Chain {
            patches: vec![p.clone(), p.clone()],
        };
        let below = p.clone().with_v_range(0.0, 0.3).expect("v range");
        let above = p.with_v_range(0.6, 1.0).expect("v range");
        let split = VSplit {
            below: &below,
            above: &above,
        };
        for jumps in [chain.join_jumps(0), split.join_jumps(0)] {
            assert!(jumps[0] > tol::DETECTED, "{jumps:?}");
        }
    }
}
