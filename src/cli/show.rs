//! `kinetics latex "<expr or equation>" [--textbook]`: print as LaTeX (default), text or
//! JSON: as written (the user's order and parentheses, only the notation changed), or with
//! `--textbook` in the textbook's order and grouping that `derive` prints.

use super::error::CliError;
use super::input;
use kinetics::algebra::{vector, AlgebraError, Axis, Expr};
use kinetics::parse::as_written::statement_as_written;
use kinetics::parse::{Diagnostic, Statement};
use kinetics::print::{self, Notation};
use kinetics::Input;

#[derive(clap::Args)]
#[command(after_help = "Example:\n  kinetics latex \"-a^2 + 1/2 m v^2\"")]
pub struct Args {
    /// The expression or equation, in ASCII (`I_x*w_x - I_xy*w_y`); `-` reads standard input.
    #[arg(allow_hyphen_values = true, value_parser = input::expression_argument)]
    pub input: String,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Latex)]
    pub format: Format,
    /// The textbook's order and grouping (as `derive` prints), not the order written.
    #[arg(long)]
    pub textbook: bool,
}

/// The output formats of the quick commands.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    Text,
    Latex,
    Json,
}

pub fn run(args: Args) -> Result<String, CliError> {
    let (name, source) = input::read(&args.input)?;
    Input::expression(&name, &source).within(|| shown(&args, &name, &source))
}

fn shown(args: &Args, name: &str, source: &str) -> Result<String, CliError> {
    let (statement, written) = statement_as_written(name, source)?;
    // The textbook's form is formed in any case: what the algebra refuses is refused as written.
    let textbook =
        render_statement(&statement, args.format).map_err(|err| at_input(name, source, err))?;
    if args.textbook {
        return Ok(textbook);
    }
    Ok(match args.format {
        Format::Text => written.text,
        Format::Latex => written.latex,
        Format::Json => {
            serde_json::json!({"text": written.text, "latex": written.latex}).to_string()
        }
    })
}

/// An algebra error about the input as a whole, located at it: it quotes what was written,
/// not the multiplied-out form the algebra saw.
pub fn at_input(name: &str, source: &str, err: AlgebraError) -> CliError {
    let end = source.trim_end().len();
    Diagnostic::at(name, source, 0, end, err.to_string()).into()
}

/// Prints an expression or an equation in the chosen format; vectors written with `i j k`
/// print component by component.
pub fn render_statement(statement: &Statement, format: Format) -> Result<String, AlgebraError> {
    let show = |notation: Notation| -> Result<String, AlgebraError> {
        Ok(match statement {
            Statement::Expression(e) => side(e, notation, Axis::X)?,
            Statement::Equation(eq) => {
                let axis = equation_axis(&eq.lhs);
                format!(
                    "{} = {}",
                    side(&eq.lhs, notation, axis)?,
                    side(&eq.rhs, notation, axis)?
                )
            }
        })
    };
    match format {
        Format::Text => show(Notation::Text),
        Format::Latex => show(Notation::Latex),
        Format::Json => Ok(serde_json::json!({
            "text": show(Notation::Text)?,
            "latex": show(Notation::Latex)?,
        })
        .to_string()),
    }
}

fn side(e: &Expr, notation: Notation, axis: Axis) -> Result<String, AlgebraError> {
    if vector::has_unit_vectors(e) {
        Ok(print::vector(&vector::components(e)?, notation))
    } else {
        Ok(print::render(e, notation, axis))
    }
}

/// The axis an equation is about, from a left side such as `M_y`.
fn equation_axis(lhs: &Expr) -> Axis {
    lhs.as_symbol()
        .and_then(|s| Axis::from_subscript(s.subscript()))
        .unwrap_or_default()
}
