//! Models of several sketched components and the compact model file
//! (paper 003, sec 4: planes at depths, merge, carve, translate / rotate /
//! copy, the `.sc` script file — here JSON).
//!
//! A component's stroke lies in a view plane: `front` (screen $x, y$ =
//! world $x, y$, plane normal $+z$), `side` (screen $x$ = world $-z$,
//! normal $+x$) or `top` (screen $y$ = world $-z$, normal $+y$), at a
//! `depth` along the normal. Without a depth, the depth comes from the first
//! stroke point (paper): the ray through it along the normal is intersected
//! with the components already built; a miss puts the plane at depth 0
//! ("in the air"). Then the optional rotation (about the component's
//! skeleton centroid) and translation apply. `copy_of` reuses another
//! (earlier) component's stroke, view and plane depth.
//!
//! Operations: `merge` sums the two components' fields (their skeletons
//! become one); `carve` negates the tool's $\lambda_i$ and merges it into the
//! target. Components not merged stay separate surfaces (separate mesh
//! groups). The file stores only strokes, planes, transforms and operations,
//! so it rebuilds at any resolution.

use super::kernel::Segment;
use super::sketch::{ConvOptions, Sketch};
use super::sketch_cache::SketchCache;
use super::ConvError;
use serde::{Deserialize, Serialize};

/// The view plane of a stroke: the one drawing [`View`] (`"front"`,
/// `"side"`, `"top"`; front when not given).
pub use crate::polygon::View;

/// A stroke's screen frame in `view` (screen x axis, screen y axis,
/// normal) in world coordinates: a right-handed camera frame, so the side
/// view's screen x is -z (`View::axes` gives the profile's (z, y) instead).
pub fn frame(view: View) -> [[f64; 3]; 3] {
    match view {
        View::Front => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        View::Side => [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
        View::Top => [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
    }
}

/// A rotation by `degrees` about `axis` (through the component's centroid).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rotation {
    pub axis: [f64; 3],
    pub degrees: f64,
}

/// Largest absolute translation or plane depth of a component: f64 grid
/// positions there still resolve 1e-4 (a model far out but within it is
/// refused later, when its mesh would be written in f32:
/// `sample::check_f32_output`); beyond it the grid cannot hold the surface.
pub const MAX_TRANSLATION: f64 = 1e12;
/// Most components a model may have. Each component without a depth
/// marches a ray through the field of all earlier ones and each separate
/// group is sampled on its own grid, so the build grows faster than
/// linearly: 100 separate unit squares without depths took 33 s at the
/// default resolution (release build, 2 cores) and 1000 would take about
/// a quarter of an hour (200 took 38 s at 32 cells).
pub const MAX_COMPONENTS: usize = 100;

/// One sketched component.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct Component {
    pub name: String,
    /// Closed stroke in screen coordinates of its view plane.
    pub stroke: Vec<[f64; 2]>,
    pub view: View,
    /// Plane depth along the view normal; `None`: from the first point.
    pub depth: Option<f64>,
    pub rotate: Option<Rotation>,
    pub translate: [f64; 3],
    /// Name of a component whose stroke, view and depth this one copies.
    pub copy_of: Option<String>,
}

/// A modeling operation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", rename_all = "lowercase", deny_unknown_fields)]
pub enum Operation {
    Merge { a: String, b: String },
    Carve { target: String, tool: String },
}

/// Polygoniser choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Polygonizer {
    #[default]
    MarchingTetrahedra,
    SurfaceNets,
}

/// The model file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct Model {
    pub name: String,
    pub options: ConvOptions,
    pub components: Vec<Component>,
    pub operations: Vec<Operation>,
}

/// A built component: its sketch and world-space segments.
#[derive(Clone, Debug)]
pub struct BuiltComponent {
    pub name: String,
    pub sketch: Sketch,
    pub frame: [[f64; 3]; 3],
    pub depth: f64,
    /// World-space segments (lambda negated for carving tools).
    pub segments: Vec<Segment>,
    pub group: usize,
    /// Largest skeleton radius (world units).
    pub max_radius: f64,
}

