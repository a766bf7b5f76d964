//! A compiled expression: a flat instruction tape over registers.
//!
//! Register `i` holds the value of instruction `i` (static single assignment) and an
//! instruction reads only registers written before it, so evaluating the tape is one pass
//! over the instructions: `r_i = op_i(r_a, r_b)` with `a, b < i`. The outputs are named
//! registers. [`Tape::compile`](crate::numeric::tape::interpreter::Tape::compile) builds a tape from
//! expressions (see `builder.rs`); this file holds the tape and its evaluation.
//!
//! The evaluator is written once for a block of `L` parameter sets evaluated side by side
//! (each register holds `L` lanes): a single evaluation is the block of one lane, and the
//! batch evaluation (`batch.rs`) runs blocks of many lanes, where the per-instruction
//! dispatch is paid once per block and the lane loops vectorise.

use crate::numeric::error::NumericError;
use num_traits::Float;

/// One step of a tape. Operands are register numbers (instruction indices) of earlier
/// instructions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Instruction {
    /// Input `k` of the parameter set.
    Input(usize),
    /// A constant (exactly the rational it came from, or an exact integer; see the builder).
    Const(f64),
    Add(u32, u32),
    Sub(u32, u32),
    Mul(u32, u32),
    Div(u32, u32),
    Neg(u32),
    /// `r^n` for an integer too large for a multiplication chain.
    Powi(u32, i32),
    Sqrt(u32),
    /// `r_a^r_b` for a non-integer, non-half-integer exponent.
    Powf(u32, u32),
    /// `r_a·r_b + r_c` (rounded twice, as the separate operations: not a fused FMA).
    MulAdd(u32, u32, u32),
    /// `r_c - r_a·r_b` (rounded twice).
    MulSub(u32, u32, u32),
    Sin(u32),
    Cos(u32),
    Tan(u32),
    Abs(u32),
    Acos(u32),
    Atan(u32),
}

impl Instruction {
    /// The instruction with each operand register `r` replaced by `f(r)` (operands visited
    /// in order).
    pub(super) fn map_registers(self, mut f: impl FnMut(u32) -> u32) -> Instruction {
        use Instruction::*;
        match self {
            Input(_) | Const(_) => self,
            Add(a, b) => Add(f(a), f(b)),
            Sub(a, b) => Sub(f(a), f(b)),
            Mul(a, b) => Mul(f(a), f(b)),
            Div(a, b) => Div(f(a), f(b)),
            Powf(a, b) => Powf(f(a), f(b)),
            MulAdd(a, b, c) => MulAdd(f(a), f(b), f(c)),
            MulSub(a, b, c) => MulSub(f(a), f(b), f(c)),
            Neg(a) => Neg(f(a)),
            Powi(a, n) => Powi(f(a), n),
            Sqrt(a) => Sqrt(f(a)),
            Sin(a) => Sin(f(a)),
            Cos(a) => Cos(f(a)),
            Tan(a) => Tan(f(a)),
            Abs(a) => Abs(f(a)),
            Acos(a) => Acos(f(a)),
            Atan(a) => Atan(f(a)),
        }
    }
}

/// A compiled list of expressions of the same inputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Tape {
    instructions: Vec<Instruction>,
    outputs: Vec<u32>,
    n_inputs: usize,
    /// The input index of each leading input load (instructions `0..n` load these).
    leading_loads: Vec<usize>,
}

impl Tape {
    /// A tape from its parts; the builder guarantees that every operand and output names an
    /// earlier register and every input index is below `n_inputs`.
    pub(super) fn from_parts(
        instructions: Vec<Instruction>,
        outputs: Vec<u32>,
        n_inputs: usize,
    ) -> Tape {
        let leading_loads = instructions
            .iter()
            .map_while(|i| match *i {
                Instruction::Input(k) => Some(k),
                _ => None,
            })
            .collect();
        Tape {
            instructions,
            outputs,
            n_inputs,
            leading_loads,
        }
    }

    pub fn instructions(&self) -> &[Instruction] {
        &self.instructions
    }

    pub fn instruction_count(&self) -> usize {
        self.instructions.len()
    }

    /// Number of inputs a parameter set must supply (the `inputs` given to `compile`).
    pub fn n_inputs(&self) -> usize {
        self.n_inputs
    }

    pub fn n_outputs(&self) -> usize {
        self.outputs.len()
    }

    /// The register holding each output, in output order (what the machine code returns).
    #[cfg(feature = "jit")]
    pub(super) fn output_registers(&self) -> &[u32] {
        &self.outputs
    }

    /// Whether any instruction loads input `k`.
    pub fn reads_input(&self, k: usize) -> bool {
        self.instructions.contains(&Instruction::Input(k))
    }

    /// Evaluates every output for one parameter set. Allocates its registers; a loop should
    /// use [`Tape::eval_with`].
    pub fn eval<T: Float>(&self, inputs: &[T], outputs: &mut [T]) -> Result<(), NumericError> {
        self.eval_with(inputs, outputs, &mut Vec::new())
    }

    /// Evaluates every output for one parameter set, with `scratch` as the registers (it is
    /// resized on the first call and then reused without allocating). Fails when the slices
    /// have the wrong lengths or an output is not finite.
    pub fn eval_with<T: Float>(
        &self,
        inputs: &[T],
        outputs: &mut [T],
        scratch: &mut Vec<T>,
    ) -> Result<(), NumericError> {
        if inputs.len() != self.n_inputs {
            return Err(length_error("tape inputs", self.n_inputs, inputs.len()));
        }
        if outputs.len() != self.outputs.len() {
            return Err(length_error(
                "tape outputs",
                self.outputs.len(),
                outputs.len(),
            ));
        }
        self.run_block::<T, 1>(inputs, self.n_inputs.max(1), scratch);
        self.read_outputs::<T, 1>(scratch, outputs, 0)
    }

