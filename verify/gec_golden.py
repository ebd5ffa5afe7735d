"""Golden values for the gec family (paper 000 eq 16, paper 002 eq 1).

Derives symbolically:
  * the identity of the two printed forms (theta = 2 pi v, J = N, orderings);
  * the enclosed area A = pi sum_n n (a_xn a_yn - b_xn b_yn) (Green's theorem);
  * the in-plane rotation map of the coefficient pairs;
and evaluates a fixed GEC (point, derivatives up to order 3, area, area
centroid, arc length by mpmath quadrature) into verify/golden/gec_golden.json.
"""
import json, os
import sympy as sp
import mpmath as mp

t, v, phi = sp.symbols('theta v phi', real=True)
J = 3
ax = sp.symbols('ax1:%d' % (J + 1)); bx = sp.symbols('bx1:%d' % (J + 1))
ay = sp.symbols('ay1:%d' % (J + 1)); by = sp.symbols('by1:%d' % (J + 1))
x0, y0 = sp.symbols('x0 y0')
X = x0 + sum(ax[n] * sp.cos((n + 1) * t) + bx[n] * sp.sin((n + 1) * t) for n in range(J))
Y = y0 + sum(ay[n] * sp.sin((n + 1) * t) + by[n] * sp.cos((n + 1) * t) for n in range(J))

# paper 000 eq 16 with x_{2j-1}=ax_j, x_{2j}=bx_j, y_{2j-1}=ay_j, y_{2j}=by_j
X000 = x0 + sum(ax[j - 1] * sp.cos(2 * j * sp.pi * v) + bx[j - 1] * sp.sin(2 * j * sp.pi * v) for j in range(1, J + 1))
Y000 = y0 + sum(ay[j - 1] * sp.sin(2 * j * sp.pi * v) + by[j - 1] * sp.cos(2 * j * sp.pi * v) for j in range(1, J + 1))
assert sp.simplify(X000 - X.subs(t, 2 * sp.pi * v)) == 0
assert sp.simplify(Y000 - Y.subs(t, 2 * sp.pi * v)) == 0

# area by Green's theorem
A = sp.integrate(sp.expand(sp.Rational(1, 2) * (X * sp.diff(Y, t) - Y * sp.diff(X, t))), (t, 0, 2 * sp.pi))
A_closed = sp.pi * sum((n + 1) * (ax[n] * ay[n] - bx[n] * by[n]) for n in range(J))
assert sp.simplify(A - A_closed) == 0

# rotation by phi: X' = c X - s Y, Y' = s X + c Y; read the new pairs
Xr = sp.expand(sp.cos(phi) * X - sp.sin(phi) * Y)
Yr = sp.expand(sp.sin(phi) * X + sp.cos(phi) * Y)
for n in range(J):
    k = n + 1
    cx = sp.integrate(Xr * sp.cos(k * t), (t, 0, 2 * sp.pi)) / sp.pi
    sx = sp.integrate(Xr * sp.sin(k * t), (t, 0, 2 * sp.pi)) / sp.pi
    cy = sp.integrate(Yr * sp.cos(k * t), (t, 0, 2 * sp.pi)) / sp.pi
    sy = sp.integrate(Yr * sp.sin(k * t), (t, 0, 2 * sp.pi)) / sp.pi
    assert sp.simplify(cx - (sp.cos(phi) * ax[n] - sp.sin(phi) * by[n])) == 0
    assert sp.simplify(sx - (sp.cos(phi) * bx[n] - sp.sin(phi) * ay[n])) == 0
    assert sp.simplify(cy - (sp.sin(phi) * ax[n] + sp.cos(phi) * by[n])) == 0
    assert sp.simplify(sy - (sp.sin(phi) * bx[n] + sp.cos(phi) * ay[n])) == 0

# a fixed GEC in the plane z = z_c
vals = {x0: sp.Rational(1, 10), y0: sp.Rational(-1, 20),
        ax[0]: sp.Rational(6, 5), bx[0]: sp.Rational(1, 10), ay[0]: sp.Rational(4, 5), by[0]: sp.Rational(1, 20),
        ax[1]: sp.Rational(1, 10), bx[1]: sp.Rational(-1, 20), ay[1]: sp.Rational(-1, 25), by[1]: sp.Rational(3, 50),
        ax[2]: sp.Rational(1, 50), bx[2]: sp.Rational(3, 100), ay[2]: sp.Rational(1, 100), by[2]: sp.Rational(-1, 50)}
Xn, Yn = X.subs(vals), Y.subs(vals)
theta0 = sp.Rational(7, 10)
derivs = [[float(sp.diff(Xn, t, k).subs(t, theta0)), float(sp.diff(Yn, t, k).subs(t, theta0))] for k in range(4)]
An = A_closed.subs(vals)
Cx = sp.integrate(sp.expand(Xn ** 2 / 2 * sp.diff(Yn, t)), (t, 0, 2 * sp.pi)) / An
Cy = -sp.integrate(sp.expand(Yn ** 2 / 2 * sp.diff(Xn, t)), (t, 0, 2 * sp.pi)) / An
mp.mp.dps = 30
fx = sp.lambdify(t, sp.diff(Xn, t), 'mpmath'); fy = sp.lambdify(t, sp.diff(Yn, t), 'mpmath')
L = mp.quad(lambda s: mp.sqrt(fx(s) ** 2 + fy(s) ** 2), mp.linspace(0, 2 * mp.pi, 13))

out = {
    "source": "verify/gec_golden.py (sympy %s, mpmath %s)" % (sp.__version__, mp.__version__),
    "centre": [float(vals[x0]), float(vals[y0])],
    "x": [[float(vals[ax[n]]), float(vals[bx[n]])] for n in range(J)],
    "y": [[float(vals[ay[n]]), float(vals[by[n]])] for n in range(J)],
    "z_c": 2.5,
    "theta": float(theta0),
    "derivs_xy": derivs,
    "area": float(An),
    "centroid_xy": [float(Cx), float(Cy)],
    "arc_length": float(L),
}
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, 'golden', 'gec_golden.json'), 'w') as f:
    json.dump(out, f, indent=1)
print(json.dumps(out, indent=1))
