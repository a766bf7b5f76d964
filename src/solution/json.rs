//! The worked solution as JSON (`kinetics solve --format json`, `docs/solution.schema.json`):
//! the statement, the givens, the quantities asked for, each step with its relations as text
//! and LaTeX, the names of long radicands, and the results with their forms and values.

use super::answer::WorkedStep;
use super::engineer::StepValues;
use super::page::{Block, Heading, Page, Section};
use super::parts_table;
use super::render::relation;
use super::result::{Body, Form, Line, Result};
use crate::mechanics::derivation::Relation;
use crate::print::{self, markup, Notation};
use crate::scene::model::Given;
use crate::scene::Analysis;

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

/// The worked solution's page as JSON (`docs/solution.schema.json`): the relations of each
/// step as the page shows them (no tautology, equal components on one row), every result.
pub(super) fn solution(page: &Page, analysis: &Analysis) -> serde_json::Value {
    let mut solution = serde_json::json!({
        "title": page.title,
        "statement": null,
        "statement_latex": null,
        "abbreviations": relations_json(&analysis.abbreviations.relations()),
    });
    let mut steps = Vec::new();
    for section in &page.sections {
        for block in &section.blocks {
            match (&section.heading, block) {
                (Heading::Statement, Block::Words(words)) => {
                    solution["statement"] = markup::text(words).into();
                    solution["statement_latex"] = markup::latex(words).into();
                }
                (_, Block::Givens(givens)) => solution["givens"] = givens_json(givens).into(),
                (_, Block::Results(results)) => {
                    solution["results"] = results.iter().map(result_json).collect();
                }
                (_, Block::Find(names)) => {
                    let names: Vec<&str> = names.iter().map(|n| n.text.as_str()).collect();
                    solution["find"] = serde_json::json!(names);
                }
                _ => {}
            }
        }
        if let Heading::Step { .. } = section.heading {
            steps.push(step_json(section));
        }
    }
    solution["plan"] = steps.iter().map(|s| s["title"].clone()).collect();
    solution["steps"] = steps.into();
    solution
}

/// A page of derivations as JSON: a derivation's name, title, convention, its steps (title,
/// table, relations as the page shows them) and its result (its last step's relations).
pub(super) fn derivations(page: &Page) -> serde_json::Value {
    let derivation = |section: &Section| {
        let Heading::Derivation { name, title } = section.heading else {
            return None;
        };
        let convention = section.blocks.iter().find_map(|b| match b {
            Block::Words(words) => Some(markup::text(words)),
            _ => None,
        });
        let steps: Vec<serde_json::Value> = section.subsections.iter().map(step_json).collect();
        let result = steps
            .last()
            .map_or(serde_json::json!([]), |s| s["relations"].clone());
        Some(serde_json::json!({
            "name": name,
            "title": markup::text(title),
            "title_latex": markup::latex(title),
            "convention": convention,
            "result": result,
            "steps": steps,
        }))
    };
    page.sections.iter().filter_map(derivation).collect()
}

/// A step of a page: its title (text and LaTeX), its table of parts and its relations.
fn step_json(section: &Section) -> serde_json::Value {
    let step = WorkedStep::of(section);
    let table = section.blocks.iter().find_map(|block| match block {
        Block::Table(t) => Some(parts_table::json(t)),
        _ => None,
    });
    let relations: Vec<serde_json::Value> = step
        .relations
        .iter()
        .map(|(text, latex)| serde_json::json!({"text": text, "latex": latex}))
        .collect();
    serde_json::json!({
        "title": step.title,
        "title_latex": step.title_latex,
        "table": table,
        "relations": relations,
    })
}

