//! One worker process: inputs one after another (generated, or mutated from the corpus),
//! each through every command of the target. Before each run the input is written, in the
//! reproducer format, to the worker's `current` file, so that a crash (a stack overflow kills
//! the process) leaves it behind for the supervisor. A panic is caught and kept as a
//! finding; a run longer than [`HANG_LIMIT`] is kept as a hang by the watchdog (this
//! process's main thread), which then ends the process with [`HANG_EXIT`].
//!
//! Standard output carries the reports the supervisor reads: `ran N` (inputs so far) and
//! `finding ...` lines.

use crate::finding::{Class, Finding};
use crate::random::Random;
use crate::target::{check, Target};
use crate::{corpus, generate, generate_claim, mutate};
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// A run longer than this is a hang.
pub const HANG_LIMIT: Duration = Duration::from_secs(2);
/// The exit code of a worker whose watchdog found a hang.
pub const HANG_EXIT: i32 = 3;
/// The stack of the thread that runs inputs: the main thread's on Linux, as in the binary.
const STACK: usize = 8 << 20;

/// Where a worker works and for how long.
pub struct Work {
    pub target: Target,
    pub seed: u64,
    pub job: u64,
    pub generation: u64,
    pub findings: PathBuf,
    pub current: PathBuf,
    pub end: Instant,
}

/// The last panic's place and message, from the panic hook.
static LAST_PANIC: Mutex<(String, String)> = Mutex::new((String::new(), String::new()));

/// Runs inputs until the end, then exits (never returns).
pub fn run(work: Work) -> ! {
    std::panic::set_hook(Box::new(|info| {
        let place = info
            .location()
            .map(|l| format!("{}:{}:{}: ", l.file(), l.line(), l.column()))
            .unwrap_or_default();
        let message = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        if let Ok(mut last) = LAST_PANIC.lock() {
            *last = (place, message);
        }
    }));
    let work = Arc::new(work);
    let ran = Arc::new(AtomicU64::new(0));
    // Milliseconds since `epoch` when the current run began, 0 between runs.
    let started = Arc::new(AtomicU64::new(0));
    let epoch = Instant::now();
    let runner = {
        let (work, ran, started) = (work.clone(), ran.clone(), started.clone());
        std::thread::Builder::new()
            .stack_size(STACK)
            .spawn(move || inputs(&work, &ran, &started, epoch))
            .expect("a thread starts")
    };
    let mut reported = u64::MAX;
    loop {
        std::thread::sleep(Duration::from_millis(100));
        let since = started.load(Ordering::SeqCst);
        let now = epoch.elapsed().as_millis() as u64;
        if since != 0 && now.saturating_sub(since) > HANG_LIMIT.as_millis() as u64 {
            let input = std::fs::read_to_string(&work.current).unwrap_or_default();
            let seconds = HANG_LIMIT.as_secs();
            Finding::of_input(Class::Hang, &format!("over {seconds} s"), &input).report(
                &work.findings,
                work.target.extension(),
                &input,
            );
            println!("ran {}", ran.load(Ordering::SeqCst));
            std::process::exit(HANG_EXIT);
        }
        let count = ran.load(Ordering::SeqCst);
        if count != reported {
            println!("ran {count}");
            reported = count;
        }
        if runner.is_finished() {
            println!("ran {}", ran.load(Ordering::SeqCst));
            std::process::exit(0);
        }
    }
}

/// The runner thread: inputs until the end.
fn inputs(work: &Work, ran: &AtomicU64, started: &AtomicU64, epoch: Instant) {
    let seeds = corpus::seeds(work.target);
    let mut random = Random::new(work.seed, work.job, work.generation);
    let r = &mut random;
    while Instant::now() < work.end {
        let text = match (work.target, r.below(8)) {
            (Target::Expr, 0..=2) => generate::statement(r),
            (Target::Check, 0..=2) => generate_claim::claim(r),
            (_, 0) => r.pick(&seeds).clone(),
            _ => {
                let (seed, other) = (r.pick(&seeds).clone(), r.pick(&seeds).clone());
                mutate::mutate(r, &seed, &other)
            }
        };
        let text = match work.target {
            // An expression or a claim is one line, as an argument is.
            Target::Expr | Target::Check => text.lines().next().unwrap_or_default().to_string(),
            Target::Scene => text,
        };
        for run in work.target.runs() {
            let reproducer = format!("# run: {run}\n{text}\n");
            let _ = std::fs::write(&work.current, &reproducer);
            started.store(epoch.elapsed().as_millis().max(1) as u64, Ordering::SeqCst);
            let outcome = std::panic::catch_unwind(|| check(run, &text));
            started.store(0, Ordering::SeqCst);
            let finding = match outcome {
                Ok(finding) => finding,
                Err(_) => {
                    let (place, message) = LAST_PANIC.lock().map(|l| l.clone()).unwrap_or_default();
                    Some(Finding::new(Class::Panic, &place, &message))
                }
            };
            if let Some(f) = finding {
                f.report(&work.findings, work.target.extension(), &reproducer);
            }
        }
        ran.fetch_add(1, Ordering::SeqCst);
    }
}
