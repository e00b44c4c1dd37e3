//! Every lab figure the README and the lab notes quote comes from a
//! committed table. A quoted figure is followed by a marker naming its
//! cell:
//!
//! ```text
//! 17.1<!-- from bench.md: impulse / grid; 1000000 | ns per particle-step (median) --> ns
//! ```
//!
//! `FILE` is a table under `docs/lab/` (Markdown or CSV), the keys (split by
//! `;`) are cells its row holds, the column a header. Options after a second
//! `|`: `min` or `max` over the rows the keys match (else exactly one row
//! must match), `%` (the cell times 100), `≤` or `≥` (the quote is a bound
//! on the cell, not its value). A quote matches when it is the cell rounded
//! to the digits written: `2.03e6` for 2.033e6, `10⁸` for 1.0e8.
//!
//! In the README's sections on methods and on speed, and the notes'
//! summary of the current runs, every measured figure (a number followed by
//! ns, ×, % or written as a power of ten below one) must carry a marker.
//!
//! After `scripts/lab-tables.sh` the quotes are brought up to date by
//! `IMPULSE_UPDATE_FIGURES=1 cargo test --test lab_figures` (the script does
//! it), which rewrites each quoted value from its cell.

mod common;

use common::csv_fields;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A table: its header and rows of cells.
struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

/// Every table of a file: the Markdown tables in it, or the CSV itself.
fn tables(path: &Path) -> Vec<Table> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    if path.extension().is_some_and(|e| e == "csv") {
        let mut lines = text.lines().filter(|l| !l.is_empty());
        let header = csv_fields(lines.next().unwrap_or_default());
        return vec![Table {
            header,
            rows: lines.map(csv_fields).collect(),
        }];
    }
    let cells = |line: &str| -> Vec<String> {
        let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
        inner.split('|').map(|c| c.trim().to_string()).collect()
    };
    let mut out = Vec::new();
    let lines: Vec<&str> = text.lines().collect();
    let mut k = 0;
    while k < lines.len() {
        let is_row = |l: &str| l.trim_start().starts_with('|');
        if is_row(lines[k]) && lines.get(k + 1).is_some_and(|l| l.contains("---")) {
            let header = cells(lines[k]);
            let mut rows = Vec::new();
            k += 2;
            while k < lines.len() && is_row(lines[k]) {
                rows.push(cells(lines[k]));
                k += 1;
            }
            out.push(Table { header, rows });
        } else {
            k += 1;
        }
    }
    out
}

const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

/// Characters a written figure is made of.
fn figure_char(c: char) -> bool {
    c.is_ascii_digit() || ".eE+-−⁻×".contains(c) || SUPERSCRIPTS.contains(&c)
}

/// A written figure: its value and half a unit of its last digit. Plain
/// (`17.1`), exponent (`2.9e-13`), power of ten (`10⁻¹³`) or both
/// (`2.9×10⁻¹³`).
fn parse_figure(text: &str) -> Option<(f64, f64)> {
    let text = text.trim().replace('−', "-");
    let decimals = |m: &str| m.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    let superscript = |s: &str| -> Option<i32> {
        let (sign, digits) = match s.strip_prefix('⁻') {
            Some(rest) => (-1, rest),
            None => (1, s),
        };
        let mut n: i32 = 0;
        for c in digits.chars() {
            n = n * 10 + SUPERSCRIPTS.iter().position(|&d| d == c)? as i32;
        }
        (!digits.is_empty()).then_some(sign * n)
    };
    let (mantissa, exponent) = if let Some((m, p)) = text.split_once("×10") {
        (m.to_string(), superscript(p)?)
    } else if let Some(p) = text
        .strip_prefix("10")
        .filter(|p| p.starts_with(['⁻', '⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']))
    {
        ("1".to_string(), superscript(p)?)
    } else if let Some((m, e)) = text.split_once(['e', 'E']) {
        (m.to_string(), e.parse().ok()?)
    } else {
        (text.clone(), 0)
    };
    let m: f64 = mantissa.parse().ok()?;
    let scale = 10f64.powi(exponent);
    Some((m * scale, 0.5 * 10f64.powi(-decimals(&mantissa)) * scale))
}

/// The value of a table cell: its first word as a figure.
fn cell_value(cell: &str) -> Option<f64> {
    parse_figure(cell.split_whitespace().next()?).map(|(v, _)| v)
}

/// One marker: where the quoted figure is in the text, and what it quotes.
struct Quote {
    /// Byte range of the figure in the document.
    figure: std::ops::Range<usize>,
    file: String,
    keys: Vec<String>,
    column: String,
    options: Vec<String>,
    /// Line number (from 1), for messages.
    line: usize,
}

