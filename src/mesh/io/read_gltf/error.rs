//! What can be wrong with a glTF input, one variant per case, each naming
//! the object (chunk, buffer, view, accessor, node) and the numbers.

use thiserror::Error;

/// Errors of reading glTF 2.0 (GLB or JSON).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GltfError {
    #[error("not a GLB file: it starts with {found:?}, not \"glTF\" (a .gltf file is JSON and starts with '{{')")]
    Magic { found: String },
    #[error("the file is truncated: {what} ends at byte {needed}, the file has {actual} bytes")]
    Truncated {
        what: String,
        needed: u64,
        actual: u64,
    },
    #[error("GLB version {version} is not supported (glTF 2.0 only)")]
    Version { version: u32 },
    #[error("GLB chunk {index} is {found:?}, expected {expected:?}")]
    ChunkType {
        index: usize,
        found: String,
        expected: &'static str,
    },
    #[error("the glTF JSON does not parse: {message}")]
    Json { message: String },
    #[error("the glTF JSON is invalid: {}", .errors.join("; "))]
    Invalid { errors: Vec<String> },
    #[error("meshes are compressed with {extension}, which pdesculpt does not decode: export the file without mesh compression (Blender: glTF export, uncheck Compression)")]
    Compressed { extension: String },
    #[error("the file requires the extension {extension}, which pdesculpt does not support")]
    UnsupportedExtension { extension: String },
    #[error("buffer {buffer} has no data: {reason}")]
    MissingBuffer { buffer: usize, reason: String },
    #[error("buffer {buffer}: uri {uri:?} is outside the file's folder (external buffers must be in the folder of the .gltf or below it)")]
    UriOutsideFolder { buffer: usize, uri: String },
    #[error("buffer {buffer} declares {declared} bytes but its data has {actual}")]
    BufferShort {
        buffer: usize,
        declared: u64,
        actual: u64,
    },
    #[error(
        "buffer view {view} ends at byte {end}, past the end of buffer {buffer} ({length} bytes)"
    )]
    ViewPastBuffer {
        view: usize,
        end: u64,
        buffer: usize,
        length: u64,
    },
    #[error("accessor {accessor} ends at byte {end} of buffer view {view}, past its end ({length} bytes)")]
    AccessorPastView {
        accessor: usize,
        end: u64,
        view: usize,
        length: u64,
    },
    #[error(
        "accessor {accessor} has no buffer view and {count} elements, over the limit of {limit}"
    )]
    TooMany {
        accessor: usize,
        count: usize,
        limit: u64,
    },
    #[error("accessor {accessor} is sparse, which pdesculpt does not read for {what}")]
    Sparse { accessor: usize, what: &'static str },
    #[error("accessor {accessor} ({what}) is {found}; expected {expected}")]
    AccessorType {
        accessor: usize,
        what: &'static str,
        found: String,
        expected: &'static str,
    },
    #[error("node {node:?}, primitive {primitive}: no POSITION attribute")]
    NoPositions { node: String, primitive: usize },
    #[error("node {node:?}, primitive {primitive} draws {mode}, not triangles; read only the triangle meshes by naming their nodes: FILE.glb#NODE[,NODE...]")]
    NotTriangles {
        node: String,
        primitive: usize,
        mode: String,
    },
    #[error(
        "node {node:?}, primitive {primitive}: {count} indices is not a whole number of triangles"
    )]
    PartialTriangle {
        node: String,
        primitive: usize,
        count: usize,
    },
    #[error(
        "node {node:?}, primitive {primitive}: index {index} is past the vertex count {count}"
    )]
    IndexOutOfRange {
        node: String,
        primitive: usize,
        index: u32,
        count: usize,
    },
    #[error("node {node:?}, vertex {vertex} is {value:?} after the node transforms: not a finite 32-bit coordinate (|x| <= 3.4e38)")]
    NonFinite {
        node: String,
        vertex: usize,
        value: [f64; 3],
    },
    #[error("node {node} is reached twice in the node hierarchy (glTF nodes form a tree)")]
    NodeCycle { node: usize },
    #[error("no node is named {name:?}; the file's nodes: {}", .available.join(", "))]
    NoSuchNode {
        name: String,
        available: Vec<String>,
    },
    #[error("the scene has no triangle meshes")]
    NoMeshes,
}
