//! Reading a claim (`parse_claim`, issue 16): the cross product (`×`, `cross(a, b)` and the
//! letter `x` between vectors), `dot(a, b)`, the product sign `·`, calls of several
//! arguments, names resolved while the claim is read, the written terms with their spans,
//! and every error of a claim's shape, each at its column. Values are written by hand.

use kinetics::algebra::Expr;
use kinetics::parse::claim::{Claim, Name};
use kinetics::parse::{parse_claim, parse_expression, Diagnostic};
use proptest::prelude::*;
use std::cell::RefCell;

fn s(name: &str) -> Expr {
    Expr::symbol(name)
}

fn ijk() -> [Expr; 3] {
    [s("i"), s("j"), s("k")]
}

/// Every name a symbol of its own.
fn symbols(_: &str) -> Name {
    Name::Symbol
}

fn claim(text: &str) -> Claim {
    parse_claim("claim", text, &symbols).unwrap_or_else(|d| panic!("{}", d.render()))
}

fn refused(text: &str) -> Diagnostic {
    match parse_claim("claim", text, &symbols) {
        Ok(c) => panic!("{text:?} was read as {c:?}"),
        Err(d) => d,
    }
}

/// The error of `text`: its message holds `message`, at `column` (1-based, in characters).
fn assert_refused(text: &str, message: &str, column: usize) -> Diagnostic {
    let d = refused(text);
    assert!(d.message.contains(message), "{text:?}: {}", d.render());
    assert_eq!((d.line, d.column), (1, column), "{text:?}: {}", d.render());
    d
}

/// The notes' cross product, in the three ways it may be written.
#[test]
fn the_cross_product_of_the_notes() {
    let [i, j, k] = ijk();
    let (w1, w2, l, r) = (s("w1"), s("w2"), s("L"), s("r"));
    let expected = -(&r * &w1 + &l * &w2) * &k;
    for text in [
        "(w1 i + w2 j) × (L i - r j) = 0",
        "cross(w1 i + w2 j, L i - r j) = 0",
        "(w1 i + w2 j) x (L i - r j) = 0",
    ] {
        assert_eq!(claim(text).lhs.value, expected, "{text}");
    }
    let general = claim("(a i + b j + c k) × (d i + e j + f k) = 0").lhs.value;
    let (a, b, c, d, e, f) = (s("a"), s("b"), s("c"), s("d"), s("e"), s("f"));
    let by_hand = (&b * &f - &c * &e) * &i + (&c * &d - &a * &f) * &j + (&a * &e - &b * &d) * &k;
    assert_eq!(general.expand().unwrap(), by_hand.expand().unwrap());
}

/// `×` is left-associative; unit vectors cross as i × j = k; zero is the zero vector.
#[test]
fn unit_vectors_cross_cyclically_and_left_to_right() {
    let [i, j, k] = ijk();
    assert_eq!(claim("cross(i, j) = k").lhs.value, k);
    assert_eq!(claim("j × k = i").lhs.value, i);
    assert_eq!(claim("k × j = -i").lhs.value, -&i);
    assert_eq!(claim("i × j × k = 0").lhs.value, Expr::zero());
    assert_eq!(claim("i × (i × j) = -j").lhs.value, -&j);
    assert_eq!(claim("(i × i) × j = 0").lhs.value, Expr::zero());
    assert_eq!(claim("dot(2 i + j, 3 i + a k) = 6").lhs.value, Expr::int(6));
    assert_eq!(
        claim("dot(a i, b i + c j) = a b").lhs.value,
        s("a") * s("b")
    );
}

