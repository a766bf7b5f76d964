//! `kinetics solve SCENE [--format text|latex|markdown|json|html] [--standalone] [--numbers]
//! [--digits N] [--units si|us]` and
//! `kinetics plan SCENE`: a scene file (or `-` for standard input) analysed on demand.

use super::budget::Input;
use super::error::CliError;
use kinetics::scene::unit_system::UnitSystem;
use kinetics::scene::{analyse, parse_scene_in, Analysis, Scene};
use kinetics::solution::numbers::{with_digits, DEFAULT_DIGITS};
use kinetics::solution::{render, render_numbers, Format};

#[derive(clap::Args)]
#[command(after_help = "Example:\n  kinetics solve examples/scenes/sp18_4_shaft_reactions.scene")]
pub struct Args {
    /// The scene file; `-` reads standard input.
    pub scene: String,
    #[arg(long, value_enum, default_value_t = SolutionFormat::Text)]
    pub format: SolutionFormat,
    /// With `--format latex`: a complete document that compiles with pdflatex.
    #[arg(long)]
    pub standalone: bool,
    /// The engineer's page: the givens, each result as a number with its unit and the
    /// intermediate values, without the symbolic steps (in any format).
    #[arg(long)]
    pub numbers: bool,
    /// Significant figures of every number on the page (1 to 17); a rounded value keeps its
    /// trailing zeros, and from 10⁵ up or below 10⁻⁴ it is in engineering notation.
    #[arg(long, default_value_t = DEFAULT_DIGITS as u8, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// The unit system of the values on the page (results and intermediate values): SI, or
    /// U.S. customary (lb, ft, slug, lb·ft, slug·ft², ft/s). Without it, the system the givens
    /// are written in. A `find … in UNIT` or an unknown's declared unit still wins.
    #[arg(long, value_enum)]
    pub units: Option<Units>,
}

/// The unit systems as the command line spells them.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Units {
    /// kg, m, N, N·m, kg·m², m/s.
    Si,
    /// U.S. customary: slug, ft, lb, lb·ft, slug·ft², ft/s.
    Us,
}

impl From<Units> for UnitSystem {
    fn from(units: Units) -> UnitSystem {
        match units {
            Units::Si => UnitSystem::Si,
            Units::Us => UnitSystem::Us,
        }
    }
}

/// The formats of a worked solution as the command line spells them (the library's
/// [`Format`] knows nothing of clap).
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SolutionFormat {
    Text,
    Latex,
    Markdown,
    Json,
    /// One self-contained HTML page, the mathematics in MathML (a preview without LaTeX).
    Html,
}

impl From<SolutionFormat> for Format {
    fn from(format: SolutionFormat) -> Format {
        match format {
            SolutionFormat::Text => Format::Text,
            SolutionFormat::Latex => Format::Latex,
            SolutionFormat::Markdown => Format::Markdown,
            SolutionFormat::Json => Format::Json,
            SolutionFormat::Html => Format::Html,
        }
    }
}

#[derive(clap::Args)]
#[command(after_help = "Example:\n  kinetics plan examples/scenes/sp18_4_shaft_reactions.scene")]
pub struct PlanArgs {
    /// The scene file; `-` reads standard input.
    pub scene: String,
}

/// Reads and parses the scene at `path`, then does `work` on it and its analysis within
/// the scene's work budget.
fn with_analysis<T>(
    path: &str,
    units: Option<Units>,
    work: impl FnOnce(&Scene, &Analysis) -> Result<T, CliError>,
) -> Result<T, CliError> {
    let (name, text) = super::input::read_file(path)?;
    Input::scene(&name, &text).within(|| {
        let scene = parse_scene_in(&name, &text, units.map(Into::into))?;
        let analysis = analyse(&scene)?;
        kinetics::solution::numbers::check_numeric_requests(&scene, &analysis)?;
        work(&scene, &analysis)
    })
}

pub fn run(args: Args) -> Result<String, CliError> {
    with_analysis(&args.scene, args.units, |scene, analysis| {
        page(&args, scene, analysis)
    })
}

fn page(args: &Args, scene: &Scene, analysis: &Analysis) -> Result<String, CliError> {
    let format = Format::from(args.format);
    if args.standalone && format != Format::Latex {
        return Err(CliError::Usage(
            "--standalone goes with --format latex".into(),
        ));
    }
    let page = with_digits(usize::from(args.digits), || match args.numbers {
        true => render_numbers(scene, analysis, format, args.standalone),
        false => render(scene, analysis, format, args.standalone),
    });
    Ok(page.trim_end().to_string())
}

pub fn plan(args: PlanArgs) -> Result<String, CliError> {
    with_analysis(&args.scene, None, |_, analysis| {
        Ok(analysis
            .plan
            .iter()
            .enumerate()
            .map(|(k, s)| format!("{}. {}", k + 1, kinetics::print::markup::text(&s.title)))
            .collect::<Vec<_>>()
            .join("\n"))
    })
}
