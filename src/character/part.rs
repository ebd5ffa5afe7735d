//! A part's surface: the globally solved C2 sixth-order PDE chain
//! (`pde6::Chain::c2_global`, paper 002) through its key sections.
//!
//! Why pde6 and not ode6: a part is exactly "a surface interpolating closed
//! cross sections at increasing u" (paper 000 sec 4.1.1), which is what the
//! C2 chain solves globally and stably for any number `3P + 1` of sections
//! with one Fourier series per section; ode6 needs boundary and control curves
//! per patch and a grid of patches for the same job. The PDE parameter `a` is
//! stored per part (default 0: the quintic per harmonic, which reproduces
//! constants and converges at order six as sections are added).

use super::ModelError;
use crate::character::spec::{PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use crate::curve::gec::{Frame, Gec};
use crate::curve::Fourier3;
use crate::pde6::{Chain, Section};

/// A built part.
#[derive(Clone, Debug)]
pub struct PartSurface {
    pub name: String,
    pub chain: Chain,
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
            let frame = Frame::new(c, e1, e2).map_err(|e| ModelError::Section(e.to_string()))?;
            Gec::new(frame, *centre, x.clone(), y.clone())
                .map_err(|e| ModelError::Section(e.to_string()))?
                .to_fourier3()
        }
    })
}

/// Checks a part's sections and builds its chain.
pub fn build_part(p: &PartSpec) -> Result<PartSurface, ModelError> {
    let bad = |m: String| ModelError::Part {
        part: p.name.clone(),
        message: m,
    };
    let SurfaceSpec::Pde6C2 { a } = p.surface;
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
    let sections: Vec<Section> = p
        .sections
        .iter()
        .zip(curves)
        .map(|(s, c)| Section {
            u: s.u,
            curve: c.with_harmonics(n),
        })
        .collect();
    let chain = Chain::c2_global(a, &sections).map_err(|e| bad(e.to_string()))?;
    Ok(PartSurface {
        name: p.name.clone(),
        chain,
        u0: p.sections[0].u,
        u1: p.sections[p.sections.len() - 1].u,
        closed_start: p.closed_start,
        closed_end: p.closed_end,
    })
}

impl PartSurface {
    /// The section curve (d = 0) or its d-th u-derivative at `u`.
    pub fn section(&self, u: f64, d: usize) -> Fourier3 {
        let k = self.chain.piece_at(u);
        self.chain.pieces[k].global_section(u, d)
    }

    /// End parameter.
    pub fn end_u(&self, end: crate::character::spec::End) -> f64 {
        match end {
            crate::character::spec::End::Start => self.u0,
            crate::character::spec::End::End => self.u1,
        }
    }
}
