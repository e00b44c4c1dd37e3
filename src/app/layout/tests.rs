//! The layout's guarantees over sizes × scales × states of the docks.
use super::*;

const SCALES: [f32; 4] = [1.0, 1.5, 2.0, 2.5];
const SHOWN: u8 = 1;
const SIDE: u8 = 2;
const TAB: u8 = 4;
const DRAWER: u8 = 8;
/// The scene's caption takes the most lines.
const LONG_CAPTION: u8 = 16;
const OPEN_TAB: u8 = SHOWN | SIDE | TAB;

fn docks(bits: u8) -> Docks {
    let [shown, side, tab_open, drawer_open, long] =
        [SHOWN, SIDE, TAB, DRAWER, LONG_CAPTION].map(|b| bits & b != 0);
    Docks {
        shown,
        side,
        tab_open,
        drawer_open,
        tab_height: None,
        caption_lines: if long { MAX_CAPTION_LINES } else { 1 },
    }
}

/// Every size (800×600, 1024×768, 1280×800, 1920×1080 among them), scale
/// and state of the docks (as bits).
fn grid() -> impl Iterator<Item = (f32, f32, f32, u8)> {
    let widths = [800.0, 1024.0, 1280.0, 1366.0, 1600.0, 1920.0];
    let sizes = widths
        .into_iter()
        .flat_map(|w| [600.0, 768.0, 800.0, 900.0, 1080.0].map(|h| (w, h)));
    let scaled = sizes.flat_map(|(w, h)| SCALES.map(|s| (w, h, s)));
    scaled.flat_map(|(w, h, s)| (0..32).map(move |b| (w, h, s, b)))
}

/// Inside the window, no overlaps, no gaps, nothing negative.
fn assert_tiles(r: &Rects, what: &str) {
    let all = [
        Some(r.top_bar),
        r.side,
        Some(r.world),
        Some(r.caption),
        r.tab_content,
        r.tab_row,
    ];
    let tiles: Vec<Rect> = all.into_iter().flatten().collect();
    for t in tiles.iter().chain(&r.drawer) {
        let sane = t.as_array().iter().all(|v| v.is_finite()) && t.w >= 0.0 && t.h >= 0.0;
        assert!(
            sane && r.window.contains(t),
            "{what}: {t:?} in {:?}",
            r.window
        );
    }
    for (i, a) in tiles.iter().enumerate() {
        for b in &tiles[i + 1..] {
            assert!(!a.overlaps(b), "{what}: {a:?} overlaps {b:?}");
        }
    }
    let gap = tiles.iter().map(Rect::area).sum::<f32>() - r.window.area();
    assert!(
        gap.abs() <= 1e-6 * r.window.area().max(1.0),
        "{what}: {gap}"
    );
}

fn assert_guarantees(w: f32, h: f32, s: f32, r: &Rects, what: &str) {
    let (world, big, bigger) = (r.world, w >= 800.0 && h >= 600.0, w >= 1024.0 && h >= 768.0);
    // From 1024×768 up at scales 1 to 2, from 800×600 up at 1 to 1.5.
    if (bigger && s <= 2.0) || (big && s <= 1.5) {
        // To f32 rounding (SLACK_PX of height).
        assert!(
            world.area() >= MIN_WORLD_SHARE * w * h * (1.0 - 1e-5),
            "{what}: {world:?}"
        );
        assert!(world.w.min(world.h) >= MIN_WORLD_PX, "{what}: {world:?}");
    }
    // At scale 2 below 1024×768, and at 2.5, from 800×600 up.
    if big && (s > 2.0 || (s >= 2.0 && !bigger)) {
        assert!(world.w == w && world.h >= MIN_WORLD_PX, "{what}: {world:?}");
        assert!(r.side.is_none(), "{what}");
    }
}

