//! Applying deformations to shapes (paper 000 sec 3.1, sec 5.1, Fig 14).
//!
//! * [`Deformed`]: a base [`Surface`] plus a deformation patch mapped onto a
//!   parameter window `[u_a, u_b] x [v_a, v_b]` (a 2-sided patch over a
//!   u-range of a part closed in v, or a 4-sided patch over any window). The
//!   patch is clamped on its edges, so the result is C1 across them.
//! * [`deform_region`]: a mesh region enclosed by a drawn closed curve. The
//!   curve's vertices are projected to their best-fit plane (axes `e1, e2`
//!   from the bounding box of the curve, normal `n`); an enclosed vertex at
//!   plane coordinates `(x, y)` gets
//!   $v = (y - y_{min})/(y_{max} - y_{min})$ and
//!   $u = (x - x_l(y))/(x_r(y) - x_l(y))$, with $x_l, x_r$ the curve's
//!   crossings of the line at height $y$ around $x$: the enclosed region maps
//!   onto the unit square with the curve on its boundary (the paper's
//!   "automatically parametrized into $0 \le u, v \le 1$"). The vertex moves by
//!   $s\,w(u, v)\,\mathbf d$ with `w` the deformation's first component,
//!   $\mathbf d$ the given direction or the vertex normal, and the magnitude
//!   `s` chosen so that the largest displacement equals the drag distance.
//! * [`deform_part`]: a mesh part closed in v (a limb, a torso) with a 2-sided
//!   deformation over a u-range of its axis, parameterised cylindrically
//!   ([`cylinder_uv`]), moved the same way.

use super::Pde4Error;
use crate::jet::Real;
use crate::mesh::Mesh;
use crate::surface::{Domain, Surface};

/// Base surface plus a deformation on a parameter window.
#[derive(Clone, Debug)]
pub struct Deformed<S, D> {
    pub base: S,
    pub deformation: D,
    /// `(u_a, u_b)` of the base mapped to `u in [0, 1]` of the deformation.
    pub u_window: (f64, f64),
    /// `(v_a, v_b)` (the whole closed range for 2-sided patches).
    pub v_window: (f64, f64),
    /// Scale applied to the displacement.
    pub scale: f64,
}

impl<S: Surface, D: Surface> Deformed<S, D> {
    /// Checks the window lies inside the base domain and is not empty.
    pub fn new(
        base: S,
        deformation: D,
        u_window: (f64, f64),
        v_window: (f64, f64),
        scale: f64,
    ) -> Result<Self, Pde4Error> {
        let dom = base.domain();
        for (what, (lo, hi), (dlo, dhi)) in
            [("u window", u_window, dom.u), ("v window", v_window, dom.v)]
        {
            if !lo.is_finite() || !hi.is_finite() {
                return Err(Pde4Error::NonFinite {
                    what,
                    value: if lo.is_finite() { hi } else { lo },
                });
            }
            if hi <= lo {
                return Err(Pde4Error::EmptyRange { what, lo, hi });
            }
            if lo < dlo || hi > dhi {
                return Err(Pde4Error::OutsideDomain {
                    what,
                    lo,
                    hi,
                    dlo,
                    dhi,
                });
            }
        }
        if !scale.is_finite() {
            return Err(Pde4Error::NonFinite {
                what: "scale",
                value: scale,
            });
        }
        Ok(Deformed {
            base,
            deformation,
            u_window,
            v_window,
            scale,
        })
    }
}

impl<S: Surface, D: Surface> Surface for Deformed<S, D> {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let mut p = self.base.eval(u, v);
        let (uv, vv) = (u.value(), v.value());
        let (ua, ub) = self.u_window;
        let (va, vb) = self.v_window;
        if uv >= ua && uv <= ub && vv >= va && vv <= vb {
            let d = self
                .deformation
                .eval((u - ua) / (ub - ua), (v - va) / (vb - va));
            for k in 0..3 {
                p[k] += d[k] * self.scale;
            }
        }
        p
    }
    fn domain(&self) -> Domain {
        self.base.domain()
    }
}

