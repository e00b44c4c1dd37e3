//! `impulse stress`: the stability suite ([`impulse::stress`]) run under every
//! method, as a table of where each one fails.
//!
//! Every scenario runs under every method in [`METHODS`] (12 × 5 runs; a
//! few seconds with `--quick`, minutes without). The command prints a
//! Markdown table (one row per scenario, one column per method, each cell the
//! scenario's figure and ✓ or ✗), the pass criteria and every run's summary,
//! and writes them to `stress.md`, the runs to `stress.csv` and a grid chart
//! to `stress.png` and `stress.svg`. Failed cells are findings, not errors:
//! the command fails only when it cannot write its files.

use super::chart::{font_has, setting_colour, write_grid, Grid, GridCell};
use crate::progress;
use anyhow::Context as _;
use impulse::stress::{self, Outcome, Size, METHODS};
use plotters::style::RGBColor;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `impulse stress`.
#[derive(Clone, Debug, clap::Args)]
pub struct StressArgs {
    /// Short runs (well under a minute in all).
    #[arg(long)]
    pub quick: bool,
    /// Folder for stress.md, stress.csv, stress.png and stress.svg.
    #[arg(long, default_value = "lab-out")]
    pub out: PathBuf,
}

/// One scenario and what each method made of it.
#[derive(Clone, Debug)]
pub struct Row {
    /// Short name (the CSV's `scenario`).
    pub key: String,
    /// Title (the table's row label).
    pub title: String,
    /// What the figure measures, with its unit.
    pub figure: String,
    /// The pass criterion, in words.
    pub criterion: String,
    /// The criterion's threshold on the figure, short.
    pub threshold: String,
    /// One outcome per method, in the order of the method names.
    pub outcomes: Vec<Outcome>,
}

/// Okabe–Ito sky blue and vermillion, lightened so black text reads on them.
const PASS_FILL: RGBColor = tint(RGBColor(0x56, 0xB4, 0xE9), 0.45);
const FAIL_FILL: RGBColor = tint(RGBColor(0xD5, 0x5E, 0x00), 0.4);

/// `colour` at opacity `alpha` over white.
const fn tint(colour: RGBColor, alpha: f64) -> RGBColor {
    const fn mix(c: u8, alpha: f64) -> u8 {
        (255.0 - alpha * (255.0 - c as f64) + 0.5) as u8
    }
    RGBColor(
        mix(colour.0, alpha),
        mix(colour.1, alpha),
        mix(colour.2, alpha),
    )
}

/// Runs the suite, prints the report and writes the files.
pub fn run(args: &StressArgs) -> anyhow::Result<()> {
    let (size, name) = if args.quick {
        (Size::Quick, "quick")
    } else {
        (Size::Full, "full")
    };
    // Before minutes of work: a folder that cannot be made is an error now.
    super::create_out_dir(&args.out)?;
    let scenarios = stress::scenarios();
    let methods: Vec<String> = METHODS.iter().map(ToString::to_string).collect();
    let bar = progress::bar((scenarios.len() * METHODS.len()) as u64, "stress");
    let started = Instant::now();
    let mut rows = Vec::with_capacity(scenarios.len());
    for scenario in &scenarios {
        let mut outcomes = Vec::with_capacity(METHODS.len());
        for (&method, method_name) in METHODS.iter().zip(&methods) {
            bar.set_message(format!("{} / {method_name}", scenario.title));
            outcomes.push(scenario.run(method, size));
            bar.inc(1);
        }
        rows.push(Row {
            key: scenario.key.into(),
            title: scenario.title_for(size).into(),
            figure: scenario.figure.into(),
            criterion: scenario.criterion.into(),
            threshold: scenario.threshold.into(),
            outcomes,
        });
    }
    bar.finish_and_clear();
    let seconds = started.elapsed().as_secs_f64();

    let report = markdown(&methods, &rows);
    print!("{report}");
    println!("\nThe {name} suite took {seconds:.1} s.");

    let mut command = String::from("impulse stress");
    if args.quick {
        command.push_str(" --quick");
    }
    if args.out != Path::new("lab-out") {
        let _ = write!(command, " --out {}", args.out.display());
    }
    let md = format!(
        "# Stability suite: where each method fails\n\n\
         The {name} suite, made by `{command}`.\n\n{report}"
    );
    let md_path = args.out.join("stress.md");
    let csv_path = args.out.join("stress.csv");
    write(&md_path, md.as_bytes())?;
    write(&csv_path, csv(&methods, &rows).as_bytes())?;
    let (png, svg) = chart(&methods, &rows, name, &args.out.join("stress"))?;
    println!(
        "wrote {}, {}, {}, {}",
        md_path.display(),
        csv_path.display(),
        png.display(),
        svg.display()
    );
    Ok(())
}

fn write(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    crate::files::write_atomically(path, bytes)
        .with_context(|| format!("writing {}", path.display()))
}

