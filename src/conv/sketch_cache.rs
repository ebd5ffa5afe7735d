//! The sketches of a model's strokes kept between rebuilds (issue 16,
//! [`super::incremental`]): a sketch is reused when its raw stroke and the
//! options are equal, bit for bit.

use super::sketch::{self, ConvOptions, Sketch};
use super::ConvError;

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
