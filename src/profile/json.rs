//! JSON polyline input: `{"view": "front", "points": [[h, v], ...]}` in
//! profile coordinates (unknown fields rejected).

use super::polygon::ProfileJson;
use super::{Profile, ProfileError};
use std::path::Path;

/// Reads a JSON profile; see [`parse_json`].
pub fn read_json(path: &Path) -> Result<Profile, ProfileError> {
    let name = path.display().to_string();
    let text = crate::mesh::io::read_input_text(path, "JSON profile").map_err(|e| match e {
        crate::mesh::MeshError::Io { path, source } => ProfileError::Io { path, source },
        e => ProfileError::Input(e),
    })?;
    parse(&text, &name)
}

/// Parses a JSON profile and validates it with [`Profile::new`].
pub fn parse_json(text: &str) -> Result<Profile, ProfileError> {
    parse(text, "<json>")
}

fn parse(text: &str, name: &str) -> Result<Profile, ProfileError> {
    let j: ProfileJson = serde_json::from_str(text).map_err(|source| ProfileError::Json {
        path: name.into(),
        source,
    })?;
    Profile::new(j.view, j.points)
}

/// The JSON form read by [`parse_json`].
pub fn to_json(p: &Profile) -> String {
    serde_json::json!({"view": p.view(), "points": p.points()}).to_string()
}
