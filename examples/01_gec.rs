//! Tutorial chapter 1 (docs/tutorial/01_gec.md): generalized elliptic curves,
//! paper 000 eq 16 and paper 002 eq 1.
//!
//! Cuts the chest of the bundled MakeHuman body (at the breasts), fits GECs with J = 1, 3 and
//! 10 terms, prints their errors ErM and ErA (paper 002 Table 1) and draws
//! them over the cut in out/tutorial/01_gec.png.
//!
//! Run: `cargo run --release --example 01_gec`

use pdesculpt::curve::gec::{self, study, FitOptions};
use pdesculpt::mesh::Mesh;
use pdesculpt::render::{self, Camera, Overlay, RenderOptions, View};

fn main() -> anyhow::Result<()> {
    // a real cross section: the horizontal cut of the skin across the chest
    let chest = study::base_sections()?
        .into_iter()
        .find(|s| s.name == "torso_chest")
        .ok_or_else(|| anyhow::anyhow!("no chest section"))?;
    println!("chest: {} points", chest.points.len());

    let mut overlays = vec![Overlay {
        points: chest.points.clone(),
        closed: true,
        colour: [0, 0, 0, 255],
        depth_test: false,
    }];
    let colours = [[220, 60, 40, 255], [40, 120, 220, 255], [30, 160, 60, 255]];
    println!("  J      ErM (dm)    ErA (dm)   ErM / D");
    for (terms, colour) in [1, 3, 10].into_iter().zip(colours) {
        // least squares for the 2J + 1 coefficients per coordinate, the
        // parameter rule and its correction chosen for the smallest ErM
        let fit = gec::fit(&chest.points, &FitOptions::new(terms))?;
        let e = fit.errors;
        println!(
            "{terms:>3} {:>12.5} {:>11.5} {:>9.5}",
            e.erm, e.era, e.erm_rel
        );
        overlays.push(Overlay {
            points: fit.gec.sample(256),
            closed: true,
            colour,
            depth_test: false,
        });
    }

    // the section seen from above; no mesh, only the curves
    let (lo, hi) =
        pdesculpt::vec3::bounds(&chest.points).ok_or_else(|| anyhow::anyhow!("empty cut"))?;
    let options = RenderOptions::default()
        .with_width(360)
        .with_height(260)
        .with_view(View::Top)
        .with_overlays(overlays);
    let camera = Camera::fit_box(lo, hi, View::Top, 360, 260, 0.08);
    let image = render::render_with_camera(&Mesh::default(), &options, &camera);
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(std::path::Path::new("out/tutorial/01_gec.png"))?;
    println!("wrote out/tutorial/01_gec.png (black: the cut; red J = 1, blue J = 3, green J = 10)");
    Ok(())
}
