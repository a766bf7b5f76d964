//! Compiling a [`Tape`] to machine code with Cranelift (a JIT): one function per tape,
//!
//! ```text
//! extern "C" fn(inputs: *const f64, outputs: *mut f64) -> u8   // 1: every output finite
//! ```
//!
//! in a single basic block, its registers computed depth first from each output in turn
//! (`native_schedule`, which keeps few values live). Each arithmetic instruction is the
//! matching Cranelift float instruction (`fadd`, `fsub`, `fmul`, `fdiv`, `fneg`, `fabs`,
//! `sqrt`); `Input(k)` loads `inputs[k]` where it is first used. Output `k` is stored to
//! `outputs[k]` at the end, after every load: a load that follows a store the processor
//! cannot yet tell apart from it waits (storing each output as soon as it was known, before
//! the next output's loads, took the general Euler tape from 4.4 to 6.6 ns). The function
//! returns whether `Σ (o_k − o_k)` is a number, that is whether every output is finite (`o − o` is 0 for a finite `o` and NaN for ±∞ or
//! NaN), so the caller need not read the outputs back to check them.
//!
//! Cranelift's optimiser is off (`opt_level = none`): the tape is already free of common
//! subexpressions and constant-folded, and the optimiser's only effect on these bodies was
//! to merge and hoist the input loads to the top, where their long lives spilled registers.
//!
//! Rounding contract: the compiled code computes the interpreter's `f64` values bit for
//! bit. `MulAdd(a, b, c)` is `fmul` then `fadd` and `MulSub` is `fmul` then `fsub` (two
//! roundings, as the interpreter, not a fused multiply-add); Cranelift does not reassociate
//! or contract floating-point arithmetic. `sin`, `cos`, `tan`, `powf` and `powi` call the
//! Rust functions the interpreter calls (`f64::sin`, ..., `f64::powi`) through the
//! `extern "C"` helpers below, registered with the JIT as symbols.

use super::interpreter::{Instruction, Tape};
use super::native::{NativeFunction, NativeTape};
use super::native_schedule::depth_first_order;
use crate::numeric::error::NumericError;
use cranelift_codegen::ir::condcodes::FloatCC;
use cranelift_codegen::ir::{types, AbiParam, FuncRef, InstBuilder, MemFlags, Value};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{default_libcall_names, FuncId, Linkage, Module};
use std::sync::OnceLock;

/// A Rust function the compiled code calls for an instruction with no native equivalent.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Helper {
    Sin,
    Cos,
    Tan,
    Acos,
    Atan,
    Powf,
    Powi,
}

impl Helper {
    /// Every helper, in declaration order (so `helper as usize` indexes this array).
    const ALL: [Helper; 7] = [
        Helper::Sin,
        Helper::Cos,
        Helper::Tan,
        Helper::Acos,
        Helper::Atan,
        Helper::Powf,
        Helper::Powi,
    ];

    fn symbol(self) -> &'static str {
        match self {
            Helper::Sin => "kinetics_tape_sin",
            Helper::Cos => "kinetics_tape_cos",
            Helper::Tan => "kinetics_tape_tan",
            Helper::Acos => "kinetics_tape_acos",
            Helper::Atan => "kinetics_tape_atan",
            Helper::Powf => "kinetics_tape_powf",
            Helper::Powi => "kinetics_tape_powi",
        }
    }

    fn address(self) -> *const u8 {
        match self {
            Helper::Sin => tape_sin as *const u8,
            Helper::Cos => tape_cos as *const u8,
            Helper::Tan => tape_tan as *const u8,
            Helper::Acos => tape_acos as *const u8,
            Helper::Atan => tape_atan as *const u8,
            Helper::Powf => tape_powf as *const u8,
            Helper::Powi => tape_powi as *const u8,
        }
    }

    /// The type of the second argument (`f64` → `f64` for the one-argument helpers).
    fn second_argument(self) -> Option<types::Type> {
        match self {
            Helper::Sin | Helper::Cos | Helper::Tan | Helper::Acos | Helper::Atan => None,
            Helper::Powf => Some(types::F64),
            Helper::Powi => Some(types::I32),
        }
    }
}

