//! Resource limits: one policy for every user-supplied count, size and
//! iteration parameter (CLI flag or file field).
//!
//! Each parameter has a documented range (a [`Range`]), checked before any
//! work with [`check`]; each costly operation estimates its memory and work
//! from its parameters and refuses with [`check_cost`] when the estimate
//! passes a documented budget ([`MEMORY_BYTES`], [`WORK_FLOPS`]). Both
//! errors name the parameter, its value and the limit. Arithmetic on user
//! numbers goes through [`mul`] / [`add`] (checked; an overflow is reported as
//! a limit error naming the parameter, never a wrapped number).
//!
//! | parameter | range | where |
//! |---|---|---|
//! | `gec fit --terms`, `--max-terms` | [`GEC_TERMS`] | paper 000/002 fit |
//! | `gec eval --samples` | [`GEC_SAMPLES`] | |
//! | `gec eval --derivative` | [`GEC_DERIVATIVE`] | |
//! | `pde4` spec `terms` | 1..=256 per direction, then the cost budget | Galerkin: `(MN)^2` matrix, `(MN)^3/3` Cholesky |
//! | `pde6 patch --nu/--nv`, `ode6 --nu/--nv` | [`TESS_NU`], [`TESS_NV`], mesh size [`MESH_VERTICES`] | |
//! | `pde6 patch --first` | `0..=sections-6`, multiple of 3 | |
//! | `pde6 body --terms`, `--anchors` | [`BODY_TERMS`], [`BODY_ANCHORS`] | |
//! | section / curve harmonics | [`CURVE_HARMONICS`] | JSON files |
//! | `ode6` polyline points | [`POLYLINE_POINTS`], then `points * grid` work | |
//! | `render --size` x views | [`RENDER_SIZE`], [`RENDER_VIEWS`], [`RENDER_PIXELS`] | |
//! | `plate --grid`, `--dm-iterations` | [`PLATE_GRID`], [`PLATE_ITERATIONS`] | |
//! | `sketch build --tolerance`, document `inputs.tolerance` | [`SKETCH_TOLERANCE`] ([`check_real`]) | also at most 1 % of the drawing's height |
//! | bytes of one input file (SVG, JSON) | [`INPUT_BYTES`] | `mesh::io::read_input` |
//! | SVG drawing: XML nodes, shapes | [`SVG_NODES`], [`SVG_SHAPES`] | `profile::svg` |
//! | SVG drawing: flattened points, estimated before flattening | [`SVG_POINTS`] | from each segment's control polygon and the tolerance |
//! | drawing size (largest side), any profile or document length | [`DRAWING_SIZE`], [`MODEL_COORD`] | |
//! | document: sections per part, harmonics per section | [`PART_SECTIONS`], [`SECTION_HARMONICS`] | `character::doc` |
//! | document: points per key section, edits per log, props | [`KEY_SECTION_POINTS`], [`LOG_EDITS`], [`DOC_PROPS`] | |
//! | conv work per component (skeleton circle tests, global fit) | [`CONV_WORK`] | props and `conv build` |

use thiserror::Error;

mod finite;
pub use finite::{first_non_finite, NonFinite};

/// Memory budget of one operation (estimated before allocating): 1 GiB.
pub const MEMORY_BYTES: u64 = 1 << 30;

/// Work budget of one operation (estimated floating-point operations before
/// starting): 2e10, a few seconds on one core.
pub const WORK_FLOPS: f64 = 2e10;

/// An inclusive range of a count parameter, with the reason for its bounds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Range {
    pub min: u64,
    pub max: u64,
    /// Why the bounds are what they are (printed in the error).
    pub why: &'static str,
}

impl Range {
    /// The same range with another lower bound.
    pub const fn with_min(self, min: u64) -> Range {
        Range { min, ..self }
    }
}

