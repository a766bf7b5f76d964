//! Output that cannot be written (standard output on a full device) is a failure like any
//! other: `error: cannot write: ...` on standard error and exit code 1, never a panic.

#![cfg(target_os = "linux")]

use std::process::{Command, Stdio};

#[test]
fn a_full_device_is_an_error_not_a_panic() {
    for args in [
        &["derive", "--general"][..],
        &["latex", "I_x*w_x - I_xy*w_y"][..],
    ] {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full opens");
        let out = Command::new(env!("CARGO_BIN_EXE_kinetics"))
            .args(args)
            .stdout(Stdio::from(full))
            .output()
            .expect("runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("error: cannot write: "),
            "{args:?}: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
}
