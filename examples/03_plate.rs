//! Tutorial chapter 3 (docs/tutorial/03_plate.md): C1 plate bending of a mesh
//! region, paper 001.
//!
//! A circular region of a flat sheet is mapped to the unit disk (eqs 13-16)
//! and bent as a clamped circular plate, eq 12:
//! xi = q / (64 D) (u^2 + v^2 - 1)^2. The example compares every moved vertex
//! with that closed form, measures the slope at the region's edge (C1) and
//! draws the sheet in out/tutorial/03_plate.png.
//!
//! Run: `cargo run --release --example 03_plate`

use pdesculpt::plate::shapes::{region_in_polygon, sheet, Shape};
use pdesculpt::plate::{Direction, PlateDeformer, RegionOptions};
use pdesculpt::render::{self, RenderOptions, View};

fn main() -> anyhow::Result<()> {
    let mesh = sheet(64); // 64 x 64 cells over [-1.25, 1.25]^2, z = 0
    let region = region_in_polygon(&mesh, &Shape::Circle.polygon()); // radius 1
    let plate = PlateDeformer::new(&mesh, &region, &RegionOptions::default())?;
    println!(
        "region: {} vertices, rigidity D = {:.4e}",
        region.len(),
        plate.rigidity()
    );

    // a cursor motion of 1 along the normal with sensitivity 1: q = 1
    let force = plate.checked_force([0.0, 0.0, 1.0], 1.0, Direction::Normal)?;
    let bent = plate.deform(&mesh, [0.0, 0.0, 1.0], 1.0, Direction::Normal)?;
    let peak = force[2] / (64.0 * plate.rigidity());
    println!("peak q / (64 D) = {peak:.4e}");

    // every region vertex against eq 12: at its disk coordinates (where the
    // deformer evaluates it) and at its geometric radius (the disk map of
    // the region's own outermost vertices is not exactly r / 1)
    let (mut at_disk, mut at_radius, mut top): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for (&v, d) in plate.region().iter().zip(plate.disk()) {
        let p = mesh.positions[v as usize];
        let z = bent.positions[v as usize][2];
        let eq12 = |r2: f64| peak * (r2 - 1.0).powi(2);
        at_disk = at_disk.max((z - eq12(d.u * d.u + d.v * d.v)).abs());
        at_radius = at_radius.max((z - eq12(p[0] * p[0] + p[1] * p[1])).abs());
        top = top.max(z.abs());
    }
    println!(
        "largest |z - eq 12| / peak: at the disk coordinates {:.1e}, at the radius {:.1e}",
        at_disk / top,
        at_radius / top
    );

    // C1 at the clamped edge: the mean slope of the ring of vertices just
    // inside the circle is O(h), the slope at mid-radius is not
    let slope = |r_lo: f64, r_hi: f64| {
        let ring: Vec<f64> = region
            .iter()
            .filter_map(|&v| {
                let p = mesh.positions[v as usize];
                let r = p[0].hypot(p[1]);
                (r > r_lo && r < r_hi).then(|| bent.positions[v as usize][2] / (1.0 - r))
            })
            .collect();
        ring.iter().sum::<f64>() / ring.len().max(1) as f64 / top
    };
    println!(
        "z / distance to the edge, relative to the peak: at r ~ 0.97 {:.3}, at r ~ 0.5 {:.3}",
        slope(0.95, 0.99),
        slope(0.45, 0.55)
    );

    let options = RenderOptions::default()
        .with_width(360)
        .with_height(200)
        .with_view(View::Perspective {
            yaw: 30.0,
            pitch: 30.0,
        });
    // shown lying down (the displacement up, y) and exaggerated to a peak of 0.5
    let mut shown = bent.clone();
    for p in &mut shown.positions {
        *p = [p[0], p[2] / (2.0 * top), -p[1]];
    }
    let image = render::render(&shown, &options);
    std::fs::create_dir_all("out/tutorial")?;
    image.save_png(std::path::Path::new("out/tutorial/03_plate.png"))?;
    println!("wrote out/tutorial/03_plate.png (height scaled to 0.5)");
    Ok(())
}
