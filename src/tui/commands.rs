//! Commands that change the document's inputs (not the edit log), typed
//! into a one-line prompt: add a part from an SVG profile (`a`), add a key
//! section to the selected part (`x`), attach a prop from a conv model file
//! (`p`). Tab completes a file path (the last word typed).
//!
//! Each command is checked in full before anything changes ([`add_part`],
//! [`add_key_section`], [`add_prop`] build a new document or return the
//! error, which stays on screen with the prompt open); the document then
//! goes through the usual rebuild, and a build failure puts back the last
//! good document. These changes are not entries of the edit log, but they
//! are steps of the session's one undo history ([`super::history`]): `u`
//! and `r` undo and redo them as they do edits.
//!
//! Typed paths are read against the working directory (Tab completes
//! there) and stored relative to the document's directory when the file is
//! in it or below it, absolute otherwise ([`stored_path`]): a document
//! copied or moved together with its files builds in its new place.
//!
//! * Add part: `PATH [NAME]`, a closed outline (SVG or JSON polyline) in
//!   model units, drawn where the part sits. It becomes a removed part
//!   (`sketch::removed`): built from its own outline as one pde6 chain, a
//!   separate closed component not stitched to the body.
//! * Key section: `Y A B` (an ellipse of semi-axes `A` along x and `B`
//!   along z about the part's centre at that height) or `Y FILE.json` (a
//!   closed curve: `[[x, z], ...]`, `{"points": ...}` or a sections file
//!   like `data/sketch/female_sections.json`, whose section of this part
//!   nearest `Y` is taken). Fitted by a GEC that replaces the stored part's
//!   section nearest `Y` (`sketch::keysection`, as a final-level
//!   derivation does) and recorded in `inputs.sections`.
//! * Prop: `MODEL.json [NAME [SCALE [TX TY TZ]]]` (`character::props`).

use super::app::{App, Effect, Mode};
use crate::character::doc::{CharacterDoc, KeySection, ProfileInput, RemovedPart};
use crate::character::props::{PropSpec, MAX_PROPS};
use crossterm::event::{KeyCode, KeyEvent};
use std::path::{Path, PathBuf};

pub use super::prompt::PromptKind;

/// Completes the last word of `typed` as a file path: to the longest
/// common prefix of the matching entries (a directory gets its `/`).
pub fn complete(typed: &str) -> String {
    let split = typed.rfind(' ').map_or(0, |i| i + 1);
    let (head, word) = typed.split_at(split);
    let (dir, stem) = match word.rfind('/') {
        Some(i) => (&word[..=i], &word[i + 1..]),
        None => ("", word),
    };
    let read_dir = if dir.is_empty() { "." } else { dir };
    let Ok(entries) = std::fs::read_dir(read_dir) else {
        return typed.to_string();
    };
    let mut names: Vec<String> = entries
        .filter_map(|e| {
            let e = e.ok()?;
            let mut n = e.file_name().to_str()?.to_string();
            if !n.starts_with(stem) || (n.starts_with('.') && !stem.starts_with('.')) {
                return None;
            }
            if e.path().is_dir() {
                n.push('/');
            }
            Some(n)
        })
        .collect();
    names.sort();
    let Some(first) = names.first() else {
        return typed.to_string();
    };
    let mut common = first.clone();
    for n in &names[1..] {
        let k = common
            .char_indices()
            .zip(n.chars())
            .find(|((_, a), b)| a != b)
            .map_or(common.len().min(n.len()), |((i, _), _)| i);
        common.truncate(k);
    }
    format!("{head}{dir}{common}")
}

/// A typed path made absolute (against the working directory), checked to
/// be a readable file with one of `exts`.
fn typed_file(word: &str, exts: &[&str]) -> Result<PathBuf, String> {
    let p = Path::new(word);
    let ext = p
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if !exts.contains(&ext.as_str()) {
        return Err(format!("{word}: expected a .{} file", exts.join(" or .")));
    }
    let abs = std::fs::canonicalize(p).map_err(|e| format!("{word}: {e}"))?;
    if !abs.is_file() {
        return Err(format!("{word}: not a file"));
    }
    Ok(abs)
}

