//! Charts for the lab commands, written as a PNG and an SVG side by side: line
//! charts ([`Chart`]) and grid charts, a heat map of labelled cells ([`Grid`],
//! in `grid.rs`).
//!
//! A [`Chart`] is a title (and a line of explanation under it), two axis
//! labels, a linear or logarithmic scale per axis, some [`Series`],
//! optionally one highlighted series (say a Pareto front: a grey band under
//! its points and a black ring around each) and optionally a labelled
//! horizontal floor (say the noise floor of a measurement, the band under it
//! shaded). [`write_chart`] renders it at 1500×1000 with grid lines, one
//! marker per point, and either a legend to the right of the plot or, with
//! [`Chart::direct_labels`], each line's name at its last point, moved up or
//! down until no two names overlap. Text given per point (a step size, say)
//! is set beside its point where it covers no marker and no other label.
//!
//! Colours come from the Okabe–Ito colour-blind-safe palette, one per method
//! in every chart ([`method_colour`]); line styles (solid, dashed, dotted,
//! dash-dot) and marker shapes tell apart series of one colour. Log axes are
//! labelled at whole decades, 10ᵏ, with minor ticks at 2…9 × 10ᵏ between.
//!
//! Text is drawn with DejaVu Sans, embedded in the binary
//! (`assets/fonts/DejaVuSans.ttf`, licence next to it), so no fontconfig or
//! system font is needed at run time. In the PNG, strings are laid out glyph
//! by glyph from the font's own metrics (see [`Metrics`]), because plotters'
//! layout puts letters unevenly. Where labels go is worked out once, in
//! pixels, from those metrics ([`Plan`]), and both images draw the same plan.
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
use impulse::method::{Method, Setting};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontTransform;
use std::fmt::Display;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Once, OnceLock};

mod axis;
mod grid;
mod layout;
mod place;
mod text;

use axis::*;
pub use grid::{font_has, write_grid, Grid, GridCell};
use layout::*;
use place::*;
use text::*;

/// One line of a chart: points joined in the given order, with a marker on
/// each.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Series {
    /// Legend entry or line-end label (and text in the SVG).
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
    /// dash-dot); by default solid, or dashed if `dashed`.
    pub line: Option<usize>,
    /// Text set beside each point (the i-th for the i-th point; missing or
    /// empty ones are none). A label equal to one already set at the same
    /// spot is not repeated.
    pub point_labels: Vec<String>,
    /// Markers drawn as outlines, larger than filled ones, so that a series
    /// lying on another one shows both.
    pub hollow: bool,
}

/// A legend entry: name, colour, marker, line pattern, hollow.
type LegendEntry<'a> = (&'a str, RGBColor, Marker, &'static [u32], bool);

/// Line styles as dash patterns in pixels (drawn, skipped, …): solid,
/// dashed, dotted, dash-dot.
pub const LINE_STYLES: [&[u32]; 4] = [&[], &[16, 8], &[3, 6], &[16, 6, 3, 6]];

impl Series {
    /// The dash pattern the line is drawn with (empty for solid).
    fn pattern(&self) -> &'static [u32] {
        match self.line {
            Some(k) => LINE_STYLES[k % LINE_STYLES.len()],
            None if self.dashed => LINE_STYLES[1],
            None => LINE_STYLES[0],
        }
    }
}

/// Everything [`write_chart`] draws.
#[derive(Debug, Clone, Copy, Default)]
pub struct Chart<'a> {
    /// Title above the plot.
    pub title: &'a str,
    /// A line of explanation under the title (may be empty).
    pub subtitle: &'a str,
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
    /// Points drawn on a grey band beneath the others, each ringed in black
    /// (a Pareto front, say); in the legend last.
    pub highlight: Option<&'a Series>,
    /// Name each line at its last point instead of in a legend.
    pub direct_labels: bool,
    /// A dashed horizontal line across the plot at this height, labelled
    /// with the text, and the band under it shaded (a noise floor, say).
    pub floor: Option<(f64, &'a str)>,
}

