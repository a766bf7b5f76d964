//! `kinetics solve SCENE [--format text|latex|markdown|json] [--standalone]` and
//! `kinetics plan SCENE`: a scene file (or `-` for standard input) analysed on demand.

use kinetics::scene::{analyse, parse_scene, Analysis, Scene};
use kinetics::solution::{render, Format};
use std::io::Read;

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

fn load(path: &str) -> Result<(Scene, Analysis), String> {
    let (name, text) = if path == "-" {
        super::input::read("-")?
    } else {
        let limit = kinetics::parse::limits::MAX_INPUT_BYTES as u64;
        let file =
            std::fs::File::open(path).map_err(|e| format!("error: cannot read {path}: {e}"))?;
        let mut bytes = Vec::new();
        file.take(limit + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| format!("error: cannot read {path}: {e}"))?;
        if bytes.len() as u64 > limit {
            return Err(format!(
                "error: {path}: the scene is larger than {limit} bytes"
            ));
        }
        let text =
            String::from_utf8(bytes).map_err(|_| format!("error: {path}: not UTF-8 text"))?;
        (path.to_string(), text)
    };
    let scene = parse_scene(&name, &text).map_err(|d| d.render())?;
    let analysis = analyse(&scene).map_err(|d| d.render())?;
    Ok((scene, analysis))
}

pub fn run(args: Args) -> Result<String, String> {
    let (scene, analysis) = load(&args.scene)?;
    if args.standalone && args.format != Format::Latex {
        return Err("error: --standalone goes with --format latex".into());
    }
    Ok(render(&scene, &analysis, args.format, args.standalone)
        .trim_end()
        .to_string())
}

pub fn plan(args: PlanArgs) -> Result<String, String> {
    let (_, analysis) = load(&args.scene)?;
    Ok(analysis
        .plan
        .iter()
        .enumerate()
        .map(|(k, s)| format!("{}. {}", k + 1, s.title))
        .collect::<Vec<_>>()
        .join("\n"))
}
