"""SymPy derivation of the curve-network constructions (paper 004 secs 5, 6.2)
used by src/ode6/network: golden weights for tests/it/ode6_network.rs.

1. Section stencils. A u-strip's sections S_k sit at u = k (one unit per
   patch). The cross derivatives at a section are the derivatives of the
   quadratic through three neighbouring sections: central inside,
   one-sided at the strip's ends, and the chord for a strip of one patch.
   Each weight set is exact for quadratics in u and is what the patches at
   a u-edge share (eqs 23-25).
2. The 3-sided patch. Its u = 0 side is collapsed: c1(v) = A (the apex).
   With the one-sided stencil on the sections (A, S1(v), S2(v)) at u = 0,
   1, 2, c2(v) = (-3A + 4 S1(v) - S2(v))/2 and c3(v) = A - 2 S1(v) + S2(v).
   For sections that are circles about the apex's axis growing linearly
   and quadratically with u (a paraboloid of revolution, exactly
   quadratic in u), c2 is the radial direction times the growth rate and
   c3 the axial curvature, for every v: the collapsed patch is then the
   polar parameterisation of the surface; the script checks this
   symbolically.
3. The face's column stencils (src/face/template.rs) at spacing h = 1/2
   in s with one column = 1 unit of u: derivatives per unit of u.
"""
import json, os
import sympy as sp

u = sp.symbols('u')
a, b, c = sp.symbols('a b c')
f = a + b * u + c * u**2


def weights(nodes, at):
    """Weights w_k with sum w_k f(nodes_k) = f'(at) and f''(at), exact for quadratics."""
    w = sp.symbols('w0:%d' % len(nodes))
    out = []
    for order in (1, 2):
        target = sp.diff(f, u, order).subs(u, at)
        expr = sum(wk * f.subs(u, n) for wk, n in zip(w, nodes)) - target
        eqs = [sp.expand(expr).coeff(s) for s in (a, b, c)]
        sol = sp.solve(eqs, w, dict=True)[0]
        out.append([float(sol.get(wk, 0)) for wk in w])
    return out

stencils = {
    'central': {'nodes': [-1, 0, 1], 'at': 0},
    'first': {'nodes': [0, 1, 2], 'at': 0},
    'last': {'nodes': [0, -1, -2], 'at': 0},
}
golden = {'source': 'verify/ode6_network.py', 'stencils': {}}
for name, s in stencils.items():
    d1, d2 = weights(s['nodes'], s['at'])
    golden['stencils'][name] = {'offsets': s['nodes'], 'first': d1, 'second': d2}

# 2. the collapsed side on a paraboloid of revolution z = k r^2, r = g u
g, k, v = sp.symbols('g k v', positive=True)
th = 2 * sp.pi * v
def S(uu):
    r = g * uu
    return sp.Matrix([r * sp.cos(th), r * sp.sin(th), k * r**2])
A, S1, S2 = S(0), S(1), S(2)
c2 = (-3 * A + 4 * S1 - S2) / 2
c3 = A - 2 * S1 + S2
exact_c2 = sp.diff(S(u), u).subs(u, 0)
exact_c3 = sp.diff(S(u), u, 2).subs(u, 0)
assert sp.simplify(c2 - exact_c2) == sp.zeros(3, 1)
assert sp.simplify(c3 - exact_c3) == sp.zeros(3, 1)
golden['three_sided'] = {
    'surface': 'paraboloid of revolution z = k r^2, r = g u, theta = 2 pi v',
    'c2_matches_polar_radius': True,
    'c3_matches_axial_curvature': True,
}

# 3. face column stencils: s-spacing h = 1/(2 nu), one column 1/nu in s:
# per unit u the spacing is 1/2
hs = sp.Rational(1, 2)
d1, d2 = weights([-hs, 0, hs], 0)
e1, e2 = weights([0, hs, 2 * hs], 0)
golden['face_columns'] = {
    'spacing_u': 0.5,
    'central': {'first': d1, 'second': d2},
    'first': {'first': e1, 'second': e2},
}
out = os.path.join(os.path.dirname(__file__), 'golden', 'ode6_network.json')
with open(out, 'w') as fh:
    json.dump(golden, fh, indent=1)
print('wrote', out)
