"""The ground truth for kinetics' exact roots of a cubic or a quartic in one unknown.

Writes `tests/data/polynomial_roots.txt`, read by `tests/suite/polynomial_roots_truth.rs`
(and timed by `benches/roots.rs` and `polynomial_roots_timing.py`):
polynomials of degree 3 and 4 in x, from a fixed seed, each with its real roots computed by
mpmath at 50 digits. The script is not run by CI; run it after changing it and check the
file in:

    python3 benches/compare/polynomial_roots.py

The cases, by kind (the first field of each line):

- cubics with integer coefficients (|c| <= 20): three irrational real roots (the casus
  irreducibilis), one irrational real root, a rational root and an irrational (real or
  complex) quadratic pair, a double rational root, a triple root, a leading coefficient
  not 1, and cubics with fractions for coefficients;
- quartics with odd powers: 0, 2 and 4 real irrational roots (irreducible over Q), two
  irrational quadratic factors, a double irrational root ((x^2 - x - 1)^2 expanded), two
  rational roots and a quadratic factor, the root 0 times a cubic, and quartics the solver
  writes as quadratics (biquadratics, x^2 times a quadratic);
- symbolic coefficients with values: `a*x^3 + b*x^2 + c*x + d`, `x^3 + p*x + q`,
  `a*x^3 + d`, `a*x^4 + b*x^3 + c*x + d`, and the forms that are quadratics in disguise
  (`a*x^2 + b*x + c`, `a*x^3 + b*x^2 + c*x`, `a*x^4 + b*x^2 + c`). The values are exact
  decimals (multiples of 1/8, so f64 holds them exactly), chosen so that every two roots
  (complex ones too) are more than 1e-3 apart and the discriminant, and the reduced form's
  coefficients, are more than 1e-3 from zero: a sign the solver decides from the values in
  f64 is then safe.

How a root is computed: the polynomial's exact rational coefficients (the values put in)
are made square-free with SymPy (`sqf_part`: a double root becomes simple, so that mpmath
converges to all 50 digits), then `mpmath.polyroots(..., extraprec=...)` at 50 digits; a root
is real when its imaginary part is below 1e-40; the real roots are sorted and must be
distinct to 1e-30. Their number is checked against SymPy's exact count
(`Poly.count_roots`, Sturm sequences), and each root against the square-free polynomial's
value.

File format: `#` lines are comments; each case is one line of five fields separated by ` | `:

    kind | polynomial | unknown | values | real roots

- kind: a word naming the family of the case (casus_irreducibilis, one_real, ...);
- polynomial: the left side of `polynomial = 0`, as kinetics parses it (`^`, `*`, `/`);
- unknown: the symbol solved for (always x);
- values: `name=decimal` for each other symbol, separated by `, `, or `-` for none;
- real roots: the distinct real roots, ascending, each to 25 significant digits,
  separated by `, `, or `none`.
"""

import random
from fractions import Fraction
from pathlib import Path

import mpmath
import sympy

SEED = 18
DIGITS = 50
SIGNIFICANT = 25
ROOT = Path(__file__).resolve().parents[2]
OUTPUT = ROOT / "tests" / "data" / "polynomial_roots.txt"

X = sympy.Symbol("x")
SYMBOLS = {n: sympy.Symbol(n) for n in "abcdpq"}


def text(e):
    """SymPy's text of `e` in the syntax kinetics parses (`^` for powers)."""
    return sympy.sstr(sympy.expand(e), order="lex").replace("**", "^")


def poly(e):
    return sympy.Poly(sympy.expand(e), X, domain="QQ")


def rational_root_count(p):
    return sum(1 for f, _ in sympy.factor_list(p.as_expr(), X)[1] if sympy.degree(f, X) == 1)


def irreducible(p):
    factors = sympy.factor_list(p.as_expr(), X)[1]
    return len(factors) == 1 and factors[0][1] == 1


def real_count(p):
    """The number of distinct real roots, exactly (Sturm)."""
    return sympy.Poly(sympy.sqf_part(p.as_expr()), X).count_roots()


def discriminant(p):
    return sympy.discriminant(p.as_expr(), X)


