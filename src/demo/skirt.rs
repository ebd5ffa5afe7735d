//! A garment from boundary and control curves (paper 004): a skirt fitted to
//! the sculpted body as one C2 sixth-order ODE surface.
//!
//! Paper 004's approach 2 builds a surface from two boundary curves and four
//! control curves: the surface passes through the boundary curves at
//! $u = 0, 1$ and takes its end tangents and curvatures from the control
//! curves through difference formulas (here the three-point quadratic ones,
//! [`DiffFormula::ThreePoint`]). The curves are horizontal rings around a
//! vertical axis through the waist: each is the support function of the
//! body's cross section at its height (the convex outline, so both thighs
//! end up inside the skirt) plus an ease that grows towards the hem,
//!
//! $$ r(\theta, y) = \max_{p \in \text{section}(y)} (p - c)\cdot(\cos\theta, \sin\theta) + e(u), $$
//!
//! sampled at the same angles on every ring so that $v$ means the same
//! direction on all six curves. The ODE
//! $\rho S^{(6)} + \eta S^{(4)} + \lambda S'' = 0$ then fills the skirt
//! between waist and hem. Whether it clears the body is measured, not
//! assumed: every skirt vertex is compared with its closest point on the
//! body.

use crate::mesh::metrics::TriangleBvh;
use crate::mesh::slice::slice;
use crate::mesh::{dot, sub, Mesh};
use crate::ode6::{Approach2, Basis, BoundaryCurves, Curve, DiffFormula, Ode6Surface, Params};
use crate::surface::{tessellate, Tessellation};
use serde::Serialize;
use std::f64::consts::PI;

/// Where and how the skirt is made (decimetres, the body's units).
/// Outside the crate, start from [`SkirtOptions::default`] and change
/// fields with the `with_*` setters (or by assignment).
#[derive(Clone, Copy, Debug, Serialize)]
#[non_exhaustive]
pub struct SkirtOptions {
    /// Height of the waistband ring (default 0.4).
    pub waist_y: f64,
    /// Height of the hem ring (default -3.2).
    pub hem_y: f64,
    /// Ease at the waistband (default 0.06); the ease along the skirt is
    /// e(u) = ease + flare u^2.
    pub ease: f64,
    /// Ease added at the hem (default 0.5).
    pub flare: f64,
    /// Shape parameter rho of the ODE (default 1).
    pub rho: f64,
    /// Shape parameter eta of the ODE (default 3).
    pub eta: f64,
    /// Shape parameter lambda of the ODE (default 1).
    pub lambda: f64,
    /// Samples per ring (default 64).
    pub ring_samples: usize,
    /// Cross sections farther than this from the axis (arms, hands) are
    /// ignored (default 3).
    pub max_reach: f64,
}

setters!(SkirtOptions {
    with_waist_y: waist_y: f64,
    with_hem_y: hem_y: f64,
    with_ease: ease: f64,
    with_flare: flare: f64,
    with_rho: rho: f64,
    with_eta: eta: f64,
    with_lambda: lambda: f64,
    with_ring_samples: ring_samples: usize,
    with_max_reach: max_reach: f64,
});

impl Default for SkirtOptions {
    fn default() -> Self {
        SkirtOptions {
            waist_y: 0.4,
            hem_y: -3.2,
            ease: 0.06,
            flare: 0.5,
            rho: 1.0,
            eta: 3.0,
            lambda: 1.0,
            ring_samples: 64,
            max_reach: 3.0,
        }
    }
}

/// What the skirt measured.
#[derive(Clone, Debug, Serialize)]
pub struct SkirtReport {
    pub options: SkirtOptions,
    /// Control curve positions u2, u3, u5, u6.
    pub control_u: [f64; 4],
    pub vertices: usize,
    pub triangles: usize,
    /// Numbers stored by the ODE representation (six rings' trigonometric
    /// coefficients and three shape parameters) against the mesh's vertex
    /// coordinates.
    pub ode_numbers: usize,
    pub mesh_numbers: usize,
    /// Smallest signed distance from a skirt vertex to the body (negative:
    /// inside, judged by the closest face's normal).
    pub min_clearance: f64,
    /// Fraction of skirt vertices inside the body.
    pub inside_fraction: f64,
    /// Largest distance between the skirt and its six defining rings at
    /// their u positions (boundary rings exact, control rings approximate:
    /// approach 2 interpolates only through its boundary curves).
    pub waist_ring_error: f64,
    pub hem_ring_error: f64,
}

