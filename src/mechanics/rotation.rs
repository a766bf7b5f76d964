//! The rotation R that takes a body's own axes x', y', z' to the frame's: a vector's frame
//! components are R times its own (`frame = R · own`), so R's columns are x', y', z'
//! written in the frame, and the body's inertia in the frame is `R [Ī'] Rᵀ`.
//!
//! - About a frame axis by θ (c = cos θ, s = sin θ):
//!   `R_x = [[1, 0, 0], [0, c, −s], [0, s, c]]`, `R_y = [[c, 0, s], [0, 1, 0], [−s, 0, c]]`,
//!   `R_z = [[c, −s, 0], [s, c, 0], [0, 0, 1]]`.
//! - About a direction a (Rodrigues): `n = a/|a|`,
//!   `R = cos θ 1 + sin θ [n]ₓ + (1 − cos θ) n nᵀ`, exact (`(0, 1, 1)` gives `n = (0, 1, 1)/√2`,
//!   √2 kept); a zero direction has no rotation about it.
//! - `along x|y|z`: the own axes relabelled cyclically so that x' lies along the named axis
//!   (`along y`: x' → y, y' → z, z' → x).
//! - A sequence, each about the frame's fixed axis, applied in the order written:
//!   `R = R_k ⋯ R_2 R_1` (after `along`, which comes first).
//! - Direction cosines: `R = [x' y' z']`, accepted when `x'ᵀx' = y'ᵀy' = z'ᵀz' = 1`,
//!   `x'ᵀy' = y'ᵀz' = z'ᵀx' = 0` and `det R = x'·(y' × z') = +1`, each decided exactly (after
//!   expansion and sin² + cos² = 1), else from the symbols' values to [`TOLERANCE`].

use crate::algebra::vector_products::{cross, dot};
use crate::algebra::{Axis, Expr, Func, Matrix, Symbol, Vector};
use std::fmt;

/// How far from its exact value a condition on direction cosines may be when it is decided
/// from the values of its symbols (decimals written to about ten digits pass).
pub const TOLERANCE: f64 = 1e-9;

/// The rotation by `angle` about the frame axis `axis`.
pub fn about_axis(axis: Axis, angle: &Expr) -> Matrix {
    let (c, s) = cos_sin(angle);
    let (z, o) = (Expr::zero, Expr::one);
    match axis {
        Axis::X => Matrix::new(o(), z(), z(), z(), c.clone(), -&s, z(), s, c),
        Axis::Y => Matrix::new(c.clone(), z(), s.clone(), z(), o(), z(), -s, z(), c),
        Axis::Z => Matrix::new(c.clone(), -&s, z(), s, c, z(), z(), z(), o()),
    }
}

/// The rotation by `angle` about the direction `a` (Rodrigues' formula); none when `a` is
/// exactly zero (or when its length cannot be formed).
pub fn about_direction(a: &Vector, angle: &Expr) -> Option<Matrix> {
    let length_squared = dot(a, a).expand().ok()?;
    if length_squared.is_zero() {
        return None;
    }
    let inverse_length = length_squared.checked_pow(&Expr::rational(-1, 2)).ok()?;
    let n = a.map(|component| &component * &inverse_length);
    let (c, s) = cos_sin(angle);
    let versine = Expr::one() - &c;
    let cross_matrix = Matrix::new(
        Expr::zero(),
        -&n[2],
        n[1].clone(),
        n[2].clone(),
        Expr::zero(),
        -&n[0],
        -&n[1],
        n[0].clone(),
        Expr::zero(),
    );
    Some(Matrix::from_fn(|i, j| {
        let diagonal = if i == j { c.clone() } else { Expr::zero() };
        diagonal + &s * &cross_matrix[(i, j)] + &versine * &n[i] * &n[j]
    }))
}

/// `along axis`: the cyclic relabelling that takes x' to `axis` (y' and z' to the next two).
pub fn along(axis: Axis) -> Matrix {
    let (z, o) = (Expr::zero, Expr::one);
    match axis {
        Axis::X => Matrix::identity(),
        Axis::Y => Matrix::new(z(), z(), o(), o(), z(), z(), z(), o(), z()),
        Axis::Z => Matrix::new(z(), o(), z(), z(), z(), o(), o(), z(), z()),
    }
}

fn cos_sin(angle: &Expr) -> (Expr, Expr) {
    (
        Expr::func(Func::Cos, angle.clone()),
        Expr::func(Func::Sin, angle.clone()),
    )
}

/// What keeps three triples of direction cosines from being a rotation.
#[derive(Debug, Clone, PartialEq)]
pub enum AxesProblem {
    /// The axis (0 for x', 1 for y', 2 for z') is not a unit vector: its length squared,
    /// when known.
    NotUnit(usize, Option<f64>),
    /// The two axes are not perpendicular: their scalar product, when known.
    NotPerpendicular(usize, usize, Option<f64>),
    /// The axes are orthonormal but left-handed: `x' × y' = −z'`.
    LeftHanded,
}

impl AxesProblem {
    /// The first axis the problem names (for the place of an error).
    pub fn first_axis(&self) -> Option<usize> {
        match self {
            AxesProblem::NotUnit(k, _) | AxesProblem::NotPerpendicular(k, _, _) => Some(*k),
            AxesProblem::LeftHanded => None,
        }
    }
}

const PRIMED: [&str; 3] = ["x'", "y'", "z'"];

