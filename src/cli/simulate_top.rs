//! `kinetics simulate` of a scene with `euler angles`: a heavy top about its fixed point,
//! streamed as its Eulerian angles and their rates (`t,theta,phi,psi,thetadot,phidot,psidot`,
//! rad and rad/s, φ and ψ unwrapped), with the turning angles its energy and momenta predict
//! on standard error; `--plot` draws the path of the axis seen from above and θ(t).
//!
//! φ and ψ count their turns from sample to sample by the bands their rates keep over the
//! nutation (`NutationLimits`): a sampling whose longest gap `Δt` makes a band as wide as
//! `π/Δt` is refused before the run, with the gap that would do. When the axis reaches the
//! vertical there is no band, and the turns are counted from the rates at the samples,
//! which standard error says needs dense samples.

use super::error::CliError;
use super::sample_rows::SampleRows;
use super::simulate::{located, method_report, Args};
use kinetics::algebra::four_significant_figures;
use kinetics::numeric::rigid_body::eulerian_angles::{AnglesAlongMotion, EulerianAngles};
use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice};
use kinetics::numeric::rigid_body::heavy_top::HeavyTop;
use kinetics::numeric::rigid_body::nutation_limits::{nutation_limits, NutationLimits};
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::Sampling;
use kinetics::scene::units::Dimension;
use kinetics::scene::Scene;

pub fn run(
    args: &Args,
    scene: &Scene,
    name: String,
    top: HeavyTop,
    start: EulerianAngles,
    choice: &Choice,
    sampling: &Sampling<f64>,
) -> Result<String, CliError> {
    let problem = top
        .problem(&start)
        .map_err(|source| located(scene, name.clone(), source))?;
    let limits =
        nutation_limits(&top, &start).map_err(|source| located(scene, name.clone(), source))?;
    turns_countable(&limits, sampling)?;
    #[cfg(feature = "plot")]
    let mut plot = args
        .plot
        .as_ref()
        .map(|path| super::plot::TopPlot::new(path, sampling));
    let mut rows = SampleRows::new(
        std::io::BufWriter::new(std::io::stdout().lock()),
        args.format,
        "t,theta,phi,psi,thetadot,phidot,psidot",
    );
    let mut along =
        AnglesAlongMotion::starting_at(start, 0.0, limits.phi_dot_band, limits.psi_dot_band);
    let mut sink = |s: Sample<f64>| {
        let a = along.next(s.t, &s.orientation, &s.omega);
        rows.push(&[
            s.t,
            a.theta,
            a.phi,
            a.psi,
            a.theta_dot,
            a.phi_dot,
            a.psi_dot,
        ]);
        #[cfg(feature = "plot")]
        if let Some(plot) = &mut plot {
            plot.add(s.t, &a);
        }
    };
    let (statistics, used) = super::progress::with_bar(|progress| {
        simulate_choice(&problem, choice, sampling, &mut sink, progress)
    })
    .map_err(|source| located(scene, name, source))?;
    rows.finish()?;
    #[cfg(feature = "plot")]
    if let Some(plot) = plot {
        plot.draw().map_err(CliError::Plot)?;
    }
    // The angles in full, to set beside the samples; the constants in four figures, in the
    // scene's unit system.
    let energy = scene.unit_system.unit(Dimension::MOMENT, true);
    let momentum = scene.unit_system.unit(Dimension::new(1, 2, -1), false);
    eprintln!(
        "nutation between theta = {:.10} and {:.10} deg (the roots of the energy cubic: \
         E = {} {energy}, p_phi = {} {momentum}, omega_z = {} rad/s)",
        limits.theta_min.to_degrees(),
        limits.theta_max.to_degrees(),
        four_significant_figures(limits.energy),
        four_significant_figures(limits.vertical_momentum),
        four_significant_figures(limits.spin),
    );
    eprintln!(
        "{} samples; method: {}",
        statistics.samples,
        method_report(&statistics, used)
    );
    Ok(String::new())
}

/// Refuses a sampling too coarse for φ and ψ to count their turns (see the module).
fn turns_countable(limits: &NutationLimits, sampling: &Sampling<f64>) -> Result<(), CliError> {
    let (Some(phi), Some(psi)) = (limits.phi_dot_band, limits.psi_dot_band) else {
        eprintln!(
            "note: the axis reaches the vertical, where φ̇ has no bound: φ and ψ count their \
             turns from the rates at the samples, which needs samples closer than a turn"
        );
        return Ok(());
    };
    let gap = match sampling {
        Sampling::Every { interval, .. } => *interval,
        Sampling::Times(times) => times
            .iter()
            .scan(0.0, |before, &t| Some(t - std::mem::replace(before, t)))
            .fold(0.0, f64::max),
    };
    let width = (phi.1 - phi.0).max(psi.1 - psi.0);
    if width * gap > std::f64::consts::PI {
        // A band's end within round-off of zero (a top released with φ̇ = 0) reads as 0.
        let shown = |x: f64| four_significant_figures(if x.abs() < 1e-9 * width { 0.0 } else { x });
        return Err(CliError::Usage(format!(
            "samples {gap} s apart are too far apart to count the turns of phi and psi: over \
             the nutation phidot ranges over [{}, {}] and psidot over [{}, {}] rad/s; sample at \
             most every {} s",
            shown(phi.0),
            shown(phi.1),
            shown(psi.0),
            shown(psi.1),
            four_significant_figures(std::f64::consts::PI / width)
        )));
    }
    Ok(())
}
