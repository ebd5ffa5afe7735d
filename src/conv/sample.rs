//! Sampling a built model's field on grids and polygonising it (paper 003,
//! sec 3.4): the brute-force reference (every node, every segment) and the
//! fast narrow-band sampler ([`super::narrow`] over [`super::bvh`]), which
//! `polygonize` uses.

use super::bvh::SegmentBvh;
use super::model::{components_field, BuiltComponent, BuiltModel, Polygonizer};
use super::narrow::{self, NarrowStats, FIELD_TOLERANCE};
pub use super::narrow_merge::node_position;
use super::ConvError;
use crate::mesh::isosurface::{marching_tetrahedra, surface_nets, ScalarGrid, MAX_NODES};
use crate::mesh::Mesh;

/// Gives every node of `grid` whose value lies within `margin` of
/// `threshold` the value of `reference` at its position (the brute-force
/// sampler's arithmetic: same node position, same summation order);
/// returns how many.
///
/// Why: the narrow band's node values are within `budget / 2` of the exact
/// field (a fill value is on its proven side), so with `margin = budget`
/// every other node lies at least `budget / 2` from $T$ on the same side as
/// the exact field, and the reference's rounding error (about $10^{-13} T$
/// for the teddy's 189 segments) is far below that: every node is then on
/// the same side of $T$ as in the reference grid, and the polygonisers,
/// whose triangles depend only on the sides, give the reference's
/// triangles (check `conv.fast.teddy_sides_match_reference`).
pub fn settle_near_threshold(
    grid: &mut ScalarGrid,
    threshold: f64,
    margin: f64,
    reference: impl Fn([f64; 3]) -> f64,
) -> usize {
    let (origin, spacing, dims) = (grid.origin, grid.spacing, grid.dims);
    let mut n = 0;
    for (id, v) in grid.values.iter_mut().enumerate() {
        if (*v - threshold).abs() <= margin {
            *v = reference(node_position(origin, spacing, dims, id));
            n += 1;
        }
    }
    n
}

/// Largest allowed resolution (cells along the longest axis).
pub const MAX_RESOLUTION: usize = 512;
/// Times the grid box is doubled when the surface reaches its boundary.
pub const MAX_BOX_GROWTH: usize = 4;

/// How the field is sampled on the grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sampler {
    /// Every node, every segment (the reference).
    Reference,
    /// Narrow band over a segment hierarchy, node values within
    /// [`FIELD_TOLERANCE`] / 2 of $T$ of the exact field.
    #[default]
    NarrowBand,
}

fn check_resolution(resolution: usize) -> Result<(), ConvError> {
    if !(4..=MAX_RESOLUTION).contains(&resolution) {
        return Err(ConvError::Parameter(format!(
            "resolution {resolution} outside 4..={MAX_RESOLUTION}"
        )));
    }
    Ok(())
}

impl BuiltModel {
    fn group_members(&self, g: usize) -> Result<Vec<&BuiltComponent>, ConvError> {
        let members = self
            .groups
            .get(g)
            .ok_or_else(|| ConvError::Parameter(format!("no group {g}")))?;
        Ok(members.iter().map(|&i| &self.components[i]).collect())
    }

    /// The segment hierarchy of group `g` (each segment with its kernel
    /// width).
    pub fn group_bvh(&self, g: usize) -> Result<SegmentBvh, ConvError> {
        let comps = self.group_members(g)?;
        Ok(SegmentBvh::new(
            comps
                .iter()
                .flat_map(|c| c.segments.iter().map(|s| (*s, c.sketch.s)))
                .collect(),
        ))
    }

    /// Samples the field of group `g` at every node (the reference): a grid
    /// with `resolution` cells along the longest side of a box around its
    /// skeleton, grown until the surface $F = T$ stays inside. `Ok(None)`:
    /// the group only carves (every $\lambda \le 0$), so it has no surface
    /// of its own.
    pub fn sample_group(
        &self,
        g: usize,
        resolution: usize,
        threshold: f64,
    ) -> Result<Option<ScalarGrid>, ConvError> {
        let comps = self.group_members(g)?;
        self.sample_group_with(g, resolution, threshold, |l, h, dims| {
            Ok(ScalarGrid::sample(l, h, dims, |r| {
                components_field(&comps, r)
            })?)
        })
    }

