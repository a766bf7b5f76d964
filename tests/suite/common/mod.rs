//! Support shared by the integration tests. Each test crate uses part of it, so items one
//! crate leaves unused are not dead code.
#![allow(dead_code)]

pub mod binary;
pub mod counting_allocator;
pub mod expression_tree;
