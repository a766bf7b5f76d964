//! `kinetics check` as a whole process, for the tests of the checker: its contexts as
//! arguments, claims files in the temporary directory, and the verdicts of its JSON output.

pub use super::binary::{kinetics_with_input, Run};
use serde_json::Value;
use std::path::PathBuf;

/// The arguments that select a context: `general` (none), `principal`, `fixed-axis`, or a
/// scene file's path relative to the crate's root.
pub fn context_args(context: &str) -> Vec<String> {
    match context {
        "general" => vec![],
        "principal" => vec!["--principal".into()],
        "fixed-axis" => vec!["--fixed-axis".into()],
        scene => vec![format!("{}/{scene}", env!("CARGO_MANIFEST_DIR"))],
    }
}

/// A claims file in the temporary directory, removed when dropped.
pub struct ClaimsFile {
    path: PathBuf,
}

impl ClaimsFile {
    /// Writes `text` to a file named after `name` and this process (tests run in parallel).
    pub fn new(name: &str, text: &str) -> ClaimsFile {
        let path = std::env::temp_dir().join(format!(
            "kinetics-check-{name}-{}.claims",
            std::process::id()
        ));
        std::fs::write(&path, text).expect("the temporary directory is writable");
        ClaimsFile { path }
    }

    pub fn path(&self) -> &str {
        self.path.to_str().expect("a UTF-8 temporary path")
    }
}

impl Drop for ClaimsFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// One claim as the JSON output judges it.
#[derive(Debug, Clone, PartialEq)]
pub struct Judged {
    /// The claim's line in its file (its position among `--claim` flags), 1-based.
    pub line: u64,
    pub verdict: String,
    /// The reading's name, `None` for JSON `null`.
    pub reading: Option<String>,
}

/// The claims of `kinetics check --format json` output, and its summary object; a panic
/// naming the output and the standard error when it is not the documented JSON.
pub fn judged(run: &Run) -> (Vec<Judged>, Value) {
    try_judged(run).unwrap_or_else(|e| panic!("{e}"))
}

/// [`judged`], or what is wrong with the output, naming it and the standard error.
pub fn try_judged(run: &Run) -> Result<(Vec<Judged>, Value), String> {
    let undocumented = |what: String| {
        format!(
            "check's output is not the documented JSON ({what}); exit {}\nstdout: {}\nstderr: {}",
            run.code, run.stdout, run.stderr
        )
    };
    let json: Value = serde_json::from_str(&run.stdout).map_err(|e| undocumented(e.to_string()))?;
    let claims = json["claims"]
        .as_array()
        .ok_or_else(|| undocumented("no \"claims\" array".into()))?
        .iter()
        .map(|c| {
            Some(Judged {
                line: c["line"].as_u64()?,
                verdict: c["verdict"].as_str()?.to_owned(),
                reading: c["reading"].as_str().map(str::to_owned),
            })
        })
        .collect::<Option<Vec<Judged>>>()
        .ok_or_else(|| undocumented("a claim without its line or verdict".into()))?;
    Ok((claims, json["summary"].clone()))
}

/// `kinetics check CONTEXT --claims FILE --format json`.
pub fn check_file(context: &str, file: &ClaimsFile) -> Run {
    let mut args = vec!["check".to_owned()];
    args.extend(context_args(context));
    args.extend(["--claims", file.path(), "--format", "json"].map(String::from));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    kinetics_with_input(&args, "")
}
