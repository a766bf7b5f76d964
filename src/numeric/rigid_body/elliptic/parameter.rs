//! The parameter `m = k²` of the elliptic functions and integrals, `0 ≤ m ≤ 1`, carried as
//! the pair `(m, m' = 1 − m)` so that `Δ² = 1 − m sin²φ` can be formed as `cos²φ + m' sin²φ`,
//! a sum of non-negative terms: nothing cancels as `m → 1` when `m'` is given directly.

use crate::numeric::error::NumericError;

/// The parameter `m = k²` of the elliptic functions with its complement `m' = 1 − m`,
/// each known to full relative precision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticParameter {
    m: f64,
    mc: f64,
}

impl EllipticParameter {
    /// The parameter `m` in `[0, 1]`.
    pub fn new(m: f64) -> Result<Self, NumericError> {
        Self::check(m, "parameter m")?;
        Ok(Self { m, mc: 1.0 - m })
    }

    /// The parameter given by its complement `m' = 1 − m` in `[0, 1]` (use this when m is
    /// close to 1: `m'` then keeps its digits).
    pub fn from_complement(mc: f64) -> Result<Self, NumericError> {
        Self::check(mc, "complementary parameter m'")?;
        Ok(Self { m: 1.0 - mc, mc })
    }

    fn check(value: f64, what: &str) -> Result<(), NumericError> {
        if value.is_finite() && (0.0..=1.0).contains(&value) {
            Ok(())
        } else {
            Err(NumericError::InvalidInput {
                what: what.to_string(),
                reason: format!("{value} is not in [0, 1]"),
            })
        }
    }

    /// `m`.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// `m' = 1 − m`.
    pub fn complement(&self) -> f64 {
        self.mc
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn out_of_range_parameter_is_an_error() {
        assert!(EllipticParameter::new(1.5).is_err());
        assert!(EllipticParameter::new(f64::NAN).is_err());
        assert!(EllipticParameter::from_complement(-1e-3).is_err());
    }
}