/// GEC terms J (the fit needs 2J + 1 points, the design matrix 4J + 2 columns).
pub const GEC_TERMS: Range = Range {
    min: 1,
    max: 2000,
    why: "a GEC term per harmonic; the fit needs 2J+1 points",
};
/// Samples of `gec eval --samples`.
pub const GEC_SAMPLES: Range = Range {
    min: 1,
    max: 10_000_000,
    why: "points printed",
};
/// Derivative order of `gec eval`.
pub const GEC_DERIVATIVE: Range = Range {
    min: 0,
    max: 8,
    why: "derivative order",
};
/// Harmonics of a curve read from a file (GEC or Fourier sections).
pub const CURVE_HARMONICS: Range = Range {
    min: 0,
    max: 2000,
    why: "harmonics of one curve",
};
/// Tessellation intervals in u (per piece for pde6).
pub const TESS_NU: Range = Range {
    min: 1,
    max: 100_000,
    why: "tessellation intervals in u",
};
/// Tessellation intervals around v.
pub const TESS_NV: Range = Range {
    min: 3,
    max: 100_000,
    why: "tessellation intervals in v",
};
/// Vertices of a tessellated mesh (about 100 bytes each with the written file).
pub const MESH_VERTICES: Range = Range {
    min: 1,
    max: 5_000_000,
    why: "vertices of one output mesh",
};
/// `pde6 body --terms`.
pub const BODY_TERMS: Range = Range {
    min: 1,
    max: 64,
    why: "GEC terms per body cross section",
};
/// `pde6 body --anchors`.
pub const BODY_ANCHORS: Range = Range {
    min: 1,
    max: 4096,
    why: "rays per body cross section",
};
/// Points of an `ode6` polyline curve (trigonometric interpolation is
/// quadratic in this number).
pub const POLYLINE_POINTS: Range = Range {
    min: 2,
    max: 20_000,
    why: "points of one polyline curve",
};
/// `render --size` (pixels per side of one view).
pub const RENDER_SIZE: Range = Range {
    min: 16,
    max: 8192,
    why: "pixels per side of one view",
};
/// Views of one `render`.
pub const RENDER_VIEWS: Range = Range {
    min: 1,
    max: 16,
    why: "views side by side",
};
/// Pixels of one rendered image (all views): 64 Mpx, about 0.5 GB of buffers.
pub const RENDER_PIXELS: Range = Range {
    min: 1,
    max: 1 << 26,
    why: "pixels of the whole image (size x size x views)",
};
/// `plate --grid`.
pub const PLATE_GRID: Range = Range {
    min: 4,
    max: 1000,
    why: "parameter-domain grid of the plate solve",
};
/// `plate --dm-iterations`.
pub const PLATE_ITERATIONS: Range = Range {
    min: 0,
    max: 10_000,
    why: "distance-map iterations",
};

/// Bytes of one input file read whole (an SVG drawing, a JSON document, an
/// edit, a sections file): 64 MiB, 1000 times the largest bundled input.
pub const INPUT_BYTES: Range = Range {
    min: 0,
    max: 64 << 20,
    why: "bytes of one input file",
};
/// XML nodes of one SVG file (elements, text, attributes' owners).
pub const SVG_NODES: Range = Range {
    min: 1,
    max: 1_000_000,
    why: "XML nodes of one SVG drawing",
};
/// Shapes (paths, rects, circles, ...) of one SVG drawing.
pub const SVG_SHAPES: Range = Range {
    min: 1,
    max: 10_000,
    why: "shapes of one SVG drawing",
};
/// Points of one flattened SVG drawing, all shapes together, estimated
/// from each curve's control polygon and the tolerance before flattening
/// (`profile::svg::estimate_points`). 200k: 270 times the bundled
/// drawings' 736-point outlines at the default tolerance; a 200k-point
/// outline validates and segments in about a second.
pub const SVG_POINTS: Range = Range {
    min: 1,
    max: 200_000,
    why: "points of the flattened drawing; raise the tolerance",
};
/// Points of one key cross-section sketch (a document's
/// `inputs.sections[i].points`; each is GEC-fitted).
pub const KEY_SECTION_POINTS: Range = Range {
    min: 3,
    max: 20_000,
    why: "points of one key cross-section sketch",
};
/// Key sections of one part (the C2 chain solves for all of them at once).
pub const PART_SECTIONS: Range = Range {
    min: 2,
    max: 256,
    why: "key sections of one part",
};
/// Harmonics (GEC terms) of one section of a document.
pub const SECTION_HARMONICS: Range = Range {
    min: 0,
    max: 256,
    why: "harmonics of one section (GEC terms)",
};
/// Edits of one document's log (every build replays the active ones).
pub const LOG_EDITS: Range = Range {
    min: 0,
    max: 4096,
    why: "edits of one document's log",
};
/// Props of one document.
pub const DOC_PROPS: Range = Range {
    min: 0,
    max: 64,
    why: "props of one document",
};
/// Patches of one curve network (`ode6 network`): the bundled networks
/// have 24 to 150; each patch is one small ODE solve (about 0.3 ms), so
/// the limit keeps a solve within seconds.
pub const NETWORK_PATCHES: Range = Range {
    min: 1,
    max: 10_000,
    why: "patches of one curve network",
};
/// Nodes, and curves, of one curve network (a patch has at most 4 curves
/// and 4 corners).
pub const NETWORK_CURVES: Range = Range {
    min: 0,
    max: 40_000,
    why: "nodes or curves of one curve network",
};
/// Points of one network curve: the bundled curves have 9; a line through
/// a v-strip joins the curves of up to every patch (a spline per line,
/// linear in its points), and every point is a constraint of its patch.
pub const NETWORK_CURVE_POINTS: Range = Range {
    min: 2,
    max: 4096,
    why: "points of one network curve",
};
/// Work of each stage of one convolution-surface component, estimated
/// from the filtered stroke before the stage runs (`conv::sketch`): the
/// skeleton's circle tests (`8 area_samples^2 points^2`) and the global fit
/// (`points segments^2 + segments^3`). The budget of [`WORK_FLOPS`]; the
/// bundled models need under 1e9.
pub const CONV_WORK: f64 = WORK_FLOPS;

