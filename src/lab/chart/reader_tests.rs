//! What a numbers reader needs of the lab's charts (issue 29): one colour per
//! method, lines told apart, the Pareto front on |error| above the floor,
//! step sizes beside the accuracy points, labels that do not overlap.

use super::*;
use std::fs;

use crate::lab::accuracy::{self, Point};
use crate::lab::bench::{self, Row};
use impulse::method::Method;

fn bench_rows() -> Vec<Row> {
    let mut rows = Vec::new();
    let configs = [
        (Method::Impulse, "brute", 1, 80.0, 1.0),
        (Method::Impulse, "grid", 1, 13.0, 0.0),
        (Method::Impulse, "sap", 1, 29.0, 0.4),
        (Method::Impulse, "quadtree", 1, 48.0, 0.15),
        (Method::Seed, "grid", 1, 13.2, 0.0),
        (Method::Verlet, "grid", 1, 14.5, 0.0),
        (Method::Exact, "cells", 1, 10.6, 0.02),
        (Method::Impulse, "grid", 2, 13.1, -0.05),
        (Method::Seed, "grid", 2, 13.0, -0.05),
        (Method::Verlet, "grid", 2, 14.7, -0.04),
    ];
    for (method, broad, threads, at_100, growth) in configs {
        for n in [100usize, 1_000, 10_000, 100_000, 1_000_000] {
            if broad == "brute" && n > 10_000 {
                continue;
            }
            let decades = (n as f64 / 100.0).log10();
            rows.push(Row {
                method,
                broad_phase: broad.to_owned(),
                threads,
                parallel: threads > 1 && n >= 10_000,
                n,
                ns_per_particle_step: at_100 * 10f64.powf(growth * decades),
                bytes_per_particle: 260.0,
                collisions_per_second: 1e5,
                steps: 100,
                speed_up: None,
            });
        }
    }
    rows
}

fn accuracy_points() -> Vec<Point> {
    let mut points = Vec::new();
    let point = |method, dt: f64, substeps: u32, cost: f64, err: f64| Point {
        method,
        dt,
        substeps,
        cost,
        trajectory_error: err,
        collision_error: err,
        energy_drift: err,
        pressure_error: err,
    };
    for (i, dt) in [1.0 / 30.0, 1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0]
        .into_iter()
        .enumerate()
    {
        let cheap = 1e-4 * 2f64.powi(i as i32);
        points.push(point(Method::Seed, dt, 1, cheap, 3.0 * dt));
        for k in [1, 4, 16] {
            let cost = cheap * f64::from(k) * 1.1;
            points.push(point(Method::Impulse, dt, k, cost, 3.0 * dt / f64::from(k)));
            // Verlet gains energy: 43.7 at its cheapest point.
            let err = if i == 0 && k == 1 { 43.7 } else { 0.65 };
            points.push(point(Method::Verlet, dt, k, 0.8 * cost, err));
        }
    }
    for (dt, cost, err) in [
        (0.1, 0.9e-4, 7e-15),
        (0.03, 1.1e-4, 5e-15),
        (0.003, 3e-4, 6e-15),
    ] {
        points.push(point(Method::Exact, dt, 1, cost, err));
    }
    points
}

fn energy(p: &Point) -> f64 {
    p.energy_drift
}

#[test]
fn the_pareto_front_is_on_the_size_of_the_error() {
    // A loss of 50 % is not better than a gain of 10 %.
    let xy = [
        (1.0, 43.7),
        (2.0, -0.5),
        (3.0, 0.1),
        (4.0, -0.2),
        (5.0, f64::NAN),
    ];
    assert_eq!(pareto_front(&xy), [0, 1, 2]);
    assert!(pareto_front(&[]).is_empty());
}

