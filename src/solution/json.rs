//! The worked solution as JSON (`kinetics solve --format json`, `docs/solution.schema.json`):
//! the givens, each step with its relations as text and LaTeX, the names of long radicands,
//! and the results with their forms and values.

use super::inertia_results;
use super::parts_table;
use super::render::{relation, Result};
use crate::mechanics::derivation::Relation;
use crate::print::{markup, Notation};
use crate::scene::{Analysis, Scene};

/// Relations as JSON objects `{"text": "lhs = rhs", "latex": "lhs = rhs"}`.
pub fn relations_json(rs: &[Relation]) -> Vec<serde_json::Value> {
    rs.iter()
        .map(|r| {
            let (lt, rt) = relation(r, Notation::Text);
            let (ll, rl) = relation(r, Notation::Latex);
            serde_json::json!({"text": format!("{lt} = {rt}"), "latex": format!("{ll} = {rl}")})
        })
        .collect()
}

/// The worked solution as JSON (`docs/solution.schema.json`).
pub(super) fn solution(
    scene: &Scene,
    analysis: &Analysis,
    results: &[Result],
) -> serde_json::Value {
    serde_json::json!({
        "title": scene.title,
        "plan": analysis.plan.iter().map(|s| markup::text(&s.title)).collect::<Vec<_>>(),
        "givens": givens_json(scene),
        "steps": analysis.plan.iter().map(|s| serde_json::json!({
            "title": markup::text(&s.title),
            "title_latex": markup::latex(&s.title),
            "table": s.table.as_ref().map(parts_table::json),
            "relations": relations_json(&s.relations),
        })).collect::<Vec<_>>(),
        "abbreviations": relations_json(&analysis.abbreviations.relations()),
        "results": results.iter().map(|r| serde_json::json!({
            "name": r.name,
            "text": r.text,
            "latex": r.latex,
            "value": value_json(r),
            "unit": r.unit,
        })).collect::<Vec<_>>(),
    })
}

/// The givens as JSON: `[{name, written, si_value, unit}]`.
pub(super) fn givens_json(scene: &Scene) -> Vec<serde_json::Value> {
    scene
        .givens
        .iter()
        .map(|g| {
            serde_json::json!({
                "name": g.symbol.name(),
                "written": g.written,
                "si_value": g.value,
                "unit": g.dimension.si_unit(),
            })
        })
        .collect()
}

/// A result's value as JSON: a number, `[x, y, z]`, a tensor's rows, a principal frame's
/// `{moments, axes, remark}`, or null without one.
pub(super) fn value_json(r: &Result) -> serde_json::Value {
    if let Some(value) = inertia_results::json_value(r) {
        return value;
    }
    match r.value.as_deref() {
        Some([x]) => serde_json::json!(x),
        Some(v) => serde_json::json!(v),
        None => serde_json::Value::Null,
    }
}
