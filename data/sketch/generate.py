#!/usr/bin/env python3
"""Draws the bundled sketch examples as data (committed SVG and JSON).

Model units are metres. The page's width and height are in cm, one user
unit of the viewBox per metre (so the drawing's physical size is the
model's), and model y = -svg y;
in a front view svg x is model x, in a side view svg x is model z (front of
the body at +z). Each outline is a smooth closed curve: a centripetal
Catmull-Rom spline through hand-placed key points of the right half (front)
or the whole outline (side), sampled densely and written as one closed path.

Run from the repository root: python3 data/sketch/generate.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def catmull_rom(points, closed, per_seg=10):
    pts = list(points)
    n = len(pts)
    out = []
    segs = n if closed else n - 1
    for i in range(segs):
        p0 = pts[(i - 1) % n] if (closed or i > 0) else pts[0]
        p1 = pts[i]
        p2 = pts[(i + 1) % n]
        p3 = pts[(i + 2) % n] if (closed or i + 2 < n) else pts[-1]

        def tj(ti, a, b):
            d = math.hypot(b[0] - a[0], b[1] - a[1])
            return ti + max(d, 1e-9) ** 0.5

        t0 = 0.0
        t1 = tj(t0, p0, p1)
        t2 = tj(t1, p1, p2)
        t3 = tj(t2, p2, p3)
        for k in range(per_seg):
            t = t1 + (t2 - t1) * k / per_seg

            def lerp(a, b, ta, tb):
                if tb == ta:
                    return a
                return tuple(((tb - t) * a[j] + (t - ta) * b[j]) / (tb - ta) for j in range(2))

            a1 = lerp(p0, p1, t0, t1)
            a2 = lerp(p1, p2, t1, t2)
            a3 = lerp(p2, p3, t2, t3)
            b1 = lerp(a1, a2, t0, t2)
            b2 = lerp(a2, a3, t1, t3)
            out.append(lerp(b1, b2, t1, t2))
    if not closed:
        out.append(pts[-1])
    return out


def mirror_front(half):
    """half: right-half key points from the head top (x = 0) down to the
    crotch (x = 0). Returns the whole closed outline, counter-clockwise."""
    right = catmull_rom(half, closed=False, per_seg=8)
    left = [(-x, y) for (x, y) in reversed(right[1:-1])]
    ring = right + left  # clockwise (top, down the right side, ...)
    return list(reversed(ring))


def write_svg(path, pts, cuts=()):
    d = "M " + " L ".join(f"{x:.5f},{-y:.5f}" for x, y in pts) + " Z"
    xs = [p[0] for p in pts]
    ys = [-p[1] for p in pts]
    pad = 0.05
    x0, x1, y0, y1 = min(xs) - pad, max(xs) + pad, min(ys) - pad, max(ys) + pad
    body = [
        '<svg xmlns="http://www.w3.org/2000/svg" '
        f'width="{100 * float(f"{x1 - x0:.4f}"):.2f}cm" height="{100 * float(f"{y1 - y0:.4f}"):.2f}cm" '
        f'viewBox="{x0:.4f} {y0:.4f} {x1 - x0:.4f} {y1 - y0:.4f}">',
        f'  <path id="outline" d="{d}" fill="none" stroke="black" stroke-width="0.003"/>',
    ]
    for cid, c in cuts:
        cd = "M " + " L ".join(f"{x:.5f},{-y:.5f}" for x, y in c)
        body.append(f'  <path id="{cid}" d="{cd}" fill="none" stroke="red" stroke-width="0.003"/>')
    body.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(body) + "\n")


def slice_x(pts, y):
    xs = []
    n = len(pts)
    for i in range(n):
        a, b = pts[i], pts[(i + 1) % n]
        lo, hi = (a, b) if a[1] < b[1] else (b, a)
        if lo[1] <= y < hi[1]:
            t = (y - lo[1]) / (hi[1] - lo[1])
            xs.append(lo[0] + t * (hi[0] - lo[0]))
    xs.sort()
    return list(zip(xs[0::2], xs[1::2]))


def section(front, side, y, cx_pick, bumps, m=48):
    """A key cross section at height y: a rounded curve with front bumps,
    scaled to the front width and the side depth there (points (x, z))."""
    iv = [iv for iv in slice_x(front, y) if abs(0.5 * (iv[0] + iv[1]) - cx_pick) < 0.1][0]
    sv = slice_x(side, y)
    z0, z1 = sv[0][0], sv[-1][1]
    raw = []
    for k in range(m):
        t = 2 * math.pi * k / m
        x = math.cos(t)
        z = math.sin(t)
        for (amp, width, centre) in bumps:
            d = math.atan2(math.sin(t - centre), math.cos(t - centre))
            z += amp * math.exp(-(d / width) ** 2) * max(math.sin(t), 0.0)
        raw.append((x, z))
    rx0, rx1 = min(p[0] for p in raw), max(p[0] for p in raw)
    rz0, rz1 = min(p[1] for p in raw), max(p[1] for p in raw)
    out = []
    for x, z in raw:
        X = iv[0] + (x - rx0) / (rx1 - rx0) * (iv[1] - iv[0])
        Z = z0 + (z - rz0) / (rz1 - rz0) * (z1 - z0)
        out.append([round(X, 6), round(Z, 6)])
    return out


FEMALE_FRONT = [
    (0.0, 1.70), (0.055, 1.685), (0.075, 1.62), (0.072, 1.55), (0.05, 1.50),
    (0.045, 1.46), (0.05, 1.43), (0.09, 1.405), (0.15, 1.385), (0.185, 1.36),
    (0.205, 1.32), (0.235, 1.20), (0.27, 1.08), (0.31, 0.96), (0.335, 0.88),
    (0.355, 0.82), (0.355, 0.77), (0.335, 0.745), (0.315, 0.77), (0.305, 0.84),
    (0.285, 0.92), (0.245, 1.04), (0.205, 1.15), (0.172, 1.245), (0.155, 1.235),
    (0.15, 1.17), (0.13, 1.07), (0.14, 0.98), (0.175, 0.90), (0.18, 0.82),
    (0.165, 0.70), (0.135, 0.55), (0.125, 0.47), (0.13, 0.38), (0.10, 0.20),
    (0.085, 0.09), (0.09, 0.035), (0.075, 0.0), (0.05, 0.0), (0.035, 0.03),
    (0.04, 0.10), (0.04, 0.25), (0.03, 0.40), (0.03, 0.50), (0.022, 0.65),
    (0.012, 0.75), (0.0, 0.79),
]

FEMALE_SIDE = [
    (0.0, 1.70), (0.06, 1.68), (0.09, 1.62), (0.095, 1.56), (0.07, 1.50),
    (0.05, 1.45), (0.06, 1.38), (0.10, 1.27), (0.12, 1.20), (0.085, 1.12),
    (0.075, 1.05), (0.085, 0.95), (0.075, 0.85), (0.07, 0.70), (0.05, 0.50),
    (0.05, 0.40), (0.04, 0.20), (0.035, 0.08), (0.05, 0.02), (0.03, 0.0),
    (-0.03, 0.0), (-0.045, 0.03), (-0.04, 0.10), (-0.06, 0.30), (-0.055, 0.42),
    (-0.06, 0.55), (-0.075, 0.72), (-0.11, 0.85), (-0.115, 0.92), (-0.085, 1.03),
    (-0.09, 1.15), (-0.10, 1.28), (-0.07, 1.40), (-0.055, 1.46), (-0.075, 1.52),
    (-0.095, 1.58), (-0.08, 1.66), (-0.05, 1.69),
]

MALE_FRONT = [
    (0.0, 1.80), (0.06, 1.785), (0.08, 1.72), (0.078, 1.64), (0.058, 1.58),
    (0.056, 1.54), (0.065, 1.51), (0.12, 1.49), (0.19, 1.465), (0.225, 1.44),
    (0.245, 1.39), (0.27, 1.27), (0.30, 1.14), (0.335, 1.02), (0.36, 0.94),
    (0.375, 0.88), (0.375, 0.82), (0.355, 0.795), (0.335, 0.82), (0.325, 0.90),
    (0.305, 0.98), (0.27, 1.10), (0.235, 1.21), (0.202, 1.315), (0.18, 1.30),
    (0.17, 1.22), (0.15, 1.10), (0.15, 1.00), (0.16, 0.92), (0.165, 0.85),
    (0.155, 0.72), (0.135, 0.57), (0.125, 0.49), (0.13, 0.40), (0.10, 0.21),
    (0.09, 0.09), (0.095, 0.035), (0.08, 0.0), (0.05, 0.0), (0.035, 0.03),
    (0.04, 0.10), (0.04, 0.26), (0.03, 0.42), (0.032, 0.52), (0.025, 0.68),
    (0.012, 0.80), (0.0, 0.84),
]

MALE_SIDE = [
    (0.0, 1.80), (0.065, 1.78), (0.095, 1.72), (0.10, 1.65), (0.075, 1.58),
    (0.055, 1.53), (0.07, 1.45), (0.115, 1.33), (0.12, 1.25), (0.10, 1.15),
    (0.10, 1.05), (0.09, 0.95), (0.08, 0.85), (0.075, 0.72), (0.05, 0.52),
    (0.055, 0.42), (0.04, 0.21), (0.035, 0.08), (0.05, 0.02), (0.03, 0.0),
    (-0.03, 0.0), (-0.045, 0.03), (-0.04, 0.10), (-0.065, 0.32), (-0.06, 0.44),
    (-0.065, 0.58), (-0.08, 0.75), (-0.105, 0.88), (-0.10, 0.98), (-0.09, 1.08),
    (-0.10, 1.22), (-0.11, 1.36), (-0.075, 1.48), (-0.06, 1.54), (-0.085, 1.60),
    (-0.10, 1.67), (-0.085, 1.76), (-0.05, 1.79),
]


# A four-legged animal. Its primary profile (the "front" file: the view
# along z, model x-y plane) is its lateral silhouette, head toward +x, all
# four legs visible apart (a walking pose); its secondary profile (the "side"
# file: the view along x, model z-y plane) is the animal seen head-on, legs
# apart in z (its left at -z). The back is domed between the tail base and
# the withers so that tail, back and neck separate going up. Clockwise key
# points from the tail tip (reversed to counter-clockwise below).
ANIMAL_FRONT = [
    (-0.575, 0.795), (-0.545, 0.79), (-0.52, 0.74), (-0.47, 0.665), (-0.42, 0.615),  # tail upper edge
    (-0.36, 0.60), (-0.31, 0.635), (-0.18, 0.67), (0.0, 0.685),  # tail base, back
    (0.14, 0.67), (0.22, 0.64), (0.27, 0.62),  # withers
    (0.32, 0.68), (0.355, 0.75), (0.38, 0.81), (0.41, 0.865), (0.46, 0.90),  # neck, skull
    (0.52, 0.90), (0.57, 0.875), (0.605, 0.84), (0.62, 0.815), (0.60, 0.79),  # muzzle
    (0.56, 0.78), (0.535, 0.745), (0.52, 0.68), (0.51, 0.60), (0.50, 0.50), (0.48, 0.42),  # jaw, throat, chest
    (0.465, 0.34), (0.46, 0.20), (0.46, 0.07), (0.45, 0.01), (0.415, 0.0),  # front leg (right)
    (0.38, 0.01), (0.37, 0.07), (0.37, 0.20), (0.365, 0.31), (0.35, 0.335),
    (0.335, 0.31), (0.33, 0.20), (0.33, 0.07), (0.32, 0.01), (0.285, 0.0),  # front leg (left)
    (0.25, 0.01), (0.24, 0.07), (0.24, 0.20), (0.235, 0.30),
    (0.20, 0.335), (0.10, 0.34), (0.0, 0.34), (-0.10, 0.34), (-0.16, 0.335),  # belly
    (-0.19, 0.30), (-0.19, 0.20), (-0.19, 0.07), (-0.20, 0.01), (-0.235, 0.0),  # hind leg (left)
    (-0.27, 0.01), (-0.28, 0.07), (-0.28, 0.20), (-0.285, 0.31), (-0.30, 0.335),
    (-0.315, 0.31), (-0.32, 0.20), (-0.32, 0.07), (-0.33, 0.01), (-0.365, 0.0),  # hind leg (right)
    (-0.40, 0.01), (-0.41, 0.07), (-0.42, 0.20), (-0.43, 0.32),
    (-0.45, 0.42), (-0.465, 0.50), (-0.475, 0.57), (-0.505, 0.64),  # haunch, rump, tail underside
    (-0.55, 0.71), (-0.585, 0.77),
]

# Head-on (z, y): right half from the head top (z = 0) down to between the
# legs (z = 0); mirrored.
ANIMAL_SIDE_HALF = [
    (0.0, 0.90), (0.05, 0.89), (0.07, 0.84), (0.065, 0.78), (0.075, 0.72),  # head
    (0.10, 0.66), (0.13, 0.62), (0.145, 0.55), (0.145, 0.47), (0.125, 0.39),  # neck, body
    (0.105, 0.34), (0.10, 0.30), (0.10, 0.20), (0.10, 0.07), (0.095, 0.01), (0.065, 0.0),  # leg
    (0.035, 0.01), (0.03, 0.07), (0.03, 0.20), (0.027, 0.30), (0.0, 0.325),
]


def make_animal():
    front = catmull_rom(list(reversed(ANIMAL_FRONT)), closed=True, per_seg=8)
    side = mirror_front(ANIMAL_SIDE_HALF)
    write_svg(os.path.join(HERE, "animal_front.svg"), front)
    write_svg(os.path.join(HERE, "animal_side.svg"), side)
    # key sections of the body (x along the animal, z across): a flatter
    # belly and a ridge along the spine
    secs = [
        {"part": "body", "y": y, "points": section(front, side, y, 0.0, bumps)}
        for (y, bumps) in [(0.50, [(0.08, 0.6, 1.5708)])]
    ]
    with open(os.path.join(HERE, "animal_sections.json"), "w") as f:
        json.dump({"sections": secs}, f, indent=1)
        f.write("\n")


def make(name, front_half, side_keys, sections):
    front = mirror_front(front_half)
    side = catmull_rom(side_keys, closed=True, per_seg=8)
    side = list(reversed(side))  # counter-clockwise in (z, y)
    write_svg(os.path.join(HERE, f"{name}_front.svg"), front)
    write_svg(os.path.join(HERE, f"{name}_side.svg"), side)
    secs = []
    for (part, y, bumps) in sections:
        secs.append({"part": part, "y": y, "points": section(front, side, y, 0.0, bumps)})
    with open(os.path.join(HERE, f"{name}_sections.json"), "w") as f:
        json.dump({"sections": secs}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    make(
        "female",
        FEMALE_FRONT,
        FEMALE_SIDE,
        [
            ("torso", 1.18, [(0.35, 0.5, 1.15), (0.35, 0.5, 1.99)]),
            ("torso", 1.06, []),
            ("torso", 0.92, [(-0.25, 0.6, 1.5708)]),
        ],
    )
    make_animal()
    make(
        "male",
        MALE_FRONT,
        MALE_SIDE,
        [
            ("torso", 1.24, [(0.15, 0.6, 1.2), (0.15, 0.6, 1.94)]),
            ("torso", 1.08, []),
            ("torso", 0.95, []),
        ],
    )
