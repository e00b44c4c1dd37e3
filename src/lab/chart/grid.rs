//! Grid charts (a heat map of labelled cells), written as a PNG and an SVG
//! side by side: a title, a line of legend swatches and a note under it,
//! column labels on top, row labels (each with a smaller second line) on the
//! left, and one filled cell with centred text per row and column.
//!
//! The image is sized to its text: the label column is as wide as the
//! longest label and every data column as wide as the widest cell or column
//! label, so nothing is clipped. Text uses the bundled font as the line charts
//! do (glyph by glyph in the PNG, whole strings in the SVG).

use super::*;

/// One cell of a [`Grid`].
#[derive(Debug, Clone, PartialEq)]
pub struct GridCell {
    /// Centred in the cell.
    pub text: String,
    /// Fill of the cell (text is black, so keep it light).
    pub fill: RGBColor,
}

/// Everything [`write_grid`] draws.
#[derive(Debug, Clone, Copy)]
pub struct Grid<'a> {
    /// Title above everything.
    pub title: &'a str,
    /// Colour swatches with their meaning, on the line under the title.
    pub legend: &'a [(&'a str, RGBColor)],
    /// Text after the legend on the same line.
    pub note: &'a str,
    /// Column labels, left to right.
    pub columns: &'a [String],
    /// A colour bar under each column label (a method's colour, say); empty
    /// for none.
    pub column_colours: &'a [RGBColor],
    /// Row labels, top to bottom: a label and a smaller line under it.
    pub rows: &'a [(String, String)],
    /// The cells, row by row (`rows.len() × columns.len()` of them; missing
    /// ones are left blank and extra ones ignored).
    pub cells: &'a [GridCell],
}

const MARGIN: i32 = 16;
const PAD: i32 = 12;
const TITLE: f64 = 28.0;
const LEGEND: f64 = 16.0;
const HEADER: f64 = 20.0;
const LABEL: f64 = 18.0;
const SUBLABEL: f64 = 14.0;
const CELL: f64 = 18.0;
const SWATCH: i32 = 16;
const HEADER_TOP: i32 = 90;
const HEADER_HEIGHT: i32 = 36;
const ROW_HEIGHT: i32 = 56;
const MIN_COLUMN: i32 = 120;

/// Whether the bundled font draws `c` (rather than an empty box).
pub fn font_has(c: char) -> bool {
    font_metrics().is_some_and(|m| m.glyph(c) != 0)
}

/// Pixel positions shared by both renderings.
struct GridLayout {
    size: (u32, u32),
    label_width: i32,
    column_width: i32,
    /// Left edge of the legend line.
    legend_x: i32,
}

impl GridLayout {
    fn new(grid: &Grid) -> GridLayout {
        let label_width = grid
            .rows
            .iter()
            .map(|(a, b)| width_of(a, LABEL).max(width_of(b, SUBLABEL)))
            .max()
            .unwrap_or(0)
            + 2 * PAD;
        let column_width = grid
            .cells
            .iter()
            .map(|c| width_of(&c.text, CELL))
            .chain(grid.columns.iter().map(|c| width_of(c, HEADER)))
            .max()
            .unwrap_or(0)
            .saturating_add(3 * PAD)
            .max(MIN_COLUMN);
        let legend_width = legend_width(grid);
        let body = label_width + column_width * grid.columns.len() as i32;
        let inner = body.max(width_of(grid.title, TITLE)).max(legend_width);
        let width = inner + 2 * MARGIN;
        let height = HEADER_TOP + HEADER_HEIGHT + ROW_HEIGHT * grid.rows.len() as i32 + MARGIN;
        GridLayout {
            size: (width.max(1) as u32, height as u32),
            label_width,
            column_width,
            legend_x: (width - legend_width) / 2,
        }
    }
}

fn legend_width(grid: &Grid) -> i32 {
    let swatches: i32 = grid
        .legend
        .iter()
        .map(|(text, _)| SWATCH + 6 + width_of(text, LEGEND) + 24)
        .sum();
    swatches + width_of(grid.note, LEGEND)
}