    /// Runs the tape on `L` parameter sets at once: set `l` has its inputs at
    /// `inputs[l * stride..][..n_inputs]` (`stride ≥ 1`). Register `i` lane `l` ends in
    /// `scratch[i * L + l]`.
    pub(super) fn run_block<T: Float, const L: usize>(
        &self,
        inputs: &[T],
        stride: usize,
        scratch: &mut Vec<T>,
    ) {
        let size = self.instructions.len() * L;
        if scratch.len() != size {
            scratch.clear();
            scratch.resize(size, T::zero());
        }
        let (registers, _) = scratch.as_chunks_mut::<L>();
        // The leading loads read each parameter set's row in order (not input by input
        // across rows, which strides through memory).
        for (l, row) in inputs.chunks(stride).take(L).enumerate() {
            for (register, &k) in registers.iter_mut().zip(&self.leading_loads) {
                register[l] = row[k];
            }
        }
        let loaded = self.leading_loads.len();
        for (i, instruction) in self.instructions.iter().enumerate().skip(loaded) {
            let (done, rest) = registers.split_at_mut(i);
            let out = &mut rest[0];
            let r = |a: u32| &done[a as usize];
            match *instruction {
                Instruction::Input(k) => {
                    for (l, o) in out.iter_mut().enumerate() {
                        *o = inputs[l * stride + k];
                    }
                }
                Instruction::Const(c) => *out = [T::from(c).unwrap_or_else(T::nan); L],
                Instruction::Add(a, b) => lanes2(out, r(a), r(b), |x, y| x + y),
                Instruction::Sub(a, b) => lanes2(out, r(a), r(b), |x, y| x - y),
                Instruction::Mul(a, b) => lanes2(out, r(a), r(b), |x, y| x * y),
                Instruction::Div(a, b) => lanes2(out, r(a), r(b), |x, y| x / y),
                Instruction::Powf(a, b) => lanes2(out, r(a), r(b), T::powf),
                Instruction::MulAdd(a, b, c) => lanes3(out, r(a), r(b), r(c), |x, y, z| x * y + z),
                Instruction::MulSub(a, b, c) => lanes3(out, r(a), r(b), r(c), |x, y, z| z - x * y),
                Instruction::Neg(a) => lanes1(out, r(a), |x| -x),
                Instruction::Powi(a, n) => lanes1(out, r(a), |x| x.powi(n)),
                Instruction::Sqrt(a) => lanes1(out, r(a), T::sqrt),
                Instruction::Sin(a) => lanes1(out, r(a), T::sin),
                Instruction::Cos(a) => lanes1(out, r(a), T::cos),
                Instruction::Tan(a) => lanes1(out, r(a), T::tan),
                Instruction::Abs(a) => lanes1(out, r(a), T::abs),
                Instruction::Acos(a) => lanes1(out, r(a), T::acos),
                Instruction::Atan(a) => lanes1(out, r(a), T::atan),
            }
        }
    }

    /// Copies the outputs of a block run by [`Tape::run_block`] into `outputs` (set after
    /// set), refusing a value that is not finite; `first_set` numbers the block's first
    /// parameter set in the message.
    pub(super) fn read_outputs<T: Float, const L: usize>(
        &self,
        scratch: &[T],
        outputs: &mut [T],
        first_set: usize,
    ) -> Result<(), NumericError> {
        let (registers, _) = scratch.as_chunks::<L>();
        let lanes = outputs.chunks_exact_mut(self.outputs.len()).take(L);
        for (l, set_outputs) in lanes.enumerate() {
            for (k, (out, &reg)) in set_outputs.iter_mut().zip(&self.outputs).enumerate() {
                let value = registers[reg as usize][l];
                if !value.is_finite() {
                    return Err(non_finite_output(value, k, first_set + l));
                }
                *out = value;
            }
        }
        Ok(())
    }
}

fn lanes1<T: Copy, const L: usize>(out: &mut [T; L], x: &[T; L], f: impl Fn(T) -> T) {
    for (o, &a) in out.iter_mut().zip(x) {
        *o = f(a);
    }
}

fn lanes2<T: Copy, const L: usize>(
    out: &mut [T; L],
    x: &[T; L],
    y: &[T; L],
    f: impl Fn(T, T) -> T,
) {
    for ((o, &a), &b) in out.iter_mut().zip(x).zip(y) {
        *o = f(a, b);
    }
}

fn lanes3<T: Copy, const L: usize>(
    out: &mut [T; L],
    x: &[T; L],
    y: &[T; L],
    z: &[T; L],
    f: impl Fn(T, T, T) -> T,
) {
    for (((o, &a), &b), &c) in out.iter_mut().zip(x).zip(y).zip(z) {
        *o = f(a, b, c);
    }
}

/// The error for output `output` of parameter set `set` being the non-finite `value`
/// (shared by every evaluator of a tape, so they refuse the same values alike).
#[cold]
pub(super) fn non_finite_output<T: Float>(value: T, output: usize, set: usize) -> NumericError {
    NumericError::InvalidInput {
        what: format!("tape output {output} of parameter set {set}"),
        reason: format!(
            "is {} (a singular or non-finite input)",
            if value.is_nan() { "NaN" } else { "infinite" }
        ),
    }
}

#[cold]
pub(super) fn length_error(what: &str, expected: usize, got: usize) -> NumericError {
    NumericError::InvalidInput {
        what: what.into(),
        reason: format!("expected {expected} values, got {got}"),
    }
}
