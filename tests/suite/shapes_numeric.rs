//! The standard shapes' centroidal inertia against sums over point masses that fill the
//! shape (midpoint rules, relative error O(1/N²)), and a rotated tensor against the sums
//! over rotated points; a tensor too large to expand is an error, not an unexpanded
//! result.

use kinetics::algebra::{AlgebraError, Expr, Matrix, Symbol};
use kinetics::mechanics::inertia::InertiaTensor;
use kinetics::mechanics::shapes::Shape;
use nalgebra::{Rotation3, Vector3};

type V = Vector3<f64>;

/// `[I_x, I_y, I_z, I_xy, I_yz, I_xz]` of weighted points.
fn sums(points: &[(f64, V)]) -> [f64; 6] {
    let s = |f: &dyn Fn(&V) -> f64| points.iter().map(|(m, r)| m * f(r)).sum::<f64>();
    [
        s(&|r| r.y * r.y + r.z * r.z),
        s(&|r| r.z * r.z + r.x * r.x),
        s(&|r| r.x * r.x + r.y * r.y),
        s(&|r| r.x * r.y),
        s(&|r| r.y * r.z),
        s(&|r| r.x * r.z),
    ]
}

fn formula(tensor: &InertiaTensor, values: &[(&str, f64)]) -> [f64; 6] {
    let v = |s: Symbol| {
        values
            .iter()
            .find(|(n, _)| Symbol::new(n) == s)
            .map(|(_, x)| *x)
    };
    let all: Vec<&Expr> = tensor
        .moments
        .iter()
        .chain(tensor.products.iter())
        .collect();
    std::array::from_fn(|k| all[k].eval(&v).unwrap())
}

fn assert_close(name: &str, a: [f64; 6], b: [f64; 6]) {
    let scale = a.iter().map(|x| x.abs()).fold(0.0, f64::max);
    for k in 0..6 {
        // The midpoint sums converge as 1/N² (2.8e-4 relative at N = 60); a wrong formula
        // is off by a factor, far beyond this bound.
        assert!(
            (a[k] - b[k]).abs() <= 1e-3 * scale,
            "{name} component {k}: formula {} vs sum {}",
            a[k],
            b[k]
        );
    }
}

fn mid(n: usize, length: f64) -> impl Iterator<Item = f64> + Clone {
    (0..n).map(move |i| (i as f64 + 0.5) / n as f64 * length - length / 2.0)
}

fn s(name: &str) -> Expr {
    Expr::symbol(name)
}

