//! The *Collisions* tab: the impacts counted (between discs and with walls,
//! as the top bar counts them), the last ones kept, newest first, and the
//! newest before and after, disc by disc. Side by side where the dock is
//! wide, one under the other where it is narrow; nothing overlaps.

use super::super::dialog::{page, scroll};
use super::super::widgets::command_button;
use super::super::{Cx, View};
use super::pinned_header::HeaderRow;
use crate::app::lang::tr;
use crate::app::model::lesson::{count_line, LEDGER_KEEP};
use crate::app::model::Command;
use crate::app::numbers::{disc_number, plain, vector, with_unit};
use crate::app::ui::tip::Tip;
use glam::DVec2;
use impulse::ledger::Impact;

/// The tab (no state of its own).
pub struct Collisions;

/// Below this width (points) the list and the newest impact stack.
const SIDE_BY_SIDE: f32 = 760.0;
/// Room kept for a scroll bar beside the table, in points.
const SCROLL_BAR: f32 = 16.0;
/// Room before a disc's row name for its colour's dot (points).
const DOT_ROOM: f32 = 18.0;
/// The names of the newest impact's rows keep at least this share of the
/// width, wrapping, however wide the numbers.
const NAMES_AT_LEAST: f32 = 0.3;

/// "discs 1 and 2" or "disc 1 and the left wall".
fn who(impact: &Impact) -> String {
    match impact {
        Impact::Pair(c) => {
            let [a, b] = c.discs_in_order();
            tr!("ledger-pair", a = disc_number(a), b = disc_number(b))
        }
        Impact::Wall(w) => tr!(
            "ledger-wall",
            disc = disc_number(w.disc),
            wall = w.wall.name()
        ),
    }
}

impl View for Collisions {
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut Cx) {
        let model = cx.model;
        let world = &model.world;
        let recent: Vec<Impact> = world
            .ledger
            .impacts()
            .rev()
            .take(LEDGER_KEEP)
            .copied()
            .collect();
        let Some(newest) = recent.first() else {
            count(ui, cx);
            ui.add(egui::Label::new(tr!("ledger-empty")).wrap());
            return;
        };
        // Another scene: the ledger from its top (its rows had stayed
        // scrolled as in the scene before, the momenta out of sight).
        let seen = egui::Id::new("ledger_scene");
        let fresh = ui.data(|d| d.get_temp::<u32>(seen)) != Some(model.open.opened);
        ui.data_mut(|d| d.insert_temp(seen, model.open.opened));
        let area = || {
            let area = egui::ScrollArea::both().auto_shrink([false, true]);
            match fresh {
                true => area.scroll_offset(egui::Vec2::ZERO),
                false => area,
            }
        };
        if ui.available_width() >= SIDE_BY_SIDE {
            // The count over the list, so the newest impact's table starts
            // at the top: at a laptop's size its third row, the total
            // momentum, was cut off.
            ui.columns(2, |columns| {
                count(&mut columns[0], cx);
                columns[0].strong(tr!("ledger-last", count = recent.len()));
                scroll(&mut columns[0], cx, area(), "ledger_list", |ui, cx| {
                    list(ui, cx, &recent)
                });
                scroll(&mut columns[1], cx, area(), "ledger_detail", |ui, cx| {
                    detail(ui, cx, newest)
                });
            });
        } else {
            // The newest impact first, and the count with its key to the
            // next under it: at a projector the tab holds four rows, and
            // under the count the two discs' total momentum was out of sight.
            // One page, scrolled as one: in areas of their own the wheel
            // scrolled the newest impact's rows to their end before the
            // page, and the list had the two rows left under the count.
            page(ui, cx, area(), "ledger_stacked", |ui, cx| {
                detail(ui, cx, newest);
                count(ui, cx);
                ui.separator();
                ui.strong(tr!("ledger-last", count = recent.len()));
                list(ui, cx, &recent);
            });
        }
    }
}

/// The impacts counted, as the top bar counts them, and the key to the next.
fn count(ui: &mut egui::Ui, cx: &mut Cx) {
    ui.horizontal_wrapped(|ui| {
        let r = ui.label(count_line(&cx.model.world));
        cx.note("ledger_count", &r);
        command_button(
            ui,
            cx,
            Command::NextCollision,
            Some("next_collision_in_tab"),
        );
    });
}

