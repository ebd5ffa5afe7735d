//! Drawing the screen: part tree and inputs on the left, the preview in the
//! middle, parameters and the edit log on the right, the status line and a
//! message line at the bottom; help, export prompt, quit and recovery
//! questions as popups.

use super::app::{App, Focus, ItemKind, Mode};
use super::fit::{elide_left, fit};
use super::popup::block;
use super::preview::{self, HalfBlocks};
use crate::character::doc::ProfileInput;
use crate::render::Image;
use ratatui::layout::{Constraint, Direction, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{List, ListItem, ListState, Paragraph, Wrap};
use ratatui::Frame;

/// The preview image of the last draw and what it was drawn for.
#[derive(Default)]
pub struct PreviewCache {
    key: Option<PreviewKey>,
    image: Option<Image>,
    /// Also send the preview through the kitty graphics protocol
    /// ([`super::kitty`]).
    pub kitty: bool,
    /// What the terminal shows through it: the preview's key and area.
    kitty_shown: Option<(PreviewKey, Rect)>,
    /// Escape sequences to write after the draw.
    kitty_out: Option<String>,
}

type PreviewKey = (u64, Option<String>, &'static str, u16, u16);

impl PreviewCache {
    /// A cache that sends the preview through the kitty graphics protocol.
    pub fn with_kitty() -> PreviewCache {
        PreviewCache {
            kitty: true,
            ..PreviewCache::default()
        }
    }

    /// The kitty escape sequences of the last draw, if any (write them to
    /// the terminal after the draw).
    pub fn take_kitty(&mut self) -> Option<String> {
        self.kitty_out.take()
    }

    /// Kitty: remove the preview's image (nothing built, or a popup
    /// covers it).
    fn kitty_hide(&mut self) {
        if self.kitty && self.kitty_shown.take().is_some() {
            self.kitty_out = Some(super::kitty::clear());
        }
    }

    /// Kitty: show the preview of `key` over `inner` (`render` draws it).
    fn kitty_show(&mut self, key: &PreviewKey, inner: Rect, render: impl FnOnce() -> Image) {
        if !self.kitty || self.kitty_shown.as_ref() == Some(&(key.clone(), inner)) {
            return;
        }
        let png = render().encode_png();
        self.kitty_out = Some(super::kitty::place(
            &png,
            inner.x,
            inner.y,
            inner.width,
            inner.height,
        ));
        self.kitty_shown = Some((key.clone(), inner));
    }
}

const SELECTED: Style = Style::new().fg(Color::Black).bg(Color::Yellow);

/// Draws the whole screen.
pub fn draw(f: &mut Frame, app: &App, cache: &mut PreviewCache) {
    let rows = Layout::default()
        .direction(Direction::Vertical)
        .constraints([
            Constraint::Min(8),
            Constraint::Length(1),
            Constraint::Length(1),
        ])
        .split(f.area());
    let cols = Layout::default()
        .direction(Direction::Horizontal)
        .constraints([
            Constraint::Length(30),
            Constraint::Min(20),
            Constraint::Length(46),
        ])
        .split(rows[0]);
    let left = Layout::default()
        .direction(Direction::Vertical)
        .constraints([Constraint::Min(5), Constraint::Length(8)])
        .split(cols[0]);
    let right = Layout::default()
        .direction(Direction::Vertical)
        .constraints([Constraint::Min(8), Constraint::Length(10)])
        .split(cols[2]);
    draw_tree(f, app, left[0]);
    draw_inputs(f, app, left[1]);
    draw_preview(f, app, cols[1], cache);
    draw_params(f, app, right[0]);
    draw_log(f, app, right[1]);
    f.render_widget(Paragraph::new(status_line(app)), rows[1]);
    draw_message(f, app, rows[2]);
    super::popup::draw_popup(f, app);
}

fn draw_tree(f: &mut Frame, app: &App, area: Rect) {
    let items: Vec<ListItem> = app
        .tree()
        .into_iter()
        .map(|t| {
            let (tag, colour) = match t.kind {
                ItemKind::Part => ("part", Color::White),
                ItemKind::Transition => ("join", Color::Cyan),
                ItemKind::Removed => ("cut ", Color::DarkGray),
                ItemKind::Prop => ("prop", Color::Magenta),
            };
            ListItem::new(Line::from(vec![
                Span::styled(format!("{tag} "), Style::default().fg(Color::DarkGray)),
                Span::styled(t.name, Style::default().fg(colour)),
                Span::styled(
                    format!("  {}", t.detail),
                    Style::default().fg(Color::DarkGray),
                ),
            ]))
        })
        .collect();
    let empty = items.is_empty();
    let list = List::new(items)
        .block(block("Parts", app.focus == Focus::Tree))
        .highlight_style(SELECTED);
    let mut st = ListState::default().with_selected((!empty).then_some(app.tree_sel));
    f.render_stateful_widget(list, area, &mut st);
    if empty {
        let inner = Rect::new(area.x + 1, area.y + 1, area.width.saturating_sub(2), 1);
        f.render_widget(Paragraph::new("deriving parts..."), inner);
    }
}

/// A profile's line of the inputs panel, made to fit `width` (a long
/// path must not wrap and push the lines below out of the panel).
fn profile_text(label: &str, p: &ProfileInput, width: usize) -> String {
    let text = match p {
        ProfileInput::Path(s) => s.clone(),
        ProfileInput::Points(v) => format!("{} points inline", v.len()),
    };
    fit(&format!("{label}{text}"), width)
}

fn draw_inputs(f: &mut Frame, app: &App, area: Rect) {
    let d = &app.doc;
    let mut per_part: Vec<(String, usize)> = Vec::new();
    for s in &d.inputs().sections {
        match per_part.iter_mut().find(|(n, _)| *n == s.part) {
            Some(e) => e.1 += 1,
            None => per_part.push((s.part.clone(), 1)),
        }
    }
    let secs = per_part
        .iter()
        .map(|(n, k)| format!("{n} {k}"))
        .collect::<Vec<_>>()
        .join(", ");
    let w = area.width.saturating_sub(2) as usize;
    let lines = vec![
        Line::from(format!("level    {}", d.level().name())),
        Line::from(profile_text("front    ", &d.inputs().front, w)),
        Line::from(
            d.inputs()
                .side
                .as_ref()
                .map_or("side     none".into(), |p| profile_text("side     ", p, w)),
        ),
        Line::from(format!(
            "sections {}",
            if secs.is_empty() { "none".into() } else { secs }
        )),
        Line::from(format!(
            "template none · tol {}",
            d.inputs()
                .tolerance
                .map_or("1/1000 of the height".to_string(), |t| format!("{t} m"))
        )),
    ];
    f.render_widget(
        Paragraph::new(lines)
            .wrap(Wrap { trim: true })
            .block(block("Inputs", false)),
        area,
    );
}

fn draw_preview(f: &mut Frame, app: &App, area: Rect, cache: &mut PreviewCache) {
    let title = format!(
        "Preview: {}{}",
        app.view.name(),
        if app.stale { " (out of date)" } else { "" }
    );
    let b = block(&title, false);
    let inner = b.inner(area);
    f.render_widget(b, area);
    let Some(shown) = &app.shown else {
        f.render_widget(Paragraph::new("building..."), inner);
        cache.kitty_hide();
        return;
    };
    let sel = app.selected().map(|t| t.name);
    let key = (
        shown.id,
        sel.clone(),
        app.view.name(),
        inner.width,
        inner.height,
    );
    if cache.key.as_ref() != Some(&key) {
        let parts: Vec<String> = app.edited.iter().map(|p| p.name.clone()).collect();
        cache.image = Some(preview::render(
            &shown.mesh,
            &parts,
            sel.as_deref(),
            app.view,
            inner.width,
            inner.height,
        ));
        cache.key = Some(key.clone());
    }
    if let Some(img) = &cache.image {
        f.render_widget(HalfBlocks(img), inner);
    }
    let popup = matches!(app.mode, Mode::Help | Mode::ConfirmQuit | Mode::Recovery(_));
    let parts: Vec<String> = app.edited.iter().map(|p| p.name.clone()).collect();
    let (px, py) = super::kitty::CELL_PX;
    if popup {
        cache.kitty_hide();
    } else {
        cache.kitty_show(&key, inner, || {
            preview::render(
                &shown.mesh,
                &parts,
                sel.as_deref(),
                app.view,
                inner.width.saturating_mul(px),
                inner.height.saturating_mul(py / 2),
            )
        });
    }
}

fn draw_params(f: &mut Frame, app: &App, area: Rect) {
    let title = match app.selected() {
        Some(t) => format!("Parameters: {}", t.name),
        None => "Parameters".into(),
    };
    let editing = match &app.mode {
        Mode::Editing { row, buffer } => Some((*row, buffer.clone())),
        _ => None,
    };
    let err = app.typing_error();
    // inside the borders, after the label
    let value_width = (area.width as usize).saturating_sub(2 + 10);
    let mut items: Vec<ListItem> = Vec::new();
    for (i, r) in app.rows().into_iter().enumerate() {
        let label = Span::styled(format!("{:<10}", r.label), Style::default().fg(Color::Cyan));
        match &editing {
            Some((row, buf)) if *row == i => {
                let colour = if err.is_some() {
                    Color::Red
                } else {
                    Color::Green
                };
                items.push(ListItem::new(Line::from(vec![
                    label,
                    Span::styled(format!("{buf}▏"), Style::default().fg(colour)),
                ])));
                let hint = match &err {
                    Some(e) => Span::styled(
                        fit(&format!("  ✗ {e}"), value_width + 10),
                        Style::default().fg(Color::Red),
                    ),
                    None => Span::styled(
                        format!("  ✓ Enter applies ({})", r.kind.hint()),
                        Style::default().fg(Color::Green),
                    ),
                };
                items.push(ListItem::new(Line::from(hint)));
            }
            _ => {
                let style = if r.kind.editable() {
                    Style::default().fg(Color::White)
                } else {
                    Style::default().fg(Color::Gray)
                };
                items.push(ListItem::new(Line::from(vec![
                    label,
                    Span::styled(fit(&r.value, value_width), style),
                ])));
            }
        }
    }
    let list = List::new(items)
        .block(block(&title, app.focus == Focus::Params))
        .highlight_style(if editing.is_some() {
            Style::default()
        } else {
            SELECTED
        });
    let focus = app.focus == Focus::Params || editing.is_some();
    let mut st = ListState::default().with_selected(focus.then_some(app.param_sel));
    f.render_stateful_widget(list, area, &mut st);
}

fn draw_log(f: &mut Frame, app: &App, area: Rect) {
    let d = &app.doc;
    let mut items = vec![ListItem::new(Line::from(Span::styled(
        format!(
            "{} (document as derived)",
            if d.cursor() == 0 { "▶" } else { " " }
        ),
        Style::default().fg(Color::DarkGray),
    )))];
    for (i, e) in d.edits().iter().enumerate() {
        let active = i < d.cursor();
        let mark = if i + 1 == d.cursor() { "▶" } else { " " };
        let style = if active {
            Style::default().fg(Color::White)
        } else {
            Style::default()
                .fg(Color::DarkGray)
                .add_modifier(Modifier::CROSSED_OUT)
        };
        items.push(ListItem::new(Line::from(Span::styled(
            format!("{mark}{:>2} {}", i + 1, e.summary()),
            style,
        ))));
    }
    let title = format!("Edit log ({} of {} active)", d.cursor(), d.edits().len());
    let list = List::new(items)
        .block(block(&title, app.focus == Focus::Log))
        .highlight_style(SELECTED);
    let mut st =
        ListState::default().with_selected((app.focus == Focus::Log).then_some(app.log_sel));
    f.render_stateful_widget(list, area, &mut st);
}

/// The status line's text.
pub fn status_line(app: &App) -> Line<'static> {
    let mut spans: Vec<Span<'static>> = Vec::new();
    let ok = |b: bool, what: &str| -> Span<'static> {
        if b {
            Span::styled(format!("✓ {what} "), Style::default().fg(Color::Green))
        } else {
            Span::styled(format!("✗ {what} "), Style::default().fg(Color::Red))
        }
    };
    if let Some(s) = &app.shown {
        let r = &s.report;
        spans.push(ok(r.topology.watertight, "watertight"));
        spans.push(ok(r.topology.manifold && r.topology.oriented, "manifold"));
        for p in &r.profile_error {
            spans.push(Span::raw(format!(
                "│ {} err {:.2}% ",
                p.view,
                100.0 * p.max_rel
            )));
        }
        let c2 = r
            .parts
            .iter()
            .flat_map(|p| &p.joins)
            .chain(r.transitions.iter().flat_map(|t| &t.joins))
            .map(|j| j.c2)
            .fold(0.0, f64::max);
        spans.push(Span::raw(format!("│ C1 {:.1e} C2 {c2:.1e} ", r.max_c1)));
        spans.push(Span::raw(format!(
            "│ {} tris │ rebuilt {} ms ",
            r.topology.triangles,
            s.elapsed.as_millis()
        )));
    }
    if let Some(r) = &app.running {
        let what = if r.export { "exporting" } else { "rebuilding" };
        let spin = ["⠋", "⠙", "⠹", "⠸", "⠼", "⠴", "⠦", "⠧", "⠇", "⠏"];
        let t = r.since.elapsed();
        spans.push(Span::styled(
            format!(
                "│ {} {what} {:.1} s (Esc abandons) ",
                spin[(t.as_millis() / 100) as usize % spin.len()],
                t.as_secs_f64()
            ),
            Style::default().fg(Color::Yellow),
        ));
    }
    if app.dirty() {
        spans.push(Span::styled(
            "│ ● unsaved",
            Style::default().fg(Color::Magenta),
        ));
    }
    Line::from(spans)
}

