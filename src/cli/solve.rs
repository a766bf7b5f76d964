//! `kinetics solve SCENE [--format text|latex|markdown|json|html] [--standalone] [--numbers]
//! [--digits N] [--units si|us] [-o FILE]` and
//! `kinetics plan SCENE`: a scene file (or `-` for standard input) analysed on demand.

use super::error::CliError;
use kinetics::figure::{figure, svg::svg};
use kinetics::scene::unit_system::UnitSystem;
use kinetics::scene::{analyse, parse_scene_in, Analysis, Scene};
use kinetics::solution::numbers::{with_digits, DEFAULT_DIGITS};
use kinetics::solution::{render_beside, render_numbers_beside, Format};
use kinetics::Input;
use std::path::{Path, PathBuf};

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
    /// Write the page to this file instead of standard output; a Markdown page's figure is
    /// written beside it, as the same name with `.svg`.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
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
    let beside = match (&args.output, format) {
        (Some(path), Format::Markdown) => Some(figure_path(path)),
        _ => None,
    };
    let figure_file = beside
        .as_deref()
        .and_then(Path::file_name)
        .map(|name| name.to_string_lossy().into_owned());
    let page = with_digits(usize::from(args.digits), || match args.numbers {
        true => render_numbers_beside(
            scene,
            analysis,
            format,
            args.standalone,
            figure_file.as_deref(),
        ),
        false => render_beside(
            scene,
            analysis,
            format,
            args.standalone,
            figure_file.as_deref(),
        ),
    });
    let page = page.trim_end().to_string();
    let Some(path) = &args.output else {
        return Ok(page);
    };
    if let Some(svg_path) = &beside {
        if svg_path == path {
            return Err(CliError::Usage(format!(
                "-o {}: the Markdown page's figure goes beside it as a .svg of the same name; name the page .md",
                path.display()
            )));
        }
        // The page names the image only when it can be drawn: then it is written.
        if let Ok(drawn) = figure(scene) {
            std::fs::write(svg_path, format!("{}\n", svg(&drawn)))
                .map_err(CliError::io(format!("write {}", svg_path.display())))?;
        }
    }
    std::fs::write(path, format!("{page}\n"))
        .map_err(CliError::io(format!("write {}", path.display())))?;
    Ok(String::new())
}

/// Where a Markdown page's figure goes: beside it, its name with `.svg`.
fn figure_path(page: &Path) -> PathBuf {
    page.with_extension("svg")
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
