//! The fuzz targets, each input through the library entry points of the commands:
//! `expr` through `kinetics simplify [--expand]` and `kinetics latex` (parse, simplify or expand, print
//! in text and LaTeX, a vector component by component), `scene` through `kinetics solve`
//! (parse, analyse, the numbers asked for, the worked solution) and `kinetics simulate
//! --until 1` (the body's problem, integrated or in closed form, 100 samples). `plan` is
//! `solve`'s analysis without the rendering, so `solve` covers it. `check` (claims through
//! `kinetics check`) is in [`crate::check`].
//!
//! Each run returns the first broken promise it sees (a panic aside: the worker catches it);
//! a clean refusal is no finding. Every output and error message is checked for `inf`/`NaN`
//! and for raw control characters; `solve`'s worked solution is also rendered in LaTeX
//! (standalone), Markdown and HTML and checked for markup injected from the scene's title
//! and names (issue 29).

use crate::finding::{
    control_name, injected, longest_digit_run, non_finite_word, raw_control, Class, Finding, Markup,
};
use kinetics::algebra::work::Budget;
use kinetics::algebra::{vector, AlgebraError, Axis, Domains, Expr};
use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice};
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::Sampling;
use kinetics::parse::as_written::statement_as_written;
use kinetics::parse::{parse_statement, Diagnostic, Statement};
use kinetics::print::{self, Notation};
use kinetics::scene::{analyse, parse_scene, simulation};
use kinetics::solution::numbers::check_numeric_requests;
use kinetics::solution::{render, Format};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Target {
    Expr,
    Scene,
    Check,
}

impl Target {
    /// The commands an input goes through, as `# run:` writes them.
    pub fn runs(self) -> &'static [&'static str] {
        match self {
            Target::Expr => &["simplify", "simplify --expand", "latex"],
            Target::Scene => &["solve", "simulate --until 1"],
            Target::Check => &crate::check::RUNS,
        }
    }

    /// The extension of its inputs' files.
    pub fn extension(self) -> &'static str {
        match self {
            Target::Expr => "expr",
            Target::Scene => "scene",
            Target::Check => "claim",
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Target::Check => "check",
            _ => self.extension(),
        }
    }
}

/// Runs `text` through the command `run`: what it broke, if anything.
/// Within the input's work budget, as the binary runs every command: a run that spends it
/// is refused cleanly (the binary's refusal, located at the input).
pub fn check(run: &str, text: &str) -> Option<Finding> {
    let outcome = Budget::for_input(text.len()).run(|| match run {
        "simplify" => expression(text, Form::Shortest),
        "latex" => expression(text, Form::AsWritten),
        "simplify --expand" => expression(text, Form::Expanded),
        "solve" => solve(text),
        "simulate --until 1" => simulate(text),
        _ => crate::check::claim(run, text),
    });
    match outcome {
        Ok((outcome, _spent)) => outcome.err().flatten(),
        Err(_out_of_work) => None,
    }
}

/// `Err(None)`: refused cleanly; `Err(Some(finding))`: a promise broken.
pub type Outcome = Result<(), Option<Finding>>;

/// The form a command shows: `latex` the canonical form, `simplify` the shortest,
/// `simplify --expand` the expansion.
#[derive(Clone, Copy)]
enum Form {
    AsWritten,
    Shortest,
    Expanded,
}

fn expression(text: &str, form: Form) -> Outcome {
    let unreadable = |d: Diagnostic| located(&d, text, false);
    let statement = match form {
        // `latex` reads its input once, for the algebra and as written (`parse::as_written`).
        Form::AsWritten => {
            let (statement, written) = statement_as_written("input", text).map_err(unreadable)?;
            printed(&written.latex, text)?;
            printed(&written.text, text)?;
            statement
        }
        _ => parse_statement("input", text).map_err(unreadable)?,
    };
    let sides = match statement {
        Statement::Expression(e) => vec![e],
        Statement::Equation(eq) => vec![eq.lhs, eq.rhs],
    };
    // As `simplify` and `latex` do, an error of the algebra stands at the whole input.
    let at_input = |err: AlgebraError| {
        let whole = Diagnostic::at("input", text, 0, text.trim_end().len(), err.to_string());
        located(&whole, text, false)
    };
    for side in sides {
        let side = match form {
            Form::AsWritten => side,
            Form::Shortest => side
                .simplify(&Domains::chapter_defaults())
                .map_err(at_input)?,
            Form::Expanded => side.expand().map_err(at_input)?,
        };
        for notation in [Notation::Text, Notation::Latex, Notation::MathMl] {
            printed(&show(&side, notation).map_err(at_input)?, text)?;
        }
    }
    Ok(())
}

