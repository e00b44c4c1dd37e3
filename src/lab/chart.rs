//! Line charts for the lab commands, written as a PNG and an SVG side by side.
//!
//! A [`Chart`] is a title, two axis labels, a linear or logarithmic scale per
//! axis, some [`Series`] and optionally one highlighted series (say a Pareto
//! front) drawn thick and black on top of the others. [`write_chart`] renders
//! it at 1200×800 with grid lines, one marker per point, a legend to the right
//! of the plot, and the Okabe–Ito colour-blind-safe palette.
//!
//! Text is drawn with DejaVu Sans, embedded in the binary
//! (`assets/fonts/DejaVuSans.ttf`, licence next to it), so no fontconfig or
//! system font is needed at run time. In the PNG, strings are laid out glyph
//! by glyph from the font's own metrics (see [`Metrics`]), because plotters'
//! layout puts letters unevenly.
//!
//! Nothing here panics on odd data: points that a log axis cannot show (zero,
//! negative) and non-finite points are skipped, and a line is broken where a
//! point was skipped; a chart without a single drawable point is still written,
//! with empty axes. Errors (a missing or unwritable directory, say) come back
//! as `anyhow` errors naming the file. Each file is written to a temporary file
//! in the same directory and renamed into place, so a reader never sees half a
//! chart.

use anyhow::{anyhow, Context, Result};
use image::ImageEncoder;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontTransform;
use std::fmt::Display;
use std::fs::{self, File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Once, OnceLock};

/// One line of a chart: points joined in the given order, with a marker on
/// each.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Series {
    /// Legend entry (and text in the SVG).
    pub name: String,
    /// `(x, y)` data points, joined in this order. Points that cannot be shown
    /// (non-finite, or not positive on a log axis) are skipped and break the
    /// line.
    pub points: Vec<(f64, f64)>,
    /// Draw the line dashed (for a reference slope or a model, say).
    pub dashed: bool,
}

/// Everything [`write_chart`] draws.
#[derive(Debug, Clone, Copy)]
pub struct Chart<'a> {
    /// Title above the plot.
    pub title: &'a str,
    /// Label under the x axis.
    pub x_label: &'a str,
    /// Label beside the y axis.
    pub y_label: &'a str,
    /// Logarithmic x axis (base 10).
    pub log_x: bool,
    /// Logarithmic y axis (base 10).
    pub log_y: bool,
    /// The series, coloured in order from the Okabe–Ito palette.
    pub series: &'a [Series],
    /// A series drawn thick and black on top of the others, e.g. a Pareto
    /// front; it gets the last legend entry.
    pub highlight: Option<&'a Series>,
}

/// Pixel size of the PNG (and the SVG's view box).
pub const SIZE: (u32, u32) = (1200, 800);

/// Okabe & Ito's colour-blind-safe palette, in the order series use it.
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0xE6, 0x9F, 0x00), // orange
    RGBColor(0x56, 0xB4, 0xE9), // sky blue
    RGBColor(0x00, 0x9E, 0x73), // bluish green
    RGBColor(0xF0, 0xE4, 0x42), // yellow
    RGBColor(0x00, 0x72, 0xB2), // blue
    RGBColor(0xD5, 0x5E, 0x00), // vermillion
    RGBColor(0xCC, 0x79, 0xA7), // reddish purple
    RGBColor(0x00, 0x00, 0x00), // black
];

/// Writes `<stem>.png` (1200x800) and `<stem>.svg` side by side; returns the two paths.
///
/// `.png` and `.svg` are appended to `stem` (so `out/bench.v2` gives
/// `out/bench.v2.png`). The directory must exist. Both images are rendered
/// before either file is written, and each file is replaced atomically.
pub fn write_chart(chart: &Chart, stem: &Path) -> Result<(PathBuf, PathBuf)> {
    if stem.file_name().is_none() {
        return Err(anyhow!(
            "chart path {} does not name a file",
            stem.display()
        ));
    }
    let png_path = with_suffix(stem, ".png");
    let svg_path = with_suffix(stem, ".svg");

    let layout = Layout::new(chart);
    let pixels = render_rgb(chart, &layout)?;
    let svg = render_svg(chart, &layout)?;

    write_atomically(&png_path, |w| {
        image::codecs::png::PngEncoder::new(w)
            .write_image(&pixels, SIZE.0, SIZE.1, image::ColorType::Rgb8)
            .context("encoding PNG")
    })?;
    write_atomically(&svg_path, |w| Ok(w.write_all(svg.as_bytes())?))?;
    Ok((png_path, svg_path))
}

// ---------------------------------------------------------------- font

/// Font family name the embedded font is registered under (plotters' default
/// sans-serif family, which is also what the SVG asks its viewer for).
const FONT: &str = "sans-serif";

static FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Registers the embedded DejaVu Sans with plotters, once per process.
fn ensure_font() -> Result<()> {
    static REGISTER: Once = Once::new();
    static LOADED: AtomicBool = AtomicBool::new(false);
    REGISTER.call_once(|| {
        let ok = plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES).is_ok();
        LOADED.store(ok, Ordering::Release);
    });
    if LOADED.load(Ordering::Acquire) {
        Ok(())
    } else {
        Err(anyhow!("the embedded DejaVu Sans font could not be loaded"))
    }
}

