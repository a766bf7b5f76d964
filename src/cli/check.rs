//! `kinetics check [SCENE] [--principal] [--fixed-point | --fixed-axis] --claim "<eq>"... [--claims FILE|-]
//! [--derivation FILE|-] [--format text|latex|json]`: hand-written claims checked against the
//! derivations; a derivation line by line ([`super::derivation`]).
//!
//! Exit status: 0 when every claim holds, 1 when one differs, 3 when none differs and one is
//! undecided, 2 when an input could not be read (the other claims are still checked).

use super::error::CliError;
use super::input::read_file;
use kinetics::algebra::work::Budget;
use kinetics::check::context::{Context, DEFAULT_RELATIVE_TOLERANCE};
use kinetics::check::forms::Forms;
use kinetics::check::report;
use kinetics::check::verdict::{check, Report, Verdict};
use kinetics::parse::Diagnostic;
use kinetics::scene::parse_scene;
use kinetics::Input;
use rayon::prelude::*;
use std::io::Write;
use std::process::ExitCode;

#[derive(clap::Args)]
#[command(
    after_help = "Example:\n  kinetics check --principal --fixed-point --claim \"T = 1/2 (I_x w_x^2 + I_y w_y^2 + I_z w_z^2)\""
)]
pub struct Args {
    /// A scene file whose givens, unknowns and derived quantities the claims may use;
    /// without one, a general body in body-fixed axes.
    pub scene: Option<String>,
    /// A claim `lhs = rhs` (repeatable).
    #[arg(long, allow_hyphen_values = true, value_parser = super::input::expression_argument)]
    pub claim: Vec<String>,
    /// A file of claims, one a line (`#` starts a comment); `-` reads standard input.
    #[arg(long)]
    pub claims: Option<String>,
    /// A derivation: successive equations, one a line (`#` comments, blank lines between
    /// parts), each checked and, where wrong, checked again against the lines before it
    /// (`follows from line k`: it carries that line's slip); `-` reads standard input.
    #[arg(long, conflicts_with_all = ["claim", "claims"])]
    pub derivation: Option<String>,
    /// Principal axes: every product of inertia is zero.
    #[arg(long, conflicts_with_all = ["scene", "fixed_axis"])]
    pub principal: bool,
    /// The body turns about a fixed point O (or its mass centre G is at rest): v̄ = 0, and
    /// the axes, moments of inertia and H_O are about that point.
    #[arg(long, conflicts_with_all = ["scene", "fixed_axis"])]
    pub fixed_point: bool,
    /// Rotation about the fixed axis z at w, alpha (§18.7).
    #[arg(long, conflicts_with = "scene")]
    pub fixed_axis: bool,
    /// How close a claim written in numbers must come to the exact value, relative to it
    /// (0.005 is 0.5 %, a number in three significant figures).
    #[arg(long, default_value_t = DEFAULT_RELATIVE_TOLERANCE, value_parser = relative_tolerance)]
    pub rtol: f64,
    #[arg(long, value_enum, default_value_t = super::show::Format::Text)]
    pub format: super::show::Format,
}

/// `--rtol`: a number from 0 up to, not including, 1.
fn relative_tolerance(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(r) if (0.0..1.0).contains(&r) => Ok(r),
        Ok(_) => Err(format!("{text} is not a relative tolerance: give a number from 0 up to 1, like 0.005 for 0.5 %")),
        Err(_) => Err(format!("{text} is not a number: give a relative tolerance like 0.005 for 0.5 %")),
    }
}

/// One claim to check: where it was written (its file and line, or its flag's place), how
/// the report names it, and its text.
struct Written {
    source_name: String,
    line: usize,
    label: String,
    text: String,
    /// A line of a claims file (else a `--claim`, a line of its own).
    from_file: bool,
}

/// Exit status 2: an input could not be read.
pub(super) const INPUT_ERROR: u8 = 2;
/// Exit status 3: no claim differs, and one is undecided.
pub(super) const UNDECIDED: u8 = 3;

pub fn run(args: Args) -> ExitCode {
    match checked(&args) {
        Ok(code) => code,
        Err(e) => {
            super::tell(e.to_string().trim_end());
            ExitCode::from(INPUT_ERROR)
        }
    }
}

fn context(args: &Args) -> Result<Context, CliError> {
    if let Some(path) = &args.scene {
        let (name, source) = read_file(path)?;
        let scene = Input::scene(&name, &source)
            .within(|| Ok::<_, CliError>(Context::scene(&parse_scene(&name, &source)?)))?;
        return Ok(scene.with_relative_tolerance(args.rtol));
    }
    let general = if args.fixed_axis {
        Context::fixed_axis()
    } else {
        Context::general(args.principal, args.fixed_point)
    };
    general.map_err(|source| CliError::Algebra { name: None, source })
}

