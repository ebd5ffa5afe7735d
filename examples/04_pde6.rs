//! Tutorial chapter 4 (docs/tutorial/04_pde6.md): sixth-order PDE patches,
//! paper 002.
//!
//! Seven cross sections of a vase (closed curves at u = 0..6) are joined by
//! one C2 chain of two patches, each solving w_uuuuuu + a w_vvvvvv = 0. The
//! example measures the interpolation of the sections, the jumps of the
//! derivatives across the join, the PDE residual through jets, and draws the
//! vase in out/tutorial/04_pde6.png.
//!
//! Run: `cargo run --release --example 04_pde6`

use pdesculpt::curve::Fourier3;
use pdesculpt::jet::Jet;
use pdesculpt::pde6::{Chain, Section};
use pdesculpt::render::{self, RenderOptions, View};
use pdesculpt::surface::{tessellate, Joined, Surface, Tessellation};

/// A section at height `u`: an ellipse of radius `r` with a small third
/// harmonic (v in [0, 2 pi): x = r cos v + ..., z = 0.8 r sin v + ...).
fn section(u: f64, r: f64) -> Section {
    let curve = Fourier3 {
        c0: [0.0, u, 0.0],
        cos: vec![[r, 0.0, 0.0], [0.0; 3], [0.05 * r, 0.0, 0.0]],
        sin: vec![[0.0, 0.0, 0.8 * r], [0.0; 3], [0.0, 0.0, -0.05 * r]],
    };
    Section { u, curve }
}

fn main() -> anyhow::Result<()> {
    let radii = [1.0, 1.4, 1.5, 1.1, 0.6, 0.5, 0.8];
    let sections: Vec<Section> = radii
        .iter()
        .enumerate()
        .map(|(i, &r)| section(i as f64, r))
        .collect();
    let a = -0.01; // the shape parameter of eq 2 (the body reconstruction's value)
    let chain = Chain::c2_global(a, &sections)?;
    println!(
        "{} patches, {} coefficients",
        chain.pieces.len(),
        chain.coefficient_count()
    );

    // the surface passes through every section
    let mut gap: f64 = 0.0;
    for s in &sections {
        for j in 0..64 {
            let v = std::f64::consts::TAU * j as f64 / 64.0;
            gap = gap.max(pdesculpt::vec3::dist(chain.point(s.u, v), s.curve.eval(v)));
        }
    }
    println!("largest distance from a section: {gap:.2e}");

    // C0, C1, C2 across the join (relative jumps of S, S_u, S_uu)
    let [c0, c1, c2] = chain.join_jumps(32);
    println!("join jumps: C0 {c0:.1e}, C1 {c1:.1e}, C2 {c2:.1e}");

    // eq 2 through jets: exact sixth derivatives in u and v; a patch's own
    // parameter runs over [0, 1] while the chain's u runs over its length L,
    // so d/du_patch = L d/du (the chain rule)
    let mut worst: f64 = 0.0;
    for &(u, v) in &[(0.4, 0.3), (2.5, 2.0), (4.2, 5.5)] {
        let l6 = chain.pieces[chain.piece_at(u)].length.powi(6);
        let s = chain.eval(Jet::<7, 7>::var_u(u), Jet::<7, 7>::var_v(v));
        for t in &s {
            let w_u6 = l6 * t.deriv(6, 0);
            worst = worst.max((w_u6 + a * t.deriv(0, 6)).abs() / w_u6.abs().max(1.0));
        }
    }
    println!("PDE residual (relative): {worst:.2e}");

    let mesh = tessellate(&chain, Tessellation { nu: 60, nv: 64 });
    println!(
        "mesh: {} coordinates for the chain's {} numbers",
        3 * mesh.positions.len(),
        chain.coefficient_count()
    );
    let options = RenderOptions::default().with_width(220).with_height(300);
    let image = render::render_views(
        &mesh,
        &[
            View::Front,
            View::Perspective {
                yaw: 30.0,
                pitch: 25.0,
            },
        ],
        &options,
    );
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(std::path::Path::new("out/tutorial/04_pde6.png"))?;
    println!("wrote out/tutorial/04_pde6.png");
    Ok(())
}