/// A built model: components and their merge groups.
#[derive(Clone, Debug)]
pub struct BuiltModel {
    pub components: Vec<BuiltComponent>,
    /// Component indices per group (the first names the group).
    pub groups: Vec<Vec<usize>>,
}

fn rotate(v: [f64; 3], axis: [f64; 3], deg: f64) -> [f64; 3] {
    let n = crate::mesh::norm(axis);
    let k = [axis[0] / n, axis[1] / n, axis[2] / n];
    let (s, c) = deg.to_radians().sin_cos();
    let kv = crate::mesh::dot(k, v);
    let x = [
        k[1] * v[2] - k[2] * v[1],
        k[2] * v[0] - k[0] * v[2],
        k[0] * v[1] - k[1] * v[0],
    ];
    [0, 1, 2].map(|i| v[i] * c + x[i] * s + k[i] * kv * (1.0 - c))
}

/// Field of a set of components at `r`.
pub fn components_field(comps: &[&BuiltComponent], r: [f64; 3]) -> f64 {
    comps
        .iter()
        .map(|c| super::kernel::total_field(&c.segments, r, c.sketch.s))
        .sum()
}

impl Model {
    /// Parses and validates a model file.
    pub fn from_json(text: &str) -> Result<Model, ConvError> {
        let m: Model = serde_json::from_str(text).map_err(ConvError::ModelJson)?;
        m.options.validate()?;
        if m.components.is_empty() {
            return Err(ConvError::Model("no components".into()));
        }
        m.check_components()?;
        Ok(m)
    }

    /// Refuses duplicate component names (operations and copies name
    /// components), translations and depths beyond [`MAX_TRANSLATION`],
    /// and more than [`MAX_COMPONENTS`].
    fn check_components(&self) -> Result<(), ConvError> {
        if self.components.len() > MAX_COMPONENTS {
            return Err(ConvError::Model(format!(
                "{} components, at most {MAX_COMPONENTS}",
                self.components.len()
            )));
        }
        let mut names = std::collections::HashMap::new();
        for (i, c) in self.components.iter().enumerate() {
            if let Some(j) = names.insert(c.name.as_str(), i) {
                return Err(ConvError::Model(format!(
                    "components {j} and {i} are both named {:?}; operations and copies need unique names",
                    c.name
                )));
            }
            let far = c
                .translate
                .iter()
                .chain(c.depth.iter())
                .find(|v| v.is_finite() && v.abs() > MAX_TRANSLATION);
            if let Some(v) = far {
                return Err(ConvError::Model(format!(
                    "component {:?}: translation or depth {v:e} beyond {MAX_TRANSLATION:e}; \
                     move the model nearer the origin",
                    c.name
                )));
            }
        }
        Ok(())
    }

