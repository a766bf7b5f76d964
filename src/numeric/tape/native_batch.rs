//! Evaluating a [`NativeTape`] over many parameter sets on all cores: tasks of
//! [`SETS_PER_TASK`] sets run with rayon, each set one call of the compiled function.
//!
//! The table layout is that of `batch.rs`: set `p` has its inputs at
//! `inputs[p * stride..][..n_inputs]` (`stride ≥ n_inputs`) and its outputs at
//! `out[p * n_outputs..][..n_outputs]`.

use super::batch::{count_sets, SETS_PER_TASK};
use super::native::NativeTape;
use crate::numeric::error::NumericError;
use rayon::prelude::*;

impl NativeTape {
    /// Every output for every parameter set, on all cores. Fails for a malformed table or
    /// when an output is not finite (the error names one such parameter set).
    pub fn eval_batch(&self, inputs: &[f64], stride: usize) -> Result<Vec<f64>, NumericError> {
        let sets = count_sets(self.n_inputs(), inputs.len(), stride)?;
        let n_outputs = self.n_outputs();
        let mut outputs = vec![0.0; sets * n_outputs];
        inputs
            .par_chunks(SETS_PER_TASK * stride)
            .zip(outputs.par_chunks_mut(SETS_PER_TASK * n_outputs))
            .enumerate()
            .try_for_each(|(task, (rows, out))| {
                let first_set = task * SETS_PER_TASK;
                // `count_sets` checked that rows are whole and at least `n_inputs` long.
                rows.chunks_exact(stride)
                    .zip(out.chunks_exact_mut(n_outputs))
                    .enumerate()
                    .try_for_each(|(r, (row, set_outputs))| {
                        self.eval_set(&row[..self.n_inputs()], set_outputs, first_set + r)
                    })
            })?;
        Ok(outputs)
    }
}
