//! Compiling expressions into a [`Tape`]: exact substitution of fixed values, then one
//! instruction per distinct value.
//!
//! - Fixed symbols are replaced by their exact values with `Expr::subs` before anything is
//!   emitted, so the canonical form drops every term they make zero (principal axes:
//!   `I_xy = I_yz = I_xz = 0` remove all product-of-inertia terms).
//! - Common subexpressions are shared across all outputs twice over: every distinct
//!   subexpression (`Expr` is hashed) is compiled once, and every distinct instruction
//!   (opcode and operands, commutative operands ordered) is emitted once (value numbering).
//!   Products are multiplied from their last factor to their first, so terms that differ
//!   only in their leading factor (`I_xz ω_x ω_y`, `I_yz ω_x ω_y`) share `ω_x ω_y`.
//! - Sums are factored greedily (`f·a + f·b + c = f·(a + b) + c`, the most common factor
//!   first), which turns the expanded `Ω × ([I]ω)` back into products with `H` and shares
//!   `H` between components; a cofactor and its negation share one register.
//! - The parts of a sum are combined shallowest first: the two partial sums with the
//!   shortest chains of instructions behind them are added (or subtracted) first, as in
//!   Huffman coding. Terms ready together form a balanced tree and a term at the end of a
//!   long chain is added last, which shortens the critical path of compiled code (the
//!   native tape) without adding instructions beyond a chain's.
//! - Constants are folded exactly by the algebra; a term with a negative coefficient is
//!   subtracted, `-1·x` is a negation and factors with negative exponents go to one
//!   denominator (`a b / (c d²)`).
//! - `x^n` for `|n| ≤ 16` is a multiplication chain by repeated squaring (`x⁴ = (x²)²`),
//!   larger integers use `powi`, `x^(m/2)` is `sqrt(x)^m`, `x^-n` is `1 / x^n`, and any
//!   other exponent is `powf`.
//! - A product used only by one sum is fused into it (`x + a·b`, `x - a·b`: one
//!   instruction, the same two roundings).
//! - Finally the instructions are ordered by dependency level and, within a level, by
//!   opcode, so that the evaluator meets runs of one kind.
//! - A rational constant that `f64` holds exactly is one constant; otherwise `p/q` with exact
//!   integers is a division evaluated in the scalar's own precision.

use super::interpreter::{Instruction, Tape};
use crate::algebra::{Expr, Func, Symbol, View, Q};
use crate::numeric::error::NumericError;
use std::collections::HashMap;

/// Largest exponent written as a multiplication chain rather than `powi`.
const MAX_CHAIN_EXPONENT: i64 = 16;
/// Integers below this magnitude are exact in `f64`.
const EXACT_F64_INTEGER: i64 = 1 << 53;

impl Tape {
    /// Compiles `outputs` as functions of `inputs` (input `k` of a parameter set is
    /// `inputs[k]`). Fails for a symbol that is not an input, for a repeated input and for
    /// an empty list of outputs.
    pub fn compile(outputs: &[Expr], inputs: &[Symbol]) -> Result<Tape, NumericError> {
        Tape::compile_with(outputs, inputs, &[])
    }

    /// Like [`Tape::compile`], with the symbols in `fixed` replaced by their exact values
    /// first. A fixed symbol may also be listed as an input (so tapes with and without the
    /// fixing take the same parameter sets); its input is then never read.
    pub fn compile_with(
        outputs: &[Expr],
        inputs: &[Symbol],
        fixed: &[(Symbol, Q)],
    ) -> Result<Tape, NumericError> {
        if outputs.is_empty() {
            return Err(invalid("tape outputs", "at least one expression is needed"));
        }
        refuse_repeats("tape inputs", inputs.iter().copied())?;
        refuse_repeats("fixed symbols", fixed.iter().map(|(s, _)| *s))?;
        let mut builder = Builder {
            inputs,
            instructions: Vec::new(),
            depths: Vec::new(),
            by_expr: HashMap::new(),
            by_instruction: HashMap::new(),
        };
        let mut registers = Vec::with_capacity(outputs.len());
        for (k, output) in outputs.iter().enumerate() {
            let value = |s: Symbol| {
                fixed
                    .iter()
                    .find(|(f, _)| *f == s)
                    .map(|(_, q)| Expr::num(q.clone()))
            };
            let substituted = output
                .subs(&value)
                .map_err(|e| NumericError::InvalidInput {
                    what: format!("tape output {k} with the fixed values"),
                    reason: e.to_string(),
                })?;
            if let Some(s) = substituted
                .symbols()
                .into_iter()
                .find(|s| !inputs.contains(s) && !s.is_pi())
            {
                return Err(NumericError::InvalidInput {
                    what: format!("symbol `{}` in tape output {k}", s.name()),
                    reason: "is neither an input nor fixed".into(),
                });
            }
            registers.push(builder.expr(&substituted)?);
        }
        let fused = fuse_multiply_add(&builder.instructions, &registers);
        let (instructions, registers) = schedule(&fused, &registers);
        Ok(Tape::from_parts(instructions, registers, inputs.len()))
    }
}

