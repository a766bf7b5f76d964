//! The expression parser: `grammar/expr.pest` read with a `PrattParser`.
//!
//! Precedence, loosest first: `+ -`; the cross product `×`; `* / ·` and juxtaposition;
//! prefix `-` and `+`; `^` (right-associative; the others left-associative). So `-a^2` is
//! `-(a^2)`, `1/2 m v^2` is `(1/2)·m·v²` and `r × m v` is `r × (m v)`. Decimals are exact
//! (`0.1` is 1/10). `sqrt(x)` is `x^(1/2)`; `cross(a, b)` is `a × b` and `dot(a, b)` the
//! scalar product. A parenthesised sum, product or chain of `×` stays one operand of the
//! list around it (`(a + b) + c` has two terms), so a claim's terms are those written.
//!
//! A product is formed once from all its factors: a minus before one of them is the factor
//! -1 (`-(a - 1) w` is `-((a - 1) w)`), and dividing by a product in parentheses divides
//! by each of its factors (`x/(3 (1 - a))` is `x/3/(1 - a)`). The value is the same either
//! way; this way a number is not distributed into a sum before the product is formed, so
//! the text the printer writes parses back to the canonical form it was written from.
//!
//! ```
//! use kinetics::parse::parse_expression;
//! use kinetics::algebra::Expr;
//! let e = parse_expression("input", "-a^2 + 1/2 m v^2").unwrap();
//! let (a, m, v) = (Expr::symbol("a"), Expr::symbol("m"), Expr::symbol("v"));
//! assert_eq!(e, -a.powi(2) + Expr::rational(1, 2) * m * v.powi(2));
//! ```

use super::diagnostic::Diagnostic;
use super::limits::check_input;
use super::lower::{is_function, Ast, Lowering, Node, Span, Units};
use crate::algebra::{Expr, Func, Q};
use pest::iterators::{Pair, Pairs};
use pest::pratt_parser::{Assoc, Op, PrattParser};
use pest::Parser;
use std::sync::OnceLock;

#[derive(pest_derive::Parser)]
#[grammar = "../grammar/expr.pest"]
pub(super) struct ExprGrammar;

/// An equation `lhs = rhs`.
#[derive(Debug, Clone, PartialEq)]
pub struct Equation {
    pub lhs: Expr,
    pub rhs: Expr,
}

/// What a line of mathematics says: an expression, or an equation.
#[derive(Debug, Clone, PartialEq)]
pub enum Statement {
    Expression(Expr),
    Equation(Equation),
}

/// Identifiers that look like numbers but are not finite values.
const NOT_FINITE: [&str; 3] = ["nan", "inf", "infinity"];

fn pratt() -> &'static PrattParser<Rule> {
    static PRATT: OnceLock<PrattParser<Rule>> = OnceLock::new();
    PRATT.get_or_init(|| {
        PrattParser::new()
            .op(Op::infix(Rule::add, Assoc::Left) | Op::infix(Rule::sub, Assoc::Left))
            .op(Op::infix(Rule::cross, Assoc::Left))
            .op(Op::infix(Rule::mul, Assoc::Left)
                | Op::infix(Rule::div, Assoc::Left)
                | Op::infix(Rule::implicit, Assoc::Left))
            .op(Op::prefix(Rule::neg) | Op::prefix(Rule::pos))
            .op(Op::infix(Rule::pow, Assoc::Right))
    })
}

/// Parses one expression.
pub fn parse_expression(source_name: &str, source: &str) -> Result<Expr, Diagnostic> {
    parse_expression_in(source_name, source, None)
}

/// Parses one expression in which a name written after a number (or after such a unit:
/// `2 m/s^2`) is the value `units` gives it, when it gives one (a unit, see
/// [`units_after_numbers`](super::units_after_numbers)); every other name is a symbol.
pub fn parse_expression_with_units(
    source_name: &str,
    source: &str,
    units: Units,
) -> Result<Expr, Diagnostic> {
    parse_expression_in(source_name, source, Some(units))
}

fn parse_expression_in(
    source_name: &str,
    source: &str,
    units: Option<Units>,
) -> Result<Expr, Diagnostic> {
    let mut pairs = parse_rule(Rule::expression_input, source_name, source)?;
    let input = pairs.next().map(Pair::into_inner);
    let expr = input.and_then(|mut p| p.next());
    match expr {
        Some(e) => build(e, source_name, source, units),
        None => Err(Diagnostic::at(source_name, source, 0, 0, "empty input")),
    }
}

