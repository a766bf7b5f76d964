//! The pieces of input that have broken the program before (issue 14), as text: numbers at
//! and beyond the limits of f64 and i64, huge exponents, deep nesting, unclosed calls,
//! unit vectors in powers, and the signs and zeros that make a mass or a length absurd.

use crate::random::Random;

/// Numbers: zero, negative, at f64's and i64's edges, and past them.
const NUMBERS: [&str; 18] = [
    "0",
    "-1",
    "1e300",
    "-1e300",
    "1e308",
    "1e-300",
    "1e200",
    "1e400",
    "9223372036854775807",
    "9223372036854775808",
    "18446744073709551616",
    "340282366920938463463374607431768211457",
    "0.000000000000000000000000000001",
    "123456789012345678901234567890.5",
    "2",
    "3",
    "0.5",
    "1",
];

/// A hostile number.
pub fn number(r: &mut Random) -> String {
    if r.one_in(8) {
        // A run of digits of any length up to a few hundred.
        let digits = r.size(400);
        return std::iter::once('1')
            .chain((1..digits).map(|_| char::from(b'0' + r.below(10) as u8)))
            .collect();
    }
    r.pick(&NUMBERS).to_string()
}

/// An exponent: small, large, at i64's edge or beyond it.
pub fn exponent(r: &mut Random) -> String {
    const EXPONENTS: [&str; 10] = [
        "2",
        "-1",
        "0",
        "50",
        "600",
        "800",
        "100000",
        "9223372036854775807",
        "9223372036854775808",
        "(-1/2)",
    ];
    r.pick(&EXPONENTS).to_string()
}

/// A construct that is costly or deep: nested calls with an error inside, unclosed calls,
/// powers of sums, products of huge decimals.
pub fn construct(r: &mut Random) -> String {
    let n = r.size(40);
    match r.below(7) {
        0 => format!("{}{}", "abs(".repeat(n), ")".repeat(n)),
        1 => "f(".repeat(n),
        2 => format!("{}x{}", "(".repeat(n * 5), ")".repeat(n * 5)),
        3 => format!("(a+b)^{}", exponent(r)),
        4 => format!("(3*v-{})^{}", r.pick(&["i", "j", "k"]), exponent(r)),
        5 => vec!["1e308"; r.size(2000)].join("*"),
        _ => format!("(a+b+c+d)^{}", r.size(120)),
    }
}

/// A token that can replace one of the input's: a number, a construct, a sign, a bracket.
pub fn token(r: &mut Random) -> String {
    match r.below(6) {
        0 | 1 => number(r),
        2 => construct(r),
        3 => format!("-{}", number(r)),
        4 => r
            .pick(&["(", ")", "^", "-", "*", "/", "=", ",", "i", "0*", "-"])
            .to_string(),
        _ => format!("^{}", exponent(r)),
    }
}
