//! `simplify`: of the equivalent forms the algebra can reach, the one with the fewest
//! operations as written ([`Expr::operation_count`]); the input itself is a candidate, so
//! the count never grows, and on a tie the earlier candidate stays.
//!
//! The candidates, after the arguments of functions and the radicands of roots are
//! simplified the same way (bottom up):
//!
//! 1. the input with radicals and absolute values of positive quantities taken out
//!    ([`Expr::simplify_radicals`]) and `sin² + cos² = 1` applied ([`Expr::simplify_trig`]);
//! 2. that form expanded, and reduced by the trigonometric identities again;
//! 3. that form in lowest terms ([`Expr::cancelled_parts`]), the denominator with its common
//!    factors pulled out and the numbers collected in front (`m (b² + c²)`), the numerator
//!    likewise when its terms share one kinematic part;
//! 4. that form over one denominator without expanding ([`Expr::together_parts`]), factored
//!    alike.
//!
//! A sum whose terms differ in their kinematic part (the product of their factors holding
//! a rate, an angular velocity, an acceleration) is simplified group by group, as the
//! textbook writes `(I_yz/l − m ȳ) α + (I_xz/l − m x̄) ω²` and `½ m v̄² + ½ I ω²`: each
//! group's coefficient takes the routes above on its own, and the sum is not brought over
//! one denominator (the printer groups its terms by kinematic part). A sum with no
//! kinematic symbol, a mass property such as `⅟₁₂ m b² + ⅟₁₂ m c²`, is offered factored.
//!
//! An expansion larger than [`MAX_READABLE_SIZE`] ends the search there: a form that
//! long is past reading, and the routes after it (trigonometry over every term, a
//! cancellation, common factors) would each take as long again.
//!
//! Each route is bounded as [`Expr::expand`] is. A route refused for size or work
//! ([`AlgebraError::is_beyond_bounds`]) is passed over, so a form too large for one route
//! still gets the others, and always at least its canonical form; never a hang.

use super::common_factor::content_and_primitive;
use super::domain::Domains;
use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::rational::Q;

/// Largest expansion, in nodes ([`Expr::has_at_most_size`]), the routes after the
/// expansion work on: about two thousand terms of a few factors each.
pub const MAX_READABLE_SIZE: usize = 20_000;

impl Expr {
    /// The shortest equivalent form; see the module documentation.
    ///
    /// ```
    /// use kinetics::algebra::{Domains, Expr};
    /// use kinetics::parse::parse_expression;
    /// let e = parse_expression("<doc>", "m_1*d/(m_1 + m_2) + m_2*d/(m_1 + m_2)").unwrap();
    /// assert_eq!(e.simplify(&Domains::chapter_defaults()).unwrap(), Expr::symbol("d"));
    /// ```
    pub fn simplify(&self, domains: &Domains) -> Result<Expr, AlgebraError> {
        let mut shortest = Shortest::new(self.clone());
        let Some(inside) = shortest.route(self.simplify_inside(domains))? else {
            return Ok(shortest.into_inner());
        };
        let reduced = match shortest.route(
            inside
                .simplify_radicals(domains)
                .and_then(|r| r.simplify_trig()),
        )? {
            Some(reduced) => reduced,
            None => inside,
        };
        let Some(expanded) = shortest.route(reduced.expand())? else {
            return Ok(shortest.into_inner());
        };
        if !expanded.has_at_most_size(MAX_READABLE_SIZE) {
            return Ok(shortest.into_inner());
        }
        let expanded = shortest
            .route(expanded.simplify_trig())?
            .unwrap_or(expanded);
        if let Some(groups) = kinematic_groups(&expanded) {
            shortest.route(simplified_by_group(&groups, domains))?;
            return Ok(shortest.into_inner());
        }
        if !has_kinematic_symbol(&expanded) && matches!(expanded.view(), View::Add(_)) {
            shortest.route(expanded.factor_terms())?;
        }
        shortest.route(
            reduced
                .cancelled_parts()
                .and_then(|(numerator, denominator)| {
                    over(&numerator.simplify_trig()?, &denominator)
                }),
        )?;
        shortest.route(
            reduced
                .together_parts()
                .and_then(|(numerator, denominator)| over(&numerator, &denominator)),
        )?;
        Ok(shortest.into_inner())
    }

