//! `kinetics check` as a whole process, for the tests of the checker: its contexts as
//! arguments, claims files in the temporary directory, and the verdicts of its JSON output.

use serde_json::Value;
use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::Duration;

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

/// How a run of `kinetics` ended: its exit code (-1 when killed by a signal), standard
/// output and standard error.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// A run longer than this is a hang (the slowest, 300 claims, takes well under a second).
const TIME_LIMIT: Duration = Duration::from_secs(60);

/// Runs `kinetics` with `args`, `stdin` written to its standard input; a panic when it does
/// not finish within [`TIME_LIMIT`].
pub fn kinetics_with_input(args: &[&str], stdin: &str) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let mut pipe = child.stdin.take().expect("stdin is piped");
    let input = stdin.to_owned();
    // Written from another thread so that a full output pipe never blocks the child.
    let writer = std::thread::spawn(move || {
        let _ = pipe.write_all(input.as_bytes());
    });
    let pid = child.id();
    let (done, finished) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = done.send(child.wait_with_output());
    });
    let out = match finished.recv_timeout(TIME_LIMIT) {
        Ok(out) => out.expect("output is readable"),
        Err(_) => {
            let _ = Command::new("kill").args(["-9", &pid.to_string()]).status();
            panic!("kinetics {args:?} did not finish: it hangs");
        }
    };
    let _ = writer.join();
    Run {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
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
