//! The dock's plots and lines at a projector's size (1024×768, text size 2)
//! under Xvfb: the momentum diagram, the speed histogram, the rough gas's
//! speeds, shares and totals take their share of the tab, inside it; a line
//! cut to its room shows one tooltip; the top bar's hidden values show on a
//! click; and In words keeps the line said at the impact in sight.

#[path = "window_harness/mod.rs"]
mod harness;

use harness::*;
use serde_json::Value;

fn main() -> std::process::ExitCode {
    harness::run(vec![
        (
            "at_the_projector_scale_the_plots_fill_their_tab_and_a_cut_line_shows_one_tooltip",
            at_the_projector_scale_the_plots_fill_their_tab_and_a_cut_line_shows_one_tooltip,
        ),
        (
            "the_rough_gas_plots_fill_their_tab_at_the_projector_scale",
            the_rough_gas_plots_fill_their_tab_at_the_projector_scale,
        ),
        (
            "in_words_keeps_the_line_said_at_the_impact_in_the_tab",
            in_words_keeps_the_line_said_at_the_impact_in_the_tab,
        ),
    ])
}

/// The rectangle of `plot`, which must be at least `share` of the tab's
/// height; with the tab's rectangle.
fn plot_with_share(s: &Value, plot: &str, share: f64) -> ([f64; 4], [f64; 4]) {
    let (area, frame) = (tab_content(s), rect(&s["panel_widgets"][plot]));
    assert!(
        frame[3] >= share * area[3],
        "{plot}: a frame {} px high in a tab {} px high",
        frame[3],
        area[3]
    );
    (frame, area)
}

/// At 1024×768 and text size 2 the dock's tab is 100 points high. The
/// momentum diagram and the speed histogram take most of it (their numbers
/// and axis names had left the diagram a quarter, 23 points), inside the
/// tab; a line cut to its room shows one tooltip when hovered (egui's own
/// one for the cut text had stacked under the app's); and the top bar's
/// hidden values show on a click (no hover on a touch screen).
fn at_the_projector_scale_the_plots_fill_their_tab_and_a_cut_line_shows_one_tooltip() {
    let x = Xvfb::start("plots");
    let app = projector_at_impact(&x, "pt-BR");
    for (key, tab, plot, share) in [
        ("d", "Momenta", "momenta_plot", 0.55),
        ("F4", "Speeds", "speeds_plot", 0.4),
    ] {
        app.xdo(&["key", key]);
        app.wait_for(tab, 60, |s| s["ui"]["tab"] == tab);
        let s = app.wait_frames(3);
        let (frame, area) = plot_with_share(&s, plot, share);
        assert!(
            frame[1] >= area[1] - 0.5 && frame[1] + frame[3] <= area[1] + area[3] + 0.5,
            "{plot} {frame:?} inside the tab {area:?}"
        );
    }
    // J's report, in words now, is whole on the strip's two lines here (its
    // energy had been cut off); it gives way to the caption after 4 s.
    let cut = |s: &Value, name: &str| {
        s["ui"]["cut"]
            .as_array()
            .is_some_and(|c| c.iter().any(|n| n == name))
    };
    let s = app.state();
    assert!(s["panel_widgets"]["message"].is_array(), "J's report");
    assert!(
        !cut(&s, "message"),
        "J's report cut: {}",
        s["ui"]["message"]
    );
    let s = app.wait_for("the caption back", 600, |s| {
        s["panel_widgets"]["caption"].is_array()
    });
    // The line over the histogram, the caption under the world (on its two
    // lines) and the scene's name are cut at this size (Portuguese): one
    // tooltip each.
    assert!(
        cut(&s, "caption"),
        "the caption is whole: no tooltip to test"
    );
    let line = tab_content(&s);
    for (what, at) in [
        (
            "the line over the plot",
            [line[0] + 0.5 * line[2], line[1] + 12.0],
        ),
        ("the caption", {
            let strip = caption_strip(&s);
            [strip[0] + 0.5 * strip[2], strip[1] + 0.5 * strip[3]]
        }),
        ("the scene's name", widget(&s, "scene_name", 0.5)),
    ] {
        app.move_to([at[0], at[1]]);
        app.wait_for(what, 120, |s| s["ui"]["tooltips"].as_u64() > Some(0));
        for _ in 0..5 {
            let s = app.wait_frames(1);
            assert_eq!(s["ui"]["tooltips"], 1, "{what}: tooltips");
        }
        app.move_to([500.0, 200.0]);
        app.wait_for("no tooltip", 120, |s| s["ui"]["tooltips"] == 0);
    }
    // What the top bar has no room for shows on a click too, and stays
    // until a click elsewhere: a touch screen has no hover.
    app.click(widget(&s, "top_bar_more", 0.5));
    app.move_to([500.0, 200.0]);
    // The click may reach the window a frame after the pointer moved on.
    app.wait_for("the hidden values on a click", 30, |s| {
        s["ui"]["tooltips"] == 1
    });
    for _ in 0..5 {
        let s = app.wait_frames(1);
        assert_eq!(s["ui"]["tooltips"], 1, "the hidden values after a click");
    }
    app.click([500.0, 200.0]);
    app.wait_for("the hidden values put away", 30, |s| {
        s["ui"]["tooltips"] == 0
    });
    // Esc puts them away too, as it does any popup.
    app.click(widget(&s, "top_bar_more", 0.5));
    app.move_to([500.0, 200.0]);
    app.wait_for("the hidden values again", 30, |s| s["ui"]["tooltips"] == 1);
    app.xdo(&["key", "Escape"]);
    app.wait_for("the hidden values put away by Esc", 30, |s| {
        s["ui"]["tooltips"] == 0
    });
    app.quit();
}

