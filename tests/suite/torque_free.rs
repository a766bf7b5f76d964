//! Exact torque-free motion (`TorqueFree`) against the double-double Taylor reference
//! (`ReferenceMotion`), and its invariants, scaling, axis-order covariance and input checks.
//!
//! Bounds: ω is compared component-wise (absolute, |ω| ~ 1), the orientation by the angle of
//! the rotation `q_exact⁻¹ q_reference`.

use kinetics::mechanics::validation::PhysicsError;
use kinetics::numeric::integrators::reference::ReferenceMotion;
use kinetics::numeric::rigid_body::torque_free::{Regime, TorqueFree};
use kinetics::numeric::NumericError;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

fn start_orientation() -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(0.3, -0.7, 1.1)
}

fn exact(moments: [f64; 3], omega0: [f64; 3]) -> TorqueFree {
    TorqueFree::new(
        Vector3::from(moments),
        Vector3::from(omega0),
        start_orientation(),
    )
    .unwrap()
}

/// Asserts that the exact motion matches the reference at `times` within `omega_bound`
/// (absolute, largest component) and `angle_bound` (radians).
fn assert_matches_reference(
    moments: [f64; 3],
    omega0: [f64; 3],
    times: &[f64],
    omega_bound: f64,
    angle_bound: f64,
) {
    let motion = exact(moments, omega0);
    let mut reference = ReferenceMotion::new(
        Vector3::from(moments),
        Vector3::from(omega0),
        start_orientation(),
    )
    .unwrap();
    for &t in times {
        let truth = reference.advance_to(t).unwrap();
        let omega_error = (motion.omega(t) - truth.omega).amax();
        let angle_error = motion.orientation(t).angle_to(&truth.orientation);
        assert!(
            omega_error < omega_bound,
            "I={moments:?} ω₀={omega0:?} t={t}: ω error {omega_error:e}"
        );
        assert!(
            angle_error < angle_bound,
            "I={moments:?} ω₀={omega0:?} t={t}: orientation error {angle_error:e}"
        );
    }
}

const LONG_TIMES: [f64; 4] = [0.5, 10.0, 100.0, 1000.0];

#[test]
fn generic_body_matches_the_reference_to_1e13_up_to_t_1000() {
    let (moments, omega0) = ([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]);
    assert_eq!(exact(moments, omega0).regime(), Regime::AroundLargestMoment);
    assert_matches_reference(moments, omega0, &LONG_TIMES, 1e-13, 1e-13);
}

#[test]
fn near_symmetric_body_matches_the_reference_to_1e13_up_to_t_1000() {
    let (moments, omega0) = ([1.0, 1.0 + 1e-9, 2.0], [1.0, 1.0, 1.0]);
    assert_eq!(exact(moments, omega0).regime(), Regime::AroundLargestMoment);
    assert_matches_reference(moments, omega0, &LONG_TIMES, 1e-13, 1e-13);
}

#[test]
fn start_near_the_intermediate_axis_reaches_1e10_at_t_100() {
    // Close to the separatrix: m' ≈ 1e-6, the period is long and the phase is sensitive.
    assert_matches_reference(
        [1.0, 2.0, 3.0],
        [1e-3, 1.0, 1e-3],
        &[30.0, 100.0],
        1e-10,
        1e-10,
    );
}

#[test]
fn start_within_1e9_of_the_intermediate_axis_stays_accurate() {
    // m' = 2e-18: m rounds to 1 in f64, the phase and Π are carried by m' and (sn, cn, dn).
    let (moments, omega0) = ([1.0, 2.0, 3.0], [1e-9, 1.0, 1e-9]);
    assert_eq!(exact(moments, omega0).regime(), Regime::AroundLargestMoment);
    assert_matches_reference(moments, omega0, &[0.5, 10.0, 100.0], 1e-13, 1e-12);
}

