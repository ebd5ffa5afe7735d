//! The glTF container: a GLB's header and chunks (every length checked
//! against the file), the JSON parsed and validated by the `gltf` crate,
//! the extensions refused by name, and each buffer's bytes (the GLB's BIN
//! chunk, a base64 `data:` URI, or a file beside the `.gltf`, which must
//! stay inside the file's folder).

use super::GltfError;
use ::gltf::json::validation::Validate;
use ::gltf::Document;
use std::path::Path;

/// Mesh-compression extensions: named in the error, since they are the
/// usual reason an exporter's file does not read.
const COMPRESSION: [&str; 3] = [
    "KHR_draco_mesh_compression",
    "EXT_meshopt_compression",
    "KHR_meshopt_compression",
];

/// Extensions that change nothing pdesculpt reads (materials, lights,
/// texture transforms): allowed even when required.
const HARMLESS: [&str; 3] = [
    "KHR_materials_unlit",
    "KHR_texture_transform",
    "KHR_lights_punctual",
];

/// A parsed glTF: its document and the bytes of each buffer.
pub struct Parsed {
    pub doc: Document,
    pub buffers: Vec<Vec<u8>>,
}

/// Parses a GLB (starts with `glTF`) or a JSON glTF; `dir` is the folder
/// external buffers are resolved in (`None`: external buffers refused).
pub fn parse(bytes: &[u8], dir: Option<&Path>) -> Result<Parsed, GltfError> {
    let (json, bin) = if bytes.first() == Some(&b'{') || is_json_with_bom(bytes) {
        (bytes, None)
    } else {
        let (j, b) = split_glb(bytes)?;
        (j, b)
    };
    let doc = document(json)?;
    let buffers = doc
        .buffers()
        .map(|b| buffer_bytes(&b, bin, dir))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Parsed { doc, buffers })
}

fn is_json_with_bom(bytes: &[u8]) -> bool {
    bytes.starts_with(&[0xEF, 0xBB, 0xBF])
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}

/// The JSON chunk and the optional BIN chunk of a GLB.
fn split_glb(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), GltfError> {
    let actual = bytes.len() as u64;
    let truncated = |what: &str, needed: u64| GltfError::Truncated {
        what: what.to_string(),
        needed,
        actual,
    };
    if bytes.len() < 4 || &bytes[..4] != b"glTF" {
        let n = bytes.len().min(4);
        return Err(GltfError::Magic {
            found: String::from_utf8_lossy(&bytes[..n]).into_owned(),
        });
    }
    if bytes.len() < 12 {
        return Err(truncated("the GLB header", 12));
    }
    let version = u32_at(bytes, 4);
    if version != 2 {
        return Err(GltfError::Version { version });
    }
    let declared = u32_at(bytes, 8) as u64;
    if declared > actual {
        return Err(truncated("the GLB (the length in its header)", declared));
    }
    let body = &bytes[..declared as usize];
    let mut chunks: Vec<&[u8]> = Vec::new();
    let mut at = 12usize;
    while at < body.len() && chunks.len() < 2 {
        if at + 8 > body.len() {
            return Err(truncated("a chunk header", at as u64 + 8));
        }
        let len = u32_at(body, at) as u64;
        let ty = &body[at + 4..at + 8];
        let end = at as u64 + 8 + len;
        if end > body.len() as u64 {
            return Err(truncated(
                &format!("chunk {} ({})", chunks.len(), String::from_utf8_lossy(ty)),
                end,
            ));
        }
        let expected: &[u8] = if chunks.is_empty() { b"JSON" } else { b"BIN\0" };
        if ty != expected {
            return Err(GltfError::ChunkType {
                index: chunks.len(),
                found: String::from_utf8_lossy(ty).into_owned(),
                expected: if chunks.is_empty() { "JSON" } else { "BIN" },
            });
        }
        chunks.push(&body[at + 8..end as usize]);
        at = end as usize;
    }
    match chunks.as_slice() {
        [] => Err(truncated("the JSON chunk", 20)),
        [j] => Ok((j, None)),
        [j, b, ..] => Ok((j, Some(b))),
    }
}

