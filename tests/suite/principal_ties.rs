//! Ties between principal moments decided exactly (issue 36): with the givens' decimals the
//! tensor is rational, and two moments are one only when the characteristic polynomial's
//! discriminant is zero. Moments 1e-13 apart are three, each with its own axis to full
//! precision; a tensor that is exactly axisymmetric, turned so that no product is zero, is
//! said to be so.
//!
//! The expected axes were computed with mpmath at 60 digits (`mpmath.eigsy` on the same
//! decimals) and are written here; the axisymmetric tensor is `R diag(1, 2, 2) Rᵀ` with `R`
//! two turns of cosine 3/5 (about z, then x), whose first column is the axis `(3/5, 12/25,
//! 16/25)` worked by hand.

// mpmath's digits are kept as printed, past what f64 holds.
#![allow(clippy::excessive_precision)]

use kinetics::algebra::{Domains, Expr, Symbol};
use kinetics::mechanics::principal_frame::{principal_frame, PrincipalFrame};
use kinetics::InertiaTensor;
use nalgebra::Vector3;

/// The tensor of the givens `I_x, I_y, I_z, I_xy, I_yz, I_xz` with these values (the
/// decimals a scene writes), and its principal frame about G.
fn frame_of(moments: [f64; 3], products: [f64; 3]) -> PrincipalFrame {
    let tensor = InertiaTensor::general();
    let values = move |s: Symbol| match s.name() {
        "I_x" => Some(moments[0]),
        "I_y" => Some(moments[1]),
        "I_z" => Some(moments[2]),
        "I_xy" => Some(products[0]),
        "I_yz" => Some(products[1]),
        "I_xz" => Some(products[2]),
        _ => None,
    };
    principal_frame(&tensor, "G", &Domains::chapter_defaults(), &values)
        .unwrap()
        .0
}

fn number(e: &Expr) -> f64 {
    e.eval(&|_| None).unwrap()
}

fn axes(frame: &PrincipalFrame) -> [Vector3<f64>; 3] {
    frame
        .axes
        .clone()
        .map(|e| Vector3::from_fn(|row, _| number(&e[row])))
}

/// The distance between two axes, either sense.
fn apart(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    (a - b).norm().min((a + b).norm())
}

#[test]
fn moments_1e13_apart_have_three_axes_each_to_full_precision() {
    let frame = frame_of(
        [2.0, 2.0000000000001, 3.0],
        [0.00000000000006, 0.00000000000002, 0.00000000000003],
    );
    assert_eq!(frame.remark, None, "moments 5e-14 apart were said equal");
    let moments = frame.moments.each_ref().map(number);
    assert!(
        moments[0] < moments[1] && moments[1] < moments[2],
        "{moments:?}"
    );
    // mpmath, 60 digits: the moments 1.99999999999997189750…, 2.00000000000012810249…, 3.
    let expected = [
        Vector3::new(
            0.905589421223679594,
            0.424155396249724743,
            3.5650790561703881e-14,
        ),
        Vector3::new(
            -0.424155396249724743,
            0.905589421223679594,
            5.3871265369825397e-15,
        ),
        Vector3::new(-2.99999999999988e-14, -2.00000000000002e-14, 1.0),
    ];
    let found = axes(&frame);
    for (k, (e, truth)) in found.iter().zip(&expected).enumerate() {
        assert!(
            apart(e, truth) < 1e-6,
            "e_{}: {e:?} against {truth:?}",
            k + 1
        );
        assert!((e.norm() - 1.0).abs() < 1e-15);
    }
    let handedness = found[0].cross(&found[1]).dot(&found[2]);
    assert!(
        (handedness - 1.0).abs() < 1e-14,
        "e₁ × e₂ · e₃ = {handedness}"
    );
    assert!(found[0].dot(&found[1]).abs() < 1e-14);
}

#[test]
fn an_exactly_axisymmetric_tensor_with_every_product_is_said_to_be_so() {
    let frame = frame_of([1.64, 1.7696, 1.5904], [0.288, 0.3072, 0.384]);
    let remark = frame.remark.as_deref().unwrap_or("");
    assert!(remark.starts_with("$I_2 = I_3$"), "{remark:?}");
    let moments = frame.moments.each_ref().map(number);
    assert_eq!(moments, [1.0, 2.0, 2.0]);
    let e1 = axes(&frame)[0];
    let by_hand = Vector3::new(3.0 / 5.0, 12.0 / 25.0, 16.0 / 25.0);
    assert!(apart(&e1, &by_hand) < 1e-15, "{e1:?}");
}

/// Without products, the moments are compared with the decimals written: 1 and
/// 1.0000000000001 are two, 2 and 2.0 one.
#[test]
fn principal_moments_compared_by_their_decimals() {
    let distinct = frame_of([1.0000000000001, 1.0, 1.5], [0.0; 3]);
    assert_eq!(distinct.remark, None);
    assert_eq!(
        distinct.moments.each_ref().map(number),
        [1.0, 1.0000000000001, 1.5]
    );
    let equal = frame_of([3.0, 2.0, 2.0], [0.0; 3]);
    let remark = equal.remark.as_deref().unwrap_or("");
    assert!(remark.starts_with("$I_1 = I_2$"), "{remark:?}");
}
