//! `kinetics figure SCENE [--format svg|tikz] [-o FILE]`: the scene's figure (the body, its
//! axes and loads) as an SVG image or a TikZ picture, on standard output or in FILE.

use super::error::CliError;
use kinetics::figure::{figure, svg::svg, tikz::tikz};
use kinetics::scene::parse_scene_in;
use kinetics::Input;

#[derive(clap::Args)]
#[command(
    after_help = "Example:\n  kinetics figure examples/scenes/sp18_4_shaft_reactions.scene --format tikz"
)]
pub struct Args {
    /// The scene file; `-` reads standard input.
    pub scene: String,
    #[arg(long, value_enum, default_value_t = FigureFormat::Svg)]
    pub format: FigureFormat,
    /// Write the figure to this file instead of standard output.
    #[arg(short, long)]
    pub output: Option<std::path::PathBuf>,
}

/// The figure's formats as the command line spells them.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FigureFormat {
    /// An SVG image (a browser, an HTML page, a Markdown page's image).
    Svg,
    /// A `tikzpicture` for a LaTeX document (`\usepackage{tikz}`).
    Tikz,
}

/// The figure in its format, or nothing when it went to `--output`.
pub fn run(args: Args) -> Result<String, CliError> {
    let (name, text) = super::input::read_file(&args.scene)?;
    let drawn = Input::scene(&name, &text).within(|| {
        let scene = parse_scene_in(&name, &text, None)?;
        figure(&scene).map_err(CliError::Figure)
    })?;
    let out = match args.format {
        FigureFormat::Svg => svg(&drawn),
        FigureFormat::Tikz => tikz(&drawn),
    };
    match &args.output {
        Some(path) => {
            std::fs::write(path, format!("{out}\n"))
                .map_err(CliError::io(format!("write {}", path.display())))?;
            Ok(String::new())
        }
        None => Ok(out),
    }
}
