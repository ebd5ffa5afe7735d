//! PLY: binary little-endian write (positions, normals, triangles); ASCII
//! and binary little-endian read of `vertex` x/y/z and `face` index lists.

use crate::mesh::{Mesh, MeshError};

/// Encodes binary little-endian PLY with vertex normals.
pub fn encode_ply(m: &Mesh) -> Vec<u8> {
    let header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment pdesculpt\nelement vertex {}\n\
property float x\nproperty float y\nproperty float z\n\
property float nx\nproperty float ny\nproperty float nz\n\
element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        m.positions.len(),
        m.triangles.len()
    );
    let mut out = header.into_bytes();
    for (p, n) in m.positions.iter().zip(m.vertex_normals()) {
        for x in p.iter().chain(n.iter()) {
            out.extend_from_slice(&(*x as f32).to_le_bytes());
        }
    }
    for t in &m.triangles {
        out.push(3);
        for &i in t {
            out.extend_from_slice(&(i as i32).to_le_bytes());
        }
    }
    out
}

#[derive(Clone, Copy, PartialEq)]
enum Ty {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Ty {
    fn parse(s: &str) -> Option<Ty> {
        Some(match s {
            "char" | "int8" => Ty::I8,
            "uchar" | "uint8" => Ty::U8,
            "short" | "int16" => Ty::I16,
            "ushort" | "uint16" => Ty::U16,
            "int" | "int32" => Ty::I32,
            "uint" | "uint32" => Ty::U32,
            "float" | "float32" => Ty::F32,
            "double" | "float64" => Ty::F64,
            _ => return None,
        })
    }
    fn size(self) -> usize {
        match self {
            Ty::I8 | Ty::U8 => 1,
            Ty::I16 | Ty::U16 => 2,
            Ty::I32 | Ty::U32 | Ty::F32 => 4,
            Ty::F64 => 8,
        }
    }
    fn read(self, b: &[u8]) -> f64 {
        match self {
            Ty::I8 => b[0] as i8 as f64,
            Ty::U8 => b[0] as f64,
            Ty::I16 => i16::from_le_bytes([b[0], b[1]]) as f64,
            Ty::U16 => u16::from_le_bytes([b[0], b[1]]) as f64,
            Ty::I32 => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            Ty::U32 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            Ty::F32 => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            Ty::F64 => f64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]),
        }
    }
}

enum Prop {
    Scalar(String, Ty),
    List(String, Ty, Ty),
}

struct Element {
    name: String,
    count: usize,
    props: Vec<Prop>,
}

/// Parses ASCII or binary little-endian PLY.
pub fn parse_ply(bytes: &[u8], path: &str) -> Result<Mesh, MeshError> {
    let end = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .ok_or_else(|| parse_error(path, 1, "no 'end_header' line".into()))?;
    let header = std::str::from_utf8(&bytes[..end])
        .map_err(|_| parse_error(path, 1, "header is not text".into()))?;
    let body = &bytes[end + 11..];
    let (ascii, elements) = parse_header(header, path)?;
    let header_end = end + 11;
    check_elements(&elements, body.len(), path)?;
    let vertex_count = elements
        .iter()
        .find(|e| e.name == "vertex")
        .map_or(0, |e| e.count);
    let mut m = Mesh::new(Vec::new(), Vec::new());
    let tokens = if ascii {
        Some(
            std::str::from_utf8(body)
                .map_err(|_| invalid(path, "ASCII body is not text".into()))?
                .split_whitespace(),
        )
    } else {
        None
    };
    let mut r = Reader {
        path,
        body,
        header_end,
        tokens,
        pos: 0,
        token_no: 0,
    };
    for e in &elements {
        for _ in 0..e.count {
            read_entry(e, &mut r, vertex_count, &mut m)?;
        }
    }
    Ok(m)
}

/// A header line's error.
fn parse_error(path: &str, line: usize, message: String) -> MeshError {
    MeshError::Parse {
        path: path.to_string(),
        line,
        message,
    }
}

/// A body's error.
fn invalid(path: &str, message: String) -> MeshError {
    MeshError::Invalid(format!("{path}: {message}"))
}

/// The header's format (ASCII or not) and its elements with their
/// properties.
fn parse_header(header: &str, path: &str) -> Result<(bool, Vec<Element>), MeshError> {
    let err = |line: usize, message: String| parse_error(path, line, message);
    let mut lines = header.lines().enumerate();
    if lines.next().map(|l| l.1.trim()) != Some("ply") {
        return Err(err(1, "missing 'ply' magic".into()));
    }
    let mut ascii = None;
    let mut elements: Vec<Element> = Vec::new();
    for (ln, line) in lines {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.as_slice() {
            ["format", "ascii", _] => ascii = Some(true),
            ["format", "binary_little_endian", _] => ascii = Some(false),
            ["format", f, ..] => return Err(err(ln + 1, format!("unsupported PLY format {f:?}"))),
            ["element", name, count] => elements.push(Element {
                name: name.to_string(),
                count: count
                    .parse()
                    .map_err(|_| err(ln + 1, format!("bad element count {count:?}")))?,
                props: Vec::new(),
            }),
            ["property", "list", c, t, name] => {
                let (c, t) = (Ty::parse(c), Ty::parse(t));
                let e = elements
                    .last_mut()
                    .ok_or_else(|| err(ln + 1, "property before element".into()))?;
                match (c, t) {
                    (Some(c), Some(t)) => e.props.push(Prop::List(name.to_string(), c, t)),
                    _ => return Err(err(ln + 1, "unknown list property type".into())),
                }
            }
            ["property", t, name] => {
                let t = Ty::parse(t)
                    .ok_or_else(|| err(ln + 1, format!("unknown property type {t:?}")))?;
                let e = elements
                    .last_mut()
                    .ok_or_else(|| err(ln + 1, "property before element".into()))?;
                e.props.push(Prop::Scalar(name.to_string(), t));
            }
            _ => {}
        }
    }
    let ascii = ascii.ok_or_else(|| err(2, "missing 'format' line".into()))?;
    Ok((ascii, elements))
}

