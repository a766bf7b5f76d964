//! `kinetics._native`: the Rust half of the Python package `kinetics` (its Python half,
//! `python/kinetics`, gives the documented classes). It calls only what the `kinetics` crate
//! re-exports at its root, and hands back plain Python data: strings, numbers, lists, and
//! expressions as trees of tuples that `kinetics._sympy` turns into SymPy.

// Diagnostics carry the source line and a hint; they are built only on the error path, so
// their size does not matter (as in the kinetics crate).
#![allow(clippy::result_large_err)]

mod derivations;
mod error;
mod expression;
mod hand_derivation;
mod simulation;
mod solution;
mod verdict;

use pyo3::prelude::*;

/// The allocator of the Rust half, as in the command line: the derivations' many small
/// nodes come from its thread-local free lists (SP 18.4 solves in about 15 % less time).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SceneError", m.py().get_type::<error::SceneError>())?;
    m.add_function(wrap_pyfunction!(solution::solve, m)?)?;
    m.add_class::<solution::Solved>()?;
    m.add_function(wrap_pyfunction!(verdict::check, m)?)?;
    m.add_function(wrap_pyfunction!(hand_derivation::check_derivation, m)?)?;
    m.add_function(wrap_pyfunction!(derivations::derive, m)?)?;
    m.add_class::<derivations::Derived>()?;
    m.add_function(wrap_pyfunction!(simulation::simulate, m)?)?;
    Ok(())
}
