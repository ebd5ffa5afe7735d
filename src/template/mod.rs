//! Template-based global modeling (000 sec 4.2, Fig 7): an existing
//! character (the template) is deformed so that its profile curves fit
//! sketched ones, in three levels.
//!
//! 1. **Correspondence and alignment** ([`landmarks`]): landmarks on the
//!    template's outline and on the sketch (top of head, hands, armpits,
//!    feet, crotch; or heel and toe in side view), a similarity transform
//!    (least squares on the landmarks, Umeyama) aligning the template to the
//!    sketch, and arc-length correspondence between consecutive landmarks.
//! 2. **RBF deformation** ([`rbf`]): polyharmonic splines with a linear
//!    polynomial part, solved densely (faer).
//!    - *Low level* (sec 4.2.1): a thin-plate warp $W(x, y)$ of the front
//!      plane takes the aligned template outline onto the sketched one and
//!      moves every vertex: $(x, y, z) \mapsto (W(x, y), z)$. Because the
//!      warp acts on the projection plane, the fitted mesh's front outline is
//!      the warped template outline wherever $W$ is one-to-one.
//!    - *Medium level* (sec 4.2.2): a scalar thin-plate spline
//!      $d(z, y)$ on the side plane moves depth only, $z \mapsto z + d(z, y)$,
//!      fitting the side outline while leaving the front projection, and so
//!      the front fit, untouched. The correction passes after it
//!      ([`envelope`]) also move heights where the side view shows them and
//!      depth cannot fit them: the head's landmarks ([`weights`]), the
//!      hand's webs and fingertips ([`envelope::feature_warp`]) and the
//!      front's shelves ([`envelope::shelf_warp`]), weighted so the front
//!      silhouette stays; the front view is measured again.
//!    - *High level* (sec 4.2.3): key cross-sections at chosen heights,
//!      GEC-fitted ([`crate::curve::gec`]); a 3D biharmonic spline
//!      ($\varphi = r$) per horizontal component moves the model's section
//!      curves onto them while vertices on the front (side) silhouette keep
//!      their x (z).
//!
//! Every level moves vertices only: the template's vertices and faces keep
//! their order (for MakeHuman every `v` line of the base OBJ, helper
//! geometry included, so MakeHuman targets still apply to the result).

pub mod belly;
pub mod check;
pub mod envelope;
pub mod features;
pub mod fit;
pub mod landmarks;
pub mod measure;
pub mod memo;
pub mod occlusion;
pub mod options;
pub mod outlines;
pub mod polygon;
pub mod rbf;
pub mod refine;
pub mod rows;
pub mod sections;
pub mod shapes;
pub mod study;
pub mod tbsm;
pub mod weights;

pub use fit::fit;
pub use landmarks::{Scheme, Similarity};
pub use options::{FitOptions, FitResult, Level, LevelReport, Sketch, Template};
pub use options::{OnMiss, ViewFit};
pub use rbf::{Rbf, RbfError};

use thiserror::Error;

/// Errors of template fitting.
#[derive(Debug, Error)]
pub enum TemplateError {
    #[error("{what}: {problem}")]
    BadProfile { what: String, problem: String },
    #[error("{outline}: cannot find the landmark '{landmark}': {problem}")]
    Landmark {
        outline: String,
        landmark: String,
        problem: String,
    },
    #[error("{view} landmarks do not match: the arc from '{from}' to '{to}' is {template:.1} % of the template's outline but {sketch:.1} % of the sketch's")]
    LandmarkMismatch {
        view: String,
        from: String,
        to: String,
        template: f64,
        sketch: f64,
    },
    #[error("the template has no closed outline in the {view} view: {problem}")]
    NoOutline { view: String, problem: String },
    #[error("the {level} level's {view} profile is {percent:.2} % of the height off the sketch after {passes} correction passes (tolerance {tolerance:.2} %): the sketch is too far from the template for this level")]
    ProfileMiss {
        level: &'static str,
        view: String,
        percent: f64,
        tolerance: f64,
        passes: usize,
    },
    #[error("cross-section at y = {y}: {problem}")]
    Section { y: f64, problem: String },
    #[error("{stage}: {source}")]
    Rbf {
        stage: &'static str,
        #[source]
        source: RbfError,
    },
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
}

pub use crate::profile::View;

/// How the fit obtains a mesh's outline in a view (the `profile` module's
/// silhouette in the library; exact outlines of synthetic shapes in tests).
pub type OutlineFn<'a> =
    dyn Fn(&crate::mesh::Mesh, View) -> Result<Vec<[f64; 2]>, TemplateError> + Sync + 'a;
