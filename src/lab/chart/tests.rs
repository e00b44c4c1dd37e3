//! Chart tests: files written, odd data survived, text laid out.

use super::*;

fn series(name: &str, points: Vec<(f64, f64)>) -> Series {
    Series {
        name: name.to_owned(),
        points,
        ..Default::default()
    }
}

/// Error against steps over many decades, like `impulse accuracy` draws,
/// with the Pareto front (lowest error at each step count) highlighted.
fn accuracy_series() -> (Vec<Series>, Series) {
    let steps: Vec<f64> = (0..=8)
        .map(|i| 10f64.powf(2.0 + 0.5 * f64::from(i)))
        .collect();
    let order = |name: &str, c: f64, p: i32, floor: f64| {
        let points = steps.iter().map(|&n| (n, (c * n.powi(-p)).max(floor)));
        series(name, points.collect())
    };
    let methods = [
        order("explicit Euler", 10.0, 1, 1e-9),
        order("semi-implicit Euler", 1e2, 2, 1e-13),
        order("velocity Verlet", 1e7, 4, 1e-16),
    ];
    let front = steps
        .iter()
        .enumerate()
        .map(|(i, &n)| {
            let best = methods
                .iter()
                .map(|s| s.points[i].1)
                .fold(f64::INFINITY, f64::min);
            (n, best)
        })
        .collect();
    let mut reference = order("reference slope O(h²)", 3e2, 2, 0.0);
    reference.dashed = true;
    let mut all = methods.to_vec();
    all.push(reference);
    (all, series("Pareto front", front))
}

fn non_background(img: &image::RgbImage) -> usize {
    img.pixels().filter(|p| p.0 != [255, 255, 255]).count()
}

fn near(img: &image::RgbImage, c: RGBColor) -> usize {
    img.pixels()
        .filter(|p| {
            let d = |a: u8, b: u8| (i32::from(a) - i32::from(b)).abs();
            d(p.0[0], c.0) + d(p.0[1], c.1) + d(p.0[2], c.2) < 20
        })
        .count()
}

#[test]
fn log_log_chart_with_highlight_writes_png_and_svg() {
    let dir = tempfile::tempdir().unwrap();
    let (all, front) = accuracy_series();
    let three = &all[..3];
    let chart = Chart {
        title: "Energy error after 10 s",
        x_label: "steps",
        y_label: "relative energy error",
        log_x: true,
        log_y: true,
        series: three,
        highlight: Some(&front),
        ..Default::default()
    };
    let (png, svg) = write_chart(&chart, &dir.path().join("accuracy")).unwrap();
    assert_eq!(png, dir.path().join("accuracy.png"));
    assert_eq!(svg, dir.path().join("accuracy.svg"));

    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), SIZE);
    assert!(non_background(&img) > 20_000, "{}", non_background(&img));
    for colour in &PALETTE[..3] {
        assert!(
            near(&img, *colour) > 300,
            "{colour:?}: {}",
            near(&img, *colour)
        );
    }

    let text = fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg"));
    for name in [
        "explicit Euler",
        "semi-implicit Euler",
        "velocity Verlet",
        "Pareto front",
    ] {
        assert!(text.contains(name), "{name} missing from the SVG");
    }
    assert!(text.contains("10⁻¹⁶") && text.contains("10⁶"));

    // Nothing but the two charts is left in the directory.
    let mut left: Vec<_> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    left.sort();
    assert_eq!(left, ["accuracy.png", "accuracy.svg"]);
}

#[test]
fn rewriting_replaces_both_files() {
    let dir = tempfile::tempdir().unwrap();
    let stem = dir.path().join("bench.v2");
    let s = [series("first", vec![(1.0, 1.0), (2.0, 3.0)])];
    let mut chart = Chart {
        title: "t",
        x_label: "x",
        y_label: "y",
        log_x: false,
        log_y: false,
        series: &s,
        highlight: None,
        ..Default::default()
    };
    write_chart(&chart, &stem).unwrap();
    let s2 = [series("second", vec![(1.0, 1.0), (2.0, 3.0)])];
    chart.series = &s2;
    let (png, svg) = write_chart(&chart, &stem).unwrap();
    assert_eq!(png, dir.path().join("bench.v2.png"));
    let text = fs::read_to_string(svg).unwrap();
    assert!(text.contains("second") && !text.contains("first"));
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
}

#[test]
fn empty_charts_still_write() {
    let dir = tempfile::tempdir().unwrap();
    let empty_series = [series("nothing yet", vec![])];
    for (i, (log, series)) in [(false, &[][..]), (true, &[][..]), (true, &empty_series[..])]
        .into_iter()
        .enumerate()
    {
        let chart = Chart {
            title: "",
            x_label: "",
            y_label: "",
            log_x: log,
            log_y: log,
            series,
            highlight: None,
            ..Default::default()
        };
        let (png, svg) = write_chart(&chart, &dir.path().join(format!("empty{i}"))).unwrap();
        let img = image::open(&png).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), SIZE);
        assert!(non_background(&img) > 0);
        assert!(fs::read_to_string(svg).unwrap().starts_with("<svg"));
    }
}

