//! The interactive deformer: everything that depends only on the region is
//! computed once ([`PlateDeformer::new`]); a cursor move
//! ([`PlateDeformer::apply`]) is one pass over the region's vertices,
//! $\mathbf p_i = \mathbf p_i^0 + \mathbf q\, w_i$ with the precomputed
//! weight $w_i = (u_i^2+v_i^2-1)^2/(64 D)$ (eq 12) and $\mathbf q = s\,\mathbf d$.

use super::boundary::{alpha_shape, mesh_edge_boundary, Boundary, ALPHA0_DEFAULT};
use super::mapping::{harmonic_disk, DiskMapping, DiskPoint};
use super::projection::{project, LocalFrame, ViewPlane};
use super::{disk_solution, Material, PlateError};
use crate::mesh::{norm, Mesh};
use std::collections::HashMap;

/// Direction of the deformation (sec 4.4, option "Mouse Direction").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// Along the cursor motion: $q_\xi = s d_\xi$ for each component.
    Cursor,
    /// Along the region normal, with $q = s\,(\mathbf d\cdot\mathbf n)$.
    Normal,
}

/// Options of the region preparation. Outside the crate, start from
/// [`RegionOptions::default`] and change fields with the `with_*` setters
/// (or by assignment).
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub struct RegionOptions {
    /// The plate's material (default [`Material::default`], the paper's).
    pub material: Material,
    /// $\alpha_0$ of eq 15 (default [`ALPHA0_DEFAULT`]).
    pub alpha0: f64,
    /// View-plane normal; `None` (the default) uses the region's
    /// area-weighted normal.
    pub view: Option<[f64; 3]>,
    /// Boundary extraction: the paper's alpha shape (default) or the
    /// region's own mesh edges.
    pub boundary: BoundaryMethod,
    /// Disk mapping: the paper's length-based eq 16 (default) or the
    /// harmonic (Tutte) mapping.
    pub mapping: MappingMethod,
}

setters!(RegionOptions {
    with_material: material: Material,
    with_alpha0: alpha0: f64,
    with_view: view: Option<[f64; 3]>,
    with_boundary: boundary: BoundaryMethod,
    with_mapping: mapping: MappingMethod,
});

/// How region vertices are mapped onto the unit disk.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MappingMethod {
    /// Eq 16: along rays from the centroid (needs a star-shaped region
    /// whose centroid lies inside).
    #[default]
    LengthBased,
    /// Harmonic (Tutte) embedding with the same boundary parametrisation:
    /// one-to-one for any disk-like region, no centroid condition.
    Harmonic,
}

/// How the boundary curve is found.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum BoundaryMethod {
    /// Eq 15: alpha shape on the Delaunay triangulation of the projection.
    #[default]
    AlphaShape,
    /// Boundary edges of the mesh triangles inside the region (robust to
    /// non-uniform vertex spacing).
    MeshEdges,
}

impl Default for RegionOptions {
    fn default() -> Self {
        RegionOptions {
            material: Material::default(),
            alpha0: ALPHA0_DEFAULT,
            view: None,
            boundary: BoundaryMethod::AlphaShape,
            mapping: MappingMethod::LengthBased,
        }
    }
}

/// A prepared region. Its fields are read through accessors: they are
/// derived from one another (the weights from the disk points and the
/// rigidity, the buffer-size guard of [`Self::apply`] from the region), so
/// only [`Self::new`] may set them.
#[derive(Clone, Debug)]
pub struct PlateDeformer {
    region: Vec<u32>,
    rest: Vec<[f64; 3]>,
    weights: Vec<f64>,
    disk: Vec<DiskPoint>,
    local: Vec<[f64; 2]>,
    frame: LocalFrame,
    boundary: Boundary,
    rigidity: f64,
    non_star_rays: usize,
    /// Largest region vertex index (buffer-size check of [`Self::apply`]).
    max_index: usize,
}

