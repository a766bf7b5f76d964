//! Distinct symbols, distinct LaTeX on one page.
//!
//! The chapter spells the symbol `w` as ω (and `Dt` as Δt), so a scene that gives `w_x` and
//! derives `omega_x` would print two different quantities as one `\omega_x`. On a page
//! declared with [`on_one_page`], every symbol whose LaTeX another symbol of the page shares
//! and that has a plain spelling ([`Symbol::plain_latex`]) prints in it: the alias keeps
//! the letter it was written with (`w_x`, `\mathit{Dt}`), the symbol named for the Greek
//! letter keeps it (`omega_x` is `\omega_x`). Symbols the page states to be one quantity
//! (a relation `omega_x = w_x`, one symbol each side) are not told apart: they are the same
//! ω_x. A page without such a pair prints as before.
//!
//! ```
//! use kinetics::algebra::{Expr, Symbol};
//! use kinetics::print;
//! let (w, omega) = (Symbol::new("w_x"), Symbol::new("omega_x"));
//! let difference = Expr::sym(w) - Expr::sym(omega);
//! let apart = print::on_one_page([w, omega], [], || print::latex(&difference));
//! assert_eq!(apart, r"-\omega_x + w_x");
//! let same = print::on_one_page([w, omega], [(omega, w)], || print::latex(&difference));
//! assert_eq!(same, r"-\omega_x + \omega_x");
//! assert_eq!(print::latex(&Expr::sym(w)), r"\omega_x");
//! ```

use crate::algebra::Symbol;
use std::cell::RefCell;
use std::collections::HashMap;

thread_local! {
    /// The symbols the page being printed on this thread spells plainly.
    static PLAIN: RefCell<Vec<Symbol>> = const { RefCell::new(Vec::new()) };
}

/// Runs `print` with `symbols` as one page: a symbol that would share its LaTeX with another
/// of them, not stated the same by one of `identities`, prints in its plain spelling. Pages
/// nest; the outer page is restored after, also when `print` panics.
pub fn on_one_page<R>(
    symbols: impl IntoIterator<Item = Symbol>,
    identities: impl IntoIterator<Item = (Symbol, Symbol)>,
    print: impl FnOnce() -> R,
) -> R {
    let mut symbols: Vec<Symbol> = symbols.into_iter().collect();
    symbols.sort();
    symbols.dedup();
    let identities: Vec<(Symbol, Symbol)> = identities.into_iter().collect();
    let same = |a: Symbol, b: Symbol| {
        a == b || identities.contains(&(a, b)) || identities.contains(&(b, a))
    };
    let mut sharing: HashMap<&str, Vec<Symbol>> = HashMap::with_capacity(symbols.len());
    for &s in &symbols {
        sharing.entry(s.latex()).or_default().push(s);
    }
    let plain: Vec<Symbol> = symbols
        .into_iter()
        .filter(|&s| {
            s.plain_latex() != s.latex() && sharing[s.latex()].iter().any(|&t| !same(s, t))
        })
        .collect();
    let outer = PLAIN.with(|p| p.replace(plain));
    /// Puts the outer page back when the inner one ends.
    struct Restore(Option<Vec<Symbol>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            if let Some(outer) = self.0.take() {
                PLAIN.with(|p| *p.borrow_mut() = outer);
            }
        }
    }
    let _restore = Restore(Some(outer));
    print()
}

/// The LaTeX of `s` on the page being printed.
#[inline]
pub(super) fn latex_of(s: Symbol) -> &'static str {
    let plain = PLAIN.with(|p| {
        let plain = p.borrow();
        !plain.is_empty() && plain.contains(&s)
    });
    if plain {
        s.plain_latex()
    } else {
        s.latex()
    }
}