/// How a typed file is stored in the document: relative to the document's
/// directory `base` (with `/` separators) when the file is in it or below
/// it, so a document moved or copied with its files still builds;
/// absolute otherwise. `character build` and the TUI resolve a relative
/// path against the document's directory (`sketch::input::read_profile`,
/// `PropSpec::path`).
pub fn stored_path(abs: &Path, base: &Path) -> String {
    let rel = std::fs::canonicalize(base)
        .ok()
        .and_then(|b| abs.strip_prefix(b).ok().map(Path::to_path_buf))
        .filter(|r| !r.as_os_str().is_empty());
    let words = rel.as_ref().and_then(|r| {
        r.components()
            .map(|c| match c {
                std::path::Component::Normal(w) => w.to_str(),
                _ => None,
            })
            .collect::<Option<Vec<&str>>>()
    });
    match words {
        Some(w) => w.join("/"),
        None => abs.display().to_string(),
    }
}

fn stem_name(p: &Path) -> String {
    let s: String = p
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("part")
        .chars()
        .map(|c| if c.is_alphanumeric() { c } else { '_' })
        .collect();
    if s.is_empty() {
        "part".into()
    } else {
        s
    }
}

/// Every name in use (parts, transitions, removed parts, props).
fn name_used(doc: &CharacterDoc, name: &str) -> bool {
    doc.parts().iter().any(|p| p.name == name)
        || doc.transitions().iter().any(|t| t.name == name)
        || doc.removed_parts().iter().any(|r| r.name == name)
        || doc.props().iter().any(|p| p.name == name)
}

fn check_name(doc: &CharacterDoc, name: &str) -> Result<(), String> {
    if name.is_empty() || name.chars().any(|c| !(c.is_alphanumeric() || c == '_')) {
        return Err(format!("name '{name}': use letters, digits and '_' only"));
    }
    if name_used(doc, name) {
        return Err(format!("name '{name}' is already used"));
    }
    Ok(())
}

fn number(w: &str, what: &str) -> Result<f64, String> {
    match w.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => Err(format!("{what} '{w}' is not finite ({v})")),
        Err(_) => Err(format!("{what} '{w}' is not a number")),
    }
}

fn need_parts(doc: &CharacterDoc) -> Result<(), String> {
    if doc.parts().is_empty() {
        Err("the document has no parts yet (wait for the first build)".into())
    } else {
        Ok(())
    }
}

/// The document with a part added from a profile file, and a message.
pub fn add_part(
    doc: &CharacterDoc,
    base: &Path,
    input: &str,
) -> Result<(CharacterDoc, String), String> {
    need_parts(doc)?;
    let words: Vec<&str> = input.split_whitespace().collect();
    if words.is_empty() || words.len() > 2 {
        return Err("expected PATH [NAME]".into());
    }
    let path = typed_file(words[0], &["svg", "json"])?;
    let name = words
        .get(1)
        .map_or_else(|| stem_name(&path), |n| n.to_string());
    check_name(doc, &name)?;
    let rp = RemovedPart {
        name: name.clone(),
        front: ProfileInput::Path(stored_path(&path, base)),
        side: None,
    };
    let placement = crate::sketch::place::placement(doc, base).map_err(|e| e.to_string())?;
    let built = crate::sketch::removed::removed_part(&rp, base, doc.inputs().tolerance, &placement)
        .map_err(|e| e.to_string())?;
    let mut out = doc.clone();
    out.add_drawn_part(rp, built.spec);
    out.validate().map_err(|e| e.to_string())?;
    let n = out.parts().last().map_or(0, |p| p.sections.len());
    Ok((
        out,
        format!(
            "added part '{name}' ({n} sections, a separate component) from {}",
            path.display()
        ),
    ))
}

/// Points of an ellipse (x, z) about `c` with semi-axes `a`, `b`.
fn ellipse(c: [f64; 2], a: f64, b: f64) -> Vec<[f64; 2]> {
    const N: usize = 64;
    (0..N)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / N as f64;
            [c[0] + a * t.cos(), c[1] + b * t.sin()]
        })
        .collect()
}

