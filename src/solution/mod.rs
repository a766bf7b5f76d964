//! Worked solutions: the givens, the principle and component equations of each step in
//! textbook form, and the results with values and units, as text, LaTeX, Markdown, JSON or
//! an HTML page.

mod html;
mod mathml_value;
pub mod numbers;
pub mod render;

pub use render::{render, Format};