fn draw_message(f: &mut Frame, app: &App, area: Rect) {
    let typing = app.typing_error();
    let width = area.width as usize;
    let line = match (&app.mode, &app.message) {
        (Mode::Editing { .. }, _) if typing.is_some() => Line::from(Span::styled(
            fit(&format!("✗ {}", typing.unwrap_or_default()), width),
            Style::default().fg(Color::Red),
        )),
        (Mode::Export { buffer }, _) => {
            const LABEL: &str = "export to: ";
            const HINT: &str = "  (.obj .glb .stl .ply .png; Enter, Esc)";
            // the typed path gives way from its start, as in a prompt
            let room = width.saturating_sub(LABEL.len() + 1 + HINT.len());
            Line::from(vec![
                Span::styled(LABEL, Style::default().fg(Color::Yellow)),
                Span::raw(format!(
                    "{}▏",
                    elide_left(buffer, room.max(PROMPT_MIN_SHOWN))
                )),
                Span::styled(HINT, Style::default().fg(Color::DarkGray)),
            ])
        }
        (
            Mode::Prompt {
                kind,
                buffer,
                error,
            },
            _,
        ) => {
            let tail = match error {
                Some(e) => Span::styled(
                    fit(
                        &format!("  ✗ {e}"),
                        width.saturating_sub(kind.label().len() + 1 + PROMPT_MIN_SHOWN),
                    ),
                    Style::default().fg(Color::Red),
                ),
                None => Span::styled(
                    format!("  {} · Enter, Esc", kind.hint()),
                    Style::default().fg(Color::DarkGray),
                ),
            };
            // a long path must not push the error off the line: the typed
            // text gives way first, keeping its end (where the cursor is)
            let room = width
                .saturating_sub(kind.label().chars().count() + 1 + tail.content.chars().count());
            let shown = elide_left(buffer, room.max(PROMPT_MIN_SHOWN));
            Line::from(vec![
                Span::styled(kind.label(), Style::default().fg(Color::Yellow)),
                Span::raw(format!("{shown}▏")),
                tail,
            ])
        }
        (_, Some(m)) => Line::from(Span::styled(
            fit(&m.text, width),
            Style::default().fg(if m.error { Color::Red } else { Color::Green }),
        )),
        _ => Line::from(Span::styled(
            fit(&format!("{}  ·  ? help", app.path.display()), width),
            Style::default().fg(Color::DarkGray),
        )),
    };
    f.render_widget(Paragraph::new(line), area);
}

/// Characters of a typed prompt kept on screen however long its error is.
const PROMPT_MIN_SHOWN: usize = 16;