/// The few metrics of a TrueType font that horizontal layout needs.
///
/// plotters 0.3.7 draws strings with ab_glyph but drops each glyph's left side
/// bearing and rounds the pen down, so letters sit unevenly ("s lop e"). For
/// the PNG, [`put_text`] lays strings out itself from these metrics (the
/// font's `cmap`, `hmtx` and `kern` tables) and has plotters draw one glyph at
/// a time, which it gets right. The SVG needs none of this: its viewer lays
/// the text out.
#[derive(Debug)]
struct Metrics {
    /// Ascender minus descender in font units: ab_glyph scales a font of
    /// size `s` px by `s / height`.
    height: f64,
    /// `cmap` format 12 groups: first char, last char, first glyph.
    groups: Vec<(u32, u32, u32)>,
    /// `hmtx`: advance width and left side bearing per glyph.
    advances: Vec<u16>,
    bearings: Vec<i16>,
    /// `kern` format 0 pairs, sorted: (left << 16 | right, adjustment).
    kerning: Vec<(u32, i16)>,
}

fn u16_at(d: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_be_bytes(d.get(at..at + 2)?.try_into().ok()?))
}

fn i16_at(d: &[u8], at: usize) -> Option<i16> {
    Some(i16::from_be_bytes(d.get(at..at + 2)?.try_into().ok()?))
}

fn u32_at(d: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_be_bytes(d.get(at..at + 4)?.try_into().ok()?))
}

impl Metrics {
    /// Reads the tables; `None` if the font lacks one or is malformed.
    fn parse(d: &[u8]) -> Option<Metrics> {
        let table = |tag: &[u8; 4]| -> Option<usize> {
            (0..usize::from(u16_at(d, 4)?))
                .map(|i| 12 + 16 * i)
                .find(|&rec| d.get(rec..rec + 4) == Some(&tag[..]))
                .and_then(|rec| Some(u32_at(d, rec + 8)? as usize))
        };
        let hhea = table(b"hhea")?;
        let height = f64::from(i16_at(d, hhea + 4)?) - f64::from(i16_at(d, hhea + 6)?);
        let metric_count = usize::from(u16_at(d, hhea + 34)?);
        let glyph_count = usize::from(u16_at(d, table(b"maxp")? + 4)?);

        let hmtx = table(b"hmtx")?;
        let mut advances = Vec::with_capacity(glyph_count);
        let mut bearings = Vec::with_capacity(glyph_count);
        for g in 0..glyph_count {
            if g < metric_count {
                advances.push(u16_at(d, hmtx + 4 * g)?);
                bearings.push(i16_at(d, hmtx + 4 * g + 2)?);
            } else {
                advances.push(*advances.last()?);
                bearings.push(i16_at(d, hmtx + 4 * metric_count + 2 * (g - metric_count))?);
            }
        }

        // The Unicode full-repertoire subtable (format 12).
        let cmap = table(b"cmap")?;
        let sub = (0..usize::from(u16_at(d, cmap + 2)?))
            .map(|i| cmap + 4 + 8 * i)
            .find_map(|rec| {
                let at = cmap + u32_at(d, rec + 4)? as usize;
                (u16_at(d, at)? == 12).then_some(at)
            })?;
        let groups = (0..u32_at(d, sub + 12)? as usize)
            .map(|i| {
                let g = sub + 16 + 12 * i;
                Some((u32_at(d, g)?, u32_at(d, g + 4)?, u32_at(d, g + 8)?))
            })
            .collect::<Option<Vec<_>>>()?;

        // Horizontal format-0 subtables of a version-0 `kern` table, if any.
        let mut kerning = Vec::new();
        if let Some(kern) = table(b"kern") {
            let mut at = kern + 4;
            for _ in 0..u16_at(d, kern + 2)? {
                let (length, coverage) = (u16_at(d, at + 2)?, u16_at(d, at + 4)?);
                if coverage == 1 {
                    for p in 0..usize::from(u16_at(d, at + 6)?) {
                        let pair = at + 14 + 6 * p;
                        kerning.push((u32_at(d, pair)?, i16_at(d, pair + 4)?));
                    }
                }
                at += usize::from(length);
            }
            kerning.sort_unstable();
        }
        (height > 0.0 && !advances.is_empty()).then_some(Metrics {
            height,
            groups,
            advances,
            bearings,
            kerning,
        })
    }

    fn glyph(&self, c: char) -> u32 {
        let c = u32::from(c);
        let i = self.groups.partition_point(|g| g.1 < c);
        match self.groups.get(i) {
            Some(&(first, _, glyph)) if first <= c => glyph + (c - first),
            _ => 0,
        }
    }

    fn kern(&self, left: u32, right: u32) -> f64 {
        let key = (left << 16) | (right & 0xFFFF);
        self.kerning
            .binary_search_by_key(&key, |p| p.0)
            .map_or(0.0, |i| f64::from(self.kerning[i].1))
    }

    /// Where each glyph's bitmap starts (px from the text origin) and the
    /// width of the whole string, at `size` px.
    fn layout(&self, text: &str, size: f64) -> (Vec<(char, i32)>, f64) {
        let scale = size / self.height;
        let mut pen = 0.0;
        let mut previous = None;
        let mut placed = Vec::new();
        for c in text.chars() {
            let g = self.glyph(c);
            let i = (g as usize).min(self.advances.len() - 1);
            if let Some(p) = previous {
                pen += self.kern(p, g) * scale;
            }
            // ab_glyph rasterises a lone glyph from the pixel its outline
            // starts in, i.e. floor(bearing) right of the origin.
            let bearing = (f64::from(self.bearings[i]) * scale).floor();
            placed.push((c, pen.round() as i32 + bearing as i32));
            pen += f64::from(self.advances[i]) * scale;
            previous = Some(g);
        }
        (placed, pen)
    }
}

/// Metrics of the embedded font, read once; `None` if they cannot be read, in
/// which case text is drawn by plotters as it is.
fn font_metrics() -> Option<&'static Metrics> {
    static METRICS: OnceLock<Option<Metrics>> = OnceLock::new();
    METRICS.get_or_init(|| Metrics::parse(FONT_BYTES)).as_ref()
}

// ---------------------------------------------------------------- axes

