//! Worked solutions: the givens, the principle and component equations of each step in
//! textbook form, and the results with values and units, as text, LaTeX, Markdown or JSON.

pub mod numbers;
pub mod render;

pub use render::{render, Format};
