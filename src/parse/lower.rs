//! Lowering: the parse tree of an expression ([`Ast`], each [`Node`] with the span of its
//! text) to an [`Expr`] through the canonical constructors. Each algebra error on the way
//! (a zero divisor, zero to a negative power, a power of a vector, a number too long) points
//! at and quotes the text the user wrote. The name `deg` is the degree, the number π/180
//! (`sin(30 deg)` is `sin(π/6)`, which is 1/2), and `pi` is π.
//!
//! A claim is lowered with its [`Names`]: each name written is resolved at its leaf (so a
//! cross product operates on the resolved vectors), and the rules of
//! [`claim_vectors`](super::claim_vectors) and [`cross_letter`](super::cross_letter) apply.
//! An expression keeps every name as a symbol.

use super::claim_vectors::{self, is_vector, VectorFactors};
use super::cross_letter;
use super::diagnostic::Diagnostic;
use super::names::Names;
use super::units_after_numbers::is_number;
use crate::algebra::vector::has_unit_vectors;
use crate::algebra::{AlgebraError, Expr, Func, Q};

/// The name of the degree, the number π/180, in an expression.
pub const DEGREE: &str = "deg";

/// The byte span of a text in the source: start and end.
pub(super) type Span = (usize, usize);

/// The parse tree of one expression before it becomes an [`Expr`]. Sums, products and
/// chains of cross products are flat lists, so a long chain `a + b + c + ...` is one node,
/// not a deep tree.
#[derive(Clone)]
pub(super) enum Ast {
    Number(Q),
    Symbol(String),
    /// `f(a, b, ...)`: the name and its arguments, their count checked when lowered.
    Call(String, Vec<Node>),
    /// Terms with `true` for a subtracted one.
    Sum(Vec<(bool, Node)>),
    /// Factors with `true` for a divisor.
    Product(Vec<(bool, Node)>),
    /// `a × b × c`, left-associative: `(a × b) × c`.
    Cross(Vec<Node>),
    Power(Box<Node>, Box<Node>),
    Negate(Box<Node>),
    Error(Diagnostic),
}

/// A node of the parse tree with the byte span of the text it was read from (a parenthesis
/// included), so that an error of the algebra points at, and quotes, what the user wrote.
#[derive(Clone)]
pub(super) struct Node {
    pub(super) ast: Ast,
    pub(super) span: Span,
}

impl Node {
    /// Whether the node is a sum, product or cross product written in parentheses: its
    /// text starts before its first operand's (an operator's chain starts with it).
    pub(super) fn is_parenthesised_list(&self) -> bool {
        let first = match &self.ast {
            Ast::Sum(items) | Ast::Product(items) => items.first().map(|(_, n)| n),
            Ast::Cross(operands) => operands.first(),
            _ => None,
        };
        first.is_some_and(|f| f.span.0 != self.span.0)
    }
}

/// `sqrt(x)`, the power `x^(1/2)`.
const SQRT: &str = "sqrt";
/// `cross(a, b)`, the vector product `a × b`.
const CROSS: &str = "cross";
/// `dot(a, b)`, the scalar product.
const DOT: &str = "dot";

/// `cot x = cos x / sin x`, `sec x = 1 / cos x`, `csc x = 1 / sin x`: names people write,
/// lowered to the quotient they stand for (no function of their own), each as
/// `(numerator, denominator)` of its argument.
pub(super) const RECIPROCAL_TRIG: [(&str, Option<Func>, Func); 3] = [
    ("cot", Some(Func::Cos), Func::Sin),
    ("sec", None, Func::Cos),
    ("csc", None, Func::Sin),
];

/// Whether `name(...)` is a call of a known function: one of [`Func`], the three above, or
/// a reciprocal of [`RECIPROCAL_TRIG`].
pub(super) fn is_function(name: &str) -> bool {
    Func::from_name(name).is_some()
        || [SQRT, CROSS, DOT].contains(&name)
        || RECIPROCAL_TRIG.iter().any(|(n, _, _)| *n == name)
}

/// Reads one parse tree into an [`Expr`]: the source it was read from, for located
/// errors, and in a claim its names.
pub(super) struct Lowering<'a> {
    pub(super) source_name: &'a str,
    pub(super) source: &'a str,
    /// The names of a claim, resolved as they are met; `None` for an expression.
    pub(super) names: Option<Names<'a>>,
    /// What a name written after a number stands for when it is a unit there
    /// ([`units_after_numbers`](super::units_after_numbers)); `None`: every name a symbol.
    pub(super) units: Option<Units<'a>>,
}