/// The JSON deserialised, its required extensions checked, validated.
fn document(json: &[u8]) -> Result<Document, GltfError> {
    let json = json.strip_prefix(&[0xEF, 0xBB, 0xBF][..]).unwrap_or(json);
    let root: ::gltf::json::Root =
        ::gltf::json::deserialize::from_slice(json).map_err(|e| GltfError::Json {
            message: e.to_string(),
        })?;
    let named =
        |list: &[String], set: &[&str]| list.iter().find(|e| set.contains(&e.as_str())).cloned();
    if let Some(extension) = named(&root.extensions_required, &COMPRESSION)
        .or_else(|| named(&root.extensions_used, &COMPRESSION))
    {
        return Err(GltfError::Compressed { extension });
    }
    if let Some(extension) = root
        .extensions_required
        .iter()
        .find(|e| !HARMLESS.contains(&e.as_str()))
    {
        return Err(GltfError::UnsupportedExtension {
            extension: extension.clone(),
        });
    }
    let mut errors = Vec::new();
    let harmless = |p: &str| p.starts_with("extensionsRequired");
    root.validate(&root, ::gltf::json::Path::new, &mut |path, error| {
        let p = path().to_string();
        if !harmless(&p) {
            errors.push(format!("{p}: {error}"));
        }
    });
    if !errors.is_empty() {
        errors.truncate(8);
        return Err(GltfError::Invalid { errors });
    }
    Ok(Document::from_json_without_validation(root))
}

/// The bytes of one buffer, at least its declared length.
fn buffer_bytes(
    b: &::gltf::Buffer,
    bin: Option<&[u8]>,
    dir: Option<&Path>,
) -> Result<Vec<u8>, GltfError> {
    let buffer = b.index();
    let missing = |reason: String| GltfError::MissingBuffer { buffer, reason };
    let data = match b.source() {
        ::gltf::buffer::Source::Bin => bin
            .ok_or_else(|| missing("no uri and no GLB binary chunk".into()))?
            .to_vec(),
        ::gltf::buffer::Source::Uri(uri) => {
            if let Some(rest) = uri.strip_prefix("data:") {
                data_uri(rest).map_err(missing)?
            } else {
                external(buffer, uri, dir)?
            }
        }
    };
    let declared = b.length() as u64;
    if (data.len() as u64) < declared {
        return Err(GltfError::BufferShort {
            buffer,
            declared,
            actual: data.len() as u64,
        });
    }
    Ok(data)
}

/// The payload of a base64 `data:` URI (`MEDIA;base64,DATA`).
fn data_uri(rest: &str) -> Result<Vec<u8>, String> {
    use base64::Engine;
    let (head, payload) = rest.split_once(',').ok_or("a data: uri without a comma")?;
    if !head.ends_with(";base64") {
        return Err(format!("a data: uri that is not base64 ({head:?})"));
    }
    base64::engine::general_purpose::STANDARD
        .decode(payload)
        .map_err(|e| format!("its base64 data does not decode: {e}"))
}

/// An external buffer file: a relative path (percent-escapes decoded)
/// with no `..`, no scheme and no absolute part, whose real path (links
/// resolved) is inside `dir`'s real path.
fn external(buffer: usize, uri: &str, dir: Option<&Path>) -> Result<Vec<u8>, GltfError> {
    let outside = || GltfError::UriOutsideFolder {
        buffer,
        uri: uri.to_string(),
    };
    let missing = |reason: String| GltfError::MissingBuffer { buffer, reason };
    let dir = dir.ok_or_else(|| missing(format!("external uri {uri:?} in an in-memory file")))?;
    let decoded = percent_decode(uri).ok_or_else(outside)?;
    let rel = Path::new(&decoded);
    let plain = rel
        .components()
        .all(|c| matches!(c, std::path::Component::Normal(_)));
    if !plain || decoded.contains(':') || decoded.contains('\\') {
        return Err(outside());
    }
    let full = dir.join(rel);
    let (real_dir, real) = match (dir.canonicalize(), full.canonicalize()) {
        (Ok(d), Ok(f)) => (d, f),
        (_, Err(e)) => return Err(missing(format!("{}: {e}", full.display()))),
        (Err(e), _) => return Err(missing(format!("{}: {e}", dir.display()))),
    };
    if !real.starts_with(&real_dir) {
        return Err(outside());
    }
    let len = std::fs::metadata(&real)
        .map_err(|e| missing(format!("{}: {e}", full.display())))?
        .len();
    if len > crate::limits::MEMORY_BYTES {
        return Err(missing(format!(
            "{} is {len} bytes, over the {} byte memory budget",
            full.display(),
            crate::limits::MEMORY_BYTES
        )));
    }
    std::fs::read(&real).map_err(|e| missing(format!("{}: {e}", full.display())))
}

/// `%XX` escapes decoded (`None` on a malformed escape or non-UTF-8).
fn percent_decode(s: &str) -> Option<String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            let hex = std::str::from_utf8(b.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}