/// A figure in a few characters: "—" when there is none, a whole number as
/// it is (below a million), anything else with two significant digits.
pub fn compact(figure: f64) -> String {
    if figure.is_nan() {
        "—".into()
    } else if figure.is_infinite() {
        if figure > 0.0 { "∞" } else { "−∞" }.into()
    } else if figure.fract() == 0.0 && figure.abs() < 1e6 {
        format!("{}", figure as i64)
    } else {
        format!("{figure:.1e}")
    }
}

fn mark(pass: bool) -> &'static str {
    if pass {
        "✓"
    } else {
        "✗"
    }
}

/// Text on one line, for a Markdown list item.
fn one_line(text: &str) -> String {
    text.replace(['\r', '\n'], " ")
}

/// Text safe inside a Markdown table cell: one line, no bare `|`.
fn cell(text: &str) -> String {
    one_line(text).replace('|', "\\|")
}

/// The table (figure and ✓/✗ per cell), then the criteria and every run's
/// summary.
pub fn markdown(methods: &[String], rows: &[Row]) -> String {
    let mut out = String::from("| scenario | pass if |");
    for m in methods {
        let _ = write!(out, " {} |", cell(m));
    }
    out.push_str("\n|---|---|");
    out.push_str(&":---:|".repeat(methods.len()));
    out.push('\n');
    for row in rows {
        let threshold = row.threshold.trim_start_matches("pass if ");
        let _ = write!(out, "| {} | {} |", cell(&row.title), cell(threshold));
        for o in &row.outcomes {
            let _ = write!(out, " {} {} |", compact(o.figure), mark(o.pass));
        }
        out.push('\n');
    }
    out.push_str(
        "\nEach cell is the scenario's figure: ✓ the criterion held, ✗ it did not; \
         — means no figure was measured (the run stalled or failed first, as its \
         details say).\n\n## criteria\n\n",
    );
    for row in rows {
        let _ = writeln!(
            out,
            "- {}: {} — {}",
            one_line(&row.title),
            one_line(&row.figure),
            one_line(&row.criterion)
        );
    }
    out.push_str("\n## details\n\n");
    for row in rows {
        for (m, o) in methods.iter().zip(&row.outcomes) {
            let _ = writeln!(
                out,
                "- {}, {m}: {} {}",
                one_line(&row.title),
                one_line(&o.summary),
                mark(o.pass)
            );
        }
    }
    out
}

/// `text` as a CSV field: in double quotes, inner ones doubled.
pub fn quote(text: &str) -> String {
    format!("\"{}\"", text.replace('"', "\"\""))
}

/// One line per scenario and method; the figure in full (empty when none).
pub fn csv(methods: &[String], rows: &[Row]) -> String {
    let mut out = String::from("scenario,method,figure_name,figure,pass,summary\n");
    for row in rows {
        for (m, o) in methods.iter().zip(&row.outcomes) {
            let figure = if o.figure.is_nan() {
                String::new()
            } else {
                o.figure.to_string()
            };
            let _ = writeln!(
                out,
                "{},{},{},{figure},{},{}",
                quote(&row.key),
                quote(m),
                quote(&row.figure),
                o.pass,
                quote(&o.summary)
            );
        }
    }
    out
}

