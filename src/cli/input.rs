//! Reading a command's mathematical input: an argument, or `-` for standard input.

use super::error::CliError;
use kinetics::parse::limits::MAX_INPUT_BYTES;
use std::io::Read;

/// The text of the argument, or all of standard input when it is `-`, with the name to use
/// in diagnostics; a leading byte-order mark dropped, input that is not UTF-8 refused at its
/// first invalid byte ([`utf8_text`]). Standard input beyond the size limit is not read.
pub fn read(argument: &str) -> Result<(String, String), CliError> {
    if argument != "-" {
        // An argument's byte-order mark is dropped by its value parser, `expression_argument`.
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
    Ok((name.into(), utf8_text(name, bytes)?))
}

/// The text of a file (size-limited), or of standard input for `-`, with its name; a
/// leading byte-order mark dropped, bytes that are not UTF-8 refused located ([`utf8_text`]).
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
    Ok((path.to_string(), utf8_text(path, bytes)?))
}

/// The byte-order mark, which some editors write before UTF-8 text: not part of the text.
const BYTE_ORDER_MARK: char = '\u{feff}';

/// The text of the input `name` read as `bytes`: a leading byte-order mark dropped, and
/// bytes that are not UTF-8 refused at the first invalid one, located by its line, column
/// and byte offset in the input (the mark counted), its line quoted with each invalid byte
/// as U+FFFD and a caret under it.
pub fn utf8_text(name: &str, mut bytes: Vec<u8>) -> Result<String, CliError> {
    let mark = BYTE_ORDER_MARK.len_utf8();
    let marked = bytes.starts_with(BYTE_ORDER_MARK.encode_utf8(&mut [0; 4]).as_bytes());
    if marked {
        bytes.drain(..mark);
    }
    let error = match String::from_utf8(bytes) {
        Ok(text) => return Ok(text),
        Err(e) => e,
    };
    let bytes = error.as_bytes();
    let at = error.utf8_error().valid_up_to();
    let line_end = bytes[at..]
        .iter()
        .position(|b| *b == b'\n')
        .map_or(bytes.len(), |n| at + n);
    // Up to the invalid byte the text is UTF-8, so offsets there are the same in the lossy
    // copy; the invalid byte is one U+FFFD there.
    let shown = String::from_utf8_lossy(&bytes[..line_end]);
    let offset = at + if marked { mark } else { 0 };
    let message = match error.utf8_error().error_len() {
        Some(_) => format!(
            "not UTF-8 text: invalid byte 0x{:02x} at byte offset {offset}",
            bytes[at]
        ),
        None => format!(
            "not UTF-8 text: the input ends inside a character (byte 0x{:02x} at byte offset {offset} begins it)",
            bytes[at]
        ),
    };
    let replacement = char::REPLACEMENT_CHARACTER.len_utf8();
    Err(
        kinetics::parse::Diagnostic::at(name, &shown, at, at + replacement, message)
            .with_help("save the file as UTF-8 text (the encoding of ASCII and of most editors)")
            .into(),
    )
}

/// The value parser of an expression or equation argument, which may begin with a minus
/// (`-a^2 + b`, clap's `allow_hyphen_values`): a word after two minus signs (`--fromat`) is
/// a misspelt option, refused as one, not read as the expression `-(-fromat)`. A leading
/// byte-order mark is dropped.
pub fn expression_argument(argument: &str) -> Result<String, String> {
    let flag = argument
        .strip_prefix("--")
        .filter(|rest| rest.starts_with(|c: char| c.is_ascii_alphabetic()));
    match flag {
        Some(_) => Err(format!(
            "'{argument}' is not an option of this command (--help lists them); \
             an expression that begins with two minus signs is written -(-...)"
        )),
        None => Ok(argument
            .strip_prefix(BYTE_ORDER_MARK)
            .unwrap_or(argument)
            .to_string()),
    }
}
