//! Where everything on the screen goes, computed before anything is drawn:
//! one pure function, [`layout`], from the window's size (px), the UI scale
//! and which docks and tabs are open to every rectangle, in the app's pixels
//! (origin top-left, y down). The egui panels are then given exactly these
//! sizes (`exact_height` / `exact_width`) and scroll their content inside,
//! so a wrapping caption or a changed tab can no longer move anything.
//!
//! ```text
//! +------------------------- top bar (1 row) --------------------------+
//! | world (the rest)                                  | side dock      |
//! |                                                   | (docked, or a  |
//! +---------------- caption strip (1 row) ------------+  drawer that   |
//! | tab content (what is granted; 0 if closed/folded) |  floats over   |
//! +---------------- tab row (1 row) ------------------+  the world)    |
//! +-------------------------------------------------------------------+
//! ```
//!
//! The tab content sits *above* the tab row, which stays at the window's
//! bottom: clicking a tab opens it without moving the tab under the pointer.
//!
//! **The world is the lesson, so it never gives way.** Constraints go down
//! (the world's guarantees bound what the docks may take), sizes come up
//! (each dock gets what it wants within that). When space is short:
//! 1. the open tab's content shrinks (it scrolls), down to [`MIN_TAB_ROWS`];
//! 2. then the side dock becomes a drawer (a top-bar button opens it over the
//!    world, like a popup; it takes nothing from the world), and the tab
//!    content may grow back in the wider bottom dock;
//! 3. then the tab content folds to the tab row ([`Rects::tab_folded`]).
//!
//! Whether the side dock is docked is decided as if a tab were open, so
//! opening or closing a tab never docks or undocks it.
//!
//! Guarantees (tested), with a tab open: from 1024×768 up at scales 1 to 2,
//! and from 800×600 up at scales 1 to 1.5, the world keeps at least
//! [`MIN_WORLD_SHARE`] of the window's area and [`MIN_WORLD_PX`] each way.
//! Above [`MAX_DOCKED_SCALE`] (at 2.5) from 800×600 up, and at scale 2 from
//! 800×600 up to below 1024×768, it keeps the full window width (the side
//! dock is a drawer) and [`MIN_WORLD_PX`] of height. (At scale 2 that
//! follows from the 40 % rule; it holds for landscape windows up to 1920
//! wide, while a very wide, short one, 2424×760, may dock.) Smaller windows
//! get the best possible: sizes never negative, everything inside.
//!
//! What stays fixed: the top bar, caption strip and tab row are one row
//! each ([`row_px`]), a function of the scale alone. Opening or closing a
//! tab, or the drawer, never moves the world's top, left or width, nor the
//! top bar, side dock or tab row; a tab moves only the world's bottom edge
//! (and the caption strip glued under it) by the tab content's height.

/// Height of a one-line bar (top bar, caption strip, tab row) at scale 1, in
/// points (px = points × scale): egui's interact height of 24 (set by the
/// theme; it holds one line of 17-point body text) + 2 + 2 of a panel's
/// frame margin + a 1-point separator, rounded up to 30.
pub const ROW_POINTS: f32 = 30.0;
/// The smallest world, each way, in px.
pub const MIN_WORLD_PX: f32 = 240.0;
/// The smallest share of the window's area the world keeps.
pub const MIN_WORLD_SHARE: f32 = 0.40;
/// The tab content's smallest height, in rows, before it folds.
pub const MIN_TAB_ROWS: f32 = 3.0;
/// Above this scale the side dock is always a drawer.
pub const MAX_DOCKED_SCALE: f32 = 2.0;
/// The UI scales the layout knows (the CLI's and the slider's range):
/// from 1 to 2.5.
pub const MIN_SCALE: f32 = 1.0;
/// See [`MIN_SCALE`].
pub const MAX_SCALE: f32 = 2.5;
/// Any window side is clamped to this: larger than any screen, and small
/// enough that sums of whole pixels stay exact in `f32`.
const MAX_WINDOW_PX: f32 = 65_536.0;
/// Absorbs `f32` rounding of the area share, so an exact fit (800×600 at
/// scale 2: 240 px of world over 3 rows of tab) does not fold.
const SLACK_PX: f32 = 1.0e-3;

