//! The command line's shared value parsers: each checks one option's value
//! and says in one line what is wrong, for `run`, the window and the lab.

#[cfg(not(target_arch = "wasm32"))]
use impulse::method::Setting;

/// Command-line parser for a positive, finite number of seconds.
pub fn positive_seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v > 0.0 && v.is_finite() => Ok(v),
        _ => Err(format!("{s:?} is not a positive number of seconds")),
    }
}

#[cfg(not(target_arch = "wasm32"))]
/// Command-line parser for substeps: `auto` or 1 to 10000, as in scene files.
pub fn substeps(s: &str) -> Result<Setting<u32>, String> {
    match s.parse::<Setting<u32>>() {
        Ok(Setting::Fixed(k)) if !(1..=10_000).contains(&k) => {
            Err(format!("{s:?} is not a number of substeps from 1 to 10000"))
        }
        other => other,
    }
}

/// Command-line parser for a number of seconds, 0 or more.
pub fn non_negative_seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v >= 0.0 && v.is_finite() => Ok(v),
        _ => Err(format!("{s:?} is not a number of seconds (0 or more)")),
    }
}

/// Command-line parser for the UI scale, 1 to 2.5.
pub fn ui_scale(s: &str) -> Result<f32, String> {
    match s.parse::<f32>() {
        Ok(v) if (1.0..=2.5).contains(&v) => Ok(v),
        _ => Err(format!("{s:?} is not a UI scale from 1 to 2.5")),
    }
}

/// Command-line parser for `--lang`: a language the window speaks (`qps`:
/// the pseudo-language for layout checks).
pub fn language(s: &str) -> Result<crate::app::lang::Lang, String> {
    use crate::app::lang::Lang;
    let known: Vec<&str> = Lang::SHIPPED.iter().map(|l| l.code()).collect();
    Lang::from_tag(s).ok_or_else(|| {
        format!(
            "{s:?} is not a language the window speaks: {} (or qps, a pseudo-language for layout checks)",
            known.join(", ")
        )
    })
}

/// Command-line parser for a window size like 1280x800.
pub fn window_size(s: &str) -> Result<(i32, i32), String> {
    let parsed = s
        .split_once('x')
        .and_then(|(w, h)| Some((w.parse::<i32>().ok()?, h.parse::<i32>().ok()?)));
    match parsed {
        Some((w, h)) if (200..=8192).contains(&w) && (200..=8192).contains(&h) => Ok((w, h)),
        _ => Err(format!(
            "{s:?} is not a window size like 1280x800 (200 to 8192 px)"
        )),
    }
}

/// Most discs `--gas` builds.
pub const MAX_GAS: usize = 1_000_000;

/// Command-line parser for `--gas`: 1 to [`MAX_GAS`] discs, written as a
/// whole number (`100000`, or `1e5` as a scientist writes it). The error
/// says which was wrong: not a number, not whole, or out of the range.
pub fn gas_count(s: &str) -> Result<usize, String> {
    let range = format!("the gas takes 1 to {MAX_GAS} discs");
    let Some(x) = s.trim().parse::<f64>().ok().filter(|x| x.is_finite()) else {
        return Err(format!("{s:?} is not a number: {range}"));
    };
    if x.fract() != 0.0 {
        return Err(format!("{s} is not a whole number of discs: {range}"));
    }
    if !(1.0..=MAX_GAS as f64).contains(&x) {
        return Err(format!("{s} discs is out of range: {range}"));
    }
    Ok(x as usize)
}

/// A number for a message: plain when it reads well, in e-notation when it
/// is very large or very small (`1e300`, not 301 digits).
#[cfg(not(target_arch = "wasm32"))]
pub fn number(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e9).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
