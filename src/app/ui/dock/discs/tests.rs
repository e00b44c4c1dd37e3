//! The Discs table laid out by egui without a window.
use super::DiscsTable;
use crate::app::model::tests::sandbox_with;
use crate::app::ui::widgets::{shapes_drawn, texts_drawn};

/// The table numbers its rows from 1, as the messages, the ledger and
/// the column kept in sight when it scrolls do: it showed 0 and 1 where
/// the strip said "Disc 1: mass = 3 kg" of the first row.
#[test]
fn the_rows_are_numbered_from_one() {
    let dir = tempfile::tempdir().unwrap();
    let model = sandbox_with(dir.path(), "preset-1-head-on.toml", true, 0.0);
    assert_eq!(model.world.particles.len(), 2);
    let mut table = DiscsTable::default();
    let texts = texts_drawn(&model, egui::vec2(900.0, 300.0), &mut table);
    let count = |number: &str| texts.iter().filter(|t| *t == number).count();
    assert!(count("1") >= 1 && count("2") >= 1, "{texts:?}");
    assert_eq!(count("0"), 0, "{texts:?}");
}

/// A disc selected in the world has its row scrolled into sight: a
/// review's student found disc 27 highlighted only after scrolling.
#[test]
fn the_selected_discs_row_is_scrolled_into_sight() {
    let dir = tempfile::tempdir().unwrap();
    let mut model = sandbox_with(dir.path(), "preset-8-gas.toml", true, 0.0);
    let last = model.world.particles.len() - 1;
    assert!(last > 50, "{last}");
    model.selected = Some(last);
    let mut table = DiscsTable::default();
    let texts = texts_drawn(&model, egui::vec2(900.0, 300.0), &mut table);
    let number = (last + 1).to_string();
    assert!(texts.contains(&number), "{number} not in {texts:?}");
    assert!(
        !texts.contains(&"1".to_string()),
        "the first row still in sight"
    );
}

/// With the colour-blind-safe palette on, each row's dot has the
/// colour its disc is drawn in: the table, the ledger and the Momenta
/// diagram had kept the scene's colours.
#[test]
fn the_rows_dots_have_the_discs_colours_with_the_safe_palette_too() {
    let dir = tempfile::tempdir().unwrap();
    let mut model = sandbox_with(dir.path(), "preset-9-billiards.toml", true, 0.0);
    let scene: Vec<_> = model.world.particles.iter().map(|p| p.color).collect();
    let recoloured = (0..scene.len()).any(|i| impulse::Color::palette(i) != scene[i]);
    assert!(recoloured, "the scene's colours are the palette's: no test");
    for safe in [false, true] {
        model.overlays.safe_palette = safe;
        let dots: Vec<egui::Color32> = shapes_drawn(
            &model,
            egui::vec2(900.0, 2000.0),
            &mut DiscsTable::default(),
        )
        .into_iter()
        .filter_map(|shape| match shape {
            egui::Shape::Circle(c) if c.radius == 7.0 => Some(c.fill),
            _ => None,
        })
        .collect();
        assert!(dots.len() >= 3, "{} dots", dots.len());
        for (i, fill) in dots.iter().enumerate() {
            let c = model.overlays.disc_color(&model.world, i);
            assert_eq!(*fill, egui::Color32::from_rgb(c.r, c.g, c.b), "disc {i}");
            let expected = if safe {
                impulse::Color::palette(i)
            } else {
                scene[i]
            };
            assert_eq!(c, expected, "disc {i}, safe palette {safe}");
        }
    }
}

/// A refused cell stays open in red with what was typed, until its
/// refusal goes: a reset took the refusal away, but "1" stayed red in
/// v_y, a value the disc never had, with the note "v_y must be 0" beside.
#[test]
fn a_refused_cell_closes_when_a_reset_takes_its_refusal_away() {
    use crate::app::model::command::{Command, EditPlace};
    let dir = tempfile::tempdir().unwrap();
    let mut model = sandbox_with(dir.path(), "preset-1-head-on.toml", true, 0.0);
    let mut table = DiscsTable::default();
    let cell = super::CellEdit {
        disc: 0,
        field: 3,
        text: "1".into(),
    };
    let mut text: [Option<String>; 6] = Default::default();
    text[cell.field] = Some(cell.text.clone());
    model.apply(Command::EditDisc {
        disc: 0,
        text,
        from: EditPlace::Table,
    });
    assert!(
        model.messages.table.as_ref().is_some_and(|n| n.error),
        "on the line, v_y is refused"
    );
    table.sent = Some((cell.clone(), false));
    texts_drawn(&model, egui::vec2(900.0, 300.0), &mut table);
    assert_eq!(
        table.editing,
        Some(cell),
        "refused: open with what was typed"
    );
    model.apply(Command::Reset);
    assert_eq!(
        model.messages.table, None,
        "the reset took the refusal away"
    );
    texts_drawn(&model, egui::vec2(900.0, 300.0), &mut table);
    assert_eq!(table.editing, None, "and the cell with it");
}

/// On a rail the momentum column is signed along it, so that it adds up
/// to the top bar's total (light hits heavy: −2.455 + 5.455 = 3, where
/// |p| made 7.91); in a plane it stays |p|.
#[test]
fn on_a_rail_the_momentum_column_adds_up_to_the_total() {
    let dir = tempfile::tempdir().unwrap();
    let mut model = sandbox_with(dir.path(), "preset-3-light-hits-heavy.toml", true, 0.0);
    assert!(model.world.laws.constrain.is_some());
    model.apply(crate::app::model::Command::NextCollision);
    let total: f64 = model.world.particles.iter().map(|p| p.momentum().x).sum();
    let mut table = DiscsTable::default();
    let texts = texts_drawn(&model, egui::vec2(1400.0, 300.0), &mut table);
    assert!(texts.iter().any(|t| t == "p_x (kg·m/s)"), "{texts:?}");
    let column: f64 = model
        .world
        .particles
        .iter()
        .map(|p| {
            let shown = crate::app::numbers::quantity(p.momentum().x, 3);
            assert!(texts.contains(&shown), "{shown} in {texts:?}");
            crate::app::numbers::parse(&shown).unwrap()
        })
        .sum();
    assert!((column - total).abs() < 2e-3, "{column} against {total}");
    assert!(model.world.particles.iter().any(|p| p.momentum().x < 0.0));
    let glancing = sandbox_with(dir.path(), "preset-4-glancing.toml", true, 0.0);
    let texts = texts_drawn(
        &glancing,
        egui::vec2(1400.0, 300.0),
        &mut DiscsTable::default(),
    );
    assert!(texts.iter().any(|t| t == "|p| (kg·m/s)"), "{texts:?}");
}