#[test]
fn a_point_that_gains_energy_is_not_on_the_front_and_none_is_on_the_floor() {
    let mut points = accuracy_points();
    // Without exact, the cheapest point is verlet's, which gains 43.7×.
    points.retain(|p| p.method != Method::Exact);
    let front = accuracy::pareto_front(&points, energy, 1e-15);
    assert!(!front.points.is_empty());
    assert!(
        front.points.iter().all(|&(_, e)| e < 1.0),
        "{:?}",
        front.points
    );
    assert!(!front.points.contains(&(0.8e-4 * 1.1, 43.7)));
    // With exact, cheaper than all and at the floor, nothing is above it.
    let points = accuracy_points();
    let floor = accuracy::noise_floor(&points, energy);
    assert_eq!(floor, 7e-15);
    let front = accuracy::pareto_front(&points, energy, floor);
    assert!(front.points.is_empty(), "{:?}", front.points);
    // A front point is never at or below the floor.
    let front = accuracy::pareto_front(&points, energy, 1e-20);
    assert!(!front.points.is_empty());
    assert!(front.points.iter().all(|&(_, e)| e > 1e-20 && e < 1.0));
}

#[test]
fn one_colour_per_method_in_every_chart() {
    let bench = bench::series_of(&bench_rows());
    let accuracy = accuracy::series_by_method(&accuracy_points(), energy);
    let mut seen: Vec<(String, usize)> = Vec::new();
    for s in bench.iter().chain(&accuracy) {
        let method = s.name.split([' ', ',']).next().unwrap().to_owned();
        let colour = s.colour.expect("a colour per method, not per series");
        match seen.iter().find(|(m, _)| *m == method) {
            Some((_, c)) => assert_eq!(*c, colour, "{method} in {}", s.name),
            None => seen.push((method, colour)),
        }
    }
    assert_eq!(seen.len(), 4, "{seen:?}");
    for m in Method::ALL {
        let c = method_colour(m);
        assert!(seen.contains(&(m.name().to_owned(), c)), "{m}");
        assert_ne!(PALETTE[c], PALETTE[3], "yellow does not read on white");
        assert_eq!(setting_colour(Setting::Fixed(m)), PALETTE[c]);
    }
    // Five different colours, and never both blues (they were confused).
    let mut all: Vec<usize> = Method::ALL.iter().map(|&m| method_colour(m)).collect();
    all.push(AUTO_COLOUR);
    all.sort_unstable();
    all.dedup();
    assert_eq!(all.len(), 5);
    assert!(!(all.contains(&1) && all.contains(&4)));
}

#[test]
fn bench_lines_differ_by_colour_or_style_and_every_row_is_drawn() {
    let rows = bench_rows();
    let series = bench::series_of(&rows);
    let mut labels: Vec<String> = Vec::new();
    for r in &rows {
        let with_threads = if r.threads > 1 {
            format!("{} / {}, {} threads", r.method, r.broad_phase, r.threads)
        } else {
            format!("{} / {}", r.method, r.broad_phase)
        };
        if !labels.contains(&with_threads) {
            labels.push(with_threads);
        }
    }
    let names: Vec<&str> = series.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, labels);
    assert_eq!(
        series.iter().map(|s| s.points.len()).sum::<usize>(),
        rows.len()
    );
    for (i, a) in series.iter().enumerate() {
        for b in &series[i + 1..] {
            let look = |s: &Series| (s.colour, s.line, s.marker, s.hollow);
            assert_ne!(look(a), look(b), "{} and {}", a.name, b.name);
        }
    }
    // Impulse's broad phases: one colour, four line styles.
    let impulse: Vec<&Series> = series
        .iter()
        .filter(|s| s.name.starts_with("impulse /") && !s.name.contains("threads"))
        .collect();
    let mut styles: Vec<_> = impulse.iter().map(|s| s.pattern()).collect();
    styles.dedup();
    assert_eq!(styles.len(), 4);

    let dir = tempfile::tempdir().unwrap();
    let (_, svg) = bench::write_bench_chart(&rows, dir.path()).unwrap();
    let text = fs::read_to_string(svg).unwrap();
    for name in names {
        assert!(text.contains(&format!("\n{name}\n")), "{name} not named");
    }
}

