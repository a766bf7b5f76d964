//! Worked solutions: the givens, the principle and component equations of each step in
//! textbook form, and the results with values and units, as text, LaTeX, Markdown, JSON or
//! an HTML page; and the derivations `kinetics derive` prints, in the same formats.

mod answer;
mod balance_rows;
pub mod derivations;
mod engineer;
pub mod evaluation;
mod html;
mod inertia_results;
mod json;
mod latex;
mod markdown;
mod mathml_value;
pub mod numbers;
mod page;
pub mod parts_table;
mod precession_rows;
pub mod render;
mod result;
mod shown_value;
mod solution_page;
mod text;
pub mod unit_latex;

pub use answer::{answers, worked_steps, Answer, AnswerForm, WorkedStep};
pub use derivations::{render_derivations, Shown};
pub use render::{render, render_beside, render_numbers, render_numbers_beside, Format};