extern "C" fn tape_sin(x: f64) -> f64 {
    x.sin()
}

extern "C" fn tape_cos(x: f64) -> f64 {
    x.cos()
}

extern "C" fn tape_tan(x: f64) -> f64 {
    x.tan()
}

extern "C" fn tape_acos(x: f64) -> f64 {
    x.acos()
}

extern "C" fn tape_atan(x: f64) -> f64 {
    x.atan()
}

extern "C" fn tape_powf(x: f64, y: f64) -> f64 {
    x.powf(y)
}

extern "C" fn tape_powi(x: f64, n: i32) -> f64 {
    x.powi(n)
}

impl Tape {
    /// Compiles the tape to machine code for `f64` (see [`NativeTape`]). Fails on a host
    /// Cranelift does not support or when code generation fails.
    ///
    /// ```
    /// use kinetics::algebra::{Expr, Symbol};
    /// use kinetics::numeric::Tape;
    ///
    /// // ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z
    /// let s = Expr::symbol;
    /// let m_x = s("I_x") * s("wdot_x") - (s("I_y") - s("I_z")) * s("w_y") * s("w_z");
    /// let inputs = ["I_x", "I_y", "I_z", "wdot_x", "w_y", "w_z"].map(Symbol::new);
    /// let tape = Tape::compile(&[m_x], &inputs)?;
    /// let native = tape.compile_native()?;
    /// let mut out = [0.0];
    /// native.eval(&[1.0, 2.0, 3.0, 0.5, 2.0, 4.0], &mut out)?;
    /// assert_eq!(out[0], 1.0 * 0.5 - (2.0 - 3.0) * 2.0 * 4.0);
    /// // A non-finite result is an error, as in the interpreter.
    /// assert!(native.eval(&[f64::INFINITY, 2.0, 3.0, 0.5, 2.0, 4.0], &mut out).is_err());
    /// # Ok::<(), kinetics::numeric::NumericError>(())
    /// ```
    pub fn compile_native(&self) -> Result<NativeTape, NumericError> {
        let mut builder = JITBuilder::with_isa(host_isa()?, default_libcall_names());
        for helper in Helper::ALL {
            builder.symbol(helper.symbol(), helper.address());
        }
        let mut module = JITModule::new(builder);
        let helpers = Helper::ALL
            .into_iter()
            .map(|helper| declare_helper(&mut module, helper))
            .collect::<Result<Vec<_>, _>>()?;

        let mut context = module.make_context();
        let pointer = module.target_config().pointer_type();
        context.func.signature.params = vec![AbiParam::new(pointer), AbiParam::new(pointer)];
        context.func.signature.returns = vec![AbiParam::new(types::I8)];
        let function = module
            .declare_function("tape", Linkage::Local, &context.func.signature)
            .map_err(codegen_error)?;
        let mut function_context = FunctionBuilderContext::new();
        let mut body = FunctionBuilder::new(&mut context.func, &mut function_context);
        let block = body.create_block();
        body.append_block_params_for_function_params(block);
        body.switch_to_block(block);
        body.seal_block(block);
        let (inputs, outputs) = (body.block_params(block)[0], body.block_params(block)[1]);

        let mut lowering = Lowering {
            module: &mut module,
            body,
            helpers: &helpers,
            inputs,
            imported: [None; Helper::ALL.len()],
            registers: vec![Register::NotYet; self.instruction_count()],
        };
        for r in depth_first_order(self) {
            lowering.registers[r as usize] =
                lowering.instruction(self.instructions()[r as usize])?;
        }
        // Σ (o − o) over the outputs is 0 when every output is finite and NaN otherwise.
        let mut non_finite_sum = None;
        for (k, &output) in self.output_registers().iter().enumerate() {
            let value = lowering.operand(output);
            let offset = byte_offset(k)?;
            let body = &mut lowering.body;
            body.ins()
                .store(MemFlags::trusted(), value, outputs, offset);
            let zero_if_finite = body.ins().fsub(value, value);
            non_finite_sum = Some(match non_finite_sum {
                None => zero_if_finite,
                Some(sum) => body.ins().fadd(sum, zero_if_finite),
            });
        }
        let all_finite = match non_finite_sum {
            Some(sum) => lowering.body.ins().fcmp(FloatCC::Ordered, sum, sum),
            None => lowering.body.ins().iconst(types::I8, 1),
        };
        lowering.body.ins().return_(&[all_finite]);
        lowering.body.finalize();

        module
            .define_function(function, &mut context)
            .map_err(codegen_error)?;
        module.finalize_definitions().map_err(codegen_error)?;
        let code = module.get_finalized_function(function);
        // SAFETY: `code` is the function just defined with the signature
        // `(pointer, pointer) -> ()` in the host's default calling convention, which is the
        // C convention `NativeFunction` names; a code pointer and a function pointer have the
        // same size and representation on the hosts Cranelift supports.
        let function = unsafe { std::mem::transmute::<*const u8, NativeFunction>(code) };
        // SAFETY: the body above loads only `inputs[k]` for the `Input(k)` instructions of
        // the tape (`k < n_inputs`, guaranteed by the tape builder), stores only
        // `outputs[0..n_outputs]`, and calls only the pure helpers of this file; the code
        // lives in `module`, handed over with it.
        Ok(unsafe { NativeTape::from_module(module, function, self.n_inputs(), self.n_outputs()) })
    }
}

