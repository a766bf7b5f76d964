//! A method's cost of one accuracy: its time at exactly the error `e`, read off its
//! work-precision line between the two settings whose errors bracket `e`, straight in
//! log-log (where such a line is straight: error ∝ time⁻ᵖ for a method of order p):
//!
//! ```text
//! log t(e) = log t₁ + (log e − log e₁) (log t₂ − log t₁) / (log e₂ − log e₁)
//! ```
//!
//! Two methods compared at their fastest settings within `e` are compared at different
//! errors (one may land just under `e`, the other ten times under); at equal error they are
//! compared at the same one.

/// The time at `error` of the runs `points`, each `(error, seconds)`, interpolated between
/// the two whose errors are nearest on either side (in order of error); none when no two
/// bracket it, or a value is not positive and finite.
pub fn time_at(points: &[(f64, f64)], error: f64) -> Option<f64> {
    let usable = |v: f64| v.is_finite() && v > 0.0;
    let mut sorted: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|&(e, t)| usable(e) && usable(t))
        .collect();
    if !usable(error) {
        return None;
    }
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    let pair = sorted
        .windows(2)
        .find(|w| w[0].0 <= error && error <= w[1].0)?;
    let ((e1, t1), (e2, t2)) = (pair[0], pair[1]);
    if e1 == e2 {
        return Some(t1.min(t2));
    }
    let slope = (t2.ln() - t1.ln()) / (e2.ln() - e1.ln());
    Some((t1.ln() + (error.ln() - e1.ln()) * slope).exp())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On an exact power law (error = 1e-3 t⁻⁸) the time read off at any error between two
    /// runs is the law's; outside them there is none.
    #[test]
    fn a_power_law_is_read_back_exactly() {
        let error = |t: f64| 1e-3 * t.powi(-8);
        let points: Vec<(f64, f64)> = [4.0, 10.0, 2.0, 20.0]
            .iter()
            .map(|&t| (error(t), t))
            .collect();
        for t in [2.5, 7.0, 10.0, 13.0] {
            let read = time_at(&points, error(t)).expect("bracketed");
            assert!((read - t).abs() < 1e-12 * t, "{read} against {t}");
        }
        assert_eq!(time_at(&points, error(1.0)), None);
        assert_eq!(time_at(&points, error(30.0)), None);
        assert_eq!(time_at(&points, f64::NAN), None);
    }
}
