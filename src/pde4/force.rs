//! Sculpting forces (paper 000 eqs 2-4, 11; appendices A and B).
//!
//! Every force is separable, $P(u,v) = p\,f(u)\,g(v)$, so each series
//! coefficient is a product of one $u$ and one $v$ projection:
//!
//! * concentrated at $(u_{p0}, v_{p0})$: $f = \delta(u-u_{p0})$, $g = \delta(v-v_{p0})$;
//! * line (eq 2): $f = \sin\frac{\pi(u-u_{p0})}{u_{p1}-u_{p0}}$ on $[u_{p0},u_{p1}]$, $g = \delta(v-v_{p0})$;
//! * area (eq 3): $f$ as for the line force, $g = \sin\frac{\pi(v-v_{p0})}{v_{p1}-v_{p0}}$ on $[v_{p0}, v_{p1}]$;
//! * uniform (plate-theory validation): $f = g = 1$ on the whole patch.
//!
//! The bump projections have the closed form (derived and checked in
//! `verify/pde4_derive.py`), with $L = b-a$, $\beta = \pi/L$, $c = (a+b)/2$,
//! $$\int_a^b \sin\tfrac{\pi(x-a)}{L}\,\{\sin,\cos\}(\omega x)\,dx
//!   = \frac{\pi\,\{\sin,\cos\}(\omega c)\,\mathrm{sinc}\big((\beta-\omega)L/2\big)}{\beta+\omega},$$
//! which is regular at $\omega = \beta$. Eq 4 (2-sided): sine series in $u$,
//! Fourier series in $v$ of period 1; eq 11 (4-sided): double sine series.
//! The appendix formulas (A1-A5, B1-B3) are kept literally in
//! [`printed_two_sided`] and [`printed_four_sided`]; several differ (ERRATA.md).

use super::Pde4Error;
use std::f64::consts::PI;

/// Where and how a sculpting force acts (patch-local parameters in `[0, 1]`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum ForceKind {
    /// Concentrated force at `(u0, v0)`.
    Concentrated { u0: f64, v0: f64 },
    /// Line distribution (eq 2) on `u0 <= u <= u1` along `v = v0`.
    Line { u0: f64, u1: f64, v0: f64 },
    /// Area distribution (eq 3) on `[u0, u1] x [v0, v1]`.
    Area { u0: f64, u1: f64, v0: f64, v1: f64 },
    /// Uniform load over the whole patch.
    Uniform,
}

/// A sculpting force: its distribution and its vector magnitude `p_t`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
// (no deny_unknown_fields: serde does not support it beside `flatten`)
pub struct Force {
    #[serde(flatten)]
    pub kind: ForceKind,
    /// `(p_x, p_y, p_z)`.
    pub p: [f64; 3],
}

fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// $\int_a^b \sin\frac{\pi(x-a)}{b-a}\sin(\omega x)\,dx$ (closed form).
pub fn bump_sin(a: f64, b: f64, omega: f64) -> f64 {
    let (l, c) = (b - a, 0.5 * (a + b));
    let beta = PI / l;
    PI * (omega * c).sin() * sinc(0.5 * (beta - omega) * l) / (beta + omega)
}

/// $\int_a^b \sin\frac{\pi(x-a)}{b-a}\cos(\omega x)\,dx$ (closed form).
pub fn bump_cos(a: f64, b: f64, omega: f64) -> f64 {
    let (l, c) = (b - a, 0.5 * (a + b));
    let beta = PI / l;
    PI * (omega * c).cos() * sinc(0.5 * (beta - omega) * l) / (beta + omega)
}

/// The bump profile $\sin\frac{\pi(x-a)}{b-a}$ on $[a,b]$, zero outside.
pub fn bump(a: f64, b: f64, x: f64) -> f64 {
    if x < a || x > b {
        0.0
    } else {
        (PI * (x - a) / (b - a)).sin()
    }
}

fn check_range(name: &'static str, lo: f64, hi: f64) -> Result<(), Pde4Error> {
    if !lo.is_finite() || !hi.is_finite() {
        return Err(Pde4Error::NonFinite {
            what: name,
            value: if lo.is_finite() { hi } else { lo },
        });
    }
    if !(0.0..=1.0).contains(&lo) || !(0.0..=1.0).contains(&hi) {
        return Err(Pde4Error::OutsidePatch { what: name, lo, hi });
    }
    if hi <= lo {
        return Err(Pde4Error::EmptyRange { what: name, lo, hi });
    }
    Ok(())
}

