//! Charts for the lab commands, written as a PNG and an SVG side by side: line
//! charts ([`Chart`]) and grid charts, a heat map of labelled cells ([`Grid`],
//! in `grid.rs`).
//!
//! A [`Chart`] is a title, two axis labels, a linear or logarithmic scale per
//! axis, some [`Series`] and optionally one highlighted series (say a Pareto
//! front) drawn thick and black beneath the others, whose markers stay
//! visible on it. [`write_chart`] renders
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

mod axis;
mod grid;
mod text;

use axis::*;
pub use grid::{font_has, write_grid, Grid, GridCell};
use text::*;

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
    /// Colour, an index into [`PALETTE`]; by default the series' own index,
    /// so series that belong together (one method) can share a colour.
    pub colour: Option<usize>,
    /// Marker shape, an index into the five shapes (circle, square,
    /// triangle, diamond, cross); by default the series' own index.
    pub marker: Option<usize>,
    /// Line style, an index into [`LINE_STYLES`] (solid, dashed, dotted,
    /// long dashes); by default solid, or dashed if `dashed`.
    pub line: Option<usize>,
}

/// A legend entry: name, colour, marker, line pattern, highlighted.
type LegendEntry<'a> = (&'a str, RGBColor, Marker, Option<(u32, u32)>, bool);

/// Line styles: `None` solid, else (dash, gap) in pixels.
pub const LINE_STYLES: [Option<(u32, u32)>; 4] = [None, Some((12, 7)), Some((3, 5)), Some((24, 6))];

impl Series {
    /// The (dash, gap) the line is drawn with, or `None` for solid.
    fn pattern(&self) -> Option<(u32, u32)> {
        match self.line {
            Some(k) => LINE_STYLES[k % LINE_STYLES.len()],
            None => self.dashed.then_some((12, 7)),
        }
    }
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
    /// A series drawn thick and black beneath the others, e.g. a Pareto
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

/// `<stem>.png` and `<stem>.svg`, or an error if `stem` names no file.
fn image_paths(stem: &Path) -> Result<(PathBuf, PathBuf)> {
    if stem.file_name().is_none() {
        return Err(anyhow!(
            "chart path {} does not name a file",
            stem.display()
        ));
    }
    Ok((with_suffix(stem, ".png"), with_suffix(stem, ".svg")))
}

/// Writes `<stem>.png` (1200x800) and `<stem>.svg` side by side; returns the two paths.
///
/// `.png` and `.svg` are appended to `stem` (so `out/bench.v2` gives
/// `out/bench.v2.png`). The directory must exist. Both images are rendered
/// before either file is written, and each file is replaced atomically.
pub fn write_chart(chart: &Chart, stem: &Path) -> Result<(PathBuf, PathBuf)> {
    let (png_path, svg_path) = image_paths(stem)?;
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

/// Draws a polyline, solid or with (dash, gap) `pattern` (any coordinate
/// system).
fn draw_line<DB: DrawingBackend, CT: CoordTranslate>(
    area: &DrawingArea<DB, CT>,
    points: Vec<CT::From>,
    pattern: Option<(u32, u32)>,
    style: ShapeStyle,
) -> Result<()>
where
    CT::From: Clone,
{
    match pattern {
        Some((dash, gap)) => area.draw(&DashedPathElement::new(points, dash, gap, style)),
        None => area.draw(&PathElement::new(points, style)),
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

    // Legend entries: (name, colour, marker, line pattern, highlighted).
    let mut entries: Vec<LegendEntry> = chart
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let colour = PALETTE[s.colour.unwrap_or(i) % PALETTE.len()];
            let marker = MARKERS[s.marker.unwrap_or(i) % MARKERS.len()];
            (s.name.as_str(), colour, marker, s.pattern(), false)
        })
        .collect();
    if let Some(h) = chart.highlight {
        entries.push((h.name.as_str(), BLACK, Marker::Circle, h.pattern(), true));
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

    // The highlight first, so that no data point is hidden under it.
    if let (Some(runs), Some(h)) = (&layout.highlight, chart.highlight) {
        // A white halo first, so the line reads on top of whatever it crosses.
        for run in runs {
            let halo = HALO.stroke_width(HIGHLIGHT_WIDTH + 4);
            draw_line(area, run.clone(), None, halo)?;
        }
        for run in runs {
            let line = BLACK.stroke_width(HIGHLIGHT_WIDTH);
            draw_line(area, run.clone(), h.pattern(), line)?;
            for &p in run {
                draw_marker(area, p, Marker::Circle, HIGHLIGHT_MARKER + 2, HALO.filled())?;
                draw_marker(area, p, Marker::Circle, HIGHLIGHT_MARKER, BLACK.filled())?;
            }
        }
    }

    for (i, runs) in layout.series.iter().enumerate() {
        let (_, colour, marker, pattern, _) = entries[i];
        for run in runs {
            draw_line(
                area,
                run.clone(),
                pattern,
                colour.stroke_width(SERIES_WIDTH),
            )?;
            for &p in run {
                draw_marker(area, p, marker, MARKER_SIZE, colour.filled())?;
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
    entries: &[LegendEntry],
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
    for (row, &(name, colour, marker, pattern, highlighted)) in entries[..shown].iter().enumerate()
    {
        let cy = TOP + 4 + ROW / 2 + row as i32 * ROW;
        let (line_width, marker_size) = if highlighted {
            (HIGHLIGHT_WIDTH, HIGHLIGHT_MARKER)
        } else {
            (SERIES_WIDTH, MARKER_SIZE)
        };
        let sample = vec![(14, cy), (56, cy)];
        draw_line(area, sample, pattern, colour.stroke_width(line_width))?;
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
mod tests;
