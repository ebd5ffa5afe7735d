//! The Cauchy kernel and the closed-form fields of a line segment
//! (paper 003, sec 3.1).
//!
//! Kernel $h(r) = 1/(1+s^2 r^2)^2$. For the segment $L(t) = b + t a$,
//! $0 \le t \le l$, $|a| = 1$, and a point $r$: $d = r - b$, $h = d\cdot a$
//! (the axial coordinate, not the kernel), $q = |d|^2 - h^2$ (squared distance
//! to the line) and $p^2 = 1 + s^2 q$. With $k(u) = 1/(p^2 + s^2 u^2)^2$ and
//! $u = t - h$,
//! $$F_1 = \int_0^l \frac{dt}{(1+s^2 r^2(t))^2}
//!   = \frac{1}{2p^2}\Big[\frac{h}{s^2h^2+p^2} + \frac{l-h}{s^2(l-h)^2+p^2}\Big] +
//!   \frac{1}{2sp^3}\Big[\arctan\frac{sh}{p} + \arctan\frac{s(l-h)}{p}\Big],$$
//! $$F_t = \int_0^l \frac{t\,dt}{(1+s^2 r^2(t))^2} =
//!   \frac{1}{2s^2}\Big[\frac{1}{s^2h^2+p^2} - \frac{1}{s^2(l-h)^2+p^2}\Big] + h F_1,$$
//! both as printed (re-derived in `verify/conv_kernel.py`). With the weight
//! $w(t) = w_0 + (w_1-w_0)t/l$ the field is
//! $F = w_0 F_1 + \frac{w_1-w_0}{l} F_t = w_0 (F_1 - F_t/l) + w_1 F_t/l$.
//!
//! The fields are written once for any [`Real`] in the variables $(h, q)$;
//! the gradient in space follows from $\nabla h = a$,
//! $\nabla q = 2(d - h a)$ and the exact partial derivatives from a
//! first-order [`Jet`].

use crate::jet::{Jet, Real};
use crate::mesh::{dot, sub};

/// The Cauchy kernel $1/(1+s^2r^2)^2$ at squared distance `r2`.
pub fn cauchy(r2: f64, s: f64) -> f64 {
    let a = 1.0 + s * s * r2;
    1.0 / (a * a)
}

/// $F_1$ (constant unit weight) in the variables `h` (axial coordinate) and
/// `q` (squared distance to the line).
pub fn f1<T: Real>(h: T, q: T, l: f64, s: f64) -> T {
    let p2 = q * (s * s) + 1.0;
    let p = p2.sqrt();
    let lh = -h + l;
    let a0 = h * h * (s * s) + p2;
    let a1 = lh * lh * (s * s) + p2;
    let rational = (h / a0 + lh / a1) / (p2 * 2.0);
    let angular = ((h * s / p).atan() + (lh * s / p).atan()) / (p2 * p * (2.0 * s));
    rational + angular
}

/// $F_t$ (weight $t$, the arc length from the start point).
pub fn ft<T: Real>(h: T, q: T, l: f64, s: f64) -> T {
    let p2 = q * (s * s) + 1.0;
    let lh = -h + l;
    let a0 = h * h * (s * s) + p2;
    let a1 = lh * lh * (s * s) + p2;
    (a0.recip() - a1.recip()) / (2.0 * s * s) + h * f1(h, q, l, s)
}

/// The linearly weighted field $w_0 F_1 + (w_1-w_0) F_t / l$.
pub fn linear_field<T: Real>(h: T, q: T, l: f64, s: f64, w0: f64, w1: f64) -> T {
    f1(h, q, l, s) * w0 + ft(h, q, l, s) * ((w1 - w0) / l)
}

/// A skeletal line segment from `p` to `q` with linear weights `w0` (at `p`)
/// and `w1` (at `q`) and the control scale `lambda` of the global fit.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Segment {
    pub p: [f64; 3],
    pub q: [f64; 3],
    pub w0: f64,
    pub w1: f64,
    pub lambda: f64,
}

/// Axial coordinate, squared line distance, offset $d$, unit direction and
/// length of `r` relative to the segment `p`..`q`.
fn frame(p: [f64; 3], q: [f64; 3], r: [f64; 3]) -> (f64, f64, [f64; 3], [f64; 3], f64) {
    let e = sub(q, p);
    let l = dot(e, e).sqrt();
    let a = [e[0] / l, e[1] / l, e[2] / l];
    let d = sub(r, p);
    let h = dot(d, a);
    let q2 = (dot(d, d) - h * h).max(0.0);
    (h, q2, d, a, l)
}

impl Segment {
    /// Length.
    pub fn length(&self) -> f64 {
        let e = sub(self.q, self.p);
        dot(e, e).sqrt()
    }

    /// $F_1$ and $F_t$ at `r` (unit weights, no lambda).
    pub fn basis(&self, r: [f64; 3], s: f64) -> (f64, f64) {
        let (h, q, _, _, l) = frame(self.p, self.q, r);
        (f1(h, q, l, s), ft(h, q, l, s))
    }

