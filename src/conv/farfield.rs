//! Cheaper evaluations of the segment field for the narrow-band sampler
//! (issue 16): one segment's closed form with a single arctangent, and a
//! far cluster of segments by a second-order expansion with a proven error
//! bound. The brute-force reference keeps [`super::kernel`]'s closed form.
//!
//! **One arctangent.** In [`super::kernel`]'s $F_1$ the angular part is
//! $\theta = \arctan\frac{sh}{p} + \arctan\frac{s(l-h)}{p}$. Both angles
//! are the arguments of $1 + iX$ and $1 + iY$ ($X = sh/p$, $Y = s(l-h)/p$),
//! so $\theta$ is the argument of their product, $(1 - XY) + i(X+Y)$; the
//! sum lies in $(-\pi, \pi)$, so no branch is lost, and scaling by
//! $p^2 > 0$: $\theta = \operatorname{atan2}(s\,l\,p,\; p^2 - s^2h(l-h))$.
//! With $F_t = \frac{1}{2s^2}(a_0^{-1} - a_1^{-1}) + hF_1$ the weighted field
//! is $\lambda[(w_0 + \frac{w_1-w_0}{l}h)F_1 + \frac{w_1-w_0}{l}F_t']$,
//! $F_t' = F_t - hF_1$: one square root, one arctangent and one division
//! (for $1/a_0$, $1/a_1$ and $1/p^3$ at once, $a_0 a_1 p^3$ inverted; the
//! three separate divisions when that product leaves the f64 range).
//! The arctangent is [`atan2_upper`] (Cephes' rational `atan`, relative
//! error near $10^{-16}$; about three times cheaper than the C library's
//! correctly rounded `atan2`, which took a third of the sampling time);
//! check `conv.fast.atan2_matches_std`.
//!
//! **Cluster expansion.** A cluster of segments of one kernel width $s$ is
//! a signed line density $\mu$ (weight $\lambda w(t)$ along each segment).
//! With $\varphi(y) = g(|y - x|^2)$, $g(u) = (1+s^2u)^{-2}$ and a centre
//! $c$, Taylor's theorem gives
//! $$\int\varphi\,d\mu = m\,\varphi(c) + \nabla\varphi(c)\cdot D + E,\qquad
//!   |E| \le \tfrac12 \sup_{B(c,R)}\|\nabla^2\varphi\|\int|y-c|^2\,d|\mu|,$$
//! $m = \int d\mu$, $D = \int (y - c)\,d\mu$, $\nabla\varphi(c) = 2g'(u_c)(c - x)$.
//! The Hessian $4g''(v)rr^T + 2g'(v)I$ ($r = y - x$, $v = |r|^2$, $w = s^2v$)
//! has the eigenvalues $4s^2(5w-1)/(1+w)^4$ and $-4s^2/(1+w)^3$, both at most
//! $20s^2/(1+w)^3$ in size since $|5w - 1| \le 5(1+w)$; decreasing in $w$, so
//! over the ball $B(c, R)$ seen from a point at distance $d_c$ from $c$,
//! $$|E| \le \frac{10\,s^2 M_2}{(1 + s^2 d_{min}^2)^3},\quad
//!   d_{min} = \max(0, d_c - R),\; M_2 = \int|y-c|^2\,d|\mu|.$$
//! The moments are integrated exactly (two-point Gauss-Legendre per piece
//! of constant sign: the integrands are cubic at most).

use super::kernel::Segment;
use crate::mesh::{dot, sub};

/// One segment's field, precomputed for repeated evaluation.
#[derive(Clone, Copy, Debug)]
pub struct SegmentField {
    p: [f64; 3],
    a: [f64; 3],
    l: f64,
    s: f64,
    s2: f64,
    /// $\lambda w_0$
    c0: f64,
    /// $\lambda (w_1 - w_0) / l$
    c1: f64,
    /// $1/s$
    inv_s: f64,
    /// $c_1 / (2s^2)$
    c1_half_s2: f64,
}

impl SegmentField {
    /// Precomputes `seg` (of positive length) under the kernel width `s`.
    pub fn new(seg: &Segment, s: f64) -> SegmentField {
        let e = sub(seg.q, seg.p);
        let l = dot(e, e).sqrt();
        SegmentField {
            p: seg.p,
            a: [e[0] / l, e[1] / l, e[2] / l],
            l,
            s,
            s2: s * s,
            c0: seg.lambda * seg.w0,
            c1: seg.lambda * (seg.w1 - seg.w0) / l,
            inv_s: 1.0 / s,
            c1_half_s2: seg.lambda * (seg.w1 - seg.w0) / l / (2.0 * s * s),
        }
    }

    /// The field at `x` (equal to [`Segment::field`] up to rounding).
    #[inline]
    pub fn value(&self, x: [f64; 3]) -> f64 {
        let d = [x[0] - self.p[0], x[1] - self.p[1], x[2] - self.p[2]];
        let h = d[0] * self.a[0] + d[1] * self.a[1] + d[2] * self.a[2];
        let q = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - h * h).max(0.0);
        let p2 = 1.0 + self.s2 * q;
        let p = p2.sqrt();
        let lh = self.l - h;
        let a0 = self.s2 * h * h + p2;
        let a1 = self.s2 * lh * lh + p2;
        let theta = atan2_upper(self.s * self.l * p, p2 - self.s2 * h * lh);
        // one division for 1/a0, 1/a1 and 1/(p^2 p)
        let pp = p2 * p;
        let (a01, app) = (a0 * a1, a0 * a1 * pp);
        let inv = 1.0 / app;
        let (i0, i1, inv_pp) = if inv.is_normal() {
            (a1 * pp * inv, a0 * pp * inv, a01 * inv)
        } else {
            (1.0 / a0, 1.0 / a1, 1.0 / pp)
        };
        let f1 = 0.5 * inv_pp * (p * (h * i0 + lh * i1) + theta * self.inv_s);
        (self.c0 + self.c1 * h) * f1 + self.c1_half_s2 * (i0 - i1)
    }
}

