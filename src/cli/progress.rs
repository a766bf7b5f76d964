//! The progress of a long command, on standard error: a bar of the fraction done, or a
//! spinner naming the step under way, cleared when the work ends (indicatif, which draws
//! only on a terminal). Without the `progress` feature the work runs without a display.

/// Runs `work`, showing the fraction done (0 to 1) that it reports as a bar.
#[cfg(feature = "progress")]
pub fn with_bar<R>(work: impl FnOnce(&mut dyn FnMut(f64)) -> R) -> R {
    let bar = indicatif::ProgressBar::new(1000);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{bar:40} {percent:>3}% {elapsed} elapsed, {eta} left",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let result = work(&mut |f| bar.set_position((f * 1000.0) as u64));
    bar.finish_and_clear();
    result
}

/// Runs `work`, showing the step it names as a spinner.
#[cfg(feature = "progress")]
pub fn with_spinner<R>(work: impl FnOnce(&mut dyn FnMut(&str)) -> R) -> R {
    let bar = indicatif::ProgressBar::new_spinner();
    let result = work(&mut |what| {
        bar.set_message(what.to_string());
        bar.tick();
    });
    bar.finish_and_clear();
    result
}

/// Runs `work`; its reports go nowhere.
#[cfg(not(feature = "progress"))]
pub fn with_bar<R>(work: impl FnOnce(&mut dyn FnMut(f64)) -> R) -> R {
    work(&mut |_| {})
}

/// Runs `work`; its reports go nowhere.
#[cfg(not(feature = "progress"))]
pub fn with_spinner<R>(work: impl FnOnce(&mut dyn FnMut(&str)) -> R) -> R {
    work(&mut |_| {})
}
