//! Issue 14, the algebra's reproducers: huge exponents, powers of sums, powers of vectors
//! and products of huge numbers each give a correct result or a clean located error (exit
//! code 1, `error: ` first, the user's own text quoted), never a stack overflow, a hang or
//! a message quoting a multiplied-out term the user never wrote.

use crate::common::binary::kinetics;
use kinetics::algebra::{Expr, Q};

/// Exit code 1, nothing on standard output, the message, the location `input:1:1` of the
/// whole input and the user's text on the caret line; no number longer than the input's.
fn assert_located(args: &[&str], message: &str, quoted: &str) {
    let (code, stdout, stderr) = kinetics(args);
    assert_eq!(code, 1, "{args:?}: {stderr}");
    assert!(stdout.is_empty(), "{args:?}: {stdout}");
    assert!(stderr.starts_with("error: "), "{args:?}: {stderr}");
    assert!(stderr.contains(message), "{args:?}: {stderr}");
    assert!(
        stderr.contains(&format!("| {quoted}")),
        "{args:?}: {stderr}"
    );
    let longest_number = stderr
        .split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0);
    assert!(
        longest_number <= 19,
        "{args:?} quotes a long number: {stderr}"
    );
}

#[test]
fn an_exponent_beyond_i64_is_refused_without_recursing() {
    let input = "(a+b)^9223372036854775808";
    assert_located(
        &["simplify", "--expand", input],
        "the exponent 9223372036854775808 is out of range",
        input,
    );
    // Unexpanded, the power is a correct result as written.
    let (code, stdout, _) = kinetics(&["simplify", input]);
    assert_eq!((code, stdout.trim()), (0, "(a + b)^9223372036854775808"));
}

#[test]
fn a_power_of_a_vector_is_refused_as_written() {
    for input in ["(a+i)^9223372036854775808", "(3*v-i)^600"] {
        assert_located(
            &["latex", input],
            &format!("a power of a vector, '{input}', has no meaning"),
            input,
        );
    }
}

/// The vector conversion's other errors point at the input, not at expanded terms.
#[test]
fn vector_errors_quote_the_input() {
    let input = "(3*v+1)^40 + i";
    assert_located(&["latex", input], "has no unit vector", input);
    assert_located(&["latex", "w*i*j"], "multiplies unit vectors", "w*i*j");
}

/// Powers of sums by the multinomial theorem: the exact result (counted terms, the value
/// at ones), and the ones past the bounds refused at once.
#[test]
fn powers_of_sums_expand_exactly_or_are_refused() {
    let s = Expr::symbol;
    let cases = [
        (s("a") + s("b"), 800, 801, 2),
        (s("a") + s("b") + s("c") + s("d"), 50, 23_426, 4),
    ];
    for (base, n, terms, at_ones) in cases {
        let expanded = base.powi(n).expand().unwrap();
        assert_eq!(expanded.terms().len(), terms, "({base})^{n}");
        let ones = expanded.subs(&|_| Some(Expr::one())).unwrap();
        assert_eq!(ones, Expr::int(at_ones).powi(n), "({base})^{n} at ones");
    }
    assert_located(
        &["simplify", "--expand", "(a+b+c)^1000"],
        "more than the limit of 100000",
        "(a+b+c)^1000",
    );
    assert_located(
        &["simplify", "--expand", "(1e300*a+b)^40"],
        "digits, more than the limit of 10000",
        "(1e300*a+b)^40",
    );
}

/// Products of huge decimals: refused at the factor that crosses the bound in digits,
/// however many factors follow; below the bound, the exact product.
#[test]
fn products_of_huge_decimals_are_bounded_in_digits() {
    for count in [200, 10_000] {
        let input = vec!["1e308"; count].join("*");
        let (code, stdout, stderr) = kinetics(&["simplify", &input]);
        assert_eq!(code, 1, "{stderr}");
        assert!(stdout.is_empty());
        assert!(
            stderr.starts_with("error: the product of these numbers would have about"),
            "{stderr}"
        );
        assert!(stderr.contains("more than the limit of 10000"), "{stderr}");
    }
    let input = vec!["1e308"; 30].join("*");
    let (code, stdout, _) = kinetics(&["simplify", &input]);
    assert_eq!(code, 0);
    assert_eq!(stdout.trim(), format!("1{}", "0".repeat(308 * 30)));
    let exact = Q::parse_decimal("1e308").unwrap();
    assert!(Q::check_bits("x", Q::product_bits(&vec![exact; 40])).is_err());
}

/// A decimal beyond the documented range is refused where it is written.
#[test]
fn decimals_beyond_the_range_are_refused() {
    for input in ["1e4097", "2e9223372036854775808"] {
        let (code, _, stderr) = kinetics(&["simplify", input]);
        assert_eq!(code, 1, "{stderr}");
        assert!(
            stderr.contains(&format!("the number {input} is out of range")),
            "{stderr}"
        );
    }
}

/// A sum is bounded by its distinct denominators: many decimals sum exactly, the
/// reciprocals of thousands of primes (a denominator of some 12,000 digits) are refused.
#[test]
fn sums_are_bounded_by_their_distinct_denominators() {
    let decimals: Vec<String> = (1..=5000).map(|i| format!("0.{:03}", i % 1000)).collect();
    let (code, stdout, stderr) = kinetics(&["simplify", &decimals.join("+")]);
    assert_eq!((code, stdout.trim()), (0, "4995/2"), "{stderr}");
    let primes: Vec<u64> = (2u64..)
        .filter(|n| (2..).take_while(|d| d * d <= *n).all(|d| n % d != 0))
        .take(3000)
        .collect();
    let reciprocals: Vec<String> = primes.iter().map(|p| format!("1/{p}")).collect();
    let (code, _, stderr) = kinetics(&["simplify", &reciprocals.join("+")]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.starts_with("error: the sum of these numbers would have about"),
        "{stderr}"
    );
}
