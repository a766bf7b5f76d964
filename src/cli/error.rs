//! Why a command failed, one variant per kind of failure. Each message goes to standard
//! error and begins `error: ` (a located input error adds the place, the line, a caret and
//! a hint; a plot that cannot be drawn says where and why). Every failure of a command
//! exits with code 1; a command line clap cannot parse exits with 2 before any command runs.

use kinetics::algebra::AlgebraError;
use kinetics::numeric::NumericError;
use kinetics::parse::Diagnostic;

#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Input refused at a place in it: an expression or a scene (boxed: a diagnostic
    /// carries its source line and is the largest of the failures).
    #[error("{}", .0.render())]
    Located(Box<Diagnostic>),
    /// Input refused as a whole before it is read: too long, or not UTF-8 text.
    #[error("error: {name}: {reason}")]
    Unreadable { name: String, reason: String },
    /// A command line clap accepts but the command refuses: a flag the method does not use,
    /// an unknown derivation, a file that would be overwritten.
    #[error("error: {0}")]
    Usage(String),
    /// Reading the input or writing the output failed.
    #[error("error: cannot {action}: {source}")]
    Io {
        action: String,
        source: std::io::Error,
    },
    /// The algebra refused the input, named when the command names it.
    #[error("error: {}{source}", subject(.name))]
    Algebra {
        name: Option<String>,
        source: AlgebraError,
    },
    /// The numerical work refused the problem, named when the command names it.
    #[error("error: {}{source}", subject(.name))]
    Numeric {
        name: Option<String>,
        source: NumericError,
    },
    /// The scene's figure could not be drawn (a size without a number).
    #[error("error: {0}")]
    Figure(kinetics::figure::FigureError),
    /// The plot could not be drawn.
    #[cfg(feature = "plot")]
    #[error("{0}")]
    Plot(String),
}

impl From<Diagnostic> for CliError {
    fn from(d: Diagnostic) -> CliError {
        CliError::Located(Box::new(d))
    }
}

impl CliError {
    /// For `map_err`: an I/O failure while doing `action` (`read FILE`, `write`).
    pub fn io(action: impl Into<String>) -> impl FnOnce(std::io::Error) -> CliError {
        let action = action.into();
        move |source| CliError::Io { action, source }
    }
}

/// `name: ` before the message, or nothing.
fn subject(name: &Option<String>) -> String {
    name.as_ref().map(|n| format!("{n}: ")).unwrap_or_default()
}
