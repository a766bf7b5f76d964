//! The integration and property tests, as one crate: one test binary to compile and link,
//! not one per file, each linking the library and its dependencies again. Each module is the
//! tests of one subject; `common` is the support they share.
//!
//! The global allocator is the counting one (`common/counting_allocator.rs`), for every
//! test: a binary has only one, and the memory tests read its per-thread counts.

mod common;

use common::counting_allocator::Counting;

mod about_fixed_point;
mod algebra_properties;
mod bad_scenes;
mod balancing_request;
mod cancel;
mod cancel_agrees_with_sympy;
mod cancel_corpus_parses;
mod check_cli;
mod check_corpus;
mod check_derivation;
mod check_dimension;
mod check_properties;
mod check_slips;
mod check_verdict;
mod claim_parsing;
mod cli_bad_input;
mod cli_write_failure;
mod cubic_scene;
mod declared_units;
mod defined_givens;
mod derivations_numeric;
mod derive_formats;
mod derive_snapshots;
mod dimension_powers;
mod domains;
mod double_double_float;
mod dual_numbers;
mod engineer_numbers;
mod engineer_tensor_lines;
mod exact_numbers;
mod expression_generator;
mod figure;
mod general_body_print;
mod gyroscope_numeric;
mod gyroscope_scenes;
mod heavy_top;
mod hostile_input;
mod hostile_output;
mod html_angles;
mod html_headings;
mod html_page;
mod impact_energy;
mod integrators;
mod issue15_scenes;
mod issue32_bodies;
mod json_schema;
mod latex_compiles;
mod latex_pages;
mod latex_width;
mod layering;
mod line_break;
mod marking;
mod markup;
mod mathml;
mod motion_obeys_loads;
mod nalgebra_ops;
mod numeric_powers;
mod operation_count;
mod orientation_and_units;
mod page_model;
mod polynomial_gcd;
mod polynomial_roots_truth;
mod polynomial_solve;
mod principal_axes;
mod principal_axes_acceptance;
mod principal_scenes;
mod print_parse_properties;
mod python_package;
mod quick_use;
mod readable_products;
mod reproducers;
mod review18;
mod robust_algebra;
mod robust_bodies;
mod robust_parse;
mod robust_simulate;
mod scene_quantities;
mod scene_solutions;
mod second_opinion;
mod shapes_numeric;
mod simplify;
mod simulate_choice;
mod simulate_cli;
mod simulate_cli_memory;
mod simulate_cli_methods;
mod simulate_extreme_momentum;
mod simulate_memory;
mod simulate_top_cli;
mod simulate_without_find;
mod skewed_rotor;
mod solved_unknowns;
mod splitting_time_torque;
mod tape;
mod tape_native;
mod tape_native_memory;
mod time_derivative;
mod title_axes;
mod torque_free;
mod torque_free_from_omega;
mod trigonometry;
mod unknown_angle;
mod us_customary;
mod work_precision;
mod work_precision_forced_truth;

#[global_allocator]
static ALLOCATOR: Counting = Counting;
mod diagnosis;