/// Parses an expression or an equation `lhs = rhs`.
pub fn parse_statement(source_name: &str, source: &str) -> Result<Statement, Diagnostic> {
    let sides = statement_sides(source_name, source)?;
    let exprs = sides
        .into_iter()
        .map(|p| build(p, source_name, source, None))
        .collect::<Result<Vec<_>, _>>()?;
    statement_of(exprs, source_name, source)
}

/// The statement whose sides are `exprs`: an expression, or an equation.
pub(super) fn statement_of(
    mut exprs: Vec<Expr>,
    source_name: &str,
    source: &str,
) -> Result<Statement, Diagnostic> {
    match exprs.len() {
        1 => Ok(Statement::Expression(exprs.remove(0))),
        2 => {
            let rhs = exprs.remove(1);
            let lhs = exprs.remove(0);
            Ok(Statement::Equation(Equation { lhs, rhs }))
        }
        _ => Err(Diagnostic::at(source_name, source, 0, 0, "empty input")),
    }
}

/// Parses an equation `lhs = rhs`.
pub fn parse_equation(source_name: &str, source: &str) -> Result<Equation, Diagnostic> {
    match parse_statement(source_name, source)? {
        Statement::Equation(eq) => Ok(eq),
        Statement::Expression(_) => Err(Diagnostic::at(
            source_name,
            source,
            source.len(),
            source.len(),
            "expected an equation 'left = right', found an expression",
        )),
    }
}

/// A statement's sides as the grammar reads them: one expression, or the two of `lhs = rhs`.
pub(super) fn statement_sides<'i>(
    source_name: &str,
    source: &'i str,
) -> Result<Vec<Pair<'i, Rule>>, Diagnostic> {
    let mut pairs = parse_rule(Rule::statement_input, source_name, source)?;
    Ok(pairs
        .next()
        .map(|p| {
            p.into_inner()
                .filter(|q| q.as_rule() == Rule::expr)
                .collect()
        })
        .unwrap_or_default())
}

fn parse_rule<'i>(
    rule: Rule,
    source_name: &str,
    source: &'i str,
) -> Result<Pairs<'i, Rule>, Diagnostic> {
    check_input(source_name, source)?;
    parse_checked(rule, source_name, source)
}

/// Parses input already within the bounds of [`check_input`].
pub(super) fn parse_checked<'i>(
    rule: Rule,
    source_name: &str,
    source: &'i str,
) -> Result<Pairs<'i, Rule>, Diagnostic> {
    ExprGrammar::parse(rule, source).map_err(|e| from_pest(e, source_name, source))
}

fn describe(rule: &Rule) -> &'static str {
    match rule {
        Rule::expr
        | Rule::number
        | Rule::symbol
        | Rule::identifier
        | Rule::call
        | Rule::degree
        | Rule::callee
        | Rule::paren
        | Rule::neg
        | Rule::pos => "an expression (a number, a symbol or a parenthesis)",
        Rule::add
        | Rule::sub
        | Rule::cross
        | Rule::mul
        | Rule::div
        | Rule::pow
        | Rule::implicit => "an operator",
        Rule::EOI => "the end of the input",
        _ => "",
    }
}

fn from_pest(e: pest::error::Error<Rule>, source_name: &str, source: &str) -> Diagnostic {
    let (start, end) = match e.location {
        pest::error::InputLocation::Pos(p) => (p, p),
        pest::error::InputLocation::Span(s) => s,
    };
    let mut expected: Vec<&str> = match &e.variant {
        pest::error::ErrorVariant::ParsingError { positives, .. } => {
            positives.iter().map(describe).collect()
        }
        pest::error::ErrorVariant::CustomError { .. } => vec![],
    };
    let at_paren_close = source[start..].starts_with(')');
    if source[start..].trim_start().is_empty() || expected.is_empty() {
        expected.retain(|d| *d != "an operator");
    }
    expected.retain(|d| !d.is_empty());
    expected.sort();
    expected.dedup();
    let found = match source[start..].chars().next() {
        None => "end of input".to_string(),
        Some(c) => format!("'{c}'"),
    };
    let expected = match expected.len() {
        0 => "a well-formed expression".to_string(),
        1 => expected[0].to_string(),
        _ => format!(
            "{} or {}",
            expected[..expected.len() - 1].join(", "),
            expected[expected.len() - 1]
        ),
    };
    let opens = source.matches('(').count();
    let closes = source.matches(')').count();
    let help = if opens > closes {
        "every '(' needs an expression and a matching ')'"
    } else if closes > opens || at_paren_close {
        "there is a ')' without a matching '(' or with nothing inside"
    } else {
        "write products with '*' or a space, powers with '^', and functions as sin(x)"
    };
    Diagnostic::at(
        source_name,
        source,
        start,
        end.max(start + 1),
        format!("expected {expected}, found {found}"),
    )
    .with_help(help)
}