    /// Serialises the model (pretty JSON).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    fn index(&self, name: &str) -> Result<usize, ConvError> {
        self.components
            .iter()
            .position(|c| c.name == name)
            .ok_or_else(|| ConvError::Model(format!("unknown component {name:?}")))
    }

    /// Reconstructs every component and resolves the operations.
    pub fn build(&self) -> Result<BuiltModel, ConvError> {
        self.build_cached(&mut SketchCache::default())
    }

    /// [`Self::build`] reusing the sketches of `cache` whose stroke and
    /// options are unchanged (copies and unedited strokes are not refitted).
    pub fn build_cached(&self, cache: &mut SketchCache) -> Result<BuiltModel, ConvError> {
        self.check_components()?;
        let strokes: Vec<&[[f64; 2]]> = self
            .components
            .iter()
            .filter(|c| c.copy_of.is_none())
            .map(|c| c.stroke.as_slice())
            .collect();
        cache.prefetch(&strokes, &self.options);
        let (mut parent, carving) = self.operation_sets()?;
        let mut built: Vec<BuiltComponent> = Vec::with_capacity(self.components.len());
        for (ci, c) in self.components.iter().enumerate() {
            let b = self.build_component(c, carving[ci], cache, &built)?;
            built.push(b);
        }
        let groups = merge_groups(&mut parent, &mut built);
        Ok(BuiltModel {
            components: built,
            groups,
        })
    }

    /// The union-find forest of the operations (each joins its two
    /// components) and which components carve.
    fn operation_sets(&self) -> Result<(Vec<usize>, Vec<bool>), ConvError> {
        let n = self.components.len();
        let mut parent: Vec<usize> = (0..n).collect();
        let mut carving = vec![false; n];
        for op in &self.operations {
            let (a, b) = match op {
                Operation::Merge { a, b } => (self.index(a)?, self.index(b)?),
                Operation::Carve { target, tool } => {
                    let (t, u) = (self.index(target)?, self.index(tool)?);
                    carving[u] = true;
                    (t, u)
                }
            };
            let (ra, rb) = (find_root(&mut parent, a), find_root(&mut parent, b));
            if ra != rb {
                parent[rb.max(ra)] = ra.min(rb);
            }
        }
        Ok((parent, carving))
    }

    /// Component `c` built after `built`: its (or its original's) sketch
    /// placed in the world at its depth, rotated, translated, its lambda
    /// negated when `carves`.
    fn build_component(
        &self,
        c: &Component,
        carves: bool,
        cache: &mut SketchCache,
        built: &[BuiltComponent],
    ) -> Result<BuiltComponent, ConvError> {
        let src = match &c.copy_of {
            Some(name) => {
                let i = self.index(name)?;
                if self.components[i].copy_of.is_some() {
                    return Err(ConvError::Model(format!(
                        "{:?} copies {name:?}, itself a copy",
                        c.name
                    )));
                }
                &self.components[i]
            }
            None => c,
        };
        let sk = cache
            .sketch(&src.stroke, &self.options)
            .map_err(|e| e.in_component(&c.name))?;
        let frame = frame(src.view);
        let copied_depth = c
            .copy_of
            .as_ref()
            .and_then(|name| built.iter().find(|b| &b.name == name))
            .map(|b| b.depth);
        let depth = match copied_depth.or(src.depth) {
            Some(d) if d.is_finite() => d,
            Some(d) => {
                return Err(ConvError::Model(format!(
                    "component {:?}: depth {d} is not finite",
                    c.name
                )))
            }
            None => {
                let prev: Vec<&BuiltComponent> = built.iter().collect();
                depth_from_surface(&prev, frame, sk.polygon[0], self.options.threshold)
            }
        };
        let to_world = |p: [f64; 3]| {
            [0, 1, 2]
                .map(|k| frame[0][k] * p[0] + frame[1][k] * p[1] + frame[2][k] * (p[2] + depth))
        };
        let mut segs: Vec<Segment> = sk
            .segments
            .iter()
            .map(|s| Segment {
                p: to_world(s.p),
                q: to_world(s.q),
                ..*s
            })
            .collect();
        if let Some(rot) = c.rotate {
            rotate_segments(c, rot, &mut segs)?;
        }
        if c.translate.iter().any(|v| !v.is_finite()) {
            return Err(ConvError::Model(format!(
                "component {:?}: translation is not finite",
                c.name
            )));
        }
        for s in &mut segs {
            for k in 0..3 {
                s.p[k] += c.translate[k];
                s.q[k] += c.translate[k];
            }
            if carves {
                s.lambda = -s.lambda;
            }
        }
        let max_radius = sk.skeleton.radii.iter().copied().fold(0.0, f64::max);
        Ok(BuiltComponent {
            name: c.name.clone(),
            sketch: sk,
            frame,
            depth,
            segments: segs,
            group: 0,
            max_radius,
        })
    }
}

/// The root of `i`'s set in the union-find forest `p` (`i` then points at
/// it).
fn find_root(p: &mut [usize], i: usize) -> usize {
    let mut r = i;
    while p[r] != r {
        r = p[r];
    }
    p[i] = r;
    r
}

