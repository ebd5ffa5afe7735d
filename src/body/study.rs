//! The data-size study of the closed body (issue 15 item 5; paper 000
//! Fig 13, paper 002 Fig 6, paper 004 Table 1): how many numbers each
//! surface stores against the mesh's vertex coordinates, and how far it is
//! from the mesh, for three surfaces through the **same** sections at three
//! section densities.
//!
//! For a density, [`super::closed::reconstruct_closed`] finds the
//! layout and fits the GEC sections of every part. Through each part's
//! sections (its collapsed tips included) three tubes are built:
//!
//! * `pde6`: the part's C2 sixth-order PDE chain (`Chain::c2_global`, the
//!   closed body's own part surface);
//! * `ode6`: a C2 chain of sixth-order ODE patches (paper 004, $\rho = 1$,
//!   $\eta = 3$, $\lambda = 1$, as the Table 1 figure of the ode6 family)
//!   whose first and second u-derivative curves at the sections are
//!   centred finite differences of the sections (one-sided at the ends);
//! * `loft`: a natural cubic spline in u through the sections, point by
//!   point in $\theta$ (no derivative data, no PDE).
//!
//! Errors, relative to the body height: `recon -> skin` over the vertices
//! and triangle centroids of a part's tube; `skin -> recon` over the skin
//! vertices nearer to this part's tube than to any other part's tube of the
//! same surface (the same assignment gives the part's share of the mesh's
//! vertex coordinates). The `body` rows take every part together; the
//! `pde6-closed` row is the closed body itself (parts and the hips, wrist and
//! shoulders transitions, the numbers of [`super::report`]), the only
//! surface that covers the armpits and the crotch: the tubes alone leave
//! those out, so their `skin -> recon` maxima sit there.
//!
//! Numbers stored: a fitted section 1 (u) + 9 (frame) + 2 (centre) + 4J, a
//! collapsed tip 4 (u and its point); `pde6` adds its parameter a per part,
//! `ode6` its (rho, eta, lambda), the loft nothing. The mesh stores 3
//! coordinates per vertex (the triangles' indices not counted).

use super::closed::{reconstruct_closed, ClosedOptions};
use super::report::section_numbers;
use super::BodyError;
use crate::character::doc::PartSpec;
use crate::character::part::build_part;
use crate::curve::Fourier3;
use crate::mesh::metrics::{point_distances, sample_points, stats};
use crate::mesh::Mesh;
use crate::ode6::{Basis, Curve, Params};
use crate::surface::{tessellate, tessellate_grid, Domain, Tessellation};
use std::f64::consts::PI;

/// A section density: sections per tube (7 + 3k each, the C2 chain's count).
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Density {
    pub name: &'static str,
    pub torso: usize,
    pub leg: usize,
    pub arm: usize,
    pub head: usize,
}

impl Density {
    /// `base` with this density's section counts.
    pub fn options(&self, base: &ClosedOptions) -> ClosedOptions {
        ClosedOptions {
            torso_sections: self.torso,
            leg_sections: self.leg,
            arm_sections: self.arm,
            head_sections: self.head,
            ..*base
        }
    }
}

/// The study's densities: coarse, the default of [`ClosedOptions`], dense.
pub const DENSITIES: [Density; 3] = [
    Density {
        name: "coarse",
        torso: 7,
        leg: 10,
        arm: 7,
        head: 10,
    },
    Density {
        name: "default",
        torso: 13,
        leg: 19,
        arm: 10,
        head: 16,
    },
    Density {
        name: "dense",
        torso: 19,
        leg: 28,
        arm: 16,
        head: 25,
    },
];

/// The surfaces compared.
pub const METHODS: [&str; 3] = ["pde6", "ode6", "loft"];

/// ODE6 shape parameters of the study (rho, eta, lambda).
pub const ODE6_PARAMS: [f64; 3] = [1.0, 3.0, 1.0];

/// Tessellation: rings per body height along a tube, points around it.
pub const STUDY_RINGS_PER_HEIGHT: f64 = 120.0;
pub const STUDY_NV: usize = 96;

