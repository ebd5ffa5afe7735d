//! Assembling parts and transitions into one mesh with shared vertices at
//! every seam, and measuring the joins.

mod weave;

use crate::character::measure::{measure, measure_seam};
pub use crate::character::measure::{orient, JoinReport, SeamReport};
use crate::character::part::{build_part, PartSurface};
use crate::character::ring::{cut_table, RING_VERTICES};
use crate::character::seam::{seams as make_seams, Seam};
use crate::character::spec::{End, PartSpec, TransitionSpec};
use crate::character::transition::{
    blend, child_transition, column, Built, ChildTransition, Column,
};
use crate::character::ModelError;
use crate::mesh::Mesh;
use weave::{part_tubes, transition_mesh};

use std::f64::consts::PI;

/// Mesh resolution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolution {
    /// Rings per model height along a part.
    pub rings_per_height: f64,
    /// Rows across a transition.
    pub transition_rows: usize,
}

impl Default for Resolution {
    fn default() -> Resolution {
        Resolution {
            rings_per_height: 160.0,
            transition_rows: 10,
        }
    }
}

/// A displacement field over a part's parameters, in patch coordinates:
/// `s` in `(0, 1)` across its u-range, `theta` the ring angle. The force
/// edits' fields (`crate::edit::ForceField`: pde4 2-sided and 4-sided
/// solutions) are the ones the pipeline adds.
pub trait DisplacementField: std::fmt::Debug + Send + Sync {
    /// The displacement at patch coordinate `s` and angle `theta`.
    fn at(&self, s: f64, theta: f64) -> [f64; 3];
}

/// A displacement field added to a part's surface over a u-range of the
/// part (a force edit of `crate::edit`: the pde4 2-sided solution, which
/// vanishes with its u-derivative at both ends of the range, so the part
/// stays in place and C1 there and its ends, where transitions join, do not
/// move; or the 4-sided one inside an angle range too).
#[derive(Clone, Debug)]
pub struct Displacement {
    pub part: String,
    pub u: [f64; 2],
    pub field: std::sync::Arc<dyn DisplacementField>,
}

impl Displacement {
    /// The displacement at part parameter `u`, angle `theta` (zero outside
    /// the range).
    pub fn at(&self, u: f64, theta: f64) -> [f64; 3] {
        let [a, b] = self.u;
        if u <= a || u >= b {
            return [0.0; 3];
        }
        self.field.at((u - a) / (b - a), theta)
    }
}

/// Built parts by specification: a rebuild re-solves only the parts whose
/// specification changed (an edit of one part re-solves that part only).
#[derive(Clone, Debug, Default)]
pub struct PartCache {
    entries: Vec<(PartSpec, PartSurface)>,
    /// Parts solved (cache misses) so far.
    pub solved: usize,
}

/// Most parts a [`PartCache`] keeps.
pub const PART_CACHE_SIZE: usize = 64;
/// Largest Hermite tangent factor of a transition (`TransitionSpec::tangent_scale`):
/// past a few times the parts' own tangents the blend loops out of the body.
pub const TANGENT_SCALE_MAX: f64 = 10.0;

impl PartCache {
    /// The built part of `spec`, solved only when not cached.
    pub fn get(&mut self, spec: &PartSpec) -> Result<PartSurface, ModelError> {
        if let Some((_, s)) = self.entries.iter().find(|(p, _)| p == spec) {
            return Ok(s.clone());
        }
        let s = build_part(spec)?;
        if self.entries.len() >= PART_CACHE_SIZE {
            self.entries.remove(0);
        }
        self.entries.push((spec.clone(), s.clone()));
        self.solved += 1;
        Ok(s)
    }
}

/// A built model: the mesh and the join measurements.
#[derive(Clone, Debug)]
pub struct Model {
    pub mesh: Mesh,
    pub parts: Vec<PartSurface>,
    pub joins: Vec<JoinReport>,
    pub seams: Vec<SeamReport>,
}

/// Builds the mesh of parts and transitions and measures the joins.
pub fn build_model(
    specs: &[PartSpec],
    transitions: &[TransitionSpec],
    height: f64,
    res: Resolution,
) -> Result<Model, ModelError> {
    build_model_with(specs, transitions, height, res, &[], None)
}

