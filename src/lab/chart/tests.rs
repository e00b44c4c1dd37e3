//! Chart tests: files written, odd data survived, text laid out.

use super::*;
use std::fs;

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