/// One row: a part (or `body`) under one surface at one density.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StudyRow {
    pub density: &'static str,
    pub method: &'static str,
    pub part: String,
    pub sections: usize,
    pub stored_numbers: usize,
    pub mesh_numbers: usize,
    pub recon_to_skin_rms_rel: f64,
    pub recon_to_skin_max_rel: f64,
    pub skin_to_recon_rms_rel: f64,
    pub skin_to_recon_max_rel: f64,
}

/// Natural cubic spline second derivatives at `knots` of values `y`.
fn spline_m2(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    let mut m = vec![0.0; n];
    if n < 3 {
        return m;
    }
    // tridiagonal system for the interior second derivatives (Thomas)
    let (mut c, mut d) = (vec![0.0; n], vec![0.0; n]);
    for i in 1..n - 1 {
        let (h0, h1) = (x[i] - x[i - 1], x[i + 1] - x[i]);
        let rhs = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
        let diag = 2.0 * (h0 + h1) - h0 * c[i - 1];
        c[i] = h1 / diag;
        d[i] = (rhs - h0 * d[i - 1]) / diag;
    }
    for i in (1..n - 1).rev() {
        m[i] = d[i] - c[i] * m[i + 1];
    }
    m
}

fn spline_eval(x: &[f64], y: &[f64], m: &[f64], u: f64) -> f64 {
    let n = x.len();
    let i = x.partition_point(|&k| k <= u).clamp(1, n - 1) - 1;
    let h = x[i + 1] - x[i];
    let (a, b) = ((x[i + 1] - u) / h, (u - x[i]) / h);
    a * y[i] + b * y[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0
}

/// The three tubes of one part: `(method, mesh)`.
fn tubes(p: &PartSpec, h: f64) -> Result<Vec<(&'static str, Mesh)>, BodyError> {
    let part = build_part(p)?;
    let us: Vec<f64> = p.sections.iter().map(|s| s.u).collect();
    let curves: Vec<Fourier3> = us.iter().map(|&u| part.section(u, 0)).collect();
    let (u0, u1) = (us[0], us[us.len() - 1]);
    let nu = (((u1 - u0) / h * STUDY_RINGS_PER_HEIGHT).ceil() as usize).max(us.len());
    let pde6 = tessellate(&*part.surface, Tessellation { nu, nv: STUDY_NV });
    // ode6: finite-difference derivative curves in the patch parameter
    let n = curves.len();
    let sections: Vec<[Curve; 3]> = (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            let w = 1.0 / (b - a) as f64;
            let d1 = Fourier3::weighted_sum(&[(w, &curves[b]), (-w, &curves[a])]);
            let m = i.clamp(1, n - 2);
            let d2 = Fourier3::weighted_sum(&[
                (1.0, &curves[m - 1]),
                (-2.0, &curves[m]),
                (1.0, &curves[m + 1]),
            ]);
            [
                Curve::Fourier(curves[i].clone()),
                Curve::Fourier(d1),
                Curve::Fourier(d2),
            ]
        })
        .collect();
    let [rho, eta, lambda] = ODE6_PARAMS;
    let bases = (0..n - 1)
        .map(|_| Basis::new(Params::new(rho, eta, lambda)))
        .collect::<Result<Vec<_>, _>>()?;
    let chain = crate::ode6::Chain::from_sections(&sections, bases)?;
    let ode6 = tessellate(&chain, Tessellation { nu, nv: STUDY_NV });
    // loft: natural cubic spline in u through the section points
    let grid_u: Vec<f64> = (0..=nu)
        .map(|i| u0 + (u1 - u0) * i as f64 / nu as f64)
        .collect();
    let mut pts = vec![[0.0; 3]; grid_u.len() * STUDY_NV];
    for j in 0..STUDY_NV {
        let t = 2.0 * PI * j as f64 / STUDY_NV as f64;
        let p: Vec<[f64; 3]> = curves.iter().map(|c| c.eval(t)).collect();
        for k in 0..3 {
            let y: Vec<f64> = p.iter().map(|q| q[k]).collect();
            let m2 = spline_m2(&us, &y);
            for (i, &u) in grid_u.iter().enumerate() {
                pts[i * STUDY_NV + j][k] = spline_eval(&us, &y, &m2, u);
            }
        }
    }
    let loft = tessellate_grid(
        pts,
        grid_u.len(),
        STUDY_NV,
        Domain {
            u: (u0, u1),
            v: (0.0, 2.0 * PI),
            closed_u: false,
            closed_v: true,
        },
    );
    Ok(vec![("pde6", pde6), ("ode6", ode6), ("loft", loft)])
}