#[test]
fn components_beyond_double_precision_range_are_dropped_not_turned_into_nan() {
    // 1e-200 next to 1 squares to 1e-400: taken as zero, so this is steady spin about the
    // intermediate axis.
    let motion = exact([1.0, 2.0, 3.0], [0.0, 1.0, 1e-200]);
    assert_eq!(motion.regime(), Regime::PrincipalAxis);
    assert_eq!(motion.omega(50.0), Vector3::new(0.0, 1.0, 0.0));
    let q = motion.orientation(50.0);
    let expected = start_orientation() * UnitQuaternion::from_euler_angles(0.0, 50.0, 0.0);
    assert!(q.angle_to(&expected) < 1e-13);
}

#[test]
fn polhode_around_the_smallest_moment_matches_the_reference() {
    let (moments, omega0) = ([1.0, 2.0, 3.0], [1.0, -0.1, 0.1]);
    assert_eq!(
        exact(moments, omega0).regime(),
        Regime::AroundSmallestMoment
    );
    assert_matches_reference(moments, omega0, &[3.0, 50.0, 300.0], 1e-13, 1e-13);
    // The moments listed in another order, the polhode still about the smallest one.
    let (moments, omega0) = ([2.5, 0.5, 2.0], [0.05, -2.0, 0.1]);
    assert_eq!(
        exact(moments, omega0).regime(),
        Regime::AroundSmallestMoment
    );
    assert_matches_reference(moments, omega0, &[3.0, 50.0], 1e-13, 1e-13);
}

#[test]
fn polhode_around_the_largest_moment_with_negative_components() {
    let (moments, omega0) = ([3.0, 1.0, 2.0], [-0.8, 0.4, -0.3]);
    assert_eq!(exact(moments, omega0).regime(), Regime::AroundLargestMoment);
    assert_matches_reference(moments, omega0, &[3.0, 50.0], 1e-13, 1e-13);
}

#[test]
fn separatrix_matches_the_reference_and_tends_to_the_intermediate_axis() {
    // I = (3, 4, 6), ω₀ = (2, ω₂, 1): I₃(I₃−I₂)ω₃² = 12 = I₁(I₂−I₁)ω₁², so H² = 2T I₂ exactly.
    for omega0 in [[2.0, 0.5, 1.0], [-2.0, 0.5, 1.0], [2.0, -0.5, -1.0]] {
        let moments = [3.0, 4.0, 6.0];
        let motion = exact(moments, omega0);
        assert_eq!(motion.regime(), Regime::Separatrix);
        // The reference leaves the separatrix once e^{pt}·1e-32 grows, so compare early.
        assert_matches_reference(moments, omega0, &[1.0, 5.0, 20.0], 1e-13, 1e-13);
        let w0 = Vector3::from(omega0);
        let inertia = Vector3::from(moments);
        let momentum = inertia.component_mul(&w0).norm();
        let late = motion.omega(200.0);
        assert!(late.x.abs() < 1e-30 && late.z.abs() < 1e-30, "{late:?}");
        assert!((late.y.abs() - momentum / 4.0).abs() < 1e-14);
    }
}

#[test]
fn axisymmetric_and_spherical_bodies_match_the_reference() {
    let (moments, omega0) = ([1.0, 2.0, 1.0], [0.7, -0.4, 1.2]);
    assert_eq!(exact(moments, omega0).regime(), Regime::Axisymmetric);
    assert_matches_reference(moments, omega0, &[0.5, 10.0, 1000.0], 1e-13, 1e-13);
    // Thin disc, I_axial = 2 I_t (the triangle inequality's edge).
    let (moments, omega0) = ([2.0, 1.0, 1.0], [0.3, 0.9, -0.5]);
    assert_eq!(exact(moments, omega0).regime(), Regime::Axisymmetric);
    assert_matches_reference(moments, omega0, &[0.5, 100.0], 1e-13, 1e-13);
    let (moments, omega0) = ([2.0, 2.0, 2.0], [0.3, 0.9, -0.5]);
    assert_eq!(exact(moments, omega0).regime(), Regime::Spherical);
    assert_matches_reference(moments, omega0, &[0.5, 100.0], 1e-13, 1e-13);
}

