//! The `check` target: a claim through what `kinetics check --claim` calls in-process, in
//! each of its contexts (the general body, `--principal`, `--fixed-axis`, and the scene
//! [`SCENE`]): the check ([`kinetics::check::verdict::check`]), then the report in text,
//! LaTeX and JSON as the command renders it, or the located error it prints.
//!
//! Each context is built once per worker (a thread-local, on the thread that runs inputs).

use crate::target::{located, printed, Outcome};
use kinetics::check::context::Context;
use kinetics::check::forms::Forms;
use kinetics::check::report;
use kinetics::check::verdict::check;
use kinetics::scene::parse_scene;
use std::thread::LocalKey;

/// The scene of the scene context, from the package's root (as `# run:` names it).
pub const SCENE: &str = "examples/scenes/sp18_2_rolling_disk.scene";

/// The commands a claim goes through, as `# run:` writes them (the claim follows `--claim`).
pub const RUNS: [&str; 4] = [
    "check --claim",
    "check --principal --claim",
    "check --fixed-axis --claim",
    "check examples/scenes/sp18_2_rolling_disk.scene --claim",
];

/// How the command names a claim given with `--claim` (its diagnostics and its report).
const LABEL: &str = "claim 1";

thread_local! {
    static GENERAL: Context = Context::general(false, false).expect("the general body derives");
    static PRINCIPAL: Context = Context::general(true, false).expect("principal axes derive");
    static FIXED_AXIS: Context = Context::fixed_axis().expect("the fixed axis derives");
    static IN_SCENE: Context = scene_context();
}

fn scene_context() -> Context {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(SCENE);
    let source = std::fs::read_to_string(&path).expect("the scene is shipped");
    let scene = parse_scene(SCENE, &source).expect("the shipped scene parses");
    Context::scene(&scene)
}

/// Checks `claim` through the command `run` (one of [`RUNS`]).
pub fn claim(run: &str, claim: &str) -> Outcome {
    let context: &'static LocalKey<Context> = match run {
        "check --principal --claim" => &PRINCIPAL,
        "check --fixed-axis --claim" => &FIXED_AXIS,
        "check --claim" => &GENERAL,
        _ => &IN_SCENE,
    };
    context.with(|context| in_context(context, claim))
}

fn in_context(context: &Context, claim: &str) -> Outcome {
    let report = match check(context, LABEL, claim) {
        Ok(report) => report,
        Err(d) => {
            printed(&d.render(), claim)?;
            return Err(located(&d, claim, false));
        }
    };
    let forms = Forms::new(context.domains());
    printed(&report::text(&report, LABEL, &forms), claim)?;
    printed(&report::latex(&report, LABEL, &forms), claim)?;
    printed(&report::json(&report, &forms).to_string(), claim)?;
    Ok(())
}