/// A rectangle in px.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Rect {
    pub x: f32,
    pub y: f32,
    pub w: f32,
    pub h: f32,
}

impl Rect {
    pub const fn new(x: f32, y: f32, w: f32, h: f32) -> Self {
        Self { x, y, w, h }
    }
    #[cfg(test)]
    pub fn area(&self) -> f32 {
        self.w * self.h
    }
    #[cfg(test)]
    pub fn right(&self) -> f32 {
        self.x + self.w
    }
    pub fn bottom(&self) -> f32 {
        self.y + self.h
    }
    /// Whether the two share an area (touching edges do not overlap).
    #[cfg(test)]
    pub fn overlaps(&self, other: &Rect) -> bool {
        self.right().min(other.right()) > self.x.max(other.x)
            && self.bottom().min(other.bottom()) > self.y.max(other.y)
    }
    /// Whether `other` lies wholly inside (edges included).
    #[cfg(test)]
    pub fn contains(&self, other: &Rect) -> bool {
        other.x >= self.x
            && other.y >= self.y
            && other.right() <= self.right()
            && other.bottom() <= self.bottom()
    }
    /// `[x, y, w, h]`.
    pub fn as_array(&self) -> [f32; 4] {
        [self.x, self.y, self.w, self.h]
    }
}

/// What the user has open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Docks {
    /// Docks shown at all (Tab hides them all).
    pub shown: bool,
    /// The side dock wanted (L closes it).
    pub side: bool,
    /// A tab of the bottom dock is open.
    pub tab_open: bool,
    /// The side dock's drawer is open (only matters when it is a drawer).
    pub drawer_open: bool,
}

/// What became of the side dock.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SideDock {
    Docked,
    /// Not docked, for want of room: a top-bar button opens it over the world.
    Drawer {
        open: bool,
    },
    /// Closed by the user (L), or all docks hidden (Tab).
    Hidden,
}

/// Every rectangle on the screen, in px.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rects {
    /// The window, (0, 0, width, height) after sanitising.
    pub window: Rect,
    pub top_bar: Rect,
    /// The side dock, when docked.
    pub side: Option<Rect>,
    /// The side dock's drawer, when open; floats over the world.
    pub drawer: Option<Rect>,
    pub side_dock: SideDock,
    /// The bottom dock's tab row, while docks are shown.
    pub tab_row: Option<Rect>,
    /// The open tab's content, above the tab row, when it got any room.
    pub tab_content: Option<Rect>,
    /// A tab is open but had to fold to the tab row (say so in the view).
    pub tab_folded: bool,
    /// The one-line strip under the world (scale bar, caption, message).
    pub caption: Rect,
    pub world: Rect,
}

/// The scale clamped to [`MIN_SCALE`]..=[`MAX_SCALE`] (NaN gives 1).
pub fn clamp_scale(scale: f32) -> f32 {
    if scale.is_nan() {
        MIN_SCALE
    } else {
        scale.clamp(MIN_SCALE, MAX_SCALE)
    }
}

fn sane_px(v: f32) -> f32 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(0.0, MAX_WINDOW_PX)
    }
}

/// One row (top bar, caption strip, tab row), in whole px.
pub fn row_px(scale: f32) -> f32 {
    (ROW_POINTS * clamp_scale(scale)).round()
}

/// The docked side dock's width in whole px: 26 % of the window's width in
/// points, within 210 to 290 points.
pub fn side_width(window_w: f32, scale: f32) -> f32 {
    let s = clamp_scale(scale);
    ((0.26 * sane_px(window_w) / s).clamp(210.0, 290.0) * s).round()
}

/// The drawer's width: the side dock's, but leaving at least a row's width
/// of the world visible beside it.
pub fn drawer_width(window_w: f32, scale: f32) -> f32 {
    let w = sane_px(window_w);
    side_width(w, scale).min(w - row_px(scale)).max(0.0)
}

/// The height an open tab's content wants: with its tab row, 22 % of the
/// window's height, within 130 to 280 points.
pub fn tab_wanted(window_h: f32, scale: f32) -> f32 {
    let s = clamp_scale(scale);
    (0.22 * sane_px(window_h)).clamp(130.0 * s, 280.0 * s) - row_px(s)
}

