//! Bounds on user input, checked before parsing so that no input can overflow the stack
//! or take unbounded time.

use super::diagnostic::Diagnostic;

/// Largest input accepted, in bytes.
pub const MAX_INPUT_BYTES: usize = 1 << 20;
/// Deepest nesting of parentheses and chained powers.
pub const MAX_NESTING: usize = 200;
/// Longest run of prefix signs (`- - x`).
pub const MAX_PREFIX_RUN: usize = 16;

/// Rejects input that is too large or nested too deeply, with the place where the limit
/// was crossed.
pub fn check_input(source_name: &str, source: &str) -> Result<(), Diagnostic> {
    if source.len() > MAX_INPUT_BYTES {
        return Err(Diagnostic::at(
            source_name,
            &source[..source.floor_char_boundary(256)],
            0,
            0,
            format!(
                "input is {} bytes, more than the limit of {} bytes",
                source.len(),
                MAX_INPUT_BYTES
            ),
        )
        .with_help("split the input into smaller expressions"));
    }
    // Chained powers nest like parentheses: count them per parenthesis level.
    let mut chains: Vec<usize> = vec![0];
    let mut previous_is_operand = false;
    let mut prefix_run = 0usize;
    let bytes = source.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        // The cross product × and the product sign · (two bytes each in UTF-8) are binary
        // operators, read here as the one-byte operator '/' (`**` is not matched after them).
        let c = match bytes[i..] {
            [0xC3, 0x97, ..] | [0xC2, 0xB7, ..] => {
                i += 1;
                b'/'
            }
            // The minus sign − (U+2212, three bytes), as typed from a word processor, is '-'.
            [0xE2, 0x88, 0x92, ..] => {
                i += 2;
                b'-'
            }
            _ => bytes[i],
        };
        let depth = chains.len() - 1;
        let too_deep = |what: &str| {
            Diagnostic::at(
                source_name,
                source,
                i,
                i + 1,
                format!("{what} nested more than {MAX_NESTING} levels deep"),
            )
            .with_help(
                "simplify the expression; no formula of this chapter needs that much nesting",
            )
        };
        match c {
            b'(' => {
                chains.push(0);
                if chains.len() - 1 > MAX_NESTING {
                    return Err(too_deep("parentheses"));
                }
                previous_is_operand = false;
            }
            b')' => {
                if chains.len() > 1 {
                    chains.pop();
                }
                previous_is_operand = true;
            }
            b'^' => {
                if let Some(chain) = chains.last_mut() {
                    *chain += 1;
                    if depth + *chain > MAX_NESTING {
                        return Err(too_deep("powers"));
                    }
                }
                previous_is_operand = false;
            }
            b'+' | b'-' | b'*' | b'/' | b'=' | b',' => {
                if c == b'*' && bytes.get(i + 1) == Some(&b'*') {
                    i += 1;
                    if let Some(chain) = chains.last_mut() {
                        *chain += 1;
                    }
                } else if previous_is_operand {
                    if let Some(chain) = chains.last_mut() {
                        *chain = 0;
                    }
                    prefix_run = 0;
                } else if c == b'+' || c == b'-' {
                    prefix_run += 1;
                    if prefix_run > MAX_PREFIX_RUN {
                        return Err(Diagnostic::at(
                            source_name,
                            source,
                            i,
                            i + 1,
                            format!("more than {MAX_PREFIX_RUN} signs in a row"),
                        ));
                    }
                }
                previous_is_operand = false;
            }
            b' ' | b'\t' | b'\r' | b'\n' => {}
            _ => {
                previous_is_operand = true;
                prefix_run = 0;
            }
        }
        i += 1;
    }
    Ok(())
}