fn invalid(what: &str, reason: &str) -> NumericError {
    NumericError::InvalidInput {
        what: what.into(),
        reason: reason.into(),
    }
}

fn refuse_repeats(what: &str, symbols: impl Iterator<Item = Symbol>) -> Result<(), NumericError> {
    let mut seen: Vec<Symbol> = Vec::new();
    for s in symbols {
        if seen.contains(&s) {
            return Err(NumericError::InvalidInput {
                what: what.into(),
                reason: format!("`{}` is listed twice", s.name()),
            });
        }
        seen.push(s);
    }
    Ok(())
}

/// Merges a product used only by one sum into it: `x + a·b` becomes `MulAdd(a, b, x)` and
/// `x - a·b` becomes `MulSub(a, b, x)` (same roundings, one dispatch fewer). The product is
/// left in place unused; [`schedule`] drops it.
fn fuse_multiply_add(instructions: &[Instruction], outputs: &[u32]) -> Vec<Instruction> {
    let mut uses = vec![0usize; instructions.len()];
    for instruction in instructions {
        instruction.map_registers(|r| {
            uses[r as usize] += 1;
            r
        });
    }
    for &r in outputs {
        uses[r as usize] += 1;
    }
    let single_product = |r: u32| match instructions[r as usize] {
        Instruction::Mul(a, b) if uses[r as usize] == 1 => Some((a, b)),
        _ => None,
    };
    instructions
        .iter()
        .map(|&instruction| match instruction {
            Instruction::Add(x, y) => match (single_product(x), single_product(y)) {
                (_, Some((a, b))) => Instruction::MulAdd(a, b, x),
                (Some((a, b)), None) => Instruction::MulAdd(a, b, y),
                (None, None) => instruction,
            },
            Instruction::Sub(x, y) => match single_product(y) {
                Some((a, b)) => Instruction::MulSub(a, b, x),
                None => instruction,
            },
            other => other,
        })
        .collect()
}

/// Drops instructions no output depends on, then orders the rest by dependency level
/// (inputs and constants first, then what depends only on them, ...) and, within a level,
/// by opcode. Instructions of one level are
/// independent, so this is a valid order; runs of one opcode make the evaluator's dispatch
/// branch predictable. Returns the instructions and the outputs renumbered.
fn schedule(instructions: &[Instruction], outputs: &[u32]) -> (Vec<Instruction>, Vec<u32>) {
    let mut live = vec![false; instructions.len()];
    for &r in outputs {
        live[r as usize] = true;
    }
    for i in (0..instructions.len()).rev() {
        if live[i] {
            instructions[i].map_registers(|r| {
                live[r as usize] = true;
                r
            });
        }
    }
    let mut levels: Vec<u32> = Vec::with_capacity(instructions.len());
    for instruction in instructions {
        let mut level = 0;
        instruction.map_registers(|r| {
            level = level.max(levels[r as usize] + 1);
            r
        });
        levels.push(level);
    }
    let mut order: Vec<usize> = (0..instructions.len()).filter(|&i| live[i]).collect();
    order.sort_by_key(|&i| (levels[i], key(instructions[i]).0, i));
    let mut position = vec![0u32; instructions.len()];
    for (new, &old) in order.iter().enumerate() {
        position[old] = new as u32;
    }
    let reordered = order
        .iter()
        .map(|&old| instructions[old].map_registers(|r| position[r as usize]))
        .collect();
    let outputs = outputs.iter().map(|&r| position[r as usize]).collect();
    (reordered, outputs)
}

