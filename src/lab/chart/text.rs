//! Text for the PNG charts: the bundled font, registered once, and a glyph-
//! by-glyph layout from the font's own metrics (plotters 0.3.7 ignores left
//! side bearings, which spaced letters unevenly).

use super::*;

/// Font family name the embedded font is registered under (plotters' default
/// sans-serif family, which is also what the SVG asks its viewer for).
pub(super) const FONT: &str = "sans-serif";

pub(super) static FONT_BYTES: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

/// Registers the embedded DejaVu Sans with plotters, once per process.
pub(super) fn ensure_font() -> Result<()> {
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
pub(super) struct Metrics {
    /// Ascender minus descender in font units: ab_glyph scales a font of
    /// size `s` px by `s / height`.
    pub(super) height: f64,
    /// `cmap` format 12 groups: first char, last char, first glyph.
    pub(super) groups: Vec<(u32, u32, u32)>,
    /// `hmtx`: advance width and left side bearing per glyph.
    pub(super) advances: Vec<u16>,
    pub(super) bearings: Vec<i16>,
    /// `kern` format 0 pairs, sorted: (left << 16 | right, adjustment).
    pub(super) kerning: Vec<(u32, i16)>,
}

pub(super) fn u16_at(d: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_be_bytes(d.get(at..at + 2)?.try_into().ok()?))
}

pub(super) fn i16_at(d: &[u8], at: usize) -> Option<i16> {
    Some(i16::from_be_bytes(d.get(at..at + 2)?.try_into().ok()?))
}

pub(super) fn u32_at(d: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_be_bytes(d.get(at..at + 4)?.try_into().ok()?))
}

impl Metrics {
    /// Reads the tables; `None` if the font lacks one or is malformed.
    pub(super) fn parse(d: &[u8]) -> Option<Metrics> {
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

    pub(super) fn glyph(&self, c: char) -> u32 {
        let c = u32::from(c);
        let i = self.groups.partition_point(|g| g.1 < c);
        match self.groups.get(i) {
            Some(&(first, _, glyph)) if first <= c => glyph + (c - first),
            _ => 0,
        }
    }

    pub(super) fn kern(&self, left: u32, right: u32) -> f64 {
        let key = (left << 16) | (right & 0xFFFF);
        self.kerning
            .binary_search_by_key(&key, |p| p.0)
            .map_or(0.0, |i| f64::from(self.kerning[i].1))
    }

    /// Where each glyph's bitmap starts (px from the text origin) and the
    /// width of the whole string, at `size` px.
    pub(super) fn layout(&self, text: &str, size: f64) -> (Vec<(char, i32)>, f64) {
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
pub(super) fn font_metrics() -> Option<&'static Metrics> {
    static METRICS: OnceLock<Option<Metrics>> = OnceLock::new();
    METRICS.get_or_init(|| Metrics::parse(FONT_BYTES)).as_ref()
}

// ---------------------------------------------------------------- axes

/// Width in pixels of `text` at `size` px.
pub(super) fn text_width<DB: DrawingBackend>(
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

/// Width of `text` at `size` px by the bundled font's metrics (a generous
/// guess if they cannot be read), whole pixels up.
pub(super) fn width_of(text: &str, size: f64) -> i32 {
    let w = font_metrics().map_or(0.62 * size * text.chars().count() as f64, |m| {
        m.layout(text, size).1
    });
    w.ceil() as i32
}

/// Draws black `text` at `size` px anchored at `at` (pixels in `area`);
/// `vertical` text reads bottom to top, its anchor taken along the text.
pub(super) fn put_text<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    typesetting: Typesetting,
    text: &str,
    size: f64,
    anchor: (HPos, VPos),
    at: (i32, i32),
    vertical: bool,
) -> Result<()> {
    put_text_in(area, typesetting, text, size, anchor, at, vertical, &BLACK)
}

/// [`put_text`] in `colour`.
#[allow(clippy::too_many_arguments)]
pub(super) fn put_text_in<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    typesetting: Typesetting,
    text: &str,
    size: f64,
    (h_pos, v_pos): (HPos, VPos),
    at: (i32, i32),
    vertical: bool,
    colour: &RGBColor,
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
            .color(colour)
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
