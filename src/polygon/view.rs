//! [`View`]: which view a drawing (a profile, a stroke, a sketch's
//! outline) is made in. One type for every modeling module; a render
//! camera's view (`render::camera::View`) is another thing.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A view direction: which two model axes a drawing is made in. Spelled
/// `"front"`, `"side"`, `"top"` in JSON and on the command line.
#[derive(Serialize, Deserialize, Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[serde(rename_all = "lowercase")]
pub enum View {
    /// Looking along -z at the character's front: (x, y).
    #[default]
    Front,
    /// Looking along -x at its side: (z, y).
    Side,
    /// Looking down along -y: (x, z).
    Top,
}

/// A name that is no [`View`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownView {
    pub name: String,
}

impl fmt::Display for UnknownView {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown view {:?} (expected front, side or top)",
            self.name
        )
    }
}

impl std::error::Error for UnknownView {}

impl View {
    /// Every view.
    pub const ALL: [View; 3] = [View::Front, View::Side, View::Top];

    /// Indices of the model axes giving (horizontal, vertical).
    pub fn axes(self) -> (usize, usize) {
        match self {
            View::Front => (0, 1),
            View::Side => (2, 1),
            View::Top => (0, 2),
        }
    }

    /// Orthographic projection of a model point to drawing coordinates
    /// ([`View::axes`]).
    pub fn project(self, p: [f64; 3]) -> [f64; 2] {
        let (h, v) = self.axes();
        [p[h], p[v]]
    }

    /// The lowercase name (`"front"`, `"side"`, `"top"`).
    pub fn name(self) -> &'static str {
        match self {
            View::Front => "front",
            View::Side => "side",
            View::Top => "top",
        }
    }

    /// Whether SVG y is minus the drawing's vertical coordinate (front,
    /// side) rather than equal to it (top).
    pub fn svg_y_flipped(self) -> bool {
        !matches!(self, View::Top)
    }
}

impl fmt::Display for View {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for View {
    type Err = UnknownView;
    /// The name, any case, surrounding blanks ignored.
    fn from_str(s: &str) -> Result<View, UnknownView> {
        match s.trim().to_ascii_lowercase().as_str() {
            "front" => Ok(View::Front),
            "side" => Ok(View::Side),
            "top" => Ok(View::Top),
            _ => Err(UnknownView { name: s.into() }),
        }
    }
}
