//! A rational coefficient and a power of a number with the same base are one canonical
//! form, however the product is built: the exponent of a numeric power is kept in (0, 1)
//! and its whole part folded into the coefficient, as SymPy does (`2^(-2/3) = 2^(1/3)/2`).

use kinetics::algebra::Expr;
use kinetics::parse::parse_expression;

fn parsed(text: &str) -> Expr {
    parse_expression("test", text).expect("the test's expression parses")
}

#[test]
fn a_coefficient_merges_with_a_numeric_power_of_its_base() {
    let cube_root = parsed("2^(1/3)");
    for text in [
        "2*2^(-2/3)",
        "2^(1/2)*2^(1/2)*2^(-2/3)",
        "2^(4/3)/2",
        "(2^(1/3))^4/2",
    ] {
        assert_eq!(parsed(text), cube_root, "{text}");
    }
    assert_eq!(parsed("2*2^(-2/3)").to_string(), "2^(1/3)");
    assert_eq!(parsed("2^(5/2)"), parsed("4*sqrt(2)"));
    assert_eq!(parsed("1/sqrt(2)"), parsed("sqrt(2)/2"));
}

/// The case `print_parse_properties::typed_input_parses_to_the_built_expression` once
/// failed on: built by the operators, `√2 · √2` is folded to 2 before the third factor
/// comes, while the parser reads the product at once.
#[test]
fn typed_roots_of_two_parse_to_the_built_expression() {
    let text = "sqrt(abs(2)) sqrt(abs(abs(-2))) ((abs(2))^(1/3))^(-2)";
    let two = Expr::int(2);
    let root = |p: i64, q: i64| two.checked_pow(&Expr::rational(p, q)).unwrap();
    let built = &(&root(1, 2) * &root(1, 2)) * &root(1, 3).powi(-2);
    assert_eq!(parsed(text), built);
    assert_eq!(built, root(1, 3));
}
