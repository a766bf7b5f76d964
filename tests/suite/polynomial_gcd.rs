//! `polynomial_gcd` and `cancel` on random polynomials in up to eight symbols: the gcd
//! divides both operands exactly, a common factor divides the gcd, and a common factor of
//! numerator and denominator does not change the cancelled fraction.

use kinetics::algebra::{polynomial_gcd, Expr};
use kinetics::parse_expression;
use proptest::prelude::*;

const NAMES: [&str; 8] = ["a", "b", "c", "m", "x", "y", "z", "Dt"];

/// A random polynomial: up to five terms, each an integer in -5..=5 times up to three
/// symbols to powers 1..=2.
fn polynomial() -> impl Strategy<Value = Expr> {
    let term = (
        -5i64..=5,
        prop::collection::vec((0..NAMES.len(), 1i64..=2), 0..=3),
    )
        .prop_map(|(c, powers)| {
            Expr::mul_all(
                std::iter::once(Expr::int(c)).chain(
                    powers
                        .into_iter()
                        .map(|(i, k)| Expr::symbol(NAMES[i]).powi(k)),
                ),
            )
        });
    prop::collection::vec(term, 1..=5).prop_map(Expr::add_all)
}

/// Whether `divisor` divides `e` exactly: the cancelled `e / divisor` has denominator 1.
fn divides(divisor: &Expr, e: &Expr) -> bool {
    if divisor.is_zero() {
        return e.is_zero();
    }
    let (_, q) = (e / divisor).cancelled_parts().unwrap();
    q.is_one()
}

#[test]
fn examples() {
    let parse = |t: &str| parse_expression("test", t).unwrap();
    let gcd = |a: &str, b: &str| polynomial_gcd(&parse(a), &parse(b)).unwrap();
    assert_eq!(gcd("x^2 - y^2", "x^2 - 2*x*y + y^2"), parse("x - y"));
    assert_eq!(gcd("0", "0"), parse("0"));
    assert_eq!(gcd("0", "-2*x - 4"), parse("2*x + 4"));
    assert_eq!(gcd("6*x^2*y", "4*x*y^3"), parse("2*x*y"));
    assert_eq!(gcd("x/2 + 1/2", "x^2 - 1"), parse("x + 1"));
    assert_eq!(
        gcd("(a + b)*(a - c)*(b + c)^2", "(a - c)^2*(b + c)*(a + 7)"),
        parse("(a - c)*(b + c)").expand().unwrap()
    );
    assert_eq!(gcd("6", "-4"), parse("2"));
    assert!(polynomial_gcd(&parse("1/x"), &parse("x")).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1_000, ..ProptestConfig::default() })]

    #[test]
    fn the_gcd_divides_both(p in polynomial(), q in polynomial(), g in polynomial()) {
        let (a, b) = ((&p * &g).expand().unwrap(), (&q * &g).expand().unwrap());
        let gcd = polynomial_gcd(&a, &b).unwrap();
        prop_assert!(divides(&gcd, &a), "gcd {gcd} does not divide {a}");
        prop_assert!(divides(&gcd, &b), "gcd {gcd} does not divide {b}");
        prop_assert!(divides(&g, &gcd), "common factor {g} does not divide the gcd {gcd}");
    }

    #[test]
    fn a_common_factor_cancels(p in polynomial(), q in polynomial(), g in polynomial()) {
        prop_assume!(!q.is_zero() && !g.is_zero());
        // Multiplied out, so that the factor is not cancelled as a base of the product.
        let with_factor = (&p * &g).expand().unwrap() / (&q * &g).expand().unwrap();
        prop_assert_eq!(with_factor.cancel().unwrap(), (&p / &q).cancel().unwrap());
    }
}