#[test]
fn accuracy_points_are_joined_in_step_order_and_carry_their_step() {
    let mut points = accuracy_points();
    points.reverse();
    let series = accuracy::series_by_method(&points, energy);
    let mut keys: Vec<(Method, u32)> = points.iter().map(|p| (p.method, p.substeps)).collect();
    keys.sort_by_key(|&(m, k)| (m.name(), k));
    keys.dedup();
    assert_eq!(series.len(), keys.len(), "a series per method and substeps");
    assert_eq!(
        series.iter().map(|s| s.points.len()).sum::<usize>(),
        points.len()
    );
    for s in &series {
        assert_eq!(s.point_labels.len(), s.points.len());
        let steps: Vec<f64> = s
            .point_labels
            .iter()
            .map(|l| match l.strip_prefix("1/") {
                Some(n) => 1.0 / n.parse::<f64>().unwrap(),
                None => l.parse().unwrap(),
            })
            .collect();
        assert!(
            steps.windows(2).all(|w| w[0] > w[1]),
            "{}: {steps:?}",
            s.name
        );
    }
    assert_eq!(accuracy::dt_label(1.0 / 240.0), "1/240");
    assert_eq!(accuracy::dt_label(0.03), "0.03");
    assert_eq!(accuracy::dt_label(0.1), "1/10");
}

/// A crowded chart: the accuracy sweep with every label and the bench's
/// ten lines ending together.
fn crowded_charts() -> Vec<(Vec<Series>, Option<Series>, Option<f64>)> {
    let points = accuracy_points();
    let floor = accuracy::noise_floor(&points, energy);
    let front = accuracy::pareto_front(&points, energy, 1e-20);
    vec![
        (
            accuracy::series_by_method(&points, energy),
            Some(front),
            Some(floor),
        ),
        (bench::series_of(&bench_rows()), None, None),
    ]
}

#[test]
fn labels_do_not_overlap_each_other_or_any_marker() {
    for (series, front, floor) in crowded_charts() {
        let chart = Chart {
            title: "crowded",
            subtitle: "a line under it",
            x_label: "x",
            y_label: "y",
            log_x: true,
            log_y: true,
            series: &series,
            highlight: front.as_ref(),
            direct_labels: true,
            floor: floor.map(|f| (f, "noise floor (rounding)")),
        };
        let plan = Plan::new(&chart);
        let image = PxRect {
            x0: 0,
            y0: 0,
            x1: SIZE.0 as i32,
            y1: SIZE.1 as i32,
        };
        for (i, a) in plan.labels.iter().enumerate() {
            assert!(a.rect.inside(&image), "{a:?} off the image");
            if a.kind != LabelKind::End {
                assert!(a.rect.inside(&plan.plot), "{a:?} off the plot");
            }
            for b in &plan.labels[i + 1..] {
                assert!(!a.rect.overlaps(&b.rect), "{a:?} overlaps {b:?}");
            }
            for (s, pts) in series.iter().zip(&plan.points) {
                for &p in pts.iter().flatten() {
                    let marker = PxRect::around(p, s.marker_radius());
                    assert!(
                        !a.rect.overlaps(&marker),
                        "{a:?} covers {} at {p:?}",
                        s.name
                    );
                }
            }
        }
        // Every line is named once, and the floor.
        for s in &series {
            let named = plan
                .labels
                .iter()
                .filter(|l| l.kind == LabelKind::End && l.text == s.name)
                .count();
            assert_eq!(named, 1, "{}", s.name);
        }
        assert_eq!(
            plan.labels
                .iter()
                .filter(|l| l.kind == LabelKind::Floor)
                .count(),
            usize::from(floor.is_some())
        );
        // Nearly every point has its step beside it (a repeat at the same
        // spot is said once).
        let wanted = series
            .iter()
            .map(|s| s.point_labels.iter().filter(|l| !l.is_empty()).count())
            .sum::<usize>();
        let set = plan
            .labels
            .iter()
            .filter(|l| l.kind == LabelKind::Point)
            .count();
        assert!(set * 10 >= wanted * 9, "{set} of {wanted} point labels set");
    }
}

