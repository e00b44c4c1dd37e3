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
//! +----------- caption strip (1 row, or 2 lines) ------+  drawer that   |
//! | tab content (what is granted; 0 if closed/folded) |  floats over   |
//! +---------------- tab row (1 row) ------------------+  the world)    |
//! +-------------------------------------------------------------------+
//! ```
//!
//! The tab content sits *above* the tab row, which stays at the window's
//! bottom: clicking a tab opens it without moving the tab under the pointer.
//! It wants [`tab_wanted`], or the height the user dragged its top edge to
//! ([`Docks::tab_height`]); either way it gets only what the world's
//! guarantees leave ([`tab_range`]).
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
//! What stays fixed: the top bar and tab row are one row each
//! ([`row_px`]), a function of the scale alone; the caption strip is one
//! row taller by a line for each line of caption beyond the first
//! ([`caption_px`] of [`Docks::caption_lines`]; the window's strip always
//! asks for [`MAX_CAPTION_LINES`], so no caption moves the world). Opening or closing a
//! tab, or the drawer, never moves the world's top, left or width, nor the
//! top bar, side dock or tab row; a tab moves only the world's bottom edge
//! (and the caption strip glued under it) by the tab content's height.

/// Height of a one-line bar (top bar, caption strip, tab row) at scale 1, in
/// points (px = points × scale): egui's interact height of 24 (set by the
/// theme; it holds one line of 17-point body text) + 2 + 2 of a panel's
/// frame margin + a 1-point separator, rounded up to 30.
pub const ROW_POINTS: f32 = 30.0;
/// A line of body text at scale 1, in points: what each line of a caption
/// beyond the first adds to its strip (17-point text takes 19).
pub const LINE_POINTS: f32 = 20.0;
/// The most lines a caption strip holds.
pub const MAX_CAPTION_LINES: u8 = 2;
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
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Docks {
    /// Docks shown at all (Tab hides them all).
    pub shown: bool,
    /// The side dock wanted (L closes it).
    pub side: bool,
    /// A tab of the bottom dock is open.
    pub tab_open: bool,
    /// The side dock's drawer is open (only matters when it is a drawer).
    pub drawer_open: bool,
    /// The tab content's height the user chose (px, by dragging its top
    /// edge), instead of [`tab_wanted`]; kept within [`tab_range`].
    pub tab_height: Option<f32>,
    /// Lines of text the caption strip holds: 1, or up to
    /// [`MAX_CAPTION_LINES`] for a long caption (anything else is taken as
    /// the nearest of those).
    pub caption_lines: u8,
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
    /// The strip under the world (scale bar, caption, message).
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

/// The caption strip's height in whole px: a row, and a line more for each
/// line of caption beyond the first (see [`Docks::caption_lines`]).
pub fn caption_px(scale: f32, lines: u8) -> f32 {
    let more = f32::from(lines.clamp(1, MAX_CAPTION_LINES) - 1);
    row_px(scale) + more * (LINE_POINTS * clamp_scale(scale)).round()
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

/// The heights (px) the open tab's content can take at this size and
/// scale, least and most: what [`Docks::tab_height`] is kept within. None
/// where the tab has to fold.
pub fn tab_range(window: (f32, f32), scale: f32, docks: Docks) -> Option<(f32, f32)> {
    let tallest = Docks {
        tab_open: true,
        tab_height: Some(MAX_WINDOW_PX),
        ..docks
    };
    let most = layout(window, scale, tallest).tab_content?.h;
    Some((MIN_TAB_ROWS * row_px(scale), most))
}

/// Lays the screen out; see the module's documentation. Never panics.
pub fn layout(window: (f32, f32), scale: f32, docks: Docks) -> Rects {
    let s = clamp_scale(scale);
    let (w, h) = (sane_px(window.0), sane_px(window.1));
    let row = row_px(s);
    let top_h = row.min(h);
    let caption_h = caption_px(s, docks.caption_lines).min(h - top_h);
    let tabs_h = if docks.shown { row } else { 0.0 }.min(h - top_h - caption_h);
    // What the world and the tab content share.
    let room = h - top_h - caption_h - tabs_h;
    let min_tab = MIN_TAB_ROWS * row;
    // Never below the least a tab has, so whether the side dock fits does
    // not depend on it.
    let wanted = docks
        .tab_height
        .map_or(tab_wanted(h, s), |v| sane_px(v).max(min_tab));
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
mod tests;
