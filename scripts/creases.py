#!/usr/bin/env python3
"""creases.py MESH.obj [DEG]: where a mesh creases.

Lists the edges whose two triangles' normals turn by more than DEG degrees
(default 60, issue 28's creased edge): their count and total length
relative to the mesh height, that length per pair of groups (an OBJ `g`
or `o` line names a part or transition), and the twelve sharpest edges
with their midpoints. `sketch build --json` reports the same measures per
part (`quality.parts`); this says where on the part they are.
"""
import collections
import math
import sys


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    path = sys.argv[1]
    thr = float(sys.argv[2]) if len(sys.argv) == 3 else 60.0
    verts, faces, groups, g = [], [], [], '-'
    with open(path) as f:  # a missing file, a bad number: one line, exit 1
        for no, line in enumerate(f, 1):
            p = line.split()
            if p and p[0] in ('v', 'f') and len(p) < 4:
                sys.exit(f'{path}:{no}: a `{p[0]}` line needs 3 numbers: {line.strip()}')
            if not p:
                continue
            if p[0] == 'v':
                verts.append(tuple(map(float, p[1:4])))
            elif p[0] in ('g', 'o'):
                g = p[1] if len(p) > 1 else '-'
            elif p[0] == 'f':
                idx = [int(x.split('/')[0]) for x in p[1:]]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                for k in range(1, len(idx) - 1):  # fan a polygon
                    faces.append((idx[0], idx[k], idx[k + 1]))
                    groups.append(g)
    if not verts or not faces:
        sys.exit(f'{path}: no vertices or faces')

    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1], a[2] - b[2])

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def norm(a):
        return math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)

    normals = []
    for a, b, c in faces:
        n = cross(sub(verts[b], verts[a]), sub(verts[c], verts[a]))
        length = norm(n) or 1.0
        normals.append(tuple(x / length for x in n))
    edges = collections.defaultdict(list)
    for i, f in enumerate(faces):
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            edges[(min(a, b), max(a, b))].append(i)
    ys = [v[1] for v in verts]
    h = (max(ys) - min(ys)) or 1.0
    out = []
    for (a, b), fs in edges.items():
        if len(fs) != 2:
            continue
        c = max(-1.0, min(1.0, sum(x * y for x, y in zip(normals[fs[0]], normals[fs[1]]))))
        ang = math.degrees(math.acos(c))
        if ang > thr:
            mid = tuple((verts[a][i] + verts[b][i]) / 2 for i in range(3))
            pair = '|'.join(sorted((groups[fs[0]], groups[fs[1]])))
            out.append((ang, norm(sub(verts[a], verts[b])), mid, pair))
    out.sort(reverse=True)
    print(f'height {h:.4f}; {len(out)} edges over {thr} deg, length {sum(o[1] for o in out) / h:.3f} h')
    by_group = collections.Counter()
    for o in out:
        by_group[o[3]] += o[1] / h
    for k, v in by_group.most_common(8):
        print(f'  {k}: {v:.3f} h')
    for o in out[:12]:
        print(f'  {o[0]:6.1f} deg at ({o[2][0]:.4f}, {o[2][1]:.4f}, {o[2][2]:.4f}) {o[3]}')


if __name__ == '__main__':
    try:
        main()
    except (OSError, ValueError, IndexError) as e:
        if isinstance(e, BrokenPipeError):  # `| head`
            sys.exit(0)
        sys.exit(f'creases.py: {e}')
