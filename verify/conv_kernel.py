"""SymPy re-derivation of the line-segment fields of the Cauchy kernel
(paper 003, sec 3.1) and golden values for the Rust checks.

F1 = int_0^l dt / (1 + s^2 (d^2 + t^2 - 2 h t))^2,  Ft = int_0^l t dt / (...)^2,
with q = d^2 - h^2 (squared distance to the line), p^2 = 1 + s^2 q.
Checks that the printed closed forms are antiderivative-exact (derivative of
the primitive equals the integrand), and emits high-precision (mpmath quad,
30 digits) values of
F1, Ft and the gradient components dF/dh, dF/dq at fixed points.
"""
import json, os, random
import sympy as sp
import mpmath as mp

t, u, h, q, l, s = sp.symbols('t u h q l s', positive=True)
p = sp.sqrt(1 + s**2 * q)
k = 1 / (p**2 + s**2 * u**2)**2  # u = t - h
# primitive of the paper's closed form, as a function of u
G1 = u / (2 * p**2 * (p**2 + s**2 * u**2)) + sp.atan(s * u / p) / (2 * s * p**3)
Gt = -1 / (2 * s**2 * (p**2 + s**2 * u**2))
assert sp.simplify(sp.diff(G1, u) - k) == 0, "F1 primitive"
assert sp.simplify(sp.diff(Gt, u) - u * k) == 0, "Ft primitive (u part)"
F1 = sp.simplify(G1.subs(u, l - h) - G1.subs(u, -h))
printed_F1 = (1 / (2 * p**2)) * (h / (s**2 * h**2 + p**2) + (l - h) / (s**2 * (l - h)**2 + p**2)) \
    + (1 / (2 * s * p**3)) * (sp.atan(s * h / p) + sp.atan(s * (l - h) / p))
assert sp.simplify(F1 - printed_F1) == 0, "printed F1"
Ft = Gt.subs(u, l - h) - Gt.subs(u, -h) + h * F1
printed_Ft = (1 / (2 * s**2)) * (1 / (s**2 * h**2 + p**2) - 1 / (s**2 * (l - h)**2 + p**2)) + h * printed_F1
assert sp.simplify(Ft - printed_Ft) == 0, "printed Ft"
print("printed F1 and Ft verified symbolically")

mp.mp.dps = 30
rng = random.Random(3)
cases = []
for i in range(24):
    L = rng.uniform(0.3, 3.0)
    S = rng.uniform(0.3, 4.0)
    H = rng.uniform(-1.0, L + 1.0)
    Q = rng.uniform(0.0, 2.0) ** 2
    w0 = rng.uniform(0.2, 3.0)
    w1 = rng.uniform(0.2, 3.0)
    kern = lambda T: 1 / (1 + S**2 * (Q + (T - H)**2))**2
    f1 = mp.quad(kern, [0, H if 0 < H < L else L / 2, L])
    ft = mp.quad(lambda T: T * kern(T), [0, H if 0 < H < L else L / 2, L])
    # derivatives of the weighted field wrt h and q by differentiating under the integral
    wt = lambda T: w0 + (w1 - w0) * T / L
    dk_dh = lambda T: 4 * S**2 * (T - H) / (1 + S**2 * (Q + (T - H)**2))**3
    dk_dq = lambda T: -2 * S**2 / (1 + S**2 * (Q + (T - H)**2))**3
    fh = mp.quad(lambda T: wt(T) * dk_dh(T), [0, L])
    fq = mp.quad(lambda T: wt(T) * dk_dq(T), [0, L])
    cases.append(dict(l=L, s=S, h=H, q=Q, w0=w0, w1=w1,
                      f1=float(f1), ft=float(ft), dfdh=float(fh), dfdq=float(fq)))
# symmetric points of a constant-weight segment: F1(h) = F1(l - h)
out = dict(source="verify/conv_kernel.py", note="F1, Ft by mpmath quad (30 digits); dF/dh, dF/dq of w0 F1 + (w1-w0) Ft / l", cases=cases)
os.makedirs(os.path.join(os.path.dirname(__file__), 'golden'), exist_ok=True)
with open(os.path.join(os.path.dirname(__file__), 'golden', 'conv_kernel.json'), 'w') as f:
    json.dump(out, f, indent=1)
print("wrote golden/conv_kernel.json with", len(cases), "cases")