/// Values beyond this magnitude are treated like non-finite ones on a linear
/// axis: the span arithmetic would overflow.
const LINEAR_LIMIT: f64 = 1e300;

/// How the labels of an axis are written.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Labels {
    /// Linear ticks `step` apart, the same number of decimals on each.
    Linear { step: f64 },
    /// Log axis, ticks on whole decades: `10ⁿ`.
    Decades,
    /// Log axis, ticks at 1, 2 and 5 times a power of ten.
    OneTwoFive,
    /// Log axis spanning much less than a decade: linear ticks `step` apart,
    /// plotted at their logarithms.
    LinearInLog { step: f64 },
}

/// One axis in plot space: on a log axis every value is its `log10`.
#[derive(Debug, Clone, PartialEq)]
struct Axis {
    log: bool,
    lo: f64,
    hi: f64,
    /// Labelled ticks with bold grid lines (plot space).
    bold: Vec<f64>,
    /// Unlabelled light grid lines (plot space).
    light: Vec<f64>,
    labels: Labels,
}

impl Axis {
    /// The axis that shows every plottable value of `values`, padded a little,
    /// with at most about `max_labels` labels.
    fn fit(values: impl Iterator<Item = f64>, log: bool, max_labels: usize) -> Axis {
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
        let (lo, hi) = (lo - pad, hi + pad);
        let (bold, light, labels) = if log {
            log_ticks(lo, hi, max_labels)
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

    /// The text of the tick at `t` (plot space), with a typographic minus.
    fn label(&self, t: f64) -> String {
        let text = self.ascii_label(t);
        match text.strip_prefix('-') {
            Some(rest) => format!("−{rest}"),
            None => text,
        }
    }

    fn ascii_label(&self, t: f64) -> String {
        match self.labels {
            Labels::Linear { step } => format_linear(t, step),
            Labels::Decades => format!("10{}", superscript(t.round() as i64)),
            Labels::OneTwoFive => {
                let k = (t + 1e-9).floor();
                let m = 10f64.powf(t - k).round();
                let k = k as i64;
                if (-3..=5).contains(&k) {
                    format!("{:.*}", (-k).max(0) as usize, m * 10f64.powi(k as i32))
                } else {
                    format!("{m}e{k}")
                }
            }
            Labels::LinearInLog { step } => format_linear(10f64.powf(t), step),
        }
    }
}

/// The axis as a plotters coordinate: linear in plot space, with our own
/// ticks (plotters' `WithKeyPoints` would not take a label formatter).
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        let pixel = f64::from(limit.0) + t * f64::from(limit.1 - limit.0);
        // Far-off values are clamped rather than wrapped; NaN maps to 0.
        pixel.round().clamp(-1e6, 1e6) as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// A data value in plot space, or `None` if the axis cannot show it.
fn to_plot(v: f64, log: bool) -> Option<f64> {
    if !v.is_finite() {
        None
    } else if log {
        (v > 0.0).then(|| v.log10())
    } else {
        (v.abs() <= LINEAR_LIMIT).then_some(v)
    }
}

/// Multiples of `step` in `lo..=hi`; empty if there would be absurdly many.
fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
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
fn linear_ticks(lo: f64, hi: f64, max: usize) -> (Vec<f64>, Vec<f64>, f64) {
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

/// Ticks for a log axis over `lo..hi` (exponents of ten).
fn log_ticks(lo: f64, hi: f64, max: usize) -> (Vec<f64>, Vec<f64>, Labels) {
    let max = max.max(2);
    let decades: Vec<i64> = ((lo.ceil() as i64)..=(hi.floor() as i64)).collect();
    let minors = |keep: &dyn Fn(f64) -> bool| -> Vec<f64> {
        ((lo.floor() as i64)..=(hi.ceil() as i64))
            .flat_map(|k| (2..=9).map(move |m| k as f64 + f64::from(m).log10()))
            .filter(|&t| t >= lo && t <= hi && keep(t))
            .collect()
    };

    if decades.len() >= 3 {
        // Label every `every`-th decade; with few decades, light lines at 2..9.
        let every = [1, 2, 3, 4, 5, 10, 20, 25, 50, 100, 200, 500]
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
        } else if hi - lo <= 8.0 {
            minors(&|_| true)
        } else {
            Vec::new()
        };
        return (bold, light, Labels::Decades);
    }

    // Under three decades: 1-2-5 ticks if that gives a few labels.
    let one_two_five: Vec<f64> = ((lo.floor() as i64)..=(hi.ceil() as i64))
        .flat_map(|k| [1.0f64, 2.0, 5.0].map(|m| k as f64 + m.log10()))
        .filter(|&t| t >= lo && t <= hi)
        .collect();
    if (3..=max).contains(&one_two_five.len()) {
        let light = minors(&|t| {
            let m = 10f64.powf(t - t.floor()).round();
            m != 2.0 && m != 5.0
        });
        return (one_two_five, light, Labels::OneTwoFive);
    }
    if decades.len() == 2 {
        return (
            decades.iter().map(|&k| k as f64).collect(),
            minors(&|_| true),
            Labels::Decades,
        );
    }

    // A small fraction of a decade: ordinary linear ticks, placed at their logs.
    let (bold, light, step) = linear_ticks(10f64.powf(lo), 10f64.powf(hi), max);
    let logs = |v: Vec<f64>| -> Vec<f64> {
        v.into_iter()
            .filter(|&v| v > 0.0)
            .map(f64::log10)
            .filter(|&t| t >= lo && t <= hi)
            .collect()
    };
    (logs(bold), logs(light), Labels::LinearInLog { step })
}

/// `v` with as many decimals as ticks `step` apart need; scientific notation
/// for very large or very small steps.
fn format_linear(v: f64, step: f64) -> String {
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
fn superscript(n: i64) -> String {
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

// ---------------------------------------------------------------- drawing

/// Axes and plot-space polylines, shared by both renderings.
struct Layout {
    x: Axis,
    y: Axis,
    /// Per series: its runs of consecutive drawable points (plot space).
    series: Vec<Vec<Vec<(f64, f64)>>>,
    highlight: Option<Vec<Vec<(f64, f64)>>>,
}

impl Layout {
    fn new(chart: &Chart) -> Layout {
        let all = || {
            chart
                .series
                .iter()
                .chain(chart.highlight)
                .flat_map(|s| &s.points)
        };
        let x = Axis::fit(all().map(|p| p.0), chart.log_x, 12);
        let y = Axis::fit(all().map(|p| p.1), chart.log_y, 10);
        let runs = |s: &Series| -> Vec<Vec<(f64, f64)>> {
            let mut runs = vec![Vec::new()];
            for &(px, py) in &s.points {
                match (to_plot(px, x.log), to_plot(py, y.log)) {
                    (Some(px), Some(py)) => {
                        if let Some(run) = runs.last_mut() {
                            run.push((px, py));
                        }
                    }
                    _ => runs.push(Vec::new()),
                }
            }
            runs.retain(|r| !r.is_empty());
            runs
        };
        let series = chart.series.iter().map(runs).collect();
        let highlight = chart.highlight.map(runs);
        Layout {
            x,
            y,
            series,
            highlight,
        }
    }
}

fn draw_error(e: impl Display) -> anyhow::Error {
    anyhow!("drawing the chart: {e}")
}

fn render_rgb(chart: &Chart, layout: &Layout) -> Result<Vec<u8>> {
    ensure_font()?;
    let typesetting = font_metrics().map_or(Typesetting::Whole, Typesetting::Glyphs);
    let mut pixels = vec![0u8; SIZE.0 as usize * SIZE.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
        draw(&root, chart, layout, typesetting)?;
        root.present().map_err(draw_error)?;
    }
    Ok(pixels)
}

fn render_svg(chart: &Chart, layout: &Layout) -> Result<String> {
    ensure_font()?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        draw(&root, chart, layout, Typesetting::Whole)?;
        root.present().map_err(draw_error)?;
    }
    Ok(svg)
}

/// How strings reach the backend.
#[derive(Debug, Clone, Copy)]
enum Typesetting {
    /// Whole strings, laid out by the backend (the SVG's viewer).
    Whole,
    /// One glyph at a time, at the places [`Metrics::layout`] gives (the PNG).
    Glyphs(&'static Metrics),
}

/// Width in pixels of `text` at `size` px.
fn text_width<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    typesetting: Typesetting,
    text: &str,
    size: f64,
) -> Result<f64> {
    match typesetting {
        Typesetting::Whole => {
            let style = (FONT, size).into_font().into_text_style(area);
            let (width, _) = area.estimate_text_size(text, &style).map_err(draw_error)?;
            Ok(f64::from(width))
        }
        Typesetting::Glyphs(metrics) => Ok(metrics.layout(text, size).1),
    }
}

/// Draws black `text` at `size` px anchored at `at` (pixels in `area`);
/// `vertical` text reads bottom to top, its anchor taken along the text.
fn put_text<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    typesetting: Typesetting,
    text: &str,
    size: f64,
    (h_pos, v_pos): (HPos, VPos),
    at: (i32, i32),
    vertical: bool,
) -> Result<()> {
    let transform = if vertical {
        FontTransform::Rotate270
    } else {
        FontTransform::None
    };
    let style = |h_pos| {
        (FONT, size)
            .into_font()
            .transform(transform.clone())
            .color(&BLACK)
            .pos(Pos::new(h_pos, v_pos))
    };
    match typesetting {
        Typesetting::Whole => area.draw_text(text, &style(h_pos), at).map_err(draw_error),
        Typesetting::Glyphs(metrics) => {
            let (glyphs, width) = metrics.layout(text, size);
            let start = match h_pos {
                HPos::Left => 0.0,
                HPos::Center => -width / 2.0,
                HPos::Right => -width,
            }
            .round() as i32;
            let style = style(HPos::Left);
            let mut utf8 = [0u8; 4];
            for (c, x) in glyphs {
                if c.is_whitespace() {
                    continue;
                }
                let along = start + x;
                let at = if vertical {
                    (at.0, at.1 - along)
                } else {
                    (at.0 + along, at.1)
                };
                area.draw_text(c.encode_utf8(&mut utf8), &style, at)
                    .map_err(draw_error)?;
            }
            Ok(())
        }
    }
}

/// Marker shapes, cycled through alongside the colours so that series stay
/// apart in greyscale too.
#[derive(Debug, Clone, Copy)]
enum Marker {
    Circle,
    Square,
    Triangle,
    Diamond,
    Cross,
}

const MARKERS: [Marker; 5] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
    Marker::Cross,
];

/// Draws one marker of half-size `r` centred on `at` (any coordinate system).
fn draw_marker<DB: DrawingBackend, CT: CoordTranslate>(
    area: &DrawingArea<DB, CT>,
    at: CT::From,
    marker: Marker,
    r: i32,
    style: ShapeStyle,
) -> Result<()> {
    let at = EmptyElement::at(at);
    match marker {
        Marker::Circle => area.draw(&(at + Circle::new((0, 0), r, style))),
        Marker::Square => area.draw(&(at + Rectangle::new([(-r, -r), (r, r)], style))),
        Marker::Triangle => area.draw(&(at + TriangleMarker::new((0, 0), r + 1, style))),
        Marker::Diamond => {
            let d = r + 1;
            area.draw(&(at + Polygon::new(vec![(0, -d), (d, 0), (0, d), (-d, 0)], style)))
        }
        Marker::Cross => area.draw(&(at + Cross::new((0, 0), r, style.stroke_width(2)))),
    }
    .map_err(draw_error)
}

/// Draws a polyline, dashed or solid (any coordinate system).
fn draw_line<DB: DrawingBackend, CT: CoordTranslate>(
    area: &DrawingArea<DB, CT>,
    points: Vec<CT::From>,
    dashed: bool,
    style: ShapeStyle,
) -> Result<()>
where
    CT::From: Clone,
{
    if dashed {
        area.draw(&DashedPathElement::new(points, 12, 7, style))
    } else {
        area.draw(&PathElement::new(points, style))
    }
    .map_err(draw_error)
}

const SERIES_WIDTH: u32 = 2;
const MARKER_SIZE: i32 = 4;
const HIGHLIGHT_WIDTH: u32 = 4;
const HIGHLIGHT_MARKER: i32 = 6;
const HALO: RGBColor = RGBColor(0xFF, 0xFF, 0xFF);

// Font sizes in px. Keep them even: plotters puts a glyph's top at
// `trunc(size / 2 + top)` below the anchor, which for odd sizes jumps a pixel
// between glyphs whose tops differ by one ("e" and "x" at 17 px).
const TITLE_SIZE: f64 = 30.0;
const LABEL_SIZE: f64 = 20.0;
const TICK_SIZE: f64 = 16.0;
const LEGEND_SIZE: f64 = 16.0;

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    chart: &Chart,
    layout: &Layout,
    ts: Typesetting,
) -> Result<()> {
    root.fill(&WHITE).map_err(draw_error)?;
    let (width, _) = root.dim_in_pixel();
    put_text(
        root,
        ts,
        chart.title,
        TITLE_SIZE,
        (HPos::Center, VPos::Top),
        (width as i32 / 2, 12),
        false,
    )?;
    let (_, body) = root.margin(0, 8, 8, 8).split_vertically(56);

    // Legend entries: (name, colour, marker, dashed, highlighted).
    let mut entries: Vec<(&str, RGBColor, Marker, bool, bool)> = chart
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let colour = PALETTE[i % PALETTE.len()];
            let marker = MARKERS[i % MARKERS.len()];
            (s.name.as_str(), colour, marker, s.dashed, false)
        })
        .collect();
    if let Some(h) = chart.highlight {
        entries.push((h.name.as_str(), BLACK, Marker::Circle, h.dashed, true));
    }
    let mut text_room = 0.0f64;
    for entry in &entries {
        text_room = text_room.max(text_width(&body, ts, entry.0, LEGEND_SIZE)?);
    }
    let (body_width, _) = body.dim_in_pixel();
    let legend_width = if entries.is_empty() {
        0
    } else {
        (text_room.ceil() as u32 + 90).clamp(170, 380)
    };
    let (plot, legend) = body.split_horizontally(body_width.saturating_sub(legend_width) as i32);

    // Grid and ticks from plotters; their labels are drawn below with
    // `put_text`, so the mesh gets empty ones.
    let (x, y) = (&layout.x, &layout.y);
    let mut cc = ChartBuilder::on(&plot)
        .margin_top(12)
        .margin_right(12)
        .x_label_area_size(72)
        .y_label_area_size(104)
        .build_cartesian_2d(x.clone(), y.clone())
        .map_err(draw_error)?;
    let no_label = |_: &f64| String::new();
    cc.configure_mesh()
        .x_label_formatter(&no_label)
        .y_label_formatter(&no_label)
        .bold_line_style(BLACK.mix(0.2))
        .light_line_style(BLACK.mix(0.07))
        .axis_style(BLACK.mix(0.8))
        .draw()
        .map_err(draw_error)?;
    let area = cc.plotting_area();
    area.draw(&Rectangle::new(
        [(x.lo, y.lo), (x.hi, y.hi)],
        BLACK.mix(0.8).stroke_width(1),
    ))
    .map_err(draw_error)?;

    // Axis text, in pixels of the whole image.
    let (xs, ys) = area.get_pixel_range();
    for &t in &x.bold {
        let (px, _) = cc.backend_coord(&(t, y.lo));
        let at = (px, ys.end + 8);
        put_text(
            root,
            ts,
            &x.label(t),
            TICK_SIZE,
            (HPos::Center, VPos::Top),
            at,
            false,
        )?;
    }
    for &t in &y.bold {
        let (_, py) = cc.backend_coord(&(x.lo, t));
        let at = (xs.start - 10, py);
        put_text(
            root,
            ts,
            &y.label(t),
            TICK_SIZE,
            (HPos::Right, VPos::Center),
            at,
            false,
        )?;
    }
    let centre = ((xs.start + xs.end) / 2, (ys.start + ys.end) / 2);
    let anchor = (HPos::Center, VPos::Top);
    put_text(
        root,
        ts,
        chart.x_label,
        LABEL_SIZE,
        anchor,
        (centre.0, ys.end + 40),
        false,
    )?;
    let anchor = (HPos::Center, VPos::Center);
    put_text(
        root,
        ts,
        chart.y_label,
        LABEL_SIZE,
        anchor,
        (xs.start - 88, centre.1),
        true,
    )?;

    for (i, runs) in layout.series.iter().enumerate() {
        let (_, colour, marker, dashed, _) = entries[i];
        for run in runs {
            draw_line(area, run.clone(), dashed, colour.stroke_width(SERIES_WIDTH))?;
            for &p in run {
                draw_marker(area, p, marker, MARKER_SIZE, colour.filled())?;
            }
        }
    }
    if let (Some(runs), Some(h)) = (&layout.highlight, chart.highlight) {
        // A white halo first, so the line reads on top of whatever it crosses.
        for run in runs {
            let halo = HALO.stroke_width(HIGHLIGHT_WIDTH + 4);
            draw_line(area, run.clone(), false, halo)?;
        }
        for run in runs {
            let line = BLACK.stroke_width(HIGHLIGHT_WIDTH);
            draw_line(area, run.clone(), h.dashed, line)?;
            for &p in run {
                draw_marker(area, p, Marker::Circle, HIGHLIGHT_MARKER + 2, HALO.filled())?;
                draw_marker(area, p, Marker::Circle, HIGHLIGHT_MARKER, BLACK.filled())?;
            }
        }
    }

    if !entries.is_empty() {
        draw_legend(&legend, ts, &entries)?;
    }
    Ok(())
}

