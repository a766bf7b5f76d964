//! Principal moments and axes of a tensor whose entries are exact rationals (the givens'
//! decimals), with ties decided exactly and the axes to full double precision however close
//! two moments are.
//!
//! The moments are the roots of the characteristic polynomial
//!
//! ```text
//! p(λ) = det(λ1 − [I]) = λ³ + bλ² + cλ + d,   b = −tr[I],  c = Σ principal 2×2 minors,  d = −det[I]
//! Δ = 18bcd − 4b³d + b²c² − 4c³ − 27d²
//! ```
//!
//! a symmetric tensor's roots are real, and two are equal exactly when the discriminant `Δ`
//! is zero: then the double root is `(9d − bc)/(2(b² − 3c))` and the simple one
//! `(4bc − 9d − b³)/(b² − 3c)` (all three equal when `b² = 3c`), rationals both. When `Δ ≠ 0`
//! the moments are distinct, however close: each is refined from its double-precision value
//! by Newton's method in exact arithmetic (rounded to 2⁻¹²⁸ of the tensor's size a step,
//! so the numbers stay short), and its axis is the null vector of `[I] − λ1`, the largest
//! cross product of two of its rows, computed exactly. An axis found in double precision is
//! off by about `ε/gap` (1e-3 for moments 1e-13 apart); these are off by `2⁻¹²⁸/gap`.

use super::principal_axes::orthonormal_complement;
use nalgebra::Vector3;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A symmetric 3 × 3 matrix of exact rationals.
pub(super) type ExactMatrix = [[BigRational; 3]; 3];

/// The frame found: moments ascending, axes right-handed, and which neighbours are equal
/// (`equal[k]`: moment k + 1 equals moment k + 2, counting from 1).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct ExactFrame {
    pub moments: [f64; 3],
    pub axes: [Vector3<f64>; 3],
    pub equal: [bool; 2],
}

/// Bits kept below the tensor's size at each Newton step.
const PRECISION_BITS: u64 = 128;
/// Newton steps from a double-precision start: 53 bits doubling past 128.
const NEWTON_STEPS: usize = 4;

/// The principal frame of the exact tensor `m`, starting from the double-precision moments
/// `approximate` (ascending). `None` when the refined moments do not separate (a start too
/// far from its root for Newton's method), for the caller's double-precision frame.
pub(super) fn rational_frame(m: &ExactMatrix, approximate: [f64; 3]) -> Option<ExactFrame> {
    let b = -(&m[0][0] + &m[1][1] + &m[2][2]);
    let c = &m[0][0] * &m[1][1] + &m[0][0] * &m[2][2] + &m[1][1] * &m[2][2]
        - &m[0][1] * &m[0][1]
        - &m[0][2] * &m[0][2]
        - &m[1][2] * &m[1][2];
    let d = -determinant(m);
    let int = |n: i64| BigRational::from_integer(BigInt::from(n));
    let discriminant = int(18) * &b * &c * &d - int(4) * &b * &b * &b * &d + &b * &b * &c * &c
        - int(4) * &c * &c * &c
        - int(27) * &d * &d;
    if discriminant.is_zero() {
        return Some(repeated_roots(m, &b, &c, &d));
    }
    let scale = m
        .iter()
        .flatten()
        .map(|x| x.abs())
        .max()
        .unwrap_or_else(BigRational::one);
    let quantum = dyadic_quantum(&scale);
    let roots = approximate.map(|x| refine_root(&b, &c, &d, x, &quantum));
    let roots = roots.into_iter().collect::<Option<Vec<_>>>()?;
    if roots[0] >= roots[1] || roots[1] >= roots[2] {
        return None;
    }
    let axes = [0, 1, 2].map(|k| null_vector(m, &roots[k]));
    let [e1, e2, e3] = [axes[0]?, axes[1]?, axes[2]?];
    let e3 = if e1.cross(&e2).dot(&e3) < 0.0 {
        -e3
    } else {
        e3
    };
    Some(ExactFrame {
        moments: [0, 1, 2].map(|k| to_f64(&roots[k])),
        axes: [e1, e2, e3],
        equal: [false, false],
    })
}

