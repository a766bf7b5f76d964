//! `kinetics simplify [--canonical | --expand] "<expr>"`: the shortest form of an expression
//! or equation (`Expr::simplify`, the chapter's symbols positive where they name masses,
//! lengths, moments of inertia and times), its canonical form, or its expansion.

use super::error::CliError;
use super::input;
use super::show::{at_input, render_statement, Format};
use kinetics::algebra::{AlgebraError, Domains, Expr};
use kinetics::parse::{parse_statement, Equation, Statement};
use kinetics::Input;

#[derive(clap::Args)]
#[command(after_help = "Example:\n  kinetics simplify \"(a^2 - b^2)/(a - b)\"")]
pub struct Args {
    /// The expression or equation, in ASCII; `-` reads standard input.
    #[arg(allow_hyphen_values = true, value_parser = input::expression_argument)]
    pub input: String,
    /// Multiply out products and powers of sums (no other simplification).
    #[arg(long, conflicts_with = "canonical")]
    pub expand: bool,
    /// The canonical form only (the form equality is decided in), not the shortest.
    #[arg(long)]
    pub canonical: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

pub fn run(args: Args) -> Result<String, CliError> {
    let (name, source) = input::read(&args.input)?;
    Input::expression(&name, &source).within(|| transformed(&args, &name, &source))
}

fn transformed(args: &Args, name: &str, source: &str) -> Result<String, CliError> {
    let statement = parse_statement(name, source)?;
    let domains = Domains::chapter_defaults();
    let transform = |e: &Expr| -> Result<Expr, AlgebraError> {
        if args.canonical {
            Ok(e.clone())
        } else if args.expand {
            e.expand()
        } else {
            e.simplify(&domains)
        }
    };
    let transform = |e: &Expr| transform(e).map_err(|err| at_input(name, source, err));
    let statement = match statement {
        Statement::Expression(e) => Statement::Expression(transform(&e)?),
        Statement::Equation(eq) => Statement::Equation(Equation {
            lhs: transform(&eq.lhs)?,
            rhs: transform(&eq.rhs)?,
        }),
    };
    render_statement(&statement, args.format).map_err(|err| at_input(name, source, err))
}
