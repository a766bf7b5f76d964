//! `kinetics simulate` streams its CSV: the process's peak resident memory (VmHWM) while it
//! writes a million rows is that of a run writing ten thousand.
//!
//! The peak is read from `/proc/<pid>/status` while the child is still running: the test
//! stops reading the child's standard output [`HELD_BACK`] rows before the end, more than a
//! pipe and the child's output buffer hold, so the child is blocked writing (or still
//! computing) and cannot exit until the test reads on. By then it has produced all but the
//! last few thousand rows, so memory that grew with the rows would show in the peak.

#![cfg(target_os = "linux")]

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

/// Rows left unread when the peak is taken: at over 200 bytes a row, about 1 MB, more than
/// a pipe's capacity (64 KiB by default, 1 MiB at most unprivileged) plus the child's
/// 8 KiB buffer.
const HELD_BACK: usize = 5_000;

/// The child's peak resident set in kB, from `/proc/<pid>/status`.
fn peak_resident_kb(pid: u32) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status"))
        .unwrap_or_else(|e| panic!("the child {pid} has gone: {e}"));
    let line = status
        .lines()
        .find(|l| l.starts_with("VmHWM:"))
        .unwrap_or_else(|| panic!("no VmHWM: the child exited early\n{status}"));
    line.split_whitespace().nth(1).unwrap().parse().unwrap()
}

/// Runs the free-body scene with `--until until --every 0.001` (`1000 until + 1` rows) and
/// `method`, and returns the child's peak resident memory (kB) taken [`HELD_BACK`] rows
/// before the end, after checking that every row arrived and the run succeeded.
fn streaming_peak(until: u32, method: &str) -> u64 {
    let rows = 1000 * until as usize + 1;
    let scene = format!(
        "{}/examples/scenes/free_body.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["simulate", &scene, "--until", &until.to_string()])
        .args(["--every", "0.001", "--method", method])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("runs");
    let mut out = BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    let mut read = 0usize;
    let mut peak = None;
    while out.read_line(&mut line).unwrap() > 0 {
        read += 1;
        line.clear();
        // The header and all rows but the held-back ones.
        if read == 1 + rows - HELD_BACK {
            peak = Some(peak_resident_kb(child.id()));
        }
    }
    assert!(child.wait().unwrap().success());
    assert_eq!(read, 1 + rows, "{method}, until {until}");
    peak.expect("the peak was taken")
}

/// Resident memory the million-row run may have beyond the ten-thousand-row one (kB). The
/// two peaks measured about 10 MB and within 112 kB of each other (the allocator's
/// page-level noise); 2 MiB is eighteen times that, and a quarter of what keeping a single
/// f64 per row (8 MB) would add.
const SLACK_KB: u64 = 2 * 1024;

#[test]
fn a_million_csv_rows_take_the_memory_of_ten_thousand() {
    for method in ["exact", "dop853"] {
        let few = streaming_peak(10, method);
        let many = streaming_peak(1000, method);
        println!("{method}: VmHWM {few} kB for 10^4 rows, {many} kB for 10^6 rows");
        assert!(
            many <= few + SLACK_KB,
            "{method}: {many} kB for 10^6 rows against {few} kB for 10^4"
        );
    }
}
