//! The committed quick lab tables (`docs/lab/quick/`, written by
//! `scripts/lab-tables.sh`) still say what the code produces: the quick
//! stability suite and the quick accuracy sweep are run again through the
//! binary, and every deterministic column (figures, verdicts and summaries;
//! errors and drifts) must match the committed CSV exactly. Timings (the
//! accuracy table's cost) are left out: they are measurements of a machine.

mod common;

use common::csv_fields as fields;
use std::path::Path;
use std::process::Command;

/// The table's rows without the columns named in `skip`, header first.
fn table(text: &str, skip: &[&str]) -> Vec<Vec<String>> {
    let mut lines = text.lines().filter(|l| !l.is_empty());
    let header = fields(lines.next().expect("a header"));
    let keep: Vec<bool> = header.iter().map(|h| !skip.contains(&h.as_str())).collect();
    let pick = |row: Vec<String>| -> Vec<String> {
        row.into_iter()
            .zip(&keep)
            .filter_map(|(f, &k)| k.then_some(f))
            .collect()
    };
    std::iter::once(pick(header))
        .chain(lines.map(|l| pick(fields(l))))
        .collect()
}

/// Runs `impulse <command> --quick` into a fresh folder, compares its
/// `file` with the committed one and returns the fresh table (all its
/// columns, header first).
fn matches_committed(command: &str, file: &str, skip: &[&str]) -> Vec<Vec<String>> {
    let out = tempfile::tempdir().unwrap();
    let status = Command::new(env!("CARGO_BIN_EXE_impulse"))
        .args([command, "--quick", "--out"])
        .arg(out.path())
        .stdout(std::process::Stdio::null())
        .status()
        .expect("the binary runs");
    assert!(status.success(), "impulse {command} --quick failed");
    let fresh = std::fs::read_to_string(out.path().join(file)).unwrap();
    let committed_path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs/lab/quick")
        .join(file);
    let committed = std::fs::read_to_string(&committed_path)
        .unwrap_or_else(|e| panic!("{}: {e}", committed_path.display()));
    let whole = table(&fresh, &[]);
    let (fresh, committed) = (table(&fresh, skip), table(&committed, skip));
    assert_eq!(fresh[0], committed[0], "{file}: the columns changed");
    assert_eq!(fresh.len(), committed.len(), "{file}: the rows changed");
    let differing: Vec<String> = fresh
        .iter()
        .zip(&committed)
        .filter(|(a, b)| a != b)
        .map(|(a, b)| format!("now       {}\ncommitted {}", a.join(","), b.join(",")))
        .collect();
    assert!(
        differing.is_empty(),
        "docs/lab/quick/{file} no longer matches the code (run scripts/lab-tables.sh --quick \
         and commit, if the change is meant):\n{}",
        differing.join("\n")
    );
    whole
}

/// The rows of `table` as maps from column name to field.
fn rows(table: &[Vec<String>]) -> Vec<std::collections::HashMap<&str, &str>> {
    let header = &table[0];
    table[1..]
        .iter()
        .map(|row| {
            header
                .iter()
                .map(String::as_str)
                .zip(row.iter().map(String::as_str))
                .collect()
        })
        .collect()
}

fn number(row: &std::collections::HashMap<&str, &str>, column: &str) -> f64 {
    row[column]
        .parse()
        .unwrap_or_else(|_| panic!("{column} = {:?} is not a number", row[column]))
}

/// The committed table is the code's, and what the fresh one says is
/// physics: `exact` (event-driven, no overlap ever) passes every scenario
/// but the resting piles it may stall on (its documented limit); and in
/// the long run (1000 elastic discs in a periodic box, 10⁴ steps) the
/// methods that keep energy by construction, `exact` and `impulse` (each
/// impact resolved at the touch, e = 1: energy kept to rounding; straight
/// flight, no gravity), drift by no more than rounding allows: about 10⁵
/// impacts each rounding the energy by a few ε = 2.2e-16 relative, so
/// ~1e-10 at worst if every rounding went the same way.
#[test]
fn the_quick_stability_table_matches_the_code() {
    let table = matches_committed("stress", "stress.csv", &[]);
    let rows = rows(&table);
    for row in &rows {
        let (scenario, method) = (row["scenario"], row["method"]);
        if method == "exact" && !matches!(scenario, "pile" | "mass-ratio") {
            assert_eq!(
                row["pass"], "true",
                "exact fails {scenario}: {}",
                row["summary"]
            );
        }
        if scenario == "long-run" && matches!(method, "exact" | "impulse") {
            let drift = number(row, "figure");
            assert!(
                drift < 1e-10,
                "{method}'s long-run energy drift {drift:e} is beyond rounding"
            );
        }
    }
}

/// The committed table is the code's (timings aside), and the fresh one
/// agrees with the analysis of each method:
///
/// - `exact` is the reference at another step: it conserves the falling
///   gas's energy to rounding (below 1e-12 relative: a few thousand
///   events each rounding by a few ε) and follows the reference's
///   trajectory to rounding over the short horizon (below 1e-9 radii).
/// - `seed` and `impulse` integrate gravity by semi-implicit Euler, whose
///   energy error is first order in the (sub)step h = dt/substeps: in
///   flight it loses ½·m·g²·h² a step, g²·h/2 per unit time and mass. So
///   energy_drift/h is the same for every row of a method, whatever dt and
///   substeps (within a factor 1.5: the gas's share of time in flight
///   varies a little).
/// - `verlet` turns collisions almost inelastic (restitution ignored): its
///   drift is not a rounding error and is left out.
#[test]
fn the_quick_accuracy_table_matches_the_code_except_for_timings() {
    let table = matches_committed("accuracy", "accuracy.csv", &["cost"]);
    let rows = rows(&table);
    for method in ["seed", "impulse"] {
        let per_h: Vec<f64> = rows
            .iter()
            .filter(|r| r["method"] == method)
            .map(|r| number(r, "energy_drift") / (number(r, "dt") / number(r, "substeps")))
            .collect();
        assert!(per_h.len() >= 2, "{method}: {} rows", per_h.len());
        let (lo, hi) = (
            per_h.iter().copied().fold(f64::INFINITY, f64::min),
            per_h.iter().copied().fold(0.0, f64::max),
        );
        eprintln!("{method}: energy drift per unit substep {per_h:?}");
        assert!(
            hi <= 1.5 * lo,
            "{method}: energy drift not first order in the substep: {per_h:?} per second"
        );
    }
    for row in rows.iter().filter(|r| r["method"] == "exact") {
        let (drift, path) = (number(row, "energy_drift"), number(row, "trajectory_error"));
        assert!(
            drift < 1e-12,
            "exact at dt {}: energy drift {drift:e}",
            row["dt"]
        );
        assert!(
            path < 1e-9,
            "exact at dt {}: trajectory off by {path:e} radii",
            row["dt"]
        );
    }
}

#[test]
fn the_csv_reader_reads_quotes_and_commas() {
    assert_eq!(
        fields(r#""a, b",1,"say ""hi""",,x"#),
        ["a, b", "1", r#"say "hi""#, "", "x"]
    );
    let t = table("x,cost,y\n1,2,3\n", &["cost"]);
    assert_eq!(t, [["x", "y"], ["1", "3"]]);
}
