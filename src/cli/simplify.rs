//! `kinetics simplify [--expand] "<expr>"`: the canonical form of an expression.

use super::error::CliError;
use super::input;
use super::show::{at_input, render_statement, Format};
use kinetics::parse::{parse_statement, Equation, Statement};

#[derive(clap::Args)]
pub struct Args {
    /// The expression or equation, in ASCII; `-` reads standard input.
    pub input: String,
    /// Multiply out products and powers of sums.
    #[arg(long)]
    pub expand: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

pub fn run(args: Args) -> Result<String, CliError> {
    let (name, source) = input::read(&args.input)?;
    let statement = parse_statement(&name, &source)?;
    let statement = if args.expand {
        let expand =
            |e: &kinetics::algebra::Expr| e.expand().map_err(|err| at_input(&name, &source, err));
        match statement {
            Statement::Expression(e) => Statement::Expression(expand(&e)?),
            Statement::Equation(eq) => Statement::Equation(Equation {
                lhs: expand(&eq.lhs)?,
                rhs: expand(&eq.rhs)?,
            }),
        }
    } else {
        statement
    };
    render_statement(&statement, args.format).map_err(|err| at_input(&name, &source, err))
}
