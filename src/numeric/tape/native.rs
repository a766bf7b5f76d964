//! A [`Tape`](crate::numeric::Tape) compiled to machine code: one native function per tape
//! (built by `native_compile.rs`), and its checked evaluation.
//!
//! Calling convention of the compiled function (the platform's C convention):
//!
//! ```text
//! extern "C" fn(inputs: *const f64, outputs: *mut f64) -> u8
//! ```
//!
//! It reads `inputs[0..n_inputs]`, writes `outputs[0..n_outputs]`, returns 1 when every
//! output is finite and 0 otherwise, and touches no other memory and no state, so it may run
//! on many threads at once. [`NativeTape::eval`] is the safe entry: it checks the slice
//! lengths before the call and refuses a non-finite output afterwards, exactly as the
//! interpreter (`Tape::eval_with`) does; the values are those of the interpreter bit for
//! bit (see `native_compile.rs` for why).

use super::interpreter::{length_error, non_finite_output};
use crate::numeric::error::NumericError;
use cranelift_jit::JITModule;
use std::fmt;
use std::sync::Mutex;

/// The compiled function: see the calling convention at the top of this file.
pub(super) type NativeFunction =
    unsafe extern "C" fn(inputs: *const f64, outputs: *mut f64) -> AllFinite;

/// What the compiled function returns: 1 when every output it wrote is finite, else 0.
pub(super) type AllFinite = u8;

/// A tape compiled to machine code for `f64`. Its executable memory is freed on drop.
pub struct NativeTape {
    function: NativeFunction,
    n_inputs: usize,
    n_outputs: usize,
    /// Owns the memory `function` points into. It is never used through `&self` (only
    /// taken in `drop`), so sharing a `NativeTape` between threads shares only the pointer
    /// to immutable code; the mutex makes that `Sync` without claiming that `JITModule`
    /// itself is. `None` only while being dropped.
    module: Option<Mutex<JITModule>>,
}

impl NativeTape {
    /// A compiled tape from the module that owns its code.
    ///
    /// # Safety
    ///
    /// `function` must point to code in `module` that follows the calling convention above
    /// for these `n_inputs` and `n_outputs`, and stays valid as long as `module` lives.
    pub(super) unsafe fn from_module(
        module: JITModule,
        function: NativeFunction,
        n_inputs: usize,
        n_outputs: usize,
    ) -> NativeTape {
        NativeTape {
            function,
            n_inputs,
            n_outputs,
            module: Some(Mutex::new(module)),
        }
    }

    /// Number of inputs a parameter set must supply.
    pub fn n_inputs(&self) -> usize {
        self.n_inputs
    }

    pub fn n_outputs(&self) -> usize {
        self.n_outputs
    }

    /// Evaluates every output for one parameter set. Fails when the slices have the wrong
    /// lengths or an output is not finite.
    #[inline]
    pub fn eval(&self, inputs: &[f64], outputs: &mut [f64]) -> Result<(), NumericError> {
        self.eval_set(inputs, outputs, 0)
    }

    /// [`NativeTape::eval`] for parameter set number `set` (named in the error).
    #[inline]
    pub(super) fn eval_set(
        &self,
        inputs: &[f64],
        outputs: &mut [f64],
        set: usize,
    ) -> Result<(), NumericError> {
        if inputs.len() != self.n_inputs {
            return Err(length_error("tape inputs", self.n_inputs, inputs.len()));
        }
        if outputs.len() != self.n_outputs {
            return Err(length_error("tape outputs", self.n_outputs, outputs.len()));
        }
        // SAFETY: `function` follows the calling convention of this file for `n_inputs` and
        // `n_outputs` (the contract of `from_module`), so it reads exactly
        // `inputs[0..n_inputs]` and writes exactly `outputs[0..n_outputs]`; both slices were
        // just checked to have those lengths, the pointers come from live slices (aligned,
        // non-null even when empty), and `outputs` is borrowed mutably so nothing else
        // aliases it. The code it points into is owned by `self.module`, alive while `self`
        // is borrowed.
        let all_finite = unsafe { (self.function)(inputs.as_ptr(), outputs.as_mut_ptr()) };
        if all_finite != 0 {
            return Ok(());
        }
        // Only now, on the way to an error, are the outputs read back to name the first
        // non-finite one.
        match outputs.iter().position(|v| !v.is_finite()) {
            Some(k) => Err(non_finite_output(outputs[k], k, set)),
            None => unreachable!("the compiled code flags a non-finite output only if one is"),
        }
    }
}

impl Drop for NativeTape {
    fn drop(&mut self) {
        if let Some(module) = self.module.take() {
            let module = module.into_inner().unwrap_or_else(|e| e.into_inner());
            // SAFETY: the only pointer into this module's memory is `self.function`, which
            // is never called again (`self` is being dropped, and `eval` borrows `self`, so
            // no call is running on any thread).
            unsafe { module.free_memory() };
        }
    }
}

impl fmt::Debug for NativeTape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("NativeTape")
            .field("n_inputs", &self.n_inputs)
            .field("n_outputs", &self.n_outputs)
            .finish_non_exhaustive()
    }
}
