//! The FFT path of the GEC fit: for uniformly spaced angles $\theta_k =
//! \theta_0 + 2\pi k/M$, $M > 2J$, the columns of the design matrix are
//! discretely orthogonal and the least-squares solution is the truncated
//! DFT, computed by [`fit_fft`] after resampling the polyline uniformly in
//! the chosen parameter. (No parameter correction here: the resampled
//! points are not the data; see [`super::correct`].)

use super::lsq::{check_counts, finish, parameters, Coefficients, FitOptions, FitReport};
use super::section::{check_scale, section};
use super::GecError;
use rustfft::num_complex::Complex;
use std::f64::consts::PI;

/// Truncated DFT of in-plane points at uniform angles `theta_0 + 2 pi k / M`:
/// the least-squares solution for those angles (M > 2J).
pub fn dft_coefficients(
    points: &[[f64; 2]],
    theta0: f64,
    terms: usize,
) -> Result<Coefficients, GecError> {
    let m = points.len();
    check_counts(m, terms)?;
    let mut buf: Vec<Complex<f64>> = points.iter().map(|p| Complex::new(p[0], p[1])).collect();
    rustfft::FftPlanner::new()
        .plan_fft_forward(m)
        .process(&mut buf);
    // z_k = x_k + i y_k; Z_n = sum z_k e^{-2 pi i n k / M}. For a real
    // sequence f: a_n = (2/M) Re F_n, b_n = -(2/M) Im F_n, with
    // F_n = (Z_n + conj Z_{M-n}) / 2 (x) and (Z_n - conj Z_{M-n}) / (2i) (y).
    let mf = m as f64;
    let centre = [buf[0].re / mf, buf[0].im / mf];
    let mut x = Vec::with_capacity(terms);
    let mut y = Vec::with_capacity(terms);
    for n in 1..=terms {
        let zn = buf[n];
        let zc = buf[m - n].conj();
        let fx = (zn + zc) * 0.5;
        let fy = (zn - zc) * Complex::new(0.0, -0.5);
        // shift by theta0: coefficients in theta, samples at theta0 + ...
        let rot = Complex::from_polar(1.0, -(n as f64) * theta0);
        let (gx, gy) = (fx * rot, fy * rot);
        let (ax, bx) = (2.0 * gx.re / mf, -2.0 * gx.im / mf);
        let (ay_cos, ay_sin) = (2.0 * gy.re / mf, -2.0 * gy.im / mf);
        x.push([ax, bx]);
        y.push([ay_sin, ay_cos]);
    }
    Ok((centre, x, y))
}

/// Resamples a closed polyline at `m` angles uniform in `[t0, t0 + 2 pi)`
/// by linear interpolation in the (monotone) parameter `thetas`.
pub fn resample_uniform(
    points: &[[f64; 2]],
    thetas: &[f64],
    m: usize,
) -> Result<(f64, Vec<[f64; 2]>), GecError> {
    let n = points.len();
    // unwrap into a strictly increasing sequence spanning one turn
    let mut t = Vec::with_capacity(n + 1);
    t.push(thetas[0]);
    for i in 1..n {
        let mut d = (thetas[i] - thetas[i - 1]).rem_euclid(2.0 * PI);
        if d > PI {
            d -= 2.0 * PI;
        }
        t.push(t[i - 1] + d);
    }
    let turn = t[n - 1] - t[0];
    let sign = if turn < 0.0 { -1.0 } else { 1.0 };
    t.push(t[0] + sign * 2.0 * PI);
    let s: Vec<f64> = t.iter().map(|v| sign * (v - t[0])).collect();
    if s.windows(2).any(|w| w[1] <= w[0]) {
        return Err(GecError::InvalidParameter(
            "the parameter is not monotone along the polyline (polar angle on a curve that is not star-shaped?)".into(),
        ));
    }
    let mut out = Vec::with_capacity(m);
    let mut seg = 0;
    for k in 0..m {
        let sk = 2.0 * PI * k as f64 / m as f64;
        while seg + 1 < n && s[seg + 1] <= sk {
            seg += 1;
        }
        let (a, b) = (points[seg], points[(seg + 1) % n]);
        let w = (sk - s[seg]) / (s[seg + 1] - s[seg]);
        out.push([a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1])]);
    }
    // samples are at angle t0 + sign * 2 pi k / m; for sign < 0 reverse order
    if sign < 0.0 {
        out[1..].reverse();
    }
    Ok((t[0], out))
}

/// The FFT path: resample uniformly in the chosen parameter with `m` points
/// (`m > 2J`), then take the truncated DFT. Errors are measured against the
/// original points.
pub fn fit_fft(points: &[[f64; 3]], opts: &FitOptions, m: usize) -> Result<FitReport, GecError> {
    check_scale(points)?;
    check_counts(points.len(), opts.terms)?;
    check_counts(m, opts.terms)?;
    let sec = section(points, opts.frame, opts.planarity_tol, 2 * opts.terms + 1)?;
    let thetas = parameters(&sec.points, opts.param, opts.theta0);
    let (t0, uni) = resample_uniform(&sec.points, &thetas, m)?;
    let (centre, x, y) = dft_coefficients(&uni, t0, opts.terms)?;
    finish(sec, thetas, centre, x, y, opts.param)
}