#[test]
fn unplottable_points_are_skipped() {
    let dir = tempfile::tempdir().unwrap();
    let odd = [
        series(
            "zeros and negatives",
            vec![(0.0, 1.0), (-1.0, 2.0), (1.0, 0.0), (2.0, -5.0), (3.0, 4.0)],
        ),
        series(
            "non-finite",
            vec![
                (f64::NAN, 1.0),
                (1.0, f64::INFINITY),
                (f64::NEG_INFINITY, 2.0),
            ],
        ),
        series("one point", vec![(5.0, 5.0)]),
        series("huge", vec![(1e308, -1e308), (f64::MAX, f64::MIN_POSITIVE)]),
    ];
    let only_bad = series("only bad", vec![(0.0, 0.0), (f64::NAN, -1.0)]);
    for (log_x, log_y) in [(true, true), (false, true), (true, false), (false, false)] {
        let chart = Chart {
            title: "odd data",
            x_label: "x",
            y_label: "y",
            log_x,
            log_y,
            series: &odd,
            highlight: Some(&only_bad),
            ..Default::default()
        };
        let stem = dir.path().join(format!("odd-{log_x}-{log_y}"));
        let (png, _) = write_chart(&chart, &stem).unwrap();
        assert_eq!(image::open(&png).unwrap().to_rgb8().dimensions(), SIZE);
    }
}

#[test]
fn unwritable_paths_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    let s = [series("a", vec![(1.0, 1.0), (2.0, 2.0)])];
    let chart = Chart {
        title: "t",
        x_label: "x",
        y_label: "y",
        log_x: false,
        log_y: false,
        series: &s,
        highlight: None,
        ..Default::default()
    };
    let missing = dir.path().join("no/such/dir/chart");
    let err = write_chart(&chart, &missing).unwrap_err();
    assert!(format!("{err:#}").contains("chart.png"), "{err:#}");

    let file = dir.path().join("a-file");
    fs::write(&file, "x").unwrap();
    assert!(write_chart(&chart, &file.join("chart")).is_err());
    assert!(write_chart(&chart, Path::new("/")).is_err());
    // Nothing half-written is left behind.
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn log_axes_over_many_decades() {
    let x = Axis::fit([1e2, 1e6].into_iter(), true, 12);
    assert_eq!(x.bold, [2.0, 3.0, 4.0, 5.0, 6.0]);
    let labels: Vec<String> = x.bold.iter().map(|&t| x.label(t)).collect();
    assert_eq!(labels, ["10²", "10³", "10⁴", "10⁵", "10⁶"]);
    assert!(!x.light.is_empty());

    let y = Axis::fit([1e-16, 1e2].into_iter(), true, 10);
    assert!(y.bold.len() <= 10 && y.bold.len() >= 5, "{:?}", y.bold);
    assert!(y.bold.contains(&-16.0) && y.bold.contains(&2.0));
    assert_eq!(y.label(-16.0), "10⁻¹⁶");
    assert!(y.lo < -16.0 && y.hi > 2.0);

    // Under two decades: out to the decades around, labelled 10ᵏ only.
    let narrow = Axis::fit([3.0, 40.0].into_iter(), true, 10);
    assert_eq!(narrow.labels, Labels::Decades);
    let labels: Vec<String> = narrow.bold.iter().map(|&t| narrow.label(t)).collect();
    assert_eq!(labels, ["10⁰", "10¹", "10²"]);
    assert_eq!(narrow.light.len(), 16, "2…9 × 10⁰ and × 10¹");

    let tiny = Axis::fit([100.0, 101.0].into_iter(), true, 10);
    assert_eq!(tiny.bold, [1.0, 2.0, 3.0]);
}

/// Every labelled tick of a log axis is a whole decade, whatever the data.
#[test]
fn log_axes_label_only_decades() {
    for (lo, hi) in [
        (7.0, 6000.0),
        (1e-15, 43.7),
        (2e-4, 3e-4),
        (0.9, 1.1),
        (1e-300, 1e300),
    ] {
        let axis = Axis::fit([lo, hi].into_iter(), true, 10);
        assert!(axis.bold.len() >= 2, "{lo}..{hi}: {:?}", axis.bold);
        assert!(axis.bold.len() <= 11, "{lo}..{hi}: {:?}", axis.bold);
        for &t in &axis.bold {
            assert_eq!(t, t.round(), "{lo}..{hi}: tick at 10^{t}");
            assert!(axis.label(t).starts_with("10"), "{}", axis.label(t));
        }
        assert!(axis.lo <= lo.log10() && axis.hi >= hi.log10());
    }
}