/// The value of a name written after a number or a unit, when the caller reads it as a unit
/// there.
pub type Units<'a> = &'a dyn Fn(&str, Follows) -> Option<Expr>;

/// What a name read as a possible unit follows in its product.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Follows {
    /// A number: `2 m` (a caller may read a name it declares, the mass m, as itself).
    Number,
    /// A unit: `N*m`, `m/s` (a quantity's unit goes on: `m` is the metre).
    Unit,
}

/// What the user wrote that the algebra could not form: the help names it.
#[derive(Clone, Copy)]
pub(super) enum Operation {
    /// A factor written after a `/`.
    Division,
    /// `base^exponent`, and `sqrt(x)`, the power `x^(1/2)`.
    Power,
    /// A sum, whose numbers are added up.
    Sum,
    /// A product, whose numbers are multiplied.
    Product,
    /// A function of an argument, `tan(x)`.
    Function(Func),
}

impl Lowering<'_> {
    /// An expression's lowering: every name a symbol.
    pub(super) fn expression<'a>(source_name: &'a str, source: &'a str) -> Lowering<'a> {
        Lowering {
            source_name,
            source,
            names: None,
            units: None,
        }
    }

    /// Whether this is a claim's lowering (names resolved, vectors checked).
    pub(super) fn in_claim(&self) -> bool {
        self.names.is_some()
    }

    /// A located error at `span` of the source.
    pub(super) fn error_at(&self, span: Span, message: impl Into<String>) -> Diagnostic {
        let (start, end) = span;
        Diagnostic::at(
            self.source_name,
            self.source,
            start,
            end.max(start + 1),
            message,
        )
    }

    /// The text written at `span`, quoted for a one-line message.
    pub(super) fn written(&self, span: Span) -> String {
        quoted(self.source.get(span.0..span.1).unwrap_or_default())
    }

    /// A located error of the algebra while lowering: it points at `span` and quotes the
    /// text the user wrote there, never a form the algebra made of it.
    pub(super) fn algebra_error(
        &self,
        err: AlgebraError,
        operation: Operation,
        span: Span,
    ) -> Diagnostic {
        let written = self.written(span);
        let (message, help) = match (&err, operation) {
            (AlgebraError::DivisionByZero, Operation::Division) => (
                format!("division by zero: {written} is exactly zero"),
                "a divisor, or a factor of one, must not be zero (as written, or as terms that cancel)",
            ),
            (AlgebraError::DivisionByZero, Operation::Power) => (
                format!("division by zero: {written} is zero to a negative power"),
                "zero has no negative powers: check the base and the sign of the exponent",
            ),
            (AlgebraError::Undefined(_), Operation::Function(Func::Acos)) => (
                format!("{written} is undefined: the inverse cosine takes a number in [-1, 1]"),
                "a cosine lies between -1 and 1: check the argument",
            ),
            (AlgebraError::Undefined(_), Operation::Function(_)) => (
                format!("{written} is undefined: the tangent of an odd multiple of 90° is infinite"),
                "check the angle: cos is zero there",
            ),
            (AlgebraError::NumberTooLarge { .. }, _) => (
                format!("{err}: {written}"),
                "exact numbers are bounded in digits; give such a value a symbol",
            ),
            _ => (
                format!("{err}: {written}"),
                "write this part of the expression another way",
            ),
        };
        self.error_at(span, message).with_help(help)
    }

    /// A power of an expression holding `i`, `j` or `k` (or such an exponent) is no
    /// vector: `(3*v - i)^2` is refused as written, before anything is multiplied out.
    fn power_of_a_vector(&self, span: Span) -> Diagnostic {
        let written = self.written(span);
        self.error_at(
            span,
            format!("a power of a vector, {written}, has no meaning"),
        )
        .with_help("write the components, like a*i + b*j + c*k")
    }

    /// Refuses a product whose numbers would pass the bound on digits (`bits` of them),
    /// before any number is folded.
    pub(super) fn check_product_bits(&self, bits: u64, span: Span) -> Result<(), Diagnostic> {
        Q::check_bits("the product of these numbers", bits)
            .map_err(|err| self.algebra_error(err, Operation::Product, span))
    }

    /// Pushes the factors of one factor of a product, as divisors when `divide` holds,
    /// each with the span of its text. A product (in parentheses) gives its own factors
    /// and a negation the factor -1 and its operand, so that the whole product is formed
    /// once: `-(a - 1)*w` is `-((a - 1) w)`, as the printer means it, and `x/(3 (1 - a))`
    /// is `x/3/(1 - a)`. Formed apart, the -1 or the 3 would first be distributed into the
    /// sum (`1 - a`, `3 - 3a`), another canonical form of the same value; the one the
    /// printer's text stands for is the product's. (In a claim, a product in which the
    /// letter x is a cross product is one factor: its grouping is its meaning.)
    ///
    /// A factor written after a `/` anywhere (`written_as_divisor`) is a division by zero
    /// when it is zero, even where two divisions cancel (`x/(1/0)`); the error points at
    /// that factor. In a claim it is refused when it is a vector.
    fn gather_factors(
        &mut self,
        f: Node,
        divide: bool,
        written_as_divisor: bool,
        out: &mut Vec<(Expr, Span)>,
    ) -> Result<(), Diagnostic> {
        match f.ast {
            Ast::Product(inner) if !(self.in_claim() && cross_letter::has_cross_letter(&inner)) => {
                for (inner_divide, g) in inner {
                    self.gather_factors(
                        g,
                        divide != inner_divide,
                        written_as_divisor || inner_divide,
                        out,
                    )?;
                }
            }
            Ast::Negate(operand) => {
                out.push((Expr::int(-1), f.span));
                self.gather_factors(*operand, divide, written_as_divisor, out)?;
            }
            ast => {
                let span = f.span;
                let e = self.lower(Node { ast, span })?;
                let fail = |err| self.algebra_error(err, Operation::Division, span);
                if written_as_divisor && e.is_zero() {
                    return Err(fail(AlgebraError::DivisionByZero));
                }
                if written_as_divisor && self.in_claim() && is_vector(&e) {
                    return Err(claim_vectors::division_by_a_vector(self, span));
                }
                let e = if divide {
                    e.checked_pow(&Expr::int(-1)).map_err(fail)?
                } else {
                    e
                };
                out.push((e, span));
            }
        }
        Ok(())
    }

    /// The terms of a sum, each lowered with its sign, with the span of its text (the
    /// sign between terms not included).
    pub(super) fn sum_terms(
        &mut self,
        terms: Vec<(bool, Node)>,
    ) -> Result<Vec<(Expr, Span)>, Diagnostic> {
        let mut out = Vec::with_capacity(terms.len());
        for (subtract, t) in terms {
            let span = t.span;
            let e = self.lower(t)?;
            out.push((if subtract { -e } else { e }, span));
        }
        Ok(out)
    }

    /// The sum of lowered terms, its numbers bounded in digits before they are added (in a
    /// claim, a scalar added to a vector refused at the scalar).
    pub(super) fn add_terms(
        &self,
        terms: &[(Expr, Span)],
        whole: Span,
    ) -> Result<Expr, Diagnostic> {
        if self.in_claim() {
            claim_vectors::check_sum(self, terms)?;
        }
        let bits = Q::sum_bits(terms.iter().map(|(e, _)| e.coefficient()));
        Q::check_bits("the sum of these numbers", bits)
            .map_err(|err| self.algebra_error(err, Operation::Sum, whole))?;
        Ok(Expr::add_all(terms.iter().map(|(e, _)| e.clone())))
    }

    /// The product of `factors` written at `whole`: each factor's factors gathered, the
    /// numbers bounded in digits as they are met, then formed once (in a claim, a product
    /// of two vectors refused).
    fn product(&mut self, factors: Vec<(bool, Node)>, whole: Span) -> Result<Expr, Diagnostic> {
        let mut out = Vec::with_capacity(factors.len());
        let mut bits = 0u64;
        let mut vectors = VectorFactors::default();
        let mut after_number: Option<Follows> = None;
        for (divide, f) in factors {
            let (gathered, span) = (out.len(), f.span);
            let number = is_number(&f);
            let unit = match after_number {
                Some(follows) => self.unit_after_number(f, divide, follows)?,
                None => Err(f),
            };
            after_number = match (number, unit.is_ok()) {
                (true, _) => Some(Follows::Number),
                (false, true) => Some(Follows::Unit),
                (false, false) => None,
            };
            match unit {
                Ok(unit) => out.push((unit, span)),
                Err(f) => self.gather_factors(f, divide, divide, &mut out)?,
            }
            // Refused once the bound is crossed, before any number is folded.
            bits = bits.saturating_add(Q::product_bits(
                out[gathered..].iter().map(|(e, _)| e.coefficient()),
            ));
            self.check_product_bits(bits, whole)?;
            if self.in_claim() {
                vectors.note(self, span, &out[gathered..])?;
            }
        }
        Ok(Expr::mul_all(out.into_iter().map(|(e, _)| e)))
    }

    /// `name(args)`: the count of arguments checked, then the function applied (in a
    /// claim, a function of a vector refused).
    fn call(&mut self, name: &str, args: Vec<Node>, whole: Span) -> Result<Expr, Diagnostic> {
        let pair = name == CROSS || name == DOT;
        let arity = if pair { 2 } else { 1 };
        if args.len() != arity {
            let wanted = if pair {
                "two arguments"
            } else {
                "one argument"
            };
            let example = if pair {
                format!("{name}(a, b)")
            } else {
                format!("{name}(x)")
            };
            return Err(self
                .error_at(
                    whole,
                    format!("{name} takes {wanted}, found {}", args.len()),
                )
                .with_help(format!("write {example}, arguments separated by commas")));
        }
        let mut operands = Vec::with_capacity(arity);
        for arg in args {
            let span = arg.span;
            operands.push((self.lower(arg)?, span));
        }
        if pair {
            let (b, a) = (operands.pop(), operands.pop());
            return match (a, b) {
                (Some(a), Some(b)) if name == CROSS => self.cross(&a, &b),
                (Some(a), Some(b)) => self.dot(&a, &b),
                _ => Err(self.error_at(whole, format!("{name} takes two arguments"))),
            };
        }
        let Some((arg, arg_span)) = operands.pop() else {
            return Err(self.error_at(whole, format!("{name} takes one argument")));
        };
        if self.in_claim() && is_vector(&arg) {
            return Err(claim_vectors::function_of_a_vector(
                self, name, whole, arg_span,
            ));
        }
        if let Some((_, numerator, denominator)) = RECIPROCAL_TRIG.iter().find(|r| r.0 == name) {
            let top = numerator.map_or_else(Expr::one, |f| f.apply(arg.clone()));
            return denominator
                .apply(arg)
                .checked_pow(&Expr::int(-1))
                .map(|reciprocal| &top * &reciprocal)
                .map_err(|e| self.algebra_error(e, Operation::Division, whole));
        }
        match Func::from_name(name) {
            Some(f) => f
                .checked_apply(arg)
                .map_err(|e| self.algebra_error(e, Operation::Function(f), whole)),
            None => arg
                .checked_pow(&Expr::rational(1, 2))
                .map_err(|e| self.algebra_error(e, Operation::Power, whole)),
        }
    }

    /// The value of a node, through the canonical constructors; the first error met, at
    /// the text it comes from.
    pub(super) fn lower(&mut self, node: Node) -> Result<Expr, Diagnostic> {
        let whole = node.span;
        Ok(match node.ast {
            Ast::Number(q) => Expr::num(q),
            // The degree is the number π/180: `cos(90 deg)` is `cos(π/2)`, which is 0.
            Ast::Symbol(name) if name == DEGREE => Expr::pi() / Expr::int(180),
            Ast::Symbol(name) => match self.names.as_mut() {
                Some(names) => names.value(&name).map_err(|help| {
                    self.error_at(whole, format!("unknown name '{name}'"))
                        .with_help(help)
                })?,
                None => Expr::symbol(&name),
            },
            Ast::Error(d) => return Err(d),
            Ast::Negate(inner) => -self.lower(*inner)?,
            Ast::Call(name, args) => self.call(&name, args, whole)?,
            Ast::Sum(terms) => {
                let terms = self.sum_terms(terms)?;
                self.add_terms(&terms, whole)?
            }
            Ast::Product(factors)
                if self.in_claim() && cross_letter::has_cross_letter(&factors) =>
            {
                self.product_with_cross_letters(factors)?
            }
            Ast::Product(factors) => self.product(factors, whole)?,
            Ast::Cross(operands) => self.cross_chain(operands)?,
            Ast::Power(base, exponent) => {
                let b = self.lower(*base)?;
                let e = self.lower(*exponent)?;
                if has_unit_vectors(&b) || has_unit_vectors(&e) {
                    return Err(self.power_of_a_vector(whole));
                }
                b.checked_pow(&e)
                    .map_err(|err| self.algebra_error(err, Operation::Power, whole))?
            }
        })
    }
}

/// The text the user wrote, for a one-line message: trimmed, line breaks as spaces, and
/// shortened when long.
fn quoted(written: &str) -> String {
    const LONGEST: usize = 40;
    let written = written.trim().replace(['\n', '\r', '\t'], " ");
    if written.chars().count() <= LONGEST {
        return format!("'{written}'");
    }
    let head: String = written.chars().take(LONGEST).collect();
    format!("'{head}...'")
}
