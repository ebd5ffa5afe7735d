//! C2 continuous sixth-order PDE patches from cross sections
//! (paper 002: Fu et al., "3D Modelling with C2 Continuous PDE Surface
//! Patches", Mathematics 10 (2022) 319; eqs 1-27, appendices A and B).
//!
//! The vector PDE (eq 2)
//! $$ \frac{\partial^6 \mathbf{w}}{\partial u^6} + a \frac{\partial^6 \mathbf{w}}{\partial v^6} = 0 $$
//! with closed cross sections $\mathbf{C}(v) = \mathbf{c}_0 + \sum_n
//! (\mathbf{c}_n \cos nv + \mathbf{s}_n \sin nv)$ (eq 1, a [`Fourier3`](crate::curve::Fourier3))
//! separates harmonic by harmonic (eqs 3-5): every coefficient becomes a
//! function $A(u)$ with $A^{(6)} = a n^6 A$ (appendix A, eqs A4-A6). Its six
//! basis functions ([`mode`]) are determined per sign of a:
//!
//! * $a < 0$, $q = n|a|^{1/6}$: $\cos qu, \sin qu, e^{\mp \frac{\sqrt3}{2}qu}(\cos\frac q2 u, \sin\frac q2 u)$ (eq 8);
//! * $a > 0$: $e^{\pm qu}, e^{\pm \frac q2 u}(\cos\frac{\sqrt3}{2}qu, \sin\frac{\sqrt3}{2}qu)$
//!   (eq 7 prints $(c_0 + c_1u + c_2u^2)e^{\pm q u}$, which does not solve the ODE: ERRATA);
//! * $a = 0$ or $n = 0$: the quintic of eq 6.
//!
//! A patch ([`Patch`]) meets six conditions per coefficient: six sections at
//! $u = 0, 0.2, \dots, 1$ (method 1, eqs 15-23) or four sections at
//! $u = 0, \frac13, \frac23, 1$ plus the slope and curvature of the neighbour at
//! the join (method 2, eqs 24-27, A17-A36). [`Chain`] strings patches along
//! sections at arbitrary increasing u: [`Chain::method1`] (paper method 1,
//! only C0 at the joins), [`Chain::method2`] (paper method 2, C2 but an
//! unstable recursion that amplifies by ~13 per patch) and
//! [`Chain::c2_global`] ([`spline`]: the method-2 conditions solved together
//! with one end condition at each end; C2 and stable — the default of the
//! body and the CLI). The whole-body reconstruction built from these chains
//! lives above the families, in [`crate::body`].
//!
//! Accuracy note: for $a \ne 0$ the harmonic functions do not contain the
//! constants, so refining the sections converges (order ~6) only down to a
//! floor set by a (002-fig7a: 1.2e-6 for a = -0.5 on the vase, where a = 0
//! keeps order 6.2).
//!
//! Documented parameter range: $|a| \le$ [`A_MAX`], N <= [`N_MAX`]. The
//! six-point interpolation is intrinsically well posed while $q \lesssim 20$
//! (Lebesgue constant <= 27 for $a<0$, <= 102 for $a>0$, golden
//! `pde6_closed_form.json`); beyond, or for $q \to 0$ with $a \ne 0$, the solver
//! refuses matrices with condition number above [`mode::MAX_CONDITION`].

pub mod chain;
pub mod check;
pub mod input;
pub mod mode;
pub mod patch;
pub mod samples;
pub mod sampling;
pub mod spline;

pub use chain::{Chain, Method, Piece, Section};
pub use mode::{Mode, ModeBasis, ModeSolver, Regime};
pub use patch::Patch;
pub use spline::{EndCurvature, END_TURN_GUARD_DEG};

/// v samples per join in the join-continuity measurement of a chain.
pub const JOIN_SAMPLES: usize = 16;

/// Largest |a| accepted.
pub const A_MAX: f64 = 10.0;
/// Largest number of harmonics in the documented range.
pub const N_MAX: usize = 20;

/// Errors of the pde6 family.
#[derive(Debug, thiserror::Error)]
pub enum Pde6Error {
    #[error("{0} is not finite")]
    NotFinite(String),
    #[error("PDE parameter a = {0} is outside [-{A_MAX}, {A_MAX}]")]
    AOutOfRange(f64),
    #[error("curve {index} has {found} harmonics (or unequal cos/sin lists), curve 0 has {expected}: all curves need the same J")]
    DifferentHarmonics {
        index: usize,
        expected: usize,
        found: usize,
    },
    #[error("u positions must increase: position {index} is {next}, after {previous}")]
    NonIncreasing {
        index: usize,
        previous: f64,
        next: f64,
    },
    #[error("this chain needs {rule} cross sections (k >= 0), got {got}")]
    ChainLength { got: usize, rule: &'static str },
    #[error("the first patch must start at a multiple of 3 and fit: first = {first}, {sections} sections")]
    FirstPatch { first: usize, sections: usize },
    #[error("the 6x6 interpolation matrix is singular (q = {q})")]
    Singular { q: f64 },
    #[error("the 6x6 interpolation matrix has condition number {condition:.3e} (q = {q}): |a| or N too large (or |a| too small but nonzero)")]
    IllConditioned { q: f64, condition: f64 },
    #[error("{0}")]
    Input(String),
    /// An input file could not be read.
    #[error("reading {what}: {source}")]
    Read {
        what: String,
        #[source]
        source: crate::mesh::MeshError,
    },
    /// An input file is not the JSON it should be.
    #[error("parsing {what}: {source}")]
    Parse {
        what: String,
        #[source]
        source: serde_json::Error,
    },
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
    /// A curve given as numbers whose magnitudes are out of range.
    #[error(transparent)]
    GecInput(#[from] crate::curve::gec::input::InputError),
    #[error("{section}: {cause}")]
    SectionFit {
        section: String,
        #[source]
        cause: Box<Pde6Error>,
    },
    #[error("anchored sampling: pull {0} outside [0, 1]")]
    Pull(f64),
    #[error("anchored sampling needs >= 3 points, >= 1 anchor, >= 3 samples (got {points}, {anchors}, {samples})")]
    SamplingCounts {
        points: usize,
        anchors: usize,
        samples: usize,
    },
    #[error("degenerate section: {0}")]
    DegenerateSection(&'static str),
    #[error(transparent)]
    Gec(#[from] crate::curve::gec::GecError),
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
}

impl Pde6Error {
    /// This error as the cause of a failed section fit.
    pub fn in_section(self, section: impl Into<String>) -> Pde6Error {
        Pde6Error::SectionFit {
            section: section.into(),
            cause: Box::new(self),
        }
    }
}

/// Checks the PDE parameter.
pub fn validate_a(a: f64) -> Result<(), Pde6Error> {
    if !a.is_finite() {
        return Err(Pde6Error::NotFinite("PDE parameter a".into()));
    }
    if a.abs() > A_MAX {
        return Err(Pde6Error::AOutOfRange(a));
    }
    Ok(())
}