/// An inclusive range of a real parameter (a length, a tolerance).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RealRange {
    pub min: f64,
    pub max: f64,
    pub why: &'static str,
}

/// `sketch build --tolerance` (SVG flattening, model units = metres); the
/// sketch module also refuses more than 1 % of the drawing's height.
pub const SKETCH_TOLERANCE: RealRange = RealRange {
    min: 1e-9,
    max: 1.0,
    why: "SVG flattening tolerance in model units (metres)",
};

/// Size of a drawing (the largest side of its bounding box, model units =
/// metres): from 10 micrometres to 100 km. Below, the tolerance and the
/// solvers' rounding meet; above, conditioning fails (a 1e30-sized drawing
/// gives interpolation matrices of condition 1e57).
pub const DRAWING_SIZE: RealRange = RealRange {
    min: 1e-5,
    max: 1e5,
    why: "size of a drawing in model units (metres)",
};
/// Largest magnitude of any coordinate or length of a character document
/// (model units): the drawing size bound.
pub const MODEL_COORD: f64 = 1e5;

/// Checks a finite real `value` of `param` against `range`; returns it.
pub fn check_real(param: &str, value: f64, range: RealRange) -> Result<f64, LimitError> {
    if value.is_nan() || value < range.min || value > range.max {
        return Err(LimitError::OutOfRealRange {
            param: param.to_string(),
            value,
            min: range.min,
            max: range.max,
            why: range.why,
        });
    }
    Ok(value)
}

/// Shows a real number for an error message: plainly in `[1e-4, 1e9)`,
/// in exponent form with at most 4 significant digits outside it (so
/// `1e300` is not printed as 301 digits, nor `2.5029505527626686e150` with
/// all of its).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = self.0.abs();
        if a == 0.0 || !a.is_finite() || (1e-4..1e9).contains(&a) {
            write!(f, "{}", self.0)
        } else {
            let s = format!("{:.3e}", self.0);
            let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
            let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
            write!(f, "{mantissa}e{exp}")
        }
    }
}

/// A parameter outside its range or an operation over budget.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LimitError {
    #[error("{param} = {value} is out of range: must be at least {min} and at most {max} ({why})")]
    OutOfRange {
        param: String,
        value: String,
        min: u64,
        max: u64,
        why: &'static str,
    },
    #[error(
        "{param} = {} is out of range: must be at least {} and at most {} ({why})", Num(*.value), Num(*.min), Num(*.max)
    )]
    OutOfRealRange {
        param: String,
        value: f64,
        min: f64,
        max: f64,
        why: &'static str,
    },
    #[error("{param} = {value}: {what} would need about {estimate:.3e} {unit}, over the budget of {budget:.3e} {unit}; reduce {param}")]
    OverBudget {
        param: String,
        value: String,
        what: String,
        estimate: f64,
        budget: f64,
        unit: &'static str,
    },
}

/// Checks `value` of `param` against `range`; returns it.
pub fn check(param: &str, value: usize, range: Range) -> Result<usize, LimitError> {
    let v = value as u64;
    if v < range.min || v > range.max {
        return Err(LimitError::OutOfRange {
            param: param.to_string(),
            value: value.to_string(),
            min: range.min,
            max: range.max,
            why: range.why,
        });
    }
    Ok(value)
}

