//! The measure `simplify` minimises: the count of operations a person writes, as SymPy's
//! `count_ops` counts them, read off the form the expression prints as.
//!
//! - a sum of n terms: n − 1 additions or subtractions (a term with a minus is subtracted;
//!   a minus on the first term, or on an expression standing alone, is one negation);
//! - a product: its factors with a negative exponent form one denominator; the numerator's
//!   n factors cost n − 1 multiplications, the denominator's likewise, and a denominator
//!   one division. A numeric coefficient `p/q` is the factor `|p|` over the factor `q`
//!   (a factor only where it is not 1); its sign is the term's minus;
//! - a power `b^e` (a root included) one operation, unless its exponent is −1, which is
//!   a denominator; `b^(−e)` in a denominator is `b^e`;
//! - a function one operation; a number or a symbol none, a non-integer number one division;
//! - a sum in a denominator one more for a leading minus and for each term with a fraction,
//!   which a reader carries across the bar (SymPy counts them as the rest).
//!
//! So `a + b` counts 1, `-6 F Δt b/(m (b² + c²))` counts 9 (a minus, three multiplications
//! above, one below, the division, two powers and an addition), and `sin(x)^2 + cos(x)^2` 5.
//! A numeric exponent is written as a superscript or a root and costs nothing beyond its
//! power.

use super::expr::{Expr, View};
use super::rational::Q;
use super::work;

impl Expr {
    /// The operation count of the module documentation.
    pub fn operation_count(&self) -> usize {
        let (negative, magnitude) = term_sign_and_magnitude(self);
        usize::from(negative) + magnitude
    }
}

/// Whether a term is written with a leading minus, and the count of operations of the
/// rest. A sum's terms share this: a minus turns the addition before it into a subtraction.
fn term_sign_and_magnitude(e: &Expr) -> (bool, usize) {
    if work::count_and_spent(1) {
        return (false, 0);
    }
    match e.view() {
        View::Num(q) => (q.is_negative(), usize::from(!q.is_integer())),
        View::Sym(_) => (false, 0),
        View::Add(terms) => {
            let mut count = terms.len() - 1;
            for (i, term) in terms.iter().enumerate() {
                let (negative, magnitude) = term_sign_and_magnitude(term);
                count += magnitude + usize::from(negative && i == 0);
            }
            (false, count)
        }
        View::Mul(factors) => {
            let coefficient = e.coefficient();
            let mut above = usize::from(!coefficient.numer().abs().is_one());
            let mut below = usize::from(!coefficient.denom().is_one());
            let mut operations = 0;
            for factor in factors.iter().filter(|f| f.as_num().is_none()) {
                let (in_denominator, cost) = factor_cost(factor);
                operations += cost;
                if in_denominator {
                    below += 1;
                } else {
                    above += 1;
                }
            }
            let products = above.saturating_sub(1) + below.saturating_sub(1);
            let division = usize::from(below > 0);
            (coefficient.is_negative(), operations + products + division)
        }
        View::Pow(..) => {
            let (in_denominator, cost) = factor_cost(e);
            // Standing alone, `1/x` is a division.
            (false, cost + usize::from(in_denominator))
        }
        View::Func(_, argument) => (false, 1 + argument.operation_count()),
    }
}

/// Whether a factor of a product stands in the denominator, and the operations it costs
/// there (its power written with the exponent's sign turned, when below).
fn factor_cost(factor: &Expr) -> (bool, usize) {
    let View::Pow(base, exponent) = factor.view() else {
        return (false, factor.operation_count());
    };
    let negative = exponent.as_num().is_some_and(Q::is_negative);
    let written_exponent = if negative {
        -exponent.clone()
    } else {
        exponent.clone()
    };
    let power = if written_exponent.is_one() {
        0
    } else if written_exponent.as_num().is_some() {
        1
    } else {
        1 + written_exponent.operation_count()
    };
    let below = match negative {
        true => carried_across_the_bar(base),
        false => 0,
    };
    (negative, base.operation_count() + power + below)
}

/// What a sum below the fraction bar makes a reader carry across it, one more operation
/// each: a leading minus, and a fraction within a term (`1/(−L² − ¼r²)` is read as
/// `−4/(4L² + r²)`).
fn carried_across_the_bar(denominator: &Expr) -> usize {
    let View::Add(terms) = denominator.view() else {
        return 0;
    };
    // A sum prints a positive term first when it has one (`b − a`).
    let leading_minus = usize::from(terms.iter().all(|t| t.coefficient().is_negative()));
    let fractions = terms
        .iter()
        .filter(|t| !t.coefficient().denom().is_one())
        .count();
    leading_minus + fractions
}