#[test]
fn grid_tiles_keeps_guarantees_and_gives_way_in_order() {
    for (w, h, s, b) in grid() {
        let (d, row) = (docks(b), row_px(s));
        let r = layout((w, h), s, d);
        let what = format!("{w}x{h} at {s} {d:?}");
        assert_tiles(&r, &what);
        assert_guarantees(w, h, s, &r, &what);
        let min_tab = MIN_TAB_ROWS * row;
        let folded = d.shown && d.tab_open && r.tab_content.is_none();
        assert_eq!(r.tab_folded, folded, "{what}");
        if let Some(c) = r.tab_content {
            assert!(c.h >= min_tab && c.h <= tab_wanted(h, s), "{what}");
        }
        // The side dock gives way (to a drawer) before the tab folds.
        assert!(!(r.tab_folded && r.side_dock == SideDock::Docked), "{what}");
        let hidden = !d.shown || !d.side;
        assert_eq!(r.side_dock == SideDock::Hidden, hidden, "{what}");
        assert_eq!(r.side.is_some(), r.side_dock == SideDock::Docked, "{what}");
        // Nothing gives way without need: a px more of tab (or the side
        // docked, with the smallest tab) would break the world's guarantee.
        let need = |world_w: f32| MIN_WORLD_PX.max(MIN_WORLD_SHARE * w * h / world_w);
        let content = r.tab_content.map_or(0.0, |c| c.h);
        if d.shown && d.tab_open && content < tab_wanted(h, s).floor() {
            let more = if r.tab_folded { min_tab } else { 1.0 };
            assert!(r.world.h - more < need(r.world.w), "{what}");
        }
        if matches!(r.side_dock, SideDock::Drawer { .. }) && s <= MAX_DOCKED_SCALE {
            let bars = 2.0 * row + caption_px(s, d.caption_lines);
            let (docked, room) = (w - side_width(w, s), h - bars);
            let fits = docked >= MIN_WORLD_PX && room - min_tab >= need(docked);
            assert!(!fits, "{what}");
        }
        // The bars are one row, whatever their content; the caption strip
        // a row and the lines more its caption needs.
        let caption_h = row + f32::from(d.caption_lines - 1) * (LINE_POINTS * s).round();
        assert_eq!((r.top_bar.h, r.caption.h), (row, caption_h), "{what}");
        assert_eq!(
            r.tab_row.map(|t| (t.h, t.bottom())),
            d.shown.then_some((row, h))
        );
        assert_eq!((r.world.x, r.world.y), (0.0, r.top_bar.bottom()), "{what}");
        assert_eq!(r.caption.y, r.world.bottom(), "{what}");
    }
}

#[test]
fn a_row_holds_a_line_of_text() {
    for s in [1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5] {
        // 17-point text (16 the smallest) in the 24-point interact
        // height, plus the panel frame's 2 + 2 points of margin.
        assert!(
            row_px(s) >= (24.0 + 4.0) * s && row_px(s) >= (17.0 + 4.0) * s,
            "{s}"
        );
    }
}

#[test]
fn opening_a_tab_moves_only_the_worlds_bottom_edge() {
    for (w, h, s, b) in grid().filter(|g| g.3 & TAB == 0) {
        let (closed, open) = (
            layout((w, h), s, docks(b)),
            layout((w, h), s, docks(b | TAB)),
        );
        let content = open.tab_content.map_or(0.0, |c| c.h);
        let mut moved = closed;
        moved.world.h -= content;
        moved.caption.y -= content;
        (moved.tab_content, moved.tab_folded) = (open.tab_content, open.tab_folded);
        assert_eq!(moved, open, "{w}x{h} at {s} {:?}", docks(b));
    }
}

#[test]
fn the_drawer_floats_and_changes_nothing_else() {
    for (w, h, s, b) in grid().filter(|g| g.3 & DRAWER == 0) {
        let (shut, open) = (
            layout((w, h), s, docks(b)),
            layout((w, h), s, docks(b | DRAWER)),
        );
        let mut same = open;
        (same.drawer, same.side_dock) = (None, shut.side_dock);
        assert_eq!(same, shut);
        assert_eq!(
            open.drawer.is_some(),
            shut.side_dock == SideDock::Drawer { open: false }
        );
        if let Some(drawer) = open.drawer {
            assert_eq!(open.side_dock, SideDock::Drawer { open: true });
            assert_eq!((drawer.right(), drawer.y), (w, open.top_bar.bottom()));
            assert_eq!(drawer.w, drawer_width(w, s));
            assert!(drawer.w <= side_width(w, s) && drawer.w <= w - row_px(s));
        }
    }
}

#[test]
fn at_1024x768_scale_2_the_world_keeps_its_share() {
    let r = layout((1024.0, 768.0), 2.0, docks(OPEN_TAB));
    assert!(r.world.area() >= MIN_WORLD_SHARE * 1024.0 * 768.0);
    assert!(r.world.w.min(r.world.h) >= MIN_WORLD_PX, "{:?}", r.world);
    // The side dock gave way, and the tab grew back past its minimum.
    assert_eq!(r.side_dock, SideDock::Drawer { open: false });
    assert!(r.tab_content.unwrap().h > MIN_TAB_ROWS * row_px(2.0));
}

