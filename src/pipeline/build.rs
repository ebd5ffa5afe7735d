//! Document -> model, once: a character document's drawings read, its
//! parts derived when it has none, its edit log replayed once, its parts
//! and transitions assembled into one mesh, its props composed, and the
//! result measured ([`build`]). Every caller (the CLI, the TUI's worker,
//! the demo, the figures, an editing [`super::Session`], a checked push)
//! goes through it.

use crate::character::assembly::{build_model_with, Model, PartCache};
use crate::character::doc::{CharacterDoc, DocError, Level};
use crate::character::log::{check_order, Edit, EditError};
use crate::character::part::PartSurface;
use crate::character::props::{self, PropError};
use crate::character::spec::PartSpec;
use crate::character::{ModelError, Resolution};
use crate::mesh::Mesh;
use crate::sketch::derive::derive;
use crate::sketch::input::Outline;
use crate::sketch::report::SketchReport;
use crate::sketch::SketchError;
use std::path::Path;

/// Everything a build produces.
#[derive(Clone, Debug)]
pub struct Built {
    /// The document with its derived parts and transitions filled in (the
    /// stored, unedited parts and the log: saving it never applies an edit
    /// twice).
    pub doc: CharacterDoc,
    /// The parts with the log's spec-level edits applied (what the model
    /// was built from).
    pub edited: Vec<PartSpec>,
    pub model: Model,
    pub report: SketchReport,
    pub front: Outline,
    pub side: Option<Outline>,
}

impl Built {
    /// Where the model misses its drawing (`sketch::overlay`): the body
    /// (without removed parts and props, as the report measures it)
    /// against the placed drawn outlines, as SVG.
    pub fn overlay_svg(&self) -> String {
        let mut names: Vec<&str> = self
            .report
            .removed
            .iter()
            .map(|r| r.name.as_str())
            .collect();
        names.extend(self.report.props.iter().map(|p| p.name.as_str()));
        let body = crate::sketch::report::without_groups(&self.model.mesh, &names);
        let views = crate::sketch::overlay::views(
            &body,
            &self.front.profile,
            self.side.as_ref().map(|s| &s.profile),
        );
        crate::sketch::overlay::svg(&views, self.report.height)
    }
}

/// Errors of a build, by step.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// The document fails its own validation.
    #[error(transparent)]
    Doc(#[from] DocError),
    /// Reading the drawings or deriving the parts failed.
    #[error(transparent)]
    Sketch(#[from] SketchError),
    /// The document's level needs an input it does not have.
    #[error("document: level {level} needs {needs}")]
    Level {
        level: &'static str,
        needs: &'static str,
    },
    /// An edit of the log failed when replayed.
    #[error("document: {0}")]
    Edit(#[from] EditError),
    /// Assembling the parts and transitions failed.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// A prop failed.
    #[error("document: {0}")]
    Prop(#[from] PropError),
    /// The built mesh has a vertex that is not finite.
    #[error("document: the built mesh has a non-finite vertex {index} ({position:?})")]
    NonFinite { index: usize, position: [f64; 3] },
    /// A redone edit was refused: the document it gives does not build
    /// (`source` says why).
    #[error("document: {what} refused: the document it gives does not build: {source}")]
    RedoRefused {
        what: String,
        #[source]
        source: Box<BuildError>,
    },
    /// A change would carry the model more than
    /// [`super::effect::GROWTH`] model sizes (its bounding box diagonal,
    /// `diagonal`, before the change) outside its extent.
    #[error(
        "document: {what}: the model would reach {} model sizes outside its extent before the change (limit {}; its size, the bounding box diagonal, is {}): the values are too large",
        crate::limits::Num(*reach),
        super::effect::GROWTH,
        crate::limits::Num(*diagonal)
    )]
    Growth {
        what: String,
        reach: f64,
        diagonal: f64,
    },
    /// The cancel hook asked the build to stop.
    #[error("cancelled")]
    Cancelled,
}

/// How to build a document. `BuildOptions::new(base)` gives the defaults;
/// the builders set the rest.
#[derive(Clone, Copy)]
#[non_exhaustive]
pub struct BuildOptions<'a> {
    /// Directory that relative profile and prop paths are resolved against
    /// (the document's directory).
    pub base: &'a Path,
    /// Mesh resolution (default [`Resolution::default`]).
    pub res: Resolution,
    /// Derive the parts from the inputs even when the document stores them
    /// (default false: stored parts are built as they are).
    pub rederive: bool,
    /// Asked before the drawings are read, between the parts' solves,
    /// between the props and at the end; `true` stops the build with
    /// [`BuildError::Cancelled`] (default: never). One part's solve, the
    /// assembly of the mesh and one prop's build are not interrupted.
    pub cancel: Option<&'a dyn Fn() -> bool>,
    /// When the derived model misses issue 28's bounds, build the other
    /// derivations the segmentation offers (a model as shells) and keep
    /// the one that misses them least (default true; false: the first
    /// derivation only, the stacked model).
    pub alternatives: bool,
}

