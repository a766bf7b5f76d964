//! Scenes: a problem described in a file (`grammar/scene.pest`), analysed on demand.

pub mod analysis;
mod exact_given;
pub mod kinematic_constraints;
pub mod model;
pub mod named_unit;
pub mod parse;
mod quantity_dimension;
pub mod simulation;
pub mod stated_kinematics;
pub mod top_simulation;
pub mod unit_system;
pub mod unit_text;
pub mod units;
pub(crate) mod units_in_math;

pub use analysis::{analyse, analyse_results, Analysis, Value};
pub use model::Scene;
pub use parse::{parse_scene, parse_scene_in, parse_scene_to_simulate};
pub use quantity_dimension::derived_dimension;
