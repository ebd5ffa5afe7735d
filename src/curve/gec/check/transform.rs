//! Transforms of GECs (scale, rotate, translate, bump, bend) against the
//! same transforms applied to sampled points.

use super::*;
use crate::check::{worst, Worst};

pub(super) fn transform_checks(tg: &Gec, out: &mut Vec<Check>) {
    let th: Vec<f64> = (0..37).map(|k| 0.17 * k as f64).collect();
    let f = tg.frame;
    let plane = |g: &Gec| -> Vec<[f64; 2]> { th.iter().map(|t| g.eval_plane(*t)).collect() };
    let p0 = plane(tg);
    let lift =
        |p: &[[f64; 2]]| -> Vec<[f64; 3]> { p.iter().map(|q| f.place(q[0], q[1])).collect() };
    let space = |g: &Gec| -> Vec<[f64; 3]> { th.iter().map(|t| g.eval(*t)).collect() };
    // scale
    let cc = [0.2, -0.1];
    let want: Vec<[f64; 2]> = p0
        .iter()
        .map(|q| [cc[0] + 1.3 * (q[0] - cc[0]), cc[1] + 0.7 * (q[1] - cc[1])])
        .collect();
    out.push(c(
        "000 sec 5.2",
        "gec.transform_scale",
        Kind::Residual,
        max_diff3(&space(&tg.scaled(1.3, 0.7, cc)), &lift(&want)),
        tol::ROUNDING,
        "per-axis scaling of coefficients equals scaled points",
    ));
    // rotate
    let (s, co) = 0.9f64.sin_cos();
    let want: Vec<[f64; 2]> = p0
        .iter()
        .map(|q| {
            let d = [q[0] - cc[0], q[1] - cc[1]];
            [cc[0] + co * d[0] - s * d[1], cc[1] + s * d[0] + co * d[1]]
        })
        .collect();
    out.push(c(
        "000 sec 5.2",
        "gec.transform_rotate",
        Kind::Residual,
        max_diff3(&space(&tg.rotated(0.9, cc)), &lift(&want)),
        tol::ROUNDING,
        "in-plane rotation of coefficient pairs equals rotated points",
    ));
    // translate
    let dvec = [0.5, -1.0, 2.0];
    let want: Vec<[f64; 3]> = space(tg)
        .iter()
        .map(|p| [p[0] + dvec[0], p[1] + dvec[1], p[2] + dvec[2]])
        .collect();
    out.push(c(
        "000 sec 5.2",
        "gec.transform_translate",
        Kind::Residual,
        max_diff3(&space(&tg.translated(dvec)), &want),
        tol::ROUNDING,
        "translation equals translated points",
    ));
    let d = bump_error(tg, &th);
    out.push(c(
        "000 sec 5.2",
        "gec.transform_bump",
        Kind::Residual,
        d,
        tol::ROUNDING,
        "local bump in coefficient space equals displaced points; peak height h at theta_c",
    ));
    let d = bend_error(tg, &th);
    out.push(c(
        "000 sec 5.2",
        "gec.transform_bend_chain",
        Kind::Residual,
        d,
        tol::ROUNDING,
        "bending a chain of z-plane sections equals the bend deformer applied to their points",
    ));
}

fn space_at(g: &Gec, th: &[f64]) -> Vec<[f64; 3]> {
    th.iter().map(|t| g.eval(*t)).collect()
}

/// A local bump in coefficient space against the displaced points, and the
/// peak height `h` at `theta_c`.
fn bump_error(tg: &Gec, th: &[f64]) -> f64 {
    let f = tg.frame;
    let lift =
        |p: &[[f64; 2]]| -> Vec<[f64; 3]> { p.iter().map(|q| f.place(q[0], q[1])).collect() };
    let space = |g: &Gec| space_at(g, th);
    let p0: Vec<[f64; 2]> = th.iter().map(|t| tg.eval_plane(*t)).collect();
    let (h, tc, sig) = (0.2, 1.1, 0.35);
    match tg.with_bump(h, tc, sig) {
        Ok(b) => {
            let gs: Vec<f64> = (1..=tg.terms())
                .map(|n| (-(n as f64 * sig).powi(2) / 2.0).exp())
                .collect();
            let nb = 1.0 + 2.0 * gs.iter().sum::<f64>();
            let want: Vec<[f64; 2]> = th
                .iter()
                .zip(&p0)
                .map(|(t, q)| {
                    let prof = (1.0
                        + 2.0
                            * gs.iter()
                                .enumerate()
                                .map(|(i, g)| g * ((i + 1) as f64 * (t - tc)).cos())
                                .sum::<f64>())
                        / nb;
                    [q[0] + h * prof * tc.cos(), q[1] + h * prof * tc.sin()]
                })
                .collect();
            let peak = b.eval_plane(tc);
            let base = tg.eval_plane(tc);
            let dpeak = ((peak[0] - base[0]).hypot(peak[1] - base[1]) - h).abs();
            max_diff3(&space(&b), &lift(&want)).worst(dpeak)
        }
        Err(_) => f64::NAN,
    }
}

/// Bending a chain of z-plane sections against the bend deformer applied to
/// their points.
fn bend_error(tg: &Gec, th: &[f64]) -> f64 {
    let space = |g: &Gec| space_at(g, th);
    match Bend::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], 0.4) {
        Ok(bend) => (0..5)
            .map(|i| {
                let sec = Gec::new(
                    Frame::z_plane(0.5 * i as f64),
                    [0.1, 0.0],
                    tg.x.clone(),
                    tg.y.clone(),
                );
                match sec {
                    Ok(sec) => {
                        let moved = bend.apply_gec(&sec);
                        let want: Vec<[f64; 3]> =
                            space(&sec).iter().map(|p| bend.apply(*p)).collect();
                        max_diff3(&space(&moved), &want)
                    }
                    Err(_) => f64::NAN,
                }
            })
            .fold(0.0, worst),
        Err(_) => f64::NAN,
    }
}