/// Lays the screen out; see the module's documentation. Never panics.
pub fn layout(window: (f32, f32), scale: f32, docks: Docks) -> Rects {
    let s = clamp_scale(scale);
    let (w, h) = (sane_px(window.0), sane_px(window.1));
    let row = row_px(s);
    let top_h = row.min(h);
    let caption_h = row.min(h - top_h);
    let tabs_h = if docks.shown { row } else { 0.0 }.min(h - top_h - caption_h);
    // What the world and the tab content share.
    let room = h - top_h - caption_h - tabs_h;
    let (wanted, min_tab) = (tab_wanted(h, s), MIN_TAB_ROWS * row);
    // The tab content a world `world_w` wide leaves room for, if not too little.
    let grant = |world_w: f32| {
        let share = MIN_WORLD_SHARE * w * h / world_w.max(f32::MIN_POSITIVE);
        let granted = wanted
            .min(room - MIN_WORLD_PX.max(share) + SLACK_PX)
            .floor();
        (granted >= min_tab).then_some(granted)
    };
    // Decided as if a tab were open, so that opening one never undocks it.
    let side_w = side_width(w, s);
    let fits = s <= MAX_DOCKED_SCALE && w - side_w >= MIN_WORLD_PX && grant(w - side_w).is_some();
    let side_dock = match (docks.shown && docks.side, fits) {
        (false, _) => SideDock::Hidden,
        (true, true) => SideDock::Docked,
        (true, false) => SideDock::Drawer {
            open: docks.drawer_open,
        },
    };
    let side =
        (side_dock == SideDock::Docked).then(|| Rect::new(w - side_w, top_h, side_w, h - top_h));
    let left_w = side.map_or(w, |r| r.x);
    let tab_open = docks.shown && docks.tab_open;
    let content_h = grant(left_w).filter(|_| tab_open).unwrap_or(0.0);
    let world = Rect::new(0.0, top_h, left_w, room - content_h);
    let caption = Rect::new(0.0, world.bottom(), left_w, caption_h);
    let content = Rect::new(0.0, caption.bottom(), left_w, content_h);
    let drawer_w = drawer_width(w, s);
    Rects {
        window: Rect::new(0.0, 0.0, w, h),
        top_bar: Rect::new(0.0, 0.0, w, top_h),
        side,
        drawer: (side_dock == SideDock::Drawer { open: true })
            .then(|| Rect::new(w - drawer_w, top_h, drawer_w, h - top_h)),
        side_dock,
        tab_row: docks
            .shown
            .then(|| Rect::new(0.0, content.bottom(), left_w, tabs_h)),
        tab_content: (content_h > 0.0).then_some(content),
        tab_folded: tab_open && content_h == 0.0,
        caption,
        world,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCALES: [f32; 4] = [1.0, 1.5, 2.0, 2.5];
    const SHOWN: u8 = 1;
    const SIDE: u8 = 2;
    const TAB: u8 = 4;
    const DRAWER: u8 = 8;
    const OPEN_TAB: u8 = SHOWN | SIDE | TAB;

    fn docks(bits: u8) -> Docks {
        let [shown, side, tab_open, drawer_open] =
            [SHOWN, SIDE, TAB, DRAWER].map(|b| bits & b != 0);
        Docks {
            shown,
            side,
            tab_open,
            drawer_open,
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
        scaled.flat_map(|(w, h, s)| (0..16).map(move |b| (w, h, s, b)))
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
                let (docked, room) = (w - side_width(w, s), h - 3.0 * row);
                let fits = docked >= MIN_WORLD_PX && room - min_tab >= need(docked);
                assert!(!fits, "{what}");
            }
            // The bars are one row, whatever their content.
            assert_eq!((r.top_bar.h, r.caption.h), (row, row), "{what}");
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
                for b in 0..16 {
                    let r = layout((w, h), s, docks(b));
                    assert_tiles(&r, &format!("{w}x{h} at {s} {:?}", docks(b)));
                }
            }
        }
        assert_eq!((clamp_scale(nan), clamp_scale(inf)), (1.0, 2.5));
    }
}