def real_roots(p):
    """The distinct real roots of `p` by mpmath at DIGITS digits, ascending (module doc)."""
    square_free = sympy.Poly(sympy.sqf_part(p.as_expr()), X, domain="QQ")
    with mpmath.workdps(DIGITS):
        coefficients = [mpmath.mpf(c.p) / c.q for c in square_free.all_coeffs()]
        roots = mpmath.polyroots(coefficients, maxsteps=400, extraprec=4 * DIGITS)
        real = sorted(mpmath.re(r) for r in roots if abs(mpmath.im(r)) < mpmath.mpf("1e-40"))
        for r0, r1 in zip(real, real[1:]):
            assert r1 - r0 > mpmath.mpf("1e-30"), (p, real)
        scale = sum(abs(c) for c in coefficients)
        for r in real:
            assert abs(mpmath.polyval(coefficients, r)) < mpmath.mpf("1e-40") * scale * max(
                1, abs(r)) ** square_free.degree(), (p, r)
        assert len(real) == real_count(p), (p, real)
        return [mpmath.nstr(r, SIGNIFICANT, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)
                for r in real]


def min_root_gap(p):
    """The least distance between two of the (complex) roots of `p`, in f64."""
    with mpmath.workdps(30):
        coefficients = [mpmath.mpf(c.p) / c.q for c in p.all_coeffs()]
        roots = mpmath.polyroots(coefficients, maxsteps=400, extraprec=100)
        return min(abs(r0 - r1) for i, r0 in enumerate(roots) for r1 in roots[i + 1:])


# --- cubics with integer or rational coefficients -------------------------------------------

def random_cubic(rng, leading, low=-20, high=20):
    a = rng.choice(leading)
    return poly(a * X**3 + rng.randint(low, high) * X**2 + rng.randint(low, high) * X
                + rng.randint(low, high))


def cubics_where(rng, count, wanted, leading=(1,), seen=None):
    """`count` integer cubics, distinct, for which `wanted(p)` holds."""
    seen = set() if seen is None else seen
    found = []
    while len(found) < count:
        p = random_cubic(rng, leading)
        if p.nth(0) != 0 and wanted(p) and p not in seen:
            seen.add(p)
            found.append(p)
    return found


def casus(p):
    return irreducible(p) and discriminant(p) > 0


def one_real(p):
    return irreducible(p) and discriminant(p) < 0


def fraction(rng, bound=20, denominators=(2, 3, 4, 5, 7)):
    return sympy.Rational(rng.randint(-bound, bound), rng.choice(denominators))


def fraction_cubics(rng, count, wanted):
    found = []
    while len(found) < count:
        p = poly(X**3 + fraction(rng) * X**2 + fraction(rng) * X + fraction(rng))
        if p.nth(0) != 0 and wanted(p) and any(c.q != 1 for c in p.all_coeffs()):
            found.append(p)
    return found


def rational_and_pair(rng, count, real_pair):
    """(s x − r)(x² + b x + c), the pair irrational real or complex, coefficients <= 20."""
    found = []
    while len(found) < count:
        s, r = rng.choice([1, 1, 2, 3]), rng.randint(-4, 4)
        b, c = rng.randint(-6, 6), rng.randint(-8, 8)
        d = b * b - 4 * c
        if sympy.gcd(s, r) != 1 or d == 0 or sympy.sqrt(d).is_rational:
            continue
        if (d > 0) != real_pair:
            continue
        p = poly((s * X - r) * (X**2 + b * X + c))
        if max(abs(k) for k in p.all_coeffs()) <= 20 and p not in found:
            found.append(p)
    return found


