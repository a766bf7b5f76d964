//! kinetics: kinetics of rigid bodies in three dimensions.
//!
//! Derives the component equations of chapter 18 symbolically ([`algebra`], [`mechanics`]),
//! reads the ASCII mathematics people type ([`parse`]), prints results as a textbook would
//! ([`print`]) and evaluates them numerically ([`numeric`]).

// Diagnostics carry the source line and a hint; they are built only on the error path, so
// their size does not matter.
#![allow(clippy::result_large_err)]

pub mod algebra;
pub mod mechanics;
pub mod numeric;
pub mod parse;
pub mod print;
pub mod scene;
pub mod solution;
