"""Closed form of the sixth-order PDE of paper 002 (eq 2) per harmonic.

    d^6 w/du^6 + a d^6 w/dv^6 = 0,   w = A_n(u) cos(n v) (or sin(n v))

gives A_n^(6)(u) - a n^6 A_n(u) = 0 (d^6/dv^6 cos nv = -n^6 cos nv), so the
characteristic equation is r^6 = a n^6. This script

  1. derives the six roots for a > 0, a < 0 and a = 0 (and n = 0) and checks
     that every basis function of the end-centred stable basis used by
     pdesculpt::pde6 solves the ODE (and the PDE with cos/sin n v) exactly;
  2. checks the bases printed in appendix A: the a < 0 basis (eq 8/A16) is
     right; the a > 0 basis (eq 7/A12) is NOT: it takes q0 = n a^(1/6) as a
     triple root of r^3 = n^3 sqrt(a), but the three cube roots are distinct,
     so (c0 + c1 u + c2 u^2) e^(q0 u) leaves a nonzero residual;
  3. writes golden values (mpmath, 40 digits) of the single-harmonic
     interpolant that takes six values at u = 0, 0.2, ..., 1 (eqs 21-23), of
     the method-2 interpolant (four values at u = 0, 1/3, 2/3, 1 plus the
     first and second derivatives at u = 1, eqs 24-25, A34-A36), and the
     Lebesgue constants of the six-point interpolation (intrinsic to the
     function space, independent of the basis).

Run: python3 verify/pde6_closed_form.py  (writes verify/golden/pde6_closed_form.json)
"""
import json
import os

import mpmath as mp
import sympy as sp

u, v = sp.symbols("u v", real=True)
q = sp.symbols("q", positive=True)  # q = n |a|^(1/6)
c = sp.symbols("c0:6")


def stable_basis(kind, q, u):
    """The end-centred basis of pdesculpt::pde6 (kind: 'neg', 'pos', 'poly')."""
    if kind == "poly":
        t = 2 * u - 1
        return [t**k for k in range(6)]
    if kind == "neg":  # roots +-i q, q(+-sqrt3/2 +- i/2)
        s, h = sp.sqrt(3) * q / 2, q / 2
        return [sp.cos(q * u), sp.sin(q * u),
                sp.exp(-s * u) * sp.cos(h * u), sp.exp(-s * u) * sp.sin(h * u),
                sp.exp(s * (u - 1)) * sp.cos(h * (u - 1)), sp.exp(s * (u - 1)) * sp.sin(h * (u - 1))]
    # pos: roots +-q, q(+-1/2 +- i sqrt3/2)
    s, h = q / 2, sp.sqrt(3) * q / 2
    return [sp.exp(-q * u), sp.exp(q * (u - 1)),
            sp.exp(-s * u) * sp.cos(h * u), sp.exp(-s * u) * sp.sin(h * u),
            sp.exp(s * (u - 1)) * sp.cos(h * (u - 1)), sp.exp(s * (u - 1)) * sp.sin(h * (u - 1))]


def roots():
    """Roots of r^6 = a n^6 in units of q = n |a|^(1/6)."""
    r = sp.symbols("r")
    pos = sorted(sp.solve(r**6 - 1, r), key=lambda z: (sp.re(z), sp.im(z)))
    neg = sorted(sp.solve(r**6 + 1, r), key=lambda z: (sp.re(z), sp.im(z)))
    return [str(sp.nsimplify(z)) for z in pos], [str(sp.nsimplify(z)) for z in neg]


def ode_residuals():
    out = {}
    for kind, sign in (("neg", -1), ("pos", 1), ("poly", 0)):
        # A^(6) - a n^6 A with a n^6 = sign * q^6
        res = [sp.simplify(sp.diff(f, u, 6) - sign * q**6 * f) for f in stable_basis(kind, q, u)]
        out[kind] = [str(x) for x in res]
        assert all(x == 0 for x in res), (kind, res)
        # and the full PDE for w = f(u) cos(n v), a = sign q^6 / n^6
        n = sp.symbols("n", positive=True, integer=True)
        a = sign * q**6 / n**6
        for f in stable_basis(kind, q, u):
            w = f * sp.cos(n * v)
            pde = sp.simplify(sp.diff(w, u, 6) + a * sp.diff(w, v, 6))
            assert pde == 0, (kind, f, pde)
    return out


def paper_bases():
    """Appendix A bases as printed (lost minus signs restored where the text
    is unambiguous: the e^(-q u) factors of the second group)."""
    q0 = q
    paper_pos = [sp.exp(q0 * u), u * sp.exp(q0 * u), u**2 * sp.exp(q0 * u),
                 sp.exp(-q0 * u), u * sp.exp(-q0 * u), u**2 * sp.exp(-q0 * u)]
    q1, q2 = sp.sqrt(3) * q / 2, q / 2
    paper_neg = [sp.cos(2 * q2 * u), sp.sin(2 * q2 * u),
                 sp.exp(q1 * u) * sp.cos(q2 * u), sp.exp(q1 * u) * sp.sin(q2 * u),
                 sp.exp(-q1 * u) * sp.cos(q2 * u), sp.exp(-q1 * u) * sp.sin(q2 * u)]
    pos_res = [sp.simplify(sp.diff(f, u, 6) - q**6 * f) for f in paper_pos]
    neg_res = [sp.simplify(sp.diff(f, u, 6) + q**6 * f) for f in paper_neg]
    assert all(x == 0 for x in neg_res)
    assert any(x != 0 for x in pos_res)
    # residual of u^k e^(q0 u) at q = 1, u = 0.5 (numbers Rust can compare)
    pos_num = [float(x.subs({q: 1, u: sp.Rational(1, 2)})) for x in pos_res]
    return {
        "paper_pos_residual_exprs": [str(x) for x in pos_res],
        "paper_pos_residual_q1_u05": pos_num,
        "paper_neg_residual_exprs": [str(x) for x in neg_res],
    }


