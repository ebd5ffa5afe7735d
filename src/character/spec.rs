//! What a character document specifies of its model: parts (tubes through
//! key sections, each with its surface family) and the transitions that
//! join them (the schema is in [`super::doc`]). Plain data, read by the edit
//! log, the document and the assembly alike.

pub use crate::pde6::EndCurvature;
use serde::{Deserialize, Serialize};

/// The curve of one key section in its frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
pub enum SectionShape {
    /// Radius (0: a collapsed end ring).
    Circle { r: f64 },
    /// Semi-axes along `e1` and `e2`, centre offset along `e2`.
    Ellipse { a: f64, b: f64, offset: f64 },
    /// GEC coefficients in the section frame (paper 000 eq 16):
    /// `(x, y)(theta) = centre + sum_j x[j] . (cos, sin)(j theta), ...`.
    Gec {
        centre: [f64; 2],
        x: Vec<[f64; 2]>,
        y: Vec<[f64; 2]>,
    },
}

/// One key section of a part.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionSpec {
    /// Arc length along the part's central curve.
    pub u: f64,
    pub centre: [f64; 3],
    pub e1: [f64; 3],
    pub e2: [f64; 3],
    pub shape: SectionShape,
}

fn is_six_point(e: &EndCurvature) -> bool {
    *e == EndCurvature::SixPoint
}

/// Surface family of a part.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "family", rename_all = "snake_case", deny_unknown_fields)]
pub enum SurfaceSpec {
    /// The globally solved C2 sixth-order PDE chain (`pde6::Chain::c2_global`)
    /// with PDE parameter `a`; `open_ends`: the condition at an end the
    /// part leaves open (a join; a closed end keeps the six-point
    /// curvature). Absent from a document: `six_point`, as before the
    /// field existed; parts derived from drawings take `guarded`.
    Pde6C2 {
        a: f64,
        #[serde(default, skip_serializing_if = "is_six_point")]
        open_ends: EndCurvature,
    },
    /// Sixth-order ODE patches between consecutive sections, C2 at each
    /// (paper 004 eqs 19, 23-25), with shape parameters rho, eta, lambda
    /// (`ode6::Params`).
    Ode6C2 { rho: f64, eta: f64, lambda: f64 },
}

impl SurfaceSpec {
    /// One line for reports and the TUI.
    pub fn describe(&self) -> String {
        match self {
            SurfaceSpec::Pde6C2 { a, .. } => format!("pde6 C2 chain (a = {a})"),
            SurfaceSpec::Ode6C2 { rho, eta, lambda } => {
                format!("ode6 C2 chain (rho = {rho}, eta = {eta}, lambda = {lambda})")
            }
        }
    }

    /// The first parameter out of its family's range: `(name, value,
    /// expected)`.
    pub fn out_of_range(&self) -> Option<(&'static str, f64, String)> {
        match *self {
            SurfaceSpec::Pde6C2 { a, .. } => (!(a.is_finite() && a.abs() <= crate::pde6::A_MAX))
                .then(|| {
                    let m = crate::pde6::A_MAX;
                    (
                        "a",
                        a,
                        format!("|a| <= {m} (the pde6 family's documented range)"),
                    )
                }),
            SurfaceSpec::Ode6C2 { rho, eta, lambda } => {
                let finite = "a finite number".to_string();
                if !(rho.is_finite() && rho != 0.0) {
                    Some(("rho", rho, "finite and not 0 (rho = 0 makes eq 2 of fourth order, which cannot meet eq 1's six constraints)".into()))
                } else if !eta.is_finite() {
                    Some(("eta", eta, finite))
                } else if !lambda.is_finite() {
                    Some(("lambda", lambda, finite))
                } else {
                    None
                }
            }
        }
    }
}

/// One part: a C2 tube through its key sections.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PartSpec {
    pub name: String,
    pub surface: SurfaceSpec,
    pub sections: Vec<SectionSpec>,
    /// The start (`u` = first) is a free end closed by a collapsed ring.
    pub closed_start: bool,
    pub closed_end: bool,
}

/// Which end of a part.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum End {
    Start,
    End,
}

