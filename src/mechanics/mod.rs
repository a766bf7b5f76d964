//! The mechanics of chapter 18: inertia, momentum, energy, rotating frames, Euler's
//! equations, fixed-axis rotation and balancing, impulse and momentum. Every function
//! derives its result from the definition with the expression algebra and returns the
//! steps with it.

pub mod angular_momentum;
pub mod balancing;
pub mod catalogue;
pub mod composite_body;
pub mod derivation;
pub mod equations_of_motion;
pub mod euler;
pub mod eulerian_angles;
mod exact_principal;
pub mod fixed_axis;
pub mod gyroscope;
pub mod impulse_momentum;
pub mod inertia;
pub mod inertia_about_point;
pub mod kinematics;
pub mod kinetic_energy;
pub mod linear_momentum;
pub mod mass_centre;
mod moment_transfer;
pub mod parts_table;
pub mod principal_axes;
pub mod principal_frame;
pub mod resultant;
pub mod rotating_frame;
pub mod rotation;
pub mod shapes;
pub mod slip;
pub mod steady_precession;
pub mod torque_free_axisymmetric;
pub mod two_plane_balance;
pub mod validation;

pub use derivation::{Derivation, Relation, Step, Table, TableRow};
pub use inertia::InertiaTensor;