#[test]
fn at_800x600_scale_2_the_world_has_the_full_width() {
    let r = layout((800.0, 600.0), 2.0, docks(OPEN_TAB));
    assert_eq!((r.world.w, r.side), (800.0, None));
    assert!(r.world.h >= MIN_WORLD_PX && !r.tab_folded, "{r:?}");
}

#[test]
fn with_room_nothing_gives_way() {
    let r = layout((1920.0, 1080.0), 1.0, docks(OPEN_TAB));
    assert_eq!(r.side.unwrap().w, side_width(1920.0, 1.0));
    assert_eq!(r.tab_content.unwrap().h, tab_wanted(1080.0, 1.0).floor());
}

#[test]
fn guarantees_hold_between_the_grid_points() {
    // Landscape windows from 800×600 to 1920 wide, every 8 px.
    let heights = (600..=1200).step_by(8).map(|h| h as f32);
    for s in [1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5] {
        for w in (800..=1920).step_by(8).map(|w| w as f32) {
            for h in heights.clone().filter(|&h| h <= w) {
                let r = layout((w, h), s, docks(OPEN_TAB));
                assert_guarantees(w, h, s, &r, &format!("{w}x{h} at {s}"));
            }
        }
    }
}

#[test]
fn a_chosen_tab_height_is_kept_within_what_the_world_leaves() {
    let chosen = [
        0.0,
        50.0,
        200.0,
        281.0,
        300.0,
        500.0,
        1e4,
        f32::NAN,
        f32::INFINITY,
    ];
    for (w, h, s, b) in grid().filter(|g| g.3 & (SHOWN | TAB) == SHOWN | TAB) {
        let plain = layout((w, h), s, docks(b));
        let range = tab_range((w, h), s, docks(b));
        assert_eq!(range.is_some(), plain.tab_content.is_some());
        for v in chosen {
            let d = Docks {
                tab_height: Some(v),
                ..docks(b)
            };
            let r = layout((w, h), s, d);
            let what = format!("{w}x{h} at {s} {d:?}");
            assert_tiles(&r, &what);
            assert_guarantees(w, h, s, &r, &what);
            // The side dock and the bars do not move; only the world's
            // bottom edge and the caption strip under it.
            assert_eq!(r.side_dock, plain.side_dock, "{what}");
            assert_eq!(
                (r.side, r.tab_row, r.top_bar),
                (plain.side, plain.tab_row, plain.top_bar)
            );
            let Some((least, most)) = range else {
                assert!(r.tab_folded, "{what}");
                continue;
            };
            let c = r.tab_content.unwrap().h;
            let expect = if v.is_nan() {
                least
            } else {
                v.clamp(least, most).floor()
            };
            assert_eq!(c, expect.max(least), "{what}");
            assert!(c >= least && c <= most, "{what}");
        }
    }
    // At a projector's size the tab can be made taller than it opens.
    let d = docks(OPEN_TAB);
    let (least, most) = tab_range((1024.0, 768.0), 2.0, d).unwrap();
    let opened = layout((1024.0, 768.0), 2.0, d).tab_content.unwrap().h;
    assert!(
        least < opened && opened + 60.0 < most,
        "{least} {opened} {most}"
    );
}

#[test]
fn degenerate_inputs_do_not_panic() {
    let (nan, inf) = (f32::NAN, f32::INFINITY);
    let sizes = [
        (0.0, 0.0),
        (100.0, 100.0),
        (1.0, 5e3),
        (5e3, 1.0),
        (239.5, 241.3),
    ];
    let odd = [(-5.0, 300.0), (1e9, 1e9), (nan, inf), (-inf, f32::MAX)];
    let scales = [nan, inf, -inf, 0.0, -1.0, 0.5, 1.3, 100.0];
    for (w, h) in sizes.into_iter().chain(odd) {
        for s in scales.into_iter().chain(SCALES) {
            for b in 0..32 {
                let r = layout((w, h), s, docks(b));
                assert_tiles(&r, &format!("{w}x{h} at {s} {:?}", docks(b)));
            }
            // Lines the caption cannot have are the nearest it can.
            for (lines, near) in [(0, 1), (3, 2), (u8::MAX, 2)] {
                let odd = Docks {
                    caption_lines: lines,
                    ..docks(OPEN_TAB)
                };
                let near = Docks {
                    caption_lines: near,
                    ..odd
                };
                assert_eq!(layout((w, h), s, odd), layout((w, h), s, near));
            }
        }
    }
    assert_eq!((clamp_scale(nan), clamp_scale(inf)), (1.0, 2.5));
}
