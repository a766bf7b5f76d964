//! The simulation driver's memory does not grow with the number of samples: the suite's
//! counting global allocator (`main.rs`) records the peak of the bytes the test's thread holds while
//! `simulate_choice` (the driver behind `kinetics simulate`) streams 10³ and then 10⁶ or 10⁷
//! samples over the same span into a sink that drops them, for every method. Storing even
//! one byte per sample would raise the second peak by a million bytes or more.
//!
//! The count is per thread because the test harness's own threads allocate at times of their
//! choosing; the driver runs on the caller's thread (no method spawns threads), which the
//! control test checks by seeing a collecting sink's memory.

use crate::common::counting_allocator::peak_during;
use kinetics::numeric::integrators::splitting::SplittingOrder;
use kinetics::numeric::rigid_body::exact_propagation::{simulate_choice, Choice};
use kinetics::numeric::rigid_body::inertia::BodyInertia;
use kinetics::numeric::rigid_body::sample_sink::Sample;
use kinetics::numeric::rigid_body::simulate::{Method, Problem, Sampling};
use kinetics::numeric::rigid_body::state::RigidBodyState;
use kinetics::numeric::rigid_body::torque::Torque;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// Span of every run (s): long enough for several hundred steps of each integrator.
const SPAN: f64 = 10.0;

/// A torque-free body given by a full tensor (so the exact method and the splitting also
/// work in a principal frame of their own) with a generic spin.
fn body() -> Problem<f64> {
    let r = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
    let tensor =
        r.matrix() * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)) * r.matrix().transpose();
    Problem {
        inertia: BodyInertia::Tensor(tensor),
        torque: Torque::None,
        initial: RigidBodyState::new(
            Vector3::new(0.4, -1.0, 0.8),
            UnitQuaternion::from_euler_angles(0.2, 0.1, -0.3),
        ),
        start_time: 0.0,
    }
}

/// Peak bytes held while `samples` samples evenly spread over [`SPAN`] are streamed into a
/// sink that only counts them.
fn streaming_peak(choice: &Choice, samples: usize) -> isize {
    let problem = body();
    let sampling = Sampling::Every {
        interval: SPAN / (samples - 1) as f64,
        end: SPAN,
    };
    let mut received = 0usize;
    let peak = peak_during(|| {
        let mut sink = |_: Sample<f64>| received += 1;
        simulate_choice(&problem, choice, &sampling, &mut sink, &mut |_| {}).unwrap();
    });
    assert_eq!(received, samples, "{choice:?}");
    peak
}

/// Bytes the long run may hold beyond the thousand-sample one. The driver allocates the
/// same things whatever the sample count (the propagator and its state: measured 248 bytes
/// for rk4 up to 1,784 for dop853, equal at both counts), so the peaks are expected equal;
/// 1 KiB leaves room for an allocation that varies in size by a few words while staying a
/// thousand times below the 10⁶ bytes that one byte kept per sample would add.
const SLACK: isize = 1024;

#[test]
fn memory_stays_flat_from_a_thousand_to_millions_of_samples() {
    // The cheap methods go to 10⁷ samples (the ten million CSV rows); the closed
    // form and the splitting cost about a microsecond a sample in a debug build, so they
    // stop at 10⁶.
    let methods = [
        ("exact", Choice::Exact, 1_000_000),
        ("auto", Choice::Auto { rtol: 1e-10 }, 1_000_000),
        (
            "dop853",
            Choice::Integrate(Method::dop853(1e-10, 1e-13)),
            10_000_000,
        ),
        (
            "rk4",
            Choice::Integrate(Method::Rk4 { step: 1e-2 }),
            10_000_000,
        ),
        (
            "splitting",
            Choice::Integrate(Method::Splitting {
                step: 1e-2,
                order: SplittingOrder::Fourth,
            }),
            1_000_000,
        ),
    ];
    for (name, choice, samples) in methods {
        let few = streaming_peak(&choice, 1_000);
        let many = streaming_peak(&choice, samples);
        println!("{name}: peak {few} bytes for 10^3 samples, {many} bytes for {samples}");
        assert!(
            many <= few + SLACK,
            "{name}: peak {many} bytes for {samples} samples against {few} for 10^3"
        );
    }
}

#[test]
fn the_counter_sees_a_sink_that_keeps_its_samples() {
    // The control: the same driver with a sink that collects does show growth, at least
    // the samples' own size, so a driver that kept them would fail the test above.
    let problem = body();
    let samples = 10_000;
    let sampling = Sampling::Every {
        interval: SPAN / (samples - 1) as f64,
        end: SPAN,
    };
    let mut kept = Vec::new();
    let peak = peak_during(|| {
        let mut sink = |s: Sample<f64>| kept.push(s);
        simulate_choice(
            &problem,
            &Choice::Integrate(Method::dop853(1e-10, 1e-13)),
            &sampling,
            &mut sink,
            &mut |_| {},
        )
        .unwrap();
    });
    let floor = (samples * std::mem::size_of::<Sample<f64>>()) as isize;
    assert_eq!(kept.len(), samples);
    assert!(peak >= floor, "peak {peak} bytes, samples alone {floor}");
}