    /// [`Self::sample_group`] by the narrow-band sampler: the same grid,
    /// exact (within `tolerance` T / 2) at the corners of every cell that
    /// may cross $T$, a value on the proven side of $T$ elsewhere; nodes
    /// within `tolerance` T of $T$ get the reference's value
    /// ([`settle_near_threshold`]), so every node is on the reference's
    /// side of $T$.
    pub fn sample_group_fast(
        &self,
        g: usize,
        resolution: usize,
        threshold: f64,
        tolerance: f64,
    ) -> Result<Option<(ScalarGrid, NarrowStats)>, ConvError> {
        if !(tolerance.is_finite() && tolerance > 0.0 && tolerance <= 0.1) {
            return Err(ConvError::Parameter(format!(
                "field tolerance {tolerance} outside (0, 0.1] (a fraction of T)"
            )));
        }
        let bvh = self.group_bvh(g)?;
        let comps = self.group_members(g)?;
        let mut stats = NarrowStats::default();
        let grid = self.sample_group_with(g, resolution, threshold, |l, h, dims| {
            let total = dims[0].saturating_mul(dims[1]).saturating_mul(dims[2]);
            if total > MAX_NODES {
                return Err(ConvError::Parameter(format!(
                    "a grid of {dims:?} nodes exceeds {MAX_NODES}"
                )));
            }
            // the reference's node positions (`ScalarGrid::sample`'s spacing)
            let spacing = [0, 1, 2].map(|k| (h[k] - l[k]) / (dims[k] - 1) as f64);
            let budget = tolerance * threshold;
            let (mut grid, st) = narrow::sample(&bvh, threshold, budget, l, spacing, dims);
            stats = st;
            stats.reference_nodes = settle_near_threshold(&mut grid, threshold, budget, |r| {
                components_field(&comps, r)
            });
            Ok(grid)
        })?;
        Ok(grid.map(|g| (g, stats)))
    }

    fn sample_group_with(
        &self,
        g: usize,
        resolution: usize,
        threshold: f64,
        // the sampler gets the first and last node and the node counts
        mut sample: impl FnMut([f64; 3], [f64; 3], [usize; 3]) -> Result<ScalarGrid, ConvError>,
    ) -> Result<Option<ScalarGrid>, ConvError> {
        check_resolution(resolution)?;
        let comps = self.group_members(g)?;
        if comps
            .iter()
            .all(|c| c.segments.iter().all(|s| s.lambda <= 0.0))
        {
            return Ok(None);
        }
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        let mut rmax: f64 = 0.0;
        for c in &comps {
            rmax = rmax.max(c.max_radius);
            for s in &c.segments {
                for p in [s.p, s.q] {
                    for k in 0..3 {
                        lo[k] = lo[k].min(p[k]);
                        hi[k] = hi[k].max(p[k]);
                    }
                }
            }
        }
        let mut margin = 1.5 * rmax;
        for _attempt in 0..MAX_BOX_GROWTH {
            let l = lo.map(|x| x - margin);
            let h = hi.map(|x| x + margin);
            let side = (0..3).map(|k| h[k] - l[k]).fold(0.0, f64::max);
            let cell = side / resolution as f64;
            let dims = [0, 1, 2].map(|k| (((h[k] - l[k]) / cell).ceil() as usize + 1).max(3));
            let last = [0, 1, 2].map(|k| l[k] + (dims[k] - 1) as f64 * cell);
            let grid = sample(l, last, dims)?;
            // does the surface reach the grid boundary? then grow the box
            let touches = (0..grid.values.len()).any(|i| {
                let c = [
                    i % dims[0],
                    (i / dims[0]) % dims[1],
                    i / (dims[0] * dims[1]),
                ];
                (0..3).any(|k| c[k] == 0 || c[k] + 1 == dims[k]) && grid.values[i] > threshold
            });
            if !touches {
                return Ok(Some(grid));
            }
            margin *= 2.0;
        }
        Err(ConvError::Numerical(format!(
            "the surface of group {g} does not close within the box (field unbounded?)"
        )))
    }