    /// The field $\lambda (w_0 F_1 + (w_1-w_0)F_t/l)$ at `r`.
    pub fn field(&self, r: [f64; 3], s: f64) -> f64 {
        let (h, q, _, _, l) = frame(self.p, self.q, r);
        self.lambda * linear_field(h, q, l, s, self.w0, self.w1)
    }

    /// The field without `lambda` (the column of the global fit).
    pub fn unscaled_field(&self, r: [f64; 3], s: f64) -> f64 {
        let (h, q, _, _, l) = frame(self.p, self.q, r);
        linear_field(h, q, l, s, self.w0, self.w1)
    }

    /// Gradient of [`Segment::field`] at `r` (exact, by a first-order jet in
    /// $(h, q)$ and the chain rule).
    pub fn gradient(&self, r: [f64; 3], s: f64) -> [f64; 3] {
        let (h, q, d, a, l) = frame(self.p, self.q, r);
        let jh = Jet::<2, 2>::var_u(h);
        let jq = Jet::<2, 2>::var_v(q);
        let f = linear_field(jh, jq, l, s, self.w0, self.w1);
        let (fh, fq) = (f.deriv(1, 0), f.deriv(0, 1));
        let mut g = [0.0; 3];
        for k in 0..3 {
            g[k] = self.lambda * (fh * a[k] + fq * 2.0 * (d[k] - h * a[k]));
        }
        g
    }
}

/// Sum of the fields of `segments` at `r`.
pub fn total_field(segments: &[Segment], r: [f64; 3], s: f64) -> f64 {
    segments.iter().map(|g| g.field(r, s)).sum()
}

/// Sum of the gradients of `segments` at `r`.
pub fn total_gradient(segments: &[Segment], r: [f64; 3], s: f64) -> [f64; 3] {
    let mut g = [0.0; 3];
    for seg in segments {
        let x = seg.gradient(r, s);
        for k in 0..3 {
            g[k] += x[k];
        }
    }
    g
}

/// Gauss-Kronrod 7-15 nodes (positive half, including 0) and weights.
const GK15_X: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const GK15_WK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
const GK7_WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// One Gauss-Kronrod 7-15 panel: (Kronrod estimate, |Kronrod - Gauss|).
fn gk15(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let c = 0.5 * (a + b);
    let hw = 0.5 * (b - a);
    let fc = f(c);
    let mut k = fc * GK15_WK[7];
    let mut g = fc * GK7_WG[3];
    for i in 0..7 {
        let x = hw * GK15_X[i];
        let s = f(c - x) + f(c + x);
        k += GK15_WK[i] * s;
        if i % 2 == 1 {
            g += GK7_WG[i / 2] * s;
        }
    }
    (k * hw, ((k - g) * hw).abs())
}

/// Adaptive Gauss-Kronrod quadrature of `f` over `[a, b]` to absolute
/// tolerance `tol` (bisection, depth-limited): the independent reference the
/// closed forms are checked against.
pub fn integrate(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    fn rec(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64, depth: u32) -> f64 {
        let (v, err) = gk15(f, a, b);
        // a NaN value, error or tolerance is returned as NaN at once: no
        // subdivision can make `err <= tol` true, and refining to depth 40
        // would take 2^40 rules (scripts/nan_inject.sh hung here)
        if v.is_nan() || err.is_nan() || tol.is_nan() {
            return f64::NAN;
        }
        if err <= tol || depth == 0 {
            return v;
        }
        let m = 0.5 * (a + b);
        rec(f, a, m, 0.5 * tol, depth - 1) + rec(f, m, b, 0.5 * tol, depth - 1)
    }
    rec(f, a, b, tol, 40)
}

/// The field of a linearly weighted segment by adaptive quadrature of the
/// kernel along it (reference for the closed form).
pub fn field_by_quadrature(seg: &Segment, r: [f64; 3], s: f64, tol: f64) -> f64 {
    let f = |t: f64| {
        let (d, w) = offset_and_weight(seg, r, t);
        w * cauchy(dot(d, d), s)
    };
    seg.lambda * integrate(&f, 0.0, seg.length(), tol)
}

/// `r - c(t)` and the weight `w(t)` at arc length `t` along the segment.
fn offset_and_weight(seg: &Segment, r: [f64; 3], t: f64) -> ([f64; 3], f64) {
    let x = t / seg.length();
    let c = [0, 1, 2].map(|k| seg.p[k] + (seg.q[k] - seg.p[k]) * x);
    (sub(r, c), seg.w0 + (seg.w1 - seg.w0) * x)
}

/// The gradient of the field by quadrature of the kernel gradient
/// $-4s^2 (r-c)/(1+s^2|r-c|^2)^3$.
pub fn gradient_by_quadrature(seg: &Segment, r: [f64; 3], s: f64, tol: f64) -> [f64; 3] {
    let l = seg.length();
    let mut g = [0.0; 3];
    for k in 0..3 {
        let f = |t: f64| {
            let (d, w) = offset_and_weight(seg, r, t);
            let a = 1.0 + s * s * dot(d, d);
            -4.0 * s * s * w * d[k] / (a * a * a)
        };
        g[k] = seg.lambda * integrate(&f, 0.0, l, tol);
    }
    g
}
