//! `kinetics derive --general [--principal] [--only H_G,T,euler,...] [--steps]
//! [--format text|latex|markdown|json] [--standalone] [--axis x|y|z]`: the chapter's
//! equations for a general body, each under its heading with the reference point and axes it is about.

use super::error::CliError;
use super::solve::SolutionFormat;
use kinetics::algebra::{Axis, Domains};
use kinetics::mechanics::catalogue::{derive_general_along, NAMES};
use kinetics::solution::{render_derivations, Format, Shown};

#[derive(clap::Args)]
#[command(after_help = "Example:\n  kinetics derive --general --principal --only euler")]
pub struct Args {
    /// Derive for a general body (symbols I_x ... I_xz, w_x, w_y, w_z, m, vbar).
    #[arg(long, required = true)]
    pub general: bool,
    /// Principal axes: every product of inertia is zero.
    #[arg(long)]
    pub principal: bool,
    /// Only these derivations (comma-separated): H_G, H_O, T, T_O, T_plane, impulse, Hdot,
    /// euler, fixed_axis, reactions, balancing, gyroscope, steady_precession,
    /// steady_precession_90, torque_free.
    #[arg(long, value_delimiter = ',')]
    pub only: Vec<String>,
    /// Show every step, not only the results.
    #[arg(long)]
    pub steps: bool,
    #[arg(long, value_enum, default_value_t = SolutionFormat::Text)]
    pub format: SolutionFormat,
    /// With `--format latex`: a complete document that compiles with pdflatex.
    #[arg(long)]
    pub standalone: bool,
    /// The axis of rotation of fixed_axis, reactions and balancing (the chapter's shafts
    /// often lie along x).
    #[arg(long, value_enum, default_value_t = RotationAxis::Z)]
    pub axis: RotationAxis,
}

/// An axis as the command line spells it.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum RotationAxis {
    X,
    Y,
    Z,
}

impl From<RotationAxis> for Axis {
    fn from(axis: RotationAxis) -> Axis {
        match axis {
            RotationAxis::X => Axis::X,
            RotationAxis::Y => Axis::Y,
            RotationAxis::Z => Axis::Z,
        }
    }
}

pub fn run(args: Args) -> Result<String, CliError> {
    let format = Format::from(args.format);
    let axis = Axis::from(args.axis);
    if args.standalone && format != Format::Latex {
        return Err(CliError::Usage(
            "--standalone goes with --format latex".into(),
        ));
    }
    let names: Vec<&str> = if args.only.is_empty() {
        NAMES.to_vec()
    } else {
        args.only.iter().map(String::as_str).collect()
    };
    let mut derivations = Vec::new();
    for name in names {
        let derived = derive_general_along(name, args.principal, axis).ok_or_else(|| {
            CliError::Usage(format!(
                "unknown derivation '{name}'\n  = help: choose from {}",
                NAMES.join(", ")
            ))
        })?;
        let derived = derived.map_err(|source| CliError::Algebra {
            name: Some(name.to_string()),
            source,
        })?;
        derivations.push(derived.simplified(&Domains::chapter_defaults()));
    }
    Ok(render_derivations(
        &derivations,
        Shown {
            format,
            all_steps: args.steps,
            standalone: args.standalone,
            axis,
        },
    ))
}