/// The code generator for this machine, configured once per process.
fn host_isa() -> Result<OwnedTargetIsa, NumericError> {
    static ISA: OnceLock<Result<OwnedTargetIsa, String>> = OnceLock::new();
    ISA.get_or_init(|| {
        let mut flags = settings::builder();
        for (name, value) in [
            ("opt_level", "none"),
            // The JIT patches absolute addresses of the helpers into the code.
            ("use_colocated_libcalls", "false"),
            ("is_pic", "false"),
        ] {
            flags.set(name, value).map_err(|e| e.to_string())?;
        }
        cranelift_native::builder()
            .map_err(str::to_owned)?
            .finish(settings::Flags::new(flags))
            .map_err(|e| e.to_string())
    })
    .clone()
    .map_err(|reason| NumericError::NativeCode { reason })
}

fn declare_helper(module: &mut JITModule, helper: Helper) -> Result<FuncId, NumericError> {
    let mut signature = module.make_signature();
    signature.params.push(AbiParam::new(types::F64));
    signature
        .params
        .extend(helper.second_argument().map(AbiParam::new));
    signature.returns.push(AbiParam::new(types::F64));
    module
        .declare_function(helper.symbol(), Linkage::Import, &signature)
        .map_err(codegen_error)
}

fn codegen_error(error: impl std::fmt::Display) -> NumericError {
    NumericError::NativeCode {
        reason: error.to_string(),
    }
}

/// The byte offset of element `k` of an `f64` array, as Cranelift's 32-bit immediate.
fn byte_offset(k: usize) -> Result<i32, NumericError> {
    k.checked_mul(size_of::<f64>())
        .and_then(|bytes| i32::try_from(bytes).ok())
        .ok_or_else(|| NumericError::NativeCode {
            reason: format!("element {k} is beyond a 32-bit offset"),
        })
}

/// The state of lowering one tape into one function body.
struct Lowering<'a> {
    module: &'a mut JITModule,
    body: FunctionBuilder<'a>,
    /// The helpers declared in the module, indexed by `helper as usize`.
    helpers: &'a [FuncId],
    /// The helpers imported into this function so far, by the same index.
    imported: [Option<FuncRef>; Helper::ALL.len()],
    /// The pointer to the inputs (the function's first parameter).
    inputs: Value,
    /// Each register of the tape as lowered so far.
    registers: Vec<Register>,
}

