#!/usr/bin/env python3
"""pde4 (paper 000 sec 3.1, eqs 1-15, appendices A and B): derivations and goldens.

Derives, and checks symbolically or at 30 digits:
  1. the closed form of the sculpting-force projection integrals
       Is(w) = int_a^b sin(pi (x-a)/L) sin(w x) dx = pi sin(w c) sinc((beta-w) L/2) / (beta+w)
       Ic(w) = int_a^b sin(pi (x-a)/L) cos(w x) dx = pi cos(w c) sinc((beta-w) L/2) / (beta+w)
     (L = b-a, beta = pi/L, c = (a+b)/2), which give every series coefficient of
     eqs 4 and 11 for line and area forces (eqs 2, 3);
  2. the clamped cubic correction of the printed bases (eqs 7, 13);
  3. the factorisation of the mode characteristic polynomial
       a1 r^4 - a2 w^2 r^2 + a3 w^4 = a1 prod(r -+ w alpha -+ w sqrt(s)),
       q = sqrt(a3/a1), alpha^2 = (2 q + a2/a1)/4, s = alpha^2 - q;
  4. goldens: series coefficients by 30-digit quadrature (independent of 1) and
     exact clamped mode solutions (mpmath polynomial roots + 4x4 solve,
     independent of 3) for real-distinct, double and complex roots.
Writes verify/golden/pde4_derive.json.
"""
import json, os
import sympy as sp
import mpmath as mp

mp.mp.dps = 30
x, a, b, w = sp.symbols('x a b w', real=True)
out = {"script": "verify/pde4_derive.py"}

# 1. projection integrals, symbolic with generic a, b, w
L = b - a
beta = sp.pi / L
c = (a + b) / 2
def sinc(z):
    return sp.sin(z) / z
Is_cf = sp.pi * sp.sin(w * c) * sinc((beta - w) * L / 2) / (beta + w)
Ic_cf = sp.pi * sp.cos(w * c) * sinc((beta - w) * L / 2) / (beta + w)
Is_sym = sp.integrate(sp.sin(sp.pi * (x - a) / L) * sp.sin(w * x), (x, a, b), conds='none')
Ic_sym = sp.integrate(sp.sin(sp.pi * (x - a) / L) * sp.cos(w * x), (x, a, b), conds='none')
worst = 0
for (av, bv, wv) in [(sp.Rational(1, 10), sp.Rational(7, 10), 3 * sp.pi), (sp.Rational(1, 5), sp.Rational(1, 2), 2 * sp.pi),
                     (sp.Rational(3, 10), sp.Rational(9, 10), 5 * sp.pi), (0, 1, 4 * sp.pi)]:
    for e1, e2 in [(Is_cf, Is_sym), (Ic_cf, Ic_sym)]:
        d = sp.N((e1 - e2).subs({a: av, b: bv, w: wv}), 30)
        worst = max(worst, abs(float(d)))
assert worst < 1e-25, worst
out["projection_closed_form_max_err"] = worst

# 2. clamped cubic of eqs 7 and 13 (same polynomial)
u = sp.symbols('u', real=True)
mm = sp.symbols('m', integer=True, positive=True)
sg = sp.symbols('sigma')  # (-1)^m
h7 = sp.pi * mm * (-(u - 3 * u**2 + 2 * u**3) + (1 - sg) * u**2 * (u - 1))
h13 = sp.pi * mm * (-u + (2 + sg) * u**2 - (1 + sg) * u**3)
assert sp.expand(h7 - h13) == 0
B = lambda h: sp.sin(mm * sp.pi * u) + h
for h in (h7,):
    Bm = B(h)
    conds = [Bm.subs(u, 0), sp.diff(Bm, u).subs(u, 0),
             Bm.subs(u, 1).subs(sp.sin(mm * sp.pi), 0),
             sp.diff(Bm, u).subs(u, 1).subs(sp.cos(mm * sp.pi), sg)]
    assert all(sp.simplify(cc) == 0 for cc in conds), conds
out["basis_eq7_eq13_clamped"] = True

# 3. characteristic factorisation
a1, a2, a3, r, om = sp.symbols('a1 a2 a3 r omega', positive=True)
q = sp.sqrt(a3 / a1)
al = sp.sqrt((2 * q + a2 / a1) / 4)
s = al**2 - q
poly = a1 * (r**2 - 2 * al * om * r + q * om**2) * (r**2 + 2 * al * om * r + q * om**2)
assert sp.simplify(sp.expand(poly - (a1 * r**4 - a2 * om**2 * r**2 + a3 * om**4))) == 0
# roots of r^2 -+ 2 alpha w r + q w^2 are w(+-alpha +- sqrt(alpha^2 - q)) = w(+-alpha +- sqrt(s))
out["characteristic_factorisation"] = True

# 4a. series coefficients by quadrature
def proj_u(f, k):  # 2 int_0^1 f sin k pi u
    return 2 * mp.quad(lambda t: f(t) * mp.sin(k * mp.pi * t), [0, 1])
def bump(p0, p1):
    return lambda t: mp.sin(mp.pi * (t - p0) / (p1 - p0)) if p0 <= t <= p1 else mp.mpf(0)
