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
use super::sketch::{self, ConvOptions, Sketch};
use super::ConvError;
use crate::mesh::Mesh;

/// Sketches by (stroke, options).
#[derive(Clone, Debug, Default)]
pub struct SketchCache {
    /// (stroke, options, sketch, prefetched and not yet handed out)
    entries: Vec<(Vec<[f64; 2]>, ConvOptions, Sketch, bool)>,
    /// Sketches built (not reused) since the cache was made.
    pub built: usize,
    /// Sketches reused.
    pub reused: usize,
}

impl SketchCache {
    /// The sketch of `stroke` under `opts`, reused when present.
    pub fn sketch(&mut self, stroke: &[[f64; 2]], opts: &ConvOptions) -> Result<Sketch, ConvError> {
        if let Some((_, _, sk, fresh)) = self
            .entries
            .iter_mut()
            .find(|(s, o, _, _)| s.as_slice() == stroke && o == opts)
        {
            if *fresh {
                self.built += 1;
                *fresh = false;
            } else {
                self.reused += 1;
            }
            return Ok(sk.clone());
        }
        let sk = sketch::build(stroke, opts)?;
        self.built += 1;
        self.entries
            .push((stroke.to_vec(), *opts, sk.clone(), false));
        Ok(sk)
    }

    /// Builds the missing sketches of `strokes` under `opts` on the
    /// available cores (each stroke's fit is independent of the others).
    /// Failures are not cached: [`Self::sketch`] reports them.
    pub fn prefetch(&mut self, strokes: &[&[[f64; 2]]], opts: &ConvOptions) {
        let mut missing: Vec<&[[f64; 2]]> = Vec::new();
        for s in strokes {
            let known = self
                .entries
                .iter()
                .any(|(e, o, _, _)| e.as_slice() == *s && o == opts);
            if !known && !missing.contains(s) {
                missing.push(s);
            }
        }
        if missing.len() < 2 {
            return;
        }
        let threads = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(missing.len());
        let chunk = missing.len().div_ceil(threads);
        let built: Vec<(Vec<[f64; 2]>, Sketch)> = std::thread::scope(|sc| {
            let handles: Vec<_> = missing
                .chunks(chunk)
                .map(|part| {
                    sc.spawn(move || {
                        part.iter()
                            .filter_map(|s| sketch::build(s, opts).ok().map(|sk| (s.to_vec(), sk)))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            handles
                .into_iter()
                .flat_map(|h| h.join().unwrap_or_default())
                .collect()
        });
        for (s, sk) in built {
            self.entries.push((s, *opts, sk, true));
        }
    }

    /// Drops the sketches not used by `keep` (strokes of the current model).
    pub fn retain(&mut self, keep: &[&[[f64; 2]]]) {
        self.entries
            .retain(|(s, _, _, _)| keep.contains(&s.as_slice()));
    }
}

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
