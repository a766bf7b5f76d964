"""The corpus of rational functions that kinetics' `cancel` is compared with SymPy's on.

Generates, from a fixed seed, at least 200 rational functions in up to six of the chapter's
symbols (m, m_1, a, b, c, L, I_x, w_x, ...), degrees up to 4, small integer and rational
coefficients:

- fractions p·g/(q·g) with a planted common factor g (cancellation really happens),
- fractions p/q with no common factor (only the numbers are normalised),
- sums of fractions over different denominators, and fractions of fractions,
- fractions whose generators include an opaque part, sin(theta) or sqrt(a^2 + b^2)
  (the root only in the common factor, to the first power, so that SymPy rewrites no
  square of it before it cancels),

and for each SymPy's answer, `sympy.fraction(sympy.cancel(e))` with numerator and
denominator each `expand`ed. The input is parsed by SymPy from the very text written to
the file, so both programs read the same expression.

    python3 benches/compare/cancel_corpus.py            # writes tests/data/cancel_corpus.txt
    python3 benches/compare/cancel_corpus.py --check    # and checks every line with kinetics

`--check` runs `target/release/kinetics simplify` on every line (it must parse) and reads
its answer back with SymPy: it must have the line's value at a random point (so both read
the ASCII syntax alike: `^`, `*`, `-a^2 = -(a^2)`, `m_1`, `I_x`).

File format: a header of `#` lines, then one case per three lines

    input: <expression>
    numerator: <expanded numerator of SymPy's cancel>
    denominator: <expanded denominator of SymPy's cancel>

with a blank line between cases.
"""

import random
import subprocess
import sys
from pathlib import Path

import sympy

SEED = 15
ROOT = Path(__file__).resolve().parents[2]
OUTPUT = ROOT / "tests" / "data" / "cancel_corpus.txt"
KINETICS = ROOT / "target" / "release" / "kinetics"

NAMES = ["m", "m_1", "m_2", "a", "b", "c", "d", "h", "r", "L", "I_x", "I_y", "w_x", "w_y",
         "F_2", "Dt"]
SYMBOLS = {name: sympy.Symbol(name) for name in NAMES}
THETA = sympy.Symbol("theta")
LOCALS = dict(SYMBOLS, theta=THETA, sin=sympy.sin, cos=sympy.cos, sqrt=sympy.sqrt)

# Fractions a reader of the chapter meets: the inputs and results of its scenes.
HAND_PICKED = [
    "m_1*d/(m_1 + m_2) + m_2*d/(m_1 + m_2)",
    "(a^2 - b^2)/(a - b)",
    "1/(1/a + 1/b)",
    "-F_2*Dt*c/(2*(-1/12*m*b^2 - 1/12*m*c^2))",
    "F_2*Dt*a/(2*(-1/12*m*a^2 - 1/12*m*b^2))",
    "m_1*L/(2*(m_1 + m_2)) + m_2*L/(m_1 + m_2)",
    "1/3*m_1*L^2 - m_1^3*L^2/(4*(m_1 + m_2)^2) - 5*m_1^2*m_2*L^2/(4*(m_1 + m_2)^2)"
    " - 2*m_1*m_2^2*L^2/(m_1 + m_2)^2 - m_2^3*L^2/(m_1 + m_2)^2 + m_2*L^2",
    "(a*sin(theta) + b*sin(theta))/(a^2 - b^2)",
    "(a^2 + b^2)/sqrt(a^2 + b^2)",
    "(m*a + m*b)/(a^2 + 2*a*b + b^2)",
]


def ascii(e):
    """SymPy's text of `e` in the syntax kinetics parses (`^` for powers)."""
    return sympy.sstr(e, order="lex").replace("**", "^")


def coefficient(rng):
    """A small nonzero integer, or now and then a small fraction."""
    if rng.random() < 0.75:
        return rng.choice([-5, -4, -3, -2, -1, 1, 1, 1, 2, 2, 3, 4, 5])
    return sympy.Rational(rng.choice([-3, -2, -1, 1, 1, 2, 3, 5]), rng.choice([2, 3, 4, 12]))


def polynomial(rng, gens, degree, terms):
    """A random polynomial in `gens` of total degree at most `degree`, with `terms` terms
    (fewer when they combine); never zero."""
    while True:
        p = sympy.Integer(0)
        for _ in range(terms):
            monomial = sympy.Integer(1)
            for _ in range(rng.randint(0, degree)):
                monomial *= rng.choice(gens)
            p += coefficient(rng) * monomial
        p = sympy.expand(p)
        if p != 0:
            return p


def factor_of_degree(rng, gens, degree):
    """A random polynomial of total degree exactly `degree` (at least 1), not a number."""
    while True:
        p = polynomial(rng, gens, degree, rng.randint(2, 3))
        if sympy.Poly(p, *gens).total_degree() == degree:
            return p


def pick_symbols(rng, count):
    return [SYMBOLS[n] for n in rng.sample(NAMES, count)]


def quotient(num, den):
    return f"({ascii(num)})/({ascii(den)})"


def planted(rng):
    """p·g/(q·g): numerator and denominator of degree at most 4 sharing the factor g."""
    gens = pick_symbols(rng, rng.randint(1, 6))
    g_degree = rng.randint(1, 2)
    g = factor_of_degree(rng, gens, g_degree)
    if rng.random() < 0.2:
        g = g ** 2 if g_degree == 1 else g
    room = 4 - sympy.Poly(g, *gens).total_degree()
    p = polynomial(rng, gens, rng.randint(0, room), rng.randint(1, 3))
    q = polynomial(rng, gens, rng.randint(0, room), rng.randint(1, 3))
    return quotient(sympy.expand(p * g), sympy.expand(q * g))


