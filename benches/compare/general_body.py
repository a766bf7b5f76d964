"""The general-body pipeline of `benches/algebra.rs` in SymPy and SymEngine, for comparison.

Builds H = [I]ω, T = ½ ωᵀ[I]ω and [I]α + ω × ([I]ω) with the six inertia components
(products of inertia negated, as in the chapter), expands T and the Euler components, and
prints the seven components as LaTeX: the same work as `general_body::pipeline()`.

    pip install sympy symengine
    python3 benches/compare/general_body.py

prints the time of one round for each library (the best of several batches, as
`timeit` recommends) beside the number of printed characters, so that a reader can check
that both did the whole job. Run `cargo bench --bench algebra -- "general body"` in the
same session for kinetics' figure.
"""

import sys
import timeit


def pipeline(lib):
    """One round: build, expand, print as LaTeX; returns the seven LaTeX strings."""
    s = lib.symbols
    ix, iy, iz = s("I_x I_y I_z")
    ixy, iyz, ixz = (-p for p in s("I_xy I_yz I_xz"))
    inertia = lib.Matrix([[ix, ixy, ixz], [ixy, iy, iyz], [ixz, iyz, iz]])
    omega = lib.Matrix(s(r"\omega_x \omega_y \omega_z"))
    alpha = lib.Matrix(s(r"\dot{\omega}_x \dot{\omega}_y \dot{\omega}_z"))
    h = inertia * omega
    t = (omega.T * h)[0] * lib.Rational(1, 2)
    cross = lib.Matrix(
        [
            omega[1] * h[2] - omega[2] * h[1],
            omega[2] * h[0] - omega[0] * h[2],
            omega[0] * h[1] - omega[1] * h[0],
        ]
    )
    euler = inertia * alpha + cross
    expanded = [lib.expand(e) for e in list(h) + [t] + list(euler)]
    return [lib.latex(e) for e in expanded]


def best_time(lib, rounds):
    """Seconds per round: the best of 7 batches of `rounds` rounds."""
    timer = timeit.Timer(lambda: pipeline(lib))
    return min(timer.repeat(repeat=7, number=rounds)) / rounds


def main():
    rows = []
    for name, rounds in [("sympy", 20), ("symengine", 500)]:
        try:
            lib = __import__(name)
        except ImportError:
            print(f"{name}: not installed (pip install {name})", file=sys.stderr)
            continue
        printed = sum(len(x) for x in pipeline(lib))
        rows.append((f"{name} {lib.__version__}", best_time(lib, rounds), printed))
    print(f"{'library':<20} {'time/round':>12} {'LaTeX chars':>12}")
    for name, seconds, printed in rows:
        print(f"{name:<20} {seconds * 1e6:>9.1f} µs {printed:>12}")


if __name__ == "__main__":
    main()
