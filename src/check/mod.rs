//! Verification reports: the [`Check`] type, its [`Kind`]s and the named
//! tolerances ([`tol`]). This module is a leaf: it names no family; the list
//! of families lives in [`crate::verify`].
//!
//! Every equation family has a `check` module whose `checks()` *measures* and
//! returns [`Check`] reports; it never asserts. Tests assert on the reports,
//! `pdesculpt verify` prints them and exits non-zero when one fails, and the
//! figure programs record them.
//!
//! Kinds (see [`Kind`]): boundary conditions, PDE/ODE residuals (derivatives
//! from [`crate::jet`], never from a paper's derivative formulas), continuity
//! across joins, implicit-field thresholds, agreement with an independent
//! reference, and the paper-literal form of an equation. A paper-literal check
//! states up front whether the printed form is expected to agree with the
//! corrected one; when ERRATA.md says it differs, the check passes only if the
//! measured difference really exceeds the tolerance, so an erratum that stops
//! reproducing (or was never real) fails loudly.

pub mod reduce;
pub mod tol;

pub use reduce::{least, max_abs_diff, worst, Measure, Worst};

use serde::Serialize;
use std::fmt;

/// What a check verifies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Printed boundary conditions (position, first and second derivatives).
    Boundary,
    /// PDE/ODE residual of a closed form, derivatives from jets.
    Residual,
    /// C0/C1/C2 jumps across patch joins.
    Continuity,
    /// Implicit field equals its threshold at points it must interpolate.
    Threshold,
    /// Agreement with an independent source (goldens, quadrature, textbooks,
    /// a reference solver).
    Reference,
    /// The equation exactly as printed in the paper.
    PaperLiteral,
}

impl fmt::Display for Kind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = match self {
            Kind::Boundary => "boundary",
            Kind::Residual => "residual",
            Kind::Continuity => "continuity",
            Kind::Threshold => "threshold",
            Kind::Reference => "reference",
            Kind::PaperLiteral => "paper-literal",
        };
        f.write_str(s)
    }
}

/// One measured verification result.
#[derive(Clone, Debug, Serialize)]
pub struct Check {
    /// Family (module) name, e.g. `"jet"`, `"pde6"`.
    pub family: String,
    /// Paper file number (`"000"`..`"004"`), or `"-"` for infrastructure.
    pub paper: String,
    /// Equation, section or figure the check is about, e.g. `"eq 12"`.
    pub equation: String,
    /// Unique, stable name (ERRATA.md cites it).
    pub name: String,
    pub kind: Kind,
    /// The measured error (non-negative; NaN or infinite never passes).
    pub measured: f64,
    pub tolerance: f64,
    /// For paper-literal checks: `true` when ERRATA.md records the printed
    /// form as wrong, so passing means `measured > tolerance`.
    pub paper_differs: bool,
    pub passed: bool,
    /// What was measured and how, in one sentence.
    pub note: String,
}

impl Check {
    /// A check that passes when `measured <= tolerance` (and is finite).
    pub fn new(
        family: &str,
        paper: &str,
        equation: &str,
        name: &str,
        kind: Kind,
        measured: f64,
        tolerance: f64,
    ) -> Self {
        Check {
            family: family.into(),
            paper: paper.into(),
            equation: equation.into(),
            name: name.into(),
            kind,
            measured,
            tolerance,
            paper_differs: false,
            passed: measured.is_finite() && measured <= tolerance,
            note: String::new(),
        }
    }

    /// A paper-literal check. With `differs = true` (the printed form is in
    /// ERRATA.md) it passes when the measured difference exceeds `tolerance`;
    /// with `differs = false` it passes when it is within it. A NaN
    /// or infinite measurement fails either way (every constructor: a failed computation
    /// fails its check).
    pub fn paper_literal(
        family: &str,
        paper: &str,
        equation: &str,
        name: &str,
        measured: f64,
        tolerance: f64,
        differs: bool,
    ) -> Self {
        let mut c = Check::new(
            family,
            paper,
            equation,
            name,
            Kind::PaperLiteral,
            measured,
            tolerance,
        );
        c.paper_differs = differs;
        c.passed = if differs {
            // a failed computation (NaN, inf) fails: it is no evidence that
            // the printed form differs; measure a printed form that is
            // undefined by a finite count instead
            measured.is_finite() && measured > tolerance
        } else {
            measured.is_finite() && measured <= tolerance
        };
        c
    }

    /// Attaches the one-sentence description.
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.note = note.into();
        self
    }
}

/// Parses a committed golden JSON (`verify/golden/*.json`). A golden that
/// does not parse is not a panic but a failing reference check named
/// `name`, so `verify` reports it beside the others.
pub fn parse_golden<T: serde::de::DeserializeOwned>(
    text: &str,
    family: &str,
    paper: &str,
    equation: &str,
    name: &str,
) -> Result<T, Box<Check>> {
    serde_json::from_str(text).map_err(|e| {
        Box::new(
            Check::new(
                family,
                paper,
                equation,
                name,
                Kind::Reference,
                f64::NAN,
                0.0,
            )
            .note(format!("golden JSON does not parse: {e}")),
        )
    })
}

/// `|a - b| / max(1, |b|)`: relative error, absolute near zero.
pub fn rel_err(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().worst(1.0)
}
