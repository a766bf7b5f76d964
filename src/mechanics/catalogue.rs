//! The chapter's equations for a general body, by name: what `kinetics derive --general`
//! prints. Each entry is derived on demand; nothing is derived that was not asked for.

use super::angular_momentum::{angular_momentum, angular_momentum_about_point};
use super::balancing::{dynamic_balancing, Unbalance};
use super::derivation::Derivation;
use super::euler::{body_angular_velocity, euler_equations};
use super::fixed_axis::{bearing_reactions, fixed_axis_rotation};
use super::impulse_momentum::{impulse_momentum, ImpulseMomentum};
use super::inertia::InertiaTensor;
use super::kinetic_energy::kinetic_energy;
use super::rotating_frame::rate_of_angular_momentum;
use crate::algebra::{AlgebraError, Expr, Vector};

/// The derivations `derive` knows, in the chapter's order.
pub const NAMES: [&str; 11] = [
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
];

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
    let inertia = if principal {
        InertiaTensor::principal()
    } else {
        InertiaTensor::general()
    };
    let omega = body_angular_velocity();
    let m = Expr::symbol("m");
    let vbar = vector(["vbar_x", "vbar_y", "vbar_z"]);
    Some(match name {
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
        "fixed_axis" => fixed_axis_rotation(&inertia),
        "reactions" => bearing_reactions(
            &inertia,
            &m,
            (&Expr::symbol("xbar"), &Expr::symbol("ybar")),
            &Expr::symbol("l"),
        ),
        "balancing" => dynamic_balancing(
            &Unbalance {
                first_moment: (&(&m * Expr::symbol("xbar")), &(&m * Expr::symbol("ybar"))),
                products: (&Expr::symbol("I_xz"), &Expr::symbol("I_yz")),
            },
            &Expr::symbol("z_1"),
            &Expr::symbol("z_2"),
        ),
        _ => return None,
    })
}
