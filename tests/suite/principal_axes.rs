//! Principal axes of numeric inertia tensors: reconstruction, proper orthonormal frames,
//! ascending moments, nearly equal and equal moments.

use kinetics::mechanics::principal_axes::{principal_axes, PrincipalAxes};
use kinetics::mechanics::validation::PhysicsError;
use nalgebra::{Matrix3, Rotation3, Vector3};
use proptest::prelude::*;

fn rotated_tensor(moments: Vector3<f64>, rotation: &Rotation3<f64>) -> Matrix3<f64> {
    let r = rotation.matrix();
    r * Matrix3::from_diagonal(&moments) * r.transpose()
}

/// Largest deviation of `RᵀR` from the identity.
fn orthonormality_error(axes: &PrincipalAxes) -> f64 {
    let r = axes.rotation.matrix();
    (r.transpose() * r - Matrix3::identity()).amax()
}

/// Largest entry of `R diag Rᵀ − tensor` relative to the largest entry of the tensor.
fn reconstruction_error(axes: &PrincipalAxes, tensor: &Matrix3<f64>) -> f64 {
    (rotated_tensor(axes.moments, &axes.rotation) - tensor).amax() / tensor.amax()
}

fn some_rotation() -> Rotation3<f64> {
    Rotation3::from_scaled_axis(Vector3::new(0.3, -1.1, 0.7))
}

#[test]
fn diagonal_tensor_is_answered_exactly_with_a_proper_permutation() {
    let sorted = Matrix3::from_diagonal(&Vector3::new(1.5, 2.0, 3.25));
    let axes = principal_axes(&sorted).unwrap();
    assert_eq!(axes.moments, Vector3::new(1.5, 2.0, 3.25));
    assert_eq!(axes.rotation, Rotation3::identity());

    // z, x, y = 1, 2, 3 is an even permutation; x, z, y = 1, 3, 2 is odd and needs a flip.
    for diagonal in [Vector3::new(2.0, 3.0, 1.0), Vector3::new(1.0, 3.0, 2.0)] {
        let tensor = Matrix3::from_diagonal(&diagonal);
        let axes = principal_axes(&tensor).unwrap();
        assert_eq!(axes.moments, Vector3::new(1.0, 2.0, 3.0));
        assert_eq!(axes.rotation.matrix().determinant(), 1.0);
        assert_eq!(rotated_tensor(axes.moments, &axes.rotation), tensor);
    }
}

#[test]
fn products_of_inertia_follow_the_chapter_sign_convention() {
    // I_xy = ∫xy dm = 1 > 0 enters the tensor as −1: mass along the line x = y, so the
    // small moment belongs to the axis (1, 1, 0)/√2.
    let tensor = Matrix3::new(2.0, -1.0, 0.0, -1.0, 2.0, 0.0, 0.0, 0.0, 4.0);
    let axes = principal_axes(&tensor).unwrap();
    assert!((axes.moments - Vector3::new(1.0, 3.0, 4.0)).amax() < 4.0 * f64::EPSILON * 4.0);
    let small_axis = axes.rotation.matrix().column(0).into_owned();
    let expected = Vector3::new(1.0, 1.0, 0.0).normalize();
    assert!(
        small_axis.dot(&expected).abs() > 1.0 - 1e-15,
        "{small_axis}"
    );
}

#[test]
fn nearly_equal_moments_give_a_proper_orthonormal_frame() {
    let rotation = some_rotation();
    for gap in [1e-6, 1e-9, 1e-12] {
        for moments in [
            Vector3::new(1.0, 1.0 + gap, 1.7),
            Vector3::new(1.0, 1.7, 1.7 * (1.0 + gap)),
            Vector3::new(1.0, 1.0 + gap, 1.0 + 2.0 * gap),
        ] {
            let tensor = rotated_tensor(moments, &rotation);
            let axes = principal_axes(&tensor).unwrap();
            let orthonormality = orthonormality_error(&axes);
            let reconstruction = reconstruction_error(&axes, &tensor);
            assert!(
                orthonormality < 1e-15,
                "gap {gap}: RᵀR − 1 = {orthonormality:e}"
            );
            assert!(
                reconstruction < 1e-12,
                "gap {gap}: reconstruction {reconstruction:e}"
            );
            assert!(axes.rotation.matrix().determinant() > 0.0);
            assert!((axes.moments - moments).amax() < 1e-14, "{}", axes.moments);
        }
    }
}

