//! Symbol domains: which symbols stand for positive quantities, so that `√(a²) = a` and
//! `|m| = m` may be used for them and never for a symbol that may be negative.
//!
//! The chapter's defaults, outside a scene ([`Domains::chapter_defaults`]), decided from a
//! symbol's [`Role`] and name (a dotted symbol, a rate, is always real):
//!
//! | positive | real |
//! |---|---|
//! | masses `m`, `m_1`, `m_A` | coordinates `x`, `y`, `z`, `xbar`, `x_1` |
//! | lengths and radii `L`, `l`, `r`, `R`, `a`, `b`, `c`, `d`, `h`, `e`, `r_1`, `d_2` | components `w_x`, `v_x`, `H_x`, `F_x`, `r_x`, `a_x` |
//! | moments of inertia `I`, `I_x`, `I_y'`, `I_G`, `I_O`, `Ibar_x`, `I_1` | products of inertia `I_xy`, `I_yz'` |
//! | times `t`, `t_1`, `Dt`; the constant `pi` (π) | angles and rates `theta`, `beta`, `w`, `alpha`, `phi`, any dotted symbol |
//! | | everything else: forces `F`, `P`, couples `M`, `g` |
//!
//! A scene declares more ([`Domains::declare`]): its givens in kg, m, s, N and kg·m² are
//! positive unless written `real`. A declaration overrides the default.
//!
//! ```
//! use kinetics::algebra::{Domain, Domains, Expr, Symbol};
//! let mut domains = Domains::chapter_defaults();
//! assert_eq!(domains.domain(Symbol::new("m_1")), Domain::Positive);
//! assert_eq!(domains.domain(Symbol::new("x")), Domain::Real);
//! assert_eq!(domains.domain(Symbol::new("I_xy")), Domain::Real);
//! domains.declare(Symbol::new("x"), Domain::Positive);
//! assert!(domains.is_positive(&(Expr::symbol("x") + Expr::symbol("L"))));
//! ```

use super::expr::Expr;
use super::symbol::{Role, Symbol};
use std::collections::HashMap;

/// The values a symbol may take.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Domain {
    /// Greater than zero: a mass, a length, a moment of inertia, a time.
    Positive,
    /// Any real number: a coordinate, a component, an angle, a rate.
    Real,
}

/// Which symbols are positive: the chapter's defaults (module documentation) and the
/// declarations made over them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Domains {
    declared: HashMap<Symbol, Domain>,
}

impl Domains {
    /// The chapter's defaults, with nothing declared (see the module documentation).
    pub fn chapter_defaults() -> Domains {
        Domains::default()
    }

    /// Declares the domain of `s`, over its default or an earlier declaration.
    pub fn declare(&mut self, s: Symbol, d: Domain) {
        self.declared.insert(s, d);
    }

    /// The domain of `s`: its declaration, else the chapter's default.
    pub fn domain(&self, s: Symbol) -> Domain {
        self.declared
            .get(&s)
            .copied()
            .unwrap_or_else(|| default_domain(s))
    }

    /// Whether `e` is provably positive: positive numbers and symbols, and sums, products,
    /// quotients and powers of positive things, an even power or the absolute value of
    /// something provably nonzero. False when unsure.
    pub fn is_positive(&self, e: &Expr) -> bool {
        self.sign(e) == super::sign::Sign::Positive
    }
}

/// The chapter's default domain of a symbol (the table of the module documentation).
fn default_domain(s: Symbol) -> Domain {
    if s.dots() > 0 {
        return Domain::Real;
    }
    let subscript = s.subscript().trim_end_matches('\'');
    let component = axis_letters(subscript) > 0 && axis_letters(subscript) == subscript.len();
    let positive = match s.role() {
        Role::Mass => true,
        Role::Inertia => !(component && subscript.len() == 2 && !repeated(subscript)),
        Role::Length => {
            !matches!(s.base(), "x" | "y" | "z") && !component && !s.name().contains("bar")
        }
        Role::Other => {
            matches!(s.base(), "R" | "t" | "Dt" | "pi") && !component && !s.name().contains("bar")
        }
        Role::Kinematic | Role::UnitVector => false,
    };
    if positive {
        Domain::Positive
    } else {
        Domain::Real
    }
}

/// How many letters of a subscript name axes (`x`, `y`, `z`, either case).
fn axis_letters(subscript: &str) -> usize {
    subscript
        .chars()
        .filter(|c| matches!(c, 'x' | 'y' | 'z' | 'X' | 'Y' | 'Z'))
        .count()
}

/// Whether a two-letter subscript repeats its letter (`xx`: a moment, not a product).
fn repeated(subscript: &str) -> bool {
    let mut letters = subscript.chars().map(|c| c.to_ascii_lowercase());
    letters.next() == letters.next()
}
