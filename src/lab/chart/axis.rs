//! Chart axes: linear or logarithmic ranges, tick positions and labels.

/// Values beyond this magnitude are treated like non-finite ones on a linear
/// axis: the span arithmetic would overflow.
pub(super) const LINEAR_LIMIT: f64 = 1e300;

/// How the labels of an axis are written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Labels {
    /// Linear ticks `step` apart, the same number of decimals on each.
    Linear { step: f64 },
    /// Log axis, ticks on whole decades: `10ⁿ`.
    Decades,
}

/// One axis in plot space: on a log axis every value is its `log10`.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Axis {
    pub(super) log: bool,
    pub(super) lo: f64,
    pub(super) hi: f64,
    /// Labelled ticks with bold grid lines (plot space).
    pub(super) bold: Vec<f64>,
    /// Unlabelled light grid lines (plot space).
    pub(super) light: Vec<f64>,
    pub(super) labels: Labels,
}

impl Axis {
    /// The axis that shows every plottable value of `values`, padded a little,
    /// with at most about `max_labels` labels.
    pub(super) fn fit(values: impl Iterator<Item = f64>, log: bool, max_labels: usize) -> Axis {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for v in values.filter_map(|v| to_plot(v, log)) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        if lo > hi {
            // Nothing to show: one decade on a log axis, 0..1 on a linear one.
            (lo, hi) = (0.0, 1.0);
        } else if hi - lo <= 1e-9 * hi.abs().max(lo.abs()) {
            let half = if log {
                0.5
            } else if lo.abs() < 1e-290 {
                1.0
            } else {
                0.1 * lo.abs()
            };
            (lo, hi) = (lo - half, hi + half);
        }
        let pad = 0.04 * (hi - lo);
        let (mut lo, mut hi) = (lo - pad, hi + pad);
        if log && hi.floor() - lo.ceil() < 1.0 {
            // Fewer than two decades inside: out to the decades around.
            (lo, hi) = (lo.floor(), hi.ceil());
            if hi - lo < 2.0 {
                hi = lo + 2.0;
            }
        }
        let (bold, light, labels) = if log {
            let (bold, light) = log_ticks(lo, hi, max_labels);
            (bold, light, Labels::Decades)
        } else {
            let (bold, light, step) = linear_ticks(lo, hi, max_labels);
            (bold, light, Labels::Linear { step })
        };
        Axis {
            log,
            lo,
            hi,
            bold,
            light,
            labels,
        }
    }

    /// The pixel of `t` (plot space) on a span running from pixel `from`
    /// (at `lo`) to `to` (at `hi`); far-off values are clamped, NaN gives
    /// `from`.
    pub(super) fn pixel(&self, t: f64, from: i32, to: i32) -> i32 {
        let f = (t - self.lo) / (self.hi - self.lo);
        let pixel = f64::from(from) + f * f64::from(to - from);
        if pixel.is_nan() {
            return from;
        }
        pixel.round().clamp(-1e6, 1e6) as i32
    }

    /// The text of the tick at `t` (plot space), with a typographic minus.
    pub(super) fn label(&self, t: f64) -> String {
        let text = self.ascii_label(t);
        match text.strip_prefix('-') {
            Some(rest) => format!("−{rest}"),
            None => text,
        }
    }

    pub(super) fn ascii_label(&self, t: f64) -> String {
        match self.labels {
            Labels::Linear { step } => format_linear(t, step),
            Labels::Decades => format!("10{}", superscript(t.round() as i64)),
        }
    }
}

/// A data value in plot space, or `None` if the axis cannot show it.
pub(super) fn to_plot(v: f64, log: bool) -> Option<f64> {
    if !v.is_finite() {
        None
    } else if log {
        (v > 0.0).then(|| v.log10())
    } else {
        (v.abs() <= LINEAR_LIMIT).then_some(v)
    }
}

/// Multiples of `step` in `lo..=hi`; empty if there would be absurdly many.
pub(super) fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    if !(step > 0.0 && step.is_finite()) {
        return Vec::new();
    }
    let first = (lo / step).ceil();
    let last = (hi / step).floor();
    if !(first.is_finite() && last.is_finite()) || last - first > 10_000.0 {
        return Vec::new();
    }
    let (first, last) = (first as i64, last as i64);
    (first..=last)
        .map(|i| {
            let v = i as f64 * step;
            if v.abs() < step * 1e-6 {
                0.0
            } else {
                v
            }
        })
        .collect()
}