const MARK: &str = "<!-- from ";

fn quotes(text: &str) -> Vec<Quote> {
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(at) = text[from..].find(MARK).map(|k| k + from) {
        let end = text[at..]
            .find("-->")
            .map(|k| k + at)
            .expect("a marker ends");
        let body = &text[at + MARK.len()..end];
        let (file, rest) = body.split_once(':').expect("from FILE: …");
        let mut parts = rest.split('|').map(str::trim);
        let keys = parts.next().unwrap_or_default();
        let column = parts.next().unwrap_or_default().to_string();
        let options = parts
            .next()
            .map(|o| o.split_whitespace().map(String::from).collect())
            .unwrap_or_default();
        let start = text[..at]
            .char_indices()
            .rev()
            .take_while(|&(_, c)| figure_char(c))
            .last()
            .map_or(at, |(k, _)| k);
        out.push(Quote {
            figure: start..at,
            file: file.trim().to_string(),
            keys: keys
                .split(';')
                .map(|k| k.trim().to_string())
                .filter(|k| !k.is_empty())
                .collect(),
            column,
            options,
            line: text[..at].lines().count(),
        });
        from = end;
    }
    out
}

/// The cell value a quote names (after its options), or what is wrong.
fn quoted_cell(q: &Quote) -> Result<f64, String> {
    let path = root().join("docs/lab").join(&q.file);
    let mut values = Vec::new();
    for table in tables(&path) {
        let Some(col) = table.header.iter().position(|h| *h == q.column) else {
            continue;
        };
        for row in &table.rows {
            if q.keys.iter().all(|k| row.iter().any(|c| c == k)) {
                let cell = row.get(col).map(String::as_str).unwrap_or_default();
                values.push(cell_value(cell).ok_or(format!("cell {cell:?} is not a number"))?);
            }
        }
    }
    let has = |o: &str| q.options.iter().any(|x| x == o);
    let value = if has("min") {
        values.iter().copied().reduce(f64::min)
    } else if has("max") {
        values.iter().copied().reduce(f64::max)
    } else if values.len() == 1 {
        Some(values[0])
    } else {
        return Err(format!(
            "{} rows of {} have {:?} under {:?} (want exactly one, or min/max)",
            values.len(),
            q.file,
            q.keys,
            q.column
        ));
    };
    let value = value.ok_or(format!(
        "no row of {} has {:?} under {:?}",
        q.file, q.keys, q.column
    ))?;
    Ok(if has("%") { value * 100.0 } else { value })
}

/// Whether the quote `written` says `cell`, under the quote's options.
fn agrees(q: &Quote, written: &str, cell: f64) -> Result<(), String> {
    let (value, half_unit) = parse_figure(written).ok_or(format!("{written:?} is not a figure"))?;
    let has = |o: &str| q.options.iter().any(|x| x == o);
    let ok = if has("≤") {
        cell <= value
    } else if has("≥") {
        cell >= value
    } else {
        (cell - value).abs() <= half_unit * (1.0 + 1e-9)
    };
    if ok {
        Ok(())
    } else {
        Err(format!("quotes {written} where the table now says {cell}"))
    }
}

/// `value` written the way `like` is: the same digits after the point, in
/// the same form.
fn rewrite(like: &str, value: f64) -> String {
    let decimals = |m: &str| m.split_once('.').map_or(0, |(_, d)| d.len());
    if let Some((m, _)) = like.split_once(['e', 'E']) {
        format!("{value:.*e}", decimals(m))
    } else if like.contains('×') || like.starts_with("10") && !like.contains('.') && like.len() > 2
    {
        // Powers of ten are bounds or orders of magnitude: leave them.
        like.to_string()
    } else {
        format!("{value:.*}", decimals(like))
    }
}

const DOCUMENTS: [&str; 2] = ["README.md", "docs/lab/NOTES.md"];