#[test]
fn shapes_match_point_mass_sums() {
    let (m, a, b, c, r, h) = (2.0, 0.6, 0.4, 0.3, 0.25, 0.9);
    let values = [("m", m), ("a", a), ("b", b), ("c", c), ("r", r), ("h", h)];
    let n = 60;
    // Slender rod along x.
    let rod: Vec<(f64, V)> = mid(4000, a)
        .map(|x| (m / 4000.0, V::new(x, 0.0, 0.0)))
        .collect();
    assert_close(
        "rod",
        formula(
            &Shape::SlenderRod { length: s("a") }
                .centroidal_inertia(&s("m"))
                .unwrap(),
            &values,
        ),
        sums(&rod),
    );
    // Thin plate a × b in the xy plane.
    let plate: Vec<(f64, V)> = mid(n * 4, a)
        .flat_map(|x| mid(n * 4, b).map(move |y| (m / (16 * n * n) as f64, V::new(x, y, 0.0))))
        .collect();
    let shape = Shape::ThinPlate {
        a: s("a"),
        b: s("b"),
    };
    assert_close(
        "plate",
        formula(&shape.centroidal_inertia(&s("m")).unwrap(), &values),
        sums(&plate),
    );
    // Rectangular prism.
    let prism: Vec<(f64, V)> = mid(n, a)
        .flat_map(|x| {
            mid(n, b).flat_map(move |y| {
                mid(n, c).map(move |z| (m / (n * n * n) as f64, V::new(x, y, z)))
            })
        })
        .collect();
    let shape = Shape::RectangularPrism {
        a: s("a"),
        b: s("b"),
        c: s("c"),
    };
    assert_close(
        "prism",
        formula(&shape.centroidal_inertia(&s("m")).unwrap(), &values),
        sums(&prism),
    );
    // Thin disk with axis x, and a solid cylinder with axis x: polar cells weighted by area.
    let (nr, nt) = (400, 64);
    let polar = |radius: f64| -> Vec<(f64, f64, f64)> {
        let area = std::f64::consts::PI * radius * radius;
        (0..nr)
            .flat_map(move |i| {
                let rho = (i as f64 + 0.5) / nr as f64 * radius;
                let weight =
                    rho * (radius / nr as f64) * (2.0 * std::f64::consts::PI / nt as f64) / area;
                (0..nt).map(move |k| {
                    let t = (k as f64 + 0.5) / nt as f64 * 2.0 * std::f64::consts::PI;
                    (weight, rho * t.cos(), rho * t.sin())
                })
            })
            .collect()
    };
    let disk: Vec<(f64, V)> = polar(r)
        .into_iter()
        .map(|(w, y, z)| (m * w, V::new(0.0, y, z)))
        .collect();
    let shape = Shape::ThinDisk { radius: s("r") };
    assert_close(
        "disk",
        formula(&shape.centroidal_inertia(&s("m")).unwrap(), &values),
        sums(&disk),
    );
    let cylinder: Vec<(f64, V)> = polar(r)
        .into_iter()
        .flat_map(|(w, y, z)| mid(40, h).map(move |x| (m * w / 40.0, V::new(x, y, z))))
        .collect();
    let shape = Shape::SolidCylinder {
        radius: s("r"),
        length: s("h"),
    };
    assert_close(
        "cylinder",
        formula(&shape.centroidal_inertia(&s("m")).unwrap(), &values),
        sums(&cylinder),
    );
}

/// The cone, tube, shell and ring of issue 32, each filled with point masses in its own
/// geometry (not from the formulas' shape): the cone sliced along its axis from the apex,
/// placed so that the apex is ¾h behind G (the sums' own mass centre is checked to be G).
#[test]
fn cone_tube_shell_and_ring_match_point_mass_sums() {
    use std::f64::consts::PI;
    let (m, r, r_i, h) = (2.0, 0.25, 0.15, 0.9);
    let values = [("m", m), ("r", r), ("r_i", r_i), ("h", h)];
    let tensor = |shape: Shape| formula(&shape.centroidal_inertia(&s("m")).unwrap(), &values);
    // An annulus ρ in (inner, outer) in the yz plane, cells weighted by area (sum 1).
    let annulus = |outer: f64, inner: f64| -> Vec<(f64, f64, f64)> {
        let (nr, nt) = (200, 64);
        let area = PI * (outer * outer - inner * inner);
        (0..nr)
            .flat_map(move |i| {
                let rho = inner + (i as f64 + 0.5) / nr as f64 * (outer - inner);
                let w = rho * ((outer - inner) / nr as f64) * (2.0 * PI / nt as f64) / area;
                (0..nt).map(move |k| {
                    let t = (k as f64 + 0.5) / nt as f64 * 2.0 * PI;
                    (w, rho * t.cos(), rho * t.sin())
                })
            })
            .collect()
    };
    // Solid cone: slices at distance u from the apex, radius r u/h, mass ∝ u².
    let slices = 400;
    let mut cone: Vec<(f64, V)> = Vec::new();
    let volume: f64 = (0..slices)
        .map(|i| ((i as f64 + 0.5) / slices as f64 * h).powi(2))
        .sum();
    for i in 0..slices {
        let u = (i as f64 + 0.5) / slices as f64 * h;
        let slice_mass = m * u * u / volume;
        for (w, y, z) in annulus(r * u / h, 0.0) {
            cone.push((slice_mass * w, V::new(u - 0.75 * h, y, z)));
        }
    }
    let centre: f64 = cone.iter().map(|(w, p)| w * p.x).sum::<f64>() / m;
    assert!(
        centre.abs() < 1e-4 * h,
        "the cone's mass centre is at x = {centre}"
    );
    let shape = Shape::SolidCone {
        radius: s("r"),
        height: s("h"),
    };
    assert_close("cone", tensor(shape), sums(&cone));
    // Tube: an annulus extruded along x.
    let tube: Vec<(f64, V)> = annulus(r, r_i)
        .into_iter()
        .flat_map(|(w, y, z)| mid(40, h).map(move |x| (m * w / 40.0, V::new(x, y, z))))
        .collect();
    let shape = Shape::Tube {
        outer: s("r"),
        inner: s("r_i"),
        length: s("h"),
    };
    assert_close("tube", tensor(shape), sums(&tube));
    // Spherical shell: latitude bands weighted by their area 2π r² sin φ dφ.
    let (nphi, nt) = (400, 64);
    let shell: Vec<(f64, V)> = (0..nphi)
        .flat_map(|i| {
            let phi = (i as f64 + 0.5) / nphi as f64 * PI;
            let w = m * phi.sin() * (PI / nphi as f64) / 2.0 / nt as f64;
            (0..nt).map(move |k| {
                let t = (k as f64 + 0.5) / nt as f64 * 2.0 * PI;
                let p = V::new(phi.cos(), phi.sin() * t.cos(), phi.sin() * t.sin());
                (w, r * p)
            })
        })
        .collect();
    let shape = Shape::SphericalShell { radius: s("r") };
    assert_close("shell", tensor(shape), sums(&shell));
    // Thin ring about x: points on the circle.
    let ring: Vec<(f64, V)> = (0..720)
        .map(|k| {
            let t = (k as f64 + 0.5) / 720.0 * 2.0 * PI;
            (m / 720.0, V::new(0.0, r * t.cos(), r * t.sin()))
        })
        .collect();
    let shape = Shape::ThinRing { radius: s("r") };
    assert_close("ring", tensor(shape), sums(&ring));
}