impl std::fmt::Debug for BuildOptions<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BuildOptions")
            .field("base", &self.base)
            .field("res", &self.res)
            .field("rederive", &self.rederive)
            .field("cancel", &self.cancel.is_some())
            .field("alternatives", &self.alternatives)
            .finish()
    }
}

impl<'a> BuildOptions<'a> {
    /// The defaults, profiles relative to `base`.
    pub fn new(base: &'a Path) -> BuildOptions<'a> {
        BuildOptions {
            base,
            res: Resolution::default(),
            rederive: false,
            cancel: None,
            alternatives: true,
        }
    }

    /// Whether the other derivations are tried ([`BuildOptions::alternatives`]).
    pub fn alternatives(mut self, alternatives: bool) -> Self {
        self.alternatives = alternatives;
        self
    }

    /// Sets the mesh resolution.
    pub fn res(mut self, res: Resolution) -> Self {
        self.res = res;
        self
    }

    /// Derives the parts again from the inputs.
    pub fn rederive(mut self, rederive: bool) -> Self {
        self.rederive = rederive;
        self
    }

    /// Sets the cancel hook.
    pub fn cancel(mut self, cancel: &'a dyn Fn() -> bool) -> Self {
        self.cancel = Some(cancel);
        self
    }

    fn check_cancel(&self) -> Result<(), BuildError> {
        match self.cancel {
            Some(c) if c() => Err(BuildError::Cancelled),
            _ => Ok(()),
        }
    }
}

/// Builds a document: reads its profiles, derives the parts and
/// transitions when the document has none (or `opts.rederive`), replays the
/// active edits of its log once, in order (spec-level edits and force
/// displacements on the parts, `crate::edit`; then the plate and SASM
/// edits on the built mesh, [`apply_mesh_edits`]), solves the parts (from
/// `cache` when given: a rebuild re-solves only the parts whose
/// specification changed, bit for bit the same), assembles the mesh,
/// composes the props and measures the result. `Built::doc` holds the
/// derived, unedited parts and the log; the report describes the edited
/// parts.
pub fn build(
    doc: &CharacterDoc,
    opts: &BuildOptions,
    cache: Option<&mut PartCache>,
) -> Result<Built, BuildError> {
    opts.check_cancel()?;
    doc.validate()?;
    let base = opts.base;
    let (front, side, tol) = crate::sketch::place::read_views(doc, base)?;
    let placed = crate::sketch::place::place(
        &front,
        side.as_ref(),
        doc.inputs().height,
        doc.inputs().body_plan,
    )?;
    let placement = placed.report.placement;
    let (front, side) = (placed.front.clone(), placed.side.clone());
    let level = |needs| BuildError::Level {
        level: doc.level().name(),
        needs,
    };
    if doc.level() != Level::Initial && side.is_none() {
        return Err(level("a side profile"));
    }
    if doc.level() == Level::Final && doc.inputs().sections.is_empty() {
        return Err(level("key cross-section sketches"));
    }
    let removed = doc
        .removed_parts()
        .iter()
        .map(|r| crate::sketch::removed::removed_part(r, base, tol, &placement))
        .collect::<Result<Vec<_>, _>>()?;
    let mut out = doc.clone();
    let mut local = PartCache::default();
    let cache = match cache {
        Some(c) => c,
        None => &mut local,
    };
    let yr = crate::polygon::span(front.points(), 1);
    let height = yr[1] - yr[0];
    let mut others = Vec::new();
    let mut first_shells = false;
    if opts.rederive || doc.parts().is_empty() {
        let d = derive(
            front.points(),
            side.as_ref().map(|s| s.points()),
            &crate::sketch::place::placed_sections(&doc.inputs().sections, &placement),
            &front.cuts,
            doc.level(),
            doc.inputs().body_plan,
        )?;
        let mut parts = d.parts;
        parts.extend(removed.iter().map(|r| r.spec.clone()));
        let mut transitions = d.transitions;
        let solved = parts
            .iter()
            .map(|p| cache.get(p))
            .collect::<Result<Vec<_>, _>>()?;
        crate::sketch::tangent_fit::fit_transitions(
            &mut transitions,
            &d.apex_alternatives,
            &solved,
            &front.profile,
            side.as_ref().map(|s| &s.profile),
            height,
        )?;
        first_shells = d.shells;
        if opts.alternatives {
            others = super::alternatives::docs(&out, d.alternatives, &removed, &transitions);
        }
        out.set_derived(parts, transitions);
    }
    let views = Views {
        front: &front,
        side: side.as_ref(),
        removed: &removed,
        height,
    };
    let first = finish(out, doc, opts, cache, &views, &placed)?;
    let (mut best, derivation) = super::alternatives::keep_least_excess(
        (first, first_shells),
        others,
        |b: &Built| &b.report.quality,
        |o| finish(o, doc, opts, cache, &views, &placed),
    );
    best.report.derivation = derivation;
    Ok(best)
}

/// The views a build measures its model against.
struct Views<'a> {
    front: &'a Outline,
    side: Option<&'a Outline>,
    removed: &'a [crate::sketch::removed::BuiltRemoved],
    height: f64,
}