fn check_pos(name: &'static str, x: f64) -> Result<(), Pde4Error> {
    if !x.is_finite() {
        return Err(Pde4Error::NonFinite {
            what: name,
            value: x,
        });
    }
    if !(0.0..=1.0).contains(&x) {
        return Err(Pde4Error::OutsidePatch {
            what: name,
            lo: x,
            hi: x,
        });
    }
    Ok(())
}

impl Force {
    /// Checks parameters: finite, inside the patch, `u0 < u1`, `v0 < v1`.
    pub fn validate(&self) -> Result<(), Pde4Error> {
        for (i, &p) in self.p.iter().enumerate() {
            if !p.is_finite() {
                return Err(Pde4Error::NonFinite {
                    what: ["p_x", "p_y", "p_z"][i],
                    value: p,
                });
            }
            if p.abs() > super::MAX_MAGNITUDE {
                return Err(Pde4Error::Magnitude {
                    what: format!("force component {}", ["p_x", "p_y", "p_z"][i]),
                    value: p,
                    lo: -super::MAX_MAGNITUDE,
                    hi: super::MAX_MAGNITUDE,
                    why: "the displacement would overflow; rescale the forces",
                });
            }
        }
        match self.kind {
            ForceKind::Concentrated { u0, v0 } => {
                check_pos("force u_p0", u0)?;
                check_pos("force v_p0", v0)
            }
            ForceKind::Line { u0, u1, v0 } => {
                check_range("force u_p0..u_p1", u0, u1)?;
                check_pos("force v_p0", v0)
            }
            ForceKind::Area { u0, u1, v0, v1 } => {
                check_range("force u_p0..u_p1", u0, u1)?;
                check_range("force v_p0..v_p1", v0, v1)
            }
            ForceKind::Uniform => Ok(()),
        }
    }

    /// $2\int_0^1 f(u)\sin k\pi u\,du$: the $u$ sine coefficient (unit magnitude).
    pub fn u_sine(&self, k: usize) -> f64 {
        let w = k as f64 * PI;
        match self.kind {
            ForceKind::Concentrated { u0, .. } => 2.0 * (w * u0).sin(),
            ForceKind::Line { u0, u1, .. } | ForceKind::Area { u0, u1, .. } => {
                2.0 * bump_sin(u0, u1, w)
            }
            ForceKind::Uniform => 2.0 * (1.0 - (w).cos()) / w,
        }
    }

    /// Fourier coefficients of $g(v)$ on period 1 (eq 4): `(constant, 0)` for
    /// `n = 0`, else the `(cos 2 n pi v, sin 2 n pi v)` coefficients.
    pub fn v_fourier(&self, n: usize) -> (f64, f64) {
        let w = 2.0 * PI * n as f64;
        match self.kind {
            ForceKind::Concentrated { v0, .. } | ForceKind::Line { v0, .. } => {
                if n == 0 {
                    (1.0, 0.0)
                } else {
                    (2.0 * (w * v0).cos(), 2.0 * (w * v0).sin())
                }
            }
            ForceKind::Area { v0, v1, .. } => {
                if n == 0 {
                    (bump_cos(v0, v1, 0.0), 0.0)
                } else {
                    (2.0 * bump_cos(v0, v1, w), 2.0 * bump_sin(v0, v1, w))
                }
            }
            ForceKind::Uniform => (if n == 0 { 1.0 } else { 0.0 }, 0.0),
        }
    }

    /// $2\int_0^1 g(v)\sin n\pi v\,dv$: the $v$ sine coefficient of eq 11.
    pub fn v_sine(&self, n: usize) -> f64 {
        let w = n as f64 * PI;
        match self.kind {
            ForceKind::Concentrated { v0, .. } | ForceKind::Line { v0, .. } => 2.0 * (w * v0).sin(),
            ForceKind::Area { v0, v1, .. } => 2.0 * bump_sin(v0, v1, w),
            ForceKind::Uniform => 2.0 * (1.0 - w.cos()) / w,
        }
    }

    /// Eq 4 coefficients for unit magnitude: `(p_m, pbar_mn, pbarbar_mn)`
    /// (`n >= 1` for the last two).
    pub fn two_sided(&self, m: usize, n: usize) -> (f64, f64, f64) {
        let um = self.u_sine(m);
        let (c0, _) = self.v_fourier(0);
        let (cn, sn) = if n == 0 {
            (0.0, 0.0)
        } else {
            self.v_fourier(n)
        };
        (um * c0, um * cn, um * sn)
    }

