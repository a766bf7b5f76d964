//! Worked solutions: the givens, the principle and component equations of each step in
//! textbook form, and the results with values and units, as text, LaTeX, Markdown or JSON;
//! and the derivations `kinetics derive` prints, in the same formats.

pub mod numbers;
pub mod parts_table;
pub mod render;
pub mod unit_latex;

pub use render::{render, Format};