/// `×` binds looser than `*`, `/`, `·` and juxtaposition, tighter than `+` and `-`.
#[test]
fn the_cross_product_binds_between_sums_and_products() {
    let [i, j, k] = ijk();
    let (a, b, m) = (s("a"), s("b"), s("m"));
    assert_eq!(claim("k + i × 2 j = 3 k").lhs.value, Expr::int(3) * &k);
    assert_eq!(claim("2 i × j = 0").lhs.value, Expr::int(2) * &k);
    assert_eq!(
        claim("a i × m b j / 2 = 0").lhs.value,
        Expr::rational(1, 2) * &a * &b * &m * &k
    );
    assert_eq!(claim("i × a·j - j = 0").lhs.value, &a * &k - &j);
    assert_eq!(claim("2·m = a").lhs.value, Expr::int(2) * &m);
    assert_eq!(claim("i × j + j × k = 0").lhs.value, &k + &i);
}

/// The context's vectors are formed before the cross product: `H_G + rbar × m vbar`.
#[test]
fn derived_names_are_resolved_before_the_cross_product() {
    let [i, j, k] = ijk();
    let h_g = s("H_x") * &i + s("H_y") * &j + s("H_z") * &k;
    let rbar = s("x_G") * &i + s("y_G") * &j;
    let vbar = s("v_x") * &i + s("v_y") * &j;
    let asked = RefCell::new(Vec::new());
    let resolve = |name: &str| {
        asked.borrow_mut().push(name.to_string());
        match name {
            "H_G" => Name::Derived(h_g.clone()),
            "rbar" => Name::Derived(rbar.clone()),
            "vbar" => Name::Derived(vbar.clone()),
            "H_O" => Name::Derived(Expr::symbol("H_Ox") * &i),
            _ => Name::Symbol,
        }
    };
    let text = "H_O + 0 rbar = H_G + rbar × m vbar + 0 rbar + 0 pi deg";
    let c = parse_claim("claim", text, &resolve).unwrap();
    let m = s("m");
    let z = s("H_z") + &m * (s("x_G") * s("v_y") - s("y_G") * s("v_x"));
    let expected = s("H_x") * &i + s("H_y") * &j + z * &k;
    assert_eq!(c.rhs.value.expand().unwrap(), expected.expand().unwrap());
    assert_eq!(c.lhs.resolved, ["H_O", "rbar"]);
    assert_eq!(c.rhs.resolved, ["H_G", "rbar", "vbar"]);
    assert_eq!(*asked.borrow(), ["H_O", "rbar", "H_G", "m", "vbar"]);
    // The letter x between the resolved vectors is the cross product too.
    let letter = parse_claim("claim", "rbar x m vbar = 0", &resolve).unwrap();
    let cross = parse_claim("claim", "rbar × m vbar = 0", &resolve).unwrap();
    assert_eq!(letter.lhs.value, cross.lhs.value);
}

/// An unknown name is refused at the name with the resolver's help.
#[test]
fn unknown_names_are_refused_where_written() {
    let resolve = |name: &str| match name {
        "q" => Name::Unknown("did you mean w?".into()),
        _ => Name::Symbol,
    };
    let d = parse_claim("claim", "T = 1/2 m q^2", &resolve).unwrap_err();
    assert_eq!(d.message, "unknown name 'q'");
    assert_eq!(d.column, 11);
    assert_eq!(d.help.as_deref(), Some("did you mean w?"));
}

/// The letter x is the cross product only between two vectors, in a claim only.
#[test]
fn the_letter_x_is_a_cross_product_only_between_vectors() {
    let (a, b, x) = (s("a"), s("b"), s("x"));
    assert_eq!(claim("(a) x (b) = x").lhs.value, &a * &x * &b);
    assert_eq!(
        claim("x i + a x j = 0").lhs.value,
        &x * s("i") + &a * &x * s("j")
    );
    assert_eq!(claim("(a i) x b = 0").lhs.value, &a * &b * &x * s("i"));
    assert_eq!(parse_expression("e", "(a) x (b)").unwrap(), &a * &x * &b);
    assert_eq!(
        parse_expression("e", "(a i) x (b j)").unwrap(),
        &a * &b * &x * s("i") * s("j")
    );
    // Two letters side by side are names, and a product of two vectors then.
    assert_refused("(a i) x x (b j) = 0", "a product of two vectors", 1);
}