#[test]
fn axisymmetric_tensor_returns_the_exact_symmetry_axis() {
    for (seed, moments, distinct) in [
        (0.4, Vector3::new(2.0, 2.0, 3.0), 2), // prolate: distinct moment largest
        (-1.3, Vector3::new(1.0, 3.0, 3.0), 0), // oblate: distinct moment smallest
    ] {
        let rotation = Rotation3::from_scaled_axis(Vector3::new(seed, 0.9, -0.5));
        let symmetry_axis = rotation.matrix().column(distinct).into_owned();
        let tensor = rotated_tensor(moments, &rotation);
        let axes = principal_axes(&tensor).unwrap();
        let found = axes.rotation.matrix().column(distinct).into_owned();
        let error = (found - symmetry_axis * found.dot(&symmetry_axis).signum()).amax();
        assert!(error < 1e-15, "symmetry axis off by {error:e}");
        assert!(orthonormality_error(&axes) < 1e-15);
        assert!(reconstruction_error(&axes, &tensor) < 1e-15);
    }
}

#[test]
fn impossible_tensors_are_rejected_with_the_reason() {
    let triangle = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 3.0));
    assert!(matches!(
        principal_axes(&triangle),
        Err(PhysicsError::TriangleInequality { .. })
    ));
    let mut nan = Matrix3::identity();
    nan[(0, 1)] = f64::NAN;
    assert!(matches!(
        principal_axes(&nan),
        Err(PhysicsError::NotFinite { .. })
    ));
    let asymmetric = Matrix3::new(2.0, -0.5, 0.0, 0.5, 2.0, 0.0, 0.0, 0.0, 2.0);
    assert!(matches!(
        principal_axes(&asymmetric),
        Err(PhysicsError::NotSymmetric { .. })
    ));
}

/// Moments of a real body: `I_x = b + c` etc. from non-negative second moments `a, b, c`.
fn body_moments() -> impl Strategy<Value = Vector3<f64>> {
    (0.0..10.0f64, 0.0..10.0f64, 0.01..10.0f64)
        .prop_map(|(a, b, c)| Vector3::new(b + c, a + c, a + b))
        .prop_filter("positive trace", |m| m.min() > 1e-3)
}

proptest! {
    #[test]
    fn random_bodies_in_random_orientations(
        moments in body_moments(),
        axis in prop::array::uniform3(-4.0..4.0f64),
    ) {
        let rotation = Rotation3::from_scaled_axis(Vector3::from(axis));
        let tensor = rotated_tensor(moments, &rotation);
        let axes = principal_axes(&tensor).unwrap();
        let mut sorted = moments;
        sorted.as_mut_slice().sort_by(f64::total_cmp);
        prop_assert!(axes.moments[0] <= axes.moments[1] && axes.moments[1] <= axes.moments[2]);
        prop_assert!((axes.moments - sorted).amax() <= 1e-13 * sorted.amax());
        prop_assert!(orthonormality_error(&axes) < 1e-15);
        prop_assert!((axes.rotation.matrix().determinant() - 1.0).abs() < 1e-15);
        prop_assert!(reconstruction_error(&axes, &tensor) < 1e-13);
    }
}

proptest! {
    /// Two equal moments in a random orientation: the distinct moment's axis is the
    /// symmetry axis to round-off (the rounded input tensor already moves it by a few ε
    /// divided by the relative gap between the moments).
    #[test]
    fn random_axisymmetric_bodies_keep_their_symmetry_axis(
        equal in 0.5..3.0f64,
        ratio in prop_oneof![0.55..0.95f64, 1.05..1.9f64],
        axis in prop::array::uniform3(-4.0..4.0f64),
    ) {
        let distinct = equal * ratio;
        let rotation = Rotation3::from_scaled_axis(Vector3::from(axis));
        let tensor = rotated_tensor(Vector3::new(equal, equal, distinct), &rotation);
        let axes = principal_axes(&tensor).unwrap();
        // Ascending order puts the distinct moment first (oblate) or last (prolate).
        let column = if distinct < equal { 0 } else { 2 };
        let symmetry_axis = rotation.matrix().column(2).into_owned();
        let found = axes.rotation.matrix().column(column).into_owned();
        let error = (found - symmetry_axis * found.dot(&symmetry_axis).signum()).amax();
        // Rounding the tensor (|ΔI| ~ ε |I|) tilts the axis by ~ ε |I| / gap.
        let bound = 50.0 * f64::EPSILON * equal.max(distinct) / (distinct - equal).abs();
        prop_assert!(error < bound, "symmetry axis off by {:e} > {:e}", error, bound);
        prop_assert!((axes.moments[column] - distinct).abs() < 1e-14 * equal);
        prop_assert!(orthonormality_error(&axes) < 1e-15);
    }
}
