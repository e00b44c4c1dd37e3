//! How the screen looks, read by the panels and the world's drawing alike:
//! one UI scale for every text and control (F2 cycles 1.0, 1.5, 2.0, for the
//! back row of a classroom), one table of text sizes, and a dark and a light
//! (bright-room) theme with the world's colours and their names.

use egui::{Color32, FontFamily, FontId, TextStyle};

pub use crate::app::model::Theme;

/// The smallest text anywhere on screen at scale 1, in points (= pixels at
/// scale 1): 16, so scale 1.5 gives 24 px and the projector's 2.0 gives 32.
pub const MIN_TEXT_POINTS: f32 = 16.0;

/// The font the world's labels are drawn in, and the panels' last resort
/// for a character egui's own fonts lack (the minus of "10⁻¹² kg").
pub static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// egui's fonts with DejaVu Sans after them: a character none of egui's
/// has is drawn from it instead of as a box.
pub fn font_definitions() -> egui::FontDefinitions {
    let mut fonts = egui::FontDefinitions::default();
    let name = "DejaVu Sans".to_string();
    fonts.font_data.insert(
        name.clone(),
        std::sync::Arc::new(egui::FontData::from_static(DEJAVU_SANS)),
    );
    for family in [FontFamily::Proportional, FontFamily::Monospace] {
        fonts.families.entry(family).or_default().push(name.clone());
    }
    fonts
}

/// Text sizes (points) by egui's text styles; nothing on screen is drawn in
/// any other size but the world's labels, which use [`MIN_TEXT_POINTS`] and up.
pub fn text_sizes() -> [(TextStyle, f32); 5] {
    [
        (TextStyle::Small, MIN_TEXT_POINTS),
        (TextStyle::Body, 17.0),
        (TextStyle::Button, 17.0),
        (TextStyle::Monospace, MIN_TEXT_POINTS),
        (TextStyle::Heading, 21.0),
    ]
}

/// What the world is drawn in, per theme (RGBA, 0–1).
#[derive(Clone, Copy, Debug)]
pub struct WorldColors {
    pub background: [f32; 4],
    pub inside: [f32; 4],
    pub wall: [f32; 4],
    /// The rail of a one-dimensional scene: never the velocity's colour.
    pub rail: [f32; 4],
    pub velocity: [f32; 4],
    pub momentum: [f32; 4],
    /// The change of momentum in a collision.
    pub delta_p: [f32; 4],
    /// Drawn round the Δp arrows, so they read on every disc colour.
    pub outline: [f32; 4],
    /// The centre of mass's marker and arrow.
    pub center_of_mass: [f32; 4],
    /// The disc a launch will make, before it is let go.
    pub ghost: [f32; 4],
    pub selected: [f32; 4],
    pub text: [f32; 4],
    pub label_background: [f32; 4],
    pub leader: [f32; 4],
}

/// The names of the arrows' colours in a theme (messages of
/// `window.ftl`), for the labels that name them ("velocity arrows
/// (white)").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArrowNames {
    pub velocity: &'static str,
    pub momentum: &'static str,
    pub delta_p: &'static str,
}

/// The arrows' colour names in `theme`, matching [`world_colors`].
pub fn arrow_names(theme: Theme) -> ArrowNames {
    match theme {
        Theme::Dark => ArrowNames {
            velocity: "colour-white",
            momentum: "colour-pink",
            delta_p: "colour-amber-outlined",
        },
        Theme::Light => ArrowNames {
            velocity: "colour-black",
            momentum: "colour-purple",
            delta_p: "colour-brown-outlined",
        },
    }
}

/// The world's colours in `theme`.
pub fn world_colors(theme: Theme) -> WorldColors {
    match theme {
        Theme::Dark => WorldColors {
            background: [0.09, 0.10, 0.14, 1.0],
            inside: [1.0, 1.0, 1.0, 0.03],
            wall: [0.85, 0.88, 0.95, 1.0],
            rail: [0.45, 0.50, 0.60, 1.0],
            velocity: [1.0, 1.0, 1.0, 0.95],
            momentum: [1.0, 0.35, 0.75, 1.0],
            delta_p: [1.0, 0.78, 0.15, 1.0],
            outline: [0.0, 0.0, 0.0, 1.0],
            center_of_mass: [0.94, 0.89, 0.26, 1.0],
            ghost: [1.0, 1.0, 1.0, 0.35],
            selected: [1.0, 1.0, 1.0, 1.0],
            text: [1.0, 1.0, 1.0, 1.0],
            label_background: [0.03, 0.04, 0.07, 0.88],
            leader: [0.85, 0.88, 0.95, 0.8],
        },
        Theme::Light => WorldColors {
            background: [0.97, 0.97, 0.95, 1.0],
            inside: [1.0, 1.0, 1.0, 1.0],
            wall: [0.10, 0.10, 0.12, 1.0],
            rail: [0.60, 0.62, 0.68, 1.0],
            velocity: [0.05, 0.05, 0.08, 1.0],
            momentum: [0.75, 0.0, 0.45, 1.0],
            delta_p: [0.55, 0.30, 0.0, 1.0],
            outline: [1.0, 1.0, 1.0, 1.0],
            center_of_mass: [0.45, 0.38, 0.0, 1.0],
            ghost: [0.0, 0.0, 0.0, 0.3],
            selected: [0.0, 0.0, 0.0, 1.0],
            text: [0.0, 0.0, 0.0, 1.0],
            label_background: [1.0, 1.0, 1.0, 0.92],
            leader: [0.15, 0.15, 0.2, 0.8],
        },
    }
}