fn build(
    expr: Pair<Rule>,
    source_name: &str,
    source: &str,
    units: Option<Units>,
) -> Result<Expr, Diagnostic> {
    let node = to_ast(expr.into_inner(), source_name, source);
    let mut lowering = Lowering::expression(source_name, source);
    lowering.units = units;
    lowering.lower(node)
}

/// The expression of a parse tree (no units), for the algebra.
pub(super) fn lower_expression(
    node: Node,
    source_name: &str,
    source: &str,
) -> Result<Expr, Diagnostic> {
    Lowering::expression(source_name, source).lower(node)
}

fn span_of(p: &Pair<Rule>) -> Span {
    (p.as_span().start(), p.as_span().end())
}

/// The parse tree of an `expr`'s parts.
pub(super) fn to_ast(pairs: Pairs<Rule>, source_name: &str, source: &str) -> Node {
    pratt()
        .map_primary(|p| Node {
            span: span_of(&p),
            ast: primary(p, source_name, source),
        })
        .map_prefix(|op, rhs| match op.as_rule() {
            Rule::neg => Node {
                span: (op.as_span().start(), rhs.span.1),
                ast: Ast::Negate(Box::new(rhs)),
            },
            _ => rhs,
        })
        .map_infix(|lhs, op, rhs| {
            let span = (lhs.span.0, rhs.span.1);
            // A chain continues the list on its left, unless that list is in parentheses.
            let chained = !lhs.is_parenthesised_list();
            let ast = match op.as_rule() {
                Rule::add | Rule::sub => {
                    let subtract = op.as_rule() == Rule::sub;
                    match lhs.ast {
                        Ast::Sum(mut terms) if chained => {
                            terms.push((subtract, rhs));
                            Ast::Sum(terms)
                        }
                        _ => Ast::Sum(vec![(false, lhs), (subtract, rhs)]),
                    }
                }
                Rule::cross => match lhs.ast {
                    Ast::Cross(mut operands) if chained => {
                        operands.push(rhs);
                        Ast::Cross(operands)
                    }
                    _ => Ast::Cross(vec![lhs, rhs]),
                },
                Rule::mul | Rule::div | Rule::implicit => {
                    let divide = op.as_rule() == Rule::div;
                    match lhs.ast {
                        Ast::Product(mut factors) if chained => {
                            factors.push((divide, rhs));
                            Ast::Product(factors)
                        }
                        _ => Ast::Product(vec![(false, lhs), (divide, rhs)]),
                    }
                }
                _ => Ast::Power(Box::new(lhs), Box::new(rhs)),
            };
            Node { ast, span }
        })
        .parse(pairs)
}

