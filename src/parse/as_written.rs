//! An expression or equation in LaTeX (and plain text) as the user wrote it: the terms and
//! factors in the order written and the parentheses kept, only the notation changed
//! (`kinetics latex`). `-a^2 + b` stays `-a^2 + b`; `b*a/(2*c)` is `\frac{b a}{2 c}`; `w1` is
//! `\omega_1` (each symbol's one LaTeX spelling, [`Symbol::latex`]); `wdot_x` `\dot{\omega}_x`.
//!
//! A product is read left to right as written: each run of factors followed by its divisors
//! is one fraction, `a b/c d/e` = `\frac{a b}{c} \frac{d}{e}` (the same value, since
//! `((a b)/c) d/e` = `(a b/c)(d/e)`); a minus before its first factor stands before the
//! whole product (`-a/b` is `-\frac{a}{b}`). Factors are juxtaposed, a thin space beside a
//! name of several letters or after a function's bare argument (the printer's rule,
//! `print/latex.rs`), `\cdot` before a factor that begins with a digit. In an exponent a
//! quotient stays on the line (`a^{1/2}`); `30 deg` is `30^\circ`.

use super::diagnostic::Diagnostic;
use super::expression::{lower_expression, statement_of, statement_sides, to_ast, Statement};
use super::lower::{Ast, Node, RECIPROCAL_TRIG};
use crate::algebra::{reads_as_several_letters, Func, Symbol};

/// A statement as written, in the two notations.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    pub latex: String,
    pub text: String,
}

/// The expression or equation `source` for the algebra and as written, from one parse (a
/// megabyte of input is read once): parse errors located as
/// [`parse_statement`](super::parse_statement)'s, and the algebra's errors of its lowering.
pub fn statement_as_written(
    source_name: &str,
    source: &str,
) -> Result<(Statement, Written), Diagnostic> {
    let sides = statement_sides(source_name, source)?;
    let mut latex = Vec::new();
    let mut text = Vec::new();
    let mut exprs = Vec::new();
    for side in sides {
        let node = to_ast(side.into_inner(), source_name, source);
        if let Some(error) = first_error(&node) {
            return Err(error.clone());
        }
        for (notation, out) in [(Notation::Latex, &mut latex), (Notation::Text, &mut text)] {
            let mut s = String::new();
            Writer { source, notation }.node(&mut s, &node, Level::Sum);
            out.push(s);
        }
        exprs.push(lower_expression(node, source_name, source)?);
    }
    let written = Written {
        latex: latex.join(" = "),
        text: text.join(" = "),
    };
    Ok((statement_of(exprs, source_name, source)?, written))
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Notation {
    Latex,
    Text,
}

/// How tightly a node binds, loosest first: what a place needs of a node written there.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Level {
    Sum,
    Cross,
    Product,
    Negation,
    Power,
    Atom,
}

fn level(node: &Node) -> Level {
    match &node.ast {
        Ast::Sum(_) => Level::Sum,
        Ast::Cross(_) => Level::Cross,
        Ast::Product(_) => Level::Product,
        Ast::Negate(_) => Level::Negation,
        Ast::Power(..) => Level::Power,
        Ast::Call(name, _) if name == "cross" => Level::Cross,
        Ast::Call(name, _) if name == "dot" => Level::Product,
        _ => Level::Atom,
    }
}

/// The first error the parse tree holds (an unknown function, a number out of range).
fn first_error(node: &Node) -> Option<&Diagnostic> {
    match &node.ast {
        Ast::Error(d) => Some(d),
        Ast::Number(_) | Ast::Symbol(_) => None,
        Ast::Call(_, args) | Ast::Cross(args) => args.iter().find_map(first_error),
        Ast::Sum(items) | Ast::Product(items) => items.iter().find_map(|(_, n)| first_error(n)),
        Ast::Power(b, e) => first_error(b).or_else(|| first_error(e)),
        Ast::Negate(n) => first_error(n),
    }
}

struct Writer<'a> {
    source: &'a str,
    notation: Notation,
}