/// The region's vertices in first-seen order without repeats, and a mask
/// over the mesh; refuses fewer than 4 vertices, out-of-range indices and
/// non-finite positions.
fn validated_region(mesh: &Mesh, region: &[u32]) -> Result<(Vec<u32>, Vec<bool>), PlateError> {
    let nv = mesh.positions.len();
    if region.len() < 4 {
        return Err(PlateError::TooFewVertices(region.len(), 4));
    }
    let mut sel = vec![false; nv];
    let mut order: Vec<u32> = Vec::with_capacity(region.len());
    for &v in region {
        let vi = v as usize;
        if vi >= nv {
            return Err(PlateError::VertexOutOfBounds(vi, nv));
        }
        if !mesh.positions[vi].iter().all(|c| c.is_finite()) {
            return Err(PlateError::NonFinite(vi));
        }
        if !sel[vi] {
            sel[vi] = true;
            order.push(v);
        }
    }
    Ok((order, sel))
}

/// The local frame at the region's centroid facing `view` (default: the
/// region normal) and the region's projected local coordinates (eqs 13-14).
fn project_region(
    mesh: &Mesh,
    sel: &[bool],
    rest: &[[f64; 3]],
    view: Option<[f64; 3]>,
) -> Result<(LocalFrame, Vec<[f64; 2]>), PlateError> {
    let n = rest.len() as f64;
    let mut centroid3 = [0.0; 3];
    for p in rest {
        for k in 0..3 {
            centroid3[k] += p[k] / n;
        }
    }
    let rn = region_normal(mesh, sel);
    let view = match view {
        Some(v) => v,
        None if norm(rn) > 0.0 => rn,
        None => {
            return Err(PlateError::DegenerateProjection(
                "region has no triangles to define a normal; give a view direction".into(),
            ))
        }
    };
    let plane = ViewPlane::through(centroid3, view)?;
    let frame = LocalFrame::new(centroid3, view)?;
    let local = rest
        .iter()
        .map(|&p| {
            let l = frame.to_local(project(&plane, p));
            [l[0], l[1]]
        })
        .collect();
    Ok((frame, local))
}

/// Paper limit 1: the projection overlaps when region triangles flip
/// orientation in the view plane.
fn check_no_overlap(local: &[[f64; 2]], tris: &[[usize; 3]]) -> Result<(), PlateError> {
    let (mut plus, mut minus) = (0usize, 0usize);
    for &[a, b, c] in tris {
        let (pa, pb, pc) = (local[a], local[b], local[c]);
        let s = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pc[0] - pa[0]) * (pb[1] - pa[1]);
        if s > 0.0 {
            plus += 1;
        } else if s < 0.0 {
            minus += 1;
        }
    }
    if plus.min(minus) > 0 {
        return Err(PlateError::OverlappingProjection(plus.min(minus)));
    }
    Ok(())
}

/// Coincident projections (seam duplicates, poles) share one site.
struct Sites {
    /// The distinct projected points.
    unique: Vec<[f64; 2]>,
    /// Site of each region vertex.
    rep: Vec<usize>,
    /// First region vertex of each site.
    first: Vec<usize>,
}

impl Sites {
    fn of(local: &[[f64; 2]]) -> Sites {
        let mut rep = Vec::with_capacity(local.len());
        let mut unique: Vec<[f64; 2]> = Vec::new();
        let mut first: Vec<usize> = Vec::new();
        let mut seen: HashMap<(u64, u64), usize> = HashMap::new();
        for (i, p) in local.iter().enumerate() {
            let key = ((p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits());
            let u = *seen.entry(key).or_insert_with(|| {
                unique.push(*p);
                first.push(i);
                unique.len() - 1
            });
            rep.push(u);
        }
        Sites { unique, rep, first }
    }
}

/// Disk coordinates of the sites (eq 16, or the harmonic map) and the number
/// of rays from the centroid that cross the boundary more than once.
fn map_to_disk(
    unique: &[[f64; 2]],
    local: &[[f64; 2]],
    boundary: &Boundary,
    mapping: MappingMethod,
) -> Result<(Vec<DiskPoint>, usize), PlateError> {
    match mapping {
        MappingMethod::LengthBased => {
            let n = local.len() as f64;
            let mut c2 = [0.0; 2];
            for p in local {
                c2[0] += p[0] / n;
                c2[1] += p[1] / n;
            }
            let polygon: Vec<[f64; 2]> = boundary.loop_indices.iter().map(|&i| unique[i]).collect();
            let mut disk_map = DiskMapping::new(polygon, c2)?;
            let on_loop: HashMap<usize, usize> = boundary
                .loop_indices
                .iter()
                .enumerate()
                .map(|(k, &i)| (i, k))
                .collect();
            let ud: Vec<DiskPoint> = unique
                .iter()
                .enumerate()
                .map(|(i, &p)| disk_map.map_point(p, on_loop.get(&i).copied()))
                .collect();
            Ok((ud, disk_map.non_star_rays))
        }
        MappingMethod::Harmonic => Ok((
            harmonic_disk(
                unique.len(),
                &boundary.triangles,
                &boundary.loop_indices,
                unique,
            )?,
            0,
        )),
    }
}

/// Area-weighted normal of the triangles whose three vertices are in `sel`.
pub fn region_normal(mesh: &Mesh, sel: &[bool]) -> [f64; 3] {
    let mut n = [0.0; 3];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        if tri.iter().all(|&v| sel[v as usize]) {
            let a = mesh.face_normal_area(t);
            for k in 0..3 {
                n[k] += a[k];
            }
        }
    }
    n
}

