//! Numbers as a person types them into a field: either decimal separator,
//! a minus sign or hyphen, a power of ten as the screen writes it
//! (2.5×10⁹), and digits in groups of three ("1 000", "1,000.5",
//! "1.000.000"). A lone separator that is not the language's decimal one,
//! between one to three digits and exactly three ("1,000" in English,
//! "1.000" in German), is a thousand in one convention and one in the
//! other: it is not read as either, and the person is asked which.

use crate::app::lang::decimal_comma;

/// Why a typed text was not read as a number.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Unread {
    /// Not one number ("two", "1,5.2").
    NotANumber,
    /// "1,000" where the decimal separator is the point, or "1.000" where
    /// it is the comma: `decimal` read with that separator as the decimal
    /// one, `grouped` read with it between thousands.
    Ambiguous { decimal: f64, grouped: f64 },
}

/// The spaces written between groups of digits: "1 000", with a plain,
/// a no-break or a narrow no-break space.
const GROUP_SPACES: [char; 4] = [' ', '\u{a0}', '\u{202f}', '\u{2009}'];

/// The number typed in `text`, or why it is not one.
pub fn read(text: &str) -> Result<f64, Unread> {
    let text = text.trim().replace('−', "-");
    // A power of ten as the screen writes it: 2.5×10⁹ (or 2.5x10^9).
    let power = ["×10", "x10", "*10"]
        .iter()
        .find_map(|sign| text.split_once(sign));
    if let Some((mantissa, exponent)) = power {
        let exponent: String = exponent
            .trim_start_matches('^')
            .chars()
            .map(|c| match c {
                '⁻' => '-',
                '⁰'..='⁹' | '¹' | '²' | '³' => superscript_digit(c),
                c => c,
            })
            .collect();
        let exponent: i32 = exponent.parse().map_err(|_| Unread::NotANumber)?;
        // A mantissa has no thousands: either separator is its decimal one.
        let mantissa = mantissa.trim().replace(',', ".");
        if mantissa.is_empty() || mantissa.matches('.').count() > 1 {
            return Err(Unread::NotANumber);
        }
        return format!("{mantissa}e{exponent}")
            .parse::<f64>()
            .map_err(|_| Unread::NotANumber);
    }
    let (sign, body) = match text.strip_prefix('-') {
        Some(rest) => (-1.0, rest),
        None => (1.0, text.strip_prefix('+').unwrap_or(&text)),
    };
    let grouping = |c: char| c == '.' || c == ',' || GROUP_SPACES.contains(&c);
    if !body.chars().all(|c| c.is_ascii_digit() || grouping(c)) {
        // "1e12", "inf": as Rust reads them, with either separator.
        let plain = text.replace(',', ".");
        if plain.matches('.').count() > 1 {
            return Err(Unread::NotANumber);
        }
        return plain.parse::<f64>().map_err(|_| Unread::NotANumber);
    }
    match digits(body) {
        Ok(v) => Ok(sign * v),
        Err(Unread::Ambiguous { decimal, grouped }) => Err(Unread::Ambiguous {
            decimal: sign * decimal,
            grouped: sign * grouped,
        }),
        Err(unread) => Err(unread),
    }
}

/// A number of digits, separators and spaces only ("1 000,5").
fn digits(body: &str) -> Result<f64, Unread> {
    let own = if decimal_comma() { ',' } else { '.' };
    let other = if own == ',' { '.' } else { ',' };
    let spaced = body.contains(GROUP_SPACES);
    let points = body.matches('.').count();
    let commas = body.matches(',').count();
    // The decimal separator, if there is one, and what groups thousands.
    let (decimal, group) = match (points, commas) {
        (0, 0) => (None, None),
        // Both: the last is the decimal separator, the other groups.
        (_, _) if points > 0 && commas > 0 => {
            let last = if body.rfind('.') > body.rfind(',') {
                '.'
            } else {
                ','
            };
            let first = if last == '.' { ',' } else { '.' };
            (Some(last), Some(first))
        }
        // One kind, more than once: it groups ("1.000.000").
        (n, 0) | (0, n) if n > 1 => (None, Some(if points > 0 { '.' } else { ',' })),
        _ => {
            let sep = if points > 0 { '.' } else { ',' };
            if sep == other && !spaced {
                let (whole, fraction) = body.split_once(sep).unwrap_or((body, ""));
                let looks_grouped = (1..=3).contains(&whole.len())
                    && !whole.starts_with('0')
                    && fraction.len() == 3;
                if looks_grouped {
                    return Err(Unread::Ambiguous {
                        decimal: assemble(whole, Some(fraction))?,
                        grouped: assemble(&format!("{whole}{fraction}"), None)?,
                    });
                }
            }
            (Some(sep), None)
        }
    };
    if spaced && group.is_some() {
        // "1 000.000.5": spaces and a separator both grouping.
        return Err(Unread::NotANumber);
    }
    let (whole, fraction) = match decimal {
        Some(sep) => {
            let (whole, fraction) = body.rsplit_once(sep).unwrap_or((body, ""));
            if whole.contains(sep) {
                return Err(Unread::NotANumber);
            }
            (whole, Some(fraction))
        }
        None => (body, None),
    };
    let is_group = |c: char| Some(c) == group || GROUP_SPACES.contains(&c);
    if whole.contains(is_group) {
        let mut groups = whole.split(is_group);
        let first = groups.next().unwrap_or_default();
        if !(1..=3).contains(&first.len()) || !groups.all(|g| g.len() == 3) {
            return Err(Unread::NotANumber);
        }
    }
    let whole: String = whole.chars().filter(|&c| !is_group(c)).collect();
    assemble(&whole, fraction)
}