def cubic_cases(rng):
    seen = set()
    cases = [("casus_irreducibilis", poly(e)) for e in
             [X**3 - 3 * X + 1, X**3 - 7 * X + 7, X**3 - 3 * X - 1, X**3 + X**2 - 2 * X - 1]]
    cases += [("casus_irreducibilis", p) for p in cubics_where(rng, 8, casus, seen=seen)]
    cases += [("casus_leading_not_1", p)
              for p in cubics_where(rng, 4, casus, leading=(2, 3, -2, 5), seen=seen)]
    cases += [("casus_fractions", p) for p in fraction_cubics(rng, 4, casus)]
    cases += [("one_real", poly(X**3 + X + 1)), ("one_real", poly(X**3 - 2))]
    cases += [("one_real", p) for p in cubics_where(rng, 6, one_real, seen=seen)]
    cases += [("one_real_leading_not_1", p)
              for p in cubics_where(rng, 3, one_real, leading=(2, -3, 4), seen=seen)]
    cases += [("one_real_fractions", p) for p in fraction_cubics(rng, 3, one_real)]
    cases += [("rational_and_real_pair", poly((X - 2) * (X**2 - 3)))]
    cases += [("rational_and_real_pair", p) for p in rational_and_pair(rng, 5, True)]
    cases += [("rational_and_complex_pair", p) for p in rational_and_pair(rng, 3, False)]
    cases += [("double_rational", poly(e)) for e in
              [(X - 1)**2 * (X + 2), (X + 3)**2 * (X - 1), (2 * X - 1)**2 * (X + 1),
               (X - 2)**2 * (3 * X + 1), 2 * (X + 1)**2 * (X - 3)]]
    cases += [("triple", poly(e)) for e in [(X - 2)**3, (2 * X + 1)**3, -(X + 1)**3]]
    return cases


# --- quartics ---------------------------------------------------------------------------------

def quartics_where(rng, count, real, seen):
    """Irreducible integer quartics with an odd power and `real` distinct real roots."""
    found = []
    while len(found) < count:
        a = rng.choice([1, 1, 1, 2, -1, 3])
        cs = [rng.randint(-20, 20) for _ in range(4)]
        p = poly(a * X**4 + cs[0] * X**3 + cs[1] * X**2 + cs[2] * X + cs[3])
        if (p.nth(3) == 0 and p.nth(1) == 0) or p.nth(0) == 0 or p in seen:
            continue
        if irreducible(p) and real_count(p) == real:
            seen.add(p)
            found.append(p)
    return found


def quartic_cases(rng):
    seen = set()
    cases = [("quartic_no_real", poly(X**4 + X + 1))]
    cases += [("quartic_no_real", p) for p in quartics_where(rng, 4, 0, seen)]
    cases += [("quartic_two_real", poly(X**4 - X - 1)), ("quartic_two_real", poly(X**4 + X**3 - 3))]
    cases += [("quartic_two_real", p) for p in quartics_where(rng, 5, 2, seen)]
    cases += [("quartic_four_real", poly(X**4 - 4 * X**3 + X**2 + 4 * X - 1))]
    cases += [("quartic_four_real", p) for p in quartics_where(rng, 5, 4, seen)]
    cases += [("quartic_two_quadratic_factors", poly(e)) for e in
              [(X**2 - 2) * (X**2 + X - 1), (X**2 + X + 1) * (X**2 - 3 * X + 1),
               (X**2 - X - 3) * (X**2 + 2 * X - 1)]]
    cases += [("quartic_double_irrational", poly(e)) for e in
              [(X**2 - X - 1)**2, (X**2 + 2 * X - 1)**2, (X**2 - 3 * X + 1)**2,
               (2 * X**2 - 2 * X - 1)**2]]
    cases += [("quartic_two_rational", poly(e)) for e in
              [(X - 1) * (2 * X + 3) * (X**2 + X - 1), (X + 2) * (X - 3) * (X**2 + 1),
               (X - 1)**2 * (X**2 - 5), (3 * X - 1) * (X + 1) * (X**2 - 2 * X - 2)]]
    cases += [("quartic_root_zero", poly(e)) for e in
              [X * (X**3 - 3 * X + 1), X * (X**3 + X + 1), X * (X - 1) * (X**2 - 3),
               X * (2 * X**3 - 5 * X**2 - 4 * X + 1)]]
    cases += [("quadratic_in_disguise", poly(e)) for e in
              [X**4 - 5 * X**2 + 6, X**4 - X**2 - 1, 2 * X**4 + 3 * X**2 - 7, X**4 + X**2 + 1,
               X**2 * (X**2 - X - 1), (X**2 - 2)**2]]
    return cases


# --- symbolic coefficients with values --------------------------------------------------------

def value(rng, bound=8):
    """A nonzero multiple of 1/8 in [-bound, bound], as an exact Fraction."""
    while True:
        v = Fraction(rng.randint(-8 * bound, 8 * bound), 8)
        if v != 0:
            return v


