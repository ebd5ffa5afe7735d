#!/usr/bin/env python3
"""Paper 004 (sixth-order ODE surfaces): independent derivation and goldens.

1. SymPy: eq 18 solves eq 8 when xi^2 = -q, q a root of eq 13; the roots of
   the characteristic polynomial r^2 (rho r^4 + eta r^2 + lambda) in every case.
2. mpmath (60 digits): the basis functions g_1..g_6 of eq 19 for every
   parameter case from the matrix exponential of the companion matrix (no case
   analysis at all, valid for repeated roots), values and first two
   derivatives at sample u -> golden for the Rust bases.
3. A parameter set where the boundary system is singular (a "buckling"
   combination of a repeated oscillatory root) -> golden.
4. The printed constants of eqs 20-22, with the minus signs the extraction
   lost restored in every sign-ambiguous place; for each g_k the best
   reconstruction's boundary-constraint error is reported.
5. Difference formulas of eqs 4-7: Taylor limits of the printed c3 and c6.

Writes verify/golden/ode6_basis.json. Runs in a few seconds.
"""
import json, itertools, os
import sympy as sp
import mpmath as mp

mp.mp.dps = 60
OUT = os.path.join(os.path.dirname(__file__), "golden", "ode6_basis.json")

# ---------- 1. symbolic: eq 18 solves eq 8 ----------
u, x1, x2, rho, eta, lam = sp.symbols("u xi1 xi2 rho eta lambda", positive=True)
b = sp.symbols("b1:7")
S = b[0]*sp.cos(x1*u) + b[1]*sp.sin(x1*u) + b[2]*sp.cos(x2*u) + b[3]*sp.sin(x2*u) + b[4]*u + b[5]
# rho, eta, lambda from xi: q_n = -xi_n^2 are the roots of rho q^2 + eta q + lambda.
subs = {eta: rho*(x1**2 + x2**2), lam: rho*x1**2*x2**2}
res = sp.simplify((rho*sp.diff(S, u, 6) + eta*sp.diff(S, u, 4) + lam*sp.diff(S, u, 2)).subs(subs))
assert res == 0, res
q = sp.symbols("q")
roots = sp.solve(rho*q**2 + eta*q + lam, q)
# eq 14 intended: q = -eta (1 +- sqrt(1 - 4 rho lambda/eta^2)) / (2 rho)
intended = [-eta*(1 + s*sp.sqrt(1 - 4*rho*lam/eta**2))/(2*rho) for s in (1, -1)]
for r in roots:
    assert any(sp.simplify(sp.expand(r - i)) == 0 or abs(complex(sp.N((r - i).subs({rho: 1, eta: 3, lam: 1})))) < 1e-12 for i in intended)
symbolic_ok = True

# ---------- 2. goldens from the companion-matrix exponential ----------
def basis_expm(p, us):
    r, e, l = [mp.mpf(x) for x in p]
    A = mp.zeros(6, 6)
    for i in range(5):
        A[i, i+1] = 1
    # y6 = -(e y4 + l y2)/r
    A[5, 4] = -e/r
    A[5, 2] = -l/r
    def phi(t):
        return mp.expm(A*t)  # row i: i-th derivative of the fundamental solutions
    P1 = phi(1)
    M = mp.zeros(6, 6)
    for k in range(6):
        for i in range(3):
            M[i, k] = 1 if i == k else 0
            M[3+i, k] = P1[i, k]
    Minv = M**-1
    out = []
    for t in us:
        Pt = phi(mp.mpf(t))
        row = []
        for j in range(6):
            row.append([float(sum(Pt[d, k]*Minv[k, j] for k in range(6))) for d in range(3)])
        out.append(row)
    return out, float(mp.det(M))

