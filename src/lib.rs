//! kinetics: kinetics of rigid bodies in three dimensions.
//!
//! Derives the component equations of chapter 18 symbolically ([`algebra`], [`mechanics`]),
//! reads the ASCII mathematics people type ([`parse`]), prints results as a textbook would
//! ([`print`](mod@print)), solves problems written as scenes ([`scene`], [`solution`]) and
//! evaluates and simulates them numerically ([`numeric`]).
//!
//! The types and functions a user needs are re-exported here; the modules keep the rest.
//!
//! # A worked solution from a scene
//!
//! Sample Problem 18.4: a massless shaft along x turns in bearings C (at O) and D (at
//! x = L); two slender rods of mass m and length c are welded to it, and a couple M acts
//! about it. About the shaft each rod turns about its end, so `I_x = 2 · m c²/3`, and
//! `ΣM_x = I_x α` gives `α = 3M/(2 m c²) = 3 · 6/(2 · 0.3 · 0.1²) = 3000 rad/s²`.
//!
//! ```
//! use kinetics::{analyse, parse_expression, parse_scene, render, Format, Value};
//!
//! let scene = parse_scene(
//!     "sp18_4.scene",
//!     "given m = 0.3 kg
//! given c = 0.1 m
//! given M = 6 N*m
//! given L : m
//! given w = 125.7 rad/s
//! unknown alpha : rad/s^2
//! unknown C_y, C_z, D_y, D_z : N
//! body rod(c) mass m at (L/2, c/2, 0) along y
//! body rod(c) mass m at (L/4, 0, c/2) along z
//! fixed point
//! omega = w*i
//! omegadot = alpha*i
//! couple M*i
//! force C = C_y*j + C_z*k at (0, 0, 0)
//! force D = D_y*j + D_z*k at (L, 0, 0)
//! find alpha",
//! )?;
//! let analysis = analyse(&scene)?;
//! let (_, Value::Scalar(alpha)) = &analysis.results[0] else {
//!     panic!("alpha is a scalar")
//! };
//! assert_eq!(*alpha, parse_expression("by hand", "3 M/(2 m c^2)")?);
//! let worked = render(&scene, &analysis, Format::Text, false);
//! assert!(worked.contains("alpha = 3*M/(2*m*c^2) = 3000 rad/s²"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Euler's equations in the cyclic form
//!
//! In principal axes `[I]` is diagonal, and `ΣM = [I]{ω̇} + ω × [I]{ω}` has the x-component
//! `I_x ω̇_x + ω_y I_z ω_z − ω_z I_y ω_y = I_x ω̇_x − (I_y − I_z) ω_y ω_z`; the y- and
//! z-equations follow by the cyclic change x → y → z → x.
//!
//! ```
//! use kinetics::{euler_equations, parse_expression, print, InertiaTensor};
//!
//! let euler = euler_equations(&InertiaTensor::principal())?;
//! let printed: Vec<String> = euler
//!     .result()
//!     .iter()
//!     .map(|r| format!("{} = {}", print::text(&r.lhs), print::text_about(&r.rhs, r.axis)))
//!     .collect();
//! assert_eq!(
//!     printed,
//!     [
//!         "SumM_x = I_x*wdot_x - (I_y - I_z)*w_y*w_z",
//!         "SumM_y = I_y*wdot_y - (I_z - I_x)*w_z*w_x",
//!         "SumM_z = I_z*wdot_z - (I_x - I_y)*w_x*w_y",
//!     ]
//! );
//! let by_hand = parse_expression("by hand", "I_x wdot_x + w_y I_z w_z - w_z I_y w_y")?;
//! assert_eq!(euler.result()[0].rhs, by_hand);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// Diagnostics carry the source line and a hint; they are built only on the error path, so
// their size does not matter.
#![allow(clippy::result_large_err)]

pub mod algebra;
pub mod check;
pub mod figure;
pub mod input;
pub mod marking;
pub mod mechanics;
pub mod numeric;
pub mod parse;
pub mod print;
pub mod scene;
pub mod solution;
pub mod visible;

// The expression algebra.
pub use algebra::{AlgebraError, Axis, Domain, Domains, Expr, Matrix, Symbol, Vector, View};
// The derivations, each returned with its steps.
pub use mechanics::angular_momentum::angular_momentum;
pub use mechanics::catalogue::{derive_general, derive_general_along, NAMES as DERIVATION_NAMES};
pub use mechanics::euler::euler_equations;
pub use mechanics::fixed_axis::fixed_axis_rotation;
pub use mechanics::kinetic_energy::kinetic_energy;
pub use mechanics::{Derivation, InertiaTensor, Relation, Step};
// Reading expressions and scenes, each within its work budget.
pub use input::Input;
pub use parse::{parse_expression, Diagnostic};
pub use scene::unit_system::UnitSystem;
pub use scene::{analyse, analyse_results, parse_scene, parse_scene_in, Analysis, Scene, Value};
// Worked solutions, and derivations as pages.
pub use figure::svg::svg as figure_svg;
pub use figure::{figure, Figure, FigureError};
pub use print::markup::{html as markup_html, latex as markup_latex, text as markup_text};
pub use print::{render as render_expr, Notation};
pub use solution::numbers::check_numeric_requests;
pub use solution::render::relation;
pub use solution::{
    answers, render, render_beside, render_derivations, render_numbers, render_numbers_beside,
    worked_steps, Answer, AnswerForm, Format, Shown, WorkedStep,
};
// Hand-written claims checked against the derivations.
pub use check::context::{Context, DEFAULT_RELATIVE_TOLERANCE};
pub use check::derivation::report::text as derivation_report_text;
pub use check::derivation::{
    check_derivation, first_slip, parts as derivation_parts, DerivationCheck, Judgement, Line,
    LineCheck,
};
pub use check::forms::Forms;
pub use check::report::{
    latex as claim_report_latex, numbers_sentence as claim_numbers_sentence,
    text as claim_report_text,
};
pub use check::verdict::{check as check_claim, Report, Verdict};
// Simulation of a body's motion.
pub use numeric::integrators::splitting::SplittingOrder;
pub use numeric::rigid_body::exact_propagation::{simulate_choice, Choice, MethodUsed};
pub use numeric::rigid_body::inertia::BodyInertia;
pub use numeric::rigid_body::sample_sink::Sample;
pub use numeric::rigid_body::simulate::{simulate, Method, Problem, Sampling};
pub use numeric::rigid_body::state::RigidBodyState;
pub use numeric::rigid_body::torque::Torque;
pub use numeric::NumericError;
pub use scene::parse_scene_to_simulate;
pub use scene::simulation::{located as simulation_located, problem as simulation_problem};
pub use scene::top_simulation::heavy_top;
