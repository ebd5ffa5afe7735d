//! A part's surface, behind one trait: the assembly asks a part for its
//! sections, points and derivatives ([`PartGeometry`]), never for a
//! family's type. Two families implement it, chosen per part in the
//! document (`surface.family`):
//!
//! * `pde6_c2` ([`pde6`]): the globally solved C2 sixth-order PDE chain
//!   (`pde6::Chain::c2_global`, paper 002) through the key sections, the
//!   default. A part is exactly "a surface interpolating closed cross
//!   sections at increasing u" (paper 000 sec 4.1.1), which the chain solves
//!   globally and stably for any number `3P + 1` of sections with one
//!   Fourier series per section. The PDE parameter `a` is stored per part
//!   (default 0: the quintic per harmonic, which reproduces constants and
//!   converges at order six as sections are added).
//! * `ode6_c2` ([`ode6`]): sixth-order ODE patches (paper 004) between
//!   consecutive sections, C2 at every section, with shape parameters
//!   rho, eta, lambda.
//!
//! A new family is a file here implementing [`PartGeometry`], a variant of
//! [`SurfaceSpec`] and its arm in [`build_part`].

pub mod ode6;
pub mod pde6;

use super::ModelError;
use crate::character::spec::{EndCurvature, PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use crate::curve::gec::{Frame, Gec};
use crate::curve::Fourier3;
use crate::surface::DynSurface;
use std::sync::Arc;

/// What the assembly, the transitions, the edits and SASM ask of a part's
/// surface. `u` is the part's own parameter (its sections' `u`), `v` the
/// section angle `theta` in `[0, 2 pi)`; the [`DynSurface`] methods give
/// points, derivatives and grids in those parameters.
pub trait PartGeometry: DynSurface + std::fmt::Debug {
    /// The section curve at `u` (`d = 0`) or its `d`-th u-derivative
    /// (`d <= 6`), a closed curve in `theta`.
    fn section(&self, u: f64, d: usize) -> Fourier3;

    /// The family's name, as in the document's `surface.family`.
    fn family(&self) -> &'static str;

    /// Largest jumps `[C0, C1, C2]` of `d^k S / du^k` across the surface's
    /// own joins (between its pieces or patches), relative to
    /// `max(|derivative|, 1)`, over `samples` angles per join.
    fn internal_jumps(&self, samples: usize) -> [f64; 3];
}

/// A built part.
#[derive(Clone, Debug)]
pub struct PartSurface {
    pub name: String,
    pub surface: Arc<dyn PartGeometry>,
    pub u0: f64,
    pub u1: f64,
    pub closed_start: bool,
    pub closed_end: bool,
}

fn curve_of(s: &SectionSpec) -> Result<Fourier3, ModelError> {
    let c = s.centre;
    let (e1, e2) = (s.e1, s.e2);
    let lin = |a: f64, b: f64| {
        [
            a * e1[0] + b * e2[0],
            a * e1[1] + b * e2[1],
            a * e1[2] + b * e2[2],
        ]
    };
    Ok(match &s.shape {
        SectionShape::Circle { r } => Fourier3 {
            c0: c,
            cos: vec![lin(*r, 0.0)],
            sin: vec![lin(0.0, *r)],
        },
        SectionShape::Ellipse { a, b, offset } => {
            let o = lin(0.0, *offset);
            Fourier3 {
                c0: [c[0] + o[0], c[1] + o[1], c[2] + o[2]],
                cos: vec![lin(*a, 0.0)],
                sin: vec![lin(0.0, *b)],
            }
        }
        SectionShape::Gec { centre, x, y } => {
            let frame = Frame::new(c, e1, e2)?;
            Gec::new(frame, *centre, x.clone(), y.clone())?.to_fourier3()
        }
    })
}

/// Checks a part's sections and builds its chain.
pub fn build_part(p: &PartSpec) -> Result<PartSurface, ModelError> {
    let bad = |m: String| ModelError::Part {
        part: p.name.clone(),
        message: m,
    };
    let mut curves = Vec::with_capacity(p.sections.len());
    for (i, s) in p.sections.iter().enumerate() {
        let finite = s.u.is_finite()
            && s.centre
                .iter()
                .chain(&s.e1)
                .chain(&s.e2)
                .all(|x| x.is_finite());
        if !finite {
            return Err(bad(format!("section {i} has a non-finite number")));
        }
        let ok = match &s.shape {
            SectionShape::Circle { r } => r.is_finite() && *r >= 0.0,
            SectionShape::Ellipse { a, b, offset } => {
                a.is_finite() && b.is_finite() && offset.is_finite() && *a >= 0.0 && *b >= 0.0
            }
            SectionShape::Gec { .. } => true,
        };
        if !ok {
            return Err(bad(format!(
                "section {i}: radii must be finite and non-negative"
            )));
        }
        curves.push(curve_of(s).map_err(|e| bad(e.to_string()))?);
    }
    let n = curves.iter().map(|c| c.harmonics()).max().unwrap_or(1);
    let sections: Vec<(f64, Fourier3)> = p
        .sections
        .iter()
        .zip(curves)
        .map(|(s, c)| (s.u, c.with_harmonics(n)))
        .collect();
    let surface: Arc<dyn PartGeometry> = match p.surface {
        SurfaceSpec::Pde6C2 { a, open_ends } => {
            let sections: Vec<crate::pde6::Section> = sections
                .into_iter()
                .map(|(u, curve)| crate::pde6::Section { u, curve })
                .collect();
            let end = |closed: bool| {
                if closed {
                    EndCurvature::SixPoint
                } else {
                    open_ends
                }
            };
            let ends = [end(p.closed_start), end(p.closed_end)];
            Arc::new(pde6::build(a, &sections, ends).map_err(|e| bad(e.to_string()))?)
        }
        SurfaceSpec::Ode6C2 { rho, eta, lambda } => {
            if let Some(w) = sections
                .windows(2)
                .position(|w| w[1].0.partial_cmp(&w[0].0) != Some(std::cmp::Ordering::Greater))
            {
                return Err(bad(format!(
                    "the ode6 surface needs increasing section u (sections {w} and {})",
                    w + 1
                )));
            }
            let params = crate::ode6::Params::new(rho, eta, lambda);
            Arc::new(ode6::build(params, &sections).map_err(|e| bad(e.to_string()))?)
        }
    };
    Ok(PartSurface {
        name: p.name.clone(),
        surface,
        u0: p.sections[0].u,
        u1: p.sections[p.sections.len() - 1].u,
        closed_start: p.closed_start,
        closed_end: p.closed_end,
    })
}

impl PartSurface {
    /// The section curve (d = 0) or its d-th u-derivative at `u`.
    pub fn section(&self, u: f64, d: usize) -> Fourier3 {
        self.surface.section(u, d)
    }

    /// The point at `(u, theta)`.
    pub fn point(&self, u: f64, theta: f64) -> [f64; 3] {
        self.surface.point(u, theta)
    }

    /// `d^(i+j) S / du^i dtheta^j` at `(u, theta)`.
    pub fn derivative(&self, u: f64, theta: f64, i: usize, j: usize) -> [f64; 3] {
        self.surface.derivative(u, theta, i, j)
    }

    /// End parameter.
    pub fn end_u(&self, end: crate::character::spec::End) -> f64 {
        match end {
            crate::character::spec::End::Start => self.u0,
            crate::character::spec::End::End => self.u1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::tol;

    fn part(surface: SurfaceSpec) -> PartSpec {
        let section = |u: f64, r: f64| SectionSpec {
            u,
            centre: [0.0, u, 0.0],
            e1: [1.0, 0.0, 0.0],
            e2: [0.0, 0.0, 1.0],
            shape: SectionShape::Ellipse {
                a: r,
                b: 0.8 * r,
                offset: 0.0,
            },
        };
        PartSpec {
            name: "arm".into(),
            surface,
            // 7 sections: the fewest the pde6 chain takes (7 + 3k)
            sections: [
                (0.0, 1.0),
                (0.4, 1.2),
                (0.9, 0.7),
                (1.2, 0.9),
                (1.5, 1.0),
                (1.9, 0.8),
                (2.2, 0.6),
            ]
            .iter()
            .map(|&(u, r)| section(u, r))
            .collect(),
            closed_start: false,
            closed_end: false,
        }
    }

    const ODE6: SurfaceSpec = SurfaceSpec::Ode6C2 {
        rho: 1.0,
        eta: 3.0,
        lambda: 1.0,
    };

    #[test]
    fn both_families_interpolate_the_same_sections_and_name_themselves() {
        let a = build_part(&part(SurfaceSpec::Pde6C2 {
            a: 0.0,
            open_ends: Default::default(),
        }))
        .unwrap();
        let b = build_part(&part(ODE6)).unwrap();
        assert_eq!(a.surface.family(), "pde6_c2");
        assert_eq!(b.surface.family(), "ode6_c2");
        for s in &part(ODE6).sections {
            for th in [0.0, 1.3, 3.9] {
                let pa = a.point(s.u, th);
                let pb = b.point(s.u, th);
                assert!(crate::mesh::dist(pa, pb) < tol::SOLVE, "{pa:?} {pb:?}");
            }
        }
        // between the sections the two equations give two surfaces
        let gap = crate::mesh::dist(a.point(0.2, 0.5), b.point(0.2, 0.5));
        assert!(gap > tol::DETECTED * tol::DETECTED, "{gap}");
    }

    #[test]
    fn the_surface_family_round_trips_through_json_and_its_range_is_checked() {
        let json = serde_json::to_string(&ODE6).unwrap();
        assert_eq!(
            json,
            r#"{"family":"ode6_c2","rho":1.0,"eta":3.0,"lambda":1.0}"#
        );
        assert_eq!(serde_json::from_str::<SurfaceSpec>(&json).unwrap(), ODE6);
        assert!(ODE6.out_of_range().is_none());
        let zero = SurfaceSpec::Ode6C2 {
            rho: 0.0,
            eta: 1.0,
            lambda: 1.0,
        };
        assert_eq!(zero.out_of_range().map(|e| e.0), Some("rho"));
        let nan = SurfaceSpec::Ode6C2 {
            rho: 1.0,
            eta: f64::NAN,
            lambda: 1.0,
        };
        assert_eq!(nan.out_of_range().map(|e| e.0), Some("eta"));
        assert!(build_part(&part(zero)).is_err());
    }

    #[test]
    fn an_ode6_part_with_sections_out_of_order_is_refused_by_name() {
        let mut p = part(ODE6);
        p.sections.swap(1, 2);
        let e = build_part(&p).unwrap_err().to_string();
        assert!(
            e.contains("increasing section u (sections 0 and 1)") || e.contains("sections 1 and 2"),
            "{e}"
        );
    }
}
