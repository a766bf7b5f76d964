//! pdflatex run on a file, for the tests that compile what kinetics writes. `.ci/run`
//! installs pdflatex when it is missing, so these tests never skip.

use std::path::Path;
use std::process::Command;

/// What compiling a file gave: pdflatex's terminal log and whether it ended well.
pub struct Compiled {
    pub log: String,
    pub succeeded: bool,
}

impl Compiled {
    /// The first error and the lines after it, if compiling failed or logged an error.
    pub fn first_error(&self) -> Option<String> {
        (!self.succeeded || self.log.contains("! ")).then(|| {
            self.log
                .lines()
                .skip_while(|l| !l.starts_with('!'))
                .take(8)
                .collect::<Vec<_>>()
                .join("\n")
        })
    }
}

/// Compiles `tex` with its output (PDF, `.log`) in `dir`, never stopping for input.
pub fn pdflatex(dir: &Path, tex: &Path) -> Compiled {
    let run = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-output-directory"])
        .arg(dir)
        .arg(tex)
        .output()
        .expect("pdflatex is installed (.ci/run installs it)");
    Compiled {
        log: String::from_utf8_lossy(&run.stdout).into_owned(),
        succeeded: run.status.success(),
    }
}
