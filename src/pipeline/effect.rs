//! Edits (and documents) validated by their effect (issue 35): an edit, or
//! a redo, is accepted only if the document it produces builds, with
//! finite geometry and a finite report, and the model stays within a bound
//! of its size before the edit.
//!
//! `pipeline::session::validate_by_build` is the one entry point (`character edit`, `redo`,
//! the TUI's pushes through [`super::push_checked`]); it builds once with
//! [`super::build`], the one document-to-model build. [`finite_result`] is what every build checks: a
//! build whose mesh or report holds a non-finite number is an error
//! naming the part or the report field, never a report printed with
//! `NaN` and exit 0.

use crate::character::spec::{PartSpec, SectionShape};
use crate::mesh::Mesh;
use crate::sketch::report::SketchReport;
use crate::sketch::SketchError;

/// How far an edit may move the model: the edited model's bounding box
/// must lie inside the box before the edit grown on every side by this
/// many times that box's diagonal. Ten model sizes: far beyond any
/// sculpting gesture (the bundled edits move a part by under one size),
/// short of a force of 1e30 that throws an arm 1e27 metres away.
pub const GROWTH: f64 = 10.0;

/// The axis-aligned bounding box of a model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extent {
    pub lo: [f64; 3],
    pub hi: [f64; 3],
}

impl Extent {
    /// The bounding box of `m`'s vertices.
    pub fn of(m: &Mesh) -> Extent {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in &m.positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        Extent { lo, hi }
    }

    /// The box of a document's stored (unedited) parts: every section's
    /// centre plus and minus its largest radius. The reference an edit is
    /// measured against: it does not move with the edits, so repeated edits
    /// cannot creep past the bound.
    pub fn of_parts(parts: &[PartSpec]) -> Extent {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for s in parts.iter().flat_map(|p| &p.sections) {
            let r = match &s.shape {
                SectionShape::Circle { r } => *r,
                SectionShape::Ellipse { a, b, offset } => a.max(*b) + offset.abs(),
                SectionShape::Gec { centre, x, y } => {
                    centre[0].hypot(centre[1])
                        + x.iter().chain(y).map(|c| c[0].hypot(c[1])).sum::<f64>()
                }
            };
            for k in 0..3 {
                lo[k] = lo[k].min(s.centre[k] - r);
                hi[k] = hi[k].max(s.centre[k] + r);
            }
        }
        Extent { lo, hi }
    }

    /// The bounding box of the vertices of `m`'s triangles outside the
    /// groups named in `skip`.
    pub fn of_groups(m: &Mesh, skip: &[&str]) -> Extent {
        let keep: Vec<bool> = m
            .groups
            .iter()
            .map(|g| !skip.contains(&g.as_str()))
            .collect();
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for (t, &g) in m.triangles.iter().zip(&m.tri_group) {
            if !keep.get(g as usize).copied().unwrap_or(true) {
                continue;
            }
            for &v in t {
                let p = m.positions[v as usize];
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        Extent { lo, hi }
    }

    /// The diagonal's length.
    pub fn diagonal(&self) -> f64 {
        crate::vec3::dist(self.lo, self.hi)
    }

    /// How far `other` reaches outside this box, in this box's diagonals.
    pub fn overreach(&self, other: &Extent) -> f64 {
        let d = self.diagonal().max(f64::MIN_POSITIVE);
        let mut worst = 0.0f64;
        for k in 0..3 {
            worst = worst
                .max((self.lo[k] - other.lo[k]) / d)
                .max((other.hi[k] - self.hi[k]) / d);
        }
        worst
    }
}

/// Refuses a build whose mesh has a non-finite vertex (naming its part)
/// or whose report holds a non-finite number (naming the field).
pub fn finite_result(mesh: &Mesh, report: &SketchReport) -> Result<(), SketchError> {
    if let Some(i) = mesh
        .positions
        .iter()
        .position(|p| p.iter().any(|x| !x.is_finite()))
    {
        let group = mesh
            .triangles
            .iter()
            .position(|t| t.contains(&(i as u32)))
            .and_then(|t| mesh.tri_group.get(t))
            .and_then(|&g| mesh.groups.get(g as usize))
            .map_or("?".to_string(), |g| format!("'{g}'"));
        return Err(SketchError::NonFiniteVertex {
            index: i,
            position: mesh.positions[i],
            group,
        });
    }
    if let Some(nf) = crate::limits::first_non_finite(report) {
        return Err(SketchError::NonFiniteReport {
            path: nf.path,
            value: nf.value,
        });
    }
    Ok(())
}