def quad_on(f, lo, hi, g):
    return mp.quad(lambda t: f(t) * g(t), [lo, hi])
cases = []
for (u0, u1, v0, v1) in [(0.2, 0.6, 0.3, 0.7), (0.1, 0.9, 0.05, 0.35), (0.45, 0.55, 0.4, 0.5), (0.0, 1.0, 0.0, 1.0)]:
    U0, U1, V0, V1 = mp.mpf(u0), mp.mpf(u1), mp.mpf(v0), mp.mpf(v1)
    fu = bump(U0, U1)
    fv = bump(V0, V1)
    M = N = 4
    Iu = [2 * quad_on(fu, U0, U1, lambda t, k=k: mp.sin(k * mp.pi * t)) for k in range(1, M + 1)]
    # 2-sided v: constant, cos 2 n pi v, sin 2 n pi v (Fourier coefficients on [0,1])
    Jc0 = quad_on(fv, V0, V1, lambda t: 1)
    Jc = [2 * quad_on(fv, V0, V1, lambda t, n=n: mp.cos(2 * n * mp.pi * t)) for n in range(1, N + 1)]
    Js = [2 * quad_on(fv, V0, V1, lambda t, n=n: mp.sin(2 * n * mp.pi * t)) for n in range(1, N + 1)]
    # 4-sided v: sine series
    Jn = [2 * quad_on(fv, V0, V1, lambda t, n=n: mp.sin(n * mp.pi * t)) for n in range(1, N + 1)]
    f = lambda z: float(z)
    cases.append({
        "u0": u0, "u1": u1, "v0": v0, "v1": v1,
        # unit force p = 1
        "line2": {"p0": [f(I) for I in Iu],
                  "pc": [[f(I * 2 * mp.cos(2 * n * mp.pi * V0)) for n in range(1, N + 1)] for I in Iu],
                  "ps": [[f(I * 2 * mp.sin(2 * n * mp.pi * V0)) for n in range(1, N + 1)] for I in Iu]},
        "area2": {"p0": [f(I * Jc0) for I in Iu],
                  "pc": [[f(I * J) for J in Jc] for I in Iu],
                  "ps": [[f(I * J) for J in Js] for I in Iu]},
        "line4": [[f(I * 2 * mp.sin(n * mp.pi * V0)) for n in range(1, N + 1)] for I in Iu],
        "area4": [[f(I * J) for J in Jn] for I in Iu],
    })
out["series_cases"] = cases

# 4b. exact clamped mode solutions: a1 w'''' - a2 om^2 w'' + a3 om^4 w = sin(k pi u),
# w(0)=w(1)=w'(0)=w'(1)=0, general solution from the 4 polynomial roots (mpmath).
modes = []
for (A1, A2, A3, n, k) in [(1, 3, 1, 1, 1), (1, 2, 1, 1, 1), (1, 0.5, 1, 1, 2), (2, -1, 1, 2, 3), (1, 2, 1, 0, 1), (0.3, 0.3, 0.3, 1, 2)]:
    A1, A2, A3 = mp.mpf(A1), mp.mpf(A2), mp.mpf(A3)
    W = 2 * n * mp.pi
    K = k * mp.pi
    amp = 1 / (A1 * K**4 + A2 * K**2 * W**2 + A3 * W**4)
    if n == 0:
        basis = [lambda t, j=j: t**j for j in range(4)]
        dbasis = [lambda t, j=j: j * t**(j - 1) if j > 0 else mp.mpf(0) for j in range(4)]
    else:
        roots = mp.polyroots([A1, 0, -A2 * W**2, 0, A3 * W**4], maxsteps=200, extraprec=60)
        # double roots: perturbation-free treatment with t e^{rt}
        rs = []
        for rr in roots:
            mult = sum(1 for q2 in rs if abs(q2[0] - rr) < mp.mpf(10)**-10)
            rs.append((rr, mult))
        basis = [lambda t, rr=rr, mu=mu: t**mu * mp.exp(rr * t) for rr, mu in rs]
        dbasis = [lambda t, rr=rr, mu=mu: (mu * t**(mu - 1) if mu else 0) * mp.exp(rr * t) + t**mu * rr * mp.exp(rr * t) for rr, mu in rs]
    wp = lambda t: amp * mp.sin(K * t)
    dwp = lambda t: amp * K * mp.cos(K * t)
    Amat = mp.matrix([[bf(0) for bf in basis], [bf(1) for bf in basis], [df(0) for df in dbasis], [df(1) for df in dbasis]])
    rhs = mp.matrix([-wp(0), -wp(1), -dwp(0), -dwp(1)])
    coef = mp.lu_solve(Amat, rhs)
    sol = lambda t: mp.re(wp(t) + sum(coef[i] * basis[i](t) for i in range(4)))
    pts = [0.1, 0.25, 0.5, 0.8]
    modes.append({"a1": float(A1), "a2": float(A2), "a3": float(A3), "n": n, "k": k,
                  "u": pts, "w": [float(sol(mp.mpf(t))) for t in pts]})
out["mode_solutions"] = modes

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "golden", "pde4_derive.json")
with open(path, "w") as fh:
    json.dump(out, fh, indent=1)
print("wrote", path)