/// The kept impacts, newest first.
fn list(ui: &mut egui::Ui, cx: &mut Cx, recent: &[Impact]) {
    let mut header = HeaderRow::default();
    let table = egui::Grid::new("ledger")
        .striped(true)
        .num_columns(4)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            for (h, hover) in [
                ("t (s)".to_string(), tr!("ledger-time-hover")),
                (tr!("ledger-what"), tr!("ledger-what-hover")),
                ("Δp (kg·m/s)".to_string(), tr!("ledger-dp-hover")),
                (
                    format!("Δ{} (J)", tr!("symbol-ke")),
                    tr!("ledger-dke-hover"),
                ),
            ] {
                let r = ui.strong(h.as_str()).tip(hover);
                header.add(&r, h);
            }
            ui.end_row();
            for impact in recent {
                let (dp, dke) = impact.total_change();
                ui.label(plain(impact.time(), 3));
                ui.label(who(impact));
                ui.label(vector(dp, 3, ""));
                ui.label(plain(dke, 3));
                ui.end_row();
            }
        })
        .response;
    header.keep_in_sight(ui, cx, "ledger_list_header_pinned", table.rect);
}

/// The newest impact, before and after: each quantity for one disc and the
/// other, and for a pair their total (the lesson: p stays, KE stays when
/// elastic). Who and when (when alone for a pair, where both take two
/// lines) name the table's first column, not a line above it, which at a
/// projector had left room for the column names only and no row.
fn detail(ui: &mut egui::Ui, cx: &mut Cx, impact: &Impact) {
    // Never "t =" on one line and "1.784 s" on the next.
    let when = format!("t = {}", with_unit(impact.time(), 3, "s")).replace(' ', "\u{a0}");
    let heading = tr!("ledger-newest", who = who(impact), when = when.as_str());
    // (name, before, after, the name a total's row is noted under, the
    // colour of the disc it is about).
    type Row<'a> = (
        String,
        String,
        String,
        Option<&'a str>,
        Option<egui::Color32>,
    );
    let mut rows: Vec<Row> = Vec::new();
    let (world, overlays) = (&cx.model.world, &cx.model.overlays);
    let colour = |disc: usize| {
        let c = (disc < world.particles.len()).then(|| overlays.disc_color(world, disc))?;
        Some(egui::Color32::from_rgb(c.r, c.g, c.b))
    };
    let row = |disc: usize, name, (b, a): (String, String)| (name, b, a, None, colour(disc));
    let pair_of = |(b, a): (DVec2, DVec2)| (vector(b, 3, ""), vector(a, 3, ""));
    let plain_pair = |(b, a): (f64, f64)| (plain(b, 3), plain(a, 3));
    // A velocity's parts before and after, along the line of impact (at a
    // wall: away from it) and across it.
    type Split = ((f64, f64), (f64, f64));
    let along: fn(Split) -> (f64, f64) = |((n0, _), (n1, _))| (n0, n1);
    let across: fn(Split) -> (f64, f64) = |((_, t0), (_, t1))| (t0, t1);
    let ke = tr!("symbol-ke");
    match impact {
        Impact::Pair(c) => {
            // Lowest disc first, as the heading names them.
            let discs = if c.discs[0] <= c.discs[1] {
                [0, 1]
            } else {
                [1, 0]
            };
            for k in discs {
                rows.push(row(
                    c.discs[k],
                    tr!("ledger-disc-p", disc = disc_number(c.discs[k])),
                    pair_of(c.momentum(k)),
                ));
            }
            let (p0, p1) = (c.momentum(0), c.momentum(1));
            let total = pair_of((p0.0 + p1.0, p0.1 + p1.1));
            rows.push((
                tr!("ledger-both-p"),
                total.0,
                total.1,
                Some("ledger_total_p"),
                None,
            ));
            for k in discs {
                let name = tr!(
                    "ledger-disc-ke",
                    disc = disc_number(c.discs[k]),
                    ke = ke.as_str()
                );
                rows.push(row(c.discs[k], name, plain_pair(c.kinetic_energy(k))));
            }
            let (e0, e1) = (c.kinetic_energy(0), c.kinetic_energy(1));
            let total = plain_pair((e0.0 + e1.0, e0.1 + e1.1));
            let name = tr!("ledger-both-ke", ke = ke.as_str());
            rows.push((name, total.0, total.1, Some("ledger_total_ke"), None));
            for (part, of) in [
                (tr!("ledger-along-impact"), along),
                (tr!("ledger-across-impact"), across),
            ] {
                for k in discs {
                    let name = tr!(
                        "ledger-disc-v",
                        disc = disc_number(c.discs[k]),
                        part = part.as_str()
                    );
                    rows.push(row(c.discs[k], name, plain_pair(of(c.components(k)))));
                }
            }
        }
        Impact::Wall(w) => {
            let d = w.disc;
            rows.push(row(
                d,
                tr!("ledger-disc-p", disc = disc_number(d)),
                pair_of(w.momentum()),
            ));
            let name = tr!("ledger-disc-ke", disc = disc_number(d), ke = ke.as_str());
            rows.push(row(d, name, plain_pair(w.kinetic_energy())));
            for (part, of) in [
                (tr!("ledger-away-from-wall"), along),
                (tr!("ledger-along-wall"), across),
            ] {
                let name = tr!("ledger-disc-v", disc = disc_number(d), part = part.as_str());
                rows.push(row(d, name, plain_pair(of(w.components()))));
            }
            let push = vector(w.wall_impulse(), 3, "");
            rows.push((tr!("ledger-wall-push"), String::new(), push, None, None));
        }
    }
    // The names wrap before the numbers are pushed out of sight: at a
    // projector's size "disc 1: v along the line of impact (m/s)" took the
    // width, and the after column was cut off.
    let (before, after) = (tr!("ledger-before"), tr!("ledger-after"));
    let font = egui::TextStyle::Body.resolve(ui.style());
    let widest = |texts: &mut dyn Iterator<Item = &String>| {
        texts
            .map(|t| {
                ui.fonts(|f| f.layout_no_wrap(t.clone(), font.clone(), egui::Color32::WHITE))
                    .size()
                    .x
            })
            .fold(0.0, f32::max)
    };
    let numbers = widest(
        &mut rows
            .iter()
            .flat_map(|(_, b, a, _, _)| [b, a])
            .chain([&before, &after]),
    );
    let spacing = 18.0;
    let names = (ui.available_width() - 2.0 * (numbers + spacing) - SCROLL_BAR)
        .max(NAMES_AT_LEAST * ui.available_width());
    // Who and when on one line, or when alone where that would take two:
    // a pair's rows name both discs, and at a projector in German the
    // second line had pushed the total momentum out of sight.
    let heading = if matches!(impact, Impact::Pair(_))
        && widest(&mut std::iter::once(&heading)) > names.max(numbers)
    {
        when
    } else {
        heading
    };
    // Rows as tall as their text, not as a button: at a projector the
    // heading and three rows (the discs' momenta and their total) fit.
    let line = ui.text_style_height(&egui::TextStyle::Body);
    let mut header = HeaderRow::default();
    let r = egui::Grid::new("ledger_newest")
        .striped(true)
        .num_columns(3)
        .min_row_height(line)
        .spacing([spacing, 4.0])
        .max_col_width(names.max(numbers))
        .show(ui, |ui| {
            let r = ui.add(egui::Label::new(egui::RichText::new(&heading).strong()).wrap());
            header.add(&r, heading);
            let r = ui.strong(&before);
            header.add(&r, before);
            let r = ui.strong(&after);
            header.add(&r, after);
            ui.end_row();
            for (what, before, after, total, dot) in rows {
                let strong = |text: String| egui::RichText::new(text).strong();
                let (what, before, after) = if total.is_some() {
                    (strong(what), strong(before), strong(after))
                } else {
                    (what.into(), before.into(), after.into())
                };
                // The disc's colour before its name, as in the Discs
                // tab: a student matches rows to discs by it. (A dot
                // painted in room left before the text: the font has
                // no "●".)
                let what: egui::WidgetText = match dot {
                    Some(_) => {
                        let mut job = egui::text::LayoutJob::default();
                        let font = egui::TextStyle::Body.resolve(ui.style());
                        let format = egui::TextFormat::simple(font, ui.visuals().text_color());
                        job.append(what.text(), DOT_ROOM, format);
                        job.into()
                    }
                    None => what.into(),
                };
                let r = ui.add(egui::Label::new(what).wrap());
                if let Some(c) = dot {
                    let centre = r.rect.left_top() + egui::vec2(0.4 * DOT_ROOM, 0.5 * line);
                    ui.painter().circle_filled(centre, 0.3 * DOT_ROOM, c);
                }
                if let Some(name) = total {
                    cx.note(name, &r);
                }
                ui.label(before);
                ui.label(after);
                ui.end_row();
            }
        })
        .response
        .tip(tr!("ledger-detail-hover"));
    // Its whole width (the dump shows whether any is cut off).
    cx.note("ledger_newest", &r);
    header.keep_in_sight(ui, cx, "ledger_header_pinned", r.rect);
}