/// Rough discs at the same size, in Portuguese: the speeds and the
/// energy's shares side by side, each plot under one line of names
/// (wrapped onto two, they left the shares a strip 22 px high); and the
/// Totals' six series named after the change, not on lines of their own
/// (which left the plots strips 35 px high), with time axes numbered
/// without a name under them and the last plot short of the tab's edge,
/// which cut its last number.
fn the_rough_gas_plots_fill_their_tab_at_the_projector_scale() {
    let x = Xvfb::start("rough plots");
    let rough = asset("preset-rough-gas.toml");
    let args = ["--size", "1024x768", "--ui-scale", "2", "--lang", "pt-BR"];
    let app = Sandbox::start(&x, &[&args[..], &[rough.as_str(), "--paused"]].concat());
    app.move_to([500.0, 200.0]);
    app.xdo(&["key", "F4"]);
    let s = app.wait_for("the two plots", 60, |s| {
        let noted = |name: &str| s["panel_widgets"][name].is_array();
        s["ui"]["tab"] == "Speeds" && noted("speeds_plot") && noted("shares_plot")
    });
    for plot in ["speeds_plot", "shares_plot"] {
        plot_with_share(&s, plot, 0.4);
    }
    let area = tab_content(&s);
    app.move_to([area[0] + 0.9 * area[2], area[1] + 12.0]);
    app.wait_for("the names' meaning", 120, |s| {
        s["ui"]["tooltips"].as_u64() > Some(0)
    });
    assert_eq!(app.wait_frames(2)["ui"]["tooltips"], 1);
    // Run a while first: the walls' pushes make the change's numbers long.
    app.move_to([500.0, 200.0]);
    app.xdo(&["key", "space"]);
    app.wait_for("a few seconds run", 600, |s| s["time"].as_f64() > Some(3.0));
    app.xdo(&["key", "space", "t"]);
    let plots = ["momentum_plot", "angular_momentum_plot", "energy_plot"];
    let s = app.wait_for("the three totals", 60, |s| {
        s["ui"]["tab"] == "Totals" && plots.iter().all(|p| s["panel_widgets"][p].is_array())
    });
    for plot in plots {
        let (frame, area) = plot_with_share(&s, plot, 0.25);
        assert!(
            frame[1] + frame[3] <= area[1] + area[3] + 0.5
                && frame[0] + frame[2] <= area[0] + area[2] - 20.0,
            "{plot} {frame:?} inside the tab {area:?} with room for its last number"
        );
    }
    app.quit();
}

/// In words at the projector's size (in French, whose tab row has room for
/// the tab's name): the line said at the impact is whole inside the tab
/// (the explanation above it, on three lines, had left it one).
fn in_words_keeps_the_line_said_at_the_impact_in_the_tab() {
    let x = Xvfb::start("words");
    let app = projector_at_impact(&x, "fr");
    let s = app.state();
    app.click(widget(&s, "tab_words", 0.5));
    let s = app.wait_for("the newest line", 60, |s| {
        s["panel_widgets"]["words_newest"].is_array()
    });
    let (area, said) = (tab_content(&s), rect(&s["panel_widgets"]["words_newest"]));
    assert!(
        said[1] >= area[1] - 0.5 && said[1] + said[3] <= area[1] + area[3] + 0.5,
        "the line said {said:?} inside the tab {area:?}"
    );
    app.quit();
}
