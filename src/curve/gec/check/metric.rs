//! ErM, ErA and distances on curves whose answers are known (circles, an
//! ellipse).

use super::*;
use crate::check::Worst;

pub(super) fn metric_checks(out: &mut Vec<Check>) {
    // ErM/ErA of the unit circle against points on the circle of radius 1.1
    let circle = Gec::ellipse(Frame::z_plane(0.0), [0.0, 0.0], 1.0, 1.0);
    let pts: Vec<[f64; 2]> = (0..50)
        .map(|k| {
            let t = 0.1 + 2.0 * PI * k as f64 / 50.0;
            [1.1 * t.cos(), 1.1 * t.sin()]
        })
        .collect();
    let e = metrics::errors(&circle, &pts);
    out.push(c(
        "002 Table 1",
        "gec.metrics_circle",
        Kind::Reference,
        (e.erm - 0.1).abs().worst((e.era - 0.1).abs()),
        tol::SOLVE,
        "ErM = ErA = 0.1 for points on a circle of radius 1.1 against the unit circle",
    ));
    // an ellipse: distance from (0, 2) to ellipse a=2, b=1 is 1 (closest point (0,1))
    let ell = Gec::ellipse(Frame::z_plane(0.0), [0.0, 0.0], 2.0, 1.0);
    let s = metrics::Sampled::new(&ell);
    let (d, _) = s.closest([0.0, 2.0]);
    let (d2, _) = s.closest([3.0, 0.0]);
    out.push(c(
        "002 Table 1",
        "gec.metrics_ellipse_distance",
        Kind::Reference,
        (d - 1.0).abs().worst((d2 - 1.0).abs()),
        tol::SOLVE,
        "point-to-curve distance with Newton polish on an ellipse (exact 1, 1)",
    ));
}
