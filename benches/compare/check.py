"""SymPy deciding the claims of kinetics' `check` benchmark: `simplify(lhs - rhs) == 0`.

The claims are read from `benches/compare/inputs/check_claims.txt` (`CONTEXT | claim`), the
same file `benches/check.rs` times in kinetics. The derived names a claim uses (`T`, `H_x`,
`SumM_x`) are built here in SymPy from their definitions, independently of kinetics:
{H_G} = [I]{w} with the chapter's inertia matrix (products of inertia with a minus),
T = 1/2 m vbar.vbar + 1/2 w.[I]w, and Euler's equations sum M = [I]{wdot} + w x H_G. Reading
a claim is not timed; `simplify(lhs - rhs)` is, best of several batches as `timeit` says.

    pip install sympy
    python3 benches/compare/check.py
"""

import pathlib
import timeit

import sympy as sp
from sympy.parsing.sympy_parser import (
    implicit_multiplication_application,
    parse_expr,
    standard_transformations,
)

ROOT = pathlib.Path(__file__).resolve().parents[2]


def context(principal):
    I_x, I_y, I_z, I_xy, I_yz, I_xz, m = sp.symbols("I_x I_y I_z I_xy I_yz I_xz m")
    if principal:
        I_xy = I_yz = I_xz = 0
    inertia = sp.Matrix([[I_x, -I_xy, -I_xz], [-I_xy, I_y, -I_yz], [-I_xz, -I_yz, I_z]])
    w = sp.Matrix(sp.symbols("w_x w_y w_z"))
    wdot = sp.Matrix(sp.symbols("wdot_x wdot_y wdot_z"))
    vbar = sp.Matrix(sp.symbols("vbar_x vbar_y vbar_z"))
    h = inertia * w
    moments = inertia * wdot + w.cross(h)
    names = {"T": (m * vbar.dot(vbar) + w.dot(inertia * w)) / 2}
    for k, axis in enumerate("xyz"):
        names[f"H_{axis}"] = h[k]
        names[f"SumM_{axis}"] = moments[k]
        names[f"M_{axis}"] = moments[k]
    symbols = {str(s): s for s in sp.symbols("I_x I_y I_z I_xy I_yz I_xz m")}
    symbols.update({str(s): s for s in list(w) + list(wdot) + list(vbar)})
    return names, symbols


def read(claim, names, symbols):
    transformations = standard_transformations + (implicit_multiplication_application,)
    local = dict(symbols)
    local.update(names)
    lhs, rhs = claim.replace("^", "**").split("=")
    return (
        parse_expr(lhs, local_dict=local, transformations=transformations),
        parse_expr(rhs, local_dict=local, transformations=transformations),
    )


def main():
    contexts = {"general": context(False), "principal": context(True)}
    lines = (ROOT / "benches/compare/inputs/check_claims.txt").read_text().splitlines()
    print(f"SymPy {sp.__version__}: simplify(lhs - rhs) per claim")
    for line in lines:
        if not line.strip() or line.startswith("#"):
            continue
        name, claim = line.split(" | ", 1)
        lhs, rhs = read(claim, *contexts[name])
        verdict = "holds" if sp.simplify(lhs - rhs) == 0 else "differs"
        runs = 5
        best = min(timeit.repeat(lambda: sp.simplify(lhs - rhs), number=runs, repeat=3)) / runs
        print(f"{best * 1e6:12.0f} µs  {verdict:8} {claim[:70]}")


if __name__ == "__main__":
    main()