#[test]
fn every_quoted_lab_figure_is_what_its_table_holds() {
    let update = std::env::var_os("IMPULSE_UPDATE_FIGURES").is_some();
    let mut wrong = Vec::new();
    let mut count = 0;
    for doc in DOCUMENTS {
        let path = root().join(doc);
        let mut text = std::fs::read_to_string(&path).unwrap();
        let found = quotes(&text);
        // Rewrite from the end, so the earlier ranges stay put.
        for q in found.iter().rev() {
            count += 1;
            let written = text[q.figure.clone()].to_string();
            let result = quoted_cell(q).and_then(|cell| match agrees(q, &written, cell) {
                Err(_) if update && q.options.iter().all(|o| o != "≤" && o != "≥") => {
                    text.replace_range(q.figure.clone(), &rewrite(&written, cell));
                    Ok(())
                }
                other => other,
            });
            if let Err(e) = result {
                wrong.push(format!("{doc}:{}: {e}", q.line));
            }
        }
        if update {
            // Whole or not at all: the other tests of this file read the
            // same documents at the same time.
            let fresh = path.with_extension("md.new");
            std::fs::write(&fresh, &text).unwrap();
            std::fs::rename(&fresh, &path).unwrap();
        }
    }
    assert!(count >= 10, "only {count} quoted figures found");
    assert!(
        wrong.is_empty(),
        "quoted figures that their tables do not hold (after scripts/lab-tables.sh, \
         IMPULSE_UPDATE_FIGURES=1 cargo test --test lab_figures rewrites them):\n{}",
        wrong.join("\n")
    );
}

/// The parts of a document the rule "every measured figure is quoted from
/// a table" covers: from each heading in `from` to the next heading of the
/// same or a higher level.
fn sections<'a>(text: &'a str, from: &[&str]) -> Vec<(usize, &'a str)> {
    let mut out = Vec::new();
    for heading in from {
        let Some(start) = text.find(&format!("\n{heading}\n")) else {
            panic!("no section {heading:?}");
        };
        let level = heading.chars().take_while(|&c| c == '#').count();
        let body = &text[start + heading.len() + 2..];
        let end = body
            .match_indices("\n#")
            .find(|(k, _)| body[k + 1..].chars().take_while(|&c| c == '#').count() <= level)
            .map_or(body.len(), |(k, _)| k);
        out.push((start + heading.len() + 2, &body[..end]));
    }
    out
}

/// Figures in `text` that look measured (a number followed by ns, × or %,
/// or a power of ten below one) and are not followed by a marker.
fn unmarked_figures(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let mut k = 0;
    while k < chars.len() {
        let starts = chars[k].1.is_ascii_digit()
            && (k == 0 || !figure_char(chars[k - 1].1) && !chars[k - 1].1.is_alphanumeric());
        if !starts {
            k += 1;
            continue;
        }
        let mut j = k;
        while j < chars.len() && figure_char(chars[j].1) {
            j += 1;
        }
        let (a, b) = (chars[k].0, chars.get(j).map_or(text.len(), |c| c.0));
        let run = &text[a..b];
        let after = &text[b..];
        let unit = [" ns", "ns", "×", " ×", " %", "%"]
            .iter()
            .any(|u| after.starts_with(u))
            || run.ends_with('×');
        let small = run.contains("e-") || run.contains('⁻');
        if (unit || small)
            && parse_figure(run.trim_end_matches('×')).is_some()
            && !after.starts_with(MARK)
        {
            let line = text[..a].lines().count();
            let context: String = text[a..].chars().take(40).collect();
            out.push(format!("line {line} of the section: {context:?}"));
        }
        k = j.max(k + 1);
    }
    out
}

#[test]
fn measured_figures_in_the_readme_and_the_notes_summary_are_all_quoted() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let notes = std::fs::read_to_string(root().join("docs/lab/NOTES.md")).unwrap();
    let mut missing = Vec::new();
    for (doc, text, heads) in [
        (
            "README.md",
            &readme,
            &["## Collision methods", "## Speed, accuracy and the lab"][..],
        ),
        (
            "docs/lab/NOTES.md",
            &notes,
            &["## Speed against accuracy", "## Where each method fails"][..],
        ),
    ] {
        for (_, body) in sections(text, heads) {
            missing.extend(
                unmarked_figures(body)
                    .into_iter()
                    .map(|m| format!("{doc}: {m}")),
            );
        }
    }
    assert!(
        missing.is_empty(),
        "measured figures without a marker naming their table cell:\n{}",
        missing.join("\n")
    );
}