/// The written terms of a side: the sum's items with their signs as values, each span
/// covering the sign and the term's text; they add up to the side's value.
#[test]
fn written_terms_keep_their_text_and_sign() {
    let text = "  T  =  1/2 m v^2 - I_x w_x^2 + -c - (a + b)  ";
    let c = claim(text);
    let written = |span: (usize, usize)| &text[span.0..span.1];
    assert_eq!(written(c.lhs.span), "T");
    assert_eq!(written(c.rhs.span), "1/2 m v^2 - I_x w_x^2 + -c - (a + b)");
    let terms: Vec<&str> = c.rhs.terms.iter().map(|t| written(t.span)).collect();
    assert_eq!(terms, ["1/2 m v^2", "- I_x w_x^2", "+ -c", "- (a + b)"]);
    let values: Vec<Expr> = c.rhs.terms.iter().map(|t| t.value.clone()).collect();
    assert_eq!(values[1], -(s("I_x") * s("w_x").powi(2)));
    assert_eq!(values[2], -s("c"));
    assert_eq!(values[3], -s("a") - s("b"));
    assert_eq!(Expr::add_all(values), c.rhs.value);
    assert_eq!(c.lhs.terms.len(), 1);
    assert_eq!(written(c.lhs.terms[0].span), "T");
    // A parenthesised sum is one term; a sum after it is another.
    let p = claim("(a + b) + c = -(d + e)");
    let terms: Vec<&str> = p
        .lhs
        .terms
        .iter()
        .map(|t| &"(a + b) + c"[t.span.0..t.span.1])
        .collect();
    assert_eq!(terms, ["(a + b)", "+ c"]);
    assert_eq!(p.rhs.terms.len(), 1);
    let whole = claim("(a + b) = c");
    assert_eq!(whole.lhs.terms.len(), 1);
    assert_eq!(whole.lhs.terms[0].span, (0, 7));
}

/// The shape of a claim: one '=', two sides that are not empty, and a vector equated
/// only to a vector (or zero).
#[test]
fn errors_of_a_claims_shape_are_located() {
    let d = assert_refused("T 1/2 m v^2", "a claim is an equation: expected '='", 12);
    assert!(d.help.is_some());
    assert_refused("a = b = c", "a claim has one '='", 7);
    assert_refused("  = b", "the left side of the claim is empty", 3);
    assert_refused("a =  ", "the right side of the claim is empty", 4);
    let d = assert_refused("2 i + a j = m", "a vector equated to a scalar", 13);
    assert!(
        d.message.contains("'2 i + a j'") && d.message.contains("'m'"),
        "{d}"
    );
    assert_refused("w_x = cross(i, j)", "a vector equated to a scalar", 1);
    assert_eq!(claim("(a i) × (b i) = 0").lhs.value, Expr::zero());
    assert_refused("a + = b", "expected an expression", 5);
}

/// Vectors where a claim has no meaning for them, each refused at the text written.
#[test]
fn misused_vectors_are_located() {
    let d = assert_refused(
        "(a i) (b j) = 0",
        "a product of two vectors, '(a i) (b j)'",
        1,
    );
    let help = d.help.unwrap_or_default();
    assert!(help.contains('×') && help.contains("cross(a, b)"), "{help}");
    assert_refused("i j = k", "a product of two vectors, 'i j'", 1);
    assert_refused("m i·j = 0", "a product of two vectors, 'i·j'", 3);
    assert_refused("(i j) = 0", "a product of two vectors, 'i j'", 2);
    assert_refused("m (i j) = 0", "a product of two vectors, '(i j)'", 3);
    assert_refused(
        "m × i = 0",
        "the cross product needs two vectors; 'm' is a scalar",
        1,
    );
    assert_refused("cross(i, 2 m) = 0", "'2 m' is a scalar", 10);
    assert_refused("dot(i, m) = 0", "the scalar product needs two vectors", 8);
    assert_refused(
        "a i + b = 0",
        "the scalar 'b' is added to the vector 'a i'",
        7,
    );
    assert_refused("a/(b i) = 0", "dividing by a vector, 'i'", 6);
    assert_refused("sin(i) = 0", "sin of a vector, 'i'", 1);
    assert_refused("2 + i^2 = 1", "a power of a vector", 5);
}

