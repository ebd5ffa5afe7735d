"""Golden derivatives for the jet module (pdesculpt::jet).

Every mixed partial d^(i+j) f / du^i dv^j, 0 <= i, j <= 6, of a few closed
forms that exercise every elementary function of the jet, at fixed points,
computed exactly by SymPy and printed to 17 significant digits.

Run: python3 verify/jet_golden.py  (writes verify/golden/jet.json)
"""
import json
import os
import sympy as sp

u, v = sp.symbols("u v", real=True)

FUNCTIONS = {
    # name: (expression, (u0, v0))
    "exp_sin_quotient": (sp.exp(sp.sin(u) * v) / (1 + u**2 * v), ("0.3", "0.7")),
    "atan2_sqrt_log": (sp.atan2(v, u) * sp.sqrt(u + 2) + sp.log(1 + u * v), ("0.8", "-0.4")),
    "atan2_steep": (sp.atan2(v, u), ("0.1", "1.3")),
    "hyperbolic_tan": (sp.sinh(u - v) * sp.cosh(2 * u * v) + sp.tan(u / 2), ("0.5", "0.25")),
    "powers_atan": (u**5 * v**-2 + sp.atan(u * v) * (u + v)**sp.Rational(3, 2), ("1.1", "0.9")),
    # cos on its own and the paired sin_cos: the f64 side of Real has an
    # impl of each that no other form calls (a mutant returning 0 from
    # f64's cos survived: docs/verification.md, jet 2/16)
    "cos_sincos": (sp.cos(u) * v + sp.sin(u * v) * sp.cos(u * v), ("0.6", "1.7")),
}

ORDER = 6


def main():
    out = {"order": ORDER, "functions": []}
    for name, (expr, (u0, v0)) in FUNCTIONS.items():
        pt = {u: sp.Rational(u0), v: sp.Rational(v0)}
        table = []
        for i in range(ORDER + 1):
            row = []
            di = sp.diff(expr, u, i) if i else expr
            for j in range(ORDER + 1):
                dij = sp.diff(di, v, j) if j else di
                row.append(float(sp.N(dij.subs(pt), 30)))
            table.append(row)
        out["functions"].append(
            {"name": name, "expr": str(expr), "u0": float(sp.Rational(u0)),
             "v0": float(sp.Rational(v0)), "derivatives": table}
        )
    path = os.path.join(os.path.dirname(__file__), "golden", "jet.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", path)


if __name__ == "__main__":
    main()
