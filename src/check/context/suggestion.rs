//! A name the context does not know: refused with the known names nearest to it (`Ix` for
//! `I_x`, one letter off), never taken as a new symbol when it misspells one.

use super::Context;

impl Context {
    /// Whether `written` is a known subscripted name with its underscore left out (`Ix` for
    /// `I_x`, `hx` for `H_x`): refused with the suggestion, never a new symbol. (Names that
    /// differ in case alone, `l` and `L`, are two symbols.)
    pub(super) fn spelt_like_known(&self, written: &str) -> bool {
        let folded = fold(written);
        !written.contains('_')
            && self
                .known_names()
                .any(|k| k.contains('_') && fold(k) == folded)
    }

    fn known_names(&self) -> impl Iterator<Item = &str> {
        self.meanings
            .keys()
            .map(String::as_str)
            .chain(self.dimensions.keys().map(|s| s.name()))
    }

    /// The help for an unknown name: the known names nearest to it, else all of them.
    pub(super) fn suggestion(&self, written: &str) -> String {
        let mut near: Vec<&str> = self
            .known_names()
            .filter(|k| fold(k) == fold(written) || close(k, written))
            .collect();
        near.sort_unstable();
        near.dedup();
        if near.is_empty() {
            let mut names: Vec<&str> = self.known_names().collect();
            names.sort_unstable();
            names.dedup();
            format!("{} knows: {}", self.description, names.join(", "))
        } else {
            format!("did you mean {}?", near.join(" or "))
        }
    }
}

/// A name in lower case without underscores: `I_x` and `Ix` fold alike.
fn fold(name: &str) -> String {
    name.to_lowercase().replace('_', "")
}

/// Whether two names are one edit apart (a letter added, dropped or changed).
fn close(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if a.len().abs_diff(b.len()) > 1 || a.len() < 2 {
        return false;
    }
    let prefix = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let suffix = a[prefix..]
        .iter()
        .rev()
        .zip(b[prefix..].iter().rev())
        .take_while(|(x, y)| x == y)
        .count();
    a.len().max(b.len()) - prefix - suffix <= 1
}