/// Calls take their number of arguments, separated by commas.
#[test]
fn calls_check_their_arguments() {
    assert_refused("cross(i) = 0", "cross takes two arguments, found 1", 1);
    assert_refused(
        "a + dot(i, j, k) = 0",
        "dot takes two arguments, found 3",
        5,
    );
    assert_refused("sin(a, b) = 0", "sin takes one argument, found 2", 1);
    assert_refused("cross(i,) = 0", "expected an expression", 9);
    assert_refused("f(i, j) = 0", "unknown function f", 1);
    assert_eq!(claim("sin(30 deg) = a").lhs.value, Expr::rational(1, 2));
}

/// `×`, `·` and the calls of two arguments read the same in an expression; the letter x
/// does not.
#[test]
fn expressions_read_the_new_operators() {
    let [i, _, k] = ijk();
    assert_eq!(parse_expression("e", "cross(i, j)").unwrap(), k);
    assert_eq!(
        parse_expression("e", "j × k · 2").unwrap(),
        Expr::int(2) * &i
    );
    assert_eq!(parse_expression("e", "2·a").unwrap(), Expr::int(2) * s("a"));
    let d = parse_expression("e", "a × b").unwrap_err();
    assert!(d.message.contains("needs two vectors"), "{d}");
}

/// Calls of two arguments nested deep with an error inside are read once (no alternative
/// of the grammar re-reads what a failed one read): the error is found at once, located.
/// The guard only turns a hang (2^depth re-reads) into a failure.
#[test]
fn nested_calls_with_an_error_inside_are_read_in_linear_time() {
    let depth = 60;
    let text = format!(
        "{}a + = 0{}",
        "dot(i, cross(j, ".repeat(depth),
        "))".repeat(depth)
    );
    let column = text.find('=').unwrap_or_default() + 1;
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(parse_claim("claim", &text, &symbols).map(|_| ()));
    });
    let outcome = receive.recv_timeout(std::time::Duration::from_secs(30));
    let Ok(Err(d)) = outcome else {
        panic!("not refused within 30 s: {outcome:?}");
    };
    assert_eq!(d.column, column, "{}", d.render());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2_000, ..ProptestConfig::default() })]

    /// No text made of a claim's characters makes the reader panic.
    #[test]
    fn any_text_is_read_or_refused(text in "[aijkx0-9 ()+\\-*/^=,×·.]{0,40}") {
        let _ = parse_claim("claim", &text, &symbols);
        let _ = parse_expression("e", &text);
    }

    /// The written terms of a sum add up to its side's value.
    #[test]
    fn written_terms_add_up(signs in proptest::collection::vec(any::<bool>(), 1..8)) {
        let rhs: String = signs
            .iter()
            .enumerate()
            .map(|(n, minus)| format!(" {} a_{n} (b + {n})", if *minus { "-" } else { "+" }))
            .collect();
        let c = claim(&format!("T ={rhs}"));
        prop_assert_eq!(c.rhs.terms.len(), signs.len());
        let total = Expr::add_all(c.rhs.terms.iter().map(|t| t.value.clone()));
        prop_assert_eq!(total, c.rhs.value);
    }
}

/// The minus sign − (U+2212), as pasted from a word processor, is a minus.
#[test]
fn the_unicode_minus_sign_is_a_minus() {
    let read = |text: &str| kinetics::parse_expression("test", text).expect("reads");
    assert_eq!(read("I_x w_x − I_xy w_y"), read("I_x w_x - I_xy w_y"));
    assert_eq!(read("−a"), read("-a"));
}
