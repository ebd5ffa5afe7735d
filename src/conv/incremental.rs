//! Rebuilding only what changed (issue 16): when one stroke of a model is
//! edited, the sketches (skeleton, weights, global fit) of every other
//! stroke and the meshes of every component group it does not touch are
//! reused.
//!
//! Reuse is keyed by content, compared exactly: a sketch by its raw stroke
//! and the options, a group's mesh by its world-space segments with their
//! kernel widths, the resolution, the threshold and the polygoniser. A
//! reused result is therefore the one a full rebuild would compute, bit for
//! bit (the test `incremental_rebuild_equals_full_build` compares them).

use super::kernel::Segment;
use super::model::{BuiltModel, Polygonizer};
use super::sample::Sampler;
pub use super::sketch_cache::SketchCache;
use super::ConvError;
use crate::mesh::Mesh;

type MeshKey = (Vec<(Segment, f64)>, usize, u64, Polygonizer);

/// Group meshes by (segments with kernel widths, resolution, threshold,
/// polygoniser).
#[derive(Clone, Debug, Default)]
pub struct MeshCache {
    entries: Vec<(MeshKey, Option<Mesh>)>,
    /// Group meshes polygonised since the cache was made.
    pub built: usize,
    /// Group meshes reused.
    pub reused: usize,
}

impl MeshCache {
    /// [`BuiltModel::polygonize`] reusing the mesh of every group whose
    /// segments are unchanged; entries of groups that no longer exist are
    /// dropped.
    pub fn polygonize(
        &mut self,
        built: &BuiltModel,
        resolution: usize,
        threshold: f64,
        method: Polygonizer,
    ) -> Result<Mesh, ConvError> {
        let mut out: Option<Mesh> = None;
        let mut keep: Vec<(MeshKey, Option<Mesh>)> = Vec::new();
        for (g, members) in built.groups.iter().enumerate() {
            let segs: Vec<(Segment, f64)> = members
                .iter()
                .flat_map(|&i| {
                    let c = &built.components[i];
                    c.segments.iter().map(move |s| (*s, c.sketch.s))
                })
                .collect();
            let key: MeshKey = (segs, resolution, threshold.to_bits(), method);
            let mesh = match self.entries.iter().position(|(k, _)| *k == key) {
                Some(i) => {
                    self.reused += 1;
                    self.entries.swap_remove(i).1
                }
                None => {
                    self.built += 1;
                    built.polygonize_group(g, resolution, threshold, method, Sampler::NarrowBand)?
                }
            };
            if let Some(mut m) = mesh.clone() {
                m.groups = vec![built.components[members[0]].name.clone()];
                match &mut out {
                    None => out = Some(m),
                    Some(o) => o.append(&m),
                }
            }
            keep.push((key, mesh));
        }
        self.entries = keep;
        let m = out.ok_or_else(|| ConvError::Numerical("the model produced no surface".into()))?;
        if m.triangles.is_empty() {
            return Err(ConvError::Numerical(
                "the surface is empty at this resolution".into(),
            ));
        }
        Ok(m)
    }
}
