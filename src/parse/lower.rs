//! Lowering: the parse tree of an expression ([`Ast`], each [`Node`] with the span of its
//! text) to an [`Expr`] through the canonical constructors. Each algebra error on the way
//! (a zero divisor, zero to a negative power, a power of a vector, a number too long) points
//! at and quotes the text the user wrote. The name `deg` is the degree, the number π/180
//! (`sin(30 deg)` is `sin(π/6)`, which is 1/2), and `pi` is π.

use super::diagnostic::Diagnostic;
use crate::algebra::vector::has_unit_vectors;
use crate::algebra::{AlgebraError, Expr, Func, Q};

/// The name of the degree, the number π/180, in an expression.
pub const DEGREE: &str = "deg";

/// The parse tree of one expression before it becomes an [`Expr`]. Sums and products are
/// flat lists, so a long chain `a + b + c + ...` is one node, not a deep tree.
pub(super) enum Ast {
    Number(Q),
    Symbol(String),
    Call(String, Box<Node>),
    Sum(Vec<(bool, Node)>),
    /// Factors with `true` for a divisor.
    Product(Vec<(bool, Node)>),
    Power(Box<Node>, Box<Node>),
    Negate(Box<Node>),
    Error(Diagnostic),
}

/// A node of the parse tree with the byte span of the text it was read from (a parenthesis
/// included), so that an error of the algebra points at, and quotes, what the user wrote.
pub(super) struct Node {
    pub(super) ast: Ast,
    pub(super) span: (usize, usize),
}

/// Pushes the factors of one factor of a product, as divisors when `divide` holds. A
/// product (in parentheses) gives its own factors and a negation the factor -1 and its
/// operand, so that the whole product is formed once: `-(a - 1)*w` is `-((a - 1) w)`, as
/// the printer means it, and `x/(3 (1 - a))` is `x/3/(1 - a)`. Formed apart, the -1 or the
/// 3 would first be distributed into the sum (`1 - a`, `3 - 3a`), another canonical form
/// of the same value; the one the printer's text stands for is the product's.
///
/// A factor written after a `/` anywhere (`written_as_divisor`) is a division by zero when
/// it is zero, even where two divisions cancel (`x/(1/0)`); the error points at that factor.
fn gather_factors(
    f: Node,
    divide: bool,
    written_as_divisor: bool,
    out: &mut Vec<Expr>,
    source_name: &str,
    source: &str,
) -> Result<(), Diagnostic> {
    match f.ast {
        Ast::Product(inner) => {
            for (inner_divide, g) in inner {
                gather_factors(
                    g,
                    divide != inner_divide,
                    written_as_divisor || inner_divide,
                    out,
                    source_name,
                    source,
                )?;
            }
        }
        Ast::Negate(operand) => {
            out.push(Expr::int(-1));
            gather_factors(
                *operand,
                divide,
                written_as_divisor,
                out,
                source_name,
                source,
            )?;
        }
        ast => {
            let span = f.span;
            let e = lower(Node { ast, span }, source_name, source)?;
            let fail = |err| lowering_error(err, Operation::Division, span, source_name, source);
            if written_as_divisor && e.is_zero() {
                return Err(fail(AlgebraError::DivisionByZero));
            }
            out.push(if divide {
                e.checked_pow(&Expr::int(-1)).map_err(fail)?
            } else {
                e
            });
        }
    }
    Ok(())
}

/// What the user wrote that the algebra could not form: the help names it.
#[derive(Clone, Copy)]
enum Operation {
    /// A factor written after a `/`.
    Division,
    /// `base^exponent`, and `sqrt(x)`, the power `x^(1/2)`.
    Power,
    /// A sum, whose numbers are added up.
    Sum,
    /// A product, whose numbers are multiplied.
    Product,
    /// A function of an argument, `tan(x)`.
    Function,
}

