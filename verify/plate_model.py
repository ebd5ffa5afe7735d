"""Paper 001 (plate bending): re-derivation of eqs 3, 9-12, 13, 16 and the
exact clamped plates used to validate the reference solver.

Writes verify/golden/plate_model.json. Run: python3 verify/plate_model.py
"""
import json
import os
import sympy as sp

u, v, x, y, r = sp.symbols("u v x y r", real=True)
q, D, a, b, E, h, mu = sp.symbols("q D a b E h mu", positive=True)


def bilap(f, s, t):
    lap = lambda g: sp.diff(g, s, 2) + sp.diff(g, t, 2)
    return sp.simplify(lap(lap(f)))


out = {}

# eq 3: rigidity with the paper's defaults E = 1e6, mu = 0.5, h = 0.1
Dexpr = E * h**3 / (12 * (1 - mu**2))
out["rigidity_default"] = float(Dexpr.subs({E: 10**6, h: sp.Rational(1, 10), mu: sp.Rational(1, 2)}))

# eqs 9-12: xi = m (u^2+v^2-1)^2; bilaplacian = 64 m, so m = q/(64 D)
m = sp.Symbol("m")
xi = m * (u**2 + v**2 - 1) ** 2
bl = bilap(xi, u, v)
assert sp.simplify(bl - 64 * m) == 0
msol = sp.solve(sp.Eq(D * bl, q), m)[0]
assert sp.simplify(msol - q / (64 * D)) == 0
w12 = (q / (64 * D)) * (u**2 + v**2 - 1) ** 2
# C1 on the unit circle (parametrised by angle)
th = sp.Symbol("th", real=True)
on = {u: sp.cos(th), v: sp.sin(th)}
for f in (w12, sp.diff(w12, u), sp.diff(w12, v)):
    assert sp.simplify(f.subs(on)) == 0
out["eq11_bilaplacian_coefficient"] = 64
out["eq12_centre_over_q_by_D"] = float(w12.subs({u: 0, v: 0}) / (q / D))  # 1/64
# golden values of eq 12 at a few points (q = 1, D = 1)
pts = [(0.0, 0.0), (0.3, -0.2), (0.5, 0.5), (-0.7, 0.1), (0.9, 0.0)]
out["eq12_samples"] = [
    {"u": pu, "v": pv, "w": float(w12.subs({q: 1, D: 1, u: pu, v: pv}))} for pu, pv in pts
]

# eq 13: projection of p onto the plane a x + b y + c z + d = 0.
A, B, C, d0 = sp.symbols("A B C d0", real=True)
px, py, pz = sp.symbols("p_x p_y p_z", real=True)
n = sp.Matrix([A, B, C])
p = sp.Matrix([px, py, pz])
correct = p - (A * px + B * py + C * pz + d0) / (A**2 + B**2 + C**2) * n
printed = p - (A * px + B * px + C * pz + d0) / (A**2 + B**2 + C**2) * n  # as printed: "b p_x"
# correct form lies on the plane and p - pbar is parallel to n
assert sp.simplify((n.T * correct)[0] + d0) == 0
assert sp.simplify((p - correct).cross(n)) == sp.zeros(3, 1)
resid_printed = sp.simplify((n.T * printed)[0] + d0)
# residual of the printed form = -B (p_x - p_y) ... != 0 whenever B != 0 and p_x != p_y
assert sp.simplify(resid_printed - B * (py - px)) == 0
case = {A: 0.3, B: 0.5, C: 0.8, d0: -0.2, px: 1.0, py: -0.5, pz: 0.25}
out["eq13_case"] = {
    "plane": [0.3, 0.5, 0.8, -0.2],
    "p": [1.0, -0.5, 0.25],
    "correct": [float(c.subs(case)) for c in correct],
    "printed": [float(c.subs(case)) for c in printed],
    "printed_plane_residual": float(resid_printed.subs(case)),
}

# eq 14: the row vector [p 1] [T][R] gives the frame coordinates
# ((p - o).vx, (p - o).vy, (p - o).vz) for any frame (R's columns are the axes)
ox, oy, oz = sp.symbols("o_x o_y o_z", real=True)
V = sp.Matrix(3, 3, sp.symbols("v0:9", real=True))  # rows: vx, vy, vz
T = sp.Matrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [-ox, -oy, -oz, 1]])
R = sp.zeros(4, 4)
for i in range(3):
    for j in range(3):
        R[i, j] = V[j, i]
R[3, 3] = 1
row = sp.Matrix([[px, py, pz, 1]]) * T * R
d = sp.Matrix([px - ox, py - oy, pz - oz])
for j in range(3):
    assert sp.expand(row[0, j] - (V[j, :] * d)[0]) == 0
assert row[0, 3] == 1
out["eq14_row_times_T_R_is_frame_coordinates"] = True

# exact clamped circular plate of radius a: w = q (a^2 - r^2)^2 / (64 D)
wc = q * (a**2 - x**2 - y**2) ** 2 / (64 * D)
assert sp.simplify(D * bilap(wc, x, y) - q) == 0
out["circle_centre_coefficient"] = 1.0 / 64.0  # w0 = q a^4 / (64 D)

# exact clamped elliptic plate (semi-axes a, b)
K = sp.Symbol("K")
we = K * (1 - x**2 / a**2 - y**2 / b**2) ** 2
Ksol = sp.solve(sp.Eq(D * bilap(we, x, y), q), K)[0]
expected = q / (D * (24 / a**4 + 16 / (a**2 * b**2) + 24 / b**4))
assert sp.simplify(Ksol - expected) == 0
for f in (we, sp.diff(we, x), sp.diff(we, y)):
    assert sp.simplify(f.subs({x: a * sp.cos(th), y: b * sp.sin(th)})) == 0
out["ellipse_centre_a1_b0p5"] = float(Ksol.subs({q: 1, D: 1, a: 1, b: sp.Rational(1, 2)}))

# eq 16: the componentwise ratios equal the radial ratio |CB|/|CD| because
# B lies on the segment C-D: B = C + t (D - C).
t, cx, cy, dx, dy = sp.symbols("t c_x c_y d_x d_y", real=True)
bx, by = cx + t * (dx - cx), cy + t * (dy - cy)
assert sp.simplify((bx - cx) / (dx - cx) - t) == 0
assert sp.simplify((by - cy) / (dy - cy) - t) == 0
out["eq16_ratio_is_radial"] = True

# Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells (1959),
# Table 35: clamped rectangular plate under uniform load, w_max = alpha q a^4 / D
# (a = shorter side).
out["timoshenko_table35"] = {"1.0": 0.00126, "1.5": 0.00220, "2.0": 0.00254}

os.makedirs(os.path.join(os.path.dirname(__file__), "golden"), exist_ok=True)
with open(os.path.join(os.path.dirname(__file__), "golden", "plate_model.json"), "w") as f:
    json.dump(out, f, indent=2)
print(json.dumps(out, indent=2))
