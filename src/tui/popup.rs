//! The popups over the screen: help (the key bindings), the quit question
//! and the autosave recovery offer.

use super::app::{App, Mode};
use super::fit::fit;
use super::keys::BINDINGS;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph};
use ratatui::Frame;

fn centred(area: Rect, w: u16, h: u16) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    )
}

pub(super) fn draw_popup(f: &mut Frame, app: &App) {
    let (title, lines): (&str, Vec<Line>) = match &app.mode {
        Mode::Help => (
            "Keys (any key closes)",
            BINDINGS
                .iter()
                .map(|(k, what)| {
                    Line::from(vec![
                        Span::styled(format!("{k:<16}"), Style::default().fg(Color::Yellow)),
                        Span::raw(*what),
                    ])
                })
                .collect(),
        ),
        Mode::ConfirmQuit => (
            "Unsaved changes",
            vec![
                Line::from("The document has unsaved changes."),
                Line::from("y: save and quit   n: quit without saving   Esc: stay"),
            ],
        ),
        Mode::Recovery(_) => (
            "Recover?",
            vec![
                Line::from(fit(
                    &format!(
                        "{} is newer than the document:",
                        super::autosave::sidecar(&app.path).display()
                    ),
                    (f.area().width as usize).saturating_sub(4),
                )),
                Line::from("unsaved changes of an earlier session."),
                Line::from("y: recover them   n: discard the autosave"),
            ],
        ),
        _ => return,
    };
    let h = lines.len() as u16 + 2;
    let w = lines.iter().map(|l| l.width() as u16).max().unwrap_or(10) + 4;
    let area = centred(f.area(), w.max(title.len() as u16 + 4), h);
    f.render_widget(Clear, area);
    f.render_widget(Paragraph::new(lines).block(block(title, true)), area);
}

/// A bordered block titled `title`, highlighted when `focused`.
pub(super) fn block(title: &str, focused: bool) -> Block<'_> {
    let style = if focused {
        Style::default().fg(Color::Yellow)
    } else {
        Style::default().fg(Color::Gray)
    };
    Block::default()
        .borders(Borders::ALL)
        .border_style(style)
        .title(Span::styled(title, style.add_modifier(Modifier::BOLD)))
}