impl PlateDeformer {
    /// Prepares `region` (vertex indices of `mesh`): projection (eqs 13-14),
    /// alpha-shape boundary (eq 15), disk mapping (eq 16), eq-12 weights.
    /// Detects the paper's limits (overlapping projection, centroid outside).
    pub fn new(mesh: &Mesh, region: &[u32], opts: &RegionOptions) -> Result<Self, PlateError> {
        let rigidity = opts.material.rigidity()?;
        let (order, sel) = validated_region(mesh, region)?;
        let rest: Vec<[f64; 3]> = order.iter().map(|&v| mesh.positions[v as usize]).collect();
        let (frame, local) = project_region(mesh, &sel, &rest, opts.view)?;
        // position of each mesh vertex in the region order
        let pos: HashMap<u32, usize> = order.iter().enumerate().map(|(k, &v)| (v, k)).collect();
        let region_tris: Vec<[usize; 3]> = mesh
            .triangles
            .iter()
            .filter_map(|t| Some([*pos.get(&t[0])?, *pos.get(&t[1])?, *pos.get(&t[2])?]))
            .collect();
        check_no_overlap(&local, &region_tris)?;
        let sites = Sites::of(&local);
        let mut boundary = match opts.boundary {
            BoundaryMethod::AlphaShape => alpha_shape(&sites.unique, opts.alpha0)?,
            BoundaryMethod::MeshEdges => {
                let tris: Vec<[usize; 3]> = region_tris
                    .iter()
                    .map(|t| t.map(|k| sites.rep[k]))
                    .collect();
                mesh_edge_boundary(&sites.unique, &tris)?
            }
        };
        let (unique_disk, non_star_rays) =
            map_to_disk(&sites.unique, &local, &boundary, opts.mapping)?;
        let disk: Vec<DiskPoint> = sites.rep.iter().map(|&u| unique_disk[u]).collect();
        // boundary indices refer to region vertices (first of each site)
        for i in boundary.loop_indices.iter_mut() {
            *i = sites.first[*i];
        }
        for t in boundary.triangles.iter_mut() {
            *t = t.map(|i| sites.first[i]);
        }
        let weights = disk
            .iter()
            .map(|d| {
                if d.rho >= 1.0 {
                    0.0
                } else {
                    disk_solution(1.0, rigidity, d.u, d.v)
                }
            })
            .collect();
        let max_index = order.iter().map(|&v| v as usize).max().unwrap_or(0);
        Ok(PlateDeformer {
            region: order,
            rest,
            weights,
            disk,
            local,
            frame,
            boundary,
            rigidity,
            non_star_rays,
            max_index,
        })
    }

    /// Region vertex indices into the mesh (first-seen order, no repeats).
    pub fn region(&self) -> &[u32] {
        &self.region
    }

    /// Rest positions of the region vertices.
    pub fn rest(&self) -> &[[f64; 3]] {
        &self.rest
    }

