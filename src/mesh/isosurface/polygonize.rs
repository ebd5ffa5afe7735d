//! The two polygonisers: marching tetrahedra and naive surface nets.

use super::scan::*;
use super::*;

/// Marching tetrahedra (Kuhn split) of `grid` at level `iso`.
pub fn marching_tetrahedra(grid: &ScalarGrid, iso: f64) -> Mesh {
    let d = grid.dims;
    let cases = mt_cases();
    let slab = d[0] * d[1];
    let mut ins = [vec![0u8; slab], vec![0u8; slab]];
    inside_layer(grid, iso, 0, &mut ins[0]);
    let mut ev = SlabVertices {
        sampler: Sampler::new(grid, iso),
        slabs: [vec![u32::MAX; slab << 3], vec![u32::MAX; slab << 3]],
        touched: [Vec::new(), Vec::new()],
        positions: Vec::new(),
    };
    let mut tris: Vec<[u32; 3]> = Vec::new();
    for k in 0..d[2] - 1 {
        // the slabs of layer k - 1 become those of layer k + 1
        ev.clear_layer(k + 1);
        inside_layer(grid, iso, k + 1, &mut ins[(k + 1) & 1]);
        let (lower, upper) = (&ins[k & 1], &ins[(k + 1) & 1]);
        for j in 0..d[1] - 1 {
            mixed_cubes_in_row(lower, upper, d[0], j, |i, mask| {
                let m = mask as usize;
                for p in &cases.pieces[m][..cases.count[m] as usize] {
                    let cube = [i, j, k];
                    if p.quad {
                        let q = p.edges.map(|e| ev.vertex(cube, e));
                        push_quad(&mut tris, &ev.positions, q);
                    } else {
                        let t = [0, 1, 2].map(|x| ev.vertex(cube, p.edges[x]));
                        tris.push(if p.flip { [t[0], t[2], t[1]] } else { t });
                    }
                }
            });
        }
    }
    let positions = ev.positions;
    Mesh::with_group(positions, tris, "surface")
}

/// The twelve cube edges (corner bits).
const CUBE_EDGES: [[usize; 2]; 12] = [
    [0, 1],
    [2, 3],
    [4, 5],
    [6, 7],
    [0, 2],
    [1, 3],
    [4, 6],
    [5, 7],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// Naive surface nets of `grid` at level `iso`.
///
/// One pass over the cubes: the vertex of cube `(i, j, k)` is placed, then
/// the quads dual to the sign-changing grid edges leaving node `(i, j, k)`
/// in +x, +y, +z are emitted (their four cubes precede it in scan order and
/// lie in cube layers `k - 1` and `k`).
pub fn surface_nets(grid: &ScalarGrid, iso: f64) -> Mesh {
    let d = grid.dims;
    // edge crossings, each shared by up to four cubes
    let slab = d[0] * d[1];
    let mut crossings = SlabVertices {
        sampler: Sampler::new(grid, iso),
        slabs: [vec![u32::MAX; slab << 3], vec![u32::MAX; slab << 3]],
        touched: [Vec::new(), Vec::new()],
        positions: Vec::new(),
    };
    let mut ins = [vec![0u8; d[0] * d[1]], vec![0u8; d[0] * d[1]]];
    inside_layer(grid, iso, 0, &mut ins[0]);
    // cube vertices of cube layers k - 1 and k, by layer parity
    let row = d[0] - 1;
    let layer = row * (d[1] - 1);
    let mut cube_vertex = vec![u32::MAX; 2 * layer];
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut tris = Vec::new();
    for k in 0..d[2] - 1 {
        let cur = (k & 1) * layer;
        cube_vertex[cur..cur + layer].fill(u32::MAX);
        crossings.clear_layer(k + 1);
        inside_layer(grid, iso, k + 1, &mut ins[(k + 1) & 1]);
        let (lower, upper) = (&ins[k & 1], &ins[(k + 1) & 1]);
        for j in 0..d[1] - 1 {
            mixed_cubes_in_row(lower, upper, d[0], j, |i, mask| {
                let mut sum = [0.0; 3];
                let mut cnt = 0;
                for [a, b] in CUBE_EDGES {
                    if ((mask >> a) ^ (mask >> b)) & 1 == 1 {
                        let e = CubeEdge {
                            corner: a as u8,
                            dir: (a ^ b) as u8,
                        };
                        let v = crossings.vertex([i, j, k], e) as usize;
                        let p = crossings.positions[v];
                        for x in 0..3 {
                            sum[x] += p[x];
                        }
                        cnt += 1;
                    }
                }
                cube_vertex[cur + i + row * j] = positions.len() as u32;
                positions.push(sum.map(|x| x / cnt as f64));
                let c = [i, j, k];
                let in0 = mask & 1;
                for a in 0..3 {
                    let (b, cc) = ((a + 1) % 3, (a + 2) % 3);
                    // the edge from corner 0 to corner 1 << a of this cube
                    if (mask >> (1 << a)) & 1 == in0 || c[b] == 0 || c[cc] == 0 {
                        continue;
                    }
                    let offs = [(1, 1), (0, 1), (0, 0), (1, 0)];
                    let mut q = [0u32; 4];
                    let mut ok = true;
                    for (m, (ob, oc)) in offs.iter().enumerate() {
                        let mut cu = c;
                        cu[b] -= ob;
                        cu[cc] -= oc;
                        match cube_vertex[(cu[2] & 1) * layer + cu[0] + row * cu[1]] {
                            u32::MAX => ok = false,
                            v => q[m] = v,
                        }
                    }
                    if !ok {
                        continue;
                    }
                    if in0 == 0 {
                        q = [q[0], q[3], q[2], q[1]];
                    }
                    push_quad(&mut tris, &positions, q);
                }
            });
        }
    }
    Mesh::with_group(positions, tris, "surface")
}