/// The rest of [`build`] for the derived document `out`: its log
/// replayed, its props composed, the result measured.
fn finish(
    out: CharacterDoc,
    doc: &CharacterDoc,
    opts: &BuildOptions,
    cache: &mut PartCache,
    v: &Views,
    placed: &crate::sketch::place::Placed,
) -> Result<Built, BuildError> {
    let base = opts.base;
    let (edited, model) = replay(&out, v.height, opts, Some(cache))?;
    let mut model = model;
    let mut props = Vec::with_capacity(doc.props().len());
    let cells = props::resolution(opts.res.rings_per_height);
    for p in doc.props() {
        opts.check_cancel()?;
        props.push(props::compose_one(&mut model.mesh, p, base, cells)?);
    }
    opts.check_cancel()?;
    let report = crate::sketch::report::report(
        &out,
        &edited,
        &model,
        v.front,
        v.side,
        v.removed,
        props,
        v.height,
        placed.report.clone(),
        placed.warnings.clone(),
    );
    super::effect::finite_result(&model.mesh, &report)?;
    Ok(Built {
        doc: out,
        edited,
        model,
        report,
        front: v.front.clone(),
        side: v.side.cloned(),
    })
}

/// The log replayed once on `doc`'s parts: the spec-level edits applied,
/// the force displacements made, the parts solved one by one (asking the
/// cancel hook between them), the mesh assembled and the mesh-level edits
/// applied.
fn replay(
    doc: &CharacterDoc,
    height: f64,
    opts: &BuildOptions,
    cache: Option<&mut PartCache>,
) -> Result<(Vec<PartSpec>, Model), BuildError> {
    let active = doc.active_edits();
    check_order(doc.transitions(), active)?;
    let edited = crate::edit::apply_to_parts(doc.parts(), active)?;
    let disp = crate::edit::displacements(active)?;
    let mut local = PartCache::default();
    let cache = match cache {
        Some(c) => c,
        None => &mut local,
    };
    for p in &edited {
        opts.check_cancel()?;
        cache.get(p)?;
    }
    let mut model = build_model_with(
        &edited,
        doc.transitions(),
        height,
        opts.res,
        &disp,
        Some(cache),
    )?;
    apply_mesh_edits(&mut model.mesh, &model.parts, active)?;
    Ok((edited, model))
}

/// Builds a document with the defaults but `res` and `rederive` (a
/// shorthand for [`build`]).
pub fn build_document(
    doc: &CharacterDoc,
    base: &Path,
    res: Resolution,
    rederive: bool,
) -> Result<Built, BuildError> {
    build(
        doc,
        &BuildOptions::new(base).res(res).rederive(rederive),
        None,
    )
}

/// Applies the mesh-level edits among `edits` to the built mesh, in log
/// order: plate bendings ([`Edit::Plate`]) and SASM features
/// ([`Edit::Sasm`], [`Edit::SasmAux`], on `parts`, the built part surfaces)
/// interleaved as the log has them (a SASM feature keeps what an earlier
/// plate or force did to its part: it adds its height to the vertices'
/// current positions).
pub fn apply_mesh_edits(
    mesh: &mut Mesh,
    parts: &[PartSurface],
    edits: &[Edit],
) -> Result<(), EditError> {
    for e in edits {
        match e {
            Edit::Plate {
                part,
                centre,
                radius,
                ..
            } => {
                // the region's centre must lie on its part (as pushing
                // checks it): the part's built surface within the radius
                if let Some(p) = parts.iter().find(|p| &p.name == part) {
                    let d = crate::edit::distance_to_part(p, *centre);
                    if d > *radius {
                        return Err(EditError::Invalid {
                            op: e.op(),
                            part: part.clone(),
                            message: format!(
                                "the region centre lies {d:.4} from the part's surface, farther than the radius {radius}"
                            ),
                        });
                    }
                }
                crate::edit::apply_plate(mesh, e)?
            }
            Edit::Sasm(_) | Edit::SasmAux(_) => {
                let invalid = |m: String| EditError::Invalid {
                    op: e.op(),
                    part: e.part().unwrap_or("").into(),
                    message: m,
                };
                if let Some(f) = crate::sasm::edit::feature_of(e, parts) {
                    let f = f.map_err(|err| invalid(err.to_string()))?;
                    let p = parts
                        .iter()
                        .find(|p| p.name == f.part)
                        .ok_or_else(|| invalid("the part is not built".into()))?;
                    crate::sasm::apply_feature(mesh, p, &f)
                        .map_err(|err| invalid(err.to_string()))?;
                }
            }
            _ => {}
        }
    }
    Ok(())
}
