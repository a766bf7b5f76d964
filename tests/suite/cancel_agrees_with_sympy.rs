//! `cancelled_parts` against SymPy's `cancel` on the corpus `tests/data/cancel_corpus.txt`
//! (`benches/compare/cancel_corpus.py`): the same numerator and denominator, but for two
//! conventions of SymPy's: a denominator that is a number is left in the numerator's
//! coefficients (`20/7 c − 20/7` over `1`, where `cancel` gives `20c − 20` over `7`), and
//! the sign of a denominator follows SymPy's order of the generators (ours is the canonical
//! order of expressions, its the order of names), so a pair may be SymPy's negated.

use crate::cancel_corpus_parses::corpus;

#[test]
fn cancel_agrees_with_sympy_on_the_corpus() {
    let mut identical = 0;
    for case in corpus() {
        let (p, q) = case.input.cancelled_parts().unwrap();
        let (n, d) = (&case.numerator, &case.denominator);
        if p == *n && q == *d {
            identical += 1;
            continue;
        }
        let negated = -&p == *n && -&q == *d;
        let number_over_one =
            q.as_num().is_some() && d.is_one() && (&p / &q).expand().unwrap() == *n;
        assert!(
            negated || number_over_one,
            "line {}: cancel gives ({p}, {q}), SymPy ({n}, {d})",
            case.line
        );
    }
    assert!(
        identical >= 200,
        "only {identical} cases identical to SymPy's"
    );
}