/// An expression as `simplify` and `latex` print it.
fn show(e: &Expr, notation: Notation) -> Result<String, AlgebraError> {
    if vector::has_unit_vectors(e) {
        Ok(print::vector(&vector::components(e)?, notation))
    } else {
        Ok(print::render(e, notation, Axis::X))
    }
}

fn solve(text: &str) -> Outcome {
    let scene = parse_scene("fuzz.scene", text).map_err(|d| located(&d, text, true))?;
    let analysis = analyse(&scene).map_err(|d| located(&d, text, true))?;
    check_numeric_requests(&scene, &analysis).map_err(|d| located(&d, text, true))?;
    printed(&render(&scene, &analysis, Format::Text, false), text)?;
    for (format, markup) in [
        (Format::Latex, Markup::Latex),
        (Format::Markdown, Markup::Markdown),
        (Format::Html, Markup::Html),
    ] {
        let page = render(&scene, &analysis, format, true);
        printed(&page, text)?;
        if let Some(what) = injected(&page, markup) {
            return Err(Some(Finding::new(Class::Injection, "solve page: ", what)));
        }
    }
    Ok(())
}

fn simulate(text: &str) -> Outcome {
    let scene = parse_scene("fuzz.scene", text).map_err(|d| located(&d, text, true))?;
    let problem = simulation::problem(&scene).map_err(|d| located(&d, text, true))?;
    let sampling = Sampling::Every {
        interval: 0.01,
        end: 1.0,
    };
    let mut non_finite = None;
    let mut sink = |s: Sample<f64>| {
        let q = s.orientation.into_inner();
        let fields = [
            ("t", s.t),
            ("w_x", s.omega.x),
            ("w_y", s.omega.y),
            ("w_z", s.omega.z),
            ("q", q.w + q.i + q.j + q.k),
            ("T", s.kinetic_energy),
            ("H", s.angular_momentum_magnitude),
        ];
        if let Some((name, _)) = fields.iter().find(|(_, v)| !v.is_finite()) {
            non_finite.get_or_insert(*name);
        }
    };
    let choice = Choice::Auto { rtol: 1e-10 };
    // As `simulate` does, a failure of the body's motion stands at the body.
    simulate_choice(&problem, &choice, &sampling, &mut sink, &mut |_| {}).map_err(|e| {
        match simulation::located(&scene, &e) {
            Some(d) => located(&d, text, true),
            None => Some(unlocated(e)),
        }
    })?;
    match non_finite {
        Some(name) => Err(Some(Finding::new(Class::NonFinite, "sample ", name))),
        None => Ok(()),
    }
}

/// What is wrong with a refusal, if anything: a place outside the input or on a comment
/// line of a scene, or a quoted number longer than any the input holds.
pub fn located(d: &Diagnostic, text: &str, scene: bool) -> Option<Finding> {
    if let Some(c) = raw_control(&d.render()) {
        return Some(Finding::new(
            Class::Control,
            "error message prints ",
            control_name(c),
        ));
    }
    let line = text.lines().nth(d.line.wrapping_sub(1));
    let said = format!("{} {}", d.message, d.help.as_deref().unwrap_or_default());
    // The end of the input is a place: where a missing line goes. An empty span at the
    // start stands for the input as a whole (too large to read).
    let at_end = d.span.offset() >= text.trim_end().len();
    let whole_input = d.span.offset() == 0 && d.span.is_empty();
    let no_place = !at_end
        && !whole_input
        && match line {
            None => true,
            Some(l) => scene && l.trim_start().starts_with('#'),
        };
    if no_place {
        return Some(Finding::new(
            Class::Unlocated,
            "points at no statement: ",
            &words(&d.message),
        ));
    }
    (longest_digit_run(&said) > longest_digit_run(text).max(12))
        .then(|| Finding::new(Class::Unquoted, "", &words(&d.message)))
}

fn unlocated(e: impl std::fmt::Display) -> Finding {
    Finding::new(Class::Unlocated, "", &words(&e.to_string()))
}

/// The words of a message (three letters or more), without the terms and numbers it quotes:
/// the same refusal of other input is the same finding.
fn words(message: &str) -> String {
    message
        .split_whitespace()
        .filter(|w| w.len() >= 3 && w.chars().all(|c| c.is_ascii_alphabetic() || c == '\''))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Checks printed output for an `inf` or `NaN` the input did not hold itself, and for a
/// raw control character.
pub fn printed(output: &str, input: &str) -> Result<(), Finding> {
    if let Some(c) = raw_control(output) {
        return Err(Finding::new(Class::Control, "prints ", control_name(c)));
    }
    match non_finite_word(output, input) {
        Some(word) => Err(Finding::new(Class::NonFinite, "prints ", word)),
        None => Ok(()),
    }
}