impl Writer<'_> {
    fn latex(&self) -> bool {
        self.notation == Notation::Latex
    }

    /// `node` where at least `need` binds: in parentheses when it binds more loosely, or when
    /// the user wrote its list in parentheses.
    fn node(&self, out: &mut String, node: &Node, need: Level) {
        let parenthesised = need > Level::Sum && node.is_parenthesised_list();
        if level(node) < need || parenthesised {
            let mut inner = String::new();
            self.bare(&mut inner, node);
            // Parentheses grow around a fraction (as the printer's, `growing_parentheses.rs`).
            let grows = self.latex() && inner.contains(r"\frac");
            out.push_str(if grows { r"\left(" } else { "(" });
            out.push_str(&inner);
            out.push_str(if grows { r"\right)" } else { ")" });
        } else {
            self.bare(out, node);
        }
    }

    /// `node` without parentheses around it: at the top, and where a fraction bar, a root,
    /// braces or a call's parentheses group it.
    fn bare(&self, out: &mut String, node: &Node) {
        match &node.ast {
            Ast::Number(_) => self.number(out, node),
            Ast::Symbol(name) => self.symbol(out, name),
            Ast::Call(name, args) => self.call(out, name, args),
            Ast::Sum(terms) => self.sum(out, terms),
            Ast::Product(factors) => self.product(out, factors),
            Ast::Cross(operands) => {
                let times = if self.latex() { r" \times " } else { " × " };
                for (k, operand) in operands.iter().enumerate() {
                    if k > 0 {
                        out.push_str(times);
                    }
                    self.node(out, operand, Level::Product);
                }
            }
            Ast::Power(base, exponent) => self.power(out, base, exponent),
            Ast::Negate(inner) => {
                out.push('-');
                self.node(out, inner, Level::Negation);
            }
            Ast::Error(_) => {}
        }
    }

    /// A number as written; `1.5e-3` is `1.5 \times 10^{-3}` in LaTeX, which ends in a
    /// superscript of its own ([`Writer::has_own_superscript`]).
    fn number(&self, out: &mut String, node: &Node) {
        let written = number_text(self.source, node);
        match scientific(written).filter(|_| self.latex()) {
            Some((mantissa, exponent)) => {
                out.push_str(&format!(r"{mantissa} \times 10^{{{exponent}}}"));
            }
            None => out.push_str(written),
        }
    }

    /// Whether `node` as written in this notation ends in a superscript of its own, so
    /// that a power of it must be fenced: LaTeX rejects `10^{5}^2`, a double superscript.
    /// Only a number in scientific notation does, in LaTeX (a power is parenthesised as
    /// any operand binding more loosely than an atom).
    fn has_own_superscript(&self, node: &Node) -> bool {
        self.latex()
            && matches!(node.ast, Ast::Number(_))
            && scientific(number_text(self.source, node)).is_some()
    }

    fn symbol(&self, out: &mut String, name: &str) {
        let symbol = Symbol::new(name);
        out.push_str(if self.latex() {
            symbol.latex()
        } else {
            symbol.name()
        });
    }

    fn call(&self, out: &mut String, name: &str, args: &[Node]) {
        match (name, args, self.notation) {
            ("cross", [a, b], _) | ("dot", [a, b], _) => {
                let operator = match (name, self.notation) {
                    ("cross", Notation::Latex) => r" \times ",
                    ("cross", Notation::Text) => " × ",
                    (_, Notation::Latex) => r" \cdot ",
                    (_, Notation::Text) => " · ",
                };
                let need = if name == "cross" {
                    Level::Product
                } else {
                    Level::Negation
                };
                self.node(out, a, need);
                out.push_str(operator);
                self.node(out, b, need);
            }
            ("sqrt", [x], Notation::Latex) => {
                out.push_str(r"\sqrt{");
                self.bare(out, x);
                out.push('}');
            }
            ("abs", [x], Notation::Latex) => {
                out.push_str(r"\left|");
                self.bare(out, x);
                out.push_str(r"\right|");
            }
            (_, [x], Notation::Latex) if operator_name(name).is_some() => {
                out.push('\\');
                out.push_str(operator_name(name).unwrap_or(name));
                self.function_argument(out, x);
            }
            _ => {
                out.push_str(name);
                out.push('(');
                for (k, a) in args.iter().enumerate() {
                    if k > 0 {
                        out.push_str(", ");
                    }
                    self.bare(out, a);
                }
                out.push(')');
            }
        }
    }

    /// `\sin\beta`, `\sin x`, `\sin(\beta + \theta)`: a lone symbol bare, else parenthesised.
    fn function_argument(&self, out: &mut String, x: &Node) {
        match &x.ast {
            Ast::Symbol(name) => {
                let latex = Symbol::new(name).latex();
                if !latex.starts_with('\\') {
                    out.push(' ');
                }
                out.push_str(latex);
            }
            _ => {
                out.push('(');
                self.bare(out, x);
                out.push(')');
            }
        }
    }

    fn sum(&self, out: &mut String, terms: &[(bool, Node)]) {
        for (k, (subtract, term)) in terms.iter().enumerate() {
            match (k, subtract) {
                (0, false) => {}
                (0, true) => out.push('-'),
                (_, false) => out.push_str(" + "),
                (_, true) => out.push_str(" - "),
            }
            // After a sign a negation is parenthesised: `a + (-b)`, never `a + -b`.
            let after_sign = k > 0 || *subtract;
            if after_sign && matches!(term.ast, Ast::Negate(_)) {
                out.push('(');
                self.bare(out, term);
                out.push(')');
            } else {
                self.node(out, term, Level::Cross);
            }
        }
    }

    fn power(&self, out: &mut String, base: &Node, exponent: &Node) {
        let function = match &base.ast {
            Ast::Call(name, args) if args.len() == 1 => operator_name(name).map(|f| (f, &args[0])),
            _ => None,
        };
        match (function, self.notation) {
            // `\sin^2 t`: the exponent on the function's name.
            (Some((f, argument)), Notation::Latex) => {
                out.push('\\');
                out.push_str(f);
                self.superscript(out, exponent);
                self.function_argument(out, argument);
            }
            _ if self.has_own_superscript(base) => {
                out.push('(');
                self.bare(out, base);
                out.push(')');
                self.superscript(out, exponent);
            }
            _ => {
                self.node(out, base, Level::Atom);
                self.superscript(out, exponent);
            }
        }
    }

    /// `^2`, `^{-2}`, `^{1/2}`; in text `^2`, `^(-2)`, `^(1/2)`.
    fn superscript(&self, out: &mut String, exponent: &Node) {
        out.push('^');
        if !self.latex() {
            self.node(out, exponent, Level::Atom);
            return;
        }
        let mut written = String::new();
        match &exponent.ast {
            // A quotient on the line: its factors in LaTeX, `/` between them.
            Ast::Product(factors) => {
                for (k, (divide, factor)) in factors.iter().enumerate() {
                    if k > 0 {
                        written.push_str(if *divide { "/" } else { " " });
                    }
                    let need = if k == 0 {
                        Level::Negation
                    } else {
                        Level::Power
                    };
                    self.node(&mut written, factor, need);
                }
            }
            _ => self.bare(&mut written, exponent),
        }
        if written.chars().count() == 1 {
            out.push_str(&written);
        } else {
            out.push('{');
            out.push_str(&written);
            out.push('}');
        }
    }

    fn product(&self, out: &mut String, factors: &[(bool, Node)]) {
        if !self.latex() {
            for (k, (divide, factor)) in factors.iter().enumerate() {
                if k > 0 {
                    out.push(if *divide { '/' } else { '*' });
                }
                let need = if k == 0 {
                    Level::Negation
                } else {
                    Level::Power
                };
                self.node(out, factor, need);
            }
            return;
        }
        // A minus before the first factor stands before the whole product.
        let (negative, first) = match factors.first() {
            Some((
                false,
                Node {
                    ast: Ast::Negate(inner),
                    ..
                },
            )) => (true, Some(&**inner)),
            _ => (false, None),
        };
        if negative {
            out.push('-');
        }
        let items: Vec<(bool, &Node)> = factors
            .iter()
            .enumerate()
            .map(|(k, (divide, n))| match (k, first) {
                (0, Some(inner)) => (*divide, inner),
                _ => (*divide, n),
            })
            .collect();
        let mut previous: Option<&Node> = None;
        let mut k = 0;
        while k < items.len() {
            let numerators: Vec<&Node> = items[k..]
                .iter()
                .take_while(|(divide, _)| !divide)
                .map(|(_, n)| *n)
                .collect();
            let after = k + numerators.len();
            let denominators: Vec<&Node> = items[after..]
                .iter()
                .take_while(|(divide, _)| *divide)
                .map(|(_, n)| *n)
                .collect();
            k = after + denominators.len();
            if denominators.is_empty() {
                for n in numerators {
                    self.factor(out, previous, n);
                    previous = Some(n);
                }
                continue;
            }
            if let Some(p) = previous {
                out.push_str(if is_long(p) || bare_function(p) {
                    r"\,"
                } else {
                    " "
                });
            }
            out.push_str(r"\frac{");
            if numerators.is_empty() {
                out.push('1');
            }
            self.fraction_part(out, &numerators);
            out.push_str("}{");
            self.fraction_part(out, &denominators);
            out.push('}');
            previous = denominators.last().copied();
        }
    }

    /// Above or below a fraction bar, which groups on its own: a lone sum needs no parentheses.
    fn fraction_part(&self, out: &mut String, factors: &[&Node]) {
        if let [alone] = factors {
            return self.bare(out, alone);
        }
        let mut previous = None;
        for n in factors {
            self.factor(out, previous, n);
            previous = Some(*n);
        }
    }

    /// A factor juxtaposed after `previous` (none: the first, where a minus needs no
    /// parentheses); the degree after a factor is a superscript circle, `30^\circ`
    /// (`{}^\circ` after a superscript).
    fn factor(&self, out: &mut String, previous: Option<&Node>, n: &Node) {
        let Some(previous) = previous else {
            return self.node(out, n, Level::Negation);
        };
        if matches!(&n.ast, Ast::Symbol(name) if name == super::DEGREE) {
            // After a factor that ends in a superscript of its own (`x^2`, `1e5`), the circle
            // stands on an empty group: a second superscript is an error to pdflatex.
            let superscripted = self.latex()
                && (matches!(previous.ast, Ast::Power(..)) || self.has_own_superscript(previous));
            out.push_str(if superscripted {
                r"{}^\circ"
            } else {
                r"^\circ"
            });
            return;
        }
        out.push_str(if starts_with_digit(n) {
            r" \cdot "
        } else if is_long(previous) || is_long(n) || bare_function(previous) && !is_function(n) {
            r"\,"
        } else {
            " "
        });
        self.node(out, n, Level::Power);
    }
}

