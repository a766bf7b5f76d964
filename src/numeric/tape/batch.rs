//! Evaluating a [`Tape`] over many parameter sets: blocks of [`LANES`] sets run side by
//! side through the tape (one instruction dispatch per block, vectorisable lane loops), and
//! with rayon, tasks of [`SETS_PER_TASK`] sets run on all cores.
//!
//! Parameter sets are rows of a flat slice: set `p` has its inputs at
//! `inputs[p * stride..][..n_inputs]` (`stride ≥ n_inputs`, so a table may carry extra
//! columns). The outputs are rows too: set `p`'s outputs at `out[p * n_outputs..]`.

use super::interpreter::{length_error, Tape};
use crate::numeric::error::NumericError;
use num_traits::Float;
use rayon::prelude::*;

/// Parameter sets evaluated side by side in one pass over the tape.
pub const LANES: usize = 32;
/// Parameter sets per rayon task.
pub const SETS_PER_TASK: usize = 32 * LANES;

impl Tape {
    /// Every output for every parameter set, on all cores. Fails for a malformed table or
    /// when an output is not finite (the error names one such parameter set).
    pub fn eval_batch<T: Float + Send + Sync>(
        &self,
        inputs: &[T],
        stride: usize,
    ) -> Result<Vec<T>, NumericError> {
        let sets = count_sets(self.n_inputs(), inputs.len(), stride)?;
        let n_outputs = self.n_outputs();
        let mut outputs = vec![T::zero(); sets * n_outputs];
        inputs
            .par_chunks(SETS_PER_TASK * stride)
            .zip(outputs.par_chunks_mut(SETS_PER_TASK * n_outputs))
            .enumerate()
            .try_for_each_init(Vec::new, |scratch, (task, (rows, out))| {
                self.eval_rows(rows, stride, out, task * SETS_PER_TASK, scratch)
            })?;
        Ok(outputs)
    }

    /// [`Tape::eval_batch`] on the calling thread only.
    pub fn eval_batch_serial<T: Float>(
        &self,
        inputs: &[T],
        stride: usize,
    ) -> Result<Vec<T>, NumericError> {
        let sets = count_sets(self.n_inputs(), inputs.len(), stride)?;
        let mut outputs = vec![T::zero(); sets * self.n_outputs()];
        self.eval_rows(inputs, stride, &mut outputs, 0, &mut Vec::new())?;
        Ok(outputs)
    }

    /// Evaluates consecutive rows, `LANES` at a time and the remainder one by one.
    fn eval_rows<T: Float>(
        &self,
        rows: &[T],
        stride: usize,
        outputs: &mut [T],
        first_set: usize,
        scratch: &mut Vec<T>,
    ) -> Result<(), NumericError> {
        let n_outputs = self.n_outputs();
        let blocks = rows.chunks(LANES * stride);
        for (b, (block, out)) in blocks
            .zip(outputs.chunks_mut(LANES * n_outputs))
            .enumerate()
        {
            let set = first_set + b * LANES;
            if block.len() == LANES * stride {
                self.run_block::<T, LANES>(block, stride, scratch);
                self.read_outputs::<T, LANES>(scratch, out, set)?;
            } else {
                for (r, (row, row_out)) in block
                    .chunks(stride)
                    .zip(out.chunks_mut(n_outputs))
                    .enumerate()
                {
                    self.run_block::<T, 1>(row, stride, scratch);
                    self.read_outputs::<T, 1>(scratch, row_out, set + r)?;
                }
            }
        }
        Ok(())
    }
}

/// Number of parameter sets in a flat table of `len` values with rows of `stride` values
/// for a tape of `n_inputs` inputs, or why the table is malformed.
pub(super) fn count_sets(
    n_inputs: usize,
    len: usize,
    stride: usize,
) -> Result<usize, NumericError> {
    if stride == 0 || stride < n_inputs {
        return Err(NumericError::InvalidInput {
            what: "batch stride".into(),
            reason: format!("{stride} is smaller than the {n_inputs} inputs (or zero)"),
        });
    }
    if !len.is_multiple_of(stride) {
        return Err(length_error(
            "batch inputs (a whole number of rows)",
            len.next_multiple_of(stride),
            len,
        ));
    }
    Ok(len / stride)
}