    /// The arguments of functions and the bases of powers with a non-integer exponent,
    /// simplified; the rest of the tree rebuilt around them.
    fn simplify_inside(&self, domains: &Domains) -> Result<Expr, AlgebraError> {
        Ok(match self.view() {
            View::Num(_) | View::Sym(_) => self.clone(),
            View::Add(terms) => Expr::add_all(
                terms
                    .iter()
                    .map(|t| t.simplify_inside(domains))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Mul(factors) => Expr::mul_all(
                factors
                    .iter()
                    .map(|f| f.simplify_inside(domains))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Pow(base, exponent) => {
                let integer = exponent.as_num().is_some_and(|q| q.is_integer());
                let base = if integer {
                    base.simplify_inside(domains)?
                } else {
                    base.simplify(domains)?
                };
                base.checked_pow(exponent)?
            }
            View::Func(f, argument) => Expr::func(f, argument.simplify(domains)?),
        })
    }
}

/// `p/q` with each part's common factors pulled out: always in the denominator, in the
/// numerator when its terms share one kinematic part (otherwise the printer groups them);
/// the numbers of both collected in front, `⅟₁₂ (m₁² L₁² + …)/(m₁ + m₂)`, not spread over
/// the terms of a sum.
fn over(numerator: &Expr, denominator: &Expr) -> Result<Expr, AlgebraError> {
    let numerator = if kinematic_parts_differ(numerator) {
        numerator.clone()
    } else {
        numerator.factor_terms()?
    };
    let (above, numerator) = number_and_rest(&numerator);
    let (below, denominator) = number_and_rest(&denominator.factor_terms()?);
    let number = above
        .checked_div(&below)
        .ok_or(AlgebraError::DivisionByZero)?;
    Ok(Expr::mul_all([
        Expr::num(number),
        numerator,
        denominator.checked_pow(&Expr::int(-1))?,
    ]))
}

/// A factored form as its number and the rest: a sum's content and primitive part (kept
/// apart, because the canonical product of a number and one sum multiplies the number in
/// again), a product's coefficient and its other factors.
fn number_and_rest(e: &Expr) -> (Q, Expr) {
    match e.view() {
        View::Add(terms) => content_and_primitive(terms),
        _ => (
            e.coefficient().clone(),
            Expr::mul_all(e.monomial().iter().cloned()),
        ),
    }
}

/// The kinematic part of a term: its factors that hold a time-dependent symbol, except a
/// sum below the line, which belongs with the coefficient it divides (`m r² ψ̇/(¼ m r² sin θ
/// + m L² sin θ)` is the rate ψ̇ times a coefficient that reduces, `4 r² /((r² + 4L²) sin θ)`).
fn kinematic_part(term: &Expr) -> Expr {
    Expr::mul_all(
        term.monomial()
            .iter()
            .filter(|f| in_kinematic_part(f))
            .cloned(),
    )
}

fn in_kinematic_part(factor: &Expr) -> bool {
    let divides_by_a_sum = matches!(factor.view(), View::Pow(base, exponent)
        if matches!(base.view(), View::Add(_)) && exponent.as_num().is_some_and(Q::is_negative));
    has_kinematic_symbol(factor) && !divides_by_a_sum
}

/// Whether the terms of a sum carry different kinematic parts.
fn kinematic_parts_differ(e: &Expr) -> bool {
    let View::Add(terms) = e.view() else {
        return false;
    };
    let first = kinematic_part(&terms[0]);
    terms[1..].iter().any(|t| kinematic_part(t) != first)
}

/// A sum's terms gathered by kinematic part, as (part, sum of the coefficients), in order
/// of first appearance; `None` unless there are at least two parts.
fn kinematic_groups(e: &Expr) -> Option<Vec<(Expr, Vec<Expr>)>> {
    if !kinematic_parts_differ(e) {
        return None;
    }
    let mut groups: Vec<(Expr, Vec<Expr>)> = Vec::new();
    for term in e.terms() {
        let part = kinematic_part(term);
        let coefficient = term.without_factors(in_kinematic_part);
        match groups.iter_mut().find(|(p, _)| *p == part) {
            Some((_, coefficients)) => coefficients.push(coefficient),
            None => groups.push((part, vec![coefficient])),
        }
    }
    Some(groups)
}

/// `Σ simplify(coefficient) · part` over the kinematic groups.
fn simplified_by_group(
    groups: &[(Expr, Vec<Expr>)],
    domains: &Domains,
) -> Result<Expr, AlgebraError> {
    let terms = groups
        .iter()
        .map(|(part, coefficients)| {
            let coefficient = Expr::add_all(coefficients.iter().cloned()).simplify(domains)?;
            Ok(&coefficient * part)
        })
        .collect::<Result<Vec<_>, AlgebraError>>()?;
    Ok(Expr::add_all(terms))
}

fn has_kinematic_symbol(e: &Expr) -> bool {
    e.has_symbol_where(&|s| s.is_time_dependent())
}

/// The candidate with the fewest operations so far; the earliest on a tie.
struct Shortest {
    best: Expr,
    count: usize,
}

impl Shortest {
    fn new(first: Expr) -> Shortest {
        let count = first.operation_count();
        Shortest { best: first, count }
    }

    /// Offers the outcome of a route and hands it back: a route refused for size or work
    /// is passed over (`None`); any other error is the answer.
    fn route(&mut self, outcome: Result<Expr, AlgebraError>) -> Result<Option<Expr>, AlgebraError> {
        super::work::check()?;
        match outcome {
            Ok(candidate) => {
                let count = candidate.operation_count();
                if count < self.count {
                    self.best = candidate.clone();
                    self.count = count;
                }
                Ok(Some(candidate))
            }
            Err(e) if e.is_beyond_bounds() => Ok(None),
            Err(e) => Err(e),
        }
    }

    fn into_inner(self) -> Expr {
        self.best
    }
}