CASES = [
    ("paper_fig4b_distinct", (1.0, 3.0, 1.0)),
    ("paper_fig4c_small_rho_lambda", (1e-4, 3.0, 1e-4)),
    ("paper_fig6b_complex", (1.0, 1.0, 3.0)),
    ("paper_fig6b_hat_complex", (0.1, 0.1, 3.0)),
    ("repeated_small", (1.0, 2.0, 1.0)),
    ("repeated_large", (1.0, 50.0, 625.0)),
    ("near_repeated_large", (1.0, 50.0, 624.9)),
    ("lambda_zero", (1.0, 1.0, 0.0)),
    ("lambda_zero_large", (0.01, 1.0, 0.0)),
    ("eta_lambda_zero", (1.0, 0.0, 0.0)),
    ("complex_large", (1.0, 10.0, 400.0)),
    ("complex_growing_large", (1.0, -30.0, 400.0)),
    ("negative_rho", (-1.0, 3.0, 1.0)),
    ("negative_eta_growing", (1.0, -30.0, 100.0)),
    ("mixed_sign_roots", (1.0, 5.0, -50.0)),
    ("all_negative", (-2.0, -7.0, -1.0)),
    ("distinct_oscillatory_large", (1.0, 40.0, 100.0)),
    ("distinct_growing_large", (1.0, -40.0, 100.0)),
    ("close_growing", (1.0, -50.0, 624.0)),
]
US = [0.0, 0.13, 0.37, 0.5, 0.81, 1.0]
golden_cases = []
for name, p in CASES:
    g, det = basis_expm(p, US)
    golden_cases.append({"name": name, "rho": p[0], "eta": p[1], "lambda": p[2], "us": US, "g": g, "det": det})

# ---------- 3. a singular boundary system ----------
# Distinct oscillatory roots q1 = -1, q2 = -w^2 (rho = 1, eta = 1 + w^2, lambda = w^2):
# the determinant of the boundary system changes sign between w = 9 and 9.5.
def det_w(w):
    w1, w2 = mp.mpf(1), mp.mpf(w)
    def y(t):
        return [[1, t, mp.cos(w1*t), mp.sin(w1*t), mp.cos(w2*t), mp.sin(w2*t)],
                [0, 1, -w1*mp.sin(w1*t), w1*mp.cos(w1*t), -w2*mp.sin(w2*t), w2*mp.cos(w2*t)],
                [0, 0, -w1**2*mp.cos(w1*t), -w1**2*mp.sin(w1*t), -w2**2*mp.cos(w2*t), -w2**2*mp.sin(w2*t)]]
    return mp.det(mp.matrix(y(0) + y(1)))

assert det_w(9.0) * det_w(9.5) < 0
w_sing = float(mp.findroot(det_w, (9.0, 9.5), solver="illinois"))
singular = {"case": "distinct oscillatory roots q = -1, -w^2", "rho": 1.0, "eta": 1 + w_sing**2, "lambda": w_sing**2, "omega": w_sing}

# ---------- 4. printed eqs 20-22 with restored signs ----------
def printed(x1, x2, s):
    """s: dict of sign choices for the sign-ambiguous places."""
    c1, s1, c2, s2 = mp.cos(x1), mp.sin(x1), mp.cos(x2), mp.sin(x2)
    e = {}
    e[1] = x1*(c1 - 1) + x1**2*s1*(1 - c2)/(x2*s2)
    e[2] = s1 - x1 + x1**2*s1*(1/s2 - 1/x2)/x2
    e[3] = c1 - 1 + x1**2*(1 - c2)/x2**2 + x1**2*(c2 - c1)*(1/x2 - 1/s2)/x2
    e[4] = x1*(s["e4"]*s1 + x1*s2/x2) + x1**2*(c2 - c1)*(c2 - 1)/(x2*s2)
    e[5] = (1/x2 - c2/s2)/x2
    e[6] = (s["e6"]*s2 + c2**2/s2 - c2/s2)/x2
    e[7] = (1/s2 - 1/x2)/x2
    e[8] = (1 - c2)/(x2*s2)
    e[11] = x1**2/x2**2 - 1
    e[12] = c2/(x2*s2)
    e[13] = 1/(x2*s2)
    D = e[1]*e[3] - e[2]*e[4]
    d = {1: e[1]/D, 2: e[2]/D, 3: e[3]/D, 4: e[4]/D}
    d[5] = d[1]*e[5] + d[2]*e[6]
    d[6] = d[1]*e[7] + d[2]*e[8]
    d[7] = d[4]*e[5] + d[3]*e[6]
    d[8] = d[4]*e[7] + d[3]*e[8]
    d[9] = (e[11] + 1)*(d[1] + d[2])
    d[10] = s["d10"]/x2**2 + (e[11] + 1)*d[5]
    e[9] = x1**2*(d[4]*s1 - d[1]*(c2 - c1))/(x2**2*s2)
    e[10] = x1**2*(d[3]*s1 - d[2]*(c2 - c1))/(x2**2*s2)
    L = s["lead"]
    g = [
        lambda t: L*d[1]*mp.cos(x1*t) - d[4]*mp.sin(x1*t) + d[1]*(e[11]+1)*mp.cos(x2*t) + e[9]*mp.sin(x2*t) - (x2*e[9] - x1*d[4])*t - (e[11]*d[1] - 1),
        lambda t: L*(d[1]+d[2])*mp.cos(x1*t) - (d[3]+d[4])*mp.sin(x1*t) + (e[9]+e[10])*mp.sin(x2*t) - (x2*(e[9]+e[10]) - x1*(d[3]+d[4]) - 1)*t - e[11]*(d[1]+d[2]),
        lambda t: L*d[5]*mp.cos(x1*t) - d[7]*mp.sin(x1*t) + d[10]*mp.cos(x2*t) + (e[5]*e[9] + e[6]*e[10] + e[12]/x2)*mp.sin(x2*t) - (x2*(e[5]*e[9] + e[6]*e[10]) - x1*d[7] + e[12])*t - (e[11]*d[5] - 1/x2**2),
        lambda t: L*d[1]*mp.cos(x1*t) + d[4]*mp.sin(x1*t) - d[1]*(e[11]+1)*mp.cos(x2*t) - e[9]*mp.sin(x2*t) + (x2*e[9] - x1*d[4])*t + e[11]*d[1],
        lambda t: L*d[2]*mp.cos(x1*t) + d[3]*mp.sin(x1*t) - d[2]*(e[11]+1)*mp.cos(x2*t) - e[10]*mp.sin(x2*t) + (x2*e[10] - x1*d[3])*t + e[11]*d[2],
        lambda t: L*d[6]*mp.cos(x1*t) - d[8]*mp.sin(x1*t) + d[6]*(e[11]+1)*mp.cos(x2*t) + (e[7]*e[9] + e[8]*e[10] - e[13]/x2)*mp.sin(x2*t) - (x2*(e[7]*e[9] + e[8]*e[10]) - x1*d[8] - e[13])*t - e[11]*d[6],
    ]
    return g

