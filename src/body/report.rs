//! The report of the closed body ([`super::closed`]): topology, errors
//! against the input skin, join jumps, data size; and loading the body to
//! reconstruct.

use super::cavity::{find_cavities, Cavities};
use super::intersect::{intersections_of, Intersections};
use super::layout::Layout;
use super::sites::{closest_hits, error_sites, hit_distances, ErrorSite};
use super::BodyError;
use crate::character::assembly::{JoinReport, Model, SeamReport};
use crate::character::doc::{PartSpec, SectionShape};
use crate::mesh::metrics::{sample_points, stats, DistanceStats};
use crate::mesh::topology::{report as topology, TopologyReport};
use crate::mesh::Mesh;

/// Errors against the input body, relative to its height.
#[derive(Clone, Debug, serde::Serialize)]
pub struct ClosedReport {
    pub layout: Layout,
    pub body_height: f64,
    pub topology: TopologyReport,
    pub recon_to_skin: DistanceStats,
    pub skin_to_recon: DistanceStats,
    pub recon_to_skin_rms_rel: f64,
    pub recon_to_skin_max_rel: f64,
    pub skin_to_recon_rms_rel: f64,
    pub skin_to_recon_max_rel: f64,
    /// Where the largest recon -> skin error sits.
    pub recon_to_skin_max_at: Option<ErrorSite>,
    /// Where the largest skin -> recon error sits.
    pub skin_to_recon_max_at: Option<ErrorSite>,
    /// The skin's cavity vertices ([`super::cavity`]: mouth, eye sockets),
    /// which one outer loop per section cannot reach.
    pub skin_cavities: Cavities,
    /// Skin -> recon over the outer skin only (every vertex but the cavity
    /// ones): the measure the max target is judged on; the full-skin one
    /// above stays reported beside it.
    pub skin_to_recon_outer: DistanceStats,
    pub skin_to_recon_outer_rms_rel: f64,
    pub skin_to_recon_outer_max_rel: f64,
    pub skin_to_recon_outer_max_at: Option<ErrorSite>,
    /// Crossing triangle pairs of the closed mesh ([`super::intersect`]).
    pub self_intersections: Intersections,
    /// Largest relative C0 / C1 / C2 jump over every join.
    pub max_join: [f64; 3],
    pub joins: Vec<JoinReport>,
    pub seams: Vec<SeamReport>,
    /// Sections per part (with tips) and the numbers they store.
    pub sections: Vec<(String, usize)>,
    pub gec_numbers: usize,
    pub skin_vertex_numbers: usize,
    pub triangles: usize,
    /// Per hand (left, right): the thumb against the skin.
    pub hands: Vec<HandReport>,
    /// Arms built without a thumb (a mitten, thumb merged), each with the
    /// reason ([`super::closed::ClosedOptions::thumbs`]); empty when both
    /// hands have their thumb.
    pub thumbless: Vec<String>,
}

/// The thumb of one hand against the skin ([`super::hand`]).
#[derive(Clone, Debug, serde::Serialize)]
pub struct HandReport {
    /// The skin's thumb vertices ([`super::hand::thumb_vertices`]) and their
    /// largest distance to the reconstruction, relative to the height.
    pub thumb_vertices: usize,
    pub thumb_skin_to_recon_max_rel: f64,
    /// Air points of the web between thumb and index finger (middles of the
    /// gaps between their loops along the arm trace), and how many of them
    /// the reconstruction encloses (winding number above 1/2: a mitten
    /// fills the web).
    pub web_points: usize,
    pub web_points_inside: usize,
    /// The thumb's arc of the wrist ring (radians either side of it).
    pub thumb_arc: f64,
}

/// Measures a built closed body against its skin.
pub fn measure(
    skin: &Mesh,
    lay: &Layout,
    model: &Model,
    specs: &[PartSpec],
    hands: &[(super::hand::Hand, f64)],
) -> ClosedReport {
    let pairs = super::intersect::crossing_pairs(&model.mesh);
    measure_with_crossings(skin, lay, model, specs, hands, &pairs)
}