mp.mp.dps = 40


def mp_basis(kind, qv, x, d=0):
    """d-th derivative of the stable basis at x (mpmath, via sympy lambdify)."""
    fs = stable_basis(kind, q, u)
    return [mp.mpf(sp.N(sp.diff(f, u, d).subs({q: qv, u: x}), 45)) for f in fs]


def solve_mode(kind, qv, rows, rhs):
    m = mp.matrix([[mp.mpf(x) for x in r] for r in rows])
    b = mp.matrix([mp.mpf(x) for x in rhs])
    return mp.lu_solve(m, b)


def interp_case(kind, qv, values, at):
    nodes = [sp.Rational(i, 5) for i in range(6)]
    rows = [mp_basis(kind, qv, x) for x in nodes]
    coef = solve_mode(kind, qv, rows, values)
    out = []
    for x in at:
        vals = []
        for d in range(3):
            b = mp_basis(kind, qv, sp.Rational(x), d)
            vals.append(float(sum(ci * bi for ci, bi in zip(coef, b))))
        out.append(vals)
    return out


def method2_case(kind, qv, values4, d1, d2, at):
    nodes = [sp.Rational(i, 3) for i in range(4)]
    rows = [mp_basis(kind, qv, x) for x in nodes]
    rows.append(mp_basis(kind, qv, 1, 1))
    rows.append(mp_basis(kind, qv, 1, 2))
    coef = solve_mode(kind, qv, rows, list(values4) + [d1, d2])
    out = []
    for x in at:
        vals = []
        for d in range(3):
            b = mp_basis(kind, qv, sp.Rational(x), d)
            vals.append(float(sum(ci * bi for ci, bi in zip(coef, b))))
        out.append(vals)
    return out


def lebesgue(kind, qv, samples=101):
    nodes = [sp.Rational(i, 5) for i in range(6)]
    m = mp.matrix([mp_basis(kind, qv, x) for x in nodes])
    minv = mp.inverse(m)
    best = mp.mpf(0)
    for k in range(samples):
        b = mp_basis(kind, qv, sp.Rational(k, samples - 1))
        # cardinal functions l_i(x) = sum_j b_j Minv[j, i]
        s = sum(abs(sum(b[j] * minv[j, i] for j in range(6))) for i in range(6))
        best = max(best, s)
    return float(best)


def method2_amplification():
    """Method 2 as a recursion: a quintic patch with zero values at
    0, 1/3, 2/3, 1 and slope s, curvature k at u = 0 has slope/curvature
    T (s, k) at u = 1; the spectral radius of T is the growth per patch."""
    c = sp.symbols("c0:6")
    s, k = sp.symbols("s k")
    A = sum(ci * u**i for i, ci in enumerate(c))
    eqs = [A.subs(u, x) for x in (0, sp.Rational(1, 3), sp.Rational(2, 3), 1)]
    eqs += [sp.diff(A, u).subs(u, 0) - s, sp.diff(A, u, 2).subs(u, 0) - k]
    A1 = A.subs(sp.solve(eqs, c))
    T = sp.Matrix([[sp.diff(sp.diff(A1, u, d).subs(u, 1), x) for x in (s, k)] for d in (1, 2)])
    ev = list(T.eigenvals().keys())
    rho = max(abs(sp.N(e, 30)) for e in ev)
    return {"method2_T_quintic": [[str(x) for x in r] for r in T.tolist()],
            "method2_eigenvalues_quintic": [str(e) for e in ev],
            "method2_amplification_quintic": float(rho)}


def main():
    pos_roots, neg_roots = roots()
    out = {
        "roots_pos_over_q": pos_roots,
        "roots_neg_over_q": neg_roots,
        "ode_residuals": ode_residuals(),
        **paper_bases(),
        **method2_amplification(),
    }
    values = ["0.3", "-1.2", "0.7", "2.0", "-0.4", "1.1"]
    at = ["0.1", "0.5", "0.93"]
    cases = []
    # (a, n) pairs: q = n |a|^(1/6)
    for a, n in ((-1.0, 1), (-1.0, 4), (-0.5, 10), (2.0, 3), (1.0, 1), (1e-3, 20), (0.0, 5), (-1.0, 0)):
        kind = "poly" if a == 0 or n == 0 else ("neg" if a < 0 else "pos")
        qv = mp.mpf(n) * mp.root(mp.mpf(abs(a)), 6) if kind != "poly" else mp.mpf(0)
        cases.append({
            "a": a, "n": n, "kind": kind, "values": [float(x) for x in values], "at": [float(x) for x in at],
            "interp": interp_case(kind, qv, values, at),
            "method2": method2_case(kind, qv, values[:4], "0.8", "-2.5", at),
        })
    out["cases"] = cases
    out["method2_d1"] = 0.8
    out["method2_d2"] = -2.5
    leb = []
    for kind in ("neg", "pos"):
        for qv in (1, 5, 10, 20, 40):
            leb.append({"kind": kind, "q": qv, "lebesgue": lebesgue(kind, mp.mpf(qv))})
    leb.append({"kind": "poly", "q": 0, "lebesgue": lebesgue("poly", mp.mpf(0))})
    out["lebesgue"] = leb
    path = os.path.join(os.path.dirname(__file__), "golden", "pde6_closed_form.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print("wrote", path)
    for l in leb:
        print(l)


if __name__ == "__main__":
    main()
