//! Cost of the exact torque-free motion: construction (`new`), `omega(t)` and
//! `orientation(t)` per time point, for an asymmetric body (elliptic functions and the
//! third-kind integral) and an axisymmetric one (elementary functions).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::numeric::rigid_body::torque_free::TorqueFree;
use nalgebra::{UnitQuaternion, Vector3};

fn bodies() -> [(&'static str, Vector3<f64>, Vector3<f64>); 2] {
    [
        (
            "asymmetric",
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(1.0, 1.0, 1.0),
        ),
        (
            "axisymmetric",
            Vector3::new(1.0, 1.0, 2.0),
            Vector3::new(0.7, -0.4, 1.2),
        ),
    ]
}

fn torque_free(c: &mut Criterion) {
    let q0 = UnitQuaternion::from_euler_angles(0.3, -0.7, 1.1);
    // Time points spread over many periods, so the reduction is exercised.
    let times: Vec<f64> = (0..64).map(|k| 0.37 * f64::from(k * k)).collect();
    for (name, moments, omega0) in bodies() {
        c.bench_function(&format!("torque_free/{name}/new"), |b| {
            b.iter(|| TorqueFree::new(black_box(moments), black_box(omega0), q0).unwrap())
        });
        let motion = TorqueFree::new(moments, omega0, q0).unwrap();
        c.bench_function(&format!("torque_free/{name}/omega_x64"), |b| {
            b.iter(|| {
                times
                    .iter()
                    .map(|&t| motion.omega(black_box(t)).x)
                    .sum::<f64>()
            })
        });
        c.bench_function(&format!("torque_free/{name}/orientation_x64"), |b| {
            b.iter(|| {
                times
                    .iter()
                    .map(|&t| motion.orientation(black_box(t)).w)
                    .sum::<f64>()
            })
        });
    }
}

criterion_group!(benches, torque_free);
criterion_main!(benches);
