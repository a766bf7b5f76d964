"""SymPy's (and SymEngine's) exact real roots of the cases kinetics' `benches/roots.rs` times.

The cases are the lines of `tests/data/polynomial_roots.txt` (cubics and quartics in x,
written by `polynomial_roots.py`, whose documentation gives the format), in the groups of
the Rust benchmark: the numeric cubics, the numeric quartics, and the cases with letters
for coefficients (`a*x^3 + b*x^2 + c*x + d`, ..., each with values for the letters). Each
figure is the total time for all the cases of a group, the best of several batches, as
`timeit` recommends (and as `general_body.py` does).

The work timed for one case, the same as kinetics' `solve_system` does:

- SymPy: `sympy.roots(Poly(expr, x), cubics=True, quartics=True)`, the distinct roots in
  radicals, the letters kept; then each root is kept when it is real: the values put in
  for the letters (exact rationals), the root evaluated numerically, real when its imaginary
  part is at most 1e-12 max(1, |root|). SymPy keeps a cache of what it computed: it is
  cleared before each round, as a program that solves each polynomial once sees it (the
  figure with the cache kept, each round repeating the last one, is printed beside it);
- SymEngine, when installed: its `solve(expr, x)` (in `symengine.lib.symengine_wrapper`,
  not exported by the module in 0.15; it writes a cubic's or a quartic's roots in
  radicals), then the same test of realness.

Reading the file and making the expressions is not timed. After timing, each library's real
roots are compared with the file's (mpmath at 50 digits, which kinetics agrees with on
every case: `tests/suite/polynomial_roots_truth.rs`): a different number of real roots, or a
root that is none of the file's (to 1e-9 max(1, |root|)), is listed under the table.

    pip install sympy symengine
    cargo bench --bench roots -- --warm-up-time 1 --measurement-time 3
    python3 benches/compare/polynomial_roots_timing.py

The kinetics column is the mean of criterion's last run of each group
(`target/criterion/polynomial roots/<group>/new/estimates.json`), left empty when there is
none; `--criterion DIR` reads another criterion folder, `--batches N` sets the number of
batches (default 5).
"""

import argparse
import json
import sys
import timeit
from fractions import Fraction
from pathlib import Path

import sympy
from sympy.core.cache import clear_cache

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "data" / "polynomial_roots.txt"
CRITERION = ROOT / "target" / "criterion"
CRITERION_GROUP = "polynomial roots"
GROUPS = ["numeric cubics", "numeric quartics", "symbolic coefficients"]
X = sympy.Symbol("x")
REAL = 1e-12
AGREE = 1e-9


class Case:
    """One line of the corpus: the polynomial's text, the values (exact), the true roots."""

    def __init__(self, number, line):
        self.line = number
        self.kind, self.text, unknown, values, roots = line.split(" | ")
        assert unknown == "x", (number, unknown)
        self.values_text = values
        self.values = {} if values == "-" else {
            name: Fraction(v) for name, v in (pair.split("=") for pair in values.split(", "))}
        self.roots = [] if roots == "none" else [float(r) for r in roots.split(", ")]
        self.expr = sympy.sympify(self.text.replace("^", "**"),
                                  locals={n: sympy.Symbol(n) for n in "abcdpqx"})
        if self.values:
            self.group = GROUPS[2]
        else:
            self.group = {3: GROUPS[0], 4: GROUPS[1]}[sympy.Poly(self.expr, X).degree()]

    def disagreement(self, real):
        """Why the real roots `real` (floats) are not the file's, or None."""
        if len(real) != len(self.roots):
            return f"{len(real)} real roots {sorted(real)}, the file {len(self.roots)}"
        for v in real:
            if not any(abs(v - r) <= AGREE * max(1.0, abs(r)) for r in self.roots):
                return f"the real root {v} is none of the file's {self.roots}"
        return None


def corpus():
    lines = CORPUS.read_text().splitlines()
    return [Case(n + 1, line) for n, line in enumerate(lines) if line and not line.startswith("#")]


def is_real(z):
    return abs(z.imag) <= REAL * max(1.0, abs(z))


class SymPy:
    name = f"SymPy {sympy.__version__}"

    def __init__(self, case):
        self.expr = case.expr
        self.values = {sympy.Symbol(n): sympy.Rational(v.numerator, v.denominator)
                       for n, v in case.values.items()}

    def real_roots(self):
        found = sympy.roots(sympy.Poly(self.expr, X), cubics=True, quartics=True)
        values = (complex(sympy.N(r.subs(self.values))) for r in found)
        return [z.real for z in values if is_real(z)]


