#!/usr/bin/env python3
"""Held-out check of `pdesculpt ode6 face --mesh`, independent of pdesculpt's
own expression code: applies a MakeHuman target (INDEX DX DY DZ, decimetres)
to the base OBJ in plain Python, runs the face rebuild on that mesh and
measures the largest and RMS distance between the input's and the output's
`v` lines.

usage: scripts/face_heldout.py PDESCULPT TARGET[.gz] [WEIGHT]
e.g.   scripts/face_heldout.py target/release/pdesculpt \
           ../shared/data/makehuman/targets/expression/mouth-part-later.target.gz
"""
import gzip, json, math, os, subprocess, sys, tempfile

BASE = os.path.join(os.path.dirname(__file__), "..", "data", "makehuman", "base.obj")


def morph(target, weight, out):
    op = gzip.open if target.endswith(".gz") else open
    d = {}
    with op(target, "rt") as f:
        for l in f:
            p = l.split()
            if len(p) == 4 and not l.startswith("#"):
                d[int(p[0])] = [float(x) for x in p[1:]]
    k = 0
    with open(BASE) as f, open(out, "w") as g:
        for l in f:
            if l.startswith("v "):
                x = [float(t) for t in l.split()[1:4]]
                if k in d:
                    x = [a + weight * b for a, b in zip(x, d[k])]
                g.write("v %.9g %.9g %.9g\n" % tuple(x))
                k += 1
            else:
                g.write(l)


def vertices(p):
    return [[float(t) for t in l.split()[1:4]] for l in open(p) if l.startswith("v ")]


def main():
    exe, target = sys.argv[1], sys.argv[2]
    weight = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
    with tempfile.TemporaryDirectory() as d:
        inp, out = os.path.join(d, "in.obj"), os.path.join(d, "out.obj")
        morph(target, weight, inp)
        r = subprocess.run([exe, "--json", "ode6", "face", "--mesh", inp, "--unit", "dm", "-o", out],
                           capture_output=True, text=True, check=True)
        rep = json.loads(r.stdout)["report"]
        a, b = vertices(inp), vertices(out)
        assert len(a) == len(b), "vertex count changed"
        dist = [math.dist(x, y) for x, y in zip(a, b)]
        moved = [x for x in dist if x > 0]
        rms = math.sqrt(sum(x * x for x in moved) / max(len(moved), 1))
        print(json.dumps({"target": os.path.basename(target), "weight": weight,
                          "measured_max": max(dist), "measured_rms": rms, "moved": len(moved),
                          "report_max": rep["max_error"], "report_rms": rep["rms_error"]}))


if __name__ == "__main__":
    main()
