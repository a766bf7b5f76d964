//! Independent numeric checks of the derivations, on random point-mass clouds: `H` equals
//! `Σ r × (ω × r) m`, `T` equals `½ Σ m |v|²`, the parallel-axis products equal the direct
//! sums, and `Ḣ` from Euler's equations equals a finite-difference derivative of `H` along a
//! numerically rotated body.

use kinetics::algebra::{Expr, Symbol, Vector};
use kinetics::mechanics::angular_momentum::{angular_momentum, angular_momentum_about_point};
use kinetics::mechanics::euler::euler_equations;
use kinetics::mechanics::inertia::InertiaTensor;
use kinetics::mechanics::kinetic_energy::kinetic_energy;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use proptest::prelude::*;

type V3 = Vector3<f64>;

/// Point masses as (mass, position from the mass centre).
fn cloud() -> impl Strategy<Value = Vec<(f64, V3)>> {
    prop::collection::vec(
        (0.1f64..3.0, -2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0),
        3..9,
    )
    .prop_map(|pts| {
        let total: f64 = pts.iter().map(|p| p.0).sum();
        let centre: V3 = pts.iter().map(|p| V3::new(p.1, p.2, p.3) * p.0).sum::<V3>() / total;
        pts.iter()
            .map(|p| (p.0, V3::new(p.1, p.2, p.3) - centre))
            .collect()
    })
}

fn vec3() -> impl Strategy<Value = V3> {
    (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0).prop_map(|(x, y, z)| V3::new(x, y, z))
}