#[test]
fn rest_and_rotation_about_principal_axes() {
    let rest = exact([1.0, 2.0, 3.0], [0.0, 0.0, 0.0]);
    assert_eq!(rest.regime(), Regime::Rest);
    assert_eq!(rest.omega(5.0), Vector3::zeros());
    assert!(rest.orientation(5.0).angle_to(&start_orientation()) < 1e-16);
    // Largest, intermediate (unstable, still an exact steady motion) and smallest axes.
    for omega0 in [[0.0, 0.0, 2.0], [0.0, -1.5, 0.0], [0.5, 0.0, 0.0]] {
        assert_eq!(
            exact([1.0, 2.0, 3.0], omega0).regime(),
            Regime::PrincipalAxis
        );
        assert_matches_reference([1.0, 2.0, 3.0], omega0, &[0.5, 100.0], 1e-13, 1e-13);
    }
    // Any ω in the plane of two equal moments is a principal axis too.
    assert_eq!(
        exact([1.0, 1.0, 2.0], [0.6, -0.8, 0.0]).regime(),
        Regime::PrincipalAxis
    );
}

#[test]
fn extreme_angular_momentum_scales_exactly() {
    // The motion of λω₀ is the motion of ω₀ with time scaled by λ; moments scale out.
    // Powers of two keep the scaled problems exactly the unit one (t/λ is exact), so any
    // difference is the solver's own: |H| is 1e-150, 1e151, 5e-150, 3e150 below.
    let unit = exact([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]);
    let p2 = |e: i32| 2f64.powi(e);
    for (moment_scale, rate_scale) in [
        (1.0, p2(-500)),
        (1.0, p2(500)),
        (p2(-332), p2(-166)),
        (p2(332), p2(166)),
    ] {
        let scaled = exact(
            [moment_scale, 2.0 * moment_scale, 3.0 * moment_scale],
            [rate_scale; 3],
        );
        assert_eq!(scaled.regime(), Regime::AroundLargestMoment);
        let momentum = (14.0f64).sqrt() * moment_scale * rate_scale;
        assert!((1e-152..1e152).contains(&momentum) && !(1e-140..1e140).contains(&momentum));
        for t in [0.5, 10.0, 100.0] {
            let w = scaled.omega(t / rate_scale);
            assert!(w.iter().all(|c| c.is_finite()));
            let expected = unit.omega(t) * rate_scale;
            assert!(
                (w - expected).amax() < 1e-14 * rate_scale,
                "λ={rate_scale:e}: {w:?} vs {expected:?}"
            );
            let angle = scaled
                .orientation(t / rate_scale)
                .angle_to(&unit.orientation(t));
            assert!(angle < 1e-13, "λ={rate_scale:e} t={t}: {angle:e}");
        }
    }
}

#[test]
fn negative_times_are_the_motion_with_reversed_spin() {
    // Time reversal: ω̃(t) = −ω(−t), q̃(t) = q(−t) is the motion from −ω₀.
    let cases = [
        ([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]),
        ([1.0, 2.0, 3.0], [1.0, -0.1, 0.1]),
        ([3.0, 4.0, 6.0], [2.0, 0.5, 1.0]),
        ([1.0, 2.0, 1.0], [0.7, -0.4, 1.2]),
    ];
    for (moments, omega0) in cases {
        let forward = exact(moments, omega0);
        let reversed = exact(moments, omega0.map(|w| -w));
        for t in [0.3, 7.0, 120.0] {
            assert!((forward.omega(-t) + reversed.omega(t)).amax() < 1e-14);
            let angle = forward.orientation(-t).angle_to(&reversed.orientation(t));
            assert!(angle < 1e-13, "{moments:?} t={t}: {angle:e}");
        }
    }
}