/// The value found, to six decimals; a value that rounds to the one wanted (`target`) is
/// shown by its departure from it (`1 + 1.2e-7`, `8.0e-8`), never as the target itself.
fn known(value: &Option<f64>, target: f64) -> String {
    match value {
        Some(v) => {
            let shown = (v * 1e6).round() / 1e6;
            let departure = v - target;
            match (shown == target, target == 0.0) {
                (false, _) => format!(" {shown}"),
                (true, true) => format!(" {departure:.1e}"),
                (true, false) => {
                    let sign = if departure < 0.0 { '-' } else { '+' };
                    format!(" {target} {sign} {:.1e}", departure.abs())
                }
            }
        }
        None => " not shown to be".to_string(),
    }
}

impl fmt::Display for AxesProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AxesProblem::NotUnit(k, value) => write!(
                f,
                "{} is not a unit vector (its length squared is{} 1)",
                PRIMED[*k],
                match value {
                    Some(_) => format!("{}, not", known(value, 1.0)),
                    None => known(value, 1.0),
                }
            ),
            AxesProblem::NotPerpendicular(a, b, value) => write!(
                f,
                "{} and {} are not perpendicular ({}·{} is{} 0)",
                PRIMED[*a],
                PRIMED[*b],
                PRIMED[*a],
                PRIMED[*b],
                match value {
                    Some(_) => format!("{}, not", known(value, 0.0)),
                    None => known(value, 0.0),
                }
            ),
            AxesProblem::LeftHanded => write!(
                f,
                "x', y', z' are left-handed (x' × y' = -z', the determinant is -1)"
            ),
        }
    }
}

/// The rotation whose columns are the body's axes `axes` (x', y', z' in the frame), or
/// every condition it fails (see the module documentation); `value` gives the symbols'
/// values where the exact route cannot decide.
pub fn from_direction_cosines(
    axes: [Vector; 3],
    value: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<Matrix, Vec<AxesProblem>> {
    let mut problems = Vec::new();
    for (k, axis) in axes.iter().enumerate() {
        let unit = dot(axis, axis) - Expr::one();
        if let Some(off) = off_zero(&unit, value) {
            problems.push(AxesProblem::NotUnit(k, off.map(|d| d + 1.0)));
        }
    }
    for (a, b) in [(0, 1), (1, 2), (2, 0)] {
        if let Some(off) = off_zero(&dot(&axes[a], &axes[b]), value) {
            problems.push(AxesProblem::NotPerpendicular(a, b, off));
        }
    }
    if problems.is_empty() {
        let determinant = dot(&axes[0], &cross(&axes[1], &axes[2]));
        if off_zero(&(determinant - Expr::one()), value).is_some() {
            problems.push(AxesProblem::LeftHanded);
        }
    }
    if !problems.is_empty() {
        return Err(problems);
    }
    let [x, y, z] = axes;
    Ok(Matrix::from_columns(&[x, y, z]))
}

/// None when `q` is zero (exactly, or from the values within [`TOLERANCE`]); else its value
/// when the symbols have values, `Some(None)` when it cannot be decided.
fn off_zero(q: &Expr, value: &dyn Fn(Symbol) -> Option<f64>) -> Option<Option<f64>> {
    let exact = q.expand().and_then(|e| e.simplify_trig());
    if exact.as_ref().is_ok_and(Expr::is_zero) {
        return None;
    }
    match q.eval(value) {
        Ok(v) if v.abs() <= TOLERANCE => None,
        Ok(v) => Some(Some(v)),
        Err(_) => Some(None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rodrigues_about_a_frame_axis_is_the_elementary_rotation() {
        let theta = Expr::symbol("theta");
        for (axis, direction) in [(Axis::X, 0), (Axis::Y, 1), (Axis::Z, 2)] {
            let a = Vector::from_fn(|i, _| Expr::int(i64::from(i == direction) * 3));
            let r = about_direction(&a, &theta).unwrap();
            assert_eq!(r, about_axis(axis, &theta));
        }
        let zero = Vector::from_element(Expr::zero());
        assert_eq!(about_direction(&zero, &theta), None);
    }

    #[test]
    fn direction_cosines_name_each_failure() {
        let v = |x: i64, y: i64, z: i64| Vector::new(Expr::int(x), Expr::int(y), Expr::int(z));
        let none = |_: Symbol| None;
        let r = from_direction_cosines([v(0, 1, 0), v(0, 0, 1), v(1, 0, 0)], &none);
        assert_eq!(r, Ok(along(Axis::Y)));
        let left = from_direction_cosines([v(1, 0, 0), v(0, 1, 0), v(0, 0, -1)], &none);
        assert_eq!(left, Err(vec![AxesProblem::LeftHanded]));
        let bad = from_direction_cosines([v(1, 1, 0), v(0, 1, 0), v(0, 0, 1)], &none);
        assert_eq!(
            bad,
            Err(vec![
                AxesProblem::NotUnit(0, Some(2.0)),
                AxesProblem::NotPerpendicular(0, 1, Some(1.0))
            ])
        );
        assert_eq!(
            AxesProblem::NotUnit(0, Some(2.0)).to_string(),
            "x' is not a unit vector (its length squared is 2, not 1)"
        );
        assert_eq!(
            AxesProblem::NotUnit(2, Some(1.000_000_12)).to_string(),
            "z' is not a unit vector (its length squared is 1 + 1.2e-7, not 1)"
        );
        assert_eq!(
            AxesProblem::NotPerpendicular(1, 2, Some(8e-8)).to_string(),
            "y' and z' are not perpendicular (y'·z' is 8.0e-8, not 0)"
        );
    }
}