/// [`build_model`] with displacement fields on parts (force edits) and an
/// optional cache of built parts (only changed parts are re-solved).
pub fn build_model_with(
    specs: &[PartSpec],
    transitions: &[TransitionSpec],
    height: f64,
    res: Resolution,
    displacements: &[Displacement],
    cache: Option<&mut PartCache>,
) -> Result<Model, ModelError> {
    let parts = solve_parts(specs, cache)?;
    for d in displacements {
        if !parts.iter().any(|p| p.name == d.part) {
            return Err(ModelError::Document(format!(
                "a displacement names unknown part '{}'",
                d.part
            )));
        }
    }
    let mut built = Vec::new();
    let mut thetas: Vec<Option<Vec<f64>>> = vec![None; parts.len()];
    let uniform: Vec<f64> = (0..RING_VERTICES)
        .map(|i| 2.0 * PI * i as f64 / RING_VERTICES as f64)
        .collect();
    for t in transitions {
        built.push(plan_transition(t, &parts, &mut thetas)?);
    }
    let end_uniform = ends_on_uniform_rings(&built, &parts, &thetas)?;
    let mut mesh = Mesh::default();
    let tubes = part_tubes(
        &mut mesh,
        &parts,
        &thetas,
        &end_uniform,
        &uniform,
        height,
        res,
        displacements,
    );
    for b in &built {
        transition_mesh(&mut mesh, b, &parts, &tubes, res)?;
    }
    orient(&mut mesh);
    let (joins, seam_reports) = measure_joins(&built, &parts, height);
    Ok(Model {
        mesh,
        parts,
        joins,
        seams: seam_reports,
    })
}

/// One way to blend a planned child ([`transition_points`]): a factor on
/// its tangent scale and the starts of its late depth blend
/// (`TransitionSpec::child_rises`, replacing the document's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlendTry {
    pub factor: f64,
    pub rise: [f64; 2],
}

impl BlendTry {
    /// Child `c` of `t` blended as the document says.
    pub fn document(t: &TransitionSpec, c: usize) -> Self {
        BlendTry {
            factor: 1.0,
            rise: t.child_rises.get(c).copied().unwrap_or([0.0; 2]),
        }
    }
}

/// The points the mesh of transition `t` holds for its child `child` (an
/// index into `t.children`) blended each way of `tries` (its tangent factor,
/// `TransitionSpec::child_scale`, times the try's, with the try's late
/// depth blend): per try, rows `s = r / rows` for `r` in `0..=rows` at
/// every loop vertex (row 0 the loop on the parent, row `rows` the child's
/// ring), as [`build_model`] places them with `rows` transition rows:
/// `rows + 1` rows of `points.len() / (rows + 1)` columns. `parts` are the
/// solved parts the transition joins. Every cross-tangent scale of a child
/// transition is its factor times a length of the geometry
/// (`character::transition::child_transition`, `column_scales`,
/// `tangent_cap`), so each factor scales the one planned child.
pub fn transition_points(
    t: &TransitionSpec,
    parts: &[PartSurface],
    child: usize,
    rows: usize,
    tries: &[BlendTry],
) -> Result<Vec<Vec<[f64; 3]>>, ModelError> {
    let (pi, ci, seams, cuts) = plan_frame(t, parts)?;
    let Some(&idx) = ci.get(child) else {
        return Err(ModelError::Document(format!(
            "transition '{}' has no child {child}",
            t.name
        )));
    };
    let planned = plan_child(t, parts, pi, idx, child, &seams, &cuts)?;
    let points = |b: &BlendTry| {
        let mut ct = planned.clone();
        ct.ell *= b.factor;
        ct.ell_vertex.iter_mut().for_each(|e| *e *= b.factor);
        crate::character::transition::set_rises(&mut ct, &parts[pi], &seams, b.rise);
        let columns: Vec<Column> = (0..ct.n)
            .map(|i| column(&ct, &parts[pi], &parts[idx], &seams, i as f64))
            .collect();
        let mut out = Vec::with_capacity(ct.n * (rows + 1));
        for r in 0..=rows {
            let s = r as f64 / rows as f64;
            out.extend(columns.iter().map(|c| blend(&ct, c, s, 0)));
        }
        out
    };
    Ok(tries.iter().map(points).collect())
}

/// The parts of `specs`, from `cache` when given (solving only the parts
/// not in it), else each solved.
fn solve_parts(
    specs: &[PartSpec],
    cache: Option<&mut PartCache>,
) -> Result<Vec<PartSurface>, ModelError> {
    Ok(match cache {
        Some(c) => specs
            .iter()
            .map(|s| c.get(s))
            .collect::<Result<Vec<_>, _>>()?,
        None => specs
            .iter()
            .map(build_part)
            .collect::<Result<Vec<_>, _>>()?,
    })
}