/// The non-numeric factor occurring in most of `terms`, when some occurs in at least two
/// (ties go to the first in the canonical order, so compilation is deterministic).
fn most_common_factor(terms: &[Expr]) -> Option<Expr> {
    let mut counts: HashMap<&Expr, usize> = HashMap::new();
    for t in terms {
        for f in t.coeff_and_factors().1 {
            *counts.entry(f).or_default() += 1;
        }
    }
    counts
        .into_iter()
        .filter(|&(_, n)| n >= 2)
        .max_by(|a, b| a.1.cmp(&b.1).then_with(|| b.0.cmp(a.0)))
        .map(|(f, _)| f.clone())
}

/// `term / factor` for a term that has `factor` among its factors.
fn cofactor(term: &Expr, factor: &Expr) -> Expr {
    let (coefficient, factors) = term.coeff_and_factors();
    let at = factors.iter().position(|f| f == factor);
    let others = factors
        .iter()
        .enumerate()
        .filter(|&(i, _)| Some(i) != at)
        .map(|(_, f)| f.clone());
    Expr::mul_all(std::iter::once(Expr::num(coefficient)).chain(others))
}

/// What identifies an instruction for value numbering: opcode, operands, and a constant by
/// its bit pattern.
type InstructionKey = (u8, u64, u64);

fn key(instruction: Instruction) -> InstructionKey {
    use Instruction::*;
    let r = u64::from;
    match instruction {
        Input(k) => (0, k as u64, 0),
        Const(c) => (1, c.to_bits(), 0),
        Add(a, b) => (2, r(a), r(b)),
        Sub(a, b) => (3, r(a), r(b)),
        Mul(a, b) => (4, r(a), r(b)),
        Div(a, b) => (5, r(a), r(b)),
        Neg(a) => (6, r(a), 0),
        Powi(a, n) => (7, r(a), n as u64),
        Sqrt(a) => (8, r(a), 0),
        Powf(a, b) => (9, r(a), r(b)),
        MulAdd(a, b, c) => (14, r(a) << 32 | r(b), r(c)),
        MulSub(a, b, c) => (15, r(a) << 32 | r(b), r(c)),
        Sin(a) => (10, r(a), 0),
        Cos(a) => (11, r(a), 0),
        Tan(a) => (12, r(a), 0),
        Abs(a) => (13, r(a), 0),
        Acos(a) => (16, r(a), 0),
        Atan(a) => (17, r(a), 0),
    }
}

struct Builder<'a> {
    inputs: &'a [Symbol],
    instructions: Vec<Instruction>,
    /// The length of the longest chain of instructions ending in each register (inputs and
    /// constants have depth 0).
    depths: Vec<u32>,
    by_expr: HashMap<Expr, u32>,
    by_instruction: HashMap<InstructionKey, u32>,
}

