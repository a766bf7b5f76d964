"""Sample Problem 18.4 from Python: kinetics.solve beside SymPy's mechanics, side by side.

The same problem — two slender rods (mass m, length c) welded to a shaft along x turning at
w in bearings C (at O) and D (at x = L) under a couple M; find alpha and the reactions —
solved in one process by

- kinetics: `kinetics.solve(scene text)` and the results' values (the package, built
  with `pip install ./python`);
- SymPy: `sympy.physics.mechanics`, the rods as RigidBody in a frame turning about N.x,
  H_O and its rate by `dt(N)`, m a of each mass centre by `a2pt_theory`, ΣF = Σ m ā and
  ΣM_O = Ḣ_O solved for alpha, C_y, C_z, D_y, D_z, then simplified and evaluated.

The two D_y agree (printed, and the run stops if they do not). Times: the import of each
(in a fresh interpreter), and the solve, best of several batches as `timeit` says.

    python3 benches/compare/python_solve.py
"""

import pathlib
import subprocess
import sys
import timeit

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = (ROOT / "examples/scenes/sp18_4_shaft_reactions.scene").read_text()
VALUES = {"m": 0.3, "c": 0.1, "M": 6.0, "w": 125.7}


def import_seconds(module):
    """Seconds to import `module` in a fresh interpreter, less the interpreter's start."""
    def run(code):
        best = float("inf")
        for _ in range(5):
            out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
            best = min(best, float(out.stdout))
        return best
    timed = "import time; t = time.perf_counter(); {}; print(time.perf_counter() - t)"
    return run(timed.format(f"import {module}"))


def kinetics_solve():
    import kinetics

    s = kinetics.solve(SCENE)
    return s.results["D_y"].value


def sympy_mechanics_solve():
    import sympy as sp
    from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

    m, c, L = sp.symbols("m c L", positive=True)
    M, w, alpha = sp.symbols("M w alpha", real=True)
    C_y, C_z, D_y, D_z = sp.symbols("C_y C_z D_y D_z", real=True)
    t = dynamicsymbols._t
    theta = dynamicsymbols("theta")
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", [theta, N.x])
    O = Point("O")
    O.set_vel(N, 0)
    O.set_acc(N, 0)
    # Rod 1 along y at x = L/2, rod 2 along z at x = L/4 (the notes' figure at the instant).
    G1 = O.locatenew("G1", L / 2 * B.x + c / 2 * B.y)
    G2 = O.locatenew("G2", L / 4 * B.x + c / 2 * B.z)
    rod = m * c**2 / 12
    rod1 = RigidBody("rod1", G1, B, m, (inertia(B, rod, 0, rod), G1))
    rod2 = RigidBody("rod2", G2, B, m, (inertia(B, rod, rod, 0), G2))
    for G in (G1, G2):
        G.v2pt_theory(O, N, B)
        G.a2pt_theory(O, N, B)
    H_O = rod1.angular_momentum(O, N) + rod2.angular_momentum(O, N)
    Hdot = H_O.dt(N)
    mass_times_a = m * G1.acc(N) + m * G2.acc(N)
    force = (C_y + D_y) * B.y + (C_z + D_z) * B.z
    moment = M * B.x + (L * B.x).cross(D_y * B.y + D_z * B.z)
    at_instant = {theta.diff(t, 2): alpha, theta.diff(t): w}
    equations = [
        ((force - mass_times_a).dot(B.y)).subs(at_instant),
        ((force - mass_times_a).dot(B.z)).subs(at_instant),
        *[((moment - Hdot).dot(e)).subs(at_instant) for e in (B.x, B.y, B.z)],
    ]
    solution = sp.solve(equations, [alpha, C_y, C_z, D_y, D_z], dict=True)[0]
    d_y = sp.simplify(solution[D_y])
    return float(d_y.subs({m: VALUES["m"], c: VALUES["c"], M: VALUES["M"], w: VALUES["w"]}))


def best_seconds(work, number):
    return min(timeit.repeat(work, number=number, repeat=5)) / number


def main():
    ours, theirs = kinetics_solve(), sympy_mechanics_solve()
    if abs(ours - theirs) > 1e-9 * abs(theirs):
        sys.exit(f"the two D_y differ: kinetics {ours}, SymPy {theirs}")
    print(f"D_y: kinetics {ours:.10g} N, SymPy mechanics {theirs:.10g} N (they agree)")
    rows = [
        ("import", import_seconds("kinetics"), import_seconds("sympy")),
        ("solve SP 18.4", best_seconds(kinetics_solve, 200), best_seconds(sympy_mechanics_solve, 3)),
    ]
    print(f"{'':16}{'kinetics':>12}{'SymPy':>12}{'SymPy/kinetics':>16}")
    for name, k, s in rows:
        print(f"{name:16}{k * 1e3:10.3f} ms{s * 1e3:10.1f} ms{s / k:16.0f}")


if __name__ == "__main__":
    main()