    /// Eq 11 coefficient `p_mn` for unit magnitude.
    pub fn four_sided(&self, m: usize, n: usize) -> f64 {
        self.u_sine(m) * self.v_sine(n)
    }

    /// The force profile $f(u)g(v)$ (unit magnitude) where it is a function
    /// (area and uniform forces); `None` for distributions.
    pub fn profile(&self, u: f64, v: f64) -> Option<f64> {
        match self.kind {
            ForceKind::Area { u0, u1, v0, v1 } => Some(bump(u0, u1, u) * bump(v0, v1, v)),
            ForceKind::Uniform => Some(1.0),
            _ => None,
        }
    }
}

/// Appendix A2 helpers, literally: `r_0..r_3` for `k`.
fn r_consts(rp0: f64, rp1: f64, k: f64) -> [f64; 4] {
    let l = rp1 - rp0;
    [
        1.0 / (k * l + 1.0),
        0.5 * (rp1 + rp0 + 1.0 / k),
        1.0 / (k * l - 1.0),
        0.5 * (rp1 + rp0 - 1.0 / k),
    ]
}

/// A2 $f_3(r, k) = 0.5(r_0 \sin 2k\pi r_1 - r_2 \sin 2k\pi r_3)$ as printed.
pub(crate) fn f3(rp0: f64, rp1: f64, k: f64) -> f64 {
    let r = r_consts(rp0, rp1, k);
    0.5 * (r[0] * (2.0 * k * PI * r[1]).sin() - r[2] * (2.0 * k * PI * r[3]).sin())
}

/// A2 $f_1(u, m) = u_0 \cos^2 m\pi u_1 - u_2 \cos^2 m\pi u_3$ as printed.
pub(crate) fn f1(rp0: f64, rp1: f64, k: f64) -> f64 {
    let r = r_consts(rp0, rp1, k);
    r[0] * (k * PI * r[1]).cos().powi(2) - r[2] * (k * PI * r[3]).cos().powi(2)
}

/// A2 $f_2(v, 2n) = v_0 \sin^2 2n\pi v_1 - v_2 \sin^2 2n\pi v_3$ as printed.
pub(crate) fn f2(rp0: f64, rp1: f64, k: f64) -> f64 {
    let r = r_consts(rp0, rp1, k);
    r[0] * (k * PI * r[1]).sin().powi(2) - r[2] * (k * PI * r[3]).sin().powi(2)
}

/// Appendix A (A1-A5) exactly as printed: `(p_m, pbar_mn, pbarbar_mn)` for unit
/// magnitude (`None` for the uniform load, which the paper does not treat).
pub fn printed_two_sided(kind: &ForceKind, m: usize, n: usize) -> Option<(f64, f64, f64)> {
    let (mf, nf) = (m as f64, n as f64);
    Some(match *kind {
        ForceKind::Concentrated { u0, v0 } => {
            let s = (mf * PI * u0).sin();
            (
                2.0 * s,
                4.0 * s * (2.0 * nf * PI * v0).cos(),
                4.0 * s * (2.0 * nf * PI * v0).sin(),
            )
        }
        ForceKind::Line { u0, u1, v0 } => {
            let c1 = -2.0 * (u1 - u0) / PI;
            let g = f3(u0, u1, mf);
            (
                c1 * g,
                2.0 * c1 * g * (2.0 * nf * PI * v0).cos(),
                2.0 * c1 * g * (2.0 * nf * PI * v0).sin(),
            )
        }
        ForceKind::Area { u0, u1, v0, v1 } => {
            let c0 = 4.0 * (u1 - u0) * (v1 - v0) / (PI * PI);
            let g = f3(u0, u1, mf);
            (
                -c0 * f1(u0, u1, mf),
                -c0 * g * f2(v0, v1, 2.0 * nf),
                c0 * g * f3(v0, v1, 2.0 * nf),
            )
        }
        ForceKind::Uniform => return None,
    })
}