/// The index of the part named `n`.
fn find_part(parts: &[PartSurface], n: &str) -> Result<usize, ModelError> {
    parts
        .iter()
        .position(|p| p.name == n)
        .ok_or_else(|| ModelError::Document(format!("unknown part '{n}'")))
}

/// Refuses a transition's late depth blend starts (`child_rises`) outside
/// `[0, RISE_MAX]` or not one pair per child (`k`).
fn check_rises(t: &TransitionSpec, k: usize) -> Result<(), ModelError> {
    use crate::character::rise::RISE_MAX;
    if !t.child_rises.is_empty() && t.child_rises.len() != k {
        return Err(ModelError::Document(format!(
            "transition '{}': child_rises has {} pairs for {k} children (one per child, or none)",
            t.name,
            t.child_rises.len()
        )));
    }
    let bad = t.child_rises.iter().enumerate().find_map(|(i, r)| {
        (0..2)
            .find(|&j| !(0.0..=RISE_MAX).contains(&r[j]))
            .map(|j| (i, j, r[j]))
    });
    if let Some((i, j, r)) = bad {
        return Err(ModelError::Document(format!(
            "transition '{}': child_rises[{i}][{j}] must be in [0, {RISE_MAX}], got {}",
            t.name,
            crate::limits::Num(r)
        )));
    }
    Ok(())
}

/// Refuses a transition's tangent scale outside `(0, TANGENT_SCALE_MAX]`
/// and cut angles out of their ranges or not making a cut table
/// (`cuts`, for `k` children).
fn check_transition(
    t: &TransitionSpec,
    k: usize,
    cuts: &[(usize, usize)],
) -> Result<(), ModelError> {
    let ok = |s: f64| s.is_finite() && s > 0.0 && s <= TANGENT_SCALE_MAX;
    let bad = std::iter::once(("tangent_scale".to_string(), t.tangent_scale))
        .chain(
            t.child_tangent_scales
                .iter()
                .enumerate()
                .map(|(i, &s)| (format!("child_tangent_scales[{i}]"), s)),
        )
        .find(|(_, s)| !ok(*s));
    if let Some((field, s)) = bad {
        return Err(ModelError::Document(format!(
            "transition '{}': {field} must be in (0, {TANGENT_SCALE_MAX}], got {}",
            t.name,
            crate::limits::Num(s)
        )));
    }
    if !t.child_tangent_scales.is_empty() && t.child_tangent_scales.len() != k {
        return Err(ModelError::Document(format!(
            "transition '{}': child_tangent_scales has {} factors for {k} children (one per child, or none)",
            t.name,
            t.child_tangent_scales.len()
        )));
    }
    check_rises(t, k)?;
    let km1 = k.saturating_sub(1);
    let out_of_range = t.cut_angles.iter().enumerate().find(|&(i, &a)| {
        let (lo, hi) = if i < km1 { (0.0, PI) } else { (PI, 2.0 * PI) };
        !(lo..=hi).contains(&a)
    });
    if let Some((i, &a)) = out_of_range {
        return Err(ModelError::Document(format!(
            "transition '{}': cut_angles[{i}] = {} is outside {} (front angles in [0, pi], back angles in [pi, 2 pi])",
            t.name,
            crate::limits::Num(a),
            if i < km1 { "[0, pi]" } else { "[pi, 2 pi]" }
        )));
    }
    if !t.cut_angles.is_empty() && cuts.is_empty() {
        return Err(ModelError::Document(format!(
            "transition '{}': cut_angles needs one finite angle per seam ({}), in (0, pi) and decreasing, optionally followed by one back angle per seam in (pi, 2 pi), increasing",
            t.name,
            k.saturating_sub(1)
        )));
    }
    Ok(())
}

/// What every child of transition `t` shares: the parent's index, the
/// children's indices, the seams and the cut table (checked).
type Frame = (usize, Vec<usize>, Vec<Seam>, Vec<(usize, usize)>);

fn plan_frame(t: &TransitionSpec, parts: &[PartSurface]) -> Result<Frame, ModelError> {
    let pi = find_part(parts, &t.parent)?;
    let ci: Vec<usize> = t
        .children
        .iter()
        .map(|c| find_part(parts, c))
        .collect::<Result<_, _>>()?;
    let k = ci.len();
    let centres: Vec<[f64; 3]> = ci
        .iter()
        .map(|&c| parts[c].section(parts[c].u0, 0).c0)
        .collect();
    let cuts = cut_table(k, &t.cut_angles);
    check_transition(t, k, &cuts)?;
    let seams = make_seams(&parts[pi], t.parent_end, k, &t.seam_apex, &centres, &cuts);
    Ok((pi, ci, seams, cuts))
}

