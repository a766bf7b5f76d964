//! Support shared by the integration tests.

pub mod binary;
pub mod check;
pub mod chromium;
pub mod counting_allocator;
pub mod examples;
pub mod expression_tree;
pub mod pdflatex;