/// The claims of `--claim` flags, then of `--claims`, blank lines and `#` comments skipped.
fn claims(args: &Args) -> Result<Vec<Written>, CliError> {
    let mut out: Vec<Written> = args
        .claim
        .iter()
        .enumerate()
        .map(|(k, text)| Written {
            source_name: format!("claim {}", k + 1),
            line: k + 1,
            label: format!("claim {}", k + 1),
            text: text.clone(),
            from_file: false,
        })
        .collect();
    if let Some(path) = &args.claims {
        let (name, source) = read_file(path)?;
        for (k, line) in source.lines().enumerate() {
            let text = line.split('#').next().unwrap_or_default();
            if !text.trim().is_empty() {
                out.push(Written {
                    source_name: name.clone(),
                    line: k + 1,
                    label: format!("{name}:{}", k + 1),
                    text: text.trim_end().to_string(),
                    from_file: true,
                });
            }
        }
    }
    if out.is_empty() {
        return Err(CliError::Usage(
            "no claim to check\n  = help: give one with --claim \"T = 1/2 m v^2\" or a file with --claims FILE".into(),
        ));
    }
    Ok(out)
}

fn checked(args: &Args) -> Result<ExitCode, CliError> {
    let context = context(args)?;
    if let Some(path) = &args.derivation {
        return super::derivation::run(&context, path, args.format);
    }
    let claims = claims(args)?;
    // The claims share one budget, that of all their text, in proportion to their lengths.
    let whole: usize = claims.iter().map(|w| w.text.len()).sum();
    let budget = Budget::for_input(whole);
    let outcomes: Vec<Result<Report, Box<Diagnostic>>> = claims
        .par_iter()
        .map(|w| {
            let claim = Input {
                budget: budget.share(w.text.len(), whole),
                ..Input::expression(&w.source_name, &w.text)
            };
            claim
                .within(|| check(&context, &w.source_name, &w.text).map_err(Box::new))
                .map_err(|mut d| {
                    // A claim of a file was read alone: its line is the file's.
                    if w.from_file {
                        d.line = w.line;
                    }
                    d
                })
        })
        .collect();
    let count = |v: Verdict| {
        outcomes
            .iter()
            .filter(|o| o.as_ref().is_ok_and(|r| r.verdict == v))
            .count()
    };
    let (holds, differs, undecided) = (
        count(Verdict::Holds),
        count(Verdict::Differs),
        count(Verdict::Undecided),
    );
    let errors = outcomes.iter().filter(|o| o.is_err()).count();
    let forms = Forms::new(context.domains());
    let mut stdout = String::new();
    let mut stderr = String::new();
    // Each claim's report is written in parallel too: for a class set the writing is a
    // fifth of the work (written in turn, 1000 claims took 132 ms on 2 cores, not 107).
    match args.format {
        super::show::Format::Json => {
            let claims: Vec<serde_json::Value> = claims
                .par_iter()
                .zip(&outcomes)
                .map(|(w, o)| match o {
                    Ok(r) => {
                        let mut j = report::json(r, &forms);
                        j["line"] = w.line.into();
                        j
                    }
                    Err(d) => serde_json::json!({"line": w.line, "claim": w.text,
                        "verdict": "error", "reading": null, "error": d.to_string(),
                        "components": [], "odd_term": null}),
                })
                .collect();
            for d in outcomes.iter().filter_map(|o| o.as_ref().err()) {
                stderr.push_str(&d.render());
            }
            let summary = serde_json::json!({"holds": holds, "differs": differs,
                "undecided": undecided, "errors": errors});
            stdout = serde_json::json!({"context": context.description, "claims": claims,
                "summary": summary})
            .to_string();
        }
        format => {
            let written: Vec<Result<String, String>> = claims
                .par_iter()
                .zip(&outcomes)
                .map(|(w, o)| match (o, format) {
                    (Ok(r), super::show::Format::Latex) => Ok(report::latex(r, &w.label, &forms)),
                    (Ok(r), _) => Ok(report::text(r, &w.label, &forms)),
                    (Err(d), _) => Err(d.render()),
                })
                .collect();
            for text in written {
                match text {
                    Ok(report) => stdout.push_str(&report),
                    Err(diagnostic) => stderr.push_str(&diagnostic),
                }
            }
            let noun = if claims.len() == 1 { "claim" } else { "claims" };
            let error_noun = if errors == 1 { "error" } else { "errors" };
            let summary = format!(
                "{} {noun}: {holds} hold, {differs} differ, {undecided} undecided, {errors} {error_noun}",
                claims.len()
            );
            match format {
                super::show::Format::Latex => stdout.push_str(&format!("% {summary}")),
                _ => stdout.push_str(&summary),
            }
        }
    }
    let _ = writeln!(std::io::stdout(), "{stdout}");
    if !stderr.is_empty() {
        super::tell(&stderr);
    }
    Ok(if errors > 0 {
        ExitCode::from(INPUT_ERROR)
    } else if differs > 0 {
        ExitCode::FAILURE
    } else if undecided > 0 {
        ExitCode::from(UNDECIDED)
    } else {
        ExitCode::SUCCESS
    })
}