/// Runs the study on `skin` at each density (see the module doc).
pub fn data_size_study(
    skin: &Mesh,
    densities: &[Density],
    base: &ClosedOptions,
) -> Result<Vec<StudyRow>, BodyError> {
    let mut rows = Vec::new();
    for d in densities {
        let o = d.options(base);
        let body = reconstruct_closed(skin, &o)?;
        let r = &body.report;
        let h = r.body_height;
        let all_sections: usize = body.specs.iter().map(|p| p.sections.len()).sum();
        rows.push(StudyRow {
            density: d.name,
            method: "pde6-closed",
            part: "body".into(),
            sections: all_sections,
            stored_numbers: r.gec_numbers + body.specs.len(),
            mesh_numbers: r.skin_vertex_numbers,
            recon_to_skin_rms_rel: r.recon_to_skin_rms_rel,
            recon_to_skin_max_rel: r.recon_to_skin_max_rel,
            skin_to_recon_rms_rel: r.skin_to_recon_rms_rel,
            skin_to_recon_max_rel: r.skin_to_recon_max_rel,
        });
        let mut meshes: Vec<Vec<(&'static str, Mesh)>> = Vec::new();
        for p in &body.specs {
            meshes.push(tubes(p, h)?);
        }
        for (mi, method) in METHODS.iter().enumerate() {
            // skin vertices assigned to their nearest tube of this method
            let per_part: Vec<Vec<f64>> = meshes
                .iter()
                .map(|m| point_distances(&skin.positions, &m[mi].1))
                .collect();
            let mut owner = vec![0usize; skin.positions.len()];
            let mut nearest = vec![f64::INFINITY; skin.positions.len()];
            for (pi, d) in per_part.iter().enumerate() {
                for (v, &x) in d.iter().enumerate() {
                    if x < nearest[v] {
                        nearest[v] = x;
                        owner[v] = pi;
                    }
                }
            }
            let extra = match *method {
                "pde6" => 1,
                "ode6" => 3,
                _ => 0,
            };
            let mut all_r2s = Vec::new();
            let mut total_stored = 0;
            for (pi, p) in body.specs.iter().enumerate() {
                let r2s = point_distances(&sample_points(&meshes[pi][mi].1), skin);
                let mine: Vec<f64> = (0..skin.positions.len())
                    .filter(|&v| owner[v] == pi)
                    .map(|v| nearest[v])
                    .collect();
                let (a, b) = (stats(&r2s), stats(&mine));
                let stored = section_numbers(p) + extra;
                total_stored += stored;
                rows.push(StudyRow {
                    density: d.name,
                    method,
                    part: p.name.clone(),
                    sections: p.sections.len(),
                    stored_numbers: stored,
                    mesh_numbers: 3 * mine.len(),
                    recon_to_skin_rms_rel: a.rms / h,
                    recon_to_skin_max_rel: a.max / h,
                    skin_to_recon_rms_rel: b.rms / h,
                    skin_to_recon_max_rel: b.max / h,
                });
                all_r2s.extend(r2s);
            }
            let (a, b) = (stats(&all_r2s), stats(&nearest));
            rows.push(StudyRow {
                density: d.name,
                method,
                part: "body".into(),
                sections: all_sections,
                stored_numbers: total_stored,
                mesh_numbers: 3 * skin.positions.len(),
                recon_to_skin_rms_rel: a.rms / h,
                recon_to_skin_max_rel: a.max / h,
                skin_to_recon_rms_rel: b.rms / h,
                skin_to_recon_max_rel: b.max / h,
            });
        }
    }
    Ok(rows)
}
