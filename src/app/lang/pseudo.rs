//! The pseudo-language `qps`: English with every letter accented, every
//! message 40 % longer and in brackets, so that a text the layout cuts off,
//! a word left in English and a string built outside the Fluent files show.

use std::borrow::Cow;

/// Every ASCII letter of `text` with an accent, or a look-alike where the
/// window's font (egui's Ubuntu Light) has no accented form (m, v, x: м,
/// ν, χ).
pub fn accent(text: &str) -> Cow<'_, str> {
    Cow::Owned(text.chars().map(accented).collect())
}

fn accented(c: char) -> char {
    const LOWER: &str = "àƀçďéƒĝĥîĵķļмñöþɋŕšţüνŵχýž";
    const UPPER: &str = "ÀƁÇĎÉƑĜĤÎĴĶĻМÑÖÞɊŔŠŢÜƲŴΧÝŽ";
    match c {
        'a'..='z' => LOWER.chars().nth(c as usize - 'a' as usize).unwrap_or(c),
        'A'..='Z' => UPPER.chars().nth(c as usize - 'A' as usize).unwrap_or(c),
        other => other,
    }
}

/// `text` 40 % longer (padded with `~` at the end of its words' run) and
/// in brackets.
pub fn lengthen(text: &str) -> String {
    let n = text.chars().count();
    let pad = (n * 2).div_ceil(5);
    format!("[{text}{}]", "~".repeat(pad.saturating_sub(2)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_letter_is_accented_and_the_rest_kept() {
        let out = accent("Pause 2 discs: ABC xyz");
        assert!(!out.chars().any(|c| c.is_ascii_alphabetic()), "{out}");
        assert_eq!(
            out.chars().count(),
            "Pause 2 discs: ABC xyz".chars().count()
        );
        assert!(out.contains(" 2 ") && out.contains(':'));
    }

    #[test]
    fn forty_percent_longer_in_brackets() {
        for text in ["Pause", "Next collision", "a"] {
            let out = lengthen(text);
            let (n, m) = (text.chars().count() as f64, out.chars().count() as f64);
            assert!(out.starts_with('[') && out.ends_with(']'));
            assert!(m >= 1.4 * n && m <= 1.4 * n + 3.0, "{text} → {out}");
        }
    }
}