    /// Polygonises every group with `resolution` cells along the longest
    /// side of its box (narrow-band sampler) and returns one mesh (a group
    /// per merged component).
    pub fn polygonize(
        &self,
        resolution: usize,
        threshold: f64,
        method: Polygonizer,
    ) -> Result<Mesh, ConvError> {
        self.polygonize_with(resolution, threshold, method, Sampler::NarrowBand)
    }

    /// [`Self::polygonize`] with a chosen sampler.
    pub fn polygonize_with(
        &self,
        resolution: usize,
        threshold: f64,
        method: Polygonizer,
        sampler: Sampler,
    ) -> Result<Mesh, ConvError> {
        check_resolution(resolution)?;
        let mut out: Option<Mesh> = None;
        for g in 0..self.groups.len() {
            let Some(m) = self.polygonize_group(g, resolution, threshold, method, sampler)? else {
                continue;
            };
            match &mut out {
                None => out = Some(m),
                Some(o) => o.append(&m),
            }
        }
        let m = out.ok_or_else(|| ConvError::Numerical("the model produced no surface".into()))?;
        if m.triangles.is_empty() {
            return Err(ConvError::Numerical(
                "the surface is empty at this resolution".into(),
            ));
        }
        Ok(m)
    }

    /// The mesh of group `g` alone (`None`: a carving-only group).
    pub fn polygonize_group(
        &self,
        g: usize,
        resolution: usize,
        threshold: f64,
        method: Polygonizer,
        sampler: Sampler,
    ) -> Result<Option<Mesh>, ConvError> {
        let grid = match sampler {
            Sampler::Reference => self.sample_group(g, resolution, threshold)?,
            Sampler::NarrowBand => self
                .sample_group_fast(g, resolution, threshold, FIELD_TOLERANCE)?
                .map(|(grid, _)| grid),
        };
        let Some(grid) = grid else {
            return Ok(None);
        };
        let mut m = match method {
            Polygonizer::MarchingTetrahedra => marching_tetrahedra(&grid, threshold),
            Polygonizer::SurfaceNets => surface_nets(&grid, threshold),
        };
        m.groups = vec![self.components[self.groups[g][0]].name.clone()];
        Ok(Some(m))
    }
}

/// Largest rounding error of an f32 coordinate in a written mesh file,
/// as a fraction of the mesh's size (bounding-box diagonal).
pub const OUTPUT_PRECISION: f64 = 1e-4;

/// Refuses a mesh whose coordinates lose its shape when stored as f32 (as
/// every mesh file writer does): a model far from the origin relative to
/// its size (e.g. shifted by 1e9). Rounding to f32 moves a coordinate $x$
/// by up to $|x| 2^{-24}$.
pub fn check_f32_output(mesh: &Mesh) -> Result<(), ConvError> {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &mesh.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let size = crate::mesh::norm(crate::mesh::sub(hi, lo));
    let far = (0..3)
        .map(|k| lo[k].abs().max(hi[k].abs()))
        .fold(0.0, f64::max);
    let err = far * f64::powi(2.0, -24);
    if !(size.is_finite() && far.is_finite()) || err > OUTPUT_PRECISION * size {
        return Err(ConvError::Model(format!(
            "the surface lies {far:e} from the origin with a size of {size:e}: mesh files store \
             f32 coordinates, which would move its points by up to {err:e} ({:.1e} of its size, \
             limit {OUTPUT_PRECISION:e}); translate the model nearer the origin",
            err / size
        )));
    }
    Ok(())
}
