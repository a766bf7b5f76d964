//! The order in which the native code computes a tape's registers: depth first from each
//! output, the operand that needs more registers first (Sethi–Ullman), so that few values
//! are live at once.
//!
//! The tape itself is ordered by dependency level (`builder::schedule`), which suits
//! the interpreter (runs of one opcode) but keeps every value of a level live together: on
//! the general Euler tape, the eight products of the first level and the inputs still
//! needed overflowed the sixteen floating-point registers of x86-64, and the compiled code
//! spilled four of them to the stack (4.9 ns a call); in this order, two (4.4 ns).
//!
//! The need of a register is the Sethi–Ullman number, generalised to three operands:
//!
//! ```text
//! need(input) = need(constant) = 1
//! need(op(a₁, …, a_k)) = max_j (n_j + j − 1)    with n₁ ≥ n₂ ≥ … the operands' needs
//! ```
//!
//! (exact for trees; on a tape, whose values are shared, a good heuristic). Any order in
//! which each register follows its operands computes the same values bit for bit, since
//! every instruction is the same operation on the same operands.

use super::interpreter::{Instruction, Tape};
use smallvec::SmallVec;

/// The operands of `instruction`, in order.
fn operands(instruction: Instruction) -> SmallVec<[u32; 3]> {
    let mut operands = SmallVec::new();
    instruction.map_registers(|r| {
        operands.push(r);
        r
    });
    operands
}

/// The Sethi–Ullman need of every register of the tape (see the module documentation).
fn needs(instructions: &[Instruction]) -> Vec<u32> {
    let mut need: Vec<u32> = Vec::with_capacity(instructions.len());
    for &instruction in instructions {
        let mut operand_needs: SmallVec<[u32; 3]> = operands(instruction)
            .iter()
            .map(|&r| need[r as usize])
            .collect();
        operand_needs.sort_unstable_by(|a, b| b.cmp(a));
        let own = operand_needs
            .iter()
            .enumerate()
            .map(|(j, &n)| n + j as u32)
            .max()
            .unwrap_or(1);
        need.push(own);
    }
    need
}

/// Every register the outputs need, each after its operands: first those of output 0, in
/// depth-first order, then those output 1 needs beyond them, and so on.
///
/// Uses an explicit stack, so the order itself puts no bound on a tape's depth.
pub(super) fn depth_first_order(tape: &Tape) -> Vec<u32> {
    let instructions = tape.instructions();
    let need = needs(instructions);
    let mut placed = vec![false; instructions.len()];
    // (register, whether its operands have been pushed already)
    let mut stack: Vec<(u32, bool)> = Vec::new();
    let mut order = Vec::with_capacity(instructions.len());
    for &output in tape.output_registers() {
        stack.push((output, false));
        while let Some((r, expanded)) = stack.pop() {
            if placed[r as usize] {
                continue;
            }
            if expanded {
                placed[r as usize] = true;
                order.push(r);
                continue;
            }
            stack.push((r, true));
            // Pushed by increasing need, so the operand that needs the most is visited
            // first; among equals, the first operand first.
            let mut pending = operands(instructions[r as usize]);
            pending.retain(|&mut a| !placed[a as usize]);
            pending.reverse();
            pending.sort_by_key(|&a| need[a as usize]);
            stack.extend(pending.into_iter().map(|a| (a, false)));
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::{Expr, Symbol};

    /// Each register comes after its operands, every register an output needs comes
    /// exactly once, and no other register comes at all.
    #[test]
    fn every_register_follows_its_operands_once() {
        let s = Expr::symbol;
        let shared = s("a") * s("b") + s("c");
        let outputs = [
            &shared * s("d") - s("e") * s("f") * s("g"),
            &shared + s("a") * s("g"),
            s("b").powi(5) / (s("c") + s("d")),
        ];
        let inputs = ["a", "b", "c", "d", "e", "f", "g", "unused"].map(Symbol::new);
        let tape = Tape::compile(&outputs, &inputs).expect("valid tape");
        let mut seen = vec![false; tape.instruction_count()];
        for r in depth_first_order(&tape) {
            assert!(!seen[r as usize], "register {r} computed twice");
            for a in operands(tape.instructions()[r as usize]) {
                assert!(seen[a as usize], "register {r} before its operand {a}");
            }
            seen[r as usize] = true;
        }
        for &output in tape.output_registers() {
            assert!(seen[output as usize], "output register {output}");
        }
        let needed = |r: usize| seen[r];
        for (r, instruction) in tape.instructions().iter().enumerate() {
            if let Instruction::Input(k) = instruction {
                assert_eq!(needed(r), *k != 7, "input {k}");
            }
        }
    }

    /// The classic case: in `(a·b)·(c·d) + e` the deeper operand goes first.
    #[test]
    fn need_is_the_sethi_ullman_number() {
        use Instruction::*;
        let tape = [
            Input(0),
            Input(1),
            Mul(0, 1),
            Input(2),
            Input(3),
            Mul(3, 4),
            Mul(2, 5),
            Input(4),
            Add(7, 6),
            MulAdd(0, 1, 2),
        ];
        assert_eq!(needs(&tape), vec![1, 1, 2, 1, 1, 2, 3, 1, 3, 3]);
    }
}
