//! Numbers as the screen shows them, in one place: a fixed number of
//! decimals, never in e-notation, never "-0.000" (a value below display
//! precision is 0.000), with its unit (a quantity of a million or more as
//! 2.000×10¹², not thirteen digits), and with the decimal separator of
//! the language spoken ([`crate::app::lang::decimal_comma`]: "2,000 J";
//! a vector's components are then separated by "; "). Fields read numbers
//! with either separator ([`parse`]). Files, the dump and the command line
//! keep the decimal point and do not come here.
//!
//! Discs are counted from 1 wherever a person reads their number
//! ([`disc_number`]): the tables, the messages, the narration and the CSV
//! files. The world's list, the dump and the command line count from 0.

mod typed;

pub use typed::{read, Unread};

use crate::app::lang::{decimal_comma, tr};
use glam::DVec2;

/// `v` with `decimals` decimals, in plain digits; a value that rounds to
/// zero has no sign, and a value that is not finite says so in words.
pub fn plain(v: f64, decimals: usize) -> String {
    if v.is_nan() {
        return tr!("number-not-a-number");
    }
    if v.is_infinite() {
        return if v > 0.0 { "∞" } else { "−∞" }.into();
    }
    let text = format!("{v:.decimals$}");
    let text = match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        Some(rest) => format!("−{rest}"),
        None => text,
    };
    local(text)
}

/// A number written with a decimal point, with the language's separator.
fn local(text: String) -> String {
    if decimal_comma() {
        text.replace('.', ",")
    } else {
        text
    }
}

/// The separator between a vector's components: ", ", or "; " where the
/// comma is the decimal separator.
pub fn list_separator() -> &'static str {
    if decimal_comma() {
        "; "
    } else {
        ", "
    }
}

/// A number typed into a field ([`typed::read`]); `None` if it is not
/// one number, or if it could be read two ways.
pub fn parse(text: &str) -> Option<f64> {
    typed::read(text).ok()
}

/// `v` and its unit: "2.000 J".
pub fn with_unit(v: f64, decimals: usize, unit: &str) -> String {
    format!("{} {unit}", quantity(v, decimals))
}

/// Values from this size up are written with a power of ten.
const POWER_FROM: f64 = 1e6;

/// A measured quantity: [`plain`], but from a million up as the mantissa
/// with `decimals` decimals times a power of ten, as a textbook writes it
/// ("2.000×10¹²"): a 10¹² kg disc's momentum fits the line it is on.
pub fn quantity(v: f64, decimals: usize) -> String {
    if !v.is_finite() || v.abs() < POWER_FROM {
        return plain(v, decimals);
    }
    let mut power = v.abs().log10().floor() as i32;
    let mut mantissa = v / 10f64.powi(power);
    // 9.9996 with three decimals would show as 10.000.
    if plain(mantissa.abs(), decimals).starts_with("10") {
        power += 1;
        mantissa = v / 10f64.powi(power);
    }
    let digits: String = power
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'][d as usize - '0' as usize],
        })
        .collect();
    format!("{}×10{digits}", plain(mantissa, decimals))
}

/// A vector and its unit: "(2.000, 0.000) kg·m/s".
pub fn vector(v: DVec2, decimals: usize, unit: &str) -> String {
    format!(
        "({}{}{}) {unit}",
        quantity(v.x, decimals),
        list_separator(),
        quantity(v.y, decimals)
    )
}

/// `v` with enough decimals to show three significant digits of a small
/// quantity (a mass of 0.00125 kg), at most six, at least `min_decimals`.
pub fn adaptive(v: f64, min_decimals: usize) -> String {
    let magnitude = v.abs();
    let decimals = if magnitude > 0.0 && magnitude < 1.0 && magnitude.is_finite() {
        ((2.0 - magnitude.log10().floor()) as usize).clamp(min_decimals, 6)
    } else {
        min_decimals
    };
    plain(v, decimals)
}

/// A number as a text field offers it for editing: up to six decimals, no
/// trailing zeros, never in e-notation, so what is typed over it is what the
/// user sees.
pub fn field(v: f64) -> String {
    if v.is_finite() && v.abs() >= POWER_FROM {
        // 2.5×10⁹, the mantissa without trailing zeros; [`parse`] reads it.
        let text = quantity(v, 6);
        let (mantissa, power) = text.split_once('×').unwrap_or((&text, ""));
        return format!("{}×{power}", trimmed(mantissa));
    }
    field_text(&plain(v, 6))
}

/// A number as a field that follows a moving disc shows it: three
/// decimals (three significant digits of a small one, up to six), no
/// trailing zeros. A velocity after a collision is "−22.188", not
/// "−22.187812" cut at the field's edge; the disc keeps every digit,
/// and a field left as it is sends nothing.
pub fn field_reading(v: f64) -> String {
    if !v.is_finite() || v.abs() >= POWER_FROM {
        return field(v);
    }
    field_text(&adaptive(v, 3))
}

/// A field's text from a number written out: no trailing zeros, and
/// zero without a sign.
fn field_text(text: &str) -> String {
    let trimmed = trimmed(text);
    if trimmed == "−0" || trimmed.is_empty() {
        "0".into()
    } else {
        trimmed.to_string()
    }
}

/// Whether `v` reads as zero with `decimals` decimals ("0.000"): a
/// change that small is said as none.
pub fn reads_as_zero(v: f64, decimals: usize) -> bool {
    plain(v, decimals) == plain(0.0, decimals)
}

/// The number a person reads for the disc at `index` of the world's list:
/// the first disc is disc 1.
pub fn disc_number(index: usize) -> usize {
    index + 1
}