/// How the world is drawn this frame: the theme's colours, and the UI
/// scale for its text (lines keep their width in pixels).
#[derive(Clone, Copy, Debug)]
pub struct Look {
    pub colors: WorldColors,
    pub text_scale: f32,
}

impl Look {
    /// The look of `theme` at UI scale `text_scale`.
    pub fn of(theme: Theme, text_scale: f32) -> Look {
        Look {
            colors: world_colors(theme),
            text_scale,
        }
    }
}

/// A theme colour as macroquad's.
pub fn color(c: [f32; 4]) -> macroquad::color::Color {
    macroquad::color::Color::new(c[0], c[1], c[2], c[3])
}

/// Sets egui's device pixels per point (the screen's pixel density times
/// the UI scale), text sizes and colours.
pub fn apply(ctx: &egui::Context, pixels_per_point: f32, theme: Theme) {
    ctx.set_pixels_per_point(pixels_per_point);
    let (preference, mut visuals) = match theme {
        Theme::Dark => (egui::Theme::Dark, egui::Visuals::dark()),
        Theme::Light => (egui::Theme::Light, egui::Visuals::light()),
    };
    // High contrast: full white on dark, full black on light; no dim text.
    visuals.override_text_color = Some(match theme {
        Theme::Dark => Color32::from_gray(245),
        Theme::Light => Color32::BLACK,
    });
    if theme == Theme::Light {
        visuals.panel_fill = Color32::from_gray(250);
        visuals.widgets.noninteractive.bg_stroke.color = Color32::from_gray(120);
    }
    ctx.set_theme(preference);
    let mut style = (*ctx.style_of(preference)).clone();
    style.visuals = visuals;
    style.text_styles = text_sizes()
        .into_iter()
        .map(|(text_style, size)| {
            let family = if text_style == TextStyle::Monospace {
                FontFamily::Monospace
            } else {
                FontFamily::Proportional
            };
            (text_style, FontId::new(size, family))
        })
        .collect();
    style.spacing.interact_size.y = 24.0;
    style.spacing.item_spacing = egui::vec2(8.0, 5.0);
    style.spacing.slider_width = 130.0;
    // A list taller than its room shows a thin handle at rest, not only
    // under the pointer: a touch screen has no hover, and a start screen
    // whose last tiles are below the fold must say there is more.
    style.spacing.scroll.floating_width = 4.0;
    style.spacing.scroll.dormant_handle_opacity = 0.7;
    ctx.set_style_of(preference, style);
    // A wheel's notch scrolls a panel (the preset menu, the side dock) by a
    // line: on X11 miniquad reports a notch as 1, which egui-macroquad
    // divides by 90 (it expects Windows' 120), so egui's 40 points a line
    // came to 0.44 of a point and the wheel seemed not to scroll at all.
    if cfg!(all(target_os = "linux", not(target_arch = "wasm32"))) {
        ctx.options_mut(|o| o.line_scroll_speed = X11_LINE_SCROLL_POINTS);
    }
}

/// The widest a tooltip's text runs (points): egui's own 500, where the
/// window has the room.
const TOOLTIP_POINTS: f32 = 500.0;
/// What a tooltip leaves of the window each side, its frame included
/// (points).
const TOOLTIP_MARGIN_POINTS: f32 = 16.0;

/// Tooltips as wide as the window leaves, at most [`TOOLTIP_POINTS`]: a
/// window 512 points wide (1024 px at size 2) clipped egui's 500 points of
/// text plus its frame at the right edge. Once a frame: the window's width
/// changes with no new style.
pub fn fit_tooltips(ctx: &egui::Context) {
    let frame = ctx.style().spacing.menu_margin.sum().x;
    let room = ctx.screen_rect().width() - frame - 2.0 * TOOLTIP_MARGIN_POINTS;
    let width = room.clamp(100.0, TOOLTIP_POINTS);
    if (ctx.style().spacing.tooltip_width - width).abs() > 0.5 {
        ctx.style_mut(|s| s.spacing.tooltip_width = width);
    }
}

/// egui's 40 points a line, times egui-macroquad's divisor of 90.
const X11_LINE_SCROLL_POINTS: f32 = 40.0 * 90.0;

