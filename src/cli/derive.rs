//! `kinetics derive --general [--principal] [--only H_G,T,euler,...] [--steps]
//! [--format text|latex|json]`: the chapter's equations for a general body.

use super::error::CliError;
use kinetics::algebra::Domains;
use kinetics::mechanics::catalogue::{derive_general, NAMES};
use kinetics::mechanics::Derivation;
use kinetics::print::{markup, Notation};
use kinetics::solution::render::{relation, relations_json};

#[derive(clap::Args)]
pub struct Args {
    /// Derive for a general body (symbols I_x ... I_xz, w_x, w_y, w_z, m, vbar).
    #[arg(long, required = true)]
    pub general: bool,
    /// Principal axes: every product of inertia is zero.
    #[arg(long)]
    pub principal: bool,
    /// Only these derivations (comma-separated): H_G, H_O, T, T_O, T_plane, impulse, Hdot,
    /// euler, fixed_axis, reactions, balancing.
    #[arg(long, value_delimiter = ',')]
    pub only: Vec<String>,
    /// Show every step, not only the results.
    #[arg(long)]
    pub steps: bool,
    #[arg(long, value_enum, default_value_t = super::show::Format::Text)]
    pub format: super::show::Format,
}

pub fn run(args: Args) -> Result<String, CliError> {
    let names: Vec<&str> = if args.only.is_empty() {
        NAMES.to_vec()
    } else {
        args.only.iter().map(String::as_str).collect()
    };
    let mut derivations = Vec::new();
    for name in names {
        let derived = derive_general(name, args.principal).ok_or_else(|| {
            CliError::Usage(format!(
                "unknown derivation '{name}'\n  = help: choose from {}",
                NAMES.join(", ")
            ))
        })?;
        let derived = derived.map_err(|source| CliError::Algebra {
            name: Some(name.to_string()),
            source,
        })?;
        derivations.push(derived.simplified(&Domains::chapter_defaults()));
    }
    Ok(match args.format {
        super::show::Format::Text => render(&derivations, Notation::Text, args.steps),
        super::show::Format::Latex => render(&derivations, Notation::Latex, args.steps),
        super::show::Format::Json => json(&derivations).to_string(),
    })
}

/// Text: a heading per derivation and `lhs = rhs` lines. LaTeX: an `align*` block per step.
fn render(derivations: &[Derivation], notation: Notation, all_steps: bool) -> String {
    let mut out = String::new();
    for d in derivations {
        let steps = if all_steps {
            &d.steps[..]
        } else {
            &d.steps[d.steps.len() - 1..]
        };
        match notation {
            Notation::Text => out.push_str(&format!("# {}\n", markup::text(&d.title))),
            Notation::Latex => out.push_str(&format!("% {}\n", markup::latex(&d.title))),
        }
        for step in steps {
            if all_steps {
                match notation {
                    Notation::Text => out.push_str(&format!("## {}\n", markup::text(&step.title))),
                    Notation::Latex => out.push_str(&format!("% {}\n", markup::latex(&step.title))),
                }
            }
            let lines: Vec<String> = step
                .relations
                .iter()
                .map(|r| {
                    let (l, rhs) = relation(r, notation);
                    match notation {
                        Notation::Text => format!("{l} = {rhs}"),
                        Notation::Latex => format!("{l} &= {rhs}"),
                    }
                })
                .collect();
            match notation {
                Notation::Text => out.push_str(&(lines.join("\n") + "\n")),
                Notation::Latex => out.push_str(&format!(
                    "\\begin{{align*}}\n{}\n\\end{{align*}}\n",
                    lines.join(" \\\\\n")
                )),
            }
        }
        out.push('\n');
    }
    out.trim_end().to_string()
}

fn json(derivations: &[Derivation]) -> serde_json::Value {
    serde_json::Value::Array(
        derivations
            .iter()
            .map(|d| {
                serde_json::json!({
                    "name": d.name,
                    "title": markup::text(&d.title),
                    "title_latex": markup::latex(&d.title),
                    "result": relations_json(d.result()),
                    "steps": d.steps.iter().map(|s| serde_json::json!({
                        "title": markup::text(&s.title),
                        "title_latex": markup::latex(&s.title),
                        "relations": relations_json(&s.relations),
                    })).collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}
