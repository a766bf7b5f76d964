//! The table of readings: each rule a name and a small function that reads the differences
//! of a claim (`comparison.rs`) and, when its pattern fits, says what the slip is in words.
//! The rules are tried in the table's order and the first that fits wins, so the more
//! specific come first:
//!
//! ```text
//! cyclic-order             (I_z − I_y) ω_y ω_z for (I_y − I_z) ω_y ω_z; axes permuted x→y→z
//! product-sign-convention  +I_xy where the chapter has −I_xy
//! scaled                   the whole side k times the correct one
//! sign-flipped             a few terms with their signs flipped
//! factor-off               one term k times what it should be
//! swapped-subscripts       I_xz where I_yz belongs
//! sin-for-cos              sin θ where cos θ belongs, or back
//! repeated-term            I_x ω_x² three times for I_x ω_x² + I_y ω_y² + I_z ω_z²
//! missing-term             terms left out
//! extra-term               terms that do not belong
//! ```
//!
//! A new kind of slip is one entry here and one function.

use super::coefficient_rules::{factor_off, scaled, sign_flipped};
use super::comparison::Differences;
use super::presence_rules::{extra_term, missing_term};
use super::product_sign::product_sign_convention;
use super::sin_for_cos::sin_for_cos;
use super::subscript_rules::{cyclic_order, repeated_term, swapped_subscripts};
use super::Reading;

/// A named reading: its pattern, read from the differences, gives the explanation.
pub(super) struct Rule {
    pub name: &'static str,
    pub reads: fn(&Differences) -> Option<String>,
}

/// The rules in the order they are tried (module documentation).
const RULES: [Rule; 10] = [
    Rule {
        name: "cyclic-order",
        reads: cyclic_order,
    },
    Rule {
        name: "product-sign-convention",
        reads: product_sign_convention,
    },
    Rule {
        name: "scaled",
        reads: scaled,
    },
    Rule {
        name: "sign-flipped",
        reads: sign_flipped,
    },
    Rule {
        name: "factor-off",
        reads: factor_off,
    },
    Rule {
        name: "swapped-subscripts",
        reads: swapped_subscripts,
    },
    Rule {
        name: "sin-for-cos",
        reads: sin_for_cos,
    },
    Rule {
        name: "repeated-term",
        reads: repeated_term,
    },
    Rule {
        name: "missing-term",
        reads: missing_term,
    },
    Rule {
        name: "extra-term",
        reads: extra_term,
    },
];

/// The names of the rules, in the order they are tried ([`super::READINGS`]).
pub(super) const fn names() -> [&'static str; RULES.len()] {
    let mut names = [""; RULES.len()];
    let mut i = 0;
    while i < RULES.len() {
        names[i] = RULES[i].name;
        i += 1;
    }
    names
}

/// The first reading of the table that fits the differences, if any.
pub(super) fn first_reading(differences: &Differences) -> Option<Reading> {
    RULES.iter().find_map(|rule| {
        (rule.reads)(differences).map(|explanation| Reading {
            name: rule.name,
            explanation,
        })
    })
}
