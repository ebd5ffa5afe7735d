//! # pdesculpt
//!
//! A verification-first research kit for modeling 3D characters with PDE and
//! ODE surfaces. Each equation family lives in its own module with a
//! `check.rs` that measures boundary conditions, residuals, continuity,
//! thresholds and agreement with independent references; [`verify::run`]
//! gathers them all.
//!
//! | module | paper | holds |
//! |---|---|---|
//! | [`vec3`] | - | `[f64; 3]` helpers and bounding boxes (the bottom) |
//! | [`polygon`] | - | planar polygons: area, crossings, bounds, distances (the bottom) |
//! | [`jet`] | - | exact derivatives by truncated Taylor arithmetic |
//! | [`check`] | all | verification reports, kinds, named tolerances (a leaf) |
//! | [`verify`] | all | the registry of every family's checks (the top) |
//! | [`study`] | all | experiments over many inputs, `pdesculpt study NAME` (the top) |
//! | [`equations`] | all | the equation index: equation, implementing function, checks, ERRATA |
//! | [`surface`] | - | the parametric-surface trait, tessellation |
//! | [`mesh`] | - | triangle meshes, files, metrics, slicing, topology |
//! | [`render`] | - | CPU rasteriser for PNG previews |
//! | [`makehuman`] | - | the bundled CC0 MakeHuman body and morph targets |
//! | [`curve::gec`] | 000, 002 | generalized elliptic curves |
//! | [`pde4`] | 000 | fourth-order sculpting deformations |
//! | [`plate`] | 001 | C1 plate-bending deformation of mesh regions |
//! | [`pde6`] | 002 | C2 sixth-order PDE patches |
//! | [`ode6`] | 004 | C2 sixth-order ODE surfaces |
//! | [`conv`] | 003 | convolution surfaces from silhouettes |
//! | [`character`] | 000 | the character document (inputs, parts, edit log) and its assembly into one model |
//! | [`edit`] | 000, 001 | local modeling: what an edit of the log does to the parts |
//! | [`pipeline`] | all | document -> model: the one build that replays the log |
//! | [`demo`] | all | the demo character |
//! | [`profile`] | 000 | closed outlines of a view: sketches (SVG, JSON), mesh outlines, distances |
//! | `harness` | - | (feature `harness`) proptest strategies and surface properties for any solver |

/// `with_*` setters of an options struct: `setters!(Options { with_x: x: Ty })`
/// gives `Options::with_x(self, x: Ty) -> Options`, so that a caller
/// outside the crate (the struct is `#[non_exhaustive]`) writes
/// `Options::default().with_x(..)`. Each setter's doc links its field,
/// which documents the value and its default.
macro_rules! setters {
    ($t:ident { $($name:ident: $field:ident: $ty:ty),* $(,)? }) => {
        impl $t {
            $(
                #[doc = concat!("Sets [`", stringify!($field), "`](", stringify!($t), "::", stringify!($field), ").")]
                #[must_use]
                pub fn $name(mut self, $field: $ty) -> $t {
                    self.$field = $field;
                    self
                }
            )*
        }
    };
}

pub mod body;
pub mod character;
pub mod check;
pub mod conv;
pub mod curve;
pub mod demo;
pub mod edit;
pub mod equations;
pub mod face;
#[cfg(feature = "harness")]
pub mod harness;
pub mod jet;
pub mod limits;
pub mod makehuman;
pub mod mesh;
pub mod ode6;
pub mod pde4;
pub mod pde6;
pub mod pipeline;
pub mod plate;
pub mod polygon;
pub mod profile;
pub mod progress;
pub mod render;
pub mod sasm;
pub mod sketch;
pub mod study;
pub mod surface;
pub mod template;
pub mod tui;
pub mod vec3;
pub mod verify;
