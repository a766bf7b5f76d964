//! The operation count `simplify` minimises, on expressions as people type them.

use kinetics::algebra::Expr;
use kinetics::parse::parse_expression;

fn count(text: &str) -> usize {
    parse_expression("<test>", text).unwrap().operation_count()
}

#[test]
fn counts_as_written() {
    assert_eq!(count("a"), 0);
    assert_eq!(count("3"), 0);
    assert_eq!(count("-3"), 1);
    assert_eq!(count("1/2"), 1);
    assert_eq!(count("a + b"), 1);
    assert_eq!(count("a - b"), 1);
    assert_eq!(count("-a - b"), 2);
    assert_eq!(count("a*b*c"), 2);
    assert_eq!(count("a/b"), 1);
    assert_eq!(count("1/a"), 1);
    assert_eq!(count("a^2"), 1);
    assert_eq!(count("sqrt(a)"), 1);
    assert_eq!(count("a^(n+1)"), 2);
    assert_eq!(count("1/2*m*v^2"), 3);
    assert_eq!(count("sin(x)^2 + cos(x)^2"), 5);
    assert_eq!(count("-6*F*Dt*b/(m*(b^2 + c^2))"), 9);
}

#[test]
fn a_minus_costs_once_however_it_is_written() {
    assert_eq!(count("a - b"), count("a + b"));
    assert_eq!(count("-a*b"), 1 + count("a*b"));
    assert_eq!(Expr::symbol("x").operation_count(), 0);
}

/// Below the fraction bar a leading minus and a fraction in a term each cost one more: a
/// reader carries them across the bar. By SymPy's count `a ω_x/(−L² − ¼r²)` (7) would beat
/// `−4 a ω_x/(4L² + r²)` (8); here it counts 9.
#[test]
fn a_minus_or_a_fraction_below_the_bar_costs_one_more() {
    assert_eq!(count("a*w_x/(-L^2 - 1/4*r^2)"), 9);
    assert_eq!(count("-4*a*w_x/(4*L^2 + r^2)"), 8);
    assert_eq!(count("1/(a - b)"), 2);
    // A minus on each term: one negation, and one more carried across the bar.
    assert_eq!(count("1/(-a - b)"), count("1/(a + b)") + 2);
}
