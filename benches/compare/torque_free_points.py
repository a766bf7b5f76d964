"""The exact torque-free ω(t) per time point beside SciPy's `ellipj` on the same points.

The body is `benches/torque_free.rs`'s asymmetric one: I = (1, 2, 3), ω₀ = (1, 1, 1), whose
ω(t) is (√2 cn u, √2 sn u, √(4/3) dn u) with m = 1/2 and u = t √(4/3) + F(π/4 | 1/2)
(Landau & Lifshitz §37: M² = 14, 2E = 6), at the bench's 64 times t = 0.37 k². SciPy's
`ellipj(u, m)` gives sn, cn, dn (and am) of those u — the special functions alone, the
smallest part of ω(t) — timed by `timeit` on the 64 points repeated to 64,000 (one ufunc
call). kinetics' whole `TorqueFree::omega(t)` (the phase reduced in double-double, the theta
series, the frame) is timed by criterion in the same run:

    python3 benches/compare/torque_free_points.py

Prints both times per point and their ratio. The accuracy (within 1e-15 of mpmath) is the
unit test `agree_with_mpmath_to_1e15` in `src/numeric/rigid_body/elliptic/jacobi.rs`.
"""

import math
import pathlib
import re
import subprocess
import timeit

import numpy as np
from scipy.special import ellipj, ellipkinc

ROOT = pathlib.Path(__file__).resolve().parents[2]
M = 0.5
RATE = math.sqrt(4.0 / 3.0)
U0 = ellipkinc(math.pi / 4, M)
TIMES = np.array([0.37 * k * k for k in range(64)])
POINTS = RATE * TIMES + U0


def scipy_ns_per_point():
    u = np.tile(POINTS, 1000)
    runs = 20
    best = min(timeit.repeat(lambda: ellipj(u, M), number=runs, repeat=5))
    return best / runs / u.size * 1e9


def kinetics_ns_per_point():
    run = subprocess.run(
        ["cargo", "bench", "--bench", "torque_free", "--", "--warm-up-time", "1",
         "--measurement-time", "3", "asymmetric/omega_x64"],
        cwd=ROOT, capture_output=True, text=True, check=True,
    )
    found = re.search(r"asymmetric/omega_x64\s+time:\s+\[\S+ \S+ (\S+) (\S+)", run.stdout)
    if found is None:
        raise SystemExit("no criterion estimate in:\n" + run.stdout)
    value, unit = float(found.group(1)), found.group(2)
    scale = {"ns": 1.0, "µs": 1e3, "us": 1e3, "ms": 1e6}[unit]
    return value * scale / len(POINTS)


def main():
    # The points are the motion's: ω(0) = (√2 cn u₀, √2 sn u₀, √(4/3) dn u₀) = (1, 1, 1).
    sn, cn, dn, _ = ellipj(U0, M)
    assert np.allclose([math.sqrt(2) * cn, math.sqrt(2) * sn, math.sqrt(4 / 3) * dn], 1.0)
    scipy = scipy_ns_per_point()
    kinetics = kinetics_ns_per_point()
    print(f"SciPy ellipj (sn, cn, dn, am):      {scipy:7.1f} ns per point")
    print(f"kinetics TorqueFree::omega (ω(t)):  {kinetics:7.1f} ns per point")
    print(f"kinetics is {scipy / kinetics:.2f}× as fast, on the same {len(POINTS)} points")


if __name__ == "__main__":
    main()