/// The legend, top-aligned with the plot, one entry per row; names too long
/// for the panel end in "…", and rows that do not fit become "… and N more".
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    ts: Typesetting,
    entries: &[(&str, RGBColor, Marker, bool, bool)],
) -> Result<()> {
    const ROW: i32 = 30;
    const TOP: i32 = 12;
    const TEXT_X: i32 = 70;
    let (width, height) = area.dim_in_pixel();
    let (width, height) = (width as i32, height as i32);
    let max_rows = ((height - 2 * TOP - 12) / ROW).max(1) as usize;
    let shown = if entries.len() > max_rows {
        max_rows - 1
    } else {
        entries.len()
    };
    let rows = shown + usize::from(shown < entries.len());
    let frame = [(4, TOP), (width - 6, TOP + 8 + rows as i32 * ROW)];
    area.draw(&Rectangle::new(frame, WHITE.filled()))
        .map_err(draw_error)?;
    area.draw(&Rectangle::new(frame, BLACK.mix(0.35).stroke_width(1)))
        .map_err(draw_error)?;

    let anchor = (HPos::Left, VPos::Center);
    let text_room = f64::from((width - TEXT_X - 12).max(10));
    for (row, &(name, colour, marker, dashed, highlighted)) in entries[..shown].iter().enumerate() {
        let cy = TOP + 4 + ROW / 2 + row as i32 * ROW;
        let (line_width, marker_size) = if highlighted {
            (HIGHLIGHT_WIDTH, HIGHLIGHT_MARKER)
        } else {
            (SERIES_WIDTH, MARKER_SIZE)
        };
        let sample = vec![(14, cy), (56, cy)];
        draw_line(area, sample, dashed, colour.stroke_width(line_width))?;
        draw_marker(area, (35, cy), marker, marker_size, colour.filled())?;
        let text = fit_text(area, ts, name, text_room)?;
        put_text(area, ts, &text, LEGEND_SIZE, anchor, (TEXT_X, cy), false)?;
    }
    if shown < entries.len() {
        let cy = TOP + 4 + ROW / 2 + shown as i32 * ROW;
        let more = format!("… and {} more", entries.len() - shown);
        put_text(area, ts, &more, LEGEND_SIZE, anchor, (14, cy), false)?;
    }
    Ok(())
}

