//! Distinct symbols, distinct LaTeX on one page.
//!
//! The chapter spells the symbol `w` as ω (and `Dt` as Δt), so a scene that gives `w_x` and
//! derives `omega_x` would print two different quantities as one `\omega_x`. On a page
//! declared with [`on_one_page`], every symbol whose LaTeX another symbol of the page shares
//! and that has a plain spelling ([`Symbol::plain_latex`]) prints in it: the alias keeps
//! the letter it was written with (`w_x`, `\mathit{Dt}`), the symbol named for the Greek
//! letter keeps it (`omega_x` is `\omega_x`). A page without such a pair prints as before.
//!
//! ```
//! use kinetics::algebra::{Expr, Symbol};
//! use kinetics::print;
//! let (w, omega) = (Symbol::new("w_x"), Symbol::new("omega_x"));
//! let printed = print::on_one_page([w, omega], || print::latex(&(Expr::sym(w) - Expr::sym(omega))));
//! assert_eq!(printed, r"w_x - \omega_x");
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
/// of them prints in its plain spelling. Pages nest; the outer page is restored after, also
/// when `print` panics.
pub fn on_one_page<R>(symbols: impl IntoIterator<Item = Symbol>, print: impl FnOnce() -> R) -> R {
    let mut symbols: Vec<Symbol> = symbols.into_iter().collect();
    symbols.sort();
    symbols.dedup();
    let mut sharing: HashMap<&str, usize> = HashMap::with_capacity(symbols.len());
    for s in &symbols {
        *sharing.entry(s.latex()).or_default() += 1;
    }
    let plain: Vec<Symbol> = symbols
        .into_iter()
        .filter(|s| sharing[s.latex()] > 1 && s.plain_latex() != s.latex())
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