/// Appendix B (B1-B3) exactly as printed (`f_3(v, k/2)` read as `k = n`).
pub fn printed_four_sided(kind: &ForceKind, m: usize, n: usize) -> Option<f64> {
    let (mf, nf) = (m as f64, n as f64);
    Some(match *kind {
        ForceKind::Concentrated { u0, v0 } => 4.0 * (mf * PI * u0).sin() * (nf * PI * v0).sin(),
        ForceKind::Line { u0, u1, v0 } => {
            let c1 = -2.0 * (u1 - u0) / PI;
            2.0 * c1 * f3(u0, u1, mf) * (nf * PI * v0).sin()
        }
        ForceKind::Area { u0, u1, v0, v1 } => {
            let c0 = 4.0 * (u1 - u0) * (v1 - v0) / (PI * PI);
            c0 * f3(u0, u1, mf) * f3(v0, v1, nf)
        }
        ForceKind::Uniform => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Below its switch, `sinc` is the series `1 - x^2/6`: it agrees with
    /// `sin x / x` (accurate to a few ulp there) to rounding. A sign slip in
    /// the series term is off by `x^2/3` (1.3e-10 to 3.3e-9 here), far above
    /// it.
    #[test]
    fn sinc_near_zero_is_sin_x_over_x() {
        for x in [2e-5f64, -5e-5, 9e-5, 9.9e-5] {
            let want = x.sin() / x;
            assert!(
                (sinc(x) - want).abs() <= crate::check::tol::ROUNDING,
                "x = {x:e}: {} against {want}",
                sinc(x)
            );
        }
    }

    /// The bump is the half sine on `[a, b]` and zero on either side of it.
    #[test]
    fn bump_is_a_half_sine_inside_and_zero_outside() {
        let (a, b) = (0.2, 0.6);
        for x in [0.0, 0.1, 0.19, 0.61, 0.9, 1.0] {
            assert_eq!(bump(a, b, x), 0.0, "x = {x}");
        }
        assert!((bump(a, b, 0.4) - 1.0).abs() < crate::check::tol::ROUNDING);
        let x = 0.3;
        let want = (PI * (x - a) / (b - a)).sin();
        assert!((bump(a, b, x) - want).abs() < crate::check::tol::ROUNDING);
    }

    /// A uniform force's profile is 1 everywhere, an area force's the
    /// product of its two bumps, and a distribution (point, line) has none.
    #[test]
    fn force_profiles_by_kind() {
        let p = [0.0, 0.0, 1.0];
        let uniform = Force {
            kind: ForceKind::Uniform,
            p,
        };
        assert_eq!(uniform.profile(0.3, 0.7), Some(1.0));
        let area = Force {
            kind: ForceKind::Area {
                u0: 0.2,
                u1: 0.6,
                v0: 0.1,
                v1: 0.5,
            },
            p,
        };
        let want = bump(0.2, 0.6, 0.3) * bump(0.1, 0.5, 0.2);
        assert_eq!(area.profile(0.3, 0.2), Some(want));
        assert_eq!(area.profile(0.7, 0.2), Some(0.0));
        let point = Force {
            kind: ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
            p,
        };
        assert_eq!(point.profile(0.5, 0.5), None);
    }
    /// Eq 4's v coefficients of the forces that have a profile (uniform,
    /// area) are the Fourier projections of `g(v)` on period 1: `int g` for
    /// `n = 0`, `2 int g {cos, sin}(2 pi n v)` above, here by the midpoint
    /// rule on 4000 panels (error about 1e-7 for the area bump's kinks).
    #[test]
    fn v_fourier_is_the_quadrature_of_the_profile() {
        let p = [0.0, 0.0, 1.0];
        let (v0, v1) = (0.15, 0.55);
        let kinds = [
            ForceKind::Uniform,
            ForceKind::Area {
                u0: 0.0,
                u1: 1.0,
                v0,
                v1,
            },
        ];
        let panels = 4000;
        // the midpoint rule's error on 4000 panels: about 1e-7 at the
        // bump's kinks, so 1e-6 leaves a decade
        const MIDPOINT: f64 = 1e-6;
        for kind in kinds {
            let f = Force { kind, p };
            // g(v): the profile at the u bump's peak, where f(u) = 1.
            let g = |v: f64| f.profile(0.5, v).expect("a profile");
            for n in 0..5usize {
                let w = 2.0 * PI * n as f64;
                let (mut c, mut s) = (0.0, 0.0);
                for i in 0..panels {
                    let v = (i as f64 + 0.5) / panels as f64;
                    c += g(v) * (w * v).cos() / panels as f64;
                    s += g(v) * (w * v).sin() / panels as f64;
                }
                let want = if n == 0 { (c, 0.0) } else { (2.0 * c, 2.0 * s) };
                let got = f.v_fourier(n);
                assert!(
                    (got.0 - want.0).abs() < MIDPOINT && (got.1 - want.1).abs() < MIDPOINT,
                    "{kind:?} n = {n}: {got:?} against {want:?}"
                );
            }
        }
    }
}