/// A located error of the algebra while lowering: it points at `span` and quotes the text
/// the user wrote there, never a form the algebra made of it.
fn lowering_error(
    err: AlgebraError,
    operation: Operation,
    span: (usize, usize),
    source_name: &str,
    source: &str,
) -> Diagnostic {
    let (start, end) = span;
    let written = quoted(&source[start..end]);
    let (message, help) = match (&err, operation) {
        (AlgebraError::DivisionByZero, Operation::Division) => (
            format!("division by zero: {written} is exactly zero"),
            "a divisor, or a factor of one, must not be zero (as written, or as terms that cancel)",
        ),
        (AlgebraError::DivisionByZero, Operation::Power) => (
            format!("division by zero: {written} is zero to a negative power"),
            "zero has no negative powers: check the base and the sign of the exponent",
        ),
        (AlgebraError::Undefined(_), Operation::Function) => (
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
    Diagnostic::at(source_name, source, start, end.max(start + 1), message).with_help(help)
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

/// A power of an expression holding `i`, `j` or `k` (or such an exponent) is no vector:
/// `(3*v - i)^2` is refused as written, before anything is multiplied out.
fn power_of_a_vector(span: (usize, usize), source_name: &str, source: &str) -> Diagnostic {
    let (start, end) = span;
    let written = quoted(&source[start..end]);
    Diagnostic::at(
        source_name,
        source,
        start,
        end.max(start + 1),
        format!("a power of a vector, {written}, has no meaning"),
    )
    .with_help("write the components, like a*i + b*j + c*k")
}

pub(super) fn lower(node: Node, source_name: &str, source: &str) -> Result<Expr, Diagnostic> {
    let whole = node.span;
    let fail =
        |err: AlgebraError, operation| lowering_error(err, operation, whole, source_name, source);
    Ok(match node.ast {
        Ast::Number(q) => Expr::num(q),
        // The degree is the number π/180: `cos(90 deg)` is `cos(π/2)`, which is 0.
        Ast::Symbol(name) if name == DEGREE => Expr::pi() / Expr::int(180),
        Ast::Symbol(name) => Expr::symbol(&name),
        Ast::Error(d) => return Err(d),
        Ast::Negate(inner) => -lower(*inner, source_name, source)?,
        Ast::Call(name, arg) => {
            let arg = lower(*arg, source_name, source)?;
            match Func::from_name(&name) {
                Some(f) => f
                    .checked_apply(arg)
                    .map_err(|e| fail(e, Operation::Function))?,
                None => arg
                    .checked_pow(&Expr::rational(1, 2))
                    .map_err(|e| fail(e, Operation::Power))?,
            }
        }
        Ast::Sum(terms) => {
            let mut out = Vec::with_capacity(terms.len());
            for (subtract, t) in terms {
                let e = lower(t, source_name, source)?;
                out.push(if subtract { -e } else { e });
            }
            let bits = Q::sum_bits(out.iter().map(Expr::coefficient));
            Q::check_bits("the sum of these numbers", bits)
                .map_err(|err| fail(err, Operation::Sum))?;
            Expr::add_all(out)
        }
        Ast::Product(factors) => {
            let mut out = Vec::with_capacity(factors.len());
            let mut bits = 0u64;
            for (divide, f) in factors {
                let gathered = out.len();
                gather_factors(f, divide, divide, &mut out, source_name, source)?;
                // Refused once the bound is crossed, before any number is folded.
                bits = bits.saturating_add(Q::product_bits(
                    out[gathered..].iter().map(Expr::coefficient),
                ));
                Q::check_bits("the product of these numbers", bits)
                    .map_err(|err| fail(err, Operation::Product))?;
            }
            Expr::mul_all(out)
        }
        Ast::Power(base, exponent) => {
            let b = lower(*base, source_name, source)?;
            let e = lower(*exponent, source_name, source)?;
            if has_unit_vectors(&b) || has_unit_vectors(&e) {
                return Err(power_of_a_vector(whole, source_name, source));
            }
            b.checked_pow(&e)
                .map_err(|err| fail(err, Operation::Power))?
        }
    })
}