#[test]
fn energy_and_fixed_angular_momentum_are_conserved() {
    let cases = [
        ([1.0, 2.0, 3.0], [1.0, 1.0, 1.0]),
        ([1.0, 2.0, 3.0], [1e-3, 1.0, 1e-3]),
        ([1.0, 2.0, 3.0], [1.0, -0.1, 0.1]),
        ([3.0, 4.0, 6.0], [2.0, 0.5, 1.0]),
        ([1.0, 2.0, 1.0], [0.7, -0.4, 1.2]),
    ];
    for (moments, omega0) in cases {
        let motion = exact(moments, omega0);
        let inertia = Vector3::from(moments);
        let energy = |w: &Vector3<f64>| 0.5 * w.dot(&inertia.component_mul(w));
        let momentum = |t: f64| {
            let w = motion.omega(t);
            motion.orientation(t) * inertia.component_mul(&w)
        };
        let (t0, h0) = (energy(&motion.omega(0.0)), momentum(0.0));
        for k in 1..=40 {
            let t = 0.015625 * f64::from(k * k * k);
            let w = motion.omega(t);
            assert!((energy(&w) - t0).abs() < 1e-14 * t0, "{moments:?} t={t}: T");
            assert!(
                (momentum(t) - h0).norm() < 1e-14 * h0.norm(),
                "{moments:?} t={t}: H"
            );
        }
    }
}

#[test]
fn impossible_bodies_and_non_finite_input_are_rejected() {
    let q0 = start_orientation();
    let w = Vector3::new(1.0, 1.0, 1.0);
    let build = |i: [f64; 3], w: Vector3<f64>| TorqueFree::new(Vector3::from(i), w, q0);
    assert!(matches!(
        build([1.0, 1.0, 3.0], w),
        Err(NumericError::Physics(
            PhysicsError::TriangleInequality { .. }
        ))
    ));
    assert!(matches!(
        build([-1.0, 2.0, 2.0], w),
        Err(NumericError::Physics(PhysicsError::NegativeMoment { .. }))
    ));
    assert!(matches!(
        build([f64::NAN, 2.0, 2.0], w),
        Err(NumericError::Physics(PhysicsError::NotFinite { .. }))
    ));
    assert!(matches!(
        build([0.0, 2.0, 2.0], w),
        Err(NumericError::InvalidInput { .. })
    ));
    assert!(matches!(
        build([1.0, 2.0, 2.0], Vector3::new(1.0, f64::INFINITY, 0.0)),
        Err(NumericError::InvalidInput { .. })
    ));
    assert!(matches!(
        build([1.0, 2.0, 2.0], Vector3::new(f64::NAN, 0.0, 0.0)),
        Err(NumericError::InvalidInput { .. })
    ));
}

#[test]
fn the_callers_axis_order_does_not_matter() {
    // Relabel the body axes by a signed permutation C with det C = +1 (an odd reordering
    // reverses one axis, else the frame would be left-handed): ω' = Cω, I' permuted,
    // q' = q ⊗ C⁻¹. Then ω'(t) = C ω(t) and q'(t) = q(t) ⊗ C⁻¹.
    let moments = [1.0, 2.0, 3.0];
    let omega0 = Vector3::new(0.3, -1.0, 0.7);
    let original = exact(moments, omega0.into());
    let orders = [
        [0, 1, 2],
        [1, 2, 0],
        [2, 0, 1],
        [1, 0, 2],
        [0, 2, 1],
        [2, 1, 0],
    ];
    for (n, order) in orders.iter().enumerate() {
        let mut c = Matrix3::zeros();
        for (new_axis, &old_axis) in order.iter().enumerate() {
            c[(new_axis, old_axis)] = if n >= 3 && new_axis == 0 { -1.0 } else { 1.0 };
        }
        let c_rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(c));
        let relabelled = TorqueFree::new(
            Vector3::from(order.map(|k| moments[k])),
            c * omega0,
            start_orientation() * c_rotation.inverse(),
        )
        .unwrap();
        assert_eq!(relabelled.regime(), original.regime());
        for t in [0.7, 25.0, 400.0] {
            let expected = c * original.omega(t);
            assert!((relabelled.omega(t) - expected).amax() < 1e-14, "{order:?}");
            let q = original.orientation(t) * c_rotation.inverse();
            assert!(relabelled.orientation(t).angle_to(&q) < 1e-14, "{order:?}");
        }
    }
}
