//! The engineer's page (`kinetics solve --numbers`): the givens, each result as a number
//! with its unit, and the key intermediate values of the plan (mass, mass centre, moments
//! and products of inertia, H, Ḣ, … whatever it derived), each as a number; no symbolic
//! steps. A relation `name = rhs` of a step is an intermediate value when `rhs` evaluates
//! with the givens ([`super::evaluation::value`]: exact where it folds, rounded once):
//!
//! ```text
//! Step k: title            →  name = value unit      (one line per relation with a value)
//! ```
//!
//! A value's unit is its name's: a declared symbol's own, a derived name's by the chapter's
//! naming ([`crate::scene::derived_dimension`]: `I_xy` kg·m², `v_Ax` m/s), else its
//! right-hand side's SI unit.

use super::page::{Block, Heading, Page, Section};
use super::result::Result;
use super::shown_value::ShownValue;
use crate::algebra::{Axis, Expr, Symbol};
use crate::figure::Figure;
use crate::mechanics::derivation::Step;
use crate::print::{self, Notation};
use crate::scene::derived_dimension;
use crate::scene::named_unit::{NamedUnit, NO_UNIT};
use crate::scene::units::dimension_of;
use crate::scene::units::{Dimension, Dimensions};
use crate::scene::{Analysis, Scene};
use std::collections::HashMap;

/// The numbers of one step of the plan.
pub(super) struct StepValues {
    /// The step's title, in the markup of titles.
    pub title: String,
    pub values: Vec<Number>,
}

/// A derived quantity's value and unit: `name = value unit`.
pub(super) struct Number {
    /// The quantity (a relation's left-hand side) and the axis it is written about.
    pub name: Expr,
    pub axis: Axis,
    pub value: f64,
    pub unit: Option<NamedUnit>,
}

/// The engineer's page: the title, the figure, the givens, the results by their numbers (the
/// answers), then the intermediate values step by step.
pub(super) fn numbers_page<'a>(
    scene: &'a Scene,
    results: &'a [Result<'a>],
    steps: &'a [StepValues],
    figure: Option<&'a Figure>,
) -> Page<'a> {
    let mut sections: Vec<Section> = figure
        .map(|f| Section::new(Heading::Statement, vec![Block::Figure(f)]))
        .into_iter()
        .collect();
    sections.extend([
        Section::new(Heading::Given, vec![Block::Givens(&scene.givens)]),
        Section::new(Heading::Results, vec![Block::Answers(results)]),
    ]);
    if !steps.is_empty() {
        sections.push(Section::new(
            Heading::Intermediate,
            vec![Block::Values(steps)],
        ));
    }
    Page {
        title: scene.title.as_deref(),
        untitled: "Numbers",
        sections,
        figure_file: None,
    }
}

impl Number {
    /// The value with its unit.
    pub(super) fn shown_value(&self) -> ShownValue<'_> {
        ShownValue {
            numbers: std::slice::from_ref(&self.value),
            unit: self.unit.as_ref().unwrap_or(&NO_UNIT),
        }
    }
}

/// The steps that have intermediate values, in the plan's order; a step of equations (a
/// left-hand side that is not a name) has none.
pub(super) fn intermediate(
    scene: &Scene,
    analysis: &Analysis,
    dims: &Dimensions,
) -> Vec<StepValues> {
    // A derived name's unit is the chapter's (`I_xy`: kg·m²), a declared one's its own:
    // the right-hand side may hold plain numbers in the scene's units (`150 mm` is 3/20) and tell nothing.
    let dimension_of = |lhs: &Expr, rhs: &Expr| {
        let symbol = lhs.as_symbol()?;
        let declared = dims.get(&symbol).copied();
        declared
            .or_else(|| derived_dimension(symbol.name()))
            .or_else(|| dimension_of(rhs, dims).ok().filter(|_| !rhs.is_zero()))
    };
    // With the givens, else with the unknowns of `solution` put in; with `needing_it`, only
    // the values that need the solution.
    let values =
        |step: &Step, solution: Option<&HashMap<Symbol, Expr>>, needing_it: bool| -> Vec<Number> {
            if step.relations.iter().any(|r| r.lhs.as_symbol().is_none()) {
                return Vec::new();
            }
            // A name for a long radicand is no quantity; a value is computed from the whole
            // expression the names stand for.
            let named = &analysis.abbreviations;
            step.relations
                .iter()
                .filter(|r| !r.lhs.as_symbol().is_some_and(|s| named.is_name(s)))
                .filter_map(|r| {
                    let shown_name = print::render(&r.lhs, Notation::Text, r.axis);
                    let rhs = named.whole(&r.rhs);
                    // The kinetic energy is work: joules (foot-pounds), as in the results.
                    let energy = stem(&shown_name) == "T";
                    // An unknown's declared unit (`unknown theta : deg`), as in the results.
                    let declared = r.lhs.as_symbol().and_then(|s| {
                        let (_, unit) = scene.unknown_units.iter().find(|(u, _)| *u == s)?;
                        Some(unit.clone())
                    });
                    // A pure number has no unit (K_y as K_x).
                    let unit = declared.or_else(|| {
                        dimension_of(&r.lhs, &rhs)
                            .filter(|d| *d != Dimension::NONE)
                            .map(|d| scene.unit_system.unit(d, energy))
                    });
                    let in_system = match super::evaluation::value(scene, &rhs) {
                        Some(_) if needing_it => return None,
                        Some(v) => v,
                        None => {
                            let unknowns = solution?;
                            let with_unknowns = rhs.subs(&|u| unknowns.get(&u).cloned()).ok()?;
                            super::evaluation::value(scene, &with_unknowns)?
                        }
                    };
                    let value =
                        in_system / unit.as_ref().map_or(1.0, |u| scene.unit_system.of_one(u));
                    Some(Number {
                        name: r.lhs.clone(),
                        axis: r.axis,
                        value,
                        unit,
                    })
                })
                .collect()
        };
    // A value that holds an unknown is shown with it solved: in its place with one solution;
    // with several, after the step under its title and `(solution k)`, once per solution.
    let mut steps = Vec::new();
    for step in &analysis.plan {
        let [single] = analysis.solutions.as_slice() else {
            steps.push(StepValues {
                title: step.title.clone(),
                values: values(step, None, false),
            });
            for (k, solution) in analysis.solutions.iter().enumerate() {
                steps.push(StepValues {
                    title: format!("{} (solution {})", step.title, k + 1),
                    values: values(step, Some(solution), true),
                });
            }
            continue;
        };
        steps.push(StepValues {
            title: step.title.clone(),
            values: values(step, Some(single), false),
        });
    }
    steps.retain(|s| !s.values.is_empty());
    steps
}

/// A derived name without its subscript: `I` of `I_xy`, `Hdot` of `Hdot_z`.
fn stem(name: &str) -> &str {
    name.rsplit_once('_').map_or(name, |(stem, _)| stem)
}

#[cfg(test)]
mod tests {
    use super::stem;

    #[test]
    fn stems() {
        assert_eq!(stem("I_xy"), "I");
        assert_eq!(stem("Hdot_z"), "Hdot");
        assert_eq!(stem("T"), "T");
    }
}
