//! Worked solutions: the givens, the principle and component equations of each step in
//! textbook form, and the results with values and units, as text, LaTeX, Markdown, JSON or
//! an HTML page; and the derivations `kinetics derive` prints, in the same formats.

mod balance_rows;
pub mod derivations;
mod engineer;
pub mod evaluation;
mod html;
mod inertia_results;
mod json;
mod mathml_value;
pub mod numbers;
pub mod parts_table;
mod precession_rows;
pub mod render;
pub mod unit_latex;

pub use derivations::{render_derivations, Shown};
pub use render::{render, render_numbers, Format};