/// Points of a closed-curve file for `part` near `y`.
fn curve_file(path: &Path, part: &str, y: f64) -> Result<Vec<[f64; 2]>, String> {
    let text = crate::mesh::io::read_input_text(path, "drawing").map_err(|e| e.to_string())?;
    let v: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let points = |v: &serde_json::Value| -> Result<Vec<[f64; 2]>, String> {
        serde_json::from_value::<Vec<[f64; 2]>>(v.clone())
            .map_err(|e| format!("{}: points: {e}", path.display()))
    };
    let pts = if v.is_array() {
        points(&v)?
    } else if let Some(p) = v.get("points") {
        points(p)?
    } else if let Some(s) = v.get("sections") {
        let secs: Vec<KeySection> = serde_json::from_value(s.clone())
            .map_err(|e| format!("{}: sections: {e}", path.display()))?;
        secs.into_iter()
            .filter(|s| s.part == part)
            .min_by(|a, b| (a.y - y).abs().total_cmp(&(b.y - y).abs()))
            .ok_or_else(|| format!("{}: no section of part '{part}'", path.display()))?
            .points
    } else {
        return Err(format!(
            "{}: expected [[x, z], ...], {{\"points\": ...}} or {{\"sections\": ...}}",
            path.display()
        ));
    };
    if let Some(p) = pts.iter().find(|p| !(p[0].is_finite() && p[1].is_finite())) {
        return Err(format!("{}: point {p:?} is not finite", path.display()));
    }
    Ok(pts)
}

/// The document with a key section added to part `part`, and a message.
pub fn add_key_section(
    doc: &CharacterDoc,
    part: &str,
    input: &str,
) -> Result<(CharacterDoc, String), String> {
    need_parts(doc)?;
    let stored = doc
        .parts()
        .iter()
        .find(|p| p.name == part)
        .ok_or_else(|| format!("'{part}' is not a part: select a part first"))?;
    let words: Vec<&str> = input.split_whitespace().collect();
    let (y, how) = match words.as_slice() {
        [y, a, b] => {
            let y = number(y, "height")?;
            let (a, b) = (number(a, "semi-axis")?, number(b, "semi-axis")?);
            if a <= 0.0 || b <= 0.0 {
                return Err(format!("semi-axes must be positive, got {a} and {b}"));
            }
            let n = stored.sections.len();
            let sec = (1..n.saturating_sub(1))
                .map(|j| &stored.sections[j])
                .min_by(|p, q| (p.centre[1] - y).abs().total_cmp(&(q.centre[1] - y).abs()))
                .ok_or_else(|| format!("part '{part}' has no interior section"))?;
            let c = [sec.centre[0], sec.centre[2]];
            (y, Ok((a, b, c)))
        }
        [y, file] => (number(y, "height")?, Err(*file)),
        _ => return Err("expected Y A B (ellipse) or Y FILE.json".into()),
    };
    let (points, what) = match how {
        Ok((a, b, c)) => (ellipse(c, a, b), format!("ellipse {a} x {b}")),
        Err(file) => {
            let p = typed_file(file, &["json"])?;
            (
                curve_file(&p, part, y)?,
                format!("curve from {}", p.display()),
            )
        }
    };
    let k = KeySection {
        part: part.into(),
        y,
        points,
    };
    let mut parts = doc.parts().to_vec();
    crate::sketch::keysection::apply_key_section(&mut parts, &k).map_err(|e| e.to_string())?;
    crate::edit::apply_to_parts(&parts, doc.active_edits())
        .map_err(|e| format!("the edit log no longer applies: {e}"))?;
    let mut out = doc.clone();
    out.add_key_section(k, parts);
    out.validate().map_err(|e| e.to_string())?;
    Ok((out, format!("key section of '{part}' at y = {y}: {what}")))
}

