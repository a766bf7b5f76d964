//! The `kinetics` binary as a whole process, for tests of its commands.

use std::process::Command;

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
