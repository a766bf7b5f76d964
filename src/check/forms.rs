//! The forms a report shows its expressions in: the textbook's ([`presented`]), or the
//! canonical one past [`PRESENTED_SIZE`] or [`PRESENTED_TERMS`] (simplifying it for reading
//! would take longer than the check). Each expression is brought to its form once per
//! [`Forms`]: the claims of a class set about one component share its correct form, and
//! simplifying it for every claim was a fifth of the marking.

use crate::algebra::{Domains, Expr};
use crate::mechanics::derivation::presented;
use std::collections::HashMap;
use std::sync::{Mutex, MutexGuard};

/// The largest form (in [`Expr::has_at_most_size`]'s measure) shown in the textbook's form.
const PRESENTED_SIZE: usize = 2000;
/// The most terms a form shown in the textbook's form may multiply out to (estimated
/// first): simplifying cancels, which multiplies out numerator and denominator.
const PRESENTED_TERMS: f64 = 2000.0;

/// The forms of the expressions of one context's reports, each found once (shared by the
/// threads writing a class set's reports).
pub struct Forms<'d> {
    domains: &'d Domains,
    found: Mutex<HashMap<Expr, Expr>>,
}

impl<'d> Forms<'d> {
    /// Forms under the assumptions of a context (its [`Domains`]).
    pub fn new(domains: &'d Domains) -> Self {
        Forms {
            domains,
            found: Mutex::new(HashMap::new()),
        }
    }

    /// The form `e` is shown in.
    pub fn readable(&self, e: &Expr) -> Expr {
        if !(e.has_at_most_size(PRESENTED_SIZE) && e.estimated_expanded_terms() <= PRESENTED_TERMS)
        {
            return e.clone();
        }
        if let Some(form) = self.found().get(e) {
            return form.clone();
        }
        let form = presented(e, self.domains);
        self.found().insert(e.clone(), form.clone());
        form
    }

    /// The forms found so far. A poisoned lock only means another thread panicked while
    /// inserting: the forms found are still right.
    fn found(&self) -> MutexGuard<'_, HashMap<Expr, Expr>> {
        self.found
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A form asked for again is the one found the first time, the textbook's; a form past
    /// the bounds is shown as it is.
    #[test]
    fn a_form_is_the_textbooks_and_found_once() {
        let domains = Domains::chapter_defaults();
        let forms = Forms::new(&domains);
        let (m, r, w) = (Expr::symbol("m"), Expr::symbol("r"), Expr::symbol("w"));
        let e = Expr::rational(1, 4) * m.clone() * r.clone().powi(2) * w.clone()
            + Expr::rational(1, 4) * m * r.powi(2) * w.powi(2);
        assert_eq!(forms.readable(&e), presented(&e, &domains));
        assert_eq!(forms.found().len(), 1);
        assert_eq!(forms.readable(&e), presented(&e, &domains));
        assert_eq!(forms.found().len(), 1);
        let large = (0..PRESENTED_SIZE as i64)
            .map(|k| Expr::symbol(&format!("x_{k}")) * Expr::rational(k + 2, 1))
            .fold(Expr::zero(), |sum, term| sum + term);
        assert_eq!(forms.readable(&large), large);
        assert_eq!(forms.found().len(), 1);
    }
}
