#!/usr/bin/env python3
"""MakeHuman's base mesh with one target applied, for a real body of
other proportions (docs/drawing-corpus.md, "real bodies").

    python3 scripts/morph_obj.py data/makehuman/base.obj \
        data/makehuman/targets/macrodetails/caucasian-male-young.target.gz out.obj

A target file holds lines "vertex dx dy dz" (gzip), added to the OBJ's
vertices in order (weight 1); everything else is copied. The result feeds
scripts/armless_obj.py like base.obj. No dependencies.
"""
import gzip
import sys


def main(base, target, out):
    offsets = {}
    try:
        for n, line in enumerate(gzip.open(target, "rt"), 1):
            p = line.split()
            if p and not line.startswith("#"):
                if len(p) != 4:
                    sys.exit(f"{target}:{n}: expected 'vertex dx dy dz', got {line.strip()[:60]!r}")
                offsets[int(p[0])] = tuple(map(float, p[1:]))
    except (OSError, EOFError, ValueError) as e:
        sys.exit(f"{target}: not a readable gzip target file ({e})")
    if not offsets:
        sys.exit(f"{target}: no vertex offsets in it")
    index = 0
    with open(out, "w") as f:
        for line in open(base):
            if line.startswith("v "):
                v = list(map(float, line.split()[1:4]))
                d = offsets.get(index, (0.0, 0.0, 0.0))
                f.write("v %.6f %.6f %.6f\n" % tuple(v[k] + d[k] for k in range(3)))
                index += 1
            else:
                f.write(line)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