/// Pixel size of the PNG (and the SVG's view box).
pub const SIZE: (u32, u32) = (1500, 1000);

/// Okabe & Ito's colour-blind-safe palette.
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

/// A method's colour, an index into [`PALETTE`], the same in every chart:
/// seed orange, impulse blue, verlet bluish green, exact reddish purple
/// (`auto`, which picks among them, is [`AUTO_COLOUR`]). No two are the
/// two blues or otherwise near each other.
pub fn method_colour(method: Method) -> usize {
    match method {
        Method::Seed => 0,
        Method::Impulse => 4,
        Method::Verlet => 2,
        Method::Exact => 6,
    }
}

/// `auto`'s colour (vermillion).
pub const AUTO_COLOUR: usize = 5;

/// The colour of a method setting: a fixed method's, or `auto`'s.
pub fn setting_colour(setting: Setting<Method>) -> RGBColor {
    PALETTE[match setting {
        Setting::Fixed(m) => method_colour(m),
        Setting::Auto => AUTO_COLOUR,
    }]
}

/// Indices of the points on the Pareto front of cost (`x`) against the size
/// of the error, `|y|`: the points no other point beats on both, in order
/// of cost. Points with a non-finite coordinate take no part.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].0.is_finite() && points[i].1.is_finite())
        .collect();
    order.sort_by(|&a, &b| {
        let (pa, pb) = (points[a], points[b]);
        pa.0.total_cmp(&pb.0)
            .then(pa.1.abs().total_cmp(&pb.1.abs()))
    });
    let mut best = f64::INFINITY;
    order.retain(|&i| {
        let err = points[i].1.abs();
        let on = err < best;
        best = best.min(err);
        on
    });
    order
}

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

/// Writes `<stem>.png` (1500×1000) and `<stem>.svg` side by side; returns the
/// two paths.
///
/// `.png` and `.svg` are appended to `stem` (so `out/bench.v2` gives
/// `out/bench.v2.png`). The directory must exist. Both images are rendered
/// before either file is written, and each file is replaced atomically.
pub fn write_chart(chart: &Chart, stem: &Path) -> Result<(PathBuf, PathBuf)> {
    let (png_path, svg_path) = image_paths(stem)?;
    let plan = Plan::new(chart);
    let pixels = render_rgb(chart, &plan)?;
    let svg = render_svg(chart, &plan)?;

    write_images((&png_path, &pixels, SIZE), (&svg_path, &svg))?;
    Ok((png_path, svg_path))
}

/// Writes the PNG of `pixels` (RGB, `size`) and the SVG text, each replaced
/// atomically ([`crate::files::write_atomically`]).
fn write_images(
    (png_path, pixels, size): (&Path, &[u8], (u32, u32)),
    (svg_path, svg): (&Path, &str),
) -> Result<()> {
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(pixels, size.0, size.1, image::ColorType::Rgb8)
        .context("encoding PNG")?;
    for (path, bytes) in [(png_path, &png[..]), (svg_path, svg.as_bytes())] {
        crate::files::write_atomically(path, bytes)
            .with_context(|| format!("writing {}", path.display()))?;
    }
    Ok(())
}

// ---------------------------------------------------------------- layout

const SERIES_WIDTH: u32 = 3;
const MARKER_SIZE: i32 = 6;
const HOLLOW_SIZE: i32 = 10;
const FRONT_WIDTH: u32 = 14;
const FRONT_RING: i32 = 13;
const HALO: RGBColor = RGBColor(0xFF, 0xFF, 0xFF);
const FLOOR_COLOUR: RGBColor = RGBColor(0x44, 0x44, 0x44);

// Font sizes in px, chosen to stay legible with the image shown at half
// size. Keep them even: plotters puts a glyph's top at `trunc(size / 2 +
// top)` below the anchor, which for odd sizes jumps a pixel between glyphs
// whose tops differ by one ("e" and "x" at 17 px).
const TITLE_SIZE: f64 = 34.0;
const SUBTITLE_SIZE: f64 = 20.0;
const LABEL_SIZE: f64 = 24.0;
const TICK_SIZE: f64 = 22.0;
const LEGEND_SIZE: f64 = 20.0;
const END_SIZE: f64 = 20.0;
const POINT_SIZE: f64 = 18.0;