/// Displacement direction for mesh deformation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Direction {
    /// Along each vertex normal.
    Normal,
    /// Along a fixed vector (normalised).
    Vector([f64; 3]),
}

/// Result of [`deform_region`].
#[derive(Clone, Debug)]
pub struct RegionDeformation {
    pub mesh: Mesh,
    /// Indices of the moved vertices and their `(u, v)`.
    pub region: Vec<(usize, [f64; 2])>,
    /// Magnitude applied to the unit deformation.
    pub magnitude: f64,
}

/// Local frame of the curve: origin, `e1`, `e2`, normal.
/// Origin, `e1`, `e2`, normal.
type Frame = ([f64; 3], [f64; 3], [f64; 3], [f64; 3]);

fn curve_frame(curve: &[[f64; 3]]) -> Result<Frame, Pde4Error> {
    use crate::mesh::{add, dot, norm, scale, sub};
    let n = curve.len() as f64;
    let c = scale(curve.iter().fold([0.0; 3], |a, p| add(a, *p)), 1.0 / n);
    // Newell normal of the closed polygon
    let mut nn = [0.0; 3];
    for i in 0..curve.len() {
        let (a, b) = (sub(curve[i], c), sub(curve[(i + 1) % curve.len()], c));
        nn = add(nn, crate::surface::cross(a, b));
    }
    let ln = norm(nn);
    if ln.is_nan() || ln <= 0.0 {
        return Err(Pde4Error::Region("the drawn curve encloses no area".into()));
    }
    let nrm = scale(nn, 1.0 / ln);
    // e1: direction of the farthest curve point, projected
    let far =
        curve
            .iter()
            .map(|p| sub(*p, c))
            .fold([0.0; 3], |a, d| if norm(d) > norm(a) { d } else { a });
    let e1 = sub(far, scale(nrm, dot(far, nrm)));
    let e1 = scale(e1, 1.0 / norm(e1).max(f64::MIN_POSITIVE));
    let e2 = crate::surface::cross(nrm, e1);
    Ok((c, e1, e2, nrm))
}

/// `(u, v)` of a point at plane coordinates `(x, y)` inside the polygon `poly`, if inside.
pub fn region_uv(poly: &[[f64; 2]], x: f64, y: f64) -> Option<[f64; 2]> {
    let (lo, hi) = crate::vec3::bounds(poly)?;
    let (ymin, ymax) = (lo[1], hi[1]);
    if !(y > ymin && y < ymax) {
        return None;
    }
    let mut xs: Vec<f64> = Vec::new();
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a[1] <= y) != (b[1] <= y) {
            xs.push(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
        }
    }
    xs.sort_by(f64::total_cmp);
    for pair in xs.chunks_exact(2) {
        if x > pair[0] && x < pair[1] {
            return Some([
                (x - pair[0]) / (pair[1] - pair[0]),
                (y - ymin) / (ymax - ymin),
            ]);
        }
    }
    None
}

/// Default `depth` of [`deform_region`]: vertices within this distance of
/// the curve's plane move (the MakeHuman body is in decimetres).
pub const DEPTH_DEFAULT: f64 = 1.0;
/// Default `u_range` of [`deform_part`]: the whole axis.
pub const U_RANGE_DEFAULT: (f64, f64) = (0.0, 1.0);
/// Default `radius` of [`deform_part`]: every vertex whose axial fraction
/// lies in the range, however far from the axis.
pub const RADIUS_DEFAULT: f64 = f64::INFINITY;

