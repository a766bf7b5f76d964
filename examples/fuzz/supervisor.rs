//! The supervisor: starts `--jobs` worker processes (this program again, with `--job`),
//! reads their reports, keeps the input of a worker that died (its `current` file) as a
//! crash, starts a new worker in its place with a fresh stream of inputs, and at the end
//! prints the summary: inputs run, inputs per second, and each finding with its count, when
//! it was first seen and the file that holds its input.
//!
//! Memory: each worker runs under `ulimit -v` [`MEMORY_LIMIT_KB`] (1 GiB of address space,
//! RLIMIT_AS, set by `/bin/sh` before it `exec`s the worker): the issue's own acceptance test,
//! and a guard for the machine (an input that asks for 3 GB fails its allocation instead of
//! pushing everyone into swap). An allocation past the limit aborts the worker with Rust's
//! "memory allocation of N bytes failed", kept as a `memory` finding. Polling VmHWM instead
//! would miss a spike between two polls and let it reach the machine. The address space is
//! more than the memory used: the worker's baseline (program, thread stacks, allocator
//! arenas, kept few by `MALLOC_ARENA_MAX=2`) is some 100 MB of it, so a `memory` finding
//! is confirmed on the binary with `ulimit -v 1048576` before it becomes a reproducer.

use crate::finding::{Class, Finding};
use crate::worker::HANG_EXIT;
use crate::Options;
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc::{channel, Sender};
use std::time::Instant;

/// What a worker thread tells the supervisor.
enum Report {
    /// Worker `job`'s generation has run this many inputs.
    Ran {
        job: u64,
        generation: u64,
        count: u64,
    },
    Found {
        finding: Finding,
        path: String,
    },
    /// The worker ended: by itself (`None`) or by dying, with the end of its standard error.
    Ended {
        job: u64,
        died: Option<String>,
    },
}

/// The address space of a worker, in KiB (`ulimit -v`): 1 GiB.
pub const MEMORY_LIMIT_KB: u64 = 1 << 20;

/// A finding's tally.
struct Tally {
    count: u64,
    first_seen: f64,
    path: String,
}

/// Runs the campaign; the process's exit code: 0 without findings, 1 with.
pub fn run(options: &Options, dir: &Path) -> i32 {
    let findings = dir.join("findings");
    std::fs::create_dir_all(&findings).expect("the findings directory can be made");
    let start = Instant::now();
    let end_ms = unix_ms() + options.seconds * 1000;
    let (tell, reports) = channel();
    let mut generation = vec![0u64; options.jobs as usize];
    for job in 0..options.jobs {
        spawn(options, job, 0, end_ms, tell.clone());
    }
    let mut running = options.jobs;
    let mut ran: BTreeMap<(u64, u64), u64> = BTreeMap::new();
    let mut tally: BTreeMap<(Class, String), Tally> = BTreeMap::new();
    let mut note = |finding: Finding, path: String| {
        let t = tally
            .entry((finding.class, finding.signature))
            .or_insert(Tally {
                count: 0,
                first_seen: start.elapsed().as_secs_f64(),
                path,
            });
        t.count += 1;
    };
    while running > 0 {
        let Ok(report) = reports.recv() else { break };
        match report {
            Report::Ran {
                job,
                generation,
                count,
            } => {
                ran.insert((job, generation), count);
            }
            Report::Found { finding, path } => note(finding, path),
            Report::Ended { job, died } => {
                running -= 1;
                if let Some(why) = died {
                    let current = current_file(dir, job);
                    let input = std::fs::read_to_string(&current).unwrap_or_default();
                    let class = match why.contains("memory allocation of") {
                        true => Class::Memory,
                        false => Class::Crash,
                    };
                    let finding = Finding::of_input(class, &why, &input);
                    let path = finding.path(&findings, options.target.extension());
                    let _ = std::fs::copy(&current, &path);
                    note(finding, path.display().to_string());
                    *ran.entry((job, generation[job as usize])).or_default() += 1;
                }
                let now = unix_ms();
                // A worker ended early by a crash or a hang: a new one in its place.
                if now + 200 < end_ms {
                    generation[job as usize] += 1;
                    spawn(options, job, generation[job as usize], end_ms, tell.clone());
                    running += 1;
                }
            }
        }
    }
    let total: u64 = ran.values().sum();
    let seconds = start.elapsed().as_secs_f64();
    println!(
        "{}: {total} inputs in {seconds:.1} s ({:.0} inputs/s, {} jobs, seed {})",
        options.target.name(),
        total as f64 / seconds,
        options.jobs,
        options.seed
    );
    if tally.is_empty() {
        println!("no findings");
        return 0;
    }
    println!("{} findings (kept in {}):", tally.len(), findings.display());
    for ((class, signature), t) in &tally {
        println!(
            "  {:<10} x{:<6} first at {:>6.1} s  {}\n             {}",
            class.name(),
            t.count,
            t.first_seen,
            t.path,
            signature
        );
    }
    1
}

/// Now, in milliseconds since the Unix epoch: the clock the supervisor and its workers share
/// for the campaign's end.
pub fn unix_ms() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_millis() as u64)
        .unwrap_or(0)
}

/// The file worker `job` writes each input to before running it.
pub fn current_file(dir: &Path, job: u64) -> PathBuf {
    dir.join(format!("current-{job}"))
}

/// Starts worker `job` in `generation` and a thread that passes on its reports.
fn spawn(options: &Options, job: u64, generation: u64, end_ms: u64, tell: Sender<Report>) {
    let exe = std::env::current_exe().expect("the fuzzer's path");
    let mut child = Command::new("/bin/sh")
        .arg("-c")
        .arg(format!("ulimit -v {MEMORY_LIMIT_KB} && exec \"$0\" \"$@\""))
        .arg(exe)
        .env("MALLOC_ARENA_MAX", "2")
        .arg(options.target.name())
        .args(["--seed", &options.seed.to_string()])
        .args(["--out", &options.out.display().to_string()])
        .args(["--job", &job.to_string()])
        .args(["--generation", &generation.to_string()])
        .args(["--end-ms", &end_ms.to_string()])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("a worker starts");
    let stdout = child.stdout.take().expect("piped");
    let mut stderr = child.stderr.take().expect("piped");
    // The end of standard error says why a worker died (a stack overflow names itself).
    let errors = std::thread::spawn(move || {
        let mut text = String::new();
        let _ = stderr.read_to_string(&mut text);
        let last = text
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or_default();
        last.chars().take(100).collect::<String>()
    });
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            let fields: Vec<&str> = line.split('\t').collect();
            let report = match fields.as_slice() {
                ["finding", class, signature, path] => {
                    Class::from_name(class).map(|class| Report::Found {
                        finding: Finding {
                            class,
                            signature: signature.to_string(),
                        },
                        path: path.to_string(),
                    })
                }
                _ => line
                    .strip_prefix("ran ")
                    .and_then(|n| n.parse().ok())
                    .map(|count| Report::Ran {
                        job,
                        generation,
                        count,
                    }),
            };
            if let Some(report) = report {
                let _ = tell.send(report);
            }
        }
        let status = child.wait().expect("the worker is waited for");
        let last = errors.join().unwrap_or_default();
        let died = match status.code() {
            Some(0) | Some(HANG_EXIT) => None,
            Some(code) => Some(format!("exit code {code} ({last})")),
            None => Some(format!("killed by a signal ({last})")),
        };
        let _ = tell.send(Report::Ended { job, died });
    });
}
