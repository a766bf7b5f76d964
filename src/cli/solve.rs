//! `kinetics solve SCENE [--format text|latex|markdown|json] [--standalone]` and
//! `kinetics plan SCENE`: a scene file (or `-` for standard input) analysed on demand.

use super::error::CliError;
use kinetics::scene::{analyse, parse_scene, Analysis, Scene};
use kinetics::solution::{render, Format};

#[derive(clap::Args)]
pub struct Args {
    /// The scene file; `-` reads standard input.
    pub scene: String,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// With `--format latex`: a complete document that compiles with pdflatex.
    #[arg(long)]
    pub standalone: bool,
}

#[derive(clap::Args)]
pub struct PlanArgs {
    /// The scene file; `-` reads standard input.
    pub scene: String,
}

fn load(path: &str) -> Result<(Scene, Analysis), CliError> {
    let (name, text) = super::input::read_file(path)?;
    let scene = parse_scene(&name, &text)?;
    let analysis = analyse(&scene)?;
    kinetics::solution::numbers::check_numeric_requests(&scene, &analysis)?;
    Ok((scene, analysis))
}

pub fn run(args: Args) -> Result<String, CliError> {
    let (scene, analysis) = load(&args.scene)?;
    if args.standalone && args.format != Format::Latex {
        return Err(CliError::Usage(
            "--standalone goes with --format latex".into(),
        ));
    }
    Ok(render(&scene, &analysis, args.format, args.standalone)
        .trim_end()
        .to_string())
}

pub fn plan(args: PlanArgs) -> Result<String, CliError> {
    let (_, analysis) = load(&args.scene)?;
    Ok(analysis
        .plan
        .iter()
        .enumerate()
        .map(|(k, s)| format!("{}. {}", k + 1, s.title))
        .collect::<Vec<_>>()
        .join("\n"))
}
