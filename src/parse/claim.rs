//! A claim: an equation `lhs = rhs` as a person types it in a hand derivation, read for
//! `kinetics check`. Beyond an expression it has the cross product (`×`, `cross(a, b)`, and
//! ` x ` between two vectors) and names the checker resolves to derived quantities (`T`,
//! `H_O`) while it is read, so that `r × m vbar` is formed from their vectors. Each side keeps
//! its top-level terms with the text they were read from, so that a report can name the term
//! the user wrote.

use super::claim_vectors::is_vector;
use super::diagnostic::Diagnostic;
use super::expression::{parse_checked, to_ast, Rule};
use super::limits::check_input;
use super::lower::{Ast, Lowering, Node, Span, Units};
use super::names::Names;
use crate::algebra::Expr;
use pest::iterators::Pair;

/// One top-level term of a side, with its sign, and the byte span of its text (the sign
/// included) in the claim.
#[derive(Debug, Clone, PartialEq)]
pub struct WrittenTerm {
    pub value: Expr,
    pub span: (usize, usize),
}

/// One side of a claim: its value (derived names resolved, cross products formed), the
/// span of its text, its top-level terms as written, and the derived names it uses.
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimSide {
    pub value: Expr,
    pub span: (usize, usize),
    pub terms: Vec<WrittenTerm>,
    /// Names the resolver gave a value for, in the order first written, each once.
    pub resolved: Vec<String>,
}

/// A claim `lhs = rhs`.
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    pub lhs: ClaimSide,
    pub rhs: ClaimSide,
}

impl Claim {
    /// The names the resolver gave a value for, on either side.
    pub fn resolved_names(&self) -> impl Iterator<Item = &String> {
        self.lhs.resolved.iter().chain(&self.rhs.resolved)
    }
}

/// What a name in a claim stands for, as the checker's context says.
#[derive(Debug, Clone, PartialEq)]
pub enum Name {
    /// A symbol of its own (a given, a coordinate): lowered as `Expr::symbol`.
    Symbol,
    /// A derived quantity: lowered as this value (a scalar, or a vector `a i + b j + c k`).
    Derived(Expr),
    /// Not known in this context: an error at the name, with this help (a suggestion).
    Unknown(String),
}

/// The blanks of the grammar.
const BLANKS: [char; 4] = [' ', '\t', '\r', '\n'];

/// How a claim is written, for the help of the errors about its shape.
const EQUATION_HELP: &str = "write one equation, left = right, like T = 1/2 m v^2";

/// Reads a claim `lhs = rhs`. `resolve` is asked once per distinct name written (not for
/// the unit vectors `i j k`, nor `pi`, `deg`): [`Name::Symbol`] lowers to
/// `Expr::symbol(name)`, [`Name::Derived`] to its value, the name recorded in that side's
/// `resolved`, and [`Name::Unknown`] is the located error "unknown name 'X'" at the name,
/// with that help. Beyond an expression, a claim refuses a product of two vectors, a scalar
/// added to a vector, and a vector equated to a nonzero scalar; its letter `x` between two
/// vectors is the cross product.
///
/// ```
/// use kinetics::algebra::Expr;
/// use kinetics::parse::claim::{parse_claim, Name};
/// let claim = parse_claim("input", "T = 1/2 m v^2 + 0", &|_| Name::Symbol).unwrap();
/// let (m, v) = (Expr::symbol("m"), Expr::symbol("v"));
/// assert_eq!(claim.rhs.value, Expr::rational(1, 2) * m * v.powi(2));
/// assert_eq!(claim.rhs.terms.len(), 2);
/// ```
pub fn parse_claim(
    source_name: &str,
    source: &str,
    resolve: &dyn Fn(&str) -> Name,
) -> Result<Claim, Diagnostic> {
    parse_claim_with_units(source_name, source, resolve, None)
}

/// [`parse_claim`] where a name after a number (`1857 N`, `150 mm`) is what `units` gives
/// it, when it gives something ([`Units`]).
pub fn parse_claim_with_units(
    source_name: &str,
    source: &str,
    resolve: &dyn Fn(&str) -> Name,
    units: Option<Units>,
) -> Result<Claim, Diagnostic> {
    ClaimSyntax::parse(source_name, source)?.read(resolve, units)
}

/// A claim's text parsed, its names not yet given values: read once, then
/// [`read`](ClaimSyntax::read) in each context the checker tries (a solution of the scene's
/// equations, the context of a slip), where a name may stand for another value.
#[derive(Clone)]
pub struct ClaimSyntax<'s> {
    source_name: &'s str,
    source: &'s str,
    lhs: WrittenSide,
    rhs: WrittenSide,
}

/// One side's parse tree and the span of its text, blanks at the ends left out.
#[derive(Clone)]
struct WrittenSide {
    node: Node,
    span: Span,
}

impl<'s> ClaimSyntax<'s> {
    /// Parses `lhs = rhs`: an error at the place of a missing, second or lonely `=`, or of
    /// the syntax error.
    pub fn parse(source_name: &'s str, source: &'s str) -> Result<Self, Diagnostic> {
        check_input(source_name, source)?;
        let equals = the_equals_sign(source_name, source)?;
        let parsed = parse_checked(Rule::claim_input, source_name, source)?;
        let mut sides = parsed
            .flat_map(Pair::into_inner)
            .filter(|p| p.as_rule() == Rule::expr)
            .map(|expr| WrittenSide {
                span: trimmed(source, (expr.as_span().start(), expr.as_span().end())),
                node: to_ast(expr.into_inner(), source_name, source),
            });
        let (Some(lhs), Some(rhs)) = (sides.next(), sides.next()) else {
            return Err(Diagnostic::at(
                source_name,
                source,
                equals,
                equals + 1,
                "a claim is an equation: expected a side on each side of '='",
            )
            .with_help(EQUATION_HELP));
        };
        Ok(ClaimSyntax {
            source_name,
            source,
            lhs,
            rhs,
        })
    }