/// Ticks at 1, 2 or 5 times a power of ten with at most about `max` in
/// `lo..=hi`: (labelled, light, step).
pub(super) fn linear_ticks(lo: f64, hi: f64, max: usize) -> (Vec<f64>, Vec<f64>, f64) {
    let span = hi - lo;
    if !(span > 0.0 && span.is_finite()) {
        return (Vec::new(), Vec::new(), 1.0);
    }
    let raw = span / max.max(1) as f64;
    let magnitude = 10f64.powf(raw.log10().floor());
    let (mantissa, minor) = [(1.0, 5.0), (2.0, 4.0), (5.0, 5.0), (10.0, 5.0)]
        .into_iter()
        .find(|&(m, _)| m * magnitude >= raw * (1.0 - 1e-9))
        .unwrap_or((10.0, 5.0));
    let step = mantissa * magnitude;
    let bold = multiples(lo, hi, step);
    let light = multiples(lo, hi, step / minor)
        .into_iter()
        .filter(|v| !bold.iter().any(|b| (b - v).abs() < step * 1e-6))
        .collect();
    (bold, light, step)
}

/// Ticks for a log axis over `lo..hi` (exponents of ten): labelled ticks
/// on whole decades only (every one, or every second, fifth, … when there
/// are more than `max`), and light ones at 2…9 × 10ᵏ between them when
/// there are few decades, at the unlabelled decades when there are many.
pub(super) fn log_ticks(lo: f64, hi: f64, max: usize) -> (Vec<f64>, Vec<f64>) {
    let max = max.max(2);
    if !(lo.is_finite() && hi.is_finite() && hi > lo) || hi - lo > 10_000.0 {
        return (Vec::new(), Vec::new());
    }
    let decades: Vec<i64> = ((lo.ceil() as i64)..=(hi.floor() as i64)).collect();
    let every = [1, 2, 3, 4, 5, 10, 20, 25, 50, 100, 200, 500, 1000]
        .into_iter()
        .find(|&s| decades.iter().filter(|k| k.rem_euclid(s) == 0).count() <= max)
        .unwrap_or(1000);
    let bold: Vec<f64> = decades
        .iter()
        .filter(|k| k.rem_euclid(every) == 0)
        .map(|&k| k as f64)
        .collect();
    let light = if every > 1 {
        decades
            .iter()
            .filter(|k| k.rem_euclid(every) != 0)
            .map(|&k| k as f64)
            .collect()
    } else if hi - lo <= 8.5 {
        ((lo.floor() as i64)..=(hi.ceil() as i64))
            .flat_map(|k| (2..=9).map(move |m| k as f64 + f64::from(m).log10()))
            .filter(|&t| t >= lo && t <= hi)
            .collect()
    } else {
        Vec::new()
    };
    (bold, light)
}

/// `v` with as many decimals as ticks `step` apart need; scientific notation
/// for very large or very small steps.
pub(super) fn format_linear(v: f64, step: f64) -> String {
    let v = if v.abs() < step * 1e-6 { 0.0 } else { v };
    let step_exp = step.log10().floor() as i64;
    let big = v.abs().max(step);
    if big >= 1e6 || step < 1e-4 {
        if v == 0.0 {
            return "0".to_owned();
        }
        let digits = (big.log10().floor() as i64 - step_exp).clamp(0, 15) as usize;
        let text = format!("{v:.digits$e}");
        match text.split_once('e') {
            Some((mantissa, exp)) if mantissa.contains('.') => {
                let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
                format!("{mantissa}e{exp}")
            }
            _ => text,
        }
    } else {
        format!("{v:.*}", (-step_exp).max(0) as usize)
    }
}

/// `n` in Unicode superscript digits.
pub(super) fn superscript(n: i64) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut out = String::new();
    if n < 0 {
        out.push('⁻');
    }
    for c in n.unsigned_abs().to_string().chars() {
        out.push(DIGITS[c.to_digit(10).unwrap_or(0) as usize]);
    }
    out
}