/// The number with digits `whole` before the decimal separator and
/// `fraction` after it.
fn assemble(whole: &str, fraction: Option<&str>) -> Result<f64, Unread> {
    let text = match fraction {
        Some(fraction) if !fraction.chars().all(|c| c.is_ascii_digit()) => {
            return Err(Unread::NotANumber)
        }
        Some(fraction) => format!("{whole}.{fraction}"),
        None => whole.to_string(),
    };
    if text.is_empty() || text == "." {
        return Err(Unread::NotANumber);
    }
    text.parse::<f64>().map_err(|_| Unread::NotANumber)
}

/// The digit a superscript digit stands for.
fn superscript_digit(c: char) -> char {
    let digits = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    digits
        .iter()
        .position(|&d| d == c)
        .and_then(|k| char::from_digit(k as u32, 10))
        .unwrap_or(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::lang::{set_language, Lang};

    #[test]
    fn digits_in_groups_of_three() {
        for lang in [Lang::En, Lang::Fr, Lang::De] {
            set_language(lang);
            for (typed, v) in [
                ("1 000", 1000.0),
                ("1\u{a0}000", 1000.0),
                ("1\u{202f}000,5", 1000.5),
                ("−12 345 678", -12_345_678.0),
                ("1 000.25", 1000.25),
                ("1.000.000", 1e6),
                ("2,500,000", 2.5e6),
            ] {
                assert_eq!(read(typed), Ok(v), "{typed} in {lang:?}");
            }
            for bad in [
                "1 00",
                "10 0000",
                "1 000.000.5",
                "1.00.000",
                " , ",
                "1,5.2",
                "-",
            ] {
                assert_eq!(read(bad), Err(Unread::NotANumber), "{bad} in {lang:?}");
            }
        }
        set_language(Lang::En);
        assert_eq!(read("1,000.5"), Ok(1000.5));
        assert_eq!(read("1.000,5"), Ok(1000.5));
    }

    #[test]
    fn a_thousand_or_one_is_asked_about() {
        set_language(Lang::En);
        let asked = Err(Unread::Ambiguous {
            decimal: 1.0,
            grouped: 1000.0,
        });
        assert_eq!(read("1,000"), asked);
        assert_eq!(read("1.000"), Ok(1.0));
        assert_eq!(read("2,5"), Ok(2.5));
        assert_eq!(read("0,125"), Ok(0.125));
        assert_eq!(read("1234,567"), Ok(1234.567));
        assert_eq!(
            read("−2,500"),
            Err(Unread::Ambiguous {
                decimal: -2.5,
                grouped: -2500.0
            })
        );
        set_language(Lang::De);
        assert_eq!(read("1.000"), asked);
        assert_eq!(read("1,000"), Ok(1.0));
        assert_eq!(read("0.5"), Ok(0.5));
        assert_eq!(read("1.000,0"), Ok(1000.0));
        set_language(Lang::En);
    }

    #[test]
    fn powers_of_ten_and_words() {
        set_language(Lang::En);
        assert_eq!(read("1,234×10³"), Ok(1234.0));
        assert_eq!(read("1e3"), Ok(1000.0));
        assert_eq!(read("inf"), Ok(f64::INFINITY));
        assert_eq!(read("+4"), Ok(4.0));
        assert_eq!(read(".5"), Ok(0.5));
        assert_eq!(read("two"), Err(Unread::NotANumber));
    }
}