    /// The name of the claim's source, for its errors.
    pub fn source_name(&self) -> &'s str {
        self.source_name
    }

    /// The claim's text as written.
    pub fn text(&self) -> &'s str {
        self.source
    }

    /// The claim with each name as `resolve` gives it and a name after a number as `units`
    /// gives it (see [`parse_claim`]).
    pub fn read(
        &self,
        resolve: &dyn Fn(&str) -> Name,
        units: Option<Units>,
    ) -> Result<Claim, Diagnostic> {
        let mut lowering = Lowering {
            source_name: self.source_name,
            source: self.source,
            names: Some(Names::new(resolve)),
            units,
        };
        let lhs = side(&mut lowering, self.lhs.clone())?;
        let rhs = side(&mut lowering, self.rhs.clone())?;
        check_kinds(&lowering, &lhs, &rhs)?;
        Ok(Claim { lhs, rhs })
    }
}

/// The place of the claim's one `=`: none, a second one, or an empty side is an error.
fn the_equals_sign(source_name: &str, source: &str) -> Result<usize, Diagnostic> {
    let mut signs = source.match_indices('=').map(|(at, _)| at);
    let error = |start: usize, message: &str| {
        Diagnostic::at(source_name, source, start, start + 1, message).with_help(EQUATION_HELP)
    };
    match (signs.next(), signs.next()) {
        (None, _) => Err(error(
            source.len(),
            "a claim is an equation: expected '=' and a right side, found the end of the claim",
        )),
        (Some(_), Some(second)) => Err(error(second, "a claim has one '=': this is a second one")),
        (Some(at), None) if source[..at].trim_matches(BLANKS).is_empty() => {
            Err(error(at, "the left side of the claim is empty"))
        }
        (Some(at), None) if source[at + 1..].trim_matches(BLANKS).is_empty() => {
            Err(error(at + 1, "the right side of the claim is empty"))
        }
        (Some(at), None) => Ok(at),
    }
}

/// One side: its value, its text's span, its top-level terms as written, and the derived
/// names it uses.
fn side(lowering: &mut Lowering, written: WrittenSide) -> Result<ClaimSide, Diagnostic> {
    let source = lowering.source;
    let WrittenSide { node, span } = written;
    let written_sum = !node.is_parenthesised_list();
    let (value, terms) = match node.ast {
        Ast::Sum(items) if written_sum => {
            let lowered = lowering.sum_terms(items)?;
            let value = lowering.add_terms(&lowered, span)?;
            let terms = lowered
                .into_iter()
                .enumerate()
                .map(|(n, (value, (start, end)))| WrittenTerm {
                    value,
                    span: if n == 0 {
                        (span.0, end)
                    } else {
                        (sign_before(source, start), end)
                    },
                })
                .collect();
            (value, terms)
        }
        ast => {
            let value = lowering.lower(Node { ast, span })?;
            let term = WrittenTerm {
                value: value.clone(),
                span,
            };
            (value, vec![term])
        }
    };
    let resolved = lowering
        .names
        .as_mut()
        .map(Names::end_side)
        .unwrap_or_default();
    Ok(ClaimSide {
        value,
        span,
        terms,
        resolved,
    })
}

/// `span` without the blanks at its ends.
fn trimmed(source: &str, (start, end): Span) -> Span {
    let text = source.get(start..end).unwrap_or_default();
    let leading = text.len() - text.trim_start_matches(BLANKS).len();
    let kept = text.trim_matches(BLANKS).len();
    (start + leading, start + leading + kept)
}

/// Where the signs before the term at `start` begin (`a - -b`: the first `-`).
fn sign_before(source: &str, start: usize) -> usize {
    let before = source.get(..start).unwrap_or_default();
    let operand_end = before
        .trim_end_matches(|c| BLANKS.contains(&c) || c == '+' || c == '-')
        .len();
    let signs = &before[operand_end..];
    operand_end + (signs.len() - signs.trim_start_matches(BLANKS).len())
}

/// A vector equated to a nonzero scalar is refused at the scalar side, naming both.
fn check_kinds(lowering: &Lowering, lhs: &ClaimSide, rhs: &ClaimSide) -> Result<(), Diagnostic> {
    let scalar = |s: &ClaimSide| !is_vector(&s.value) && !s.value.is_zero();
    let (vector, scalar, vector_side, scalar_side) = if is_vector(&lhs.value) && scalar(rhs) {
        (lhs, rhs, "left", "right")
    } else if is_vector(&rhs.value) && scalar(lhs) {
        (rhs, lhs, "right", "left")
    } else {
        return Ok(());
    };
    let message = format!(
        "a vector equated to a scalar: the {vector_side} side, {}, is a vector, the {scalar_side} side, {}, a scalar",
        lowering.written(vector.span),
        lowering.written(scalar.span)
    );
    Err(lowering.error_at(scalar.span, message).with_help(
        "equate a component to a component (H_x = ...), or write this side as a vector with i, j and k",
    ))
}
