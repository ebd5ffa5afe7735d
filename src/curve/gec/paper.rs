//! The printed coefficient orderings of paper 000 eq 16 and paper 002
//! eq 1 (conversions to and from [`Gec`]) and both equations evaluated
//! literally as printed (the paper-literal checks compare them with
//! [`Gec::eval`]).

use super::{Frame, Gec, GecError};
use std::f64::consts::PI;

impl Gec {
    /// Paper 000 eq 16 ordering: `(x_k, y_k)` for `k = 0..=2J`.
    pub fn to_paper_000(&self) -> (Vec<f64>, Vec<f64>) {
        let mut xs = vec![self.centre[0]];
        let mut ys = vec![self.centre[1]];
        for (cx, cy) in self.x.iter().zip(&self.y) {
            xs.extend_from_slice(cx);
            ys.extend_from_slice(cy);
        }
        (xs, ys)
    }

    /// From paper 000 eq 16 ordering: `xs = [x_0, x_1, .., x_2J]`, same for
    /// `ys`, placed by `frame` (`Frame::z_plane(z_c)` for the paper).
    pub fn from_paper_000(frame: Frame, xs: &[f64], ys: &[f64]) -> Result<Gec, GecError> {
        if xs.len() != ys.len() || xs.len() < 3 || xs.len() % 2 == 0 {
            return Err(GecError::Malformed(format!(
                "paper 000 needs 2J+1 >= 3 x and y coefficients, got {} and {}",
                xs.len(),
                ys.len()
            )));
        }
        let pairs = |c: &[f64]| c[1..].chunks(2).map(|p| [p[0], p[1]]).collect();
        Gec::new(frame, [xs[0], ys[0]], pairs(xs), pairs(ys))
    }

    /// Paper 002 eq 1 ordering: `(a_x, b_x, a_y, b_y)` with `a_x = [a_x0..a_xN]`,
    /// `b_x = [b_x1..b_xN]` (and the same for y).
    pub fn to_paper_002(&self) -> [Vec<f64>; 4] {
        let mut ax = vec![self.centre[0]];
        let mut ay = vec![self.centre[1]];
        ax.extend(self.x.iter().map(|c| c[0]));
        ay.extend(self.y.iter().map(|c| c[0]));
        let bx = self.x.iter().map(|c| c[1]).collect();
        let by = self.y.iter().map(|c| c[1]).collect();
        [ax, bx, ay, by]
    }

    /// From paper 002 eq 1 ordering (see [`Gec::to_paper_002`]).
    pub fn from_paper_002(
        frame: Frame,
        ax: &[f64],
        bx: &[f64],
        ay: &[f64],
        by: &[f64],
    ) -> Result<Gec, GecError> {
        let n = bx.len();
        if ax.len() != n + 1 || ay.len() != n + 1 || by.len() != n || n == 0 {
            return Err(GecError::Malformed(format!(
                "paper 002 needs N+1, N, N+1, N coefficients with N >= 1, got {}, {}, {}, {}",
                ax.len(),
                bx.len(),
                ay.len(),
                by.len()
            )));
        }
        let x = (0..n).map(|i| [ax[i + 1], bx[i]]).collect();
        let y = (0..n).map(|i| [ay[i + 1], by[i]]).collect();
        Gec::new(frame, [ax[0], ay[0]], x, y)
    }
}

/// Paper 000 eq 16 evaluated literally as printed (coefficient arrays
/// `x_0..x_2J`, `y_0..y_2J`, parameter `v` in `[0, 1]`, plane `z = z_c`).
pub fn paper_000_literal(xs: &[f64], ys: &[f64], z_c: f64, v: f64) -> [f64; 3] {
    let jmax = (xs.len().min(ys.len()).saturating_sub(1)) / 2;
    let mut x = xs.first().copied().unwrap_or(0.0);
    let mut y = ys.first().copied().unwrap_or(0.0);
    for j in 1..=jmax {
        let a = 2.0 * j as f64 * PI * v;
        x += xs[2 * j - 1] * a.cos() + xs[2 * j] * a.sin();
        y += ys[2 * j - 1] * a.sin() + ys[2 * j] * a.cos();
    }
    [x, y, z_c]
}

/// Paper 002 eq 1 evaluated literally as printed (`v` in `[0, 2 pi]`).
pub fn paper_002_literal(
    ax: &[f64],
    bx: &[f64],
    ay: &[f64],
    by: &[f64],
    z_c: f64,
    v: f64,
) -> [f64; 3] {
    let n_max = bx.len().min(by.len()).min(ax.len().saturating_sub(1));
    let mut x = ax.first().copied().unwrap_or(0.0);
    let mut y = ay.first().copied().unwrap_or(0.0);
    for n in 1..=n_max {
        let a = n as f64 * v;
        x += ax[n] * a.cos() + bx[n - 1] * a.sin();
        y += ay[n] * a.sin() + by[n - 1] * a.cos();
    }
    [x, y, z_c]
}