def coprime(rng):
    """p/q with (almost surely) no common factor: only the numbers are normalised."""
    gens = pick_symbols(rng, rng.randint(1, 6))
    p = polynomial(rng, gens, rng.randint(1, 4), rng.randint(1, 4))
    q = polynomial(rng, gens, rng.randint(1, 4), rng.randint(1, 4))
    return quotient(p, q)


def sum_of_fractions(rng):
    """p₁/q₁ ± p₂/q₂ over different denominators sharing a factor, or a fraction of
    fractions such as 1/(1/a + 1/b)."""
    gens = pick_symbols(rng, rng.randint(2, 5))
    if rng.random() < 0.25:
        x, y = (polynomial(rng, gens, 1, rng.randint(1, 2)) for _ in range(2))
        u, v = (polynomial(rng, gens, 1, 1) for _ in range(2))
        return f"({ascii(u)})/(1/({ascii(x)}) + 1/({ascii(y)})) + ({ascii(v)})"
    shared = factor_of_degree(rng, gens, 1)
    q1 = sympy.expand(shared * polynomial(rng, gens, 1, rng.randint(1, 2)))
    q2 = sympy.expand(shared * polynomial(rng, gens, 1, rng.randint(1, 2)))
    p1 = polynomial(rng, gens, rng.randint(0, 2), rng.randint(1, 2))
    p2 = polynomial(rng, gens, rng.randint(0, 2), rng.randint(1, 2))
    sign = rng.choice(["+", "-"])
    return f"{quotient(p1, q1)} {sign} {quotient(p2, q2)}"


def opaque(rng):
    """A planted fraction whose generators include sin(theta) (any power) or
    sqrt(a^2 + b^2) (in the common factor only, to the first power: SymPy would rewrite
    its square as a^2 + b^2, and the factor would no longer be seen)."""
    gens = pick_symbols(rng, rng.randint(1, 4))
    if rng.random() < 0.6:
        s = sympy.sin(THETA)
        g = factor_of_degree(rng, gens + [s], rng.randint(1, 2))
        p = polynomial(rng, gens + [s], rng.randint(0, 2), rng.randint(1, 3))
        q = polynomial(rng, gens + [s], rng.randint(0, 2), rng.randint(1, 3))
    else:
        a, b = SYMBOLS["a"], SYMBOLS["b"]
        s = sympy.sqrt(a ** 2 + b ** 2)
        g = sympy.expand(polynomial(rng, gens, 1, 1) * s + polynomial(rng, gens, 1, 2))
        p = polynomial(rng, gens + [a, b], rng.randint(0, 2), rng.randint(1, 3))
        q = polynomial(rng, gens + [a, b], rng.randint(0, 2), rng.randint(1, 3))
    return quotient(sympy.expand(p * g), sympy.expand(q * g))


def cases():
    """The inputs: the hand-picked ones, then the random kinds, from the fixed seed."""
    rng = random.Random(SEED)
    inputs = list(HAND_PICKED)
    for kind, count in [(planted, 130), (coprime, 30), (sum_of_fractions, 40), (opaque, 30)]:
        inputs += [kind(rng) for _ in range(count)]
    return inputs


def read(text):
    """The expression of a line of the file, as SymPy reads it."""
    return sympy.parse_expr(text.replace("^", "**"), local_dict=LOCALS)


def answer(text):
    """SymPy's cancel of the input: (numerator, denominator), each expanded."""
    num, den = sympy.fraction(sympy.cancel(read(text)))
    return sympy.expand(num), sympy.expand(den)


def write(inputs):
    lines = [
        "# Rational functions and SymPy's cancel of each: numerator and denominator expanded.",
        "# Generated by: python3 benches/compare/cancel_corpus.py",
        f"# SymPy {sympy.__version__}, Python random seed {SEED}; {len(inputs)} cases.",
        "# Each case: input, then sympy.fraction(sympy.cancel(input)), each expand()ed.",
        "",
    ]
    for text in inputs:
        num, den = answer(text)
        lines += [f"input: {text}", f"numerator: {ascii(num)}", f"denominator: {ascii(den)}", ""]
    OUTPUT.parent.mkdir(parents=True, exist_ok=True)
    OUTPUT.write_text("\n".join(lines[:-1]) + "\n")


def check():
    """Every expression of the file through `kinetics simplify`: it parses, and kinetics'
    answer read back by SymPy has the expression's value at a random point."""
    rng = random.Random(SEED)
    lines = [line for line in OUTPUT.read_text().splitlines() if ": " in line and
             not line.startswith("#")]
    for line in lines:
        text = line.split(": ", 1)[1]
        run = subprocess.run([str(KINETICS), "simplify", "--", text], capture_output=True,
                             text=True)
        if run.returncode != 0:
            sys.exit(f"kinetics does not parse {text!r}: {run.stderr}")
        ours, theirs = read(run.stdout.strip()), read(text)
        value = sympy.nan
        while not value.is_finite:  # a point off the poles
            point = {s: sympy.Rational(rng.randint(3, 40), rng.randint(3, 20))
                     for s in theirs.free_symbols | ours.free_symbols}
            value = sympy.N(theirs.subs(point), 30)
        difference = sympy.N(ours.subs(point), 30) - value
        if abs(difference) > 1e-20 * max(1, abs(value)):
            sys.exit(f"kinetics reads {text!r} as {run.stdout.strip()!r}, another value")
    print(f"{len(lines)} lines parsed by kinetics, each with SymPy's value", file=sys.stderr)


def main():
    write(cases())
    if "--check" in sys.argv[1:]:
        check()


if __name__ == "__main__":
    main()