/// The chapter's components by direct sums: `I_x = Σ m (y² + z²)`, `I_xy = Σ m x y`, ...
fn components(points: &[(f64, V3)]) -> [(&'static str, f64); 6] {
    let s = |f: &dyn Fn(&V3) -> f64| points.iter().map(|(m, r)| m * f(r)).sum::<f64>();
    [
        ("I_x", s(&|r| r.y * r.y + r.z * r.z)),
        ("I_y", s(&|r| r.z * r.z + r.x * r.x)),
        ("I_z", s(&|r| r.x * r.x + r.y * r.y)),
        ("I_xy", s(&|r| r.x * r.y)),
        ("I_yz", s(&|r| r.y * r.z)),
        ("I_xz", s(&|r| r.x * r.z)),
    ]
}

fn values(pairs: Vec<(String, f64)>) -> impl Fn(Symbol) -> Option<f64> {
    move |s: Symbol| {
        pairs
            .iter()
            .find(|(n, _)| Symbol::new(n) == s)
            .map(|(_, v)| *v)
    }
}

fn with_omega(points: &[(f64, V3)], w: &V3, extra: &[(&str, f64)]) -> Vec<(String, f64)> {
    let mut pairs: Vec<(String, f64)> = components(points)
        .iter()
        .map(|(n, v)| (n.to_string(), *v))
        .collect();
    pairs.extend([("w_x", w.x), ("w_y", w.y), ("w_z", w.z)].map(|(n, v)| (n.to_string(), v)));
    pairs.extend(extra.iter().map(|(n, v)| (n.to_string(), *v)));
    pairs
}

fn result_vector(d: &kinetics::mechanics::Derivation, value: &dyn Fn(Symbol) -> Option<f64>) -> V3 {
    let r = d.result();
    V3::new(
        r[0].rhs.eval(value).unwrap(),
        r[1].rhs.eval(value).unwrap(),
        r[2].rhs.eval(value).unwrap(),
    )
}

fn close(a: &V3, b: &V3, scale: f64) -> bool {
    (a - b).norm() <= 1e-9 * scale.max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn angular_momentum_is_the_sum_over_particles(points in cloud(), w in vec3()) {
        let d = angular_momentum(&InertiaTensor::general(), &kinetics::mechanics::euler::body_angular_velocity(), "G").unwrap();
        let value = values(with_omega(&points, &w, &[]));
        let derived = result_vector(&d, &value);
        let direct: V3 = points.iter().map(|(m, r)| r.cross(&w.cross(r)) * *m).sum();
        prop_assert!(close(&derived, &direct, direct.norm()), "{derived} vs {direct}");
    }

    #[test]
    fn kinetic_energy_and_h_about_o_are_sums_over_particles(points in cloud(), w in vec3(), v in vec3(), rbar in vec3()) {
        let m_total: f64 = points.iter().map(|p| p.0).sum();
        let omega = kinetics::mechanics::euler::body_angular_velocity();
        let vbar = Vector::new(Expr::symbol("vbar_x"), Expr::symbol("vbar_y"), Expr::symbol("vbar_z"));
        let rb = Vector::new(Expr::symbol("xbar"), Expr::symbol("ybar"), Expr::symbol("zbar"));
        let m = Expr::symbol("m");
        let extra = [("m", m_total), ("vbar_x", v.x), ("vbar_y", v.y), ("vbar_z", v.z), ("xbar", rbar.x), ("ybar", rbar.y), ("zbar", rbar.z)];
        let value = values(with_omega(&points, &w, &extra));
        let t = kinetic_energy(&InertiaTensor::general(), &omega, Some((&m, &vbar))).unwrap();
        let derived_t: f64 = t.result()[0].rhs.eval(&value).unwrap();
        let direct_t: f64 = points.iter().map(|(mi, r)| 0.5 * mi * (v + w.cross(r)).norm_squared()).sum();
        prop_assert!((derived_t - direct_t).abs() <= 1e-9 * direct_t.max(1.0));
        let h_g = InertiaTensor::general().matrix() * &omega;
        let h_o = angular_momentum_about_point(&h_g, &rb, &m, &vbar).unwrap();
        let derived = result_vector(&h_o, &value);
        let direct: V3 = points.iter().map(|(mi, r)| (rbar + r).cross(&(v + w.cross(r))) * *mi).sum();
        prop_assert!(close(&derived, &direct, direct.norm()));
    }

    #[test]
    fn parallel_axis_products_equal_direct_sums(points in cloud(), offset in vec3()) {
        let m_total: f64 = points.iter().map(|p| p.0).sum();
        let centroidal = components(&points);
        let tensor = InertiaTensor {
            moments: [0, 1, 2].map(|k| Expr::symbol(centroidal[k].0)),
            products: [3, 4, 5].map(|k| Expr::symbol(centroidal[k].0)),
        };
        let rbar = Vector::new(Expr::symbol("xbar"), Expr::symbol("ybar"), Expr::symbol("zbar"));
        let moved = tensor.parallel_axis(&Expr::symbol("m"), &rbar);
        let mut pairs: Vec<(String, f64)> = centroidal.iter().map(|(n, v)| (n.to_string(), *v)).collect();
        pairs.extend([("m", m_total), ("xbar", offset.x), ("ybar", offset.y), ("zbar", offset.z)].map(|(n, v)| (n.to_string(), v)));
        let value = values(pairs);
        let shifted: Vec<(f64, V3)> = points.iter().map(|(mi, r)| (*mi, r + offset)).collect();
        let direct = components(&shifted);
        let derived = moved.moments.iter().chain(moved.products.iter());
        for (e, (name, d)) in derived.zip(direct.iter()) {
            let v: f64 = e.eval(&value).unwrap();
            prop_assert!((v - d).abs() <= 1e-9 * d.abs().max(1.0), "{name}: {v} vs {d}");
        }
    }
}

/// `q̇ = ½ q ⊗ (0, ω)` integrated with many small RK4 steps, for a body-frame angular
/// velocity that changes linearly in time.
fn orientation_at(t: f64, w0: &V3, wdot: &V3) -> UnitQuaternion<f64> {
    let steps = 400;
    let h = t / steps as f64;
    let mut q = Quaternion::identity();
    let f = |tau: f64, q: &Quaternion<f64>| {
        let w = w0 + wdot * tau;
        q * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5
    };
    for i in 0..steps {
        let tau = i as f64 * h;
        let k1 = f(tau, &q);
        let k2 = f(tau + h / 2.0, &(q + k1 * (h / 2.0)));
        let k3 = f(tau + h / 2.0, &(q + k2 * (h / 2.0)));
        let k4 = f(tau + h, &(q + k3 * h));
        q += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
    }
    UnitQuaternion::from_quaternion(q)
}

/// H in the fixed frame at time t: `Σ m R r × R(ω(t) × r)`.
fn fixed_frame_h(points: &[(f64, V3)], t: f64, w0: &V3, wdot: &V3) -> V3 {
    let q = orientation_at(t, w0, wdot);
    let w = w0 + wdot * t;
    points
        .iter()
        .map(|(m, r)| (q * r).cross(&(q * w.cross(r))) * *m)
        .sum()
}

#[test]
fn euler_rate_matches_finite_differences_of_a_rotating_body() {
    let points = [
        (1.0, V3::new(0.3, -0.2, 0.9)),
        (2.0, V3::new(-0.7, 0.4, 0.1)),
        (0.5, V3::new(0.2, 1.1, -0.6)),
        (1.5, V3::new(0.5, -0.8, -0.3)),
    ];
    let total: f64 = points.iter().map(|p| p.0).sum();
    let centre: V3 = points.iter().map(|(m, r)| r * *m).sum::<V3>() / total;
    let points: Vec<(f64, V3)> = points.iter().map(|(m, r)| (*m, r - centre)).collect();
    let (w0, wdot) = (V3::new(0.7, -1.3, 0.4), V3::new(0.25, 0.6, -0.9));
    let euler = euler_equations(&InertiaTensor::general()).unwrap();
    let extra = [("wdot_x", wdot.x), ("wdot_y", wdot.y), ("wdot_z", wdot.z)];
    let value = values(with_omega(&points, &w0, &extra));
    let derived = result_vector(&euler, &value);
    // Five-point central difference at t = 0 (where the body and fixed frames coincide).
    let h = 1e-3;
    let hh = |t: f64| fixed_frame_h(&points, t, &w0, &wdot);
    let numeric = (hh(-2.0 * h) - hh(-h) * 8.0 + hh(h) * 8.0 - hh(2.0 * h)) / (12.0 * h);
    let error = (derived - numeric).norm() / numeric.norm();
    assert!(
        error < 1e-9,
        "relative error {error:e}: {derived} vs {numeric}"
    );
}