/// Deforms the mesh vertices enclosed by `curve` with the scalar deformation
/// `w(u, v)` (first component of `deformation`) so the largest displacement is `drag`.
/// Only vertices within `depth` of the curve's plane (along its normal) are moved.
pub fn deform_region<D: Surface>(
    mesh: &Mesh,
    curve: &[[f64; 3]],
    deformation: &D,
    direction: Direction,
    drag: f64,
    depth: f64,
) -> Result<RegionDeformation, Pde4Error> {
    use crate::mesh::{dot, sub};
    if curve.len() < 3 {
        return Err(Pde4Error::Region(format!(
            "the closed curve needs at least 3 points, got {}",
            curve.len()
        )));
    }
    if curve.iter().flatten().any(|x| !x.is_finite()) {
        return Err(Pde4Error::NonFinite {
            what: "curve point",
            value: f64::NAN,
        });
    }
    if !depth.is_finite() || depth <= 0.0 {
        return Err(Pde4Error::NotPositive {
            what: "depth",
            value: depth,
        });
    }
    let dir = check_motion(direction, drag)?;
    let (c, e1, e2, nrm) = curve_frame(curve)?;
    let poly: Vec<[f64; 2]> = curve
        .iter()
        .map(|p| [dot(sub(*p, c), e1), dot(sub(*p, c), e2)])
        .collect();
    let mut region = Vec::new();
    for (i, p) in mesh.positions.iter().enumerate() {
        let d = sub(*p, c);
        if dot(d, nrm).abs() > depth {
            continue;
        }
        if let Some(uv) = region_uv(&poly, dot(d, e1), dot(d, e2)) {
            region.push((i, uv));
        }
    }
    if region.is_empty() {
        return Err(Pde4Error::Region(
            "the drawn curve encloses no mesh vertex".into(),
        ));
    }
    displace(mesh, region, deformation, dir, drag)
}

/// Validates drag and direction; `None` means along the vertex normals.
fn check_motion(direction: Direction, drag: f64) -> Result<Option<[f64; 3]>, Pde4Error> {
    use crate::mesh::norm;
    if !drag.is_finite() {
        return Err(Pde4Error::NonFinite {
            what: "drag",
            value: drag,
        });
    }
    match direction {
        Direction::Vector(d) => {
            let l = norm(d);
            if l.is_nan() || l <= 0.0 || !l.is_finite() {
                return Err(Pde4Error::Region(
                    "direction vector is zero or not finite".into(),
                ));
            }
            Ok(Some([d[0] / l, d[1] / l, d[2] / l]))
        }
        Direction::Normal => Ok(None),
    }
}

/// Moves each `(vertex, (u, v))` of `region` by `s w(u, v) d` with `s` such
/// that the largest displacement is `drag`.
fn displace<D: Surface>(
    mesh: &Mesh,
    region: Vec<(usize, [f64; 2])>,
    deformation: &D,
    dir: Option<[f64; 3]>,
    drag: f64,
) -> Result<RegionDeformation, Pde4Error> {
    let w: Vec<f64> = region
        .iter()
        .map(|(_, uv)| deformation.point(uv[0], uv[1])[0])
        .collect();
    let wmax = w.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    if wmax.is_nan() || wmax <= 0.0 || !wmax.is_finite() {
        return Err(Pde4Error::Region(
            "the deformation vanishes on the region".into(),
        ));
    }
    let magnitude = drag / wmax;
    let normals = mesh.vertex_normals();
    let mut out = mesh.clone();
    for ((i, _), wi) in region.iter().zip(&w) {
        let d = dir.unwrap_or(normals[*i]);
        for k in 0..3 {
            out.positions[*i][k] += magnitude * wi * d[k];
        }
        // a finite drag near f64::MAX still overflows the coordinates
        if !out.positions[*i].iter().all(|x| x.is_finite()) {
            return Err(Pde4Error::Region(format!(
                "drag {} moves vertex {i} to a non-finite position: use a smaller drag",
                crate::limits::Num(drag)
            )));
        }
    }
    Ok(RegionDeformation {
        mesh: out,
        region,
        magnitude,
    })
}