/// The document with a prop attached, and a message.
pub fn add_prop(
    doc: &CharacterDoc,
    base: &Path,
    input: &str,
) -> Result<(CharacterDoc, String), String> {
    let words: Vec<&str> = input.split_whitespace().collect();
    if words.is_empty() || words.len() > 6 || words.len() == 4 || words.len() == 5 {
        return Err("expected MODEL.json [NAME [SCALE [TX TY TZ]]]".into());
    }
    if doc.props().len() >= MAX_PROPS {
        return Err(format!("the document has {MAX_PROPS} props already"));
    }
    let path = typed_file(words[0], &["json"])?;
    let name = words
        .get(1)
        .map_or_else(|| stem_name(&path), |n| n.to_string());
    check_name(doc, &name)?;
    let scale = words.get(2).map_or(Ok(1.0), |w| number(w, "scale"))?;
    let mut translate = [0.0; 3];
    if words.len() == 6 {
        for k in 0..3 {
            translate[k] = number(words[3 + k], "translation")?;
        }
    }
    let p = PropSpec {
        name: name.clone(),
        model: stored_path(&path, base),
        translate,
        scale,
    };
    p.validate().map_err(|e| e.to_string())?;
    let (_, model) = p.read_model(base).map_err(|e| e.to_string())?;
    let mut out = doc.clone();
    out.push_prop(p);
    out.validate().map_err(|e| e.to_string())?;
    Ok((
        out,
        format!(
            "attached prop '{name}' ({} components) from {}",
            model.components.len(),
            path.display()
        ),
    ))
}

impl App {
    /// Takes the outcome of a checked edit ([`Effect::Check`]): push it
    /// when the document built with it, else say why (the document is
    /// unchanged).
    pub(super) fn checked(
        &mut self,
        edit: crate::character::log::Edit,
        result: Result<Box<super::worker::Rebuilt>, String>,
        elapsed: std::time::Duration,
    ) -> Vec<Effect> {
        let summary = edit.summary();
        let r = match result {
            Ok(r) => r,
            Err(e) => {
                self.say(format!("not applied: {e}"), true);
                return Vec::new();
            }
        };
        // the worker built the document with the edit: it enters the log
        // as judged there (no second replay here)
        self.doc.append_edit(edit);
        self.history.record_edit();
        self.log_sel = self.doc.cursor();
        self.edited = r.edited.clone();
        // autosave; the build with the edit is at hand (no second rebuild)
        let _ = self.changed_without_replay();
        self.say(format!("applied: {summary}"), false);
        self.built(*r, elapsed)
    }

    /// Opens the prompt of a command.
    pub(super) fn prompt(&mut self, kind: PromptKind) -> Vec<Effect> {
        self.mode = Mode::Prompt {
            kind,
            buffer: String::new(),
            error: None,
        };
        Vec::new()
    }

    pub(super) fn on_prompt_key(
        &mut self,
        k: KeyEvent,
        kind: PromptKind,
        mut buffer: String,
    ) -> Vec<Effect> {
        match k.code {
            KeyCode::Esc => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Tab => buffer = complete(&buffer),
            KeyCode::Backspace => {
                buffer.pop();
            }
            KeyCode::Char(c) => buffer.push(c),
            KeyCode::Enter => {
                let part = self.selected().map(|t| t.name).unwrap_or_default();
                let r = match kind {
                    PromptKind::AddPart => add_part(&self.doc, &self.base, &buffer),
                    PromptKind::KeySection => add_key_section(&self.doc, &part, &buffer),
                    PromptKind::AddProp => add_prop(&self.doc, &self.base, &buffer),
                };
                match r {
                    Ok((doc, msg)) => {
                        let what = match kind {
                            PromptKind::AddPart => format!(
                                "add part '{}'",
                                doc.removed_parts().last().map_or("", |r| r.name.as_str())
                            ),
                            PromptKind::KeySection => format!("key section of '{part}'"),
                            PromptKind::AddProp => format!(
                                "attach prop '{}'",
                                doc.props().last().map_or("", |p| p.name.as_str())
                            ),
                        };
                        let before = std::mem::replace(&mut self.doc, doc);
                        self.history.record_inputs(what, &before, &mut self.doc);
                        self.mode = Mode::Normal;
                        self.say(msg, false);
                        return self.changed();
                    }
                    Err(e) => {
                        self.say(format!("not applied: {e}"), true);
                        self.mode = Mode::Prompt {
                            kind,
                            buffer,
                            error: Some(e),
                        };
                        return Vec::new();
                    }
                }
            }
            _ => return Vec::new(),
        }
        self.mode = Mode::Prompt {
            kind,
            buffer,
            error: None,
        };
        Vec::new()
    }
}