/// Space around the image and room for the axis text (px).
const EDGE: i32 = 10;
const Y_TEXT_ROOM: i32 = 140;
const X_TEXT_ROOM: i32 = 96;

fn draw_error(e: impl Display) -> anyhow::Error {
    anyhow!("drawing the chart: {e}")
}

fn render_rgb(chart: &Chart, plan: &Plan) -> Result<Vec<u8>> {
    ensure_font()?;
    let typesetting = font_metrics().map_or(Typesetting::Whole, Typesetting::Glyphs);
    let mut pixels = vec![0u8; SIZE.0 as usize * SIZE.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
        draw(&root, chart, plan, typesetting)?;
        root.present().map_err(draw_error)?;
    }
    Ok(pixels)
}

fn render_svg(chart: &Chart, plan: &Plan) -> Result<String> {
    ensure_font()?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        draw(&root, chart, plan, Typesetting::Whole)?;
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

/// Draws one marker of half-size `r` centred on `at` (pixels).
fn draw_marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    at: (i32, i32),
    marker: Marker,
    r: i32,
    style: ShapeStyle,
) -> Result<()> {
    let centre = at;
    let at = EmptyElement::at(centre);
    // A closed outline around the centre: filled, or its line only.
    let shape = |corners: Vec<(i32, i32)>| {
        let at = EmptyElement::at(centre);
        if style.filled {
            area.draw(&(at + Polygon::new(corners, style)))
        } else {
            area.draw(&(at + PathElement::new(corners, style)))
        }
    };
    let d = r + 2;
    match marker {
        Marker::Circle => area.draw(&(at + Circle::new((0, 0), r, style))),
        Marker::Square => {
            let r = r * 7 / 8;
            area.draw(&(at + Rectangle::new([(-r, -r), (r, r)], style)))
        }
        Marker::Triangle => shape(vec![(0, -d), (d, d * 3 / 4), (-d, d * 3 / 4), (0, -d)]),
        Marker::Diamond => shape(vec![(0, -d), (d, 0), (0, d), (-d, 0), (0, -d)]),
        Marker::Cross => area.draw(&(at + Cross::new((0, 0), r, style.stroke_width(3)))),
    }
    .map_err(draw_error)
}

/// A marker as a series draws it: filled, or an outline if `hollow`.
fn series_marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    at: (i32, i32),
    marker: Marker,
    colour: RGBColor,
    hollow: bool,
) -> Result<()> {
    if hollow {
        draw_marker(area, at, marker, HOLLOW_SIZE, colour.stroke_width(3))
    } else {
        draw_marker(area, at, marker, MARKER_SIZE + 1, HALO.filled())?;
        draw_marker(area, at, marker, MARKER_SIZE, colour.filled())
    }
}

