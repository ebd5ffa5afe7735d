//! Accessor reads with every bound checked first (view inside its buffer,
//! last element inside its view, in u64 arithmetic), so a malformed file
//! is an error naming the accessor or view, never a panic or a read past
//! the data: POSITION as f32 VEC3, indices as u8/u16/u32 scalars.

use super::GltfError;
use ::gltf::accessor::{DataType, Dimensions};
use ::gltf::Accessor;

/// The bytes of `a`'s elements: (data starting at the first element,
/// stride, element size); `None` for an accessor without a buffer view
/// (all zeros by the spec).
fn elements<'b>(
    a: &Accessor,
    buffers: &'b [Vec<u8>],
    elem: usize,
) -> Result<Option<(&'b [u8], usize)>, GltfError> {
    let Some(view) = a.view() else {
        let limit = crate::limits::MESH_VERTICES.max;
        if a.count() as u64 > limit {
            return Err(GltfError::TooMany {
                accessor: a.index(),
                count: a.count(),
                limit,
            });
        }
        return Ok(None);
    };
    let buffer = view.buffer().index();
    let data = &buffers[buffer];
    let (vo, vl) = (view.offset() as u64, view.length() as u64);
    let view_end = vo.saturating_add(vl);
    if view_end > data.len() as u64 {
        return Err(GltfError::ViewPastBuffer {
            view: view.index(),
            end: view_end,
            buffer,
            length: data.len() as u64,
        });
    }
    let stride = view.stride().unwrap_or(elem);
    let count = a.count() as u64;
    let end = if count == 0 {
        a.offset() as u64
    } else {
        (count - 1)
            .checked_mul(stride as u64)
            .and_then(|x| x.checked_add(a.offset() as u64))
            .and_then(|x| x.checked_add(elem as u64))
            .unwrap_or(u64::MAX)
    };
    if end > vl || stride < elem {
        return Err(GltfError::AccessorPastView {
            accessor: a.index(),
            end,
            view: view.index(),
            length: vl,
        });
    }
    let start = (vo + a.offset() as u64) as usize;
    Ok(Some((&data[start..(vo + end) as usize], stride)))
}

/// POSITION: f32 VEC3 (a quantised or normalised position names the
/// extension it needs).
pub fn positions(a: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<[f32; 3]>, GltfError> {
    if a.sparse().is_some() {
        return Err(GltfError::Sparse {
            accessor: a.index(),
            what: "positions",
        });
    }
    if a.data_type() != DataType::F32 || a.dimensions() != Dimensions::Vec3 {
        return Err(GltfError::AccessorType {
            accessor: a.index(),
            what: "POSITION",
            found: format!("{:?} {:?}", a.data_type(), a.dimensions()),
            expected: "F32 Vec3 (quantised positions, KHR_mesh_quantization, are not read)",
        });
    }
    let Some((bytes, stride)) = elements(a, buffers, 12)? else {
        return Ok(vec![[0.0; 3]; a.count()]);
    };
    let f =
        |at: usize| f32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    Ok((0..a.count())
        .map(|i| {
            let at = i * stride;
            [f(at), f(at + 4), f(at + 8)]
        })
        .collect())
}

/// Indices: u8, u16 or u32 scalars, tightly packed or strided.
pub fn indices(a: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<u32>, GltfError> {
    if a.sparse().is_some() {
        return Err(GltfError::Sparse {
            accessor: a.index(),
            what: "indices",
        });
    }
    let size = match (a.data_type(), a.dimensions()) {
        (DataType::U8, Dimensions::Scalar) => 1,
        (DataType::U16, Dimensions::Scalar) => 2,
        (DataType::U32, Dimensions::Scalar) => 4,
        (t, d) => {
            return Err(GltfError::AccessorType {
                accessor: a.index(),
                what: "indices",
                found: format!("{t:?} {d:?}"),
                expected: "U8, U16 or U32 Scalar",
            })
        }
    };
    let Some((bytes, stride)) = elements(a, buffers, size)? else {
        return Ok(vec![0; a.count()]);
    };
    Ok((0..a.count())
        .map(|i| {
            let b = &bytes[i * stride..i * stride + size];
            match size {
                1 => b[0] as u32,
                2 => u16::from_le_bytes([b[0], b[1]]) as u32,
                _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            }
        })
        .collect())
}
