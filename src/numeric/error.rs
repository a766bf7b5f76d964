//! Errors of the numerical layer.

use crate::mechanics::validation::PhysicsError;
use thiserror::Error;

/// Why a numerical computation was refused before it started or stopped before it ended.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum NumericError {
    /// The body cannot exist (negative mass, inertia violating the triangle inequality, ...).
    #[error(transparent)]
    Physics(#[from] PhysicsError),
    /// An argument that is not physical but is still out of range (a negative step, an end
    /// time before the start, a non-finite initial value).
    #[error("{what}: {reason}")]
    InvalidInput { what: String, reason: String },
}
