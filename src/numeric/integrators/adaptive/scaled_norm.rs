//! Norms of the error estimates without overflow or underflow: `‖v‖ = m · ‖v/m‖` with `m = maxᵢ |vᵢ|`,
//! so no square leaves the normal range whatever the problem's scale (dividing by a power of
//! two is exact, so a vector scaled by one has its norm scaled exactly).

use nalgebra::{RealField, SVector};

/// The 2-norm of `v` without overflow or underflow: the components are divided by the
/// largest magnitude before squaring (and the norm of a vector scaled by a power of two is
/// scaled exactly). Zero for a zero vector; not finite when a component is not.
pub(in crate::numeric::integrators) fn scaled_norm<T: RealField + Copy, const N: usize>(
    v: &SVector<T, N>,
) -> T {
    let largest = largest_magnitude(v.iter());
    if largest == T::zero() || !largest.is_finite() {
        return largest;
    }
    v.unscale(largest).norm() * largest
}

/// The largest `|vᵢ|`; not finite if a component is not (where a plain maximum would skip
/// a NaN).
pub(in crate::numeric::integrators) fn largest_magnitude<'a, T: RealField + Copy>(
    v: impl Iterator<Item = &'a T>,
) -> T {
    v.fold(T::zero(), |largest, x| {
        let x = x.abs();
        if !largest.is_finite() {
            return largest;
        }
        match x.partial_cmp(&largest) {
            // `None`: x is NaN.
            Some(std::cmp::Ordering::Greater) | None => x,
            _ => largest,
        }
    })
}
