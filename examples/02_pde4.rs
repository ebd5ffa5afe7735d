//! Tutorial chapter 2 (docs/tutorial/02_pde4.md): fourth-order PDE surfaces
//! and sculpting forces, paper 000 sec 3.1.
//!
//! A 2-sided patch between two rings (a tube around the y axis) solves
//! a1 t_uuuu + a2 t_uuvv + a3 t_vvvv = P_t(u, v) per coordinate t, clamped to
//! the rings at u = 0 and u = 1. One concentrated force pushes the front of
//! the tube out. The example measures the PDE residual through jets and the
//! boundary error, and draws the result in out/tutorial/02_pde4.png.
//!
//! Run: `cargo run --release --example 02_pde4`

use pdesculpt::curve::Fourier3;
use pdesculpt::jet::Jet;
use pdesculpt::pde4::two_sided::{Boundary, Method};
use pdesculpt::pde4::{Force, ForceKind, ShapeParams, TwoSided};
use pdesculpt::render::{self, RenderOptions, View};
use pdesculpt::surface::{tessellate, Surface, Tessellation};

/// A ring of radius `r` at height `y` (theta = 2 pi v; x = r cos, z = r sin).
fn ring(r: f64, y: f64) -> Fourier3 {
    Fourier3 {
        c0: [0.0, y, 0.0],
        cos: vec![[r, 0.0, 0.0]],
        sin: vec![[0.0, 0.0, r]],
    }
}

fn main() -> anyhow::Result<()> {
    // boundary curves and their u-tangents (the tube rises by 1 along u)
    let up = Fourier3 {
        c0: [0.0, 1.0, 0.0],
        cos: vec![[0.0; 3]],
        sin: vec![[0.0; 3]],
    };
    let boundary = Boundary {
        curve0: ring(1.0, 0.0),
        curve1: ring(0.7, 1.0),
        tangent0: up.clone(),
        tangent1: up,
    };
    // a concentrated force in +z at the middle of the front (v = 1/4: theta = pi/2)
    let force = Force {
        kind: ForceKind::Concentrated { u0: 0.5, v0: 0.25 },
        p: [0.0, 0.0, 4.0],
    };
    // stiff along u, soft around v (a plate, a = (1, 2, 1), would pinch the
    // tube: bending around the ring costs (2 pi)^4 times more)
    let params = [ShapeParams {
        a1: 1.0,
        a2: 0.02,
        a3: 1e-4,
    }; 3];
    let patch = TwoSided::new(params, &[force], 24, 24, Method::Exact, Some(&boundary))?;

    let plain = TwoSided::new(params, &[], 24, 24, Method::Exact, Some(&boundary))?;
    let (p, q) = (patch.point(0.5, 0.25), plain.point(0.5, 0.25));
    println!(
        "under the force: z = {:.4} (without the force: {:.4})",
        p[2], q[2]
    );

    // residual of eq 1 through jets: exact derivatives up to order 4
    let mut worst: f64 = 0.0;
    for &(u, v) in &[(0.2, 0.1), (0.35, 0.6), (0.8, 0.9)] {
        let s = patch.eval(Jet::<5, 5>::var_u(u), Jet::<5, 5>::var_v(v));
        for (k, t) in s.iter().enumerate() {
            let a = params[k];
            let lhs = a.a1 * t.deriv(4, 0) + a.a2 * t.deriv(2, 2) + a.a3 * t.deriv(0, 4);
            worst = worst.max((lhs - patch.force_series(k, u, v)).abs());
        }
    }
    println!("PDE residual against the force series: {worst:.2e}");

    // boundary: S(0, v) is the first ring
    let mut gap: f64 = 0.0;
    for i in 0..64 {
        let v = i as f64 / 64.0;
        let (s, c) = (
            patch.point(0.0, v),
            boundary.curve0.eval(2.0 * std::f64::consts::PI * v),
        );
        gap = gap.max(pdesculpt::vec3::dist(s, c));
    }
    println!("largest distance from S(0, v) to the ring: {gap:.2e}");

    let mesh = tessellate(&patch, Tessellation { nu: 48, nv: 96 });
    let options = RenderOptions::default().with_width(240).with_height(240);
    let views = [View::Front, View::Side];
    let image = render::render_views(&mesh, &views, &options);
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(std::path::Path::new("out/tutorial/02_pde4.png"))?;
    println!("wrote out/tutorial/02_pde4.png (front and side)");
    Ok(())
}
