//! The names written in a claim, resolved by the checker's context as they are met while
//! the claim is lowered: each distinct name is asked once ([`Name`]), and the derived ones a
//! side uses are recorded for that side, in the order first written. The unit vectors
//! `i j k` and `pi` are never asked (nor `deg`, read before names).

use super::claim::Name;
use crate::algebra::{Expr, PI_NAME};
use std::collections::HashMap;

/// Names with a fixed meaning in every claim.
const FIXED: [&str; 4] = ["i", "j", "k", PI_NAME];

/// What a name was resolved to, and the side it was last recorded for.
struct Resolution {
    name: Name,
    recorded_on: Option<usize>,
}

/// The resolver of a claim's names and what it answered so far.
pub(super) struct Names<'a> {
    resolve: &'a dyn Fn(&str) -> Name,
    known: HashMap<String, Resolution>,
    /// The side being read: 0 the left, 1 the right.
    side: usize,
    /// The derived names the side being read uses, each once.
    resolved: Vec<String>,
}

impl<'a> Names<'a> {
    pub(super) fn new(resolve: &'a dyn Fn(&str) -> Name) -> Names<'a> {
        Names {
            resolve,
            known: HashMap::new(),
            side: 0,
            resolved: Vec::new(),
        }
    }

    /// The value of `written`: its symbol, or the derived value (recorded for this side);
    /// for a name the context does not know, its help.
    pub(super) fn value(&mut self, written: &str) -> Result<Expr, String> {
        if FIXED.contains(&written) {
            return Ok(Expr::symbol(written));
        }
        let resolve = self.resolve;
        let resolution = self
            .known
            .entry(written.to_string())
            .or_insert_with(|| Resolution {
                name: resolve(written),
                recorded_on: None,
            });
        match &resolution.name {
            Name::Symbol => Ok(Expr::symbol(written)),
            Name::Derived(value) => {
                if resolution.recorded_on != Some(self.side) {
                    resolution.recorded_on = Some(self.side);
                    self.resolved.push(written.to_string());
                }
                Ok(value.clone())
            }
            Name::Unknown(help) => Err(help.clone()),
        }
    }

    /// The derived names the side just read uses; what follows is the next side.
    pub(super) fn end_side(&mut self) -> Vec<String> {
        self.side += 1;
        std::mem::take(&mut self.resolved)
    }
}