/// The engineer's page as JSON: `{title, givens, results: [{name, value, unit}],
/// intermediate: [{step, values: [{name, value, unit}]}]}` (`docs/solution.schema.json`);
/// a result said in words has its `text` too.
pub(super) fn numbers(page: &Page) -> serde_json::Value {
    let mut numbers = serde_json::json!({
        "title": page.title,
        "givens": [],
        "results": [],
        "intermediate": [],
    });
    let blocks = page.sections.iter().flat_map(|s| &s.blocks);
    for block in blocks {
        match block {
            Block::Givens(givens) => numbers["givens"] = givens_json(givens).into(),
            Block::Answers(results) => {
                numbers["results"] = results.iter().map(answer_json).collect();
            }
            Block::Values(steps) => {
                numbers["intermediate"] = steps.iter().map(step_values_json).collect();
            }
            _ => {}
        }
    }
    numbers
}

/// A result by its number: its name, value and unit, and its words where it is said in words.
fn answer_json(r: &Result) -> serde_json::Value {
    let mut answer = serde_json::json!({
        "name": r.name.text,
        "value": value_json(r),
        "unit": unit(r),
    });
    if let Body::Line(line) = &r.body {
        if let Some(Form::Words(words)) = &line.form {
            answer["text"] = serde_json::json!(markup::text(words));
        }
    }
    answer
}

/// A step's values: `{step, values: [{name, value, unit}]}`.
fn step_values_json(step: &StepValues) -> serde_json::Value {
    let values: Vec<serde_json::Value> = step
        .values
        .iter()
        .map(|n| {
            let name = print::render(&n.name, Notation::Text, n.axis);
            let unit = n.unit.as_ref().map(ToString::to_string);
            serde_json::json!({"name": name, "value": n.value, "unit": unit})
        })
        .collect();
    serde_json::json!({"step": markup::text(&step.title), "values": values})
}

/// A result: its name, its form in text and LaTeX, its value and unit.
fn result_json(r: &Result) -> serde_json::Value {
    serde_json::json!({
        "name": r.name.text,
        "text": r.one_line(Notation::Text),
        "latex": r.one_line(Notation::Latex),
        "value": value_json(r),
        "unit": unit(r),
    })
}

/// The givens as JSON: `[{name, written, definition, si_value, unit}]`.
fn givens_json(givens: &[Given]) -> Vec<serde_json::Value> {
    givens
        .iter()
        .map(|g| {
            serde_json::json!({
                "name": g.symbol.name(),
                "written": g.written.as_ref().map(ToString::to_string),
                "definition": g.definition.as_ref().map(|d| d.expr.to_string()),
                "si_value": g.value,
                "unit": g.dimension.si_unit(),
            })
        })
        .collect()
}

/// A result's value as JSON: a number, `[x, y, z]`, a tensor's rows, a principal frame's
/// `{moments, axes, remark}`, or null without one.
fn value_json(r: &Result) -> serde_json::Value {
    let numbers = |l: &Line| match (&l.form, l.value.as_deref()) {
        (_, None) => serde_json::Value::Null,
        (_, Some([x])) => serde_json::json!(x),
        (Some(Form::Matrix(_)), Some(v)) => serde_json::json!(v.chunks(3).collect::<Vec<_>>()),
        (_, Some(v)) => serde_json::json!(v),
    };
    match &r.body {
        Body::Line(l) => numbers(l),
        Body::Frame {
            moments,
            axes,
            remark,
        } => {
            let all = |lines: &[Line]| -> Option<Vec<serde_json::Value>> {
                lines
                    .iter()
                    .map(|l| l.value.as_ref().map(|_| numbers(l)))
                    .collect()
            };
            let remark = remark.as_ref().and_then(|l| match &l.form {
                Some(Form::Words(w)) => Some(markup::text(w)),
                _ => None,
            });
            serde_json::json!({"moments": all(moments), "axes": all(axes), "remark": remark})
        }
    }
}

/// A result's unit in text: its line's, a frame's moments'.
fn unit(r: &Result) -> Option<String> {
    let unit = match &r.body {
        Body::Line(l) => l.unit.as_ref(),
        Body::Frame { moments, .. } => moments.first()?.unit.as_ref(),
    };
    unit.map(ToString::to_string)
}
