//! Particular solutions of eq 2 for a sculpting force $F(u)$ (the paper
//! leaves them to future work).
//!
//! **Polynomial** $F = \sum_k \mathbf f_k u^k$: let $m \in \{2, 4, 6\}$ be the
//! lowest derivative order with a non-zero parameter ($\lambda$, else $\eta$,
//! else $\rho$) and $P = S_p^{(m)}$. Then $a_0 P + a_1 P'' + a_2 P'''' = F$
//! with $a_0 \ne 0$ is solved for a polynomial $P$ of the degree of $F$ from
//! the top coefficient down,
//! $p_n = \big(f_n - a_1 (n+2)(n+1) p_{n+2} - a_2 (n+4)(n+3)(n+2)(n+1) p_{n+4}\big)/a_0$,
//! and $S_p$ is $P$ integrated $m$ times (zero constants).
//!
//! **Sine** $F = \mathbf A \sin(\kappa u + \varphi)$: $S_p = \mathbf A
//! \sin(\kappa u + \varphi) / \sigma(\kappa)$ with the symbol
//! $\sigma(\kappa) = -\rho\kappa^6 + \eta\kappa^4 - \lambda\kappa^2$; the
//! force resonates where $\sigma = 0$, i.e. where $-\kappa^2$ is a root $q$
//! of eq 13; then, since $L[u f] = u L[f] + L'(D) f$ with
//! $L'(D) = 6\rho D^5 + 4\eta D^3 + 2\lambda D$,
//! $S_p = \mathbf A\, u \cos(\kappa u + \varphi) / \sigma'(\kappa)$ with
//! $\sigma'(\kappa) = -6\rho\kappa^5 + 4\eta\kappa^3 - 2\lambda\kappa$. A double
//! resonance ($\sigma = \sigma' = 0$, a repeated root) and $\kappa = 0$ are
//! named errors.
//!
//! The full solution is $S = S_p + \sum_j g_j (c_j - p_j)$ with $p_j$ the
//! constraint values of $S_p$ ([`super::Ode6Surface::with_force`]).

use super::{Ode6Error, Params};
use crate::jet::Real;

/// Relative size of the symbol below which a sine force resonates.
pub const RESONANCE: f64 = 1e-10;

/// A sculpting force `F(u)`, the same on every iso-parametric line.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Force {
    /// `F(u) = sum_k coef[k] u^k`.
    Polynomial { coef: Vec<[f64; 3]> },
    /// `F(u) = amp sin(kappa u + phase)`.
    Sine {
        amp: [f64; 3],
        kappa: f64,
        phase: f64,
    },
}

impl Force {
    /// `F(u)`.
    pub fn eval<T: Real>(&self, u: T) -> [T; 3] {
        match self {
            Force::Polynomial { coef } => horner(coef, u),
            Force::Sine { amp, kappa, phase } => {
                let s = (u * *kappa + *phase).sin();
                [s * amp[0], s * amp[1], s * amp[2]]
            }
        }
    }
}

fn horner<T: Real>(coef: &[[f64; 3]], u: T) -> [T; 3] {
    let mut p = [T::zero(); 3];
    for c in coef.iter().rev() {
        for k in 0..3 {
            p[k] = p[k] * u + c[k];
        }
    }
    p
}

/// A particular solution `S_p(u)` of eq 2.
#[derive(Clone, Debug, PartialEq)]
pub enum Particular {
    Polynomial {
        coef: Vec<[f64; 3]>,
    },
    Sine {
        amp: [f64; 3],
        kappa: f64,
        phase: f64,
    },
    /// `amp u cos(kappa u + phase)` (a sine force at a simple resonance).
    ResonantSine {
        amp: [f64; 3],
        kappa: f64,
        phase: f64,
    },
}

