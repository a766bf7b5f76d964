//! Reading a command's mathematical input: an argument, or `-` for standard input.

use super::error::CliError;
use kinetics::parse::limits::MAX_INPUT_BYTES;
use std::io::Read;

/// The text of the argument, or all of standard input when it is `-`, with the name to use
/// in diagnostics. Standard input beyond the size limit is not read.
pub fn read(argument: &str) -> Result<(String, String), CliError> {
    if argument != "-" {
        return Ok(("input".into(), argument.to_string()));
    }
    let name = "<stdin>";
    let mut bytes = Vec::new();
    std::io::stdin()
        .take(MAX_INPUT_BYTES as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(CliError::io("read standard input"))?;
    if bytes.len() > MAX_INPUT_BYTES {
        return Err(CliError::Unreadable {
            name: name.into(),
            reason: format!(
                "input is more than the limit of {MAX_INPUT_BYTES} bytes\n  = help: split the input into smaller expressions"
            ),
        });
    }
    let text = String::from_utf8(bytes).map_err(|e| CliError::Unreadable {
        name: name.into(),
        reason: format!(
            "input is not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ),
    })?;
    Ok((name.into(), text))
}

/// The text of a file (size-limited), or of standard input for `-`, with its name.
pub fn read_file(path: &str) -> Result<(String, String), CliError> {
    if path == "-" {
        return read("-");
    }
    let limit = MAX_INPUT_BYTES as u64;
    let file = std::fs::File::open(path).map_err(CliError::io(format!("read {path}")))?;
    let mut bytes = Vec::new();
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(CliError::io(format!("read {path}")))?;
    if bytes.len() as u64 > limit {
        let head = String::from_utf8_lossy(&bytes[..bytes.len().min(200)]).into_owned();
        let line = head.lines().next().unwrap_or_default();
        let message = format!("the file is larger than the limit of {limit} bytes");
        return Err(kinetics::parse::Diagnostic::at(path, line, 0, 0, message)
            .with_help("split the problem into smaller scene files")
            .into());
    }
    let text = String::from_utf8(bytes).map_err(|_| CliError::Unreadable {
        name: path.to_string(),
        reason: "not UTF-8 text".into(),
    })?;
    Ok((path.to_string(), text))
}

/// The value parser of an expression or equation argument, which may begin with a minus
/// (`-a^2 + b`, clap's `allow_hyphen_values`): a word after two minus signs (`--fromat`) is
/// a misspelt option, refused as one, not read as the expression `-(-fromat)`.
pub fn expression_argument(argument: &str) -> Result<String, String> {
    let flag = argument
        .strip_prefix("--")
        .filter(|rest| rest.starts_with(|c: char| c.is_ascii_alphabetic()));
    match flag {
        Some(_) => Err(format!(
            "'{argument}' is not an option of this command (--help lists them); \
             an expression that begins with two minus signs is written -(-...)"
        )),
        None => Ok(argument.to_string()),
    }
}