def decimal(v):
    """The exact decimal of a multiple of 1/8."""
    s = f"{float(v):.3f}".rstrip("0").rstrip(".")
    assert Fraction(s) == v, (v, s)
    return s


def reduced_coefficients(p):
    """p, q (and r for a quartic) of the reduced (depressed) form of `p`."""
    n = p.degree()
    a = p.all_coeffs()
    t = sympy.Symbol("t")
    shifted = sympy.Poly(sympy.expand(p.as_expr().subs(X, t - a[1] / (n * a[0])) / a[0]), t)
    return [shifted.nth(k) for k in range(n - 2, -1, -1)]


def safe(p, reduced):
    """Roots more than 1e-3 apart; the discriminant, and when `reduced` the coefficients of
    the reduced form, more than 1e-3 from zero."""
    quantities = [discriminant(p)] + (reduced_coefficients(p) if reduced else [])
    return all(abs(v) > sympy.Rational(1, 1000) for v in quantities) and min_root_gap(p) > 1e-3


def symbolic_cases(rng):
    forms = [
        # kind, form, real roots, cases, whether the reduced form's coefficients are kept
        # from zero (a pure cube's and a biquadratic's are zero by their form)
        ("symbolic_cubic", "a*x^3 + b*x^2 + c*x + d", 3, 4, True),
        ("symbolic_cubic", "a*x^3 + b*x^2 + c*x + d", 1, 4, True),
        ("symbolic_reduced_cubic", "x^3 + p*x + q", 3, 2, True),
        ("symbolic_reduced_cubic", "x^3 + p*x + q", 1, 2, True),
        ("symbolic_pure_cubic", "a*x^3 + d", 1, 1, False),
        ("symbolic_quartic", "a*x^4 + b*x^3 + c*x + d", 0, 2, True),
        ("symbolic_quartic", "a*x^4 + b*x^3 + c*x + d", 2, 3, True),
        ("symbolic_quartic", "a*x^4 + b*x^3 + c*x + d", 4, 2, True),
        ("symbolic_quadratic_in_disguise", "a*x^2 + b*x + c", 2, 1, True),
        ("symbolic_quadratic_in_disguise", "a*x^3 + b*x^2 + c*x", 3, 1, False),
        ("symbolic_quadratic_in_disguise", "a*x^4 + b*x^2 + c", 2, 1, False),
    ]
    cases = []
    for kind, form, real, count, reduced in forms:
        e = sympy.sympify(form.replace("^", "**"), locals=dict(SYMBOLS, x=X))
        names = sorted(str(s) for s in e.free_symbols if s != X)
        made = 0
        while made < count:
            values = {n: value(rng) for n in names}
            p = poly(e.subs({SYMBOLS[n]: sympy.Rational(v.numerator, v.denominator)
                             for n, v in values.items()}))
            if real_count(p) != real or not safe(p, reduced):
                continue
            cases.append((kind, form, p, ", ".join(f"{n}={decimal(values[n])}" for n in names)))
            made += 1
    return cases


def main():
    rng = random.Random(SEED)
    lines = []
    for kind, p in cubic_cases(rng) + quartic_cases(rng):
        roots = real_roots(p)
        lines.append(f"{kind} | {text(p.as_expr())} | x | - | {', '.join(roots) or 'none'}")
    for kind, form, p, values in symbolic_cases(rng):
        roots = real_roots(p)
        lines.append(f"{kind} | {form} | x | {values} | {', '.join(roots) or 'none'}")
    header = [
        "# Cubics and quartics in x and their real roots by mpmath at 50 digits.",
        "# Generated by: python3 benches/compare/polynomial_roots.py",
        f"# mpmath {mpmath.__version__}, SymPy {sympy.__version__}, Python random seed {SEED};"
        f" {len(lines)} cases.",
        "# kind | polynomial (= 0) | unknown | values of the other symbols, or - |"
        " distinct real roots ascending, 25 significant digits, or none",
    ]
    OUTPUT.write_text("\n".join(header + lines) + "\n")
    print(f"wrote {len(lines)} cases to {OUTPUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