#[test]
fn dash_patterns_cover_the_line_in_pieces() {
    let line = [(0, 0), (100, 0)];
    assert_eq!(dashes(&line, &[]), vec![line.to_vec()]);
    let pieces = dashes(&line, &[10, 10]);
    assert_eq!(pieces.len(), 5, "{pieces:?}");
    assert_eq!(pieces[0], [(0, 0), (10, 0)]);
    assert_eq!(pieces[1], [(20, 0), (30, 0)]);
    // Across a corner the dash goes on.
    let bent = dashes(&[(0, 0), (5, 0), (5, 20)], &[10, 4]);
    assert_eq!(bent[0], [(0, 0), (5, 0), (5, 5)]);
    assert!(dashes(&[(3, 3)], &[1, 1]).len() == 1);
}

/// Writes the bench and accuracy charts from the CSV files in
/// `$IMPULSE_LAB` (default `docs/lab`) to `$TMPDIR/chart-preview/`, for a
/// look at full-run data without the runs:
/// `cargo test --bin impulse charts_from_csv -- --ignored`.
#[test]
#[ignore = "writes charts to /tmp for a person to look at; not a check"]
fn charts_from_csv() {
    let dir = std::env::var("IMPULSE_LAB").unwrap_or_else(|_| "docs/lab".into());
    let out = std::env::temp_dir().join("chart-preview");
    fs::create_dir_all(&out).unwrap();
    let read = |name: &str| -> Vec<Vec<String>> {
        let text = fs::read_to_string(Path::new(&dir).join(name)).unwrap_or_default();
        text.lines()
            .skip(1)
            .map(|l| l.split(',').map(String::from).collect())
            .collect()
    };
    let rows: Vec<Row> = read("bench.csv")
        .into_iter()
        .map(|f| Row {
            method: f[0].parse().unwrap(),
            broad_phase: f[1].clone(),
            threads: f[2].parse().unwrap(),
            parallel: f[3] == "true",
            n: f[4].parse().unwrap(),
            ns_per_particle_step: f[5].parse().unwrap(),
            bytes_per_particle: f[6].parse().unwrap(),
            collisions_per_second: f[7].parse().unwrap(),
            steps: f[8].parse().unwrap(),
            speed_up: f.get(9).and_then(|x| x.parse().ok()),
        })
        .collect();
    bench::write_bench_chart(&rows, &out).unwrap();
    let points: Vec<Point> = read("accuracy.csv")
        .into_iter()
        .map(|f| Point {
            method: f[0].parse().unwrap(),
            dt: f[1].parse().unwrap(),
            substeps: f[2].parse().unwrap(),
            cost: f[3].parse().unwrap(),
            trajectory_error: f[4].parse().unwrap(),
            collision_error: f[5].parse().unwrap(),
            energy_drift: f[6].parse().unwrap(),
            pressure_error: f[7].parse().unwrap(),
        })
        .collect();
    accuracy::write_charts(&points, &out).unwrap();
    println!("{}", out.display());
}

#[test]
fn stacked_labels_keep_their_order_and_do_not_overlap() {
    assert_eq!(stack(&[100, 300], 20, 0, 1000), [100, 300]);
    let ys = stack(&[100, 102, 104, 300], 20, 0, 1000);
    assert_eq!(ys, [82, 102, 122, 300]);
    // Against the bottom: moved up as a block.
    let ys = stack(&[995, 996, 997], 20, 0, 1000);
    assert_eq!(ys, [950, 970, 990]);
    let ys = stack(&[10, 50, 52, 54, 56, 58, 60, 62], 24, 0, 1000);
    assert!(ys.windows(2).all(|w| w[1] - w[0] >= 24), "{ys:?}");
}