/// Cylindrical parameterisation of a part closed in v about the axis from
/// `a` to `b`: `u` is the fraction along the axis of a vertex's projection,
/// `v` its angle about the axis over `2 pi`, measured from a fixed direction
/// perpendicular to the axis (the world axis least aligned with it, projected).
/// Returns `(u, v, distance from the axis)`, or `None` where the angle is undefined.
pub fn cylinder_uv(a: [f64; 3], b: [f64; 3], p: [f64; 3]) -> Option<(f64, f64, f64)> {
    use crate::mesh::{dot, norm, scale, sub};
    let ax = sub(b, a);
    let len = norm(ax);
    if !(len > 0.0 && len.is_finite()) {
        return None;
    }
    let e3 = scale(ax, 1.0 / len);
    let k = (0..3)
        .min_by(|&i, &j| e3[i].abs().total_cmp(&e3[j].abs()))
        .unwrap_or(0);
    let mut w = [0.0; 3];
    w[k] = 1.0;
    let e1 = crate::surface::normalize(sub(w, scale(e3, dot(w, e3))));
    let e2 = crate::surface::cross(e3, e1);
    let d = sub(p, a);
    let u = dot(d, e3) / len;
    let (x, y) = (dot(d, e1), dot(d, e2));
    let r = x.hypot(y);
    if r.is_nan() || r <= 0.0 {
        return None;
    }
    let v = (y.atan2(x) / (2.0 * std::f64::consts::PI)).rem_euclid(1.0);
    Some((u, v, r))
}

/// Deforms a part that is closed in v (a limb or torso mesh) with a 2-sided
/// deformation over the u-range `[u_a, u_b]` of its axis from `a` to `b`
/// (paper 000 sec 3.1: the deformation is clamped at both ends of the range,
/// so the part stays C1 there). Vertices whose axial fraction lies in the
/// range and whose distance from the axis is at most `radius` get
/// `u = (t - u_a)/(u_b - u_a)` and the angle `v` of [`cylinder_uv`], and move
/// by `s w(u, v) d` as in [`deform_region`].
#[allow(clippy::too_many_arguments)]
pub fn deform_part<D: Surface>(
    mesh: &Mesh,
    axis: ([f64; 3], [f64; 3]),
    u_range: (f64, f64),
    radius: f64,
    deformation: &D,
    direction: Direction,
    drag: f64,
) -> Result<RegionDeformation, Pde4Error> {
    let (a, b) = axis;
    if a.iter().chain(&b).any(|x| !x.is_finite()) {
        return Err(Pde4Error::NonFinite {
            what: "axis point",
            value: f64::NAN,
        });
    }
    let len = crate::mesh::dist(a, b);
    if len.is_nan() || len <= 0.0 {
        return Err(Pde4Error::Region("the part axis has zero length".into()));
    }
    let (ua, ub) = u_range;
    if !ua.is_finite() || !ub.is_finite() {
        return Err(Pde4Error::NonFinite {
            what: "part u range",
            value: if ua.is_finite() { ub } else { ua },
        });
    }
    if ub <= ua {
        return Err(Pde4Error::EmptyRange {
            what: "part u range",
            lo: ua,
            hi: ub,
        });
    }
    if ua < 0.0 || ub > 1.0 {
        return Err(Pde4Error::OutsidePatch {
            what: "part u range",
            lo: ua,
            hi: ub,
        });
    }
    if radius.is_nan() || radius <= 0.0 {
        return Err(Pde4Error::NotPositive {
            what: "radius",
            value: radius,
        });
    }
    let dir = check_motion(direction, drag)?;
    let region: Vec<(usize, [f64; 2])> = mesh
        .positions
        .iter()
        .enumerate()
        .filter_map(|(i, p)| {
            let (t, v, r) = cylinder_uv(a, b, *p)?;
            (t >= ua && t <= ub && r <= radius).then_some((i, [(t - ua) / (ub - ua), v]))
        })
        .collect();
    if region.is_empty() {
        return Err(Pde4Error::Region(
            "no mesh vertex lies in the u-range of the part axis".into(),
        ));
    }
    displace(mesh, region, deformation, dir, drag)
}
