"""SymPy's cancel, gcd and simplify on the inputs of kinetics' simplification benchmark.

The same inputs as the Rust criterion benchmark, read from the same files:

- the corpus `tests/data/cancel_corpus.txt` (made by `cancel_corpus.py`): the total time
  for all its inputs;
- `benches/compare/inputs/gcd_4_symbols_degree_6.txt`: two random polynomials in the four
  symbols m, a, b, c, of total degree 6, sharing a random factor of degree 2 (their gcd),
  one a line;
- `benches/compare/inputs/free_box_unknowns.txt`: the six solved unknowns of
  `examples/scenes/free_box_struck_at_corner.scene` as `kinetics solve` prints them, one
  `name = expression` a line: the total time for all six.

Every expression is in kinetics' ASCII syntax (`^` for powers), which SymPy reads once
`^` is `**`; reading is not timed.

    pip install sympy symengine      # and gmpy2, the integers SymPy's polynomials prefer
    python3 benches/compare/simplification.py                 # the table
    python3 benches/compare/simplification.py --write-inputs  # make the two input files

`--write-inputs` generates the gcd pair from a fixed seed (and checks that their gcd is
the planted factor) and takes the unknowns from `target/release/kinetics solve
examples/scenes/free_box_struck_at_corner.scene --format json` (build it first with
`cargo build --release`).

The first line says which integers SymPy used (its ground types: `gmpy` with gmpy2
installed, else `python`; gmpy2 makes its gcd and cancel about 1.5 times faster here).
Each figure is the best of several batches, as `timeit` recommends (and as
`general_body.py` does). SymEngine has no cancel, multivariate gcd or simplify in its
Python module (0.15), so only SymPy's figures are printed; the script says so when
SymEngine is installed. Run kinetics' criterion benchmark of the same inputs in the same
session for the ratios.
"""

import json
import random
import subprocess
import sys
import timeit
from pathlib import Path

import sympy

ROOT = Path(__file__).resolve().parents[2]
INPUTS = Path(__file__).resolve().parent / "inputs"
CORPUS = ROOT / "tests" / "data" / "cancel_corpus.txt"
GCD_PAIR = INPUTS / "gcd_4_symbols_degree_6.txt"
FREE_BOX = INPUTS / "free_box_unknowns.txt"
FREE_BOX_SCENE = ROOT / "examples" / "scenes" / "free_box_struck_at_corner.scene"
KINETICS = ROOT / "target" / "release" / "kinetics"

SEED = 15
GCD_SYMBOLS = sympy.symbols("m a b c")


def read(text):
    """A line of kinetics ASCII as a SymPy expression; every name a plain symbol."""
    text = text.replace("^", "**")
    names = {str(s): s for s in sympy.parse_expr(text, evaluate=False).free_symbols}
    local = {name: sympy.Symbol(name) for name in names}
    local.update(sin=sympy.sin, cos=sympy.cos, sqrt=sympy.sqrt)
    return sympy.parse_expr(text, local_dict=local)


def ascii(e):
    return sympy.sstr(e, order="lex").replace("**", "^")


def random_polynomial(rng, degree, terms):
    """A polynomial in the four symbols with `terms` random monomials of total degree at
    most `degree`, one of them of degree exactly `degree`; small integer coefficients."""
    def monomial(d):
        return sympy.Mul(*(rng.choice(GCD_SYMBOLS) for _ in range(d)))

    p = monomial(degree) * rng.choice([1, 2, 3])
    for _ in range(terms - 1):
        p += rng.choice([-5, -4, -3, -2, -1, 1, 2, 3, 4, 5]) * monomial(rng.randint(0, degree))
    return sympy.expand(p)


def write_gcd_pair():
    """p·g and q·g: cofactors of degree 4 with 10 terms, g of degree 2 with 4 terms; the
    gcd of the two is g up to a number (checked)."""
    rng = random.Random(SEED)
    g = random_polynomial(rng, 2, 4)
    p, q = random_polynomial(rng, 4, 10), random_polynomial(rng, 4, 10)
    first, second = sympy.expand(p * g), sympy.expand(q * g)
    found = sympy.gcd(first, second)
    assert sympy.simplify(found / g).is_number, f"gcd {found} is not the planted {g}"
    for e in (first, second):
        assert sympy.Poly(e, *GCD_SYMBOLS).total_degree() == 6
    INPUTS.mkdir(exist_ok=True)
    GCD_PAIR.write_text(f"{ascii(first)}\n{ascii(second)}\n")


def write_free_box_unknowns():
    """The solved unknowns of the free-box scene, as kinetics prints them."""
    run = subprocess.run([str(KINETICS), "solve", str(FREE_BOX_SCENE), "--format", "json"],
                         capture_output=True, text=True, check=True)
    results = json.loads(run.stdout)["results"]
    INPUTS.mkdir(exist_ok=True)
    FREE_BOX.write_text("".join(f"{r['name']} = {r['text']}\n" for r in results))


def corpus_inputs():
    return [read(line.split(": ", 1)[1]) for line in CORPUS.read_text().splitlines()
            if line.startswith("input: ")]


def free_box_unknowns():
    return [read(line.split(" = ", 1)[1]) for line in FREE_BOX.read_text().splitlines()]


def best_time(job, rounds, batches):
    """Seconds per round: the best of `batches` batches of `rounds` rounds."""
    return min(timeit.Timer(job).repeat(repeat=batches, number=rounds)) / rounds


def rows():
    """(input set, operation, seconds per round, operation count of the results)."""
    corpus, box = corpus_inputs(), free_box_unknowns()
    first, second = (read(line) for line in GCD_PAIR.read_text().splitlines())
    quotient = first / second

    def over(inputs, operation):
        return lambda: [operation(e) for e in inputs]

    jobs = [
        ("corpus (all cases)", "cancel", over(corpus, sympy.cancel), 3, 5),
        ("corpus (all cases)", "simplify", over(corpus, sympy.simplify), 1, 3),
        ("gcd 4 symbols degree 6", "gcd", lambda: [sympy.gcd(first, second)], 20, 7),
        ("gcd 4 symbols degree 6", "cancel", lambda: [sympy.cancel(quotient)], 20, 7),
        ("free-box unknowns", "cancel", over(box, sympy.cancel), 200, 7),
        ("free-box unknowns", "simplify", over(box, sympy.simplify), 5, 5),
    ]
    for inputs, operation, job, rounds, batches in jobs:
        size = sum(sympy.count_ops(e) for e in job())
        yield inputs, operation, best_time(job, rounds, batches), size


def main():
    if "--write-inputs" in sys.argv[1:]:
        write_gcd_pair()
        write_free_box_unknowns()
    try:
        import symengine

        print(f"symengine {symengine.__version__}: no cancel, multivariate gcd or simplify "
              "in its Python module; not timed", file=sys.stderr)
    except ImportError:
        pass
    ground = sympy.external.gmpy.GROUND_TYPES
    print(f"sympy {sympy.__version__} (ground types {ground})")
    print(f"{'input':<24} {'operation':<10} {'time/round':>14} {'count_ops':>10}")
    for inputs, operation, seconds, size in rows():
        print(f"{inputs:<24} {operation:<10} {seconds * 1e3:>11.3f} ms {size:>10}")


if __name__ == "__main__":
    main()
