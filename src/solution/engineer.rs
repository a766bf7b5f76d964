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

use super::numbers::{format_value, unit};
use super::render::given_line;
use super::result::{Body, Form, Result};
use crate::algebra::Expr;
use crate::mechanics::derivation::Step;
use crate::print::{self, markup, Notation};
use crate::scene::derived_dimension;
use crate::scene::units::Dimensions;
use crate::scene::{Analysis, Scene};

/// The numbers of one step of the plan.
pub(super) struct StepValues {
    pub title: String,
    pub values: Vec<Number>,
}

/// A derived quantity's value and unit.
pub(super) struct Number {
    pub name: String,
    pub value: f64,
    pub unit: Option<String>,
}

/// The steps that have intermediate values, in the plan's order; a step of equations (a
/// left-hand side that is not a name) has none.
pub(super) fn intermediate(
    scene: &Scene,
    analysis: &Analysis,
    dims: &Dimensions,
) -> Vec<StepValues> {
    // A derived name's unit is the chapter's (`I_xy`: kg·m²), a declared one's its own:
    // the right-hand side may hold plain SI numbers (`150 mm` is 3/20) and tell nothing.
    let unit_of = |lhs: &Expr, rhs: &Expr| {
        let symbol = lhs.as_symbol()?;
        let declared = dims.get(&symbol).copied();
        match declared.or_else(|| derived_dimension(symbol.name())) {
            Some(d) => Some(d.si_unit()),
            None => Some(rhs)
                .filter(|e| !e.is_zero())
                .and_then(|e| unit(dims, e)),
        }
    };
    let values = |step: &Step| -> Vec<Number> {
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
                let name = print::render(&r.lhs, Notation::Text, r.axis);
                let rhs = named.whole(&r.rhs);
                let value = super::evaluation::value(scene, &rhs)?;
                let unit = unit_of(&r.lhs, &rhs);
                // The kinetic energy is work: joules, as in the results.
                let unit = unit.map(|u| {
                    if stem(&name) == "T" && u == "N·m" {
                        "J".into()
                    } else {
                        u
                    }
                });
                Some(Number { name, value, unit })
            })
            .collect()
    };
    analysis
        .plan
        .iter()
        .map(|step| StepValues {
            title: markup::text(&step.title),
            values: values(step),
        })
        .filter(|s| !s.values.is_empty())
        .collect()
}

/// A derived name without its subscript: `I` of `I_xy`, `Hdot` of `Hdot_z`.
fn stem(name: &str) -> &str {
    name.rsplit_once('_').map_or(name, |(stem, _)| stem)
}

/// `value unit`, or the value alone.
fn number_text(n: &Number) -> String {
    match n.unit.as_deref() {
        Some(u) if !u.is_empty() => format!("{} {u}", format_value(n.value)),
        _ => format_value(n.value),
    }
}

/// The engineer's page as text: title, givens, results, intermediate values.
pub(super) fn text(
    scene: &Scene,
    analysis: &Analysis,
    results: &[Result],
    dims: &Dimensions,
) -> String {
    let mut out = String::new();
    if let Some(t) = &scene.title {
        out.push_str(&format!("{}\n\n", markup::text(t)));
    }
    out.push_str("Given\n");
    for g in &scene.givens {
        out.push_str(&format!("  {}\n", given_line(g)));
    }
    out.push_str("\nResults\n");
    out.push_str(&super::text::answers(results));
    for r in results.iter().filter(|r| !r.has_value()) {
        out.push_str(&format!(
            "  {} has no value: a given it needs is symbolic\n",
            r.name.text
        ));
    }
    let steps = intermediate(scene, analysis, dims);
    if !steps.is_empty() {
        out.push_str("\nIntermediate values\n");
    }
    for step in steps {
        out.push_str(&format!("  {}\n", step.title));
        for n in &step.values {
            out.push_str(&format!("    {} = {}\n", n.name, number_text(n)));
        }
    }
    out
}

/// The engineer's page as JSON: `{title, givens, results: [{name, value, unit}],
/// a result said in words with its `text` too,
/// intermediate: [{step, values: [{name, value, unit}]}]}` (`docs/solution.schema.json`).
pub(super) fn json(
    scene: &Scene,
    analysis: &Analysis,
    results: &[Result],
    dims: &Dimensions,
) -> serde_json::Value {
    let number = |n: &Number| serde_json::json!({"name": n.name, "value": n.value, "unit": n.unit});
    serde_json::json!({
        "title": scene.title,
        "givens": super::json::givens_json(&scene.givens),
        "results": results.iter().map(|r| {
            let mut row = serde_json::json!({
                "name": r.name.text,
                "value": super::json::value_json(r),
                "unit": super::json::unit(r),
            });
            if let Body::Line(line) = &r.body {
                if let Some(Form::Words(words)) = &line.form {
                    row["text"] = serde_json::json!(markup::text(words));
                }
            }
            row
        }).collect::<Vec<_>>(),
        "intermediate": intermediate(scene, analysis, dims).iter().map(|s| serde_json::json!({
            "step": s.title,
            "values": s.values.iter().map(number).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    })
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