    /// Precomputed eq-12 weights $(u^2+v^2-1)^2/(64D)$ of the region
    /// vertices (zero outside the disk).
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// Disk coordinates (eq 16) of the region vertices.
    pub fn disk(&self) -> &[DiskPoint] {
        &self.disk
    }

    /// Projected local coordinates (eq 14) of the region vertices.
    pub fn local(&self) -> &[[f64; 2]] {
        &self.local
    }

    /// The local frame of the projection (eq 14).
    pub fn frame(&self) -> &LocalFrame {
        &self.frame
    }

    /// Unit region normal (the frame's $z'$ axis, facing the view).
    pub fn normal(&self) -> [f64; 3] {
        self.frame.vz
    }

    /// The boundary (eq 15); its indices refer to [`Self::region`].
    pub fn boundary(&self) -> &Boundary {
        &self.boundary
    }

    /// Flexural rigidity $D$ of the material.
    pub fn rigidity(&self) -> f64 {
        self.rigidity
    }

    /// Rays from the centroid that cross the boundary more than once.
    pub fn non_star_rays(&self) -> usize {
        self.non_star_rays
    }

    /// The sculpting force vector for a cursor motion `d` with sensitivity
    /// `s` ($q_\xi = s d_\xi$, or along the normal).
    pub fn force(&self, d: [f64; 3], sensitivity: f64, direction: Direction) -> [f64; 3] {
        match direction {
            Direction::Cursor => [sensitivity * d[0], sensitivity * d[1], sensitivity * d[2]],
            Direction::Normal => {
                let n = self.normal();
                let q = sensitivity * crate::mesh::dot(d, n);
                [q * n[0], q * n[1], q * n[2]]
            }
        }
    }

    /// One cursor move: writes the deformed region into `positions`
    /// (the whole mesh's vertex buffer), one pass over the region.
    pub fn apply(&self, positions: &mut [[f64; 3]], force: [f64; 3]) -> Result<(), PlateError> {
        if positions.len() <= self.max_index {
            return Err(PlateError::VertexOutOfBounds(
                self.max_index,
                positions.len(),
            ));
        }
        for ((&v, p0), &w) in self.region.iter().zip(&self.rest).zip(&self.weights) {
            positions[v as usize] = [
                p0[0] + force[0] * w,
                p0[1] + force[1] * w,
                p0[2] + force[2] * w,
            ];
        }
        Ok(())
    }

    /// The force of [`Self::force`], refused when the motion or the
    /// sensitivity is not finite or their product overflows.
    pub fn checked_force(
        &self,
        d: [f64; 3],
        sensitivity: f64,
        direction: Direction,
    ) -> Result<[f64; 3], PlateError> {
        if !(sensitivity.is_finite() && d.iter().all(|c| c.is_finite())) {
            return Err(PlateError::NonFiniteForce { d, sensitivity });
        }
        let f = self.force(d, sensitivity, direction);
        if f.iter().any(|x| !x.is_finite()) {
            return Err(PlateError::ForceTooLarge {
                d,
                sensitivity,
                what: "overflows",
            });
        }
        Ok(f)
    }

    /// Largest displacement of a region vertex under `force`: the peak
    /// eq-12 weight times the force's length.
    pub fn max_displacement(&self, force: [f64; 3]) -> f64 {
        let peak = self.weights.iter().fold(0.0f64, |m, w| m.max(*w));
        peak * crate::mesh::norm(force)
    }

    /// Deformed copy of `mesh` for cursor motion `d`; refuses a motion that
    /// would move a vertex to a non-finite position.
    pub fn deform(
        &self,
        mesh: &Mesh,
        d: [f64; 3],
        sensitivity: f64,
        direction: Direction,
    ) -> Result<Mesh, PlateError> {
        let force = self.checked_force(d, sensitivity, direction)?;
        let mut out = mesh.clone();
        self.apply(&mut out.positions, force)?;
        if self
            .region
            .iter()
            .any(|&v| out.positions[v as usize].iter().any(|x| !x.is_finite()))
        {
            return Err(PlateError::ForceTooLarge {
                d,
                sensitivity,
                what: "moves vertices to non-finite positions",
            });
        }
        Ok(out)
    }
}