/// Refuses an element with entries but no properties, one declaring more
/// entries than the body (`body_len` bytes) could hold, and a vertex
/// element without x, y and z.
fn check_elements(elements: &[Element], body_len: usize, path: &str) -> Result<(), MeshError> {
    let berr = |message: String| invalid(path, message);
    for e in elements {
        if e.count > 0 && e.props.is_empty() {
            return Err(berr(format!("element '{}' has no properties", e.name)));
        }
        // every element takes at least one token or byte: a count beyond the
        // data is refused before any allocation or loop
        if e.count > body_len {
            return Err(berr(format!(
                "element '{}' declares {} entries but the data has only {} bytes",
                e.name, e.count, body_len
            )));
        }
        if e.name == "vertex" {
            for axis in ["x", "y", "z"] {
                if !e
                    .props
                    .iter()
                    .any(|p| matches!(p, Prop::Scalar(n, _) if n == axis))
                {
                    return Err(berr(format!(
                        "element 'vertex' has no scalar property '{axis}'"
                    )));
                }
            }
        }
    }
    Ok(())
}

/// The body's values in order: ASCII tokens, or binary little-endian
/// values read from `pos`.
struct Reader<'a> {
    path: &'a str,
    body: &'a [u8],
    /// Byte offset of the body in the file.
    header_end: usize,
    /// The ASCII body's tokens; `None` for a binary body.
    tokens: Option<std::str::SplitWhitespace<'a>>,
    pos: usize,
    token_no: usize,
}

impl Reader<'_> {
    /// Where the next value starts: byte offset in the file (binary) or the
    /// value number in the body (ASCII).
    fn at(&self) -> String {
        if self.tokens.is_some() {
            format!("value {} of the data", self.token_no)
        } else {
            format!("byte {}", self.header_end + self.pos)
        }
    }

    /// The next value (of type `ty` in a binary body) and where it starts.
    fn next(&mut self, ty: Ty) -> Result<(f64, String), MeshError> {
        let here = self.at();
        let berr = |message: String| invalid(self.path, message);
        if let Some(t) = self.tokens.as_mut() {
            self.token_no += 1;
            let s = t
                .next()
                .ok_or_else(|| berr(format!("{here}: unexpected end of PLY data")))?;
            let v = s
                .parse::<f64>()
                .map_err(|_| berr(format!("{here}: bad PLY value {s:?}")))?;
            Ok((v, here))
        } else {
            let n = ty.size();
            let b = self
                .body
                .get(self.pos..self.pos + n)
                .ok_or_else(|| berr(format!("{here}: unexpected end of PLY data")))?;
            self.pos += n;
            Ok((ty.read(b), here))
        }
    }

    /// `v` (read at `here`) as an index in `0..max`, refused otherwise.
    fn index(&self, v: f64, here: &str, what: &str, max: f64) -> Result<usize, MeshError> {
        if !(v.is_finite() && v.fract() == 0.0 && v >= 0.0 && v < max) {
            return Err(invalid(
                self.path,
                format!("{here}: {what} {v} is not an integer in 0..{max}"),
            ));
        }
        Ok(v as usize)
    }
}

/// Reads one entry of element `e` and adds it to `m`: a vertex's position,
/// or a face fanned into triangles.
fn read_entry(
    e: &Element,
    r: &mut Reader,
    vertex_count: usize,
    m: &mut Mesh,
) -> Result<(), MeshError> {
    let berr = |message: String| invalid(r.path, message);
    let mut p = [0.0; 3];
    let mut face: Vec<u32> = Vec::new();
    for prop in &e.props {
        match prop {
            Prop::Scalar(name, ty) => {
                let (x, here) = r.next(*ty)?;
                let slot = match name.as_str() {
                    "x" => Some(0),
                    "y" => Some(1),
                    "z" => Some(2),
                    _ => None,
                };
                if let Some(k) = slot {
                    if !x.is_finite() {
                        return Err(berr(format!("{here}: vertex coordinate {x}")));
                    }
                    p[k] = x;
                }
            }
            Prop::List(name, cty, ity) => {
                let (n, here) = r.next(*cty)?;
                let n = r.index(n, &here, "list length", 1e6)?;
                for _ in 0..n {
                    let (i, here) = r.next(*ity)?;
                    if name == "vertex_indices" || name == "vertex_index" {
                        let i = r.index(i, &here, "face index", vertex_count as f64)?;
                        face.push(i as u32);
                    }
                }
            }
        }
    }
    if e.name == "vertex" {
        m.positions.push(p);
    } else if e.name == "face" {
        if face.len() < 3 {
            return Err(berr(format!("face with {} vertices", face.len())));
        }
        for k in 1..face.len() - 1 {
            m.triangles.push([face[0], face[k], face[k + 1]]);
            m.tri_group.push(0);
        }
    }
    Ok(())
}