def bc_error(gk, k):
    err = 0
    for i, t in enumerate([0, 0, 0, 1, 1, 1]):
        order = i % 3
        val = mp.diff(gk, t, order) if order else gk(t)
        target = 1 if i == k else 0
        err = max(err, abs(val - target))
    return err

# paper case rho = lambda = 1, eta = 3
x1p = mp.sqrt((3 + mp.sqrt(5))/2)
x2p = mp.sqrt((3 - mp.sqrt(5))/2)
printed_report = []
for k in range(6):
    best = None
    for sg in itertools.product([1, -1], repeat=4):
        s = {"e4": sg[0], "e6": sg[1], "d10": sg[2], "lead": sg[3]}
        for (a, bb) in [(x1p, x2p), (x2p, x1p)]:
            err = bc_error(printed(a, bb, s)[k], k)
            if best is None or err < best[0]:
                best = (err, s, "xi1>xi2" if a > bb else "xi1<xi2")
    printed_report.append({"g": k+1, "best_boundary_error": float(best[0]), "signs": best[1], "order": best[2]})

# ---------- 5. difference formulas ----------
h, a2, a3 = sp.symbols("h a2 a3", positive=True)
f = sp.Function("f")
t = sp.symbols("t")
F = sum(sp.Symbol(f"f{n}")*t**n/sp.factorial(n) for n in range(5))  # Taylor of f at 0
U2, U3 = a2*h, a3*h
c3 = (U2*F.subs(t, U3) - U3*F.subs(t, U2) + (U3 - U2)*F.subs(t, 0))/(U2**2*(U3 - U2))
c3_lim = sp.simplify(sp.limit(c3, h, 0))
c2 = (F.subs(t, U2) - F.subs(t, 0))/U2
c2_lim = sp.simplify(sp.limit(c2, h, 0))
diff_formulas = {"printed_c2_limit": str(c2_lim), "printed_c3_limit": str(c3_lim)}
assert sp.simplify(c3_lim - sp.Symbol("f2")*a3/(2*a2)) == 0

json.dump({
    "source": "verify/ode6_golden.py (sympy %s, mpmath %s, 60 digits)" % (sp.__version__, mp.__version__),
    "cases": golden_cases,
    "singular": singular,
    "printed_eq20": printed_report,
    "difference_formulas": diff_formulas,
}, open(OUT, "w"), indent=1)
print("printed eq 20 best boundary errors:", [(r["g"], "%.2e" % r["best_boundary_error"]) for r in printed_report])
print("singular repeated root omega =", w_sing)
print("difference formulas:", diff_formulas)