fn primary(p: Pair<Rule>, source_name: &str, source: &str) -> Ast {
    let (start, end) = span_of(&p);
    match p.as_rule() {
        // A second point right after a number (2.5.1) is a mistyped number, not 2.5 times .1.
        Rule::number if source[end..].starts_with('.') => Ast::Error(
            Diagnostic::at(
                source_name,
                source,
                end,
                end + 1,
                format!("a second decimal point after {}", p.as_str()),
            )
            .with_help("a number has at most one decimal point"),
        ),
        Rule::number => match Q::parse_decimal(p.as_str()) {
            Some(q) => Ast::Number(q),
            None => Ast::Error(
                Diagnostic::at(
                    source_name,
                    source,
                    start,
                    end,
                    format!("the number {} is out of range", p.as_str()),
                )
                .with_help("numbers may have at most 4096 digits of exponent"),
            ),
        },
        Rule::symbol => {
            let name = p.as_str();
            if NOT_FINITE.contains(&name.to_ascii_lowercase().as_str()) {
                return Ast::Error(
                    Diagnostic::at(source_name, source, start, end, format!("{name} is not a finite number"))
                        .with_help("give every quantity a finite value, or leave it as a symbol with another name"),
                );
            }
            if Func::from_name(name).is_some() || name == "sqrt" {
                return Ast::Error(
                    Diagnostic::at(
                        source_name,
                        source,
                        start,
                        end,
                        format!("the function {name} needs an argument"),
                    )
                    .with_help(format!("write {name}(x)")),
                );
            }
            Ast::Symbol(name.to_string())
        }
        Rule::degree => Ast::Symbol(super::DEGREE.to_string()),
        Rule::call => {
            let mut inner = p.into_inner();
            let callee = inner.next();
            let name = callee
                .as_ref()
                .map(|c| c.as_str().trim_end_matches('(').to_string())
                .unwrap_or_default();
            if !is_function(&name) {
                let end = start + name.len();
                return Ast::Error(
                    Diagnostic::at(source_name, source, start, end, format!("unknown function {name}"))
                        .with_help(format!(
                            "the functions are sin, cos, tan, cot, sec, csc, acos, sqrt, abs, cross(a, b) and dot(a, b); for a product write {name}*(...)"
                        )),
                );
            }
            let arguments = inner
                .map(|a| to_ast(a.into_inner(), source_name, source))
                .collect();
            Ast::Call(name, arguments)
        }
        Rule::paren => match p.into_inner().next() {
            Some(e) => to_ast(e.into_inner(), source_name, source).ast,
            None => Ast::Error(Diagnostic::at(
                source_name,
                source,
                start,
                end,
                "empty parentheses",
            )),
        },
        _ => Ast::Error(Diagnostic::at(
            source_name,
            source,
            start,
            end,
            "unexpected input",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(input: &str) -> Expr {
        parse_expression("test", input).unwrap()
    }

    /// A minus before a factor and a product as a divisor belong to the whole product,
    /// formed once: the -1 or the number is not distributed into a sum first.
    #[test]
    fn a_product_is_formed_once_from_all_its_factors() {
        let (a, w, x) = (Expr::symbol("a"), Expr::symbol("w_x"), Expr::symbol("x"));
        let one = Expr::one();
        assert_eq!(
            parsed("-(a - 1)*w_x"),
            Expr::mul_all([Expr::int(-1), &a - &one, w.clone()])
        );
        assert_eq!(
            parsed("x/(3*(1 - a))"),
            Expr::mul_all([x.clone(), Expr::rational(1, 3), (&one - &a).powi(-1)])
        );
        let four = Expr::int(4);
        assert_eq!(
            parsed("-(a + 4)/(-a - 4)"),
            Expr::mul_all([Expr::int(-1), &a + &four, (-&a - &four).powi(-1)])
        );
        assert_eq!(
            parsed("x/(2/(a + 1))"),
            Expr::mul_all([x.clone(), Expr::rational(1, 2), &a + &one])
        );
    }

    /// A power of anything holding a unit vector is refused as written, located at the
    /// whole power, before anything is multiplied out.
    #[test]
    fn powers_of_vectors_are_refused_where_written() {
        for (input, power) in [
            ("(3*v - i)^600", "(3*v - i)^600"),
            ("x + (a+i)^9223372036854775808", "(a+i)^9223372036854775808"),
            ("2*k^2", "k^2"),
            ("2^j", "2^j"),
        ] {
            let err = parse_expression("test", input).unwrap_err();
            assert_eq!(
                err.message,
                format!("a power of a vector, '{power}', has no meaning"),
                "{input}"
            );
            assert_eq!(err.column, input.find(power).unwrap() + 1, "{input}");
        }
        assert!(parse_expression("test", "(a + b)^2*i").is_ok());
    }

    /// Exact numbers are bounded in digits: a product of huge numbers is refused before
    /// it is formed, quoting the product.
    #[test]
    fn products_of_huge_numbers_are_refused_at_the_bound() {
        let input = vec!["1e308"; 200].join("*");
        let err = parse_expression("test", &input).unwrap_err();
        assert!(
            err.message.contains("more than the limit of 10000"),
            "{err}"
        );
        assert!(err.message.contains("'1e308*1e308"), "{err}");
        let fine = vec!["1e308"; 30].join("*");
        assert!(parse_expression("test", &fine).is_ok());
    }

    /// Negations elsewhere keep their meaning: `-a^2` is `-(a^2)`, `a^-2 x` is `a^(-2) x`,
    /// `-(a + 1)` alone is the sum `-a - 1`; a divisor product with a zero factor is still
    /// a division by zero.
    #[test]
    fn other_negations_and_zero_divisors_are_unchanged() {
        let (a, x) = (Expr::symbol("a"), Expr::symbol("x"));
        assert_eq!(parsed("-a^2"), -a.powi(2));
        assert_eq!(parsed("a^-2 x"), a.powi(-2) * &x);
        assert_eq!(parsed("-(a + 1)"), -&a - Expr::one());
        for input in ["x/(2*(a - a))", "x/(1/0)", "x/(a/(-(1 - 1)))"] {
            let zero = parse_expression("test", input).unwrap_err();
            assert!(zero.message.contains("division by zero"), "{input}: {zero}");
        }
    }
}