impl Builder<'_> {
    /// The register of `instruction`, emitting it unless an identical one exists.
    fn emit(&mut self, instruction: Instruction) -> u32 {
        let instruction = match instruction {
            Instruction::Add(a, b) => Instruction::Add(a.min(b), a.max(b)),
            Instruction::Mul(a, b) => Instruction::Mul(a.min(b), a.max(b)),
            other => other,
        };
        let next = self.instructions.len() as u32;
        let register = *self.by_instruction.entry(key(instruction)).or_insert(next);
        if register == next {
            let mut depth = 0;
            instruction.map_registers(|r| {
                depth = depth.max(self.depths[r as usize] + 1);
                r
            });
            self.instructions.push(instruction);
            self.depths.push(depth);
        }
        register
    }

    /// The register holding the value of `e` (whose symbols are all inputs).
    fn expr(&mut self, e: &Expr) -> Result<u32, NumericError> {
        if let Some(&register) = self.by_expr.get(e) {
            return Ok(register);
        }
        let register = match e.view() {
            View::Num(q) => self.constant(q)?,
            View::Sym(s) if s.is_pi() => self.emit(Instruction::Const(std::f64::consts::PI)),
            View::Sym(s) => {
                let k = self.inputs.iter().position(|&i| i == s).ok_or_else(|| {
                    NumericError::InvalidInput {
                        what: format!("symbol `{}`", s.name()),
                        reason: "is neither an input nor fixed".into(),
                    }
                })?;
                self.emit(Instruction::Input(k))
            }
            View::Add(terms) => self.sum(terms)?,
            View::Mul(_) => self.product(e)?,
            View::Pow(base, exponent) => self.power(base, exponent)?,
            View::Func(f, arg) => {
                let a = self.expr(arg)?;
                self.emit(match f {
                    Func::Sin => Instruction::Sin(a),
                    Func::Cos => Instruction::Cos(a),
                    Func::Tan => Instruction::Tan(a),
                    Func::Abs => Instruction::Abs(a),
                    Func::Acos => Instruction::Acos(a),
                    Func::Atan => Instruction::Atan(a),
                })
            }
        };
        self.by_expr.insert(e.clone(), register);
        Ok(register)
    }

    fn constant(&mut self, q: &Q) -> Result<u32, NumericError> {
        if let Q::Small(n, d) = *q {
            let exact_numerator = n.unsigned_abs() < EXACT_F64_INTEGER as u64;
            if exact_numerator && (d as u64).is_power_of_two() {
                return Ok(self.emit(Instruction::Const(n as f64 / d as f64)));
            }
            if exact_numerator && d < EXACT_F64_INTEGER {
                let p = self.emit(Instruction::Const(n as f64));
                let q = self.emit(Instruction::Const(d as f64));
                return Ok(self.emit(Instruction::Div(p, q)));
            }
        }
        let value = q.to_f64();
        if !value.is_finite() {
            return Err(NumericError::InvalidInput {
                what: format!("constant {q}"),
                reason: "is too large for floating point".into(),
            });
        }
        Ok(self.emit(Instruction::Const(value)))
    }

    /// A sum: common factors pulled out greedily (see [`Builder::sum_parts`]), then the
    /// two shallowest signed parts combined until one is left (`a + b`, `a - b`, or
    /// `-(a + b)` kept as a negative part), negated at the end only if every part is.
    fn sum(&mut self, terms: &[Expr]) -> Result<u32, NumericError> {
        let mut parts = Vec::new();
        self.sum_parts(terms, &mut parts)?;
        while parts.len() > 1 {
            // The deepest first (stable, so ties keep the order of the terms): the two
            // shallowest are at the end.
            parts.sort_by_key(|&(r, _)| std::cmp::Reverse(self.depths[r as usize]));
            let (Some((a, a_negative)), Some((b, b_negative))) = (parts.pop(), parts.pop()) else {
                break;
            };
            parts.push(match (a_negative, b_negative) {
                (false, false) => (self.emit(Instruction::Add(b, a)), false),
                (true, true) => (self.emit(Instruction::Add(b, a)), true),
                (false, true) => (self.emit(Instruction::Sub(a, b)), false),
                (true, false) => (self.emit(Instruction::Sub(b, a)), false),
            });
        }
        match parts.pop() {
            Some((sum, false)) => Ok(sum),
            Some((negated_sum, true)) => Ok(self.emit(Instruction::Neg(negated_sum))),
            None => self.constant(&Q::ZERO),
        }
    }

    /// Signed registers (`true` for minus) adding up to the sum of `terms`: the factor
    /// shared by most terms is pulled out, `f·a + f·b + c = f·(a + b) + c`, and the rest is
    /// factored again (a greedy multivariate Horner scheme). In the chapter's equations this
    /// recovers `Ω_y (-I_xz ω_x - I_yz ω_y + I_z ω_z) = Ω_y H_z` from the expanded form.
    fn sum_parts(
        &mut self,
        terms: &[Expr],
        parts: &mut Vec<(u32, bool)>,
    ) -> Result<(), NumericError> {
        let Some(common) = most_common_factor(terms) else {
            for t in terms {
                parts.push(self.signed(t)?);
            }
            return Ok(());
        };
        let (with, without): (Vec<&Expr>, Vec<&Expr>) = terms
            .iter()
            .partition(|t| t.coeff_and_factors().1.contains(&common));
        let cofactor = Expr::add_all(with.into_iter().map(|t| cofactor(t, &common)));
        let (c, negative) = self.signed(&cofactor)?;
        let f = self.expr(&common)?;
        parts.push((self.emit(Instruction::Mul(f, c)), negative));
        let rest: Vec<Expr> = without.into_iter().cloned().collect();
        self.sum_parts(&rest, parts)
    }

    /// `e` as a register and a sign, the register holding `e` or `-e` so that its leading
    /// coefficient is positive: `H` and `-H` share one register.
    fn signed(&mut self, e: &Expr) -> Result<(u32, bool), NumericError> {
        if e.terms()[0].coeff_and_factors().0.is_negative() {
            Ok((self.expr(&-e)?, true))
        } else {
            Ok((self.expr(e)?, false))
        }
    }

    /// A product: `coefficient · numerator / denominator`, each part multiplied from its
    /// last factor to its first.
    fn product(&mut self, e: &Expr) -> Result<u32, NumericError> {
        let (coefficient, factors) = e.coeff_and_factors();
        let mut numerator = Vec::new();
        let mut denominator = Vec::new();
        for f in factors {
            let (base, exponent) = f.base_and_exponent();
            match exponent.as_num() {
                Some(x) if x.is_negative() => {
                    let reciprocal = base.checked_pow(&-&exponent).map_err(|err| {
                        NumericError::InvalidInput {
                            what: format!("factor {f}"),
                            reason: err.to_string(),
                        }
                    })?;
                    denominator.push(self.expr(&reciprocal)?);
                }
                _ => numerator.push(self.expr(f)?),
            }
        }
        let mut value = self.multiply(&numerator);
        let negate = coefficient == Q::MINUS_ONE;
        if !coefficient.is_one() && !negate {
            let c = self.constant(&coefficient)?;
            value = Some(match value {
                Some(v) => self.emit(Instruction::Mul(c, v)),
                None => c,
            });
        }
        if let Some(d) = self.multiply(&denominator) {
            let n = match value {
                Some(v) => v,
                None => self.constant(&Q::ONE)?,
            };
            value = Some(self.emit(Instruction::Div(n, d)));
        }
        // A canonical product has at least two factors, so `value` is set here.
        let value = match value {
            Some(v) => v,
            None => self.constant(&coefficient)?,
        };
        Ok(if negate {
            self.emit(Instruction::Neg(value))
        } else {
            value
        })
    }

    /// The product of registers, from the last to the first; `None` for no factors.
    fn multiply(&mut self, registers: &[u32]) -> Option<u32> {
        let (&last, rest) = registers.split_last()?;
        Some(
            rest.iter()
                .rev()
                .fold(last, |acc, &f| self.emit(Instruction::Mul(f, acc))),
        )
    }

    fn power(&mut self, base: &Expr, exponent: &Expr) -> Result<u32, NumericError> {
        let b = self.expr(base)?;
        let Some(q) = exponent.as_num() else {
            let x = self.expr(exponent)?;
            return Ok(self.emit(Instruction::Powf(b, x)));
        };
        let (root, n) = match (q.numer().to_i64(), q.denom().to_i64()) {
            (Some(n), Some(1)) => (b, n),
            (Some(n), Some(2)) => (self.emit(Instruction::Sqrt(b)), n),
            _ => {
                let x = self.constant(q)?;
                return Ok(self.emit(Instruction::Powf(b, x)));
            }
        };
        let magnitude = self.integer_power(root, n.unsigned_abs());
        Ok(if n < 0 {
            let one = self.constant(&Q::ONE)?;
            self.emit(Instruction::Div(one, magnitude))
        } else {
            magnitude
        })
    }

    /// `r^n` for `n ≥ 1`: repeated squaring up to [`MAX_CHAIN_EXPONENT`], `powi` beyond.
    fn integer_power(&mut self, r: u32, n: u64) -> u32 {
        if n > MAX_CHAIN_EXPONENT as u64 {
            if let Ok(n) = i32::try_from(n) {
                return self.emit(Instruction::Powi(r, n));
            }
            let x = self.emit(Instruction::Const(n as f64));
            return self.emit(Instruction::Powf(r, x));
        }
        let mut result: Option<u32> = None;
        let mut square = r;
        let mut rest = n;
        loop {
            if rest & 1 == 1 {
                result = Some(match result {
                    Some(acc) => self.emit(Instruction::Mul(acc, square)),
                    None => square,
                });
            }
            rest >>= 1;
            if rest == 0 {
                return result.unwrap_or(r);
            }
            square = self.emit(Instruction::Mul(square, square));
        }
    }
}