/// The grid chart: scenarios down, methods across, pass blue and fail
/// vermillion.
fn chart(
    methods: &[String],
    rows: &[Row],
    size: &str,
    stem: &Path,
) -> anyhow::Result<(PathBuf, PathBuf)> {
    let glyphs = font_has('✓') && font_has('✗');
    let (yes, no) = if glyphs {
        ("✓", "✗")
    } else {
        ("pass", "FAIL")
    };
    let labels: Vec<(String, String)> = rows
        .iter()
        .map(|r| (r.title.clone(), format!("{}; {}", r.figure, r.threshold)))
        .collect();
    let cells: Vec<GridCell> = rows
        .iter()
        .flat_map(|r| &r.outcomes)
        .map(|o| GridCell {
            text: format!("{} {}", compact(o.figure), if o.pass { yes } else { no }),
            fill: if o.pass { PASS_FILL } else { FAIL_FILL },
        })
        .collect();
    // Each method's colour in the line charts, as a bar under its name.
    let colours: Vec<RGBColor> = METHODS.iter().map(|&m| setting_colour(m)).collect();
    let pass = format!("{yes} criterion held");
    let fail = format!("{no} criterion missed");
    let note = format!("{size} suite; cells: the figure named under each scenario (— none: the run stalled or failed first); bar under a method: its colour in the line charts");
    let grid = Grid {
        title: "Stability suite: where each method fails",
        legend: &[(&pass, PASS_FILL), (&fail, FAIL_FILL)],
        note: &note,
        columns: methods,
        column_colours: &colours,
        rows: &labels,
        cells: &cells,
    };
    write_grid(&grid, stem)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(figure: f64, summary: &str, pass: bool) -> Outcome {
        Outcome {
            figure,
            summary: summary.into(),
            pass,
        }
    }

    fn fake() -> (Vec<String>, Vec<Row>) {
        let methods = vec!["seed".to_owned(), "exact".to_owned()];
        let row = |key: &str, title: &str, outcomes| Row {
            key: key.into(),
            title: title.into(),
            figure: format!("{key} figure"),
            criterion: format!("{key} criterion"),
            threshold: format!("{key} threshold"),
            outcomes,
        };
        let rows = vec![
            row(
                "bullet",
                "1. Bullet | fast",
                vec![
                    outcome(1.0, "tunnelled, \"once\"", false),
                    outcome(0.0, "hit", true),
                ],
            ),
            row(
                "pile",
                "4. Pile",
                vec![
                    outcome(f64::NAN, "stalls", false),
                    outcome(0.0213, "overlap 0.02 r", true),
                ],
            ),
        ];
        (methods, rows)
    }

    #[test]
    fn figures_are_compact() {
        assert_eq!(compact(f64::NAN), "—");
        assert_eq!(compact(0.0), "0");
        assert_eq!(compact(-0.0), "0");
        assert_eq!(compact(31415.0), "31415");
        assert_eq!(compact(-3.0), "-3");
        assert_eq!(compact(0.9081), "9.1e-1");
        assert_eq!(compact(2.217e-14), "2.2e-14");
        assert_eq!(compact(2.5e6), "2.5e6");
        assert_eq!(compact(f64::INFINITY), "∞");
    }

    #[test]
    fn csv_fields_are_quoted_and_inner_quotes_doubled() {
        assert_eq!(quote("plain"), "\"plain\"");
        assert_eq!(quote("a, b"), "\"a, b\"");
        assert_eq!(quote("say \"hi\""), "\"say \"\"hi\"\"\"");
        let (methods, rows) = fake();
        let text = csv(&methods, &rows);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 1 + 4, "{text}");
        assert_eq!(lines[0], "scenario,method,figure_name,figure,pass,summary");
        assert_eq!(
            lines[1],
            "\"bullet\",\"seed\",\"bullet figure\",1,false,\"tunnelled, \"\"once\"\"\""
        );
        assert_eq!(
            lines[3],
            "\"pile\",\"seed\",\"pile figure\",,false,\"stalls\""
        );
        assert!(lines[4].contains(",0.0213,true,"), "{}", lines[4]);
    }

    #[test]
    fn markdown_has_a_row_per_scenario_a_column_per_method_and_every_summary() {
        let (methods, rows) = fake();
        let md = markdown(&methods, &rows);
        let table: Vec<&str> = md.lines().take_while(|l| l.starts_with('|')).collect();
        assert_eq!(table.len(), 2 + rows.len(), "{md}");
        assert_eq!(table[0], "| scenario | pass if | seed | exact |");
        assert_eq!(table[1], "|---|---|:---:|:---:|");
        assert_eq!(
            table[2],
            "| 1. Bullet \\| fast | bullet threshold | 1 ✗ | 0 ✓ |"
        );
        assert_eq!(table[3], "| 4. Pile | pile threshold | — ✗ | 2.1e-2 ✓ |");
        // The escaped pipe aside, every table line has one cell per column.
        for line in &table {
            assert_eq!(line.replace("\\|", "").matches('|').count(), 5, "{line}");
        }
        let section = |name: &str| -> Vec<String> {
            md.split(&format!("## {name}\n\n"))
                .nth(1)
                .unwrap_or_default()
                .lines()
                .take_while(|l| l.starts_with("- "))
                .map(String::from)
                .collect()
        };
        assert_eq!(
            section("criteria"),
            [
                "- 1. Bullet | fast: bullet figure — bullet criterion",
                "- 4. Pile: pile figure — pile criterion"
            ]
        );
        let details = section("details");
        assert_eq!(details.len(), 4, "{md}");
        assert_eq!(details[1], "- 1. Bullet | fast, exact: hit ✓");
        assert_eq!(details[2], "- 4. Pile, seed: stalls ✗");
    }

    #[test]
    fn tints_run_from_white_to_the_colour_and_the_fills_stay_light() {
        let vermillion = RGBColor(0xD5, 0x5E, 0x00);
        assert_eq!(tint(vermillion, 0.0), RGBColor(255, 255, 255));
        assert_eq!(tint(vermillion, 1.0), vermillion);
        assert_eq!(tint(vermillion, 0.5), RGBColor(234, 175, 128));
        let luma =
            |c: RGBColor| 0.3 * f64::from(c.0) + 0.59 * f64::from(c.1) + 0.11 * f64::from(c.2);
        for c in [PASS_FILL, FAIL_FILL] {
            assert!(luma(c) > 150.0, "{c:?} too dark for black text");
        }
    }
}
