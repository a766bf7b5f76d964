//! The pieces of input that have broken the program before (issues 14 and 29), as text:
//! numbers at and beyond the limits of f64 and i64, huge exponents, deep nesting, unclosed
//! calls, unit vectors in powers, the signs and zeros that make a mass or a length absurd;
//! and issue 29's shapes ([`Shape`]): chains of `**` and of signed exponents, minus signs
//! between powers, implicit products, nests of functions with sums inside, long flat chains
//! (up to the 1 MiB input limit), control characters, and text that would inject markup
//! into an output format ([`title`], [`control`]).

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
/// powers of sums, products of huge decimals, and now and then one of issue 29's shapes.
pub fn construct(r: &mut Random) -> String {
    let n = r.size(40);
    match r.below(10) {
        7..=9 => any_shape(r),
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

/// Issue 29's shapes, each named so a finding can be traced to the construct that made it.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// `x**x**…**x`: `**` was not counted by the nesting limit (7,500 overflow the stack).
    DoubleStarChain,
    /// `1e-1^1e-1^…`: a signed exponent in a number reset the count.
    SignedExponentChain,
    /// `-x^-x^-x…`, `-(-(-x)^2)^2`: unary minus between powers.
    MinusPowerChain,
    /// `2x(3y(4z(…)))`, `a b c …`: products without a sign.
    ImplicitProducts,
    /// `sin(a + b*cos(c + sqrt(…)))`: functions nested with sums, squares and
    /// `sin² + cos²` inside (a 762-byte one took 9.6 s in `simplify`).
    FunctionNest,
    /// A sum, product or chain of powers up to 1 MiB (`a^2*b^3*…`, `sin(a_0) + sin(a_1) + …`).
    FlatChain,
}

impl Shape {
    pub const ALL: [Shape; 6] = [
        Shape::DoubleStarChain,
        Shape::SignedExponentChain,
        Shape::MinusPowerChain,
        Shape::ImplicitProducts,
        Shape::FunctionNest,
        Shape::FlatChain,
    ];
}

const NAMES: [&str; 8] = ["a", "b", "c", "m", "r", "t", "w_x", "theta"];

/// One of issue 29's shapes, any.
pub fn any_shape(r: &mut Random) -> String {
    let which = *r.pick(&Shape::ALL);
    shape(r, which)
}

/// One of issue 29's shapes, its size drawn small far more often than large.
pub fn shape(r: &mut Random, shape: Shape) -> String {
    let x = *r.pick(&NAMES);
    match shape {
        Shape::DoubleStarChain => {
            let op = *r.pick(&["**", "^", "**-", " ** "]);
            chain(x, op, r.size(10_000))
        }
        Shape::SignedExponentChain => {
            let number = *r.pick(&["1e-1", "2e+0", "1E-300", "-1e-1", "5e-324", "1.5e-2"]);
            chain(number, "^", r.size(10_000))
        }
        Shape::MinusPowerChain => {
            let n = r.size(2_000);
            match r.below(3) {
                0 => chain(x, "^-", n),
                1 => format!("{}{x}{}", "-(".repeat(n), ")^2".repeat(n)),
                _ => format!("{}{x}", "-".repeat(n)),
            }
        }
        Shape::ImplicitProducts => {
            let n = r.size(400);
            match r.below(3) {
                0 => {
                    (0..n)
                        .map(|i| format!("{}{}(", i + 2, NAMES[i % 8]))
                        .collect::<String>()
                        + x
                        + &")".repeat(n)
                }
                1 => repeat_joined(&format!("{x} 2"), " ", r.size(50_000)),
                _ => repeat_joined(&format!("({x}+1)"), "", r.size(5_000)),
            }
        }
        Shape::FunctionNest => {
            let depth = r.size(200);
            function_nest(r, depth)
        }
        Shape::FlatChain => {
            let bytes = r.size(1 << 20);
            flat_chain(r, bytes)
        }
    }
}

/// `x op x op … x`, `n` operators.
fn chain(x: &str, op: &str, n: usize) -> String {
    let mut s = String::with_capacity(n * (x.len() + op.len()) + x.len());
    s.push_str(x);
    for _ in 0..n {
        s.push_str(op);
        s.push_str(x);
    }
    s
}

fn repeat_joined(unit: &str, separator: &str, n: usize) -> String {
    vec![unit; n.max(1)].join(separator)
}

/// `depth` functions nested, each around a sum (or a square, or a `sin² + cos²` pair).
fn function_nest(r: &mut Random, depth: usize) -> String {
    const FUNCTIONS: [&str; 5] = ["sin", "cos", "tan", "sqrt", "abs"];
    let mut e = NAMES[r.below(8)].to_string();
    for level in 0..depth {
        let f = *r.pick(&FUNCTIONS);
        let (a, b) = (NAMES[level % 8], NAMES[(level + 3) % 8]);
        e = match r.below(6) {
            0 => format!("{f}({a} + {e})"),
            1 => format!("{f}({a} + {b}*{e})"),
            2 => format!("{f}({a} - {e})^2"),
            3 => format!("sin({a} + {e})^2 + cos({a} + {e})^2"),
            4 => format!("({a} + {b})*{f}({e} + {b})"),
            _ => format!("{f}({e})^2 + {b}"),
        };
        // The `sin² + cos²` pair doubles the text: kept to a few kilobytes.
        if e.len() > 8_000 {
            break;
        }
    }
    e
}

/// A flat chain of about `bytes` bytes: a sum, a product, or a chain of powers.
fn flat_chain(r: &mut Random, bytes: usize) -> String {
    let kind = r.below(8);
    let mut s = String::with_capacity(bytes + 16);
    let mut i = 0usize;
    while s.len() < bytes {
        let (n, m) = (NAMES[i % 8], i % 7 + 2);
        let term = match kind {
            0 => format!("{n}+"),
            1 => format!("a_{i}+"),
            2 => format!("{n}*"),
            3 => format!("{n}^{m}*"),
            4 => format!("a_{i}^{m}*"),
            5 => format!("sin(a_{i})+"),
            6 => format!("{n} {m} "),
            _ => format!("{m}^"),
        };
        s.push_str(&term);
        i += 1;
    }
    s.push('x');
    s
}

/// Characters a terminal, a bidirectional renderer or pdflatex takes for commands: ESC
/// sequences, other C0 and C1 controls, the bidirectional overrides, a byte-order mark, and
/// the replacement character a byte that is not UTF-8 becomes.
pub const CONTROLS: [&str; 12] = [
    "\u{1b}[2J",
    "\u{1b}]0;owned\u{7}",
    "\u{1b}[31m",
    "\u{7}",
    "\u{0}",
    "\u{8}",
    "\r",
    "\u{7f}",
    "\u{85}",
    "\u{202e}",
    "\u{feff}",
    "\u{fffd}",
];

/// Text that would inject markup if an output format left it raw: HTML in Markdown and
/// HTML, TeX commands and specials in LaTeX, links in Markdown.
pub const INJECTIONS: [&str; 12] = [
    "<script>alert(1)</script>",
    "$<script>$",
    "$x_{<img src=x onerror=alert(1)>}$",
    "\\input{/etc/passwd}",
    "$\\input{/etc/passwd}$",
    "\\immediate\\write18{id}",
    "$",
    "}",
    "&",
    "%",
    "[link](javascript:alert(1))",
    "# ^ _ ~ \\ { }",
];

/// A control character or sequence.
pub fn control(r: &mut Random) -> String {
    r.pick(&CONTROLS).to_string()
}

/// A scene's title made of words, injection strings and control characters.
pub fn title(r: &mut Random) -> String {
    let mut words = vec!["title".to_string()];
    for _ in 0..r.size(6) {
        words.push(match r.below(4) {
            0 | 1 => r.pick(&INJECTIONS).to_string(),
            2 => control(r),
            _ => r
                .pick(&["Sample", "Problem", "$\\omega_x$", "18.4"])
                .to_string(),
        });
    }
    words.join(" ")
}
