//! The chapter's equations for a general body, by name: what `kinetics derive --general`
//! prints. Each entry is derived on demand; nothing is derived that was not asked for.

use super::angular_momentum::{angular_momentum, angular_momentum_about_point};
use super::balancing::{dynamic_balancing, Unbalance};
use super::derivation::Derivation;
use super::euler::{body_angular_velocity, euler_equations};
use super::eulerian_angles::EulerianAngles;
use super::fixed_axis::{bearing_reactions, fixed_axis_rotation};
use super::gyroscope::gyroscope_equations;
use super::impulse_momentum::{impulse_momentum, ImpulseMomentum};
use super::inertia::InertiaTensor;
use super::kinetic_energy::kinetic_energy;
use super::rotating_frame::rate_of_angular_momentum;
use super::steady_precession::steady_precession;
use super::torque_free_axisymmetric::torque_free_axisymmetric;
use crate::algebra::{AlgebraError, Axis, Expr, Vector};

/// The derivations `derive` knows, in the chapter's order.
pub const NAMES: [&str; 14] = [
    "H_G",
    "H_O",
    "T",
    "T_O",
    "T_plane",
    "impulse",
    "Hdot",
    "euler",
    "fixed_axis",
    "reactions",
    "balancing",
    "gyroscope",
    "steady_precession",
    "torque_free",
];

/// What each derivation of [`NAMES`] is about: the reference point and the axes, in the
/// step-title markup (words, mathematics between `$…$`), so a reader knows which formula
/// of the chapter is meant before reading it. `axis` is the axis of rotation of the
/// fixed-axis derivations.
pub fn convention(name: &str, axis: Axis) -> Option<String> {
    let (a, unit) = match axis {
        Axis::X => ("x", r"\mathbf{i}"),
        Axis::Y => ("y", r"\mathbf{j}"),
        Axis::Z => ("z", r"\mathbf{k}"),
    };
    Some(match name {
        "fixed_axis" => format!(
            r"About the fixed point $O$ on the axis; rotation about ${a}$, $\boldsymbol{{\omega}} = \omega{unit}$."
        ),
        "reactions" => {
            format!("Bearing $A$ at $O$ and bearing $B$ at ${a} = l$ on the axis of rotation ${a}$.")
        }
        "balancing" => format!(
            "Correcting masses in the planes ${a} = {a}_1$ and ${a} = {a}_2$; the axis of rotation is ${a}$."
        ),
        other => fixed_convention(other)?.to_string(),
    })
}

/// [`convention`] of the derivations that do not depend on an axis of rotation.
fn fixed_convention(name: &str) -> Option<&'static str> {
    Some(match name {
        "H_G" | "Hdot" | "impulse" => {
            r"About the mass centre $G$; axes $x, y, z$ through $G$, products of inertia $I_{xy} = \int xy\,dm$."
        }
        "T" => {
            r"About the mass centre $G$: $T = \frac{1}{2} m\bar{v}^2 + \frac{1}{2}\{\boldsymbol{\omega}\}^T[\bar{I}]\{\boldsymbol{\omega}\}$."
        }
        "H_O" => {
            r"About a point $O$, from the mass centre $G$ at $\bar{\mathbf{r}}$ moving at $\bar{\mathbf{v}}$."
        }
        "T_O" => {
            r"About the fixed point $O$: moments and products of inertia about axes through $O$."
        }
        "T_plane" => {
            r"Plane motion: $z$ a principal axis through $G$, $\bar{\mathbf{v}}$ along $x$."
        }
        "euler" => {
            r"About $G$ or a fixed point $O$; axes fixed in the body, $\boldsymbol{\Omega} = \boldsymbol{\omega}$."
        }
        _ => return None,
    })
}

fn vector(names: [&str; 3]) -> Vector {
    Vector::from_iterator(names.into_iter().map(Expr::symbol))
}

/// Derives one of [`NAMES`] for a general body (`principal` drops the products of inertia).
/// Returns `None` for an unknown name.
///
/// ```
/// use kinetics::mechanics::catalogue::NAMES;
/// use kinetics::{derive_general, parse_expression};
///
/// // About a fixed point, principal axes: T = ½(I_x ω_x² + I_y ω_y² + I_z ω_z²).
/// let t = derive_general("T_O", true).expect("a known name")?;
/// let by_hand = parse_expression("by hand", "1/2 (I_x w_x^2 + I_y w_y^2 + I_z w_z^2)")?;
/// assert_eq!(t.result()[0].rhs, by_hand.expand()?);
/// assert!(NAMES.iter().all(|name| derive_general(name, false).is_some_and(|d| d.is_ok())));
/// assert!(derive_general("T_G", false).is_none());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn derive_general(name: &str, principal: bool) -> Option<Result<Derivation, AlgebraError>> {
    derive_general_along(name, principal, Axis::Z)
}