#[test]
fn rotated_tensor_matches_rotated_points() {
    let (m, a, b, c) = (3.0, 0.5, 0.3, 0.2);
    let n = 40;
    let points: Vec<(f64, V)> = mid(n, a)
        .flat_map(|x| {
            mid(n, b).flat_map(move |y| {
                mid(n, c).map(move |z| (m / (n * n * n) as f64, V::new(x, y, z)))
            })
        })
        .collect();
    let rotation = Rotation3::from_euler_angles(0.4, -0.9, 1.3);
    let turned: Vec<(f64, V)> = points.iter().map(|(w, p)| (*w, rotation * p)).collect();
    let numbers = rotation.matrix();
    let symbolic = Matrix::from_fn(|i, j| {
        let x = numbers[(i, j)];
        let magnitude =
            Expr::num(kinetics::algebra::Q::parse_decimal(&format!("{:.17}", x.abs())).unwrap());
        if x < 0.0 {
            -magnitude
        } else {
            magnitude
        }
    });
    let tensor = Shape::RectangularPrism {
        a: Expr::symbol("a"),
        b: Expr::symbol("b"),
        c: Expr::symbol("c"),
    }
    .centroidal_inertia(&Expr::symbol("m"))
    .unwrap()
    .rotated(&symbolic)
    .unwrap();
    let values = [("m", m), ("a", a), ("b", b), ("c", c)];
    assert_close("rotated prism", formula(&tensor, &values), sums(&turned));
}

#[test]
fn a_tensor_too_large_to_expand_is_an_error() {
    // (a + b + ... + q)^12 has 293,930 terms, over the bound of 100,000.
    let sum = Expr::add_all("abcdefghpq".chars().map(|c| Expr::symbol(&c.to_string())));
    let too_large =
        |r: Result<InertiaTensor, AlgebraError>| matches!(r, Err(AlgebraError::TooLarge { .. }));
    let rod = Shape::SlenderRod {
        length: sum.powi(6),
    };
    assert!(too_large(rod.centroidal_inertia(&Expr::symbol("m"))));
    let tensor = InertiaTensor::diagonal([sum.powi(12), Expr::zero(), Expr::zero()]);
    assert!(too_large(tensor.rotated(&Matrix::identity())));
}