/// A transition laid out over the parts: its seams and each child's
/// transition surface; each child's ring angles (its loop's) go into
/// `thetas`, which refuses a child of two transitions.
fn plan_transition(
    t: &TransitionSpec,
    parts: &[PartSurface],
    thetas: &mut [Option<Vec<f64>>],
) -> Result<Built, ModelError> {
    let (pi, ci, seams, cuts) = plan_frame(t, parts)?;
    let mut cts = Vec::new();
    for (c, &idx) in ci.iter().enumerate() {
        let ct = plan_child(t, parts, pi, idx, c, &seams, &cuts)?;
        if thetas[idx].is_some() {
            return Err(ModelError::Document(format!(
                "part '{}' is the child of two transitions",
                parts[idx].name
            )));
        }
        thetas[idx] = Some(
            (0..ct.n)
                .map(|i| ct.theta0 + ct.sigma * 2.0 * PI * i as f64 / ct.n as f64)
                .collect(),
        );
        cts.push(ct);
    }
    Ok(Built {
        spec: t.clone(),
        parent: pi,
        children: ci,
        seams,
        cts,
    })
}

/// Child `c` (part `idx`) of transition `t` on parent part `pi`.
fn plan_child(
    t: &TransitionSpec,
    parts: &[PartSurface],
    pi: usize,
    idx: usize,
    c: usize,
    seams: &[Seam],
    cuts: &[(usize, usize)],
) -> Result<ChildTransition, ModelError> {
    if parts[idx].closed_start {
        return Err(ModelError::Document(format!(
            "part '{}' joins transition '{}' at its start, which is closed",
            parts[idx].name, t.name
        )));
    }
    let mut ct = child_transition(
        c,
        t.children.len(),
        &parts[pi],
        t.parent_end,
        &parts[idx],
        seams,
        cuts,
        t.child_scale(c),
        t.continuity,
    );
    if t.cap_tangents {
        crate::character::tangent_cap::cap_tangents(&mut ct, &parts[pi], seams);
    }
    if let Some(r) = t.child_rises.get(c) {
        crate::character::transition::set_rises(&mut ct, &parts[pi], seams, *r);
    }
    Ok(ct)
}

/// Which parts switch to the uniform ring halfway along their tube.
///
/// A part that is a child (its start ring follows its transition's loop)
/// and the parent of a transition at its end (whose ring is the uniform
/// one the cuts index) switches from one ring to the other halfway
/// along its tube (`weave::zip`): an arm under the shoulders ending at a wrist.
fn ends_on_uniform_rings(
    built: &[Built],
    parts: &[PartSurface],
    thetas: &[Option<Vec<f64>>],
) -> Result<Vec<bool>, ModelError> {
    let mut end_uniform = vec![false; parts.len()];
    for b in built {
        if thetas[b.parent].is_some() {
            if b.spec.parent_end == End::Start {
                return Err(ModelError::Document(format!(
                    "part '{}' is a child and the parent of transition '{}' at the same end (its start)",
                    parts[b.parent].name, b.spec.name
                )));
            }
            end_uniform[b.parent] = true;
        }
    }
    Ok(end_uniform)
}

/// The C0/C1/C2 reports of every join (each child transition at its parent
/// and at its child) and the report of every seam.
fn measure_joins(
    built: &[Built],
    parts: &[PartSurface],
    height: f64,
) -> (Vec<JoinReport>, Vec<SeamReport>) {
    let mut joins = Vec::new();
    let mut seam_reports = Vec::new();
    for b in built {
        for (ct, &ci) in b.cts.iter().zip(&b.children) {
            joins.push(measure(
                b,
                ct,
                &parts[b.parent],
                &parts[b.parent].name,
                true,
                &parts[ci],
                height,
            ));
            joins.push(measure(
                b,
                ct,
                &parts[b.parent],
                &parts[ci].name,
                false,
                &parts[ci],
                height,
            ));
        }
        for (j, _) in b.seams.iter().enumerate() {
            seam_reports.push(measure_seam(b, j, parts));
        }
    }
    (joins, seam_reports)
}
