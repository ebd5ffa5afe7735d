//! Tutorial chapter 5 (docs/tutorial/05_ode6.md): sixth-order ODE surfaces,
//! paper 004.
//!
//! Every line v = const of a patch solves
//! rho S'''''' + eta S'''' + lambda S'' = 0 in u (eq 2), with the position,
//! first and second u-derivative given at u = 0 and u = 1 (eq 1, six curves
//! c1..c6). The same six curves give three surfaces for three sets of shape
//! parameters; the example measures the constraints and the ODE residual
//! through jets and draws the three in out/tutorial/05_ode6.png.
//!
//! Run: `cargo run --release --example 05_ode6`

use pdesculpt::curve::Fourier3;
use pdesculpt::jet::Jet;
use pdesculpt::ode6::{Basis, BoundaryCurves, Curve, Ode6Surface, Params};
use pdesculpt::render::{self, Image, RenderOptions, View};
use pdesculpt::surface::{tessellate, Surface, Tessellation};

/// A closed curve c0 + r (cos, 0, sin): a ring (r > 0) or a constant (r = 0).
fn ring(c0: [f64; 3], r: f64) -> Curve {
    Curve::Fourier(Fourier3 {
        c0,
        cos: vec![[r, 0.0, 0.0]],
        sin: vec![[0.0, 0.0, r]],
    })
}

fn main() -> anyhow::Result<()> {
    // c1 = S(0, v), c2 = S_u(0, v), c3 = S_uu(0, v), c4..c6 the same at u = 1:
    // a ring of radius 1 at y = 0 leaving upward and inward, a ring of
    // radius 0.5 at y = 2 arriving upward and outward, no second derivatives
    let curves = || {
        BoundaryCurves::direct([
            ring([0.0, 0.0, 0.0], 1.0),
            ring([0.0, 2.0, 0.0], -1.5),
            ring([0.0; 3], 0.0),
            ring([0.0, 2.0, 0.0], 0.5),
            ring([0.0, 2.0, 0.0], 1.0),
            ring([0.0; 3], 0.0),
        ])
    };
    let mut images = Vec::new();
    for (rho, eta, lambda) in [(1.0, 3.0, 1.0), (1e-4, 3.0, 1e-4), (1.0, 1.0, 300.0)] {
        let params = Params::new(rho, eta, lambda);
        let patch = Ode6Surface::new(Basis::new(params)?, curves()?);
        // eq 1 at u = 0: S(0, v) = c1(v) and S_u(0, v) = c2(v)
        let (mut bc, mut ode): (f64, f64) = (0.0, 0.0);
        for j in 0..32 {
            let v = j as f64 / 32.0;
            let th = std::f64::consts::TAU * v;
            let s = patch.eval(Jet::<2, 1>::var_u(0.0), Jet::<2, 1>::constant(v));
            for k in 0..3 {
                bc = bc.max((s[k].deriv(0, 0) - [th.cos(), 0.0, th.sin()][k]).abs());
                bc = bc.max((s[k].deriv(1, 0) - [-1.5 * th.cos(), 2.0, -1.5 * th.sin()][k]).abs());
            }
            // eq 2 along the line v at u = 0.37
            let s = patch.eval(Jet::<7, 1>::var_u(0.37), Jet::<7, 1>::constant(v));
            for t in &s {
                let r = rho * t.deriv(6, 0) + eta * t.deriv(4, 0) + lambda * t.deriv(2, 0);
                ode = ode.max(r.abs());
            }
        }
        let mid = patch.point(0.5, 0.0);
        println!("rho {rho}, eta {eta}, lambda {lambda}: radius at u = 0.5: {:.3}; constraint error {bc:.1e}, ODE residual {ode:.1e}", mid[0]);
        let mesh = tessellate(&patch, Tessellation { nu: 40, nv: 64 });
        let options = RenderOptions::default()
            .with_width(160)
            .with_height(200)
            .with_view(View::Front);
        images.push(render::render(&mesh, &options));
    }
    std::fs::create_dir_all("out/tutorial")?;
    Image::hstack(&images, [255; 4]).save_png(std::path::Path::new("out/tutorial/05_ode6.png"))?;
    println!("wrote out/tutorial/05_ode6.png (the three parameter sets, left to right)");
    Ok(())
}