/// Draws a polyline (pixels) with a dash `pattern` (empty: solid).
fn draw_line<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    points: &[(i32, i32)],
    pattern: &[u32],
    style: ShapeStyle,
) -> Result<()> {
    for piece in dashes(points, pattern) {
        area.draw(&PathElement::new(piece, style))
            .map_err(draw_error)?;
    }
    Ok(())
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    chart: &Chart,
    plan: &Plan,
    ts: Typesetting,
) -> Result<()> {
    root.fill(&WHITE).map_err(draw_error)?;
    let (width, _) = root.dim_in_pixel();
    let centre_top = (HPos::Center, VPos::Top);
    put_text(
        root,
        ts,
        chart.title,
        TITLE_SIZE,
        centre_top,
        (width as i32 / 2, 14),
        false,
    )?;
    if !chart.subtitle.is_empty() {
        let at = (width as i32 / 2, 60);
        put_text(
            root,
            ts,
            chart.subtitle,
            SUBTITLE_SIZE,
            centre_top,
            at,
            false,
        )?;
    }
    let plot = plan.plot;
    let (x, y) = (&plan.x, &plan.y);
    let px = |t: f64| x.pixel(t, plot.x0, plot.x1);
    let py = |t: f64| y.pixel(t, plot.y1, plot.y0);
    let line = |a: (i32, i32), b: (i32, i32), style: ShapeStyle| {
        root.draw(&PathElement::new(vec![a, b], style))
            .map_err(draw_error)
    };

    // Below the floor: shaded, what rounding alone gives.
    if let Some(fy) = plan.floor {
        let band = [(plot.x0, fy), (plot.x1, plot.y1)];
        root.draw(&Rectangle::new(band, BLACK.mix(0.06).filled()))
            .map_err(draw_error)?;
    }
    // Grid: light lines at minor ticks, darker at labelled ones.
    for &t in &x.light {
        line((px(t), plot.y0), (px(t), plot.y1), BLACK.mix(0.07).into())?;
    }
    for &t in &y.light {
        line((plot.x0, py(t)), (plot.x1, py(t)), BLACK.mix(0.07).into())?;
    }
    for &t in &x.bold {
        line((px(t), plot.y0), (px(t), plot.y1), BLACK.mix(0.2).into())?;
    }
    for &t in &y.bold {
        line((plot.x0, py(t)), (plot.x1, py(t)), BLACK.mix(0.2).into())?;
    }
    // Frame, and ticks outside it: long at labels, short at minor ticks.
    root.draw(&Rectangle::new(
        [(plot.x0, plot.y0), (plot.x1, plot.y1)],
        BLACK.mix(0.8).stroke_width(1),
    ))
    .map_err(draw_error)?;
    let tick = BLACK.mix(0.8).stroke_width(1);
    for (ticks, len) in [(&x.bold, 9), (&x.light, 5)] {
        for &t in ticks {
            line((px(t), plot.y1), (px(t), plot.y1 + len), tick)?;
        }
    }
    for (ticks, len) in [(&y.bold, 9), (&y.light, 5)] {
        for &t in ticks {
            line((plot.x0 - len, py(t)), (plot.x0, py(t)), tick)?;
        }
    }

    // Axis text.
    for &t in &x.bold {
        let at = (px(t), plot.y1 + 14);
        put_text(root, ts, &x.label(t), TICK_SIZE, centre_top, at, false)?;
    }
    for &t in &y.bold {
        let at = (plot.x0 - 14, py(t));
        let anchor = (HPos::Right, VPos::Center);
        put_text(root, ts, &y.label(t), TICK_SIZE, anchor, at, false)?;
    }
    let centre = ((plot.x0 + plot.x1) / 2, (plot.y0 + plot.y1) / 2);
    let at = (centre.0, plot.y1 + 54);
    put_text(root, ts, chart.x_label, LABEL_SIZE, centre_top, at, false)?;
    let anchor = (HPos::Center, VPos::Center);
    let at = (plot.x0 - Y_TEXT_ROOM + 18, centre.1);
    put_text(root, ts, chart.y_label, LABEL_SIZE, anchor, at, true)?;

    // The floor line.
    if let Some(fy) = plan.floor {
        let style = FLOOR_COLOUR.stroke_width(2);
        draw_line(root, &[(plot.x0, fy), (plot.x1, fy)], &[10, 6], style)?;
    }

    // The highlight beneath everything else: a grey band along it.
    for run in runs(&plan.highlight) {
        let band = BLACK.mix(0.16).stroke_width(FRONT_WIDTH);
        draw_line(root, &run, &[], band)?;
    }

    // Leaders of labels that had to move, under the lines.
    for l in &plan.labels {
        if let Some((from, to)) = l.leader {
            let far = (from.0 - to.0).abs().max((from.1 - to.1).abs());
            if l.kind == LabelKind::End || far > LEADER_FROM {
                line(from, to, l.colour.mix(0.7).stroke_width(1))?;
            }
        }
    }

    // Lines first, then markers, so that no line hides a marker.
    for (i, (s, pts)) in chart.series.iter().zip(&plan.points).enumerate() {
        for run in runs(pts) {
            let style = s.colour_at(i).stroke_width(SERIES_WIDTH);
            draw_line(root, &run, s.pattern(), style)?;
        }
    }
    for (i, (s, pts)) in chart.series.iter().zip(&plan.points).enumerate() {
        for &p in pts.iter().flatten() {
            series_marker(root, p, s.marker_at(i), s.colour_at(i), s.hollow)?;
        }
    }
    for &p in plan.highlight.iter().flatten() {
        root.draw(&Circle::new(p, FRONT_RING, BLACK.stroke_width(3)))
            .map_err(draw_error)?;
    }

    // Labels on a white ground.
    for l in &plan.labels {
        let r = l.rect;
        let ground = [(r.x0, r.y0), (r.x1, r.y1)];
        root.draw(&Rectangle::new(ground, WHITE.mix(0.85).filled()))
            .map_err(draw_error)?;
        let anchor = (HPos::Left, VPos::Center);
        let at = (r.x0 + PAD, r.centre_y());
        put_text_in(root, ts, &l.text, l.size, anchor, at, false, &l.colour)?;
    }

    if let Some(rect) = plan.legend {
        let mut entries: Vec<LegendEntry> = chart
            .series
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let (c, m) = (s.colour_at(i), s.marker_at(i));
                (s.name.as_str(), c, m, s.pattern(), s.hollow)
            })
            .collect();
        if let Some(h) = chart.highlight {
            entries.push((h.name.as_str(), BLACK, Marker::Circle, &[], true));
        }
        draw_legend(root, ts, rect, &entries)?;
    }
    Ok(())
}