/// The smallest text size egui draws with now, in points.
pub fn min_text_points(ctx: &egui::Context) -> f32 {
    let smallest = ctx
        .style()
        .text_styles
        .values()
        .map(|f| f.size)
        .fold(f32::INFINITY, f32::min);
    smallest
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::model::next_scale;
    use crate::app::model::panels::UI_SCALES;
    use crate::app::ui::tip::Tip;

    #[test]
    fn f2_cycles_the_three_scales() {
        assert_eq!(next_scale(1.0), 1.5);
        assert_eq!(next_scale(1.5), 2.0);
        assert_eq!(next_scale(2.0), 1.0);
        assert_eq!(next_scale(1.2), 1.5, "from the slider's in-between value");
        assert_eq!(next_scale(2.5), 1.0);
    }

    #[test]
    fn no_text_style_is_below_the_minimum_and_the_projector_reaches_24_px() {
        for (style, size) in text_sizes() {
            assert!(size >= MIN_TEXT_POINTS, "{style:?}");
        }
        let (smallest, middle) = (MIN_TEXT_POINTS, MIN_TEXT_POINTS * UI_SCALES[1]);
        assert!(smallest >= 14.0 && middle >= 24.0, "{smallest} {middle}");
    }

    #[test]
    fn egui_takes_the_sizes_and_the_scale() {
        let ctx = egui::Context::default();
        for scale in UI_SCALES {
            for theme in [Theme::Dark, Theme::Light] {
                apply(&ctx, scale, theme);
                let _ = ctx.run(Default::default(), |_| {});
                assert_eq!(
                    min_text_points(&ctx) * ctx.pixels_per_point(),
                    MIN_TEXT_POINTS * scale,
                    "{scale} {theme:?}"
                );
            }
        }
    }

    /// The third review's case: at 1024×768 at size 2 (512 points) a long
    /// caption's tooltip was 1,026 px wide, its right edge clipped. A
    /// tooltip shown at the window's right edge lies wholly inside it, from
    /// a narrow window to a wide one.
    #[test]
    fn a_long_tooltip_lies_inside_the_window() {
        let long = "a long caption that runs on ".repeat(12);
        for width in [300.0, 512.0, 1280.0] {
            let ctx = egui::Context::default();
            apply(&ctx, 2.0, Theme::Dark);
            let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(width, 400.0));
            let mut tip = egui::Rect::NOTHING;
            // The window is made narrower after a first tooltip.
            for (k, w) in [1920.0, 1920.0, width, width].into_iter().enumerate() {
                let input = egui::RawInput {
                    time: Some(k as f64 * 0.1),
                    screen_rect: Some(egui::Rect::from_min_size(
                        egui::Pos2::ZERO,
                        egui::vec2(w, 400.0),
                    )),
                    ..Default::default()
                };
                let _ = ctx.run(input, |ctx| {
                    fit_tooltips(ctx);
                    egui::CentralPanel::default().show(ctx, |ui| {
                        ui.with_layout(egui::Layout::right_to_left(egui::Align::Max), |ui| {
                            ui.label("caption").tip_now(long.as_str());
                        });
                    });
                });
                tip = ctx.memory(|m| {
                    m.layer_ids()
                        .filter(|l| l.order == egui::Order::Tooltip)
                        .filter_map(|l| m.area_rect(l.id))
                        .fold(egui::Rect::NOTHING, |a, b| a.union(b))
                });
            }
            assert!(tip.width() > 50.0, "{width}: no tooltip {tip:?}");
            assert!(
                screen.contains_rect(tip),
                "{width}: the tooltip {tip:?} leaves the window {screen:?}"
            );
        }
    }

    /// A list taller than its room shows its scroll handle with no pointer
    /// over it (a touch screen has no hover); the list that fits shows none.
    #[test]
    fn a_list_taller_than_its_room_shows_its_handle_at_rest() {
        let handles = |rows: usize| {
            let ctx = egui::Context::default();
            apply(&ctx, 1.0, Theme::Dark);
            let mut shapes = Vec::new();
            let mut area = egui::Rect::NOTHING;
            for k in 0..3 {
                let input = egui::RawInput {
                    time: Some(f64::from(k) * 0.1),
                    screen_rect: Some(egui::Rect::from_min_size(
                        egui::Pos2::ZERO,
                        egui::vec2(400.0, 300.0),
                    )),
                    ..Default::default()
                };
                let out = ctx.run(input, |ctx| {
                    egui::CentralPanel::default().show(ctx, |ui| {
                        let r = egui::ScrollArea::vertical()
                            .auto_shrink(false)
                            .max_height(150.0)
                            .show(ui, |ui| {
                                for row in 0..rows {
                                    ui.label(format!("row {row}"));
                                }
                            });
                        area = r.inner_rect;
                    });
                });
                shapes = ctx.tessellate(out.shapes, 1.0);
            }
            // Painted near the area's right edge, narrow and tall: a handle.
            shapes
                .iter()
                .filter_map(|c| match &c.primitive {
                    egui::epaint::Primitive::Mesh(m) => Some(m),
                    _ => None,
                })
                .filter(|m| {
                    let b = m.calc_bounds();
                    let seen = m.vertices.iter().any(|v| v.color.a() > 40);
                    seen && b.width() <= 8.0
                        && b.height() >= 10.0
                        && b.right() >= area.right() - 12.0
                        && b.right() <= area.right() + 12.0
                })
                .count()
        };
        assert!(handles(60) > 0, "no handle on a list of 60 rows at rest");
        assert_eq!(handles(3), 0, "a handle on a list that fits");
    }
}