/// Writes `<stem>.png` and `<stem>.svg` side by side; returns the two paths.
/// The directory must exist; each file is replaced atomically, and errors
/// name the file.
pub fn write_grid(grid: &Grid, stem: &Path) -> Result<(PathBuf, PathBuf)> {
    let (png_path, svg_path) = super::image_paths(stem)?;
    ensure_font()?;
    let layout = GridLayout::new(grid);
    let size = layout.size;

    let mut pixels = vec![0u8; size.0 as usize * size.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, size).into_drawing_area();
        let ts = font_metrics().map_or(Typesetting::Whole, Typesetting::Glyphs);
        draw_grid(&root, grid, &layout, ts)?;
        root.present().map_err(draw_error)?;
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw_grid(&root, grid, &layout, Typesetting::Whole)?;
        root.present().map_err(draw_error)?;
    }

    write_images((&png_path, &pixels, size), (&svg_path, &svg))?;
    Ok((png_path, svg_path))
}

fn draw_grid<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    grid: &Grid,
    layout: &GridLayout,
    ts: Typesetting,
) -> Result<()> {
    root.fill(&WHITE).map_err(draw_error)?;
    let width = layout.size.0 as i32;
    let centre_top = (HPos::Center, VPos::Top);
    put_text(
        root,
        ts,
        grid.title,
        TITLE,
        centre_top,
        (width / 2, 14),
        false,
    )?;

    // Legend: swatch, meaning; then the note.
    let cy = 64;
    let mut x = layout.legend_x;
    let left = (HPos::Left, VPos::Center);
    for &(text, colour) in grid.legend {
        let swatch = [(x, cy - SWATCH / 2), (x + SWATCH, cy + SWATCH / 2)];
        root.draw(&Rectangle::new(swatch, colour.filled()))
            .map_err(draw_error)?;
        root.draw(&Rectangle::new(swatch, BLACK.mix(0.5).stroke_width(1)))
            .map_err(draw_error)?;
        x += SWATCH + 6;
        put_text(root, ts, text, LEGEND, left, (x, cy), false)?;
        x += width_of(text, LEGEND) + 24;
    }
    put_text(root, ts, grid.note, LEGEND, left, (x, cy), false)?;

    let x0 = MARGIN + layout.label_width;
    let cw = layout.column_width;
    let centre = (HPos::Center, VPos::Center);
    for (c, name) in grid.columns.iter().enumerate() {
        let at = (
            x0 + c as i32 * cw + cw / 2,
            HEADER_TOP + HEADER_HEIGHT / 2 - 3,
        );
        put_text(root, ts, name, HEADER, centre, at, false)?;
        if let Some(&colour) = grid.column_colours.get(c) {
            let left = x0 + c as i32 * cw;
            let bar = [
                (left + 2, HEADER_TOP + HEADER_HEIGHT - 7),
                (left + cw - 2, HEADER_TOP + HEADER_HEIGHT - 2),
            ];
            root.draw(&Rectangle::new(bar, colour.filled()))
                .map_err(draw_error)?;
        }
    }
    let y0 = HEADER_TOP + HEADER_HEIGHT;
    for (r, (label, sublabel)) in grid.rows.iter().enumerate() {
        let top = y0 + r as i32 * ROW_HEIGHT;
        if r % 2 == 1 {
            // Faint banding ties a row's label to its cells.
            let band = [(MARGIN, top), (x0, top + ROW_HEIGHT)];
            root.draw(&Rectangle::new(band, BLACK.mix(0.04).filled()))
                .map_err(draw_error)?;
        }
        let cy = top + ROW_HEIGHT / 2;
        put_text(root, ts, label, LABEL, left, (MARGIN + PAD, cy - 10), false)?;
        put_text(
            root,
            ts,
            sublabel,
            SUBLABEL,
            left,
            (MARGIN + PAD, cy + 13),
            false,
        )?;
        for c in 0..grid.columns.len() {
            let Some(cell) = grid.cells.get(r * grid.columns.len() + c) else {
                continue;
            };
            let left_edge = x0 + c as i32 * cw;
            let rect = [
                (left_edge + 2, top + 2),
                (left_edge + cw - 2, top + ROW_HEIGHT - 2),
            ];
            root.draw(&Rectangle::new(rect, cell.fill.filled()))
                .map_err(draw_error)?;
            let at = (left_edge + cw / 2, cy);
            put_text(root, ts, &cell.text, CELL, centre, at, false)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    #[test]
    fn the_image_grows_with_its_text_and_both_files_are_written() {
        let dir = tempfile::tempdir().unwrap();
        let columns: Vec<String> = ["a", "b"].map(String::from).to_vec();
        let rows = vec![
            ("first row".to_owned(), "unit".to_owned()),
            (
                "a much, much longer second row label".to_owned(),
                "x".to_owned(),
            ),
        ];
        let blue = RGBColor(0xB0, 0xDD, 0xF5);
        let cell = |text: &str| GridCell {
            text: text.to_owned(),
            fill: blue,
        };
        let cells = vec![
            cell("1"),
            cell("2"),
            cell("a rather wide cell text"),
            cell("4"),
        ];
        let grid = Grid {
            title: "t",
            legend: &[("pass", blue)],
            note: "note",
            columns: &columns,
            column_colours: &[],
            rows: &rows,
            cells: &cells,
        };
        let (png, svg) = write_grid(&grid, &dir.path().join("g")).unwrap();
        let img = image::open(&png).unwrap().to_rgb8();
        let layout = GridLayout::new(&grid);
        assert_eq!(img.dimensions(), layout.size);
        assert!(layout.column_width >= width_of("a rather wide cell text", CELL) + 2 * PAD);
        assert!(layout.label_width > width_of("a much, much longer second row label", LABEL));
        assert!(img.dimensions().1 as i32 >= HEADER_TOP + 2 * ROW_HEIGHT);
        assert!(img.pixels().filter(|p| p.0 == [0xB0, 0xDD, 0xF5]).count() > 4 * 1000);
        let text = fs::read_to_string(&svg).unwrap();
        assert!(text.contains("a rather wide cell text") && text.contains("first row"));
    }

    #[test]
    fn every_row_is_drawn() {
        let dir = tempfile::tempdir().unwrap();
        let columns: Vec<String> = ["seed", "auto"].map(String::from).to_vec();
        let rows: Vec<(String, String)> = (1..=12)
            .map(|i| (format!("{i}. scenario"), "figure".to_owned()))
            .collect();
        let cells: Vec<GridCell> = (0..24)
            .map(|i| GridCell {
                text: format!("cell {i}"),
                fill: RGBColor(0xB0, 0xDD, 0xF5),
            })
            .collect();
        let colours = [PALETTE[0], PALETTE[5]];
        let grid = Grid {
            title: "t",
            legend: &[],
            note: "",
            columns: &columns,
            column_colours: &colours,
            rows: &rows,
            cells: &cells,
        };
        let (png, svg) = write_grid(&grid, &dir.path().join("g")).unwrap();
        let img = image::open(&png).unwrap().to_rgb8();
        let bottom = HEADER_TOP + HEADER_HEIGHT + 12 * ROW_HEIGHT;
        assert!(
            img.dimensions().1 as i32 >= bottom,
            "{:?}",
            img.dimensions()
        );
        // The last row's cells are filled.
        let y = (bottom - ROW_HEIGHT / 2) as u32;
        assert!((0..img.width()).any(|x| img.get_pixel(x, y).0 == [0xB0, 0xDD, 0xF5]));
        let text = fs::read_to_string(&svg).unwrap();
        for (label, _) in &rows {
            assert!(text.contains(label.as_str()), "{label}");
        }
        assert!(text.contains("cell 23"));
    }

    #[test]
    fn the_bundled_font_has_latin_but_not_everything() {
        assert!(font_has('a'));
        assert!(!font_has('\u{10FFFD}'));
    }
}