const LEGEND_ROW: i32 = 32;

/// The legend in `rect`, one entry per row; names too long for the panel
/// end in "…", and rows that do not fit become "… and N more".
fn draw_legend<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    ts: Typesetting,
    rect: PxRect,
    entries: &[LegendEntry],
) -> Result<()> {
    let max_rows = ((rect.y1 - rect.y0 - 10) / LEGEND_ROW).max(1) as usize;
    let shown = if entries.len() > max_rows {
        max_rows - 1
    } else {
        entries.len()
    };
    let frame = [(rect.x0, rect.y0), (rect.x1, rect.y1)];
    root.draw(&Rectangle::new(frame, WHITE.filled()))
        .map_err(draw_error)?;
    root.draw(&Rectangle::new(frame, BLACK.mix(0.35).stroke_width(1)))
        .map_err(draw_error)?;

    let anchor = (HPos::Left, VPos::Center);
    let text_x = rect.x0 + 76;
    let text_room = f64::from((rect.x1 - text_x - 8).max(10));
    for (row, &(name, colour, marker, pattern, hollow)) in entries[..shown].iter().enumerate() {
        let cy = rect.y0 + 5 + LEGEND_ROW / 2 + row as i32 * LEGEND_ROW;
        let sample = [(rect.x0 + 10, cy), (rect.x0 + 62, cy)];
        draw_line(root, &sample, pattern, colour.stroke_width(SERIES_WIDTH))?;
        series_marker(root, (rect.x0 + 36, cy), marker, colour, hollow)?;
        let text = fit_text(root, ts, name, text_room)?;
        put_text(root, ts, &text, LEGEND_SIZE, anchor, (text_x, cy), false)?;
    }
    if shown < entries.len() {
        let cy = rect.y0 + 5 + LEGEND_ROW / 2 + shown as i32 * LEGEND_ROW;
        let more = format!("… and {} more", entries.len() - shown);
        put_text(
            root,
            ts,
            &more,
            LEGEND_SIZE,
            anchor,
            (rect.x0 + 10, cy),
            false,
        )?;
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

#[cfg(test)]
mod reader_tests;
#[cfg(test)]
mod tests;
