//! The `given` statement: a symbol with a value and a unit, or a unit alone, and its
//! domain. A given in kg, m, s, N or kg·m² (a mass, a length, a time, the magnitude of a
//! force, a moment of inertia; in any unit of those kinds) is positive unless it is written
//! `real` (`given x = 0.2 m real`, `given x : m real`: a coordinate) or its value is
//! negative; any other given is real, and `real` on it is refused at the word.

use super::super::model::{Definition, Given, Written};
use super::super::named_unit::NamedUnit;
use super::super::units::Dimension;
use super::{span, Reader, Rule};
use crate::algebra::{Domain, Expr, Symbol};
use crate::mechanics::validation::validate_mass;
use crate::parse::Diagnostic;
use crate::scene::model::Span;
use pest::iterators::Pair;

/// The dimensions of the givens that are positive unless written `real`.
const POSITIVE_UNITS: [Dimension; 5] = [
    Dimension::MASS,
    Dimension::LENGTH,
    Dimension::TIME,
    Dimension::FORCE,
    Dimension::INERTIA,
];

impl Reader<'_> {
    pub(super) fn given(&mut self, inner: Vec<Pair<Rule>>) -> Result<(), Diagnostic> {
        let name = &inner[0];
        let mut value = None;
        let mut written = None;
        let mut dimension = None;
        let mut real = None;
        let mut definition = None;
        for p in &inner[1..] {
            match p.as_rule() {
                Rule::real => real = Some(span(p)),
                Rule::definition => {
                    let (expr, d) = self.definition(p)?;
                    value = expr.eval(&|s: Symbol| self.scene.value(s)).ok();
                    let exact = self.exact_definition(&expr);
                    definition = Some(Definition { expr, exact });
                    dimension = Some((d, span(p)));
                }
                Rule::quantity => {
                    let mut q = p.clone().into_inner();
                    let number = q
                        .next()
                        .ok_or_else(|| self.error(span(p), "expected a number"))?;
                    let n: f64 = number
                        .as_str()
                        .parse()
                        .map_err(|_| self.error(span(&number), "not a number"))?;
                    if !n.is_finite() {
                        return Err(self
                            .error(span(&number), "the value is not a finite number")
                            .with_help("write the value in a unit that keeps it within 1e308"));
                    }
                    let named = match q.next() {
                        Some(u) => self.unit(&u)?,
                        None => NamedUnit::default(),
                    };
                    let unit = named.unit();
                    value = Some(n * self.scene.unit_system.of_one(&named));
                    written = Some(Written {
                        number: number.as_str().to_string(),
                        unit: named,
                    });
                    dimension = Some((unit.dimension, span(p)));
                }
                Rule::unit => {
                    let unit = self.unit(p)?.unit();
                    if let Some((d, _)) = dimension {
                        if d != unit.dimension {
                            return Err(self
                                .error(
                                    span(p),
                                    format!(
                                        "unit mismatch: the value is in {} but the unit is {}",
                                        self.unit_of(d),
                                        self.unit_of(unit.dimension)
                                    ),
                                )
                                .with_help("give the value in a unit of the declared kind"));
                        }
                    }
                    dimension = Some((unit.dimension, span(p)));
                }
                _ => {}
            }
        }
        let Some((dimension, _)) = dimension else {
            return Err(self
                .error(
                    span(name),
                    format!("the given {} has neither a value nor a unit", name.as_str()),
                )
                .with_help(format!(
                    "write 'given {0} = 2 m' or 'given {0} : m'",
                    name.as_str()
                )));
        };
        let positive = POSITIVE_UNITS.contains(&dimension);
        if let (Some(at), false) = (real, positive) {
            return Err(self
                .error(
                    at,
                    format!("{} is real already: it is in {dimension}", name.as_str()),
                )
                .with_help(
                    "'real' is for a given in kg, m, s, N or kg·m², which is otherwise positive",
                ));
        }
        let symbol = self.declare(name, dimension)?;
        if dimension == Dimension::MASS
            && value.is_some_and(|v| validate_mass(name.as_str(), v).is_err())
        {
            return Err(self
                .error(
                    span(&inner[1]),
                    format!("mass {} must be positive", name.as_str()),
                )
                .with_help("a body's mass is a positive number"));
        }
        self.scene.givens.push(Given {
            symbol,
            dimension,
            value,
            written,
            definition,
            domain: if positive && real.is_none() && !value.is_some_and(|v| v < 0.0) {
                Domain::Positive
            } else {
                Domain::Real
            },
            span: Span {
                start: span(name).0,
                end: span(name).1,
            },
        });
        Ok(())
    }

    /// `given psidot = v/r_w`: the expression in the scene's units and its dimension, from givens declared
    /// before it (an unknown or a name declared later is refused at the expression).
    fn definition(&self, p: &Pair<Rule>) -> Result<(Expr, Dimension), Diagnostic> {
        let e = self
            .math(p)
            .map_err(|d| match reads_as_a_value(p.as_str()) {
                true => self.unreadable_value(d),
                false => self.declared_later(d, span(p).1),
            })?;
        if let Some(u) = e.symbols().into_iter().find(|s| self.scene.is_unknown(*s)) {
            return Err(self
                .error(
                    span(p),
                    format!(
                        "a given is defined by givens, and {} is an unknown",
                        u.name()
                    ),
                )
                .with_help(
                    "declare the givens it is made of first, or make this quantity an unknown too",
                ));
        }
        let dimension = self.dimension(&e, span(p))?;
        Ok((self.in_units(&e, span(p))?, dimension))
    }

    /// A value that is neither a number with its unit nor an expression (`2,5 kg`,
    /// `2 kg;`, `NaN kg`): refused where the expression's reading stopped, the character
    /// there named.
    fn unreadable_value(&self, d: Diagnostic) -> Diagnostic {
        let at = d.span.offset();
        let found = self.source[at..].chars().next().unwrap_or(' ');
        let help = match found {
            ',' => "a decimal is written with a point, 2.5, and one given a line",
            '.' => "a number has at most one decimal point",
            _ => "write the value as a number and its unit, 'given m = 2.5 kg', or define it by earlier givens, 'given b = 2*a'",
        };
        self.error(
            (at, at + d.span.len().max(1)),
            format!(
                "cannot read this 'given' statement (found '{}'): its value is neither a number with a unit nor an expression of earlier givens",
                found.escape_default()
            ),
        )
        .with_help(help)
    }

    /// An unknown symbol in a definition that a `given` after it declares: the help says so
    /// (the definition reads only the givens before it).
    fn declared_later(&self, d: Diagnostic, after: usize) -> Diagnostic {
        let Some(name) = d.message.strip_prefix("unknown symbol ") else {
            return d;
        };
        let later = self.source[after..].lines().enumerate().find(|(_, line)| {
            let rest = line.trim_start().strip_prefix("given ").unwrap_or_default();
            let declared: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            declared == name
        });
        let Some((k, _)) = later else {
            return d;
        };
        let line = self.source[..after].matches('\n').count() + 1 + k;
        let help = format!(
            "{name} is given on line {line}, after this one: a given is defined by the givens before it, so move this line below that one"
        );
        d.with_help(help)
    }

    /// A defined given's exact value, when every given it is made of has one (and the
    /// algebra's bounds allow it).
    fn exact_definition(&self, e: &Expr) -> Option<Expr> {
        let scene = &self.scene;
        let exact = |s: Symbol| scene.exact_given(s);
        let all_exact = e
            .symbols()
            .into_iter()
            .all(|s| s.is_pi() || exact(s).is_some());
        all_exact.then(|| e.subs(&exact).ok()).flatten()
    }
}

/// Whether a given's text after `=` starts as a number would (a digit, a point, a sign, or
/// the words NaN and inf), so that an error reading it is about its value.
fn reads_as_a_value(text: &str) -> bool {
    let text = text.trim_start();
    let word: String = text.chars().take_while(char::is_ascii_alphabetic).collect();
    text.starts_with(|c: char| c.is_ascii_digit() || c == '.' || c == '-')
        || ["nan", "inf", "infinity"].contains(&word.to_ascii_lowercase().as_str())
}
