//! Composite Gauss-Legendre quadrature on intervals (for Galerkin integrals
//! and residual norms).

/// Nodes and weights of the `n`-point Gauss-Legendre rule on `[-1, 1]`
/// (Newton iteration on `P_n`, converged to rounding).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let p = if n == 1 { z } else { p1 };
            let pm = if n == 1 { 1.0 } else { p0 };
            dp = n as f64 * (z * p - pm) / (z * z - 1.0);
            let dz = p / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// Composite rule on `[a, b]`: `panels` equal panels of `order` points.
pub fn composite(a: f64, b: f64, panels: usize, order: usize) -> (Vec<f64>, Vec<f64>) {
    let (x, w) = gauss_legendre(order);
    let h = (b - a) / panels as f64;
    let mut xs = Vec::with_capacity(panels * order);
    let mut ws = Vec::with_capacity(panels * order);
    for p in 0..panels {
        let c = a + (p as f64 + 0.5) * h;
        for (xi, wi) in x.iter().zip(&w) {
            xs.push(c + 0.5 * h * xi);
            ws.push(0.5 * h * wi);
        }
    }
    (xs, ws)
}
