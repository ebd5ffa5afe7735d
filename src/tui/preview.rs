//! The preview: the CPU rasteriser's image drawn with half-block characters.
//!
//! A terminal cell is about twice as tall as wide, so each cell shows two
//! square pixels: the upper one as the foreground colour of `▀`, the lower
//! one as its background. A `cols x rows` area therefore shows an image of
//! `cols x 2 rows` pixels. The selected part (a mesh group of the same name)
//! is drawn in a highlight colour, the other parts in grey and the
//! transitions in a darker grey. In kitty the same image, rendered at
//! 8 x 16 pixels per cell, is laid over it as a PNG ([`super::kitty`]).

use crate::mesh::Mesh;
use crate::render::{render_views, Image, RenderOptions, View};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::widgets::Widget;

/// Which views the preview shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewSet {
    Front,
    Side,
    Top,
    /// Front, side and top side by side at one scale.
    All,
}

impl ViewSet {
    /// The next set (the `v` key).
    pub fn next(self) -> ViewSet {
        match self {
            ViewSet::Front => ViewSet::Side,
            ViewSet::Side => ViewSet::Top,
            ViewSet::Top => ViewSet::All,
            ViewSet::All => ViewSet::Front,
        }
    }

    /// Stable name.
    pub fn name(self) -> &'static str {
        match self {
            ViewSet::Front => "front",
            ViewSet::Side => "side",
            ViewSet::Top => "top",
            ViewSet::All => "front | side | top",
        }
    }

    fn views(self) -> Vec<View> {
        match self {
            ViewSet::Front => vec![View::Front],
            ViewSet::Side => vec![View::Side],
            ViewSet::Top => vec![View::Top],
            ViewSet::All => vec![View::Front, View::Side, View::Top],
        }
    }
}

/// Background of the preview.
pub const BACKGROUND: [u8; 4] = [20, 22, 30, 255];
/// Colour of the selected part.
pub const HIGHLIGHT: [u8; 3] = [255, 150, 40];
const PART: [u8; 3] = [170, 180, 200];
const OTHER: [u8; 3] = [110, 116, 130];

/// Group colours: `selected` highlighted, `parts` grey, the rest darker.
pub fn group_colours(m: &Mesh, parts: &[String], selected: Option<&str>) -> Vec<[u8; 3]> {
    m.groups
        .iter()
        .map(|g| {
            if Some(g.as_str()) == selected {
                HIGHLIGHT
            } else if parts.iter().any(|p| p == g) {
                PART
            } else {
                OTHER
            }
        })
        .collect()
}

/// Renders the preview image for a `cols x rows` cell area.
pub fn render(
    m: &Mesh,
    parts: &[String],
    selected: Option<&str>,
    set: ViewSet,
    cols: u16,
    rows: u16,
) -> Image {
    let views = set.views();
    let n = views.len();
    let w = (cols as usize / n).max(1);
    let o = RenderOptions {
        width: w,
        height: (2 * rows as usize).max(1),
        background: BACKGROUND,
        group_colours: Some(group_colours(m, parts, selected)),
        margin: 0.04,
        ..RenderOptions::default()
    };
    render_views(m, &views, &o)
}

/// An image as half-block cells.
#[derive(Clone, Debug, PartialEq)]
pub struct HalfBlocks<'a>(pub &'a Image);

fn colour(p: [u8; 4]) -> Color {
    Color::Rgb(p[0], p[1], p[2])
}

impl Widget for HalfBlocks<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let img = self.0;
        for row in 0..area.height {
            for col in 0..area.width {
                let (x, y) = (col as usize, 2 * row as usize);
                if x >= img.width || y >= img.height {
                    continue;
                }
                let top = img.get(x, y);
                let bottom = if y + 1 < img.height {
                    img.get(x, y + 1)
                } else {
                    BACKGROUND
                };
                if let Some(cell) = buf.cell_mut((area.x + col, area.y + row)) {
                    cell.set_symbol("▀")
                        .set_fg(colour(top))
                        .set_bg(colour(bottom));
                }
            }
        }
    }
}