#[test]
fn font_metrics_agree_with_plotters() {
    ensure_font().unwrap();
    let metrics = font_metrics().expect("metrics of the embedded font");
    let mut buffer = vec![0u8; 400 * 100 * 3];
    let area = BitMapBackend::with_buffer(&mut buffer, (400, 100)).into_drawing_area();
    for (text, size) in [
        ("reference slope O(h²)", 16.0),
        ("Energy error after 10 s", 30.0),
        ("AVAVA Tw 10⁻¹⁶ |ΔE| / E₀", 20.0),
        ("impulse / grid, 2 threads", 20.0),
    ] {
        let style = (FONT, size).into_font().into_text_style(&area);
        let (theirs, _) = area.estimate_text_size(text, &style).unwrap();
        let (glyphs, ours) = metrics.layout(text, size);
        assert_eq!(glyphs.len(), text.chars().count());
        assert!(
            (ours - f64::from(theirs)).abs() <= 2.0,
            "{text}: {ours} vs {theirs}"
        );
        assert!(glyphs.windows(2).all(|w| w[0].1 < w[1].1 + 3), "{glyphs:?}");
    }
    assert!(metrics.kern(metrics.glyph('A'), metrics.glyph('V')) < 0.0);
    assert_ne!(metrics.glyph('⁶'), 0);
    assert_eq!(metrics.glyph('\u{10FFFF}'), 0);
    assert!(Metrics::parse(&FONT_BYTES[..4096]).is_none());
    assert!(Metrics::parse(&[]).is_none());
}

#[test]
fn linear_axis_labels() {
    let a = Axis::fit([0.0, 1.0].into_iter(), false, 10);
    let labels: Vec<String> = a.bold.iter().map(|&t| a.label(t)).collect();
    assert_eq!(labels, ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
    let big = Axis::fit([0.0, 3e7].into_iter(), false, 10);
    assert_eq!(big.label(big.bold[1]), "5e6");
    assert_eq!(format_linear(1.5e-7, 1e-8), "1.5e-7");
    assert_eq!(format_linear(-2.0, 1.0), "-2");
    let signed = Axis::fit([-2.0, 2.0].into_iter(), false, 10);
    assert_eq!(signed.label(-1.0), "−1.0");
    let flat = Axis::fit([7.0, 7.0].into_iter(), false, 10);
    assert!(flat.lo < 7.0 && flat.hi > 7.0 && !flat.bold.is_empty());
}

/// Writes /tmp/chart-example.{png,svg} for a look:
/// `cargo test --bin impulse chart_example -- --ignored`.
#[test]
#[ignore = "writes an example chart to /tmp for a person to look at; not a check"]
fn chart_example() {
    let (all, front) = accuracy_series();
    let chart = Chart {
        title: "Energy error after 10 s, default scene",
        x_label: "steps",
        y_label: "relative energy error |ΔE| / E₀",
        log_x: true,
        log_y: true,
        series: &all,
        highlight: Some(&front),
        ..Default::default()
    };
    let (png, svg) = write_chart(&chart, &std::env::temp_dir().join("chart-example")).unwrap();
    println!("{} {}", png.display(), svg.display());
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    fn value() -> impl Strategy<Value = f64> {
        prop_oneof![
            4 => -1e3..1e3f64,
            2 => (-300..300i32).prop_map(|e| 10f64.powi(e)),
            1 => Just(0.0),
            1 => Just(f64::NAN),
            1 => Just(f64::INFINITY),
            1 => Just(f64::MAX),
            1 => Just(-f64::MAX),
            1 => Just(f64::MIN_POSITIVE),
            1 => Just(5e-324),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// Any data renders without panicking or failing.
        #[test]
        fn any_points_render(
            points in proptest::collection::vec((value(), value()), 0..12),
            log_x: bool,
            log_y: bool,
        ) {
            let s = [series("s", points.clone()), series("t", points.iter().rev().copied().collect())];
            let chart = Chart {
                title: "p", x_label: "x", y_label: "y", log_x, log_y,
                series: &s, highlight: None, ..Default::default()
            };
            let layout = Plan::new(&chart);
            for axis in [&layout.x, &layout.y] {
                prop_assert!(axis.lo.is_finite() && axis.hi.is_finite() && axis.lo < axis.hi);
                prop_assert!(axis.bold.len() <= 40);
            }
            render_rgb(&chart, &layout).unwrap();
            render_svg(&chart, &layout).unwrap();
        }
    }
}

// ------------------------------------------------------------ what a reader needs

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
