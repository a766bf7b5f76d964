//! `kinetics check --derivation FILE [SCENE]`: a hand derivation checked line by line, each
//! part (lines between blank lines) a chain of its own; a wrong line that is right from an
//! earlier wrong one `follows from` it.
//!
//! Exit status as `check`'s: 0 when every line holds, 1 when one differs or follows from
//! one that does, 3 when none differs and one is undecided, 2 when a line could not be read.

use super::check::{INPUT_ERROR, UNDECIDED};
use super::error::CliError;
use super::input::read_file;
use super::show::Format;
use kinetics::check::context::Context;
use kinetics::check::derivation::{check_derivation, parts, report, Judgement, LineCheck};
use kinetics::Input;
use std::io::Write;
use std::process::ExitCode;

pub fn run(context: &Context, path: &str, format: Format) -> Result<ExitCode, CliError> {
    let (name, source) = read_file(path)?;
    let parts = parts(&source);
    if parts.is_empty() {
        return Err(CliError::Usage(format!(
            "{name} holds no line to check\n  = help: write one equation a line, like T = 1/2 m v^2"
        )));
    }
    let checked: Vec<Vec<LineCheck>> = Input::expression(&name, &source)
        .within(|| Ok::<_, CliError>(check_derivation(context, &name, &parts, &[])))?
        .parts;
    let domains = context.domains();
    let mut stdout = String::new();
    match format {
        Format::Json => {
            let parts: Vec<serde_json::Value> =
                checked.iter().map(|c| report::json(c, domains)).collect();
            stdout =
                serde_json::json!({"context": context.description, "parts": parts}).to_string();
        }
        Format::Latex => {
            for part in &checked {
                stdout.push_str(&report::latex(part, &name, domains));
            }
        }
        Format::Text => {
            for part in &checked {
                stdout.push_str(&report::text(part, &name, domains));
            }
        }
    }
    let _ = write!(std::io::stdout(), "{stdout}");
    let errors: Vec<String> = checked
        .iter()
        .flatten()
        .filter_map(|c| c.outcome.as_ref().err().map(|d| d.render()))
        .collect();
    if !errors.is_empty() {
        super::tell(errors.join("").trim_end());
    }
    let any = |j: Judgement| checked.iter().flatten().any(|c| c.judgement() == j);
    Ok(if any(Judgement::Error) {
        ExitCode::from(INPUT_ERROR)
    } else if any(Judgement::Differs) || any(Judgement::Follows) {
        ExitCode::FAILURE
    } else if any(Judgement::Undecided) {
        ExitCode::from(UNDECIDED)
    } else {
        ExitCode::SUCCESS
    })
}
