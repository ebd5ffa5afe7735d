#!/usr/bin/env python3
"""A body mesh without its arms, for an armless side view of a real body
(docs/drawing-corpus.md, "a real body").

    python3 scripts/armless_obj.py data/makehuman/base.obj body 1.9 0.0 out.obj

Reads the OBJ's group GROUP, drops every face with a vertex farther than
HALF_WIDTH from x = 0 above height Y_MIN (the arms of a standing figure
seen from the front; the legs below Y_MIN stay), keeps the largest
connected piece, writes triangles. Units are the mesh's own (MakeHuman:
decimetres). No dependencies.
"""
import sys
from collections import Counter


def main(src, group, half_width, y_min, out):
    half_width, y_min = float(half_width), float(y_min)
    verts, faces, current = [], [], None
    for line in open(src):
        t = line.split()
        if not t:
            continue
        if t[0] == "v":
            verts.append(tuple(map(float, t[1:4])))
        elif t[0] == "g":
            current = t[1]
        elif t[0] == "f" and current == group:
            faces.append([int(x.split("/")[0]) - 1 for x in t[1:]])
    keep = [f for f in faces
            if not any(abs(verts[i][0]) > half_width and verts[i][1] > y_min for i in f)]
    parent = list(range(len(verts)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for f in keep:
        for i in f[1:]:
            ra, rb = find(f[0]), find(i)
            if ra != rb:
                parent[ra] = rb
    if not keep:
        sys.exit("no face left: check GROUP, HALF_WIDTH and Y_MIN")
    big = Counter(find(f[0]) for f in keep).most_common(1)[0][0]
    keep = [f for f in keep if find(f[0]) == big]
    with open(out, "w") as o:
        for v in verts:
            o.write("v %f %f %f\n" % v)
        for f in keep:
            for k in range(1, len(f) - 1):
                o.write("f %d %d %d\n" % (f[0] + 1, f[k] + 1, f[k + 1] + 1))
    print("%d faces kept of %d" % (len(keep), len(faces)), file=sys.stderr)


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    main(*sys.argv[1:])