/// [`measure`] with the crossing pairs of `model.mesh` found before
/// ([`super::intersect::crossing_pairs`]; the closed reconstruction's
/// shoulder-cut search finds them for the model it keeps).
pub fn measure_with_crossings(
    skin: &Mesh,
    lay: &Layout,
    model: &Model,
    specs: &[PartSpec],
    hands: &[(super::hand::Hand, f64)],
    pairs: &[super::intersect::CrossingPair],
) -> ClosedReport {
    let h = lay.height();
    let hand_reports = hands
        .iter()
        .map(|(hand, arc)| {
            let tv = super::hand::thumb_vertices(skin, hand);
            let pts: Vec<[f64; 3]> = tv.iter().map(|&i| skin.positions[i]).collect();
            let d = stats(&hit_distances(&closest_hits(&pts, &model.mesh)));
            let inside = hand
                .web
                .iter()
                .filter(|p| super::hand::winding_number(&model.mesh, **p).abs() > 0.5)
                .count();
            HandReport {
                thumb_vertices: tv.len(),
                thumb_skin_to_recon_max_rel: if tv.is_empty() { f64::NAN } else { d.max / h },
                web_points: hand.web.len(),
                web_points_inside: inside,
                thumb_arc: *arc,
            }
        })
        .collect();
    // one closest-point query per sample, for the statistics and the sites
    let r2s_points = sample_points(&model.mesh);
    let r2s_hits = closest_hits(&r2s_points, skin);
    let s2r_hits = closest_hits(&skin.positions, &model.mesh);
    let r2s = stats(&hit_distances(&r2s_hits));
    let s2r = stats(&hit_distances(&s2r_hits));
    let (r2s_at, s2r_at) = error_sites(
        &model.mesh,
        &r2s_points,
        &r2s_hits,
        &s2r_hits,
        skin,
        specs,
        lay,
    );
    let cav = find_cavities(skin, lay.sole, h);
    let outer_hits: Vec<_> = s2r_hits
        .iter()
        .zip(&cav.cavity)
        .map(|(hit, &c)| if c { None } else { *hit })
        .collect();
    let outer_d: Vec<f64> = s2r_hits
        .iter()
        .zip(&cav.cavity)
        .filter(|(_, &c)| !c)
        .map(|(hit, _)| hit.map_or(f64::INFINITY, |x| x.1))
        .collect();
    let s2r_outer = stats(&outer_d);
    let (_, s2r_outer_at) = error_sites(&model.mesh, &[], &[], &outer_hits, skin, specs, lay);
    let mut max_join = [0.0f64; 3];
    for j in &model.joins {
        max_join[0] = max_join[0].max(j.c0);
        max_join[1] = max_join[1].max(j.c1);
        max_join[2] = max_join[2].max(j.c2);
    }
    let sections: Vec<(String, usize)> = specs
        .iter()
        .map(|p| (p.name.clone(), p.sections.len()))
        .collect();
    ClosedReport {
        layout: *lay,
        body_height: h,
        topology: topology(&model.mesh),
        recon_to_skin: r2s,
        skin_to_recon: s2r,
        recon_to_skin_rms_rel: r2s.rms / h,
        recon_to_skin_max_rel: r2s.max / h,
        skin_to_recon_rms_rel: s2r.rms / h,
        skin_to_recon_max_rel: s2r.max / h,
        recon_to_skin_max_at: r2s_at,
        skin_to_recon_max_at: s2r_at,
        skin_cavities: cav,
        skin_to_recon_outer: s2r_outer,
        skin_to_recon_outer_rms_rel: s2r_outer.rms / h,
        skin_to_recon_outer_max_rel: s2r_outer.max / h,
        skin_to_recon_outer_max_at: s2r_outer_at,
        max_join,
        self_intersections: intersections_of(&model.mesh, pairs),
        joins: model.joins.clone(),
        seams: model.seams.clone(),
        sections,
        gec_numbers: specs.iter().map(section_numbers).sum(),
        skin_vertex_numbers: 3 * skin.positions.len(),
        triangles: model.mesh.triangles.len(),
        hands: hand_reports,
        thumbless: Vec::new(),
    }
}

/// Numbers a part's sections store: a fitted section u, its frame (origin
/// and two unit vectors: 9), centre 2 and 4 per term it has (a section with
/// few sliced points is fitted with fewer than the asked terms); a collapsed
/// tip u and its point.
pub fn section_numbers(p: &PartSpec) -> usize {
    p.sections
        .iter()
        .map(|s| match &s.shape {
            SectionShape::Gec { x, .. } => 1 + 9 + 2 + 4 * x.len(),
            _ => 4,
        })
        .sum()
}

