//! Length units of meshes, and the rule every reader and writer follows.
//!
//! A [`Mesh`](super::Mesh) stores bare numbers; its unit is a property of
//! where it came from, stated once here and carried to the writers, which
//! convert:
//!
//! | source | unit |
//! |---|---|
//! | the bundled MakeHuman data (`makehuman`, `demo`, `pde6 body`) | decimetres ([`MAKEHUMAN`]) |
//! | a mesh file read (OBJ, STL, PLY: none of them records a unit) | `--input-unit`, default metres ([`READ_DEFAULT`]) |
//! | a JSON spec or model file (pde4, pde6, ode6, conv) | `--input-unit`, default metres |
//! | an SVG sketch | its own document unit, see below |
//!
//! | written as | unit |
//! |---|---|
//! | GLB (glTF 2.0) | always metres: glTF's unit is the metre (glTF 2.0 spec, sec 3.4 "Coordinate system and units") |
//! | OBJ, STL, PLY | `--unit m\|dm\|cm\|mm`, default metres ([`WRITE_DEFAULT`]) |
//!
//! Every command that writes a mesh states the unit it wrote in its `--json`
//! report (`"unit": "m"`). Conversion is a uniform scale of the positions by
//! [`Unit::factor_to`] (no translation, no axis change), applied to a copy
//! just before encoding ([`crate::mesh::io::write_in_unit`]); the library's
//! own algorithms keep working in the source unit, so their tolerances and
//! reported lengths are unchanged (the demo's report says `"unit": "dm"`).
//!
//! **SVG sketches.** An SVG sketch's coordinates are user units. The rule for
//! the SVG reader: the root `<svg>` element's `width`/`height` with an
//! absolute CSS unit (`mm`, `cm`, `in`, `pt`, `pc`, `px`; a bare number is
//! `px`) and its `viewBox` give the length of one user unit; CSS fixes
//! 1 in = 96 px = 25.4 mm, so without a `viewBox` one user unit is one CSS
//! pixel, 0.2645833 mm. A `viewBox` of width `w` with `width="L"` makes one
//! user unit `L / w`. [`svg_length_metres`] converts such a length; the
//! sketch's mesh is then built in metres ([`Unit::M`]). Percentages and
//! font-relative units (`%`, `em`, `ex`) have no absolute size and are
//! rejected with [`UnitError::SvgLength`].

use super::Mesh;
use serde::Serialize;
use std::fmt;
use std::str::FromStr;
use thiserror::Error;

/// A length unit of mesh coordinates.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub enum Unit {
    /// Metres (glTF's unit; the default).
    #[default]
    #[serde(rename = "m")]
    M,
    /// Decimetres (the bundled MakeHuman data).
    #[serde(rename = "dm")]
    Dm,
    /// Centimetres.
    #[serde(rename = "cm")]
    Cm,
    /// Millimetres.
    #[serde(rename = "mm")]
    Mm,
}

/// The unit of the bundled MakeHuman base mesh and morph targets.
pub const MAKEHUMAN: Unit = Unit::Dm;
/// What a reader assumes for a file that records no unit (OBJ, STL, PLY,
/// JSON specs) unless told otherwise (`--input-unit`).
pub const READ_DEFAULT: Unit = Unit::M;
/// What OBJ/STL/PLY are written in unless the user asks otherwise (`--unit`).
pub const WRITE_DEFAULT: Unit = Unit::M;
/// The unit of every GLB written (glTF 2.0: metres).
pub const GLB: Unit = Unit::M;

/// A unit name or SVG length that could not be understood.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum UnitError {
    #[error("unknown length unit {given:?}: expected one of m, dm, cm, mm")]
    Unknown { given: String },
    #[error("SVG length {given:?}: {reason}")]
    SvgLength { given: String, reason: &'static str },
}

impl Unit {
    /// Every unit, largest first.
    pub const ALL: [Unit; 4] = [Unit::M, Unit::Dm, Unit::Cm, Unit::Mm];

    /// Metres in one of this unit.
    pub fn metres(self) -> f64 {
        match self {
            Unit::M => 1.0,
            Unit::Dm => 0.1,
            Unit::Cm => 0.01,
            Unit::Mm => 0.001,
        }
    }

    /// The factor that turns a coordinate in `self` into one in `to`:
    /// exactly 1 when they are equal, otherwise a power of ten computed
    /// from the integer exponents so no rounding accumulates.
    pub fn factor_to(self, to: Unit) -> f64 {
        let e = self.exponent() - to.exponent();
        10f64.powi(e)
    }

    /// Decimal exponent: one of this unit is `10^exponent` metres.
    fn exponent(self) -> i32 {
        match self {
            Unit::M => 0,
            Unit::Dm => -1,
            Unit::Cm => -2,
            Unit::Mm => -3,
        }
    }

    /// The symbol (`"m"`, `"dm"`, `"cm"`, `"mm"`).
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::M => "m",
            Unit::Dm => "dm",
            Unit::Cm => "cm",
            Unit::Mm => "mm",
        }
    }
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.symbol())
    }
}

impl FromStr for Unit {
    type Err = UnitError;
    fn from_str(s: &str) -> Result<Unit, UnitError> {
        let t = s.trim().to_ascii_lowercase();
        Unit::ALL
            .into_iter()
            .find(|u| u.symbol() == t)
            .ok_or(UnitError::Unknown { given: s.into() })
    }
}

/// A copy of `m` with its positions converted from `from` to `to` (a
/// uniform scale; groups and triangles unchanged).
pub fn convert(m: &Mesh, from: Unit, to: Unit) -> Mesh {
    let mut out = m.clone();
    let k = from.factor_to(to);
    if k != 1.0 {
        out.map_positions(|p| [k * p[0], k * p[1], k * p[2]]);
    }
    out
}

/// Length of an SVG `width`/`height` attribute in metres (CSS absolute
/// units: 1 in = 2.54 cm = 96 px = 72 pt = 6 pc; a bare number is px).
pub fn svg_length_metres(s: &str) -> Result<f64, UnitError> {
    let t = s.trim();
    let bad = |reason| UnitError::SvgLength {
        given: s.into(),
        reason,
    };
    // the unit is the trailing run of letters or `%` (so `1e-3mm` is a
    // number in exponent form followed by mm)
    let split = t
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_ascii_alphabetic() || *c == '%')
        .last()
        .map_or(t.len(), |(i, _)| i);
    let (num, unit) = t.split_at(split);
    let x: f64 = num.trim().parse().map_err(|_| bad("not a number"))?;
    if !x.is_finite() || x <= 0.0 {
        return Err(bad("not a positive finite length"));
    }
    let inch = 0.0254;
    let per = match unit.trim() {
        "" | "px" => inch / 96.0,
        "in" => inch,
        "mm" => 0.001,
        "cm" => 0.01,
        "pt" => inch / 72.0,
        "pc" => inch / 6.0,
        "%" | "em" | "ex" => return Err(bad("relative lengths have no absolute size")),
        _ => return Err(bad("unknown unit")),
    };
    Ok(x * per)
}