/// A failure to make the skirt.
#[derive(Debug, thiserror::Error)]
pub enum SkirtError {
    #[error("skirt: {0}")]
    Options(String),
    /// The tessellated skirt is not a valid mesh.
    #[error("skirt: tessellation: {0}")]
    Tessellation(#[source] crate::mesh::MeshError),
    #[error("skirt: the body has no cross section at y = {0} within reach of the axis")]
    NoSection(f64),
    #[error("skirt: {0}")]
    Ode6(#[from] crate::ode6::Ode6Error),
}

/// Points of the cross sections of `body` at height `y` within `reach` of
/// the vertical axis through `(cx, cz)`.
fn section_points(body: &Mesh, y: f64, axis: [f64; 2], reach: f64) -> Vec<[f64; 2]> {
    slice(body, [0.0, y, 0.0], [0.0, 1.0, 0.0])
        .into_iter()
        .filter(|p| p.closed)
        .flat_map(|p| p.points)
        .map(|p| [p[0] - axis[0], p[2] - axis[1]])
        .filter(|d| d[0].hypot(d[1]) <= reach)
        .collect()
}

/// The support function of `pts` at `m` equally spaced angles.
fn support(pts: &[[f64; 2]], m: usize) -> Vec<f64> {
    (0..m)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / m as f64;
            pts.iter()
                .map(|p| p[0] * t.cos() + p[1] * t.sin())
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .collect()
}

/// A ring at height `y`: radius `r[k] + ease` at angle `2 pi k / m`.
fn ring(axis: [f64; 2], y: f64, r: &[f64], ease: f64) -> Vec<[f64; 3]> {
    let m = r.len();
    (0..m)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / m as f64;
            [
                axis[0] + (r[k] + ease) * t.cos(),
                y,
                axis[1] + (r[k] + ease) * t.sin(),
            ]
        })
        .collect()
}

/// Intervals of the tessellation from waist to hem.
const NU: usize = 40;

/// Builds the skirt around `body` (y up, the body facing +z). Returns the
/// tessellated skirt (group `"skirt"`) and its report.
pub fn skirt(body: &Mesh, o: &SkirtOptions) -> Result<(Mesh, SkirtReport), SkirtError> {
    check_options(o)?;
    let c = skirt_axis(body, o)?;
    let control_u = [0.2, 0.4, 0.6, 0.8];
    let rings = skirt_rings(body, o, c, control_u)?;
    let surface = skirt_surface(&rings, control_u, o)?;
    let ode_numbers = surface.scalars();
    let mut mesh = tessellate(
        &surface,
        Tessellation {
            nu: NU,
            nv: 2 * o.ring_samples,
        },
    );
    mesh.set_single_group("skirt");
    orient_outwards(&mut mesh, c);
    let (min_clearance, inside) = clearance(body, &mesh);
    // tessellation column 2j is ring sample j (nv = 2 ring_samples)
    let nv = 2 * o.ring_samples;
    let ring_error = |row: usize, k: usize| {
        rings[k]
            .iter()
            .enumerate()
            .map(|(j, q)| crate::mesh::dist(mesh.positions[row * nv + 2 * j], *q))
            .fold(0.0, f64::max)
    };
    let report = SkirtReport {
        options: *o,
        control_u,
        vertices: mesh.positions.len(),
        triangles: mesh.triangles.len(),
        ode_numbers,
        mesh_numbers: 3 * mesh.positions.len(),
        min_clearance,
        inside_fraction: inside as f64 / mesh.positions.len() as f64,
        waist_ring_error: ring_error(0, 0),
        hem_ring_error: ring_error(NU, 5),
    };
    mesh.validate().map_err(SkirtError::Tessellation)?;
    Ok((mesh, report))
}

/// Refuses options not finite, a hem not below the waist, a negative ease
/// or flare, a reach not positive, and ring samples outside 8..=1024.
fn check_options(o: &SkirtOptions) -> Result<(), SkirtError> {
    let finite = [
        o.waist_y,
        o.hem_y,
        o.ease,
        o.flare,
        o.rho,
        o.eta,
        o.lambda,
        o.max_reach,
    ]
    .iter()
    .all(|x| x.is_finite());
    if !finite || o.hem_y >= o.waist_y || o.ease < 0.0 || o.flare < 0.0 || o.max_reach <= 0.0 {
        return Err(SkirtError::Options(format!(
            "need finite options with hem_y < waist_y, ease >= 0, flare >= 0, max_reach > 0 (got {o:?})"
        )));
    }
    if !(8..=1024).contains(&o.ring_samples) {
        return Err(SkirtError::Options(format!(
            "ring_samples {} outside 8..=1024",
            o.ring_samples
        )));
    }
    Ok(())
}