/// A transition joining one end of a parent part to the starts of its
/// children (ordered by model x). Between consecutive children a seam runs
/// from the front to the back of the parent's end ring through `apex`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TransitionSpec {
    pub name: String,
    pub parent: String,
    pub parent_end: End,
    pub children: Vec<String>,
    /// One apex per seam (children - 1).
    pub seam_apex: Vec<[f64; 3]>,
    /// Where each seam cuts the parent's end ring: the front cut's ring
    /// angle in (0, pi), one per seam, decreasing (the back cut mirrors it),
    /// or those followed by the back cuts' angles in (pi, 2 pi), one per
    /// seam, increasing (`character::transition::cut_table`).
    /// Empty: the fixed angles `pi - j pi / k` (`character::transition`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cut_angles: Vec<f64>,
    /// Factor on the Hermite tangent length (the loop-to-ring centroid
    /// distance); 1 by default.
    #[serde(default = "unit_scale", skip_serializing_if = "is_unit_scale")]
    pub tangent_scale: f64,
    /// One factor per child replacing `tangent_scale` for that child
    /// (sketched humanoids: the arms' shorter than the head's). Empty:
    /// `tangent_scale` for every child.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub child_tangent_scales: Vec<f64>,
    /// Order of the blend across the transition (`character::transition`):
    /// `c1` (cubic Hermite, the default) or `c2` (quintic Hermite).
    #[serde(default, skip_serializing_if = "Continuity::is_default")]
    pub continuity: Continuity,
    /// Caps each loop column's cross tangent at its scale where the
    /// parent's end ring flares (`character::tangent_cap::cap_tangents`).
    /// Sketch-guided modeling sets it; false (the default) for documents
    /// written before it and for the closed body.
    #[serde(default, skip_serializing_if = "is_false")]
    pub cap_tangents: bool,
    /// Per child, where its blend starts to move in depth (model z, the
    /// side view's horizontal axis), on the loop's -z and +z sides: `s0`
    /// in `[0, RISE_MAX]` (`character::transition::late_weight`; 0 is
    /// the plain Hermite blend). A column first rises along its parent,
    /// then turns toward the child ring, as a drawn side view does at
    /// square shoulders (sketch-guided modeling fits them to the drawing,
    /// `sketch::tangent_fit`). Empty: 0 for every child.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub child_rises: Vec<[f64; 2]>,
}

/// Cross-tangent scale of the shoulder transition. Measured on the base and
/// nine morphs (README): 0.7 instead of 1 flattens the Hermite bulge in
/// front of the throat (recon -> skin max of african-male-young 3.89 ->
/// 2.68 %, caucasian-female-young 3.38 -> 2.48 %,
/// universal-female-young-averagemuscle-maxweight 3.78 -> 2.80 %), at a
/// cost on the base (2.51 -> 2.94 %); 0.5 overshoots (base 3.2 %).
///
/// Sketched humanoids (`sketch::derive`) give it to the arms only: on the
/// drawing corpus the arms' creases at the neck's seams drop below issue
/// 28's bound (docs/drawing-corpus.md), while the head's at 0.7 moved the
/// neck off the side outline (near_t side 1.82 -> 1.94 %).
pub const SHOULDER_TANGENT_SCALE: f64 = 0.7;

impl TransitionSpec {
    /// The humanoid body plan's two transitions: `hips` (the torso's start to
    /// both legs, one seam through `crotch`) and `shoulders` (the torso's end
    /// to the left arm, the head and the right arm, seams through
    /// `shoulder_apex`, tangent factors `arms` for both arms and `head` for
    /// the head), fixed cut angles (`sketch::derive` widens the shoulders'
    /// to a wide neck just above the torso), C1. Shared by sketch-guided modeling
    /// (`sketch::derive`) and the closed body (`body::joins`).
    pub fn humanoid(
        crotch: [f64; 3],
        shoulder_apex: Vec<[f64; 3]>,
        arms: f64,
        head: f64,
    ) -> Vec<TransitionSpec> {
        let spec =
            |name: &str, end, children: &[&str], seam_apex, tangent_scale, child_tangent_scales| {
                TransitionSpec {
                    name: name.into(),
                    parent: "torso".into(),
                    parent_end: end,
                    children: children.iter().map(|c| c.to_string()).collect(),
                    seam_apex,
                    cut_angles: Vec::new(),
                    tangent_scale,
                    child_tangent_scales,
                    continuity: Continuity::default(),
                    cap_tangents: false,
                    child_rises: Vec::new(),
                }
            };
        let (scale, per_child) = if arms == head {
            (arms, Vec::new())
        } else {
            (1.0, vec![arms, head, arms])
        };
        vec![
            spec(
                "hips",
                End::Start,
                &["leg_l", "leg_r"],
                vec![crotch],
                1.0,
                Vec::new(),
            ),
            spec(
                "shoulders",
                End::End,
                &["arm_l", "head", "arm_r"],
                shoulder_apex,
                scale,
                per_child,
            ),
        ]
    }

    /// The tangent factor of child `c`.
    pub fn child_scale(&self, c: usize) -> f64 {
        self.child_tangent_scales
            .get(c)
            .copied()
            .unwrap_or(self.tangent_scale)
    }
}

/// Continuity of a transition with its parts at its two boundary rings.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Continuity {
    /// Cubic Hermite: position and first cross derivative.
    #[default]
    C1,
    /// Quintic Hermite: position, first and second cross derivatives.
    C2,
}

impl Continuity {
    fn is_default(&self) -> bool {
        *self == Continuity::default()
    }
}

fn unit_scale() -> f64 {
    1.0
}

fn is_unit_scale(x: &f64) -> bool {
    *x == 1.0
}

fn is_false(x: &bool) -> bool {
    !*x
}