/// The body to reconstruct: the mesh at `path`, or the bundled MakeHuman body
/// with `morphs` (`NAME=WEIGHT`) applied.
pub fn load_body(path: Option<&std::path::Path>, morphs: &[String]) -> Result<Mesh, BodyError> {
    if let Some(p) = path {
        if !morphs.is_empty() {
            return Err(BodyError::MorphWithMesh);
        }
        let m = crate::mesh::io::read(p)?;
        m.validate()?;
        return Ok(m);
    }
    let mut targets = Vec::new();
    for s in morphs {
        let (name, w) = s.split_once('=').ok_or_else(|| BodyError::Morph {
            spec: s.clone(),
            problem: "expected NAME=WEIGHT".into(),
        })?;
        let w: f64 = w.trim().parse().map_err(|_| BodyError::Morph {
            spec: s.clone(),
            problem: "weight is not a number".into(),
        })?;
        if !w.is_finite() || w.abs() > MORPH_WEIGHT_MAX {
            return Err(BodyError::Morph {
                spec: s.clone(),
                problem: format!("weight outside [-{MORPH_WEIGHT_MAX}, {MORPH_WEIGHT_MAX}]"),
            });
        }
        targets.push((crate::makehuman::target(name.trim())?, w));
    }
    Ok(crate::makehuman::body(&targets)?.mesh)
}

pub use crate::makehuman::MORPH_WEIGHT_MAX;

impl ClosedReport {
    /// The RMS the target [`super::closed::RMS_MAX_REL`] is judged on: the
    /// larger of both directions over the whole skin.
    pub fn judged_rms_rel(&self) -> f64 {
        self.recon_to_skin_rms_rel.max(self.skin_to_recon_rms_rel)
    }

    /// The max the target [`super::closed::MAX_MAX_REL`] is judged on: the
    /// larger of recon -> skin and skin -> recon over the outer skin (the
    /// cavity vertices of [`super::cavity`] left out: no section with one
    /// outer loop reaches them; the full-skin max is
    /// `skin_to_recon_max_rel`, reported beside it).
    pub fn judged_max_rel(&self) -> f64 {
        self.recon_to_skin_max_rel
            .max(self.skin_to_recon_outer_max_rel)
    }

    /// Text summary (percent of the height).
    pub fn summary(&self, output: &std::path::Path) -> String {
        let t = &self.topology;
        format!(
            "wrote {} ({} triangles); watertight {} manifold {} oriented {}\n  reconstruction -> skin: RMS {:.3} %, max {:.3} % of the height\n  skin -> reconstruction: RMS {:.3} %, max {:.3} % (all {} skin vertices)\n  skin -> reconstruction, outer skin: RMS {:.3} %, max {:.3} % ({} cavity vertices left out: {}; the max target is judged on this)\n  joins: max C0 {:.2e} C1 {:.2e} C2 {:.2e}\n  self-intersections: {} crossing triangle pairs {:?}\n",
            output.display(),
            self.triangles,
            t.watertight,
            t.manifold,
            t.oriented,
            100.0 * self.recon_to_skin_rms_rel,
            100.0 * self.recon_to_skin_max_rel,
            100.0 * self.skin_to_recon_rms_rel,
            100.0 * self.skin_to_recon_max_rel,
            self.skin_to_recon.samples,
            100.0 * self.skin_to_recon_outer_rms_rel,
            100.0 * self.skin_to_recon_outer_max_rel,
            self.skin_cavities.count,
            self.skin_cavities.height_range_rel.map_or("none".to_string(), |(a, b)| format!("heights {a:.3}-{b:.3} of the body")),
            self.max_join[0],
            self.max_join[1],
            self.max_join[2],
            self.self_intersections.pairs,
            self.self_intersections.by_groups
        ) + &[("reconstruction -> skin", &self.recon_to_skin_max_at), ("skin -> reconstruction", &self.skin_to_recon_max_at), ("skin -> reconstruction, outer skin", &self.skin_to_recon_outer_max_at)]
            .iter()
            .filter_map(|(w, s)| s.as_ref().map(|s| format!("  max {w}: {}\n", s.line())))
            .collect::<String>()
    }
}