/// Refuses when `estimate` (in `unit`) is over `budget`; `param = value` is
/// the parameter blamed (the one the user should reduce).
pub fn check_cost(
    param: &str,
    value: impl std::fmt::Display,
    what: &str,
    estimate: f64,
    budget: f64,
    unit: &'static str,
) -> Result<(), LimitError> {
    if estimate.is_nan() || estimate > budget {
        return Err(LimitError::OverBudget {
            param: param.to_string(),
            value: value.to_string(),
            what: what.to_string(),
            estimate,
            budget,
            unit,
        });
    }
    Ok(())
}

/// Memory check against [`MEMORY_BYTES`].
pub fn check_memory(
    param: &str,
    value: impl std::fmt::Display,
    what: &str,
    bytes: f64,
) -> Result<(), LimitError> {
    check_cost(param, value, what, bytes, MEMORY_BYTES as f64, "bytes")
}

/// Work check against [`WORK_FLOPS`].
pub fn check_work(
    param: &str,
    value: impl std::fmt::Display,
    what: &str,
    flops: f64,
) -> Result<(), LimitError> {
    check_cost(param, value, what, flops, WORK_FLOPS, "operations")
}

/// `a * b`, or an error naming `param` when it overflows `usize`.
pub fn mul(param: &str, a: usize, b: usize) -> Result<usize, LimitError> {
    a.checked_mul(b).ok_or_else(|| overflow(param, a, b, '*'))
}

/// `a + b`, or an error naming `param` when it overflows `usize`.
pub fn add(param: &str, a: usize, b: usize) -> Result<usize, LimitError> {
    a.checked_add(b).ok_or_else(|| overflow(param, a, b, '+'))
}

fn overflow(param: &str, a: usize, b: usize, op: char) -> LimitError {
    LimitError::OverBudget {
        param: param.to_string(),
        value: format!("{a} {op} {b}"),
        what: "the size".into(),
        estimate: f64::INFINITY,
        budget: usize::MAX as f64,
        unit: "elements",
    }
}

/// Vertices of a `nu x nv` tessellation, checked against [`MESH_VERTICES`]
/// (`param` names the flags, e.g. `"--nu/--nv"`).
pub fn mesh_vertices(param: &str, nu: usize, nv: usize) -> Result<usize, LimitError> {
    let n = mul(param, nu.saturating_add(1), nv.saturating_add(1))?;
    if n as u64 > MESH_VERTICES.max {
        return Err(LimitError::OverBudget {
            param: param.to_string(),
            value: format!("{nu} x {nv}"),
            what: "the mesh".into(),
            estimate: n as f64,
            budget: MESH_VERTICES.max as f64,
            unit: "vertices",
        });
    }
    Ok(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_error_names_parameter_value_and_limit() {
        let e = check("--terms", 9_223_372_036_854_775_808, GEC_TERMS).unwrap_err();
        let s = e.to_string();
        assert!(s.contains("--terms = 9223372036854775808"), "{s}");
        assert!(s.contains("2000"), "{s}");
        assert_eq!(check("--terms", 10, GEC_TERMS), Ok(10));
    }

    #[test]
    fn overflow_is_an_error_not_a_wrap() {
        assert!(mul("--nu", usize::MAX, 2).is_err());
        assert!(mesh_vertices("--nu/--nv", usize::MAX, 64).is_err());
        assert_eq!(mesh_vertices("--nu/--nv", 16, 64), Ok(17 * 65));
    }

    #[test]
    fn num_shows_huge_and_tiny_values_in_exponent_form() {
        assert_eq!(Num(1e300).to_string(), "1e300");
        assert_eq!(Num(-2.5e-7).to_string(), "-2.5e-7");
        assert_eq!(Num(1.4).to_string(), "1.4");
        assert_eq!(Num(0.0).to_string(), "0");
        assert_eq!(Num(f64::NAN).to_string(), "NaN");
        assert_eq!(Num(2.5029505527626686e150).to_string(), "2.503e150");
        assert_eq!(Num(9.99999995904e11).to_string(), "1e12");
    }

    #[test]
    fn nan_cost_is_refused() {
        assert!(check_work("x", 1, "y", f64::NAN).is_err());
        assert!(check_work("x", 1, "y", 1.0).is_ok());
    }
}