def symengine_solver():
    """SymEngine's class like SymPy's, or None (with the reason on stderr)."""
    try:
        import symengine
        from symengine.lib.symengine_wrapper import solve
    except ImportError as e:
        print(f"SymEngine not timed: {e} (pip install symengine)", file=sys.stderr)
        return None
    x = symengine.Symbol("x")

    class SymEngine:
        name = f"SymEngine {symengine.__version__}"

        def __init__(self, case):
            self.expr = symengine.sympify(case.text.replace("^", "**"))
            self.values = {symengine.Symbol(n): symengine.Rational(v.numerator, v.denominator)
                           for n, v in case.values.items()}

        def real_roots(self):
            found = solve(self.expr, x)
            if not isinstance(found, symengine.FiniteSet):
                raise ValueError(f"solve gave {found}")
            values = (complex(r.subs(self.values).n(53, real=False)) for r in found.args)
            return [z.real for z in values if is_real(z)]

    return SymEngine


def best_time(round_, batches):
    """Seconds for one round: the best of `batches` rounds."""
    return min(timeit.Timer(round_).repeat(repeat=batches, number=1))


def kinetics_seconds(folder, group):
    path = folder / CRITERION_GROUP / group / "new" / "estimates.json"
    if not path.exists():
        return None
    return json.loads(path.read_text())["mean"]["point_estimate"] * 1e-9


def milliseconds(seconds):
    return "-" if seconds is None else f"{seconds * 1e3:.3f} ms"


def ratio(seconds, kinetics):
    """How many times kinetics' time `seconds` is: two significant figures, at least."""
    if seconds is None or kinetics is None:
        return "-"
    r = seconds / kinetics
    return f"{r:.0f}" if r >= 10 else f"{r:.2f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--criterion", type=Path, default=CRITERION)
    parser.add_argument("--batches", type=int, default=5)
    args = parser.parse_args()

    cases = corpus()
    libraries = [SymPy] + [s for s in [symengine_solver()] if s]
    disagreements = []
    rows = []
    for group in GROUPS:
        members = [c for c in cases if c.group == group]
        row = {"group": group, "cases": len(members)}
        for library in libraries:
            solvers = [library(c) for c in members]

            def one_round(solvers=solvers):
                return [s.real_roots() for s in solvers]

            def cold_round():
                clear_cache()
                return one_round()

            try:
                found = one_round()
            except Exception as e:  # SymEngine raises plain Exception; report, go on
                print(f"{library.name} not timed on the {group}: {e}", file=sys.stderr)
                continue
            for case, real in zip(members, found):
                why = case.disagreement(real)
                if why:
                    disagreements.append(
                        f"{library.name}, line {case.line} ({case.kind}) {case.text}"
                        f"{' at ' + case.values_text if case.values else ''}: {why}")
            if library is SymPy:
                row["SymPy"] = best_time(cold_round, args.batches)
                row["SymPy cached"] = best_time(one_round, args.batches)
            else:
                row["SymEngine"] = best_time(one_round, args.batches)
        row["kinetics"] = kinetics_seconds(args.criterion, group)
        rows.append(row)

    names = ", ".join(library.name for library in libraries)
    print(f"{names}; each figure the total for the group's cases, best of {args.batches}")
    columns = ["SymPy", "SymPy cached", "SymEngine", "kinetics"]
    print(f"{'group':<22} {'cases':>5} " + " ".join(f"{c:>14}" for c in columns)
          + f" {'SymPy/kinetics':>15} {'SymEngine/kinetics':>19}")
    for row in rows:
        print(f"{row['group']:<22} {row['cases']:>5} "
              + " ".join(f"{milliseconds(row.get(c)):>14}" for c in columns)
              + f" {ratio(row.get('SymPy'), row['kinetics']):>15}"
              + f" {ratio(row.get('SymEngine'), row['kinetics']):>19}")
    if disagreements:
        print("\nreal roots that differ from the file's (mpmath; kinetics agrees with it):")
        for line in disagreements:
            print(f"  {line}")
    else:
        print("\nevery library's real roots agree with the file's on every case")


if __name__ == "__main__":
    main()