/// A register of the tape as lowered: a value, or an input not used yet. An input is loaded
/// where it is first used rather than all at the top, so that the 15 or so inputs of a
/// typical tape do not all hold a register from the start (on x86-64, 16 of them: loading
/// everything first spilled a quarter of the inputs of the general Euler tape to the stack).
#[derive(Debug, Clone, Copy)]
enum Register {
    /// Not lowered yet: the order of `native_schedule` lowers every register before its
    /// first use.
    NotYet,
    Value(Value),
    /// The byte offset of the input in the input array.
    Input(i32),
}

impl Lowering<'_> {
    /// The SSA value of register `a`; an input is loaded here on its first use (see
    /// [`Register::Input`]).
    fn operand(&mut self, a: u32) -> Value {
        match self.registers[a as usize] {
            Register::Value(value) => value,
            Register::Input(offset) => {
                let value =
                    self.body
                        .ins()
                        .load(types::F64, MemFlags::trusted(), self.inputs, offset);
                self.registers[a as usize] = Register::Value(value);
                value
            }
            Register::NotYet => unreachable!("register {a} is used before it is computed"),
        }
    }

    /// The register `instruction` defines, whose operands are all lowered already.
    fn instruction(&mut self, instruction: Instruction) -> Result<Register, NumericError> {
        use Instruction::*;
        let value = match instruction {
            Input(k) => return Ok(Register::Input(byte_offset(k)?)),
            Const(c) => self.body.ins().f64const(c),
            Add(a, b) => {
                let (a, b) = (self.operand(a), self.operand(b));
                self.body.ins().fadd(a, b)
            }
            Sub(a, b) => {
                let (a, b) = (self.operand(a), self.operand(b));
                self.body.ins().fsub(a, b)
            }
            Mul(a, b) => {
                let (a, b) = (self.operand(a), self.operand(b));
                self.body.ins().fmul(a, b)
            }
            Div(a, b) => {
                let (a, b) = (self.operand(a), self.operand(b));
                self.body.ins().fdiv(a, b)
            }
            MulAdd(a, b, c) => {
                let (a, b) = (self.operand(a), self.operand(b));
                let product = self.body.ins().fmul(a, b);
                let c = self.operand(c);
                self.body.ins().fadd(product, c)
            }
            MulSub(a, b, c) => {
                let (a, b) = (self.operand(a), self.operand(b));
                let product = self.body.ins().fmul(a, b);
                let c = self.operand(c);
                self.body.ins().fsub(c, product)
            }
            Neg(a) => {
                let a = self.operand(a);
                self.body.ins().fneg(a)
            }
            Abs(a) => {
                let a = self.operand(a);
                self.body.ins().fabs(a)
            }
            Sqrt(a) => {
                let a = self.operand(a);
                self.body.ins().sqrt(a)
            }
            Sin(a) => {
                let a = self.operand(a);
                self.call(Helper::Sin, &[a])
            }
            Cos(a) => {
                let a = self.operand(a);
                self.call(Helper::Cos, &[a])
            }
            Tan(a) => {
                let a = self.operand(a);
                self.call(Helper::Tan, &[a])
            }
            Acos(a) => {
                let a = self.operand(a);
                self.call(Helper::Acos, &[a])
            }
            Atan(a) => {
                let a = self.operand(a);
                self.call(Helper::Atan, &[a])
            }
            Powf(a, b) => {
                let (a, b) = (self.operand(a), self.operand(b));
                self.call(Helper::Powf, &[a, b])
            }
            Powi(a, n) => {
                let a = self.operand(a);
                let n = self.body.ins().iconst(types::I32, i64::from(n));
                self.call(Helper::Powi, &[a, n])
            }
        };
        Ok(Register::Value(value))
    }

    /// The result of calling `helper`, imported into the function on first use.
    fn call(&mut self, helper: Helper, arguments: &[Value]) -> Value {
        let index = helper as usize;
        let callee = match self.imported[index] {
            Some(callee) => callee,
            None => {
                let callee = self
                    .module
                    .declare_func_in_func(self.helpers[index], self.body.func);
                self.imported[index] = Some(callee);
                callee
            }
        };
        let call = self.body.ins().call(callee, arguments);
        self.body.inst_results(call)[0]
    }
}
