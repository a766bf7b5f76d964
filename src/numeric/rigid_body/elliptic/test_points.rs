//! The points the elliptic tests sample: parameters across `[0, 1]`, with `m'` down to
//! 1e-300 given directly, and arguments around and beyond the quarter period `K`.

use super::legendre_integrals::complete_first_kind;
use super::parameter::EllipticParameter;

/// Parameters from 0 to 0.999 by `m`, and by `m'` down to 1e-300.
pub(super) fn parameters() -> Vec<EllipticParameter> {
    let mut list: Vec<_> = [0.0, 1e-9, 0.1, 0.5, 0.9, 0.999]
        .iter()
        .map(|&m| EllipticParameter::new(m).unwrap())
        .collect();
    list.extend(
        [1e-6, 1e-12, 1e-300]
            .iter()
            .map(|&mc| EllipticParameter::from_complement(mc).unwrap()),
    );
    list
}

/// Arguments: fixed ones up to 40, and fractions and multiples of the quarter period `k`.
pub(super) fn arguments(k: f64) -> Vec<f64> {
    let mut list = vec![0.0, 0.3, -0.7, 1.3, 2.9, -7.5, 40.0];
    list.extend([0.5 * k, k, 1.5 * k, 3.0 * k, -0.9 * k]);
    list
}

/// Every parameter of [`parameters`] with every argument of [`arguments`] around its
/// quarter period (K capped at 30).
pub(super) fn samples() -> Vec<(EllipticParameter, f64)> {
    parameters()
        .into_iter()
        .flat_map(|p| {
            let k = complete_first_kind(p.complement());
            arguments(k.min(30.0)).into_iter().map(move |u| (p, u))
        })
        .collect()
}
