//! The committed quick lab tables (`docs/lab/quick/`, written by
//! `scripts/lab-tables.sh`) still say what the code produces: the quick
//! stability suite and the quick accuracy sweep are run again through the
//! binary, and every deterministic column (figures, verdicts and summaries;
//! errors and drifts) must match the committed CSV exactly. Timings (the
//! accuracy table's cost) are left out: they are measurements of a machine.

use std::path::Path;
use std::process::Command;

/// The fields of one CSV line (quoted fields may hold commas; `""` is a
/// quote).
fn fields(line: &str) -> Vec<String> {
    let (mut out, mut field, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut field)),
            _ => field.push(c),
        }
    }
    out.push(field);
    out
}

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

/// Runs `impulse <command> --quick` into a fresh folder and compares its
/// `file` with the committed one.
fn matches_committed(command: &str, file: &str, skip: &[&str]) {
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
}

#[test]
fn the_quick_stability_table_matches_the_code() {
    matches_committed("stress", "stress.csv", &[]);
}

#[test]
fn the_quick_accuracy_table_matches_the_code_except_for_timings() {
    matches_committed("accuracy", "accuracy.csv", &["cost"]);
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
