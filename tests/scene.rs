//! Scene files: every shipped scene loads, bad files are refused with the
//! file and field named, and a saved world reloads bit for bit.

use impulse::{Scene, SceneError};

fn error_of(text: &str) -> String {
    match Scene::parse(text, "lab.toml").and_then(|s| s.build("lab.toml").map(|_| ())) {
        Ok(()) => panic!("accepted a bad scene:\n{text}"),
        Err(e) => e.to_string(),
    }
}

const WORLD: &str = "[world]\nsize = [10.0, 10.0]\n";

#[test]
fn every_shipped_scene_loads_and_builds() {
    for file in impulse::catalogue::ALL {
        let scene = Scene::parse(file.text, file.path).unwrap_or_else(|e| panic!("{e}"));
        let world = scene.build(file.path).unwrap_or_else(|e| panic!("{e}"));
        assert!(world.laws.size.min_element() > 0.0);
    }
}

#[test]
fn the_catalogue_is_every_file_in_assets_scenes_as_it_is_on_disk() {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut on_disk: Vec<String> = std::fs::read_dir(format!("{root}/assets/scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| format!("assets/scenes/{}", p.file_name().unwrap().to_str().unwrap()))
        .collect();
    on_disk.sort();
    let listed: Vec<&str> = impulse::catalogue::ALL.iter().map(|f| f.path).collect();
    assert_eq!(listed, on_disk, "a new scene file goes into the catalogue");
    for file in impulse::catalogue::ALL {
        let text = std::fs::read_to_string(format!("{root}/{}", file.path)).unwrap();
        assert_eq!(
            file.text, text,
            "{} is embedded as it is on disk",
            file.path
        );
        assert_eq!(impulse::catalogue::find(file.path), Some(&file));
    }
}

#[test]
fn bad_values_name_the_file_and_the_field() {
    let disc = |field: &str| {
        let mut fields = vec![
            ("pos", "[5.0, 5.0]"),
            ("vel", "[0.0, 0.0]"),
            ("mass", "1.0"),
            ("radius", "0.5"),
        ];
        let (name, value) = field.split_once('=').unwrap();
        fields.retain(|(n, _)| *n != name);
        fields.push((name, value));
        let body: Vec<String> = fields.iter().map(|(n, v)| format!("{n} = {v}")).collect();
        format!("{WORLD}[[particles]]\n{}\n", body.join("\n"))
    };
    for (field, needle) in [
        ("mass=-1.0", "particles[0].mass"),
        ("mass=0.0", "particles[0].mass"),
        ("mass=nan", "particles[0].mass"),
        ("radius=inf", "particles[0].radius"),
        ("radius=0.0", "particles[0].radius"),
        ("vel=[nan, 0.0]", "particles[0].vel"),
        ("pos=[0.2, 5.0]", "particles[0].pos"),
        ("pos=[50.0, 5.0]", "particles[0].pos"),
    ] {
        let text = disc(field);
        let msg = error_of(&text);
        // The message names the file, the line where the field is written
        // (it is the last line of the table) and the field.
        let line = text.lines().count();
        assert!(
            msg.starts_with(&format!("lab.toml, line {line}: {needle}")),
            "{field}: {msg}"
        );
    }
}

#[test]
fn overlapping_discs_are_refused() {
    let text = format!(
        "{WORLD}[[particles]]\npos = [5.0, 5.0]\nmass = 1.0\nradius = 0.5\n\
         [[particles]]\npos = [5.5, 5.0]\nmass = 1.0\nradius = 0.5\n"
    );
    let msg = error_of(&text);
    assert!(
        msg.contains("particles[1].pos") && msg.contains("overlaps particles[0]"),
        "{msg}"
    );
}

#[test]
fn syntax_errors_and_unknown_fields_give_the_line() {
    let msg = error_of("[world]\nsize = [10.0, 10.0\n");
    assert!(msg.contains("line 2"), "{msg}");
    // A syntax error reads as a sentence: the line, the parser's words, the
    // column and the line quoted; not the parser's picture of the line with
    // a caret under it, squashed onto one line ("| 3 | gravity … | ^ |").
    let msg = error_of("[world]\nsize = [16.0, 10.0\ngravity = [0, 0]\n");
    assert_eq!(
        msg,
        "lab.toml, line 3: invalid array; expected `]` (column 1: \"gravity = [0, 0]\")"
    );
    let long = format!("[world]\nsize = [1.0, 2.0] {}\n", "x".repeat(300));
    let msg = error_of(&long);
    assert!(
        msg.starts_with("lab.toml, line 2: ") && msg.contains("size = [1.0, 2.0] xxx"),
        "{msg}"
    );
    assert!(msg.chars().count() < 200 && msg.contains("…\")"), "{msg}");
    // What the parser expected, as one list.
    let msg = error_of("[world]\nsize = [1.0, 2.0]\nrestitution = 1.0.0\n");
    assert!(msg.contains("expected newline or `#`"), "{msg}");
    let msg = error_of("[world]\nsize = [10.0, 10.0]\nviscosity = 0.3\n");
    assert!(msg.contains("line 3") && msg.contains("viscosity"), "{msg}");
    let msg = error_of("[world]\nsize = [10.0, -1.0]\n");
    assert!(msg.contains("world.size"), "{msg}");
    let msg = error_of("[world]\nsize = [10.0, 10.0]\nrestitution = 1.5\n");
    assert!(msg.contains("world.restitution"), "{msg}");
    let msg = error_of("[world]\nsize = [10.0, 10.0]\n[[particles]]\npos = [5.0, 5.0]\nmass = 1.0\nradius = 0.5\ncolor = \"red\"\n");
    assert!(msg.contains("colour") && msg.contains("line"), "{msg}");
}

#[test]
fn rough_disc_values_out_of_range_are_refused_with_their_field() {
    for (line, field) in [
        (
            "tangential_restitution = 1.5",
            "world.tangential_restitution",
        ),
        (
            "tangential_restitution = -1.01",
            "world.tangential_restitution",
        ),
        (
            "wall_tangential_restitution = 2.0",
            "world.wall_tangential_restitution",
        ),
        ("friction = -0.1", "world.friction"),
        ("friction = nan", "world.friction"),
        ("friction = inf", "world.friction"),
    ] {
        let msg = error_of(&format!("{WORLD}{line}\n"));
        assert!(msg.contains(field), "{line}: {msg}");
    }
    for spin in ["nan", "inf", "-inf"] {
        let text = format!(
            "{WORLD}[[particles]]\npos = [5.0, 5.0]\nmass = 1.0\nradius = 0.5\nspin = {spin}\n"
        );
        let msg = error_of(&text);
        assert!(msg.contains("particles[0].spin"), "{spin}: {msg}");
    }
    // In range they load, and a spin is kept.
    let text = format!(
        "{WORLD}tangential_restitution = 0.5\nfriction = 0.3\n[[particles]]\npos = [5.0, 5.0]\nmass = 1.0\nradius = 0.5\nspin = -2.5\n"
    );
    let world = Scene::parse(&text, "a").unwrap().build("a").unwrap();
    assert_eq!(world.particles[0].spin, -2.5);
    assert_eq!(world.laws.friction, Some(0.3));
}

#[test]
fn an_overfull_fill_is_refused_not_looped_forever() {
    let text = format!("{WORLD}[fill]\ncount = 1000\nradius = [0.5, 0.5]\n");
    let msg = error_of(&text);
    assert!(msg.contains("fill") && msg.contains("too full"), "{msg}");
}

#[test]
fn a_missing_file_is_an_io_error_naming_it() {
    let err = Scene::load(std::path::Path::new("/no/such/scene.toml")).unwrap_err();
    assert!(matches!(err, SceneError::Io { .. }));
    assert!(err.to_string().contains("/no/such/scene.toml"));
}

#[test]
fn a_saved_world_reloads_bit_for_bit() {
    let text =
        format!("{WORLD}[fill]\ncount = 30\nseed = 9\nradius = [0.1, 0.4]\nspeed = [0.0, 3.0]\n");
    let mut world = Scene::parse(&text, "a").unwrap().build("a").unwrap();
    for _ in 0..500 {
        world.step(1e-3);
    }
    let saved = Scene::from_world(&world, Some("saved".into()), None).to_toml();
    let reloaded = Scene::parse(&saved, "saved")
        .unwrap()
        .build("saved")
        .unwrap();
    assert_eq!(reloaded.particles, world.particles);
    assert_eq!(reloaded.laws.restitution, world.laws.restitution);
    // Stepping both gives the same future.
    let (mut a, mut b) = (world.clone(), reloaded);
    b.time = a.time;
    b.steps = a.steps;
    for _ in 0..500 {
        a.step(1e-3);
        b.step(1e-3);
    }
    assert_eq!(a.state_hash(), b.state_hash());
}

#[test]
fn a_saved_pile_with_its_contacts_overlapping_reopens_exactly() {
    // Discs at rest in contact overlap a little: a save of a running pile
    // must reopen (autosave and recovery depend on it), while the same
    // overlap written by hand is still refused as a mistake.
    let file = impulse::catalogue::PRESET_0_PILE;
    let mut world = Scene::parse(file.text, file.path)
        .unwrap()
        .build(file.path)
        .unwrap();
    for _ in 0..1200 {
        world.step(1.0 / 240.0);
    }
    let saved = Scene::from_world(&world, None, None);
    assert!(
        saved.overlapping,
        "a settled pile has contacts that overlap"
    );
    let reloaded = Scene::parse(&saved.to_toml(), "saved")
        .unwrap()
        .build("saved")
        .unwrap();
    assert_eq!(reloaded.particles, world.particles);
    let by_hand = saved.to_toml().replace("overlapping = true\n", "");
    let refused = Scene::parse(&by_hand, "by hand").and_then(|s| s.build("by hand"));
    let e = refused
        .expect_err("an overlap written by hand is refused")
        .to_string();
    assert!(e.contains("overlaps"), "{e}");
    // A world without overlaps is saved without the flag.
    let spread = Scene::parse(WORLD, "spread")
        .unwrap()
        .build("spread")
        .unwrap();
    assert!(!Scene::from_world(&spread, None, None).overlapping);
}

#[test]
fn value_errors_give_the_line_of_the_field_too() {
    // Overlap: the second disc's `pos` line (line 8 of this text).
    let text = format!(
        "{WORLD}[[particles]]\npos = [5.0, 5.0]\nmass = 1.0\nradius = 0.5\n\
         [[particles]]\npos = [5.5, 5.0]\nmass = 1.0\nradius = 0.5\n"
    );
    assert_eq!(text.lines().nth(7), Some("pos = [5.5, 5.0]"));
    let msg = error_of(&text);
    assert!(msg.contains("lab.toml, line 8: particles[1].pos"), "{msg}");
    // A negative mass in the first disc: line 5.
    let text = format!("{WORLD}[[particles]]\npos = [5.0, 5.0]\nmass = -1.0\nradius = 0.5\n");
    assert_eq!(text.lines().nth(4), Some("mass = -1.0"));
    let msg = error_of(&text);
    assert!(msg.contains("line 5: particles[0].mass"), "{msg}");
    // A bad world value: its own line.
    let msg = error_of("[world]\nsize = [10.0, 10.0]\nrestitution = 1.5\n");
    assert!(msg.contains("line 3: world.restitution"), "{msg}");
}

/// A scene's own name and description in other languages: read, kept when
/// saved, and the scene's own where a language has none.
#[test]
fn translations_are_read_kept_and_fall_back_to_the_scenes_own() {
    let text = "name = \"Head-on\"\ndescription = \"Two discs\"\n\n[world]\nsize = [4.0, 4.0]\n\n\
                [translations.es]\nname = \"Choque frontal\"\n\n\
                [translations.pt-BR]\nname = \"Frontal\"\ndescription = \"Dois discos\"\n";
    let scene = impulse::Scene::parse(text, "test").unwrap();
    assert_eq!(scene.name_in("es"), Some("Choque frontal"));
    assert_eq!(
        scene.description_in("es"),
        Some("Two discs"),
        "no Spanish description"
    );
    assert_eq!(scene.description_in("pt-BR"), Some("Dois discos"));
    assert_eq!(scene.name_in("de"), Some("Head-on"), "no German at all");
    let again = impulse::Scene::parse(&scene.to_toml(), "again").unwrap();
    assert_eq!(again.translations, scene.translations);
    let bad = "[world]\nsize = [4.0, 4.0]\n\n[translations.es]\ntitle = \"x\"\n";
    let err = impulse::Scene::parse(bad, "bad").unwrap_err().to_string();
    assert!(err.contains("title"), "{err}");
}

/// Only regular files are read: a FIFO without a writer, a device and a
/// folder are refused at once, in one line.
#[cfg(unix)]
#[test]
fn only_regular_files_are_opened() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("scene.toml");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    let start = std::time::Instant::now();
    for (path, kind) in [
        (fifo.as_path(), "a FIFO"),
        (std::path::Path::new("/dev/zero"), "a device"),
        (dir.path(), "a folder"),
    ] {
        let err = Scene::load(path).unwrap_err().to_string();
        assert!(
            err.contains("not a regular file") && err.contains(kind),
            "{err}"
        );
        assert!(!err.contains('\n'), "{err}");
    }
    assert!(start.elapsed().as_secs_f64() < 1.0, "refused at once");
}

/// An error is one line of at most 300 characters whatever the input: a
/// file of one 8 MB line, nested arrays a hundred thousand deep.
#[test]
fn errors_are_one_short_line_whatever_the_input() {
    let nul = "\0".repeat(8 << 20);
    let deep = format!("x = {}{}", "[".repeat(100_000), "]".repeat(100_000));
    let long_string = format!("name = \"{}", "a".repeat(1 << 20));
    for text in [nul.as_str(), deep.as_str(), long_string.as_str()] {
        let err = Scene::parse(text, "big.toml").unwrap_err().to_string();
        assert!(
            err.chars().count() <= 300,
            "{} characters",
            err.chars().count()
        );
        assert!(!err.contains('\n'));
        assert!(err.starts_with("big.toml"), "names the file: {err}");
    }
}

/// What a scene would silently ignore is refused, saying what to write:
/// walls where there is no box, a velocity across a one-dimensional world.
#[test]
fn ignored_settings_are_refused_with_what_to_write() {
    let walls = "[world]\nsize = [4.0, 4.0]\nboundary = \"periodic\"\nwalls = [\"left\"]\n";
    let err = error_of(walls);
    assert!(
        err.contains("world.walls") && err.contains("boundary = \"box\""),
        "{err}"
    );
    let across =
        "[world]\nsize = [4.0, 4.0]\nconstrain = \"x\"\n\n[[particles]]\npos = [1.0, 2.0]\n\
                  vel = [1.0, 0.5]\nmass = 1.0\nradius = 0.2\n";
    let err = error_of(across);
    assert!(
        err.contains("particles[0].vel") && err.contains("vel = [vx, 0]"),
        "{err}"
    );
    // Saved from a world whose edges were opened, a scene reopens.
    let mut world = Scene::parse(
        "[world]\nsize = [4.0, 4.0]\nwalls = [\"left\"]\n",
        "pi.toml",
    )
    .unwrap()
    .build("pi.toml")
    .unwrap();
    world.laws.boundary = impulse::Boundary::Periodic;
    let saved = Scene::from_world(&world, None, None).to_toml();
    Scene::parse(&saved, "saved.toml").unwrap_or_else(|e| panic!("{e}"));
}

/// A value of the wrong type is named by its field and line, in plain words.
#[test]
fn a_type_error_names_its_field() {
    let text = "[world]\nsize = [4.0, 4.0]\n\n[fill]\ncount = -5\nradius = 0.1\nmass = 1.0\nspeed = 1.0\nseed = 1\n";
    let err = Scene::parse(text, "t.toml").unwrap_err().to_string();
    assert_eq!(
        err,
        "t.toml, line 5: fill.count: expected a whole number of at least 0, got -5"
    );
    let text = "[world]\nsize = [4.0, \"four\"]\n";
    let err = Scene::parse(text, "t.toml").unwrap_err().to_string();
    assert!(err.starts_with("t.toml, line 2: world.size"), "{err}");
}