impl Particular {
    /// Solves for the particular solution of `force` under `params`.
    pub fn new(params: Params, force: &Force) -> Result<Particular, Ode6Error> {
        let Params { rho, eta, lambda } = params;
        if [rho, eta, lambda].iter().all(|x| *x == 0.0) {
            return Err(Ode6Error::AllZero);
        }
        match force {
            Force::Polynomial { coef } => {
                if coef.iter().flatten().any(|x| !x.is_finite()) {
                    return Err(Ode6Error::NotFinite {
                        what: "a polynomial force coefficient",
                    });
                }
                let (m, a) = if lambda != 0.0 {
                    (2, [lambda, eta, rho])
                } else if eta != 0.0 {
                    (4, [eta, rho, 0.0])
                } else {
                    (6, [rho, 0.0, 0.0])
                };
                let deg = coef.len();
                let mut p = vec![[0.0; 3]; deg];
                for n in (0..deg).rev() {
                    for k in 0..3 {
                        let mut r = coef[n][k];
                        if n + 2 < deg {
                            r -= a[1] * ((n + 2) * (n + 1)) as f64 * p[n + 2][k];
                        }
                        if n + 4 < deg {
                            r -=
                                a[2] * ((n + 4) * (n + 3) * (n + 2) * (n + 1)) as f64 * p[n + 4][k];
                        }
                        p[n][k] = r / a[0];
                    }
                }
                // Integrate m times: s_{n+m} = p_n n!/(n+m)!.
                let mut s = vec![[0.0; 3]; deg + m];
                for n in 0..deg {
                    let f = (n + 1..=n + m).fold(1.0, |acc, i| acc * i as f64);
                    for k in 0..3 {
                        s[n + m][k] = p[n][k] / f;
                    }
                }
                Ok(Particular::Polynomial { coef: s })
            }
            Force::Sine { amp, kappa, phase } => {
                if amp.iter().chain([kappa, phase]).any(|x| !x.is_finite()) {
                    return Err(Ode6Error::NotFinite {
                        what: "the sine force (amplitude, kappa or phase)",
                    });
                }
                let k2 = kappa * kappa;
                let symbol = -rho * k2 * k2 * k2 + eta * k2 * k2 - lambda * k2;
                let size = rho.abs() * k2 * k2 * k2 + eta.abs() * k2 * k2 + lambda.abs() * k2;
                if !(symbol.is_finite() && size.is_finite()) {
                    return Err(Ode6Error::SymbolOverflow { kappa: *kappa });
                }
                if size == 0.0 {
                    return Err(Ode6Error::Resonance { kappa2: k2, symbol });
                }
                if symbol.abs() <= RESONANCE * size {
                    let k = *kappa;
                    let dsym = -6.0 * rho * k2 * k2 * k + 4.0 * eta * k2 * k - 2.0 * lambda * k;
                    let dsize = 6.0 * rho.abs() * k2 * k2 * k.abs()
                        + 4.0 * eta.abs() * k2 * k.abs()
                        + 2.0 * lambda.abs() * k.abs();
                    if dsym.abs() <= RESONANCE * dsize {
                        return Err(Ode6Error::Resonance { kappa2: k2, symbol });
                    }
                    return Ok(Particular::ResonantSine {
                        amp: [amp[0] / dsym, amp[1] / dsym, amp[2] / dsym],
                        kappa: k,
                        phase: *phase,
                    });
                }
                Ok(Particular::Sine {
                    amp: [amp[0] / symbol, amp[1] / symbol, amp[2] / symbol],
                    kappa: *kappa,
                    phase: *phase,
                })
            }
        }
    }

    /// `S_p(u)`.
    pub fn eval<T: Real>(&self, u: T) -> [T; 3] {
        match self {
            Particular::Polynomial { coef } => horner(coef, u),
            Particular::Sine { amp, kappa, phase } => {
                let s = (u * *kappa + *phase).sin();
                [s * amp[0], s * amp[1], s * amp[2]]
            }
            Particular::ResonantSine { amp, kappa, phase } => {
                let s = (u * *kappa + *phase).cos() * u;
                [s * amp[0], s * amp[1], s * amp[2]]
            }
        }
    }
}