/// A number written by [`plain`] without the zeros after its decimal
/// separator, nor the separator left alone: "2.50" is "2.5", "3.00" "3",
/// "300" stays.
pub fn trimmed(text: &str) -> &str {
    let point = if decimal_comma() { ',' } else { '.' };
    if text.contains(point) {
        text.trim_end_matches('0').trim_end_matches(point)
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_million_and_more_is_written_with_a_power_of_ten() {
        assert_eq!(with_unit(999_999.0, 3, "J"), "999999.000 J");
        assert_eq!(with_unit(2e12, 3, "J"), "2.000×10¹² J");
        assert_eq!(with_unit(-1.5e6, 2, "J"), "−1.50×10⁶ J");
        assert_eq!(quantity(9.9996e8, 3), "1.000×10⁹");
        assert_eq!(
            vector(DVec2::new(2e12, 0.0), 3, "kg·m/s"),
            "(2.000×10¹², 0.000) kg·m/s"
        );
        assert_eq!(quantity(f64::INFINITY, 3), "∞");
    }

    #[test]
    fn tiny_values_print_as_zero_without_a_sign_or_an_exponent() {
        assert_eq!(plain(-8.9e-16, 3), "0.000");
        assert_eq!(plain(8.9e-16, 3), "0.000");
        assert_eq!(plain(-0.0, 2), "0.00");
        assert_eq!(plain(-0.0004, 3), "0.000");
        assert_eq!(plain(-0.0006, 3), "−0.001");
        assert_eq!(plain(2.0, 3), "2.000");
        assert_eq!(plain(1.5e12, 1), "1500000000000.0");
        assert_eq!(plain(f64::NAN, 3), "not a number");
        for v in [1e-300, -1e-20, 3.7e15, -2.5e-7] {
            for d in 0..6 {
                assert!(!plain(v, d).contains('e'), "{v} with {d} decimals");
            }
        }
    }

    #[test]
    fn units_and_vectors() {
        assert_eq!(with_unit(2.0, 3, "J"), "2.000 J");
        assert_eq!(
            vector(DVec2::new(2.0, -1e-17), 3, "kg·m/s"),
            "(2.000, 0.000) kg·m/s"
        );
    }

    #[test]
    fn a_moving_discs_field_shows_three_decimals_or_three_digits() {
        assert_eq!(field_reading(-22.187812), "−22.188");
        assert_eq!(field_reading(3f64.sqrt()), "1.732");
        assert_eq!(field_reading(2.5), "2.5");
        assert_eq!(field_reading(0.000123456), "0.000123");
        assert_eq!(field_reading(-1e-9), "0");
        assert_eq!(field_reading(2.5e9), field(2.5e9));
        for v in [-22.187812, 0.000123456, 1234.5678] {
            let read = parse(&field_reading(v)).unwrap();
            assert!((read - v).abs() <= 5e-4 * v.abs().max(1e-3), "{v}: {read}");
        }
    }

    #[test]
    fn small_quantities_keep_three_significant_digits() {
        assert_eq!(adaptive(0.00125, 2), "0.00125");
        assert_eq!(adaptive(0.5, 2), "0.500");
        assert_eq!(adaptive(12.0, 2), "12.00");
        assert_eq!(adaptive(1e-9, 2), "0.000000");
    }

    #[test]
    fn a_decimal_comma_where_the_language_has_one() {
        use crate::app::lang::{set_language, Lang};
        set_language(Lang::De);
        assert_eq!(plain(-2.5, 2), "−2,50");
        assert_eq!(vector(DVec2::new(2.0, -0.5), 2, "m/s"), "(2,00; −0,50) m/s");
        assert_eq!(field(0.25), "0,25");
        assert_eq!(field(3.0), "3");
        assert_eq!(parse(&field(-2.345678)), Some(-2.345678));
        set_language(Lang::En);
        assert_eq!(plain(-2.5, 2), "−2.50");
    }

    #[test]
    fn fields_take_either_separator() {
        assert_eq!(parse("1,5"), Some(1.5));
        assert_eq!(parse(" 1.5 "), Some(1.5));
        assert_eq!(parse("−2"), Some(-2.0));
        assert_eq!(parse("1,5.2"), None);
        assert_eq!(parse("two"), None);
    }

    #[test]
    fn fields_read_back_and_have_no_e_notation() {
        assert_eq!(field(1.0), "1");
        assert_eq!(field(0.1 + 0.2), "0.3");
        // The minus sign of every other number on screen (it was "-1.000"
        // in the Discs table beside "−1.083" in the ledger); "-" typed over
        // it reads the same.
        assert_eq!(field(-2.345678), "−2.345678");
        assert_eq!(parse("-2.345678"), Some(-2.345678));
        assert_eq!(field(-1e-9), "0");
        assert_eq!(field(999_999.0), "999999");
        // A million and more with a power of ten, as the readouts write it
        // (2500000000 was cut to "250000000" in a table's cell).
        assert_eq!(field(2.5e9), "2.5×10⁹");
        assert_eq!(field(-1e12), "−1×10¹²");
        for v in [1.0, 0.3, -2.5, 0.001, 2.5e9, 1e12, -1.234567e7, 1e6] {
            assert_eq!(parse(&field(v)), Some(v), "{}", field(v));
        }
        for (typed, v) in [
            ("2.5×10⁹", 2.5e9),
            ("2,5×10⁹", 2.5e9),
            ("1x10^12", 1e12),
            ("−3×10⁻²", -0.03),
            ("1e12", 1e12),
        ] {
            assert_eq!(parse(typed), Some(v), "{typed}");
        }
        for bad in ["×10⁹", "2.5×10", "2.5×10⁹⁹⁹⁹⁹⁹⁹⁹⁹⁹⁹⁹", "1.2.3×10²"]
        {
            assert_eq!(parse(bad), None, "{bad}");
        }
    }
}