/// Rotates component `c`'s segments by `rot` about their centre (the mean
/// of their midpoints); refuses a rotation not finite or about a zero axis.
fn rotate_segments(c: &Component, rot: Rotation, segs: &mut [Segment]) -> Result<(), ConvError> {
    // a finite length: an axis of norm overflowing to infinity
    // made `rotate` scale the component by cos(angle) instead
    let len = crate::mesh::norm(rot.axis);
    if !(rot.degrees.is_finite() && len.is_finite() && len > 0.0) {
        return Err(ConvError::Model(format!(
            "component {:?}: bad rotation {rot:?}",
            c.name
        )));
    }
    let m = segs.len() as f64;
    let mut cen = [0.0; 3];
    for s in segs.iter() {
        for k in 0..3 {
            cen[k] += 0.5 * (s.p[k] + s.q[k]) / m;
        }
    }
    let rot_pt = |p: [f64; 3]| {
        let v = rotate(
            [p[0] - cen[0], p[1] - cen[1], p[2] - cen[2]],
            rot.axis,
            rot.degrees,
        );
        [v[0] + cen[0], v[1] + cen[1], v[2] + cen[2]]
    };
    for s in segs.iter_mut() {
        s.p = rot_pt(s.p);
        s.q = rot_pt(s.q);
    }
    Ok(())
}

/// The merge groups (component indices, in order of their first
/// component) of the union-find forest `parent`; each built component gets
/// its group's index.
fn merge_groups(parent: &mut [usize], built: &mut [BuiltComponent]) -> Vec<Vec<usize>> {
    let mut roots: Vec<usize> = Vec::new();
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for i in 0..built.len() {
        let r = find_root(parent, i);
        let g = match roots.iter().position(|&x| x == r) {
            Some(g) => g,
            None => {
                roots.push(r);
                groups.push(Vec::new());
                roots.len() - 1
            }
        };
        groups[g].push(i);
        built[i].group = g;
    }
    groups
}

/// Depth of the first surface hit along the view normal through `pt`
/// (coming from the viewer), or 0 when the ray misses.
fn depth_from_surface(prev: &[&BuiltComponent], frame: [[f64; 3]; 3], pt: [f64; 2], t: f64) -> f64 {
    if prev.is_empty() {
        return 0.0;
    }
    let n = frame[2];
    let base = [0, 1, 2].map(|k| frame[0][k] * pt[0] + frame[1][k] * pt[1]);
    let mut reach: f64 = 0.0;
    for c in prev {
        for s in &c.segments {
            for p in [s.p, s.q] {
                reach = reach.max(crate::mesh::dot(p, n).abs() + 2.0 * c.max_radius);
            }
        }
    }
    let steps = 400;
    let at = |d: f64| {
        let r = [0, 1, 2].map(|k| base[k] + d * n[k]);
        components_field(prev, r) - t
    };
    let mut d0 = reach;
    let mut f0 = at(d0);
    for i in 1..=steps {
        let d1 = reach - 2.0 * reach * i as f64 / steps as f64;
        let f1 = at(d1);
        if f0 < 0.0 && f1 >= 0.0 {
            let (mut a, mut b) = (d0, d1);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if at(m) >= 0.0 {
                    b = m;
                } else {
                    a = m;
                }
            }
            return 0.5 * (a + b);
        }
        d0 = d1;
        f0 = f1;
    }
    0.0
}

impl BuiltModel {
    /// The field of group `g` at `r`.
    pub fn group_field(&self, g: usize, r: [f64; 3]) -> f64 {
        let comps: Vec<&BuiltComponent> = self.groups[g]
            .iter()
            .map(|&i| &self.components[i])
            .collect();
        components_field(&comps, r)
    }

    /// The gradient of the field of group `g` at `r`.
    pub fn group_gradient(&self, g: usize, r: [f64; 3]) -> [f64; 3] {
        let mut out = [0.0; 3];
        for &i in &self.groups[g] {
            let c = &self.components[i];
            let d = super::kernel::total_gradient(&c.segments, r, c.sketch.s);
            for k in 0..3 {
                out[k] += d[k];
            }
        }
        out
    }
}
