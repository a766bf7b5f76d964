//! The `kinetics` binary as a whole process, for tests of its commands.

use std::io::Write;
use std::process::{Command, Stdio};
use std::time::Duration;

/// Runs `kinetics` with `args`: its exit code (-1 when killed by a signal), standard
/// output and standard error.
pub fn kinetics(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(args)
        .output()
        .expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The path of the shipped scene `examples/scenes/<name>.scene`.
pub fn scene(name: &str) -> String {
    format!(
        "{}/examples/scenes/{name}.scene",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// How a run of `kinetics` ended: its exit code (-1 when killed by a signal), standard
/// output and standard error.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// A run longer than this is a hang (the slowest tests' runs take well under a second).
const TIME_LIMIT: Duration = Duration::from_secs(60);

/// Runs `kinetics` with `args`, `stdin` written to its standard input; a panic when it does
/// not finish within [`TIME_LIMIT`].
pub fn kinetics_with_input(args: &[&str], stdin: impl Into<Vec<u8>>) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let mut pipe = child.stdin.take().expect("stdin is piped");
    let input: Vec<u8> = stdin.into();
    // Written from another thread so that a full output pipe never blocks the child.
    let writer = std::thread::spawn(move || {
        // The program may stop reading at its size limit: a broken pipe is expected then.
        let _ = pipe.write_all(&input);
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