/// `text`, cut short with "…" if it is wider than `room` pixels.
fn fit_text<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    ts: Typesetting,
    text: &str,
    room: f64,
) -> Result<String> {
    if text_width(area, ts, text, LEGEND_SIZE)? <= room {
        return Ok(text.to_owned());
    }
    let mut chars: Vec<char> = text.chars().collect();
    while chars.pop().is_some() {
        let candidate: String = chars.iter().collect::<String>() + "…";
        if text_width(area, ts, &candidate, LEGEND_SIZE)? <= room {
            return Ok(candidate);
        }
    }
    Ok("…".to_owned())
}

// ---------------------------------------------------------------- files

/// `path` with `suffix` appended to its last component.
fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

/// Writes `path` through a temporary file in the same directory, renamed into
/// place once complete; the temporary file is removed on failure.
fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> Result<()>,
) -> Result<()> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    let tmp = dir.join(format!(
        ".{name}.{}-{}.tmp",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    let result = (|| -> Result<()> {
        let file = OpenOptions::new().write(true).create_new(true).open(&tmp)?;
        let mut writer = BufWriter::new(file);
        write(&mut writer)?;
        let file = writer.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        drop(file);
        fs::rename(&tmp, path)?;
        Ok(())
    })();
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result.with_context(|| format!("writing {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn series(name: &str, points: Vec<(f64, f64)>) -> Series {
        Series {
            name: name.to_owned(),
            points,
            dashed: false,
        }
    }

    /// Error against steps over many decades, like `impulse accuracy` draws,
    /// with the Pareto front (lowest error at each step count) highlighted.
    fn accuracy_series() -> (Vec<Series>, Series) {
        let steps: Vec<f64> = (0..=8)
            .map(|i| 10f64.powf(2.0 + 0.5 * f64::from(i)))
            .collect();
        let order = |name: &str, c: f64, p: i32, floor: f64| {
            let points = steps.iter().map(|&n| (n, (c * n.powi(-p)).max(floor)));
            series(name, points.collect())
        };
        let methods = [
            order("explicit Euler", 10.0, 1, 1e-9),
            order("semi-implicit Euler", 1e2, 2, 1e-13),
            order("velocity Verlet", 1e7, 4, 1e-16),
        ];
        let front = steps
            .iter()
            .enumerate()
            .map(|(i, &n)| {
                let best = methods
                    .iter()
                    .map(|s| s.points[i].1)
                    .fold(f64::INFINITY, f64::min);
                (n, best)
            })
            .collect();
        let mut reference = order("reference slope O(h²)", 3e2, 2, 0.0);
        reference.dashed = true;
        let mut all = methods.to_vec();
        all.push(reference);
        (all, series("Pareto front", front))
    }

    fn non_background(img: &image::RgbImage) -> usize {
        img.pixels().filter(|p| p.0 != [255, 255, 255]).count()
    }

    fn near(img: &image::RgbImage, c: RGBColor) -> usize {
        img.pixels()
            .filter(|p| {
                let d = |a: u8, b: u8| (i32::from(a) - i32::from(b)).abs();
                d(p.0[0], c.0) + d(p.0[1], c.1) + d(p.0[2], c.2) < 20
            })
            .count()
    }

    #[test]
    fn log_log_chart_with_highlight_writes_png_and_svg() {
        let dir = tempfile::tempdir().unwrap();
        let (all, front) = accuracy_series();
        let three = &all[..3];
        let chart = Chart {
            title: "Energy error after 10 s",
            x_label: "steps",
            y_label: "relative energy error",
            log_x: true,
            log_y: true,
            series: three,
            highlight: Some(&front),
        };
        let (png, svg) = write_chart(&chart, &dir.path().join("accuracy")).unwrap();
        assert_eq!(png, dir.path().join("accuracy.png"));
        assert_eq!(svg, dir.path().join("accuracy.svg"));

        let img = image::open(&png).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), (1200, 800));
        assert!(non_background(&img) > 20_000, "{}", non_background(&img));
        for colour in &PALETTE[..3] {
            assert!(
                near(&img, *colour) > 300,
                "{colour:?}: {}",
                near(&img, *colour)
            );
        }

        let text = fs::read_to_string(&svg).unwrap();
        assert!(text.starts_with("<svg"));
        for name in [
            "explicit Euler",
            "semi-implicit Euler",
            "velocity Verlet",
            "Pareto front",
        ] {
            assert!(text.contains(name), "{name} missing from the SVG");
        }
        assert!(text.contains("10⁻¹⁶") && text.contains("10⁶"));

        // Nothing but the two charts is left in the directory.
        let mut left: Vec<_> = fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        left.sort();
        assert_eq!(left, ["accuracy.png", "accuracy.svg"]);
    }

    #[test]
    fn rewriting_replaces_both_files() {
        let dir = tempfile::tempdir().unwrap();
        let stem = dir.path().join("bench.v2");
        let s = [series("first", vec![(1.0, 1.0), (2.0, 3.0)])];
        let mut chart = Chart {
            title: "t",
            x_label: "x",
            y_label: "y",
            log_x: false,
            log_y: false,
            series: &s,
            highlight: None,
        };
        write_chart(&chart, &stem).unwrap();
        let s2 = [series("second", vec![(1.0, 1.0), (2.0, 3.0)])];
        chart.series = &s2;
        let (png, svg) = write_chart(&chart, &stem).unwrap();
        assert_eq!(png, dir.path().join("bench.v2.png"));
        let text = fs::read_to_string(svg).unwrap();
        assert!(text.contains("second") && !text.contains("first"));
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    #[test]
    fn empty_charts_still_write() {
        let dir = tempfile::tempdir().unwrap();
        let empty_series = [series("nothing yet", vec![])];
        for (i, (log, series)) in [(false, &[][..]), (true, &[][..]), (true, &empty_series[..])]
            .into_iter()
            .enumerate()
        {
            let chart = Chart {
                title: "",
                x_label: "",
                y_label: "",
                log_x: log,
                log_y: log,
                series,
                highlight: None,
            };
            let (png, svg) = write_chart(&chart, &dir.path().join(format!("empty{i}"))).unwrap();
            let img = image::open(&png).unwrap().to_rgb8();
            assert_eq!(img.dimensions(), SIZE);
            assert!(non_background(&img) > 0);
            assert!(fs::read_to_string(svg).unwrap().starts_with("<svg"));
        }
    }

    #[test]
    fn unplottable_points_are_skipped() {
        let dir = tempfile::tempdir().unwrap();
        let odd = [
            series(
                "zeros and negatives",
                vec![(0.0, 1.0), (-1.0, 2.0), (1.0, 0.0), (2.0, -5.0), (3.0, 4.0)],
            ),
            series(
                "non-finite",
                vec![
                    (f64::NAN, 1.0),
                    (1.0, f64::INFINITY),
                    (f64::NEG_INFINITY, 2.0),
                ],
            ),
            series("one point", vec![(5.0, 5.0)]),
            series("huge", vec![(1e308, -1e308), (f64::MAX, f64::MIN_POSITIVE)]),
        ];
        let only_bad = series("only bad", vec![(0.0, 0.0), (f64::NAN, -1.0)]);
        for (log_x, log_y) in [(true, true), (false, true), (true, false), (false, false)] {
            let chart = Chart {
                title: "odd data",
                x_label: "x",
                y_label: "y",
                log_x,
                log_y,
                series: &odd,
                highlight: Some(&only_bad),
            };
            let stem = dir.path().join(format!("odd-{log_x}-{log_y}"));
            let (png, _) = write_chart(&chart, &stem).unwrap();
            assert_eq!(image::open(&png).unwrap().to_rgb8().dimensions(), SIZE);
        }
    }

    #[test]
    fn unwritable_paths_are_errors() {
        let dir = tempfile::tempdir().unwrap();
        let s = [series("a", vec![(1.0, 1.0), (2.0, 2.0)])];
        let chart = Chart {
            title: "t",
            x_label: "x",
            y_label: "y",
            log_x: false,
            log_y: false,
            series: &s,
            highlight: None,
        };
        let missing = dir.path().join("no/such/dir/chart");
        let err = write_chart(&chart, &missing).unwrap_err();
        assert!(format!("{err:#}").contains("chart.png"), "{err:#}");

        let file = dir.path().join("a-file");
        fs::write(&file, "x").unwrap();
        assert!(write_chart(&chart, &file.join("chart")).is_err());
        assert!(write_chart(&chart, Path::new("/")).is_err());
        // Nothing half-written is left behind.
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn log_axes_over_many_decades() {
        let x = Axis::fit([1e2, 1e6].into_iter(), true, 12);
        assert_eq!(x.bold, [2.0, 3.0, 4.0, 5.0, 6.0]);
        let labels: Vec<String> = x.bold.iter().map(|&t| x.label(t)).collect();
        assert_eq!(labels, ["10²", "10³", "10⁴", "10⁵", "10⁶"]);
        assert!(!x.light.is_empty());

        let y = Axis::fit([1e-16, 1e2].into_iter(), true, 10);
        assert!(y.bold.len() <= 10 && y.bold.len() >= 5, "{:?}", y.bold);
        assert!(y.bold.contains(&-16.0) && y.bold.contains(&2.0));
        assert_eq!(y.label(-16.0), "10⁻¹⁶");
        assert!(y.lo < -16.0 && y.hi > 2.0);

        let narrow = Axis::fit([3.0, 40.0].into_iter(), true, 10);
        assert_eq!(narrow.labels, Labels::OneTwoFive);
        let labels: Vec<String> = narrow.bold.iter().map(|&t| narrow.label(t)).collect();
        assert_eq!(labels, ["5", "10", "20"]);

        let tiny = Axis::fit([100.0, 101.0].into_iter(), true, 10);
        assert!(matches!(tiny.labels, Labels::LinearInLog { .. }));
        assert!(tiny.bold.len() >= 3);
        assert_eq!(tiny.label(tiny.bold[0]), "100.0");
    }

    #[test]
    fn font_metrics_agree_with_plotters() {
        ensure_font().unwrap();
        let metrics = font_metrics().expect("metrics of the embedded font");
        let mut buffer = vec![0u8; 400 * 100 * 3];
        let area = BitMapBackend::with_buffer(&mut buffer, (400, 100)).into_drawing_area();
        for (text, size) in [
            ("reference slope O(h²)", 16.0),
            ("Energy error after 10 s", 30.0),
            ("AVAVA Tw 10⁻¹⁶ |ΔE| / E₀", 20.0),
        ] {
            let style = (FONT, size).into_font().into_text_style(&area);
            let (theirs, _) = area.estimate_text_size(text, &style).unwrap();
            let (glyphs, ours) = metrics.layout(text, size);
            assert_eq!(glyphs.len(), text.chars().count());
            assert!(
                (ours - f64::from(theirs)).abs() <= 2.0,
                "{text}: {ours} vs {theirs}"
            );
            assert!(glyphs.windows(2).all(|w| w[0].1 < w[1].1 + 3), "{glyphs:?}");
        }
        assert!(metrics.kern(metrics.glyph('A'), metrics.glyph('V')) < 0.0);
        assert_ne!(metrics.glyph('⁶'), 0);
        assert_eq!(metrics.glyph('\u{10FFFF}'), 0);
        assert!(Metrics::parse(&FONT_BYTES[..4096]).is_none());
        assert!(Metrics::parse(&[]).is_none());
    }

    #[test]
    fn linear_axis_labels() {
        let a = Axis::fit([0.0, 1.0].into_iter(), false, 10);
        let labels: Vec<String> = a.bold.iter().map(|&t| a.label(t)).collect();
        assert_eq!(labels, ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        let big = Axis::fit([0.0, 3e7].into_iter(), false, 10);
        assert_eq!(big.label(big.bold[1]), "5e6");
        assert_eq!(format_linear(1.5e-7, 1e-8), "1.5e-7");
        assert_eq!(format_linear(-2.0, 1.0), "-2");
        let signed = Axis::fit([-2.0, 2.0].into_iter(), false, 10);
        assert_eq!(signed.label(-1.0), "−1.0");
        let flat = Axis::fit([7.0, 7.0].into_iter(), false, 10);
        assert!(flat.lo < 7.0 && flat.hi > 7.0 && !flat.bold.is_empty());
    }

    /// Writes /tmp/chart-example.{png,svg} for a look:
    /// `cargo test --bin impulse chart_example -- --ignored`.
    #[test]
    #[ignore]
    fn chart_example() {
        let (all, front) = accuracy_series();
        let chart = Chart {
            title: "Energy error after 10 s, default scene",
            x_label: "steps",
            y_label: "relative energy error |ΔE| / E₀",
            log_x: true,
            log_y: true,
            series: &all,
            highlight: Some(&front),
        };
        let (png, svg) = write_chart(&chart, &std::env::temp_dir().join("chart-example")).unwrap();
        println!("{} {}", png.display(), svg.display());
    }

    mod properties {
        use super::*;
        use proptest::prelude::*;

        fn value() -> impl Strategy<Value = f64> {
            prop_oneof![
                4 => -1e3..1e3f64,
                2 => (-300..300i32).prop_map(|e| 10f64.powi(e)),
                1 => Just(0.0),
                1 => Just(f64::NAN),
                1 => Just(f64::INFINITY),
                1 => Just(f64::MAX),
                1 => Just(-f64::MAX),
                1 => Just(f64::MIN_POSITIVE),
                1 => Just(5e-324),
            ]
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(24))]
            /// Any data renders without panicking or failing.
            #[test]
            fn any_points_render(
                points in proptest::collection::vec((value(), value()), 0..12),
                log_x: bool,
                log_y: bool,
            ) {
                let s = [series("s", points.clone()), series("t", points.iter().rev().copied().collect())];
                let chart = Chart {
                    title: "p", x_label: "x", y_label: "y", log_x, log_y,
                    series: &s, highlight: None,
                };
                let layout = Layout::new(&chart);
                for axis in [&layout.x, &layout.y] {
                    prop_assert!(axis.lo.is_finite() && axis.hi.is_finite() && axis.lo < axis.hi);
                    prop_assert!(axis.bold.len() <= 40);
                }
                render_rgb(&chart, &layout).unwrap();
                render_svg(&chart, &layout).unwrap();
            }
        }
    }
}