/// $\tan(3\pi/8)$.
const TAN_3PI_8: f64 = 2.414_213_562_373_095;
/// Cephes' bound between the direct and the $\pi/4$-shifted range.
const CEPHES_MID: f64 = 0.66;
/// The low bits of $\pi/2$ beyond `FRAC_PI_2` (Cephes `MOREBITS`).
const PI_2_LOW: f64 = 6.123_233_995_736_766e-17;
const ATAN_P: [f64; 5] = [
    -8.750_608_600_031_904e-1,
    -1.615_753_718_733_365e1,
    -7.500_855_792_314_705e1,
    -1.228_866_684_490_136e2,
    -6.485_021_904_942_025e1,
];
const ATAN_Q: [f64; 5] = [
    2.485_846_490_142_306e1,
    1.650_270_098_316_988_5e2,
    4.328_810_604_912_903e2,
    4.853_903_996_359_137e2,
    1.945_506_571_482_614e2,
];

/// $\operatorname{atan2}(y, x)$ for $y > 0$ (a value in $(0, \pi)$), by
/// Cephes' `atan` (S. Moshier): the ratio is reduced to
/// $|z| \le \tan(\pi/8)$ through $\pi/2 - \arctan(1/t)$ or
/// $\pi/4 + \arctan\frac{t-1}{t+1}$ (one division either way), then
/// $\arctan z = z + z\,z^2 P(z^2)/Q(z^2)$. Agrees with [`f64::atan2`] to
/// a few units in the last place (check `conv.fast.atan2_matches_std`).
#[inline]
pub fn atan2_upper(y: f64, x: f64) -> f64 {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    let ax = x.abs();
    let (base, low, z) = if y > TAN_3PI_8 * ax {
        (FRAC_PI_2, PI_2_LOW, -ax / y)
    } else if y <= CEPHES_MID * ax {
        (0.0, 0.0, y / ax)
    } else {
        (FRAC_PI_4, 0.5 * PI_2_LOW, (y - ax) / (y + ax))
    };
    let z2 = z * z;
    let p = (((ATAN_P[0] * z2 + ATAN_P[1]) * z2 + ATAN_P[2]) * z2 + ATAN_P[3]) * z2 + ATAN_P[4];
    let q =
        ((((z2 + ATAN_Q[0]) * z2 + ATAN_Q[1]) * z2 + ATAN_Q[2]) * z2 + ATAN_Q[3]) * z2 + ATAN_Q[4];
    let a = base + ((z * (z2 * p / q) + z) + low);
    if x < 0.0 {
        PI - a
    } else {
        a
    }
}

/// Moments of a signed line density about a centre: mass $m$, first
/// moment $D$, and $M_2 = \int |y-c|^2 d|\mu|$ (see the module doc).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Moments {
    pub mass: f64,
    pub dipole: [f64; 3],
    pub m2: f64,
}

impl Moments {
    /// The moments of `seg`'s density $\lambda w(t)$ about `c`.
    pub fn of_segment(seg: &Segment, c: [f64; 3]) -> Moments {
        let e = sub(seg.q, seg.p);
        let rho = |t: f64| seg.lambda * (seg.w0 + (seg.w1 - seg.w0) * t);
        let (r0, r1) = (rho(0.0), rho(1.0));
        // pieces of constant sign, in the parameter t in [0, 1]
        let cut = if r0 * r1 < 0.0 { r0 / (r0 - r1) } else { 1.0 };
        let len = dot(e, e).sqrt();
        let mut m = Moments::default();
        let g = 0.5 / 3f64.sqrt();
        for (a, b) in [(0.0, cut), (cut, 1.0)] {
            if b <= a {
                continue;
            }
            let (mid, half) = (0.5 * (a + b), b - a);
            for t in [mid - g * half, mid + g * half] {
                let w = 0.5 * half * len * rho(t);
                let y = [0, 1, 2].map(|k| seg.p[k] + t * e[k] - c[k]);
                m.mass += w;
                for k in 0..3 {
                    m.dipole[k] += w * y[k];
                }
                m.m2 += w.abs() * dot(y, y);
            }
        }
        m
    }

    /// Sum of two moment sets about the same centre.
    pub fn add(&mut self, o: &Moments) {
        self.mass += o.mass;
        for k in 0..3 {
            self.dipole[k] += o.dipole[k];
        }
        self.m2 += o.m2;
    }

    /// The second-order expansion about `c` of the cluster's field at `x`
    /// under the kernel width `s`.
    #[inline]
    pub fn expansion(&self, c: [f64; 3], s: f64, x: [f64; 3]) -> f64 {
        let r = [c[0] - x[0], c[1] - x[1], c[2] - x[2]];
        let s2 = s * s;
        let b = 1.0 / (1.0 + s2 * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]));
        let g = b * b;
        // 2 g'(u) = -4 s^2 b^3
        let dg = -4.0 * s2 * g * b;
        self.mass * g + dg * (r[0] * self.dipole[0] + r[1] * self.dipole[1] + r[2] * self.dipole[2])
    }

    /// Bound of [`Self::expansion`]'s error at every point at least `dmin`
    /// from the ball that holds the cluster.
    #[inline]
    pub fn error_bound(&self, s: f64, dmin: f64) -> f64 {
        let b = 1.0 / (1.0 + (s * dmin) * (s * dmin));
        10.0 * s * s * self.m2 * b * b * b
    }
}
