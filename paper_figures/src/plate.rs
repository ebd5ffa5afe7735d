//! Figures of the plate family (paper 001): the comparison table against the
//! finite-element ground truth, Figs 11 and 12 (comparisons with Delta Mush
//! and the Laplacian deformer), Fig 8 (cursor direction and sensitivity),
//! Fig 9 (basic models) and Fig 1 (Utah teapot and a flat sheet).

#[path = "plate/compare.rs"]
mod compare;
#[path = "plate/models.rs"]
mod models;

use crate::common::Figure;
use pdesculpt::mesh::Mesh;
use pdesculpt::render::{render, render_with_camera, Camera, Image, Overlay, RenderOptions, View};

/// The figures of the plate family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "001-table-errors",
            paper: "001",
            title: "RMS / max error of ours, Delta Mush, Laplacian against the FE ground truth",
            run: compare::table,
        },
        Figure {
            id: "001-fig11",
            paper: "001",
            title: "Square and pentagram regions: deformed shapes and contour maps",
            run: compare::fig11,
        },
        Figure {
            id: "001-fig12",
            paper: "001",
            title: "Side views of triangle and rectangle regions against the ground truth",
            run: compare::fig12,
        },
        Figure {
            id: "001-fig8",
            paper: "001",
            title: "Cursor direction and sensitivities 40, 70, 110",
            run: models::fig8,
        },
        Figure {
            id: "001-fig9",
            paper: "001",
            title: "Sphere, cube, cylinder and cone with deformation regions",
            run: models::fig9,
        },
        Figure {
            id: "001-fig1",
            paper: "001",
            title: "Deformations on the Utah teapot and on a flat sheet",
            run: models::fig1,
        },
    ]
}

/// The plate-family meshes are z-up; the renderer is y-up.
pub(crate) fn yup(m: &Mesh) -> Mesh {
    let mut o = m.clone();
    o.positions = m.positions.iter().map(|p| [p[0], p[2], -p[1]]).collect();
    o
}

/// Renders z-up meshes side by side, each with an optional red boundary
/// overlay (z-up points), with one camera fitted to all of them.
pub(crate) fn render_row(meshes: &[(&Mesh, Vec<[f64; 3]>)], view: View, size: usize) -> Image {
    let ys: Vec<Mesh> = meshes.iter().map(|(m, _)| yup(m)).collect();
    let mut all = Mesh::default();
    for m in &ys {
        all.append(m);
    }
    let (lo, hi) = all.bbox();
    let cam = Camera::fit_box(lo, hi, view, size, size, 0.06);
    let imgs: Vec<Image> = ys
        .iter()
        .zip(meshes)
        .map(|(m, (_, overlay))| {
            let overlays = if overlay.is_empty() {
                Vec::new()
            } else {
                vec![Overlay {
                    points: overlay.iter().map(|p| [p[0], p[2], -p[1]]).collect(),
                    closed: true,
                    colour: [220, 30, 30, 255],
                    depth_test: false,
                }]
            };
            let o = RenderOptions::default()
                .with_width(size)
                .with_height(size)
                .with_view(view)
                .with_overlays(overlays);
            render_with_camera(m, &o, &cam)
        })
        .collect();
    Image::hstack(&imgs, [255, 255, 255, 255])
}

#[allow(dead_code)]
pub(crate) fn render_one(m: &Mesh, view: View, size: usize) -> Image {
    render(
        &yup(m),
        &RenderOptions::default()
            .with_width(size)
            .with_height(size)
            .with_view(view),
    )
}