/// The skirt's axis (x, z): the centre of the waist section's points
/// (within reach of the bounding box's vertical centre line).
fn skirt_axis(body: &Mesh, o: &SkirtOptions) -> Result<[f64; 2], SkirtError> {
    let (lo, hi) = body.bbox();
    let mid = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[2] + hi[2])];
    let waist = section_points(body, o.waist_y, mid, o.max_reach);
    if waist.is_empty() {
        return Err(SkirtError::NoSection(o.waist_y));
    }
    let n = waist.len() as f64;
    Ok([0, 1].map(|k| mid[k] + waist.iter().map(|p| p[k]).sum::<f64>() / n))
}

/// The six rings around the body about axis `c`: at the waist, at the
/// control parameters `control_u` and at the hem, each the body's support
/// plus the ease and the flare at its height.
fn skirt_rings(
    body: &Mesh,
    o: &SkirtOptions,
    c: [f64; 2],
    control_u: [f64; 4],
) -> Result<Vec<Vec<[f64; 3]>>, SkirtError> {
    let us = [
        0.0,
        control_u[0],
        control_u[1],
        control_u[2],
        control_u[3],
        1.0,
    ];
    let mut rings = Vec::with_capacity(6);
    for &u in &us {
        let y = o.waist_y + (o.hem_y - o.waist_y) * u;
        let pts = section_points(body, y, c, o.max_reach);
        if pts.is_empty() {
            return Err(SkirtError::NoSection(y));
        }
        rings.push(ring(
            c,
            y,
            &support(&pts, o.ring_samples),
            o.ease + o.flare * u * u,
        ));
    }
    Ok(rings)
}

/// The ODE6 surface through the rings: waist and hem the boundary curves,
/// the four control rings the keys of approach 2.
fn skirt_surface(
    rings: &[Vec<[f64; 3]>],
    control_u: [f64; 4],
    o: &SkirtOptions,
) -> Result<Ode6Surface, SkirtError> {
    let curve = |k: usize| Curve::from_polyline(&rings[k], true);
    // keys of approach 2: [c1, c̄2, c̄3, c̄5, c̄6, c4]; c̄5 is the control
    // curve farther from the hem (u5 < u6)
    let a2 = Approach2 {
        u2: control_u[0],
        u3: control_u[1],
        u5: control_u[2],
        u6: control_u[3],
        formula: DiffFormula::ThreePoint,
    };
    let curves = BoundaryCurves::approach2(
        curve(0)?,
        [curve(1)?, curve(2)?, curve(3)?, curve(4)?],
        curve(5)?,
        &a2,
    )?;
    let basis = Basis::new(Params::new(o.rho, o.eta, o.lambda))?;
    Ok(Ode6Surface::new(basis, curves))
}

/// Turns the triangles so the skirt's outside faces away from the axis
/// `c` (judged at the first triangle).
fn orient_outwards(mesh: &mut Mesh, c: [f64; 2]) {
    let p0 = mesh.positions[mesh.triangles[0][0] as usize];
    let nrm = mesh.face_normal_area(0);
    if dot(nrm, [p0[0] - c[0], 0.0, p0[2] - c[1]]) < 0.0 {
        for t in &mut mesh.triangles {
            t.swap(1, 2);
        }
    }
}

/// The clearance against the body: the smallest signed distance of a
/// skirt vertex from it (negative inside) and the number of vertices
/// inside.
fn clearance(body: &Mesh, mesh: &Mesh) -> (f64, usize) {
    let bvh = TriangleBvh::new(body);
    let mut min_clearance = f64::INFINITY;
    let mut inside = 0usize;
    for p in &mesh.positions {
        if let Some((q, d, t)) = bvh.closest(*p) {
            let s = if dot(sub(*p, q), body.face_normal_area(t)) < 0.0 {
                inside += 1;
                -d
            } else {
                d
            };
            min_clearance = min_clearance.min(s);
        }
    }
    (min_clearance, inside)
}
