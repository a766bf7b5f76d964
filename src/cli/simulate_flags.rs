//! The numbers given to `kinetics simulate`'s flags, each checked by the flag's name before
//! the scene is read or anything is written: `--until`, `--every`, `--rtol` and `--step`
//! finite and positive; `--at` finite, not negative, strictly increasing; and at most
//! [`MAX_SAMPLES`] samples, `⌊until/every⌋ + 1` of them, unless `--force`.

use super::error::CliError;
use kinetics::numeric::rigid_body::simulate::Sampling;

/// Most samples written without `--force`: ten million rows are about 2 GB of CSV.
pub const MAX_SAMPLES: usize = 10_000_000;

/// `value` as the user would write it: `1e9`, `0.5`, `-5`.
pub fn written(value: f64) -> String {
    let plain = value.to_string();
    let scientific = format!("{value:e}");
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}

/// The value of `flag`, refused unless finite and positive.
pub fn positive(flag: &str, value: f64) -> Result<f64, CliError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(CliError::Usage(format!(
            "{flag} {}: it must be a finite positive number",
            written(value)
        )))
    }
}

/// The sample times asked for by `--until` (with `--every`, default `until/100`) or `--at`,
/// starting at t = 0.
pub fn sampling(
    until: Option<f64>,
    every: Option<f64>,
    at: Option<&[f64]>,
    force: bool,
) -> Result<Sampling<f64>, CliError> {
    let (sampling, count, flags) = match (at, until) {
        (Some(times), _) => {
            let count = times.len() as f64;
            (Sampling::Times(sample_times(times)?), count, "--at".into())
        }
        (None, Some(until)) => {
            let end = positive("--until", until)?;
            let interval = match every {
                Some(every) => positive("--every", every)?,
                None => end / 100.0,
            };
            // As the simulation counts them: rounding in end/interval keeps `end` itself.
            let count = ((end / interval) * (1.0 + 1e-12)).floor() + 1.0;
            let flags = match every {
                Some(every) => format!("--until {} --every {}", written(end), written(every)),
                None => format!("--until {}", written(end)),
            };
            (Sampling::Every { interval, end }, count, flags)
        }
        (None, None) => return Err(CliError::Usage("give --until T or --at t1,t2,...".into())),
    };
    if count > MAX_SAMPLES as f64 && !force {
        return Err(CliError::Usage(format!(
            "{flags} would write {count:.0} samples, more than {MAX_SAMPLES}; pass --force to \
             write them all, or sample less often"
        )));
    }
    Ok(sampling)
}

/// The times of `--at`: finite, none before the start t = 0, strictly increasing.
fn sample_times(times: &[f64]) -> Result<Vec<f64>, CliError> {
    let refuse = |reason: String| Err(CliError::Usage(format!("--at: {reason}")));
    if times.is_empty() {
        return refuse("no times given".into());
    }
    for (k, &t) in times.iter().enumerate() {
        if !t.is_finite() || t < 0.0 {
            return refuse(format!(
                "time number {} is {}; each time must be finite and not negative (the \
                 simulation starts at t = 0)",
                k + 1,
                written(t)
            ));
        }
    }
    if let Some(k) = times.windows(2).position(|w| w[1] <= w[0]) {
        return refuse(format!(
            "time number {} ({}) is not after {}; the times must be strictly increasing",
            k + 2,
            written(times[k + 1]),
            written(times[k])
        ));
    }
    Ok(times.to_vec())
}

#[cfg(test)]
mod tests {
    use super::MAX_SAMPLES;

    /// The cap is written out in `--every`'s and `--force`'s help; it must stay the cap.
    #[test]
    fn the_help_states_the_cap() {
        let command = clap::Command::new("simulate");
        let mut command = <super::super::simulate::Args as clap::Args>::augment_args(command);
        let help = command.render_long_help().to_string();
        let cap = MAX_SAMPLES.to_string();
        assert_eq!(help.matches(&cap).count(), 2, "{help}");
    }
}