#[test]
fn figures_parse_as_written_and_markers_find_their_figure() {
    assert_eq!(parse_figure("17.1"), Some((17.1, 0.05)));
    let (v, h) = parse_figure("2.03e6").unwrap();
    assert!((v - 2.03e6).abs() < 1e-6 && (h - 5e3).abs() < 1e-9);
    let (v, _) = parse_figure("10⁻¹³").unwrap();
    assert!((v - 1e-13).abs() < 1e-27);
    let (v, _) = parse_figure("2.9×10⁻¹³").unwrap();
    assert!((v - 2.9e-13).abs() < 1e-27);
    assert_eq!(parse_figure("words"), None);
    let text = "costs 17.1<!-- from bench.md: impulse / grid; 1000000 | ns | max --> ns";
    let q = &quotes(text)[0];
    assert_eq!(&text[q.figure.clone()], "17.1");
    assert_eq!((q.file.as_str(), q.column.as_str()), ("bench.md", "ns"));
    assert_eq!(q.keys, ["impulse / grid", "1000000"]);
    assert_eq!(q.options, ["max"]);
    assert!(agrees(q, "17.1", 17.14).is_ok());
    assert!(agrees(q, "17.1", 17.2).is_err());
    assert_eq!(rewrite("17.1", 12.345), "12.3");
    assert_eq!(rewrite("2.03e6", 1.5e6), "1.50e6");
    assert_eq!(
        unmarked_figures("a 2.5× gain and 3 % more, 9.7 ns").len(),
        3
    );
    assert!(unmarked_figures("10⁶ discs, 1024 px, e = 0.5").is_empty());
}

/// The words of every `<text>` of an SVG chart, unescaped.
fn svg_texts(path: &Path) -> Vec<String> {
    let svg = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let body = &t[t.find('>')? + 1..t.find("</text>")?];
            Some(
                body.trim()
                    .replace("&lt;", "<")
                    .replace("&gt;", ">")
                    .replace("&quot;", "\"")
                    .replace("&apos;", "'")
                    .replace("&#39;", "'")
                    .replace("&amp;", "&"),
            )
        })
        .collect()
}

/// The committed stability table and chart have a row for every scenario
/// of the suite, under every method.
#[test]
fn the_committed_stability_table_and_chart_cover_the_whole_suite() {
    use impulse::stress::{scenarios, Size, METHODS};
    let lab = root().join("docs/lab");
    let texts = svg_texts(&lab.join("stress.svg"));
    let csv = &tables(&lab.join("stress.csv"))[0];
    let markdown = std::fs::read_to_string(lab.join("stress.md")).unwrap();
    let suite = scenarios();
    for s in &suite {
        let title = s.title_for(Size::Full);
        assert!(
            texts.iter().any(|t| t.contains(title)),
            "stress.svg has no row {title:?} (scripts/lab-tables.sh regenerates it)"
        );
        assert!(markdown.contains(title), "stress.md has no row {title:?}");
    }
    for m in METHODS {
        let name = m.to_string();
        assert!(texts.contains(&name), "stress.svg has no column {name}");
    }
    assert_eq!(
        csv.rows.len(),
        suite.len() * METHODS.len(),
        "stress.csv: a row per scenario and method"
    );
}

/// The committed bench chart has a line for every series of its table, and
/// each accuracy chart one for every method and substep count of the sweep.
#[test]
fn the_committed_bench_and_accuracy_charts_have_every_series() {
    let lab = root().join("docs/lab");
    let bench = tables(&lab.join("bench.md"));
    let main = bench
        .iter()
        .find(|t| {
            t.header
                .first()
                .is_some_and(|h| h == "method / broad phase")
        })
        .expect("bench.md's main table");
    let texts = svg_texts(&lab.join("bench.svg"));
    let mut series: Vec<&String> = main.rows.iter().map(|r| &r[0]).collect();
    series.dedup();
    assert!(series.len() >= 10, "{series:?}");
    for s in series {
        assert!(texts.contains(s), "bench.svg has no line labelled {s:?}");
    }
    let sweep = &tables(&lab.join("accuracy.csv"))[0];
    let column = |name: &str| sweep.header.iter().position(|h| h == name).unwrap();
    let (method, substeps) = (column("method"), column("substeps"));
    let mut runs: Vec<(String, String)> = sweep
        .rows
        .iter()
        .map(|r| (r[method].clone(), r[substeps].clone()))
        .collect();
    runs.sort();
    runs.dedup();
    for chart in ["trajectory", "collisions", "energy", "pressure"] {
        let texts = svg_texts(&lab.join(format!("accuracy-{chart}.svg")));
        for (m, k) in &runs {
            let several = runs.iter().filter(|(n, _)| n == m).count() > 1;
            let label = match (several, k.as_str()) {
                (false, _) => m.clone(),
                (true, "1") => format!("{m}, 1 substep"),
                (true, k) => format!("{m}, {k} substeps"),
            };
            assert!(
                texts.contains(&label),
                "accuracy-{chart}.svg has no line labelled {label:?}"
            );
        }
    }
}