/// `Δ = 0`: a double root (or a triple one), rational.
fn repeated_roots(
    m: &ExactMatrix,
    b: &BigRational,
    c: &BigRational,
    d: &BigRational,
) -> ExactFrame {
    let int = |n: i64| BigRational::from_integer(BigInt::from(n));
    let spread = b * b - int(3) * c;
    if spread.is_zero() {
        let moment = to_f64(&(-b / int(3)));
        return ExactFrame {
            moments: [moment; 3],
            axes: [0, 1, 2].map(|k| Vector3::ith(k, 1.0)),
            equal: [true, true],
        };
    }
    let double = (int(9) * d - b * c) / (int(2) * &spread);
    let simple = (int(4) * b * c - int(9) * d - b * b * b) / &spread;
    // The simple root's axis is exact up to its last rounding; the plane normal to it is
    // the double root's, any pair in it principal.
    let axis = null_vector(m, &simple).unwrap_or_else(|| Vector3::ith(2, 1.0));
    let (u, w) = orthonormal_complement(&axis);
    let below = simple < double;
    let (double, simple) = (to_f64(&double), to_f64(&simple));
    if below {
        ExactFrame {
            moments: [simple, double, double],
            axes: [axis, u, w],
            equal: [false, true],
        }
    } else {
        ExactFrame {
            moments: [double, double, simple],
            axes: [u, w, axis],
            equal: [true, false],
        }
    }
}

fn determinant(m: &ExactMatrix) -> BigRational {
    &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
        - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
        + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0])
}

/// `2⁻ᵏ` with `k` such that it is about `2⁻¹²⁸` of `scale`.
fn dyadic_quantum(scale: &BigRational) -> BigRational {
    let exponent = scale.to_f64().map_or(0, |s| s.log2().floor() as i64);
    let shift = PRECISION_BITS as i64 - exponent;
    let two = BigRational::from_integer(BigInt::from(2));
    if shift >= 0 {
        BigRational::one() / num_traits::pow(two, shift as usize)
    } else {
        num_traits::pow(two, (-shift) as usize)
    }
}

/// A root of `λ³ + bλ² + cλ + d` by Newton's method from `start`, each iterate rounded to a
/// multiple of `quantum`; `None` for a start that is not finite or a zero derivative.
fn refine_root(
    b: &BigRational,
    c: &BigRational,
    d: &BigRational,
    start: f64,
    quantum: &BigRational,
) -> Option<BigRational> {
    let mut x = BigRational::from_float(start)?;
    let int = |n: i64| BigRational::from_integer(BigInt::from(n));
    for _ in 0..NEWTON_STEPS {
        let value = ((&x + b) * &x + c) * &x + d;
        let slope = (int(3) * &x + int(2) * b) * &x + c;
        if slope.is_zero() {
            return None;
        }
        let next = &x - value / slope;
        x = (next / quantum).round() * quantum;
    }
    Some(x)
}

/// The unit null vector of `m − λ1`: its largest cross product of two rows, normalised in
/// double precision after the exact products. `None` when every product vanishes.
fn null_vector(m: &ExactMatrix, lambda: &BigRational) -> Option<Vector3<f64>> {
    let row = |r: usize| -> [BigRational; 3] {
        [0, 1, 2].map(|k| {
            if k == r {
                &m[r][k] - lambda
            } else {
                m[r][k].clone()
            }
        })
    };
    let rows = [row(0), row(1), row(2)];
    let cross = |a: &[BigRational; 3], b: &[BigRational; 3]| {
        [
            &a[1] * &b[2] - &a[2] * &b[1],
            &a[2] * &b[0] - &a[0] * &b[2],
            &a[0] * &b[1] - &a[1] * &b[0],
        ]
    };
    let norm_squared = |v: &[BigRational; 3]| v.iter().map(|x| x * x).sum::<BigRational>();
    let largest = [(0, 1), (0, 2), (1, 2)]
        .map(|(a, b)| cross(&rows[a], &rows[b]))
        .into_iter()
        .max_by(|a, b| norm_squared(a).cmp(&norm_squared(b)))?;
    let biggest = largest.iter().map(|x| x.abs()).max()?;
    if biggest.is_zero() {
        return None;
    }
    Some(Vector3::from(largest.map(|x| to_f64(&(x / &biggest)))).normalize())
}

fn to_f64(x: &BigRational) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}
