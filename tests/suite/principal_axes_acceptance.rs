//! Issue 18's acceptance of `principal_axes`: for seeded random tensors and for tensors
//! `R diag(λ) Rᵀ` with moment gaps down to 1e-12 (random rotations), the moments agree with an
//! independent eigen-solver to 1e-13 relative to ‖[I]‖, the frame is right-handed and
//! orthonormal to 1e-14, and each axis's residual ‖[I]v − λv‖/‖[I]‖ is below 1e-14.
//!
//! The independent solver is the cyclic Jacobi method in double-double arithmetic (about 32
//! digits) on the very f64 tensor the code is given, so its eigenvalues are those of that
//! tensor to far below the bounds checked (nalgebra's `SymmetricEigen`, which the code uses,
//! is not involved). Residuals are also formed in double-double, so they measure the axes,
//! not the rounding of the check.

use kinetics::mechanics::principal_axes::principal_axes;
use kinetics::numeric::scalar::double_double::DoubleDouble as Dd;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3, Vector4};

/// SplitMix64: a small seeded generator, so the cases are the same on every run.
struct Seeded(u64);

impl Seeded {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A rotation from a point of the 4-ball (rejection), normalised: uniform on SO(3).
    fn rotation(&mut self) -> Rotation3<f64> {
        loop {
            let q = Vector4::from_fn(|_, _| self.uniform(-1.0, 1.0));
            if q.norm_squared() > 1e-4 && q.norm_squared() <= 1.0 {
                let unit = UnitQuaternion::from_quaternion(nalgebra::Quaternion::from(q));
                return unit.to_rotation_matrix();
            }
        }
    }
}

fn dd(x: f64) -> Dd {
    Dd::from(x)
}

/// Eigenvalues of a symmetric tensor by cyclic Jacobi sweeps in double-double, ascending.
fn jacobi_eigenvalues(tensor: &Matrix3<f64>) -> [f64; 3] {
    let mut a = [[dd(0.0); 3]; 3];
    for (r, row) in a.iter_mut().enumerate() {
        for (c, entry) in row.iter_mut().enumerate() {
            *entry = dd(tensor[(r, c)]);
        }
    }
    for _sweep in 0..30 {
        let off: f64 = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .map(|&(p, q)| a[p][q].to_f64().abs())
            .sum();
        let scale: f64 = (0..3).map(|k| a[k][k].to_f64().abs()).sum();
        if off <= 1e-34 * scale {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q].to_f64() == 0.0 {
                continue;
            }
            // The rotation that zeroes a[p][q]: θ = (a_qq − a_pp)/(2 a_pq), t = sgn θ/(|θ| + √(θ² + 1)).
            let theta = (a[q][q] - a[p][p]) / (dd(2.0) * a[p][q]);
            let root = (theta * theta + dd(1.0)).sqrt();
            let t = if theta.to_f64() >= 0.0 {
                dd(1.0) / (theta + root)
            } else {
                dd(-1.0) / (root - theta)
            };
            let c = dd(1.0) / (t * t + dd(1.0)).sqrt();
            let s = t * c;
            for row in a.iter_mut() {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            #[allow(clippy::needless_range_loop)] // rows p and q, column by column
            for k in 0..3 {
                let (apk, aqk) = (a[p][k], a[q][k]);
                a[p][k] = c * apk - s * aqk;
                a[q][k] = s * apk + c * aqk;
            }
        }
    }
    let mut values = [0, 1, 2].map(|k| a[k][k].to_f64());
    values.sort_by(f64::total_cmp);
    values
}

fn frobenius(tensor: &Matrix3<f64>) -> f64 {
    tensor.norm()
}

/// ‖[I]v − λv‖ in double-double, rounded once at the end.
fn residual(tensor: &Matrix3<f64>, v: &Vector3<f64>, lambda: f64) -> f64 {
    let mut sum = dd(0.0);
    for r in 0..3 {
        let mut row = dd(-lambda) * dd(v[r]);
        for c in 0..3 {
            row += dd(tensor[(r, c)]) * dd(v[c]);
        }
        sum += row * row;
    }
    sum.sqrt().to_f64()
}

/// The worst of each measure over the cases, for the report of a failure.
#[derive(Default, Debug)]
struct Worst {
    moments: f64,
    orthonormality: f64,
    determinant: f64,
    residual: f64,
}

fn measure(tensor: &Matrix3<f64>, worst: &mut Worst) {
    let axes = principal_axes(tensor).expect("an admissible tensor");
    let norm = frobenius(tensor);
    let reference = jacobi_eigenvalues(tensor);
    for (found, exact) in axes.moments.iter().zip(reference) {
        worst.moments = worst.moments.max((found - exact).abs() / norm);
    }
    let r = axes.rotation.matrix();
    worst.orthonormality = worst
        .orthonormality
        .max((r.transpose() * r - Matrix3::identity()).amax());
    worst.determinant = worst.determinant.max((r.determinant() - 1.0).abs());
    for k in 0..3 {
        let v = r.column(k).into_owned();
        worst.residual = worst
            .residual
            .max(residual(tensor, &v, axes.moments[k]) / norm);
    }
}

fn assert_within_bounds(worst: &Worst) {
    eprintln!("worst over the cases: {worst:?}");
    assert!(worst.moments < 1e-13, "{worst:?}");
    assert!(worst.orthonormality < 1e-14, "{worst:?}");
    assert!(worst.determinant < 1e-14, "{worst:?}");
    assert!(worst.residual < 1e-14, "{worst:?}");
}

/// Moments of a real body: `I_x = B + C`, `I_y = C + A`, `I_z = A + B` from second moments
/// `A, B, C ≥ 0`, so the triangle inequality holds.
fn body_moments(rng: &mut Seeded) -> Vector3<f64> {
    let (a, b, c) = (
        rng.uniform(0.0, 10.0),
        rng.uniform(0.0, 10.0),
        rng.uniform(0.01, 10.0),
    );
    Vector3::new(b + c, c + a, a + b)
}

#[test]
fn random_tensors_agree_with_jacobi_in_double_double() {
    let mut rng = Seeded(18);
    let mut worst = Worst::default();
    for _ in 0..2000 {
        let r = rng.rotation();
        let tensor =
            r.matrix() * Matrix3::from_diagonal(&body_moments(&mut rng)) * r.matrix().transpose();
        measure(&tensor, &mut worst);
    }
    assert_within_bounds(&worst);
}

#[test]
fn near_equal_moments_down_to_gaps_of_1e_12_agree_with_jacobi() {
    let mut rng = Seeded(1812);
    let mut worst = Worst::default();
    for gap in [1e-3, 1e-6, 1e-9, 1e-10, 1e-11, 1e-12, 0.0] {
        for _ in 0..200 {
            let base = rng.uniform(0.5, 5.0);
            let third = base * rng.uniform(1.1, 1.9);
            for moments in [
                Vector3::new(base, base * (1.0 + gap), third),
                Vector3::new(base, third, third * (1.0 + gap)),
                Vector3::new(base, base * (1.0 + gap), base * (1.0 + 2.0 * gap)),
            ] {
                let r = rng.rotation();
                let tensor = r.matrix() * Matrix3::from_diagonal(&moments) * r.matrix().transpose();
                measure(&tensor, &mut worst);
            }
        }
    }
    assert_within_bounds(&worst);
}
