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