/// The text of a number node as the user typed it: its span without the parentheses
/// around it (`(1e5)` is the number `1e5`; a number's own text holds none).
fn number_text<'s>(source: &'s str, node: &Node) -> &'s str {
    source
        .get(node.span.0..node.span.1)
        .unwrap_or("")
        .trim_matches(|c: char| c == '(' || c == ')' || c.is_whitespace())
}

/// A number in scientific notation as its mantissa and its exponent without a plus sign:
/// `2.5E+10` is `("2.5", "10")`, `1e-5` `("1", "-5")`; none for a number without one.
fn scientific(number: &str) -> Option<(&str, &str)> {
    number
        .split_once(['e', 'E'])
        .map(|(mantissa, exponent)| (mantissa, exponent.trim_start_matches('+')))
}

/// Whether the LaTeX of `node` begins with a digit (after which juxtaposition would read
/// as one number: `2 \cdot 3`).
fn starts_with_digit(node: &Node) -> bool {
    match &node.ast {
        Ast::Number(_) => true,
        Ast::Power(base, _) => starts_with_digit(base),
        _ => false,
    }
}

/// A symbol (or a power of one) whose LaTeX reads as several letters: `\Delta t`, `\mathit{Lb}`.
fn is_long(node: &Node) -> bool {
    match &node.ast {
        Ast::Power(base, _) => is_long(base),
        Ast::Symbol(name) => reads_as_several_letters(Symbol::new(name).latex()),
        _ => false,
    }
}

/// `\sin\beta` (or a power of it): a function of a symbol written without parentheses.
fn bare_function(node: &Node) -> bool {
    match &node.ast {
        Ast::Power(base, _) => bare_function(base),
        Ast::Call(name, args) => {
            name != "abs"
                && Func::from_name(name).is_some()
                && matches!(
                    args.as_slice(),
                    [Node {
                        ast: Ast::Symbol(_),
                        ..
                    }]
                )
        }
        _ => false,
    }
}

/// The LaTeX operator (without its backslash) of a function written `name(x)`: `sin`,
/// `arccos`, `cot`; none for `abs` and `sqrt`, which are not written as operators.
fn operator_name(name: &str) -> Option<&str> {
    match Func::from_name(name) {
        Some(Func::Abs) => None,
        Some(f) => Some(f.page_name()),
        None => RECIPROCAL_TRIG
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|(n, _, _)| *n),
    }
}

fn is_function(node: &Node) -> bool {
    match &node.ast {
        Ast::Power(base, _) => is_function(base),
        Ast::Call(name, _) => operator_name(name).is_some(),
        _ => false,
    }
}
