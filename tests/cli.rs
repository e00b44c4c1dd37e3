//! The binary from the outside: one-line errors, exit codes, `run` output.

use std::process::{Command, Output};

fn impulse(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_impulse"))
        .args(args)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn asset(name: &str) -> String {
    format!("{}/assets/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn without_a_display_it_says_so_in_one_line_and_names_the_headless_command() {
    let out = impulse(&[]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(
        err.contains("display") && err.contains("impulse run"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn a_bad_scene_file_is_one_line_naming_file_and_field() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(
        &path,
        "[world]\nsize = [4.0, 4.0]\n[[particles]]\npos = [2.0, 2.0]\nmass = -3.0\nradius = 0.5\n",
    )
    .unwrap();
    for args in [
        vec![path.to_str().unwrap()],
        vec!["run", path.to_str().unwrap(), "--time", "1"],
    ] {
        let out = impulse(&args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = stderr(&out);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(
            err.contains("bad.toml") && err.contains("particles[0].mass"),
            "{err}"
        );
    }
    let out = impulse(&["/no/such/file.toml"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("/no/such/file.toml"));
}

#[test]
fn wrong_arguments_are_refused_by_the_parser() {
    for args in [
        vec!["run", "x.toml", "--time", "-1"],
        vec!["run", "x.toml", "--time", "1", "--dt", "0"],
        vec!["--dt", "nan"],
        vec!["--size", "10x10"],
        vec!["--no-such-flag"],
        vec!["--frame-stats"],
    ] {
        let out = impulse(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(!stderr(&out).contains("panicked"));
    }
}

#[test]
fn gas_wants_a_disc_count_and_no_scene_file_beside_it() {
    for (value, why) in [
        (
            "0",
            "0 discs is out of range: the gas takes 1 to 1000000 discs",
        ),
        ("-5", "-5 discs is out of range"),
        ("1000001", "1000001 discs is out of range"),
        ("2e6", "2e6 discs is out of range"),
        (
            "many",
            "\"many\" is not a number: the gas takes 1 to 1000000 discs",
        ),
        ("2.5", "2.5 is not a whole number of discs"),
        ("inf", "\"inf\" is not a number"),
    ] {
        let out = impulse(&[&format!("--gas={value}")]);
        assert_eq!(out.status.code(), Some(2), "--gas {value}");
        let err = stderr(&out);
        assert!(err.contains(value) && err.contains(why), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let out = impulse(&["--gas", "100", &asset("default.toml")]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("cannot be used with"),
        "{}",
        stderr(&out)
    );
    // A good count, plain or as a scientist writes it, gets as far as the
    // display check.
    for count in ["100000", "1e5"] {
        let out = impulse(&["--gas", count, "--frame-stats", "times.csv"]);
        assert_eq!(out.status.code(), Some(1), "--gas {count}");
        assert!(stderr(&out).contains("display"), "{}", stderr(&out));
    }
}

#[test]
fn run_simulates_headlessly_and_reports_json() {
    let out = impulse(&[
        "run",
        &asset("default.toml"),
        "--time",
        "2",
        "--dt",
        "0.005",
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    assert_eq!(v["steps"], 400);
    assert!((v["sim_time"].as_f64().unwrap() - 2.0).abs() < 1e-9);
    assert_eq!(v["particles"].as_array().unwrap().len(), 26);
    let ke = v["kinetic_energy"].as_f64().unwrap();
    assert!(ke > 0.0 && ke.is_finite());
    // The default scene is elastic everywhere: kinetic energy is conserved.
    let scene = impulse::Scene::load(std::path::Path::new(&asset("default.toml"))).unwrap();
    let ke0 = scene.build("default").unwrap().metrics().kinetic_energy;
    assert!((ke - ke0).abs() < 1e-9 * ke0, "{ke} vs {ke0}");
}

#[test]
fn run_takes_method_broad_phase_and_substeps_and_says_what_auto_chose() {
    let scene = asset("default.toml");
    let out = impulse(&[
        "run",
        &scene,
        "--time",
        "1",
        "--method",
        "impulse",
        "--broadphase",
        "grid",
        "--substeps",
        "3",
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["plan"]["method"], "impulse");
    assert_eq!(v["plan"]["broad_phase"], "grid");
    assert_eq!(v["plan"]["substeps"], 3);

    let out = impulse(&["run", &scene, "--time", "1"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("auto chose") && text.contains("exact"),
        "{text}"
    );

    let out = impulse(&["run", &scene, "--time", "1", "--method", "rk4"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("seed, impulse, verlet, exact"),
        "{}",
        stderr(&out)
    );
}

/// The fields of one CSV line (double-quoted fields, inner quotes doubled).
fn csv_fields(line: &str) -> Vec<String> {
    let (mut fields, mut field, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                field.push('"');
            }
            ('"', _) => quoted = !quoted,
            (',', false) => fields.push(std::mem::take(&mut field)),
            (c, _) => field.push(c),
        }
    }
    fields.push(field);
    fields
}

#[test]
fn stress_quick_writes_table_csv_and_chart_for_every_scenario_and_method() {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().join("made/by/stress");
    let out = impulse(&["stress", "--quick", "--out", out_dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", stderr(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("| scenario | pass if | seed | impulse | verlet | exact | auto |"));
    for name in ["stress.md", "stress.csv", "stress.png", "stress.svg"] {
        let len = std::fs::metadata(out_dir.join(name)).map_or(0, |m| m.len());
        assert!(len > 0, "{name} missing or empty");
    }
    let md = std::fs::read_to_string(out_dir.join("stress.md")).unwrap();
    assert!(md.contains("quick") && md.contains("impulse stress --quick"));

    let csv = std::fs::read_to_string(out_dir.join("stress.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    // A header, then a row per scenario and method.
    let rows_wanted = impulse::stress::scenarios().len() * impulse::stress::METHODS.len();
    assert_eq!(lines.len(), 1 + rows_wanted, "{csv}");
    assert_eq!(lines[0], "scenario,method,figure_name,figure,pass,summary");
    let rows: Vec<Vec<String>> = lines[1..].iter().map(|l| csv_fields(l)).collect();
    assert!(rows.iter().all(|r| r.len() == 6), "{csv}");
    for scenario in impulse::stress::scenarios() {
        for method in impulse::stress::METHODS {
            let method = method.to_string();
            let found = rows
                .iter()
                .filter(|r| r[0] == scenario.key && r[1] == method);
            assert_eq!(found.count(), 1, "{} × {method}", scenario.key);
        }
    }
    assert!(rows.iter().all(|r| r[4] == "true" || r[4] == "false"));
}

/// Asserts a one-line error with `code`, no panic and no backtrace, that
/// contains every one of `wanted`.
fn assert_one_line(args: &[&str], code: i32, wanted: &[&str]) {
    let out = impulse(args);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "{args:?}: not one line: {err}"
    );
    assert!(
        !err.contains("panicked") && !err.contains("backtrace"),
        "{args:?}: {err}"
    );
    for w in wanted {
        assert!(err.contains(w), "{args:?}: no {w:?} in {err}");
    }
}

#[test]
fn missing_unreadable_and_garbage_scene_files_are_one_line_naming_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let binary = dir.path().join("binary.toml");
    std::fs::write(&binary, [0xff, 0xfe, 0x00, 0x80, b'\n']).unwrap();
    let empty = dir.path().join("empty.toml");
    std::fs::write(&empty, "").unwrap();
    let not_toml = dir.path().join("not.toml");
    std::fs::write(&not_toml, "[world\nsize = ").unwrap();
    let folder = dir.path().to_str().unwrap().to_string();
    for (path, why) in [
        ("/no/such/file.toml", "No such file"),
        (folder.as_str(), "not a regular file (a folder)"),
        (binary.to_str().unwrap(), "UTF-8"),
        (empty.to_str().unwrap(), "world"),
        (not_toml.to_str().unwrap(), "line 1"),
        ("/dev/zero", "not a regular file (a device)"),
    ] {
        assert_one_line(&[path], 1, &[path, why]);
        assert_one_line(&["run", path, "--time", "1"], 1, &[path, why]);
    }
}

#[test]
fn every_wrong_argument_is_one_line_with_exit_code_two() {
    let scene = asset("default.toml");
    for (args, wanted) in [
        (vec!["run", &scene], "--time"),
        (vec!["run", "--time", "1"], "SCENE"),
        (vec!["run", &scene, "--time", "-1"], "-1"),
        (vec!["run", &scene, "--time", "inf"], "inf"),
        (vec!["run", &scene, "--time", "1", "--dt", "0"], "--dt"),
        (vec!["run", &scene, "--time", "1", "--dt", "nan"], "nan"),
        (vec!["run", &scene, "--time", "1", "--method", "rk4"], "rk4"),
        (
            vec!["run", &scene, "--time", "1", "--broadphase", "kd"],
            "kd",
        ),
        (
            vec!["run", &scene, "--time", "1", "--substeps", "0"],
            "substeps",
        ),
        (
            vec!["run", &scene, "--time", "1", "--substeps", "4000000000"],
            "substeps",
        ),
        (
            vec!["run", &scene, "--time", "1", "--threads", "0"],
            "--threads",
        ),
        (
            vec!["run", &scene, "--time", "1", "--json", "extra"],
            "extra",
        ),
        (vec!["bench", "--threads", "0"], "--threads"),
        (vec!["bench", "--quick", "--nope"], "--nope"),
        (vec!["accuracy", "--out"], "--out"),
        (vec!["stress", "surplus"], "surplus"),
        (vec!["--dt", "nan"], "--dt"),
        (vec!["--dt=-0.01"], "--dt"),
        (vec!["--exit-after", "0"], "--exit-after"),
        (vec!["--size", "10x10"], "10x10"),
        (vec!["--size", "wide"], "wide"),
        (vec!["--gas"], "--gas"),
        (vec!["--no-such-flag"], "--no-such-flag"),
        (vec!["--frame-stats"], "--frame-stats"),
        (vec!["a.toml", "b.toml"], "b.toml"),
    ] {
        assert_one_line(&args, 2, &[wanted]);
    }
    for args in [["--help"], ["--version"]] {
        let out = impulse(&args);
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        assert!(!out.stdout.is_empty(), "{args:?}");
    }
}

#[test]
fn a_run_too_long_or_a_bad_output_folder_is_refused_at_once() {
    let scene = asset("default.toml");
    assert_one_line(&["run", &scene, "--time", "1e300"], 1, &["steps"]);
    assert_one_line(
        &["run", &scene, "--time", "1e6", "--dt", "1e-9"],
        1,
        &["steps"],
    );
    // Over 10⁸ steps: asked for --yes, at once.
    let started = std::time::Instant::now();
    assert_one_line(
        &["run", &scene, "--time", "2", "--dt", "1e-8"],
        1,
        &["2.0e8 steps", "--yes"],
    );
    assert!(started.elapsed().as_secs_f64() < 5.0);
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "not a folder").unwrap();
    let out = file.join("out");
    let out = out.to_str().unwrap();
    for command in ["bench", "accuracy", "stress"] {
        let started = std::time::Instant::now();
        assert_one_line(&[command, "--quick", "--out", out], 1, &[out]);
        assert!(
            started.elapsed().as_secs_f64() < 10.0,
            "{command}: refused only after {:?}",
            started.elapsed()
        );
    }
}

#[test]
fn window_output_files_in_missing_folders_are_refused_before_a_window_opens() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().to_str().unwrap().to_string();
    let missing = dir.path().join("no-such-folder").join("out.json");
    let missing = missing.to_str().unwrap();
    for flag in ["--dump-state", "--screenshot", "--frame-stats"] {
        assert_one_line(&[flag, missing], 1, &[flag, "no folder"]);
        assert_one_line(&[flag, &folder], 1, &[flag, "is a folder"]);
    }
}

#[test]
fn a_run_that_falls_behind_says_so_and_exits_with_its_own_code() {
    // A disc at 10⁶ m/s in a 2 m box with one-second steps: a million wall
    // hits a step, past `exact`'s event cap.
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bullet.toml");
    std::fs::write(
        &scene,
        "[world]\nsize = [2.0, 2.0]\n\n[simulation]\ndt = 1.0\n\n[[particles]]\npos = [1.0, 1.0]\nvel = [1e6, 0.3]\nmass = 1.0\nradius = 0.5\n",
    )
    .unwrap();
    let scene = scene.to_str().unwrap().to_string();
    let out = impulse(&["run", &scene, "--time", "3", "--method", "exact", "--json"]);
    assert_eq!(out.status.code(), Some(3), "{}", stderr(&out));
    let summary: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let (reached, asked) = (
        summary["sim_time"].as_f64().unwrap(),
        summary["requested_time"].as_f64().unwrap(),
    );
    assert!(reached < asked && asked == 3.0, "{reached} of {asked}");
    assert!(summary["truncated_steps"].as_u64().unwrap() > 0);
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("exact") && err.contains("--method impulse"),
        "{err}"
    );
    // The same scene under impulse reaches its time, cuts nothing, exits 0.
    let out = impulse(&[
        "run", &scene, "--time", "3", "--method", "impulse", "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let summary: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(summary["truncated_steps"], 0);
    assert!((summary["sim_time"].as_f64().unwrap() - 3.0).abs() < 1e-9);
    // ...and says it may have missed hits, with the travel it measured: at
    // 10⁶ m/s a substep of at most 1/64 s is over 10⁴ radii.
    let travel = summary["max_travel"].as_f64().unwrap();
    assert!(travel > 1e4, "{travel}");
    let warnings = summary["warnings"].as_array().unwrap();
    let substeps = warnings
        .iter()
        .find(|w| w["code"] == "substeps_too_few")
        .unwrap_or_else(|| panic!("{warnings:?}"));
    let radii = substeps["values"]
        .as_array()
        .unwrap()
        .iter()
        .find(|v| v[0] == "radii")
        .unwrap()[1]
        .as_f64()
        .unwrap();
    assert_eq!(radii, travel, "the warning quotes the measured travel");
}

#[test]
fn negative_numbers_reach_their_check_and_messages_say_things_once() {
    let scene = asset("default.toml");
    let out = impulse(&["run", &scene, "--time", "-1"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("-1") && err.contains("number of seconds"),
        "{err}"
    );
    assert!(!err.contains("unexpected argument"), "{err}");
    let out = impulse(&["run", &scene, "--time", "1", "--dt", "-0.5"]);
    assert!(stderr(&out).contains("positive"), "{}", stderr(&out));
    // A missing file: its cause once.
    let out = impulse(&["run", "/no/such/scene.toml", "--time", "1"]);
    let err = stderr(&out);
    assert_eq!(err.matches("No such file").count(), 1, "{err}");
    // A huge number in e-notation, not hundreds of digits.
    let out = impulse(&["run", &scene, "--time", "1e300"]);
    let err = stderr(&out);
    assert!(err.contains("--time 1e300") && err.len() < 200, "{err}");
}

/// Off a terminal (a log, CI) a long run still says how far it got, a line
/// every few seconds (here every 0.1 s) on standard error.
#[test]
fn a_long_run_reports_progress_off_a_terminal() {
    let out = Command::new(env!("CARGO_BIN_EXE_impulse"))
        .args([
            "run",
            &asset("preset-8-gas.toml"),
            "--time",
            "120",
            "--method",
            "impulse",
        ])
        .args(["--substeps", "16"])
        .env("IMPULSE_PROGRESS_SECONDS", "0.1")
        .output()
        .expect("the binary runs");
    assert!(out.status.success(), "{}", stderr(&out));
    let lines: Vec<String> = stderr(&out)
        .lines()
        .filter(|l| l.starts_with("impulse: simulating: "))
        .map(str::to_string)
        .collect();
    assert!(lines.len() >= 2, "progress lines: {lines:?}");
    assert!(
        lines
            .iter()
            .all(|l| l.contains(" steps)") && l.contains('%')),
        "{lines:?}"
    );
}
