//! The corpus `tests/data/cancel_corpus.txt` itself (made by
//! `benches/compare/cancel_corpus.py`): every line parses, and for each case SymPy's
//! `numerator / denominator` has the input's value, checked in double-double at points
//! away from the poles. The comparison with kinetics' own `cancel` is elsewhere; this only
//! makes sure the corpus says what it claims.

use kinetics::algebra::{Expr, Symbol};
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use kinetics::parse::parse_expression;

/// One case of the corpus: the input and SymPy's cancelled form.
pub struct Case {
    pub line: usize,
    pub input: Expr,
    pub numerator: Expr,
    pub denominator: Expr,
}

/// Points each case is checked at, and how many of them may be skipped (near a pole).
const POINTS: u64 = 6;
const MAY_SKIP: u64 = 2;

/// Below this magnitude a denominator counts as a pole (the input loses the digits).
const NEAR_POLE: f64 = 1e-6;

pub fn corpus() -> Vec<Case> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/cancel_corpus.txt");
    let text = std::fs::read_to_string(path).expect("the corpus exists");
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let mut cases = Vec::new();
    while let Some((line, first)) = lines.next() {
        let field = |(n, l): (usize, &str), key: &str| {
            let text = l
                .strip_prefix(key)
                .and_then(|rest| rest.strip_prefix(": "))
                .unwrap_or_else(|| panic!("line {}: expected `{key}: `, found {l:?}", n + 1));
            parse_expression(&format!("cancel_corpus.txt:{}", n + 1), text)
                .unwrap_or_else(|d| panic!("{}", d.render()))
        };
        let input = field((line, first), "input");
        let numerator = field(lines.next().expect("a numerator line"), "numerator");
        let denominator = field(lines.next().expect("a denominator line"), "denominator");
        cases.push(Case {
            line: line + 1,
            input,
            numerator,
            denominator,
        });
    }
    cases
}

/// A value in [1/2, 3) for each symbol at point `k`, from its name: each byte mixed in by
/// SplitMix64's finaliser, so that names one letter apart get unrelated values.
fn value(symbol: Symbol, k: u64) -> f64 {
    let mix = |mut z: u64| {
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    };
    let h = symbol.name().bytes().fold(mix(k + 1), |h, byte| {
        mix(h
            .wrapping_add(u64::from(byte))
            .wrapping_mul(0x9E37_79B9_7F4A_7C15))
    });
    0.5 + 2.5 * ((h >> 11) as f64 / (1u64 << 53) as f64)
}

#[test]
fn the_corpus_has_at_least_200_cases_and_each_parses() {
    let cases = corpus();
    assert!(cases.len() >= 200, "only {} cases", cases.len());
}

#[test]
fn sympys_cancelled_form_has_the_value_of_the_input() {
    for case in corpus() {
        let mut skipped = 0;
        for k in 0..POINTS {
            let at = |s: Symbol| Some(Dd::from(value(s, k)));
            let den: Dd = case.denominator.eval(&at).expect("a finite denominator");
            let Ok(input) = case.input.eval(&at) else {
                skipped += 1;
                continue;
            };
            if den.abs().to_f64() < NEAR_POLE {
                skipped += 1;
                continue;
            }
            let num: Dd = case.numerator.eval(&at).expect("a finite numerator");
            let difference = (num - input * den).abs().to_f64();
            let scale = 1.0 + num.abs().to_f64() + (input * den).abs().to_f64();
            assert!(
                difference <= 1e-20 * scale,
                "line {}: {} is not ({}) / ({}) at point {k}: they differ by {difference:e}",
                case.line,
                case.input,
                case.numerator,
                case.denominator
            );
        }
        assert!(
            skipped <= MAY_SKIP,
            "line {}: {skipped} of {POINTS} points skipped",
            case.line
        );
    }
}
