//! Scene-file errors said in one short line: the parser's message cut to
//! [`MAX_MESSAGE_CHARS`], a value of the wrong type named by its field and
//! line in plain words, and what a path that is not a regular file is.

use super::SceneError;

/// The longest message an error carries (characters): the parser quotes
/// the offending line, which may be a whole file of one line.
pub const MAX_MESSAGE_CHARS: usize = 240;

/// A parser's message on one line, at most [`MAX_MESSAGE_CHARS`]
/// characters, cut with "…".
fn one_line(message: &str) -> String {
    let line = message.trim_end().replace('\n', " | ");
    if line.chars().count() <= MAX_MESSAGE_CHARS {
        return line;
    }
    let cut: String = line.chars().take(MAX_MESSAGE_CHARS - 1).collect();
    format!("{cut}…")
}

/// A TOML error in one short line: for a value of the wrong type, the
/// field's path and line and what was expected, in plain words
/// (`fill.count: expected a whole number of at least 0, got -5`); for a
/// syntax error, the parser's own message.
pub(super) fn type_error(
    text: &str,
    origin: &str,
    e: serde_path_to_error::Error<toml::de::Error>,
) -> SceneError {
    let path = e.path().to_string();
    let inner = e.into_inner();
    if path.is_empty() || path == "." {
        return syntax_error(text, origin, &inner);
    }
    let line = inner
        .span()
        .map(|span| text[..span.start.min(text.len())].matches('\n').count() + 1);
    let origin = match line {
        Some(line) => format!("{origin}, line {line}"),
        None => origin.to_string(),
    };
    SceneError::Invalid {
        origin,
        field: path,
        reason: one_line(&plain_words(inner.message())),
    }
}

/// Most characters of the offending line a syntax error quotes.
const QUOTED_CHARS: usize = 60;

/// A syntax error as a sentence on one line: the file and line, the
/// parser's words, the column and the line itself, quoted
/// (`scene.toml, line 3: invalid array; expected `]` (column 1:
/// "gravity = [0, 0]")`). The parser's own text draws the line with a caret
/// under it, which on one line reads as `| | 3 | gravity … | ^ |`.
fn syntax_error(text: &str, origin: &str, e: &toml::de::Error) -> SceneError {
    // "invalid array\nexpected `]`" → "invalid array; expected `]`", and a
    // list of what was expected read as one: "expected newline or `#`".
    let words = e
        .message()
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .map(|l| {
            match l
                .strip_prefix("expected ")
                .and_then(|r| r.rsplit_once(", "))
            {
                Some((first, last)) => format!("expected {first} or {last}"),
                None => l.to_string(),
            }
        })
        .collect::<Vec<_>>()
        .join("; ");
    let Some(span) = e.span() else {
        return SceneError::Syntax {
            origin: origin.to_string(),
            message: one_line(&words),
        };
    };
    let at = span.start.min(text.len());
    let mut at = (0..=at)
        .rev()
        .find(|&i| text.is_char_boundary(i))
        .unwrap_or(0);
    // At the end of the text (an array left open), or on a blank line: the
    // end of the last line with something on it, where the parser gave up.
    let blank = |at: usize| {
        let start = text[..at].rfind('\n').map_or(0, |i| i + 1);
        let end = text[at..].find('\n').map_or(text.len(), |i| at + i);
        text[start..end].trim().is_empty()
    };
    while at > 0 && blank(at) {
        let start = text[..at].rfind('\n').unwrap_or(0);
        at = text[..start].trim_end().len();
    }
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[at..].find('\n').map_or(text.len(), |i| at + i);
    let line = text[..at].matches('\n').count() + 1;
    let column = text[line_start..at].chars().count() + 1;
    let quoted: String = text[line_start..line_end]
        .trim_end()
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    let quoted = if quoted.chars().count() > QUOTED_CHARS {
        let cut: String = quoted.chars().take(QUOTED_CHARS - 1).collect();
        format!("{cut}…")
    } else {
        quoted
    };
    let message = if quoted.trim().is_empty() {
        format!("{words} (column {column})")
    } else {
        format!("{words} (column {column}: \"{quoted}\")")
    };
    SceneError::Syntax {
        origin: format!("{origin}, line {line}"),
        message: one_line(&message),
    }
}

/// serde's words for a type error, as a person reads them: "invalid value:
/// integer `-5`, expected usize" → "expected a whole number of at least 0,
/// got -5".
fn plain_words(message: &str) -> String {
    if !(message.starts_with("invalid value") || message.starts_with("invalid type")) {
        return message.to_string(); // an unknown field, a missing one: as serde says
    }
    let expected = message.split("expected ").nth(1).unwrap_or("").trim();
    let wanted = match expected {
        "usize" | "u64" | "u32" | "u16" | "u8" => "a whole number of at least 0",
        "i64" | "i32" => "a whole number",
        "f64" | "f32" => "a number",
        "a boolean" => "true or false",
        "" => return message.to_string(),
        other => other,
    };
    let got = message.split('`').nth(1);
    match got {
        Some(got) => format!("expected {wanted}, got {got}"),
        None => format!("expected {wanted}"),
    }
}

/// What a path that is not a regular file is, in words.
pub(super) fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if meta.is_dir() {
        "a folder"
    } else {
        "not a file"
    }
}
