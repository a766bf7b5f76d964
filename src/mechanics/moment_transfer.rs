//! The angular momentum and its rate carried from the mass centre G to the origin O (§18.1,
//! §18.5): the moment about O of the momentum (or its rate) placed at G,
//!
//! ```text
//! H_O = H_G + r̄ × m v̄
//! Ḣ_O = Ḣ_G + r̄ × m ā        (O fixed)
//! ```
//!
//! where `r̄` is the position of G from O.

use super::derivation::{Derivation, Relation, Step};
use crate::algebra::vector::expand_each;
use crate::algebra::vector_products::cross;
use crate::algebra::{AlgebraError, Vector};

/// How one transfer is named and shown: the components' name (`H`, `Hdot`), the moment's
/// name (`\bar{\mathbf{r}} \times m\bar{\mathbf{v}}`), the derivation's name and title, and
/// the titles of its two steps.
pub(super) struct Labels<'a> {
    pub components: &'a str,
    pub moment: &'a str,
    pub name: &'a str,
    pub title: &'a str,
    pub moment_title: &'a str,
    pub total_title: &'a str,
}

/// `X_O = X_G + r̄ × (m u)`: `about_g` is `X_G`, `momentum` is `m u` placed at G.
pub(super) fn moment_transfer(
    about_g: &Vector,
    rbar: &Vector,
    momentum: &Vector,
    labels: Labels,
) -> Result<Derivation, AlgebraError> {
    let moment = expand_each(&cross(rbar, momentum))?;
    let about_o = expand_each(&(about_g + &moment))?;
    Ok(Derivation {
        name: labels.name.into(),
        title: labels.title.into(),
        steps: vec![
            Step::vector(labels.moment_title, labels.moment, moment),
            Step::new(
                labels.total_title,
                Relation::components(labels.components, &about_o),
            ),
        ],
    })
}