/// [`derive_general`] with the fixed-axis derivations (`fixed_axis`, `reactions`,
/// `balancing`) about `axis` (the chapter's shafts often lie along x); the others do not
/// depend on it. The derivation is named as asked.
pub fn derive_general_along(
    name: &str,
    principal: bool,
    axis: Axis,
) -> Option<Result<Derivation, AlgebraError>> {
    let turn = |k: usize| ["x", "y", "z"][(axis.index() + k) % 3];
    let bar = |k: usize| Expr::symbol(&format!("{}bar", turn(k)));
    let inertia = if principal {
        InertiaTensor::principal()
    } else {
        InertiaTensor::general()
    };
    let omega = body_angular_velocity();
    let m = Expr::symbol("m");
    let vbar = vector(["vbar_x", "vbar_y", "vbar_z"]);
    let derived = match name {
        "H_G" => angular_momentum(&inertia, &omega, "G"),
        "H_O" => {
            let h_g = inertia.matrix() * &omega;
            angular_momentum_about_point(&h_g, &vector(["xbar", "ybar", "zbar"]), &m, &vbar)
        }
        "T" => kinetic_energy(&inertia, &omega, Some((&m, &vbar))),
        // About a fixed point O: no translational part; moments and products about O.
        "T_O" => kinetic_energy(&inertia, &omega, None),
        // Plane motion: ω along the principal axis z (moment I), x along v̄.
        "T_plane" => {
            let plane = InertiaTensor::diagonal([
                Expr::symbol("I_x"),
                Expr::symbol("I_y"),
                Expr::symbol("I"),
            ]);
            let spin = Vector::new(Expr::zero(), Expr::zero(), Expr::symbol("w"));
            let v = Vector::new(Expr::symbol("vbar"), Expr::zero(), Expr::zero());
            kinetic_energy(&plane, &spin, Some((&m, &v))).map(|mut d| {
                d.title = "kinetic energy in plane motion".into();
                d
            })
        }
        "impulse" => impulse_momentum(&ImpulseMomentum {
            mass: &m,
            velocity_before: &vector(["vbar_x1", "vbar_y1", "vbar_z1"]),
            velocity_after: &vector(["vbar_x2", "vbar_y2", "vbar_z2"]),
            angular_momentum_before: &vector(["H_x1", "H_y1", "H_z1"]),
            angular_momentum_after: &vector(["H_x2", "H_y2", "H_z2"]),
            linear_impulse: &vector(["F_x", "F_y", "F_z"]).map(|f| f * Expr::symbol("Dt")),
            angular_impulse: &vector(["M_x", "M_y", "M_z"]).map(|f| f * Expr::symbol("Dt")),
        }),
        "Hdot" => rate_of_angular_momentum(
            &inertia,
            &omega,
            &vector(["wdot_x", "wdot_y", "wdot_z"]),
            &vector(["Omega_x", "Omega_y", "Omega_z"]),
            "G",
        ),
        "euler" => euler_equations(&inertia),
        "gyroscope" => gyroscope_equations(&EulerianAngles::chapter(), "O").map(|(_, d)| d),
        "steady_precession" => steady_precession(&EulerianAngles::chapter(), "O").map(|(_, d)| d),
        "torque_free" => torque_free_axisymmetric(&EulerianAngles::chapter()).map(|(_, d)| d),
        "fixed_axis" => fixed_axis_rotation(&inertia, axis),
        "reactions" => {
            bearing_reactions(&inertia, &m, (&bar(1), &bar(2)), &Expr::symbol("l"), axis)
        }
        "balancing" => {
            let product = |k: usize| {
                let mut pair = [turn(0), turn(k)];
                pair.sort_unstable();
                Expr::symbol(&format!("I_{}{}", pair[0], pair[1]))
            };
            dynamic_balancing(
                &Unbalance {
                    first_moment: (&(&m * bar(1)), &(&m * bar(2))),
                    products: (&product(1), &product(2)),
                },
                &Expr::symbol(&format!("{}_1", turn(0))),
                &Expr::symbol(&format!("{}_2", turn(0))),
                axis,
            )
        }
        _ => return None,
    };
    // Named as asked (`T_O`, not the kinetic-energy function's `T`), so its convention is found.
    Some(derived.map(|mut d| {
        d.name = name.to_string();
        d
    }))
}
