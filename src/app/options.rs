//! What a window is opened with: its command-line options, the scene
//! `--gas N` builds (named in every language), and the check that an output
//! file has a folder to go to.

use super::{lang, model};
#[cfg(not(target_arch = "wasm32"))]
use impulse::Scene;
use std::path::PathBuf;

/// Options for the window, from the command line.
#[derive(Clone, Debug, clap::Args)]
pub struct WindowOptions {
    /// Scene file to open (TOML); the built-in sandbox scene when absent.
    pub scene: Option<PathBuf>,
    /// Open a gas of N equal discs (periodic box, 30 % of the area covered)
    /// instead of a scene file: for trying large numbers of discs.
    #[arg(long, value_name = "N", conflicts_with = "scene", value_parser = crate::cli::gas_count)]
    pub gas: Option<usize>,
    /// Start paused.
    #[arg(long)]
    pub paused: bool,
    /// Physics time step in seconds [default: the scene's, else 1/240].
    #[arg(long, value_parser = crate::cli::positive_seconds)]
    pub dt: Option<f64>,
    /// Keep FILE updated with the state as JSON (rewritten atomically each frame).
    #[arg(long, value_name = "FILE")]
    pub dump_state: Option<PathBuf>,
    /// Save the last frame as a PNG when the window closes.
    #[arg(long, value_name = "FILE")]
    pub screenshot: Option<PathBuf>,
    /// Close the window after this many seconds of real time.
    #[arg(long, value_name = "SECONDS", value_parser = crate::cli::positive_seconds)]
    pub exit_after: Option<f64>,
    /// Folder for saved scenes (Ctrl+S); created when first needed.
    #[arg(long, value_name = "DIR", default_value = "impulse-out")]
    pub out: PathBuf,
    /// Write every frame's timings (frame, physics, drawing, presenting; ms)
    /// to FILE as CSV when the window closes, and their medians on stderr.
    #[arg(long, value_name = "FILE")]
    pub frame_stats: Option<PathBuf>,
    /// Seconds between autosaves of the sandbox to the recovery file, which
    /// the next start offers to restore if this window does not close
    /// normally; 0 turns autosave off.
    #[arg(long, value_name = "SECONDS", default_value_t = model::recovery::DEFAULT_EVERY,
          value_parser = crate::cli::non_negative_seconds)]
    pub autosave: f64,
    /// How the window looks.
    #[command(flatten)]
    pub look: LookOptions,
    /// Open straight on the scene, without the start screen's tiles (which
    /// a start without a scene file shows).
    #[arg(long)]
    pub no_start: bool,
    /// The window's language: en, es, fr, de or pt-BR (qps: a pseudo-language
    /// for layout checks) [default: the one chosen in View before, else the
    /// system's]. The command line and its messages stay English.
    #[arg(long, value_name = "LANG", value_parser = crate::cli::language)]
    pub lang: Option<lang::Lang>,
}

/// How the window looks: its size, the size of its text, its theme and its
/// edges.
#[derive(Clone, Debug, clap::Args)]
pub struct LookOptions {
    /// Window size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "1280x800", value_parser = crate::cli::window_size)]
    pub size: (i32, i32),
    /// Size of every text and control, 1 to 2.5 (F2 cycles 1, 1.5 and 2; 2 is
    /// for a projector); default: the size chosen before, else 1.
    #[arg(long, value_name = "SCALE", value_parser = crate::cli::ui_scale)]
    pub ui_scale: Option<f32>,
    /// Draw discs and lines without smoothing their edges (no
    /// multisampling). On a computer that draws in software, without a
    /// graphics driver, a frame then costs less than half as much.
    #[arg(long)]
    pub no_antialias: bool,
    /// Start in the light theme (for a projector in a bright room); without
    /// it, the theme chosen before, else dark.
    #[arg(long)]
    pub light: bool,
}

#[cfg(not(target_arch = "wasm32"))]
/// The scene `--gas N` opens: `impulse::presets::Gas` with N discs.
pub fn gas_scene(count: usize) -> (Scene, String) {
    let mut world = impulse::presets::Gas {
        count,
        ..Default::default()
    }
    .build();
    // Like a scene file without a [simulation] section: `auto` chooses
    // (the preset's fixed brute force would freeze the window at 10⁵ discs).
    world.method = impulse::method::Setting::Auto;
    world.broad_phase = impulse::method::Setting::Auto;
    world.substeps = impulse::method::Setting::Auto;
    let words = |lang: lang::Lang| {
        let words = lang::Words::new(lang);
        impulse::scene::SceneWords {
            name: Some(words.get("gas-name", &[("count", lang::Arg::Count(count as i64))])),
            description: Some(words.get(
                "gas-description",
                &[("count", lang::Arg::Count(count as i64))],
            )),
        }
    };
    let mut scene = Scene::from_world(&world, words(lang::Lang::En).name, None);
    scene.description = words(lang::Lang::En).description;
    for lang in &lang::Lang::SHIPPED[1..] {
        scene
            .translations
            .insert(lang.code().to_string(), words(*lang));
    }
    (scene, format!("--gas {count}"))
}

#[cfg(not(target_arch = "wasm32"))]
/// Refuses, before any window opens, an output file whose folder does not
/// exist or which is a folder itself (the window would only find out when it
/// writes, frame after frame).
pub fn writable_place(flag: &str, file: &std::path::Path) -> anyhow::Result<()> {
    let folder = match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => std::path::Path::new("."),
    };
    if !folder.is_dir() {
        anyhow::bail!("{flag} {}: no folder {}", file.display(), folder.display());
    }
    if file.is_dir() {
        anyhow::bail!("{flag} {}: is a folder, not a file", file.display());
    }
    Ok(())
}
