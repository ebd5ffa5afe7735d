//! Outlines remembered by the mesh they came from (issue 30).
//!
//! A fit asks for the outline of the same skin several times per pass:
//! the refine step measures the front and side outlines after a level, the
//! side pass extracts the side outline again to move it, the depth spans
//! and the height remap extract the front, the shelf and feature warps the
//! front again, and the study measures each level's outlines once more
//! after the fit. The skin has not moved between most of these calls, and
//! an outline (exact scanline coverage of 13 k triangles on a 1000-pixel
//! grid) is the fit's largest cost. [`OutlineMemo`] wraps an
//! [`OutlineFn`] and returns the outline it computed before for a mesh
//! equal bit for bit (positions compared by their bits, triangles, groups)
//! in the same view, so results are identical with and without it.
//!
//! Only successful outlines are kept (an error is computed again, so its
//! message is the function's own). The memo holds the last
//! [`OutlineMemo::CAPACITY`] meshes per memo; it lives as long as one fit
//! or one study case.

use super::{OutlineFn, TemplateError, View};
use crate::mesh::Mesh;
use std::collections::VecDeque;
use std::sync::Mutex;

struct Entry {
    view: View,
    mesh: Mesh,
    outline: Vec<[f64; 2]>,
}

/// An outline function with a memory of its last results.
pub struct OutlineMemo<'a> {
    outline: &'a OutlineFn<'a>,
    entries: Mutex<VecDeque<Entry>>,
    hits: std::sync::atomic::AtomicUsize,
}

/// Positions equal bit for bit (a `-0.0` is not a `0.0`, a NaN equals the
/// same NaN), then triangles and groups.
fn same_mesh(a: &Mesh, b: &Mesh) -> bool {
    a.positions.len() == b.positions.len()
        && a.triangles == b.triangles
        && a.tri_group == b.tri_group
        && a.groups == b.groups
        && a.positions
            .iter()
            .zip(&b.positions)
            .all(|(p, q)| (0..3).all(|k| p[k].to_bits() == q[k].to_bits()))
}

impl<'a> OutlineMemo<'a> {
    /// Meshes remembered: a fit pass alternates between at most the
    /// positions before and after a move, each in two views, and the
    /// trunk's outline of the side pass (a mesh without the arms' triangles).
    pub const CAPACITY: usize = 8;

    pub fn new(outline: &'a OutlineFn<'a>) -> Self {
        OutlineMemo {
            outline,
            entries: Mutex::new(VecDeque::new()),
            hits: Default::default(),
        }
    }

    /// How many calls were answered from memory.
    pub fn hits(&self) -> usize {
        self.hits.load(std::sync::atomic::Ordering::Relaxed)
    }

    /// The outline of `mesh` in `view`: remembered, or computed by the
    /// wrapped function and remembered.
    pub fn outline(&self, mesh: &Mesh, view: View) -> Result<Vec<[f64; 2]>, TemplateError> {
        if let Ok(entries) = self.entries.lock() {
            if let Some(e) = entries
                .iter()
                .find(|e| e.view == view && same_mesh(&e.mesh, mesh))
            {
                self.hits.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                return Ok(e.outline.clone());
            }
        }
        let outline = (self.outline)(mesh, view)?;
        if let Ok(mut entries) = self.entries.lock() {
            if entries.len() == Self::CAPACITY {
                entries.pop_front();
            }
            entries.push_back(Entry {
                view,
                mesh: mesh.clone(),
                outline: outline.clone(),
            });
        }
        Ok(outline)
    }
}
