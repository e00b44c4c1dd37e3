//! Every scene file the program ships (`assets/scenes/`), embedded at
//! build time, so a build without a file system (a browser) has them too:
//! the window's presets, the stress suite's scenarios and the tests all take
//! their files from here.

/// One shipped scene file: where it lives in the repository, and its text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SceneFile {
    /// Path from the repository root, e.g. `assets/scenes/preset-1-head-on.toml`.
    pub path: &'static str,
    /// The file's text.
    pub text: &'static str,
}

macro_rules! scene_file {
    ($file:literal) => {
        SceneFile {
            path: concat!("assets/scenes/", $file),
            text: include_str!(concat!("../../../assets/scenes/", $file)),
        }
    };
}

/// `assets/scenes/default.toml`.
pub const DEFAULT: SceneFile = scene_file!("default.toml");
/// `assets/scenes/empty.toml`.
pub const EMPTY: SceneFile = scene_file!("empty.toml");
/// `assets/scenes/pi-blocks-1.toml`.
pub const PI_BLOCKS_1: SceneFile = scene_file!("pi-blocks-1.toml");
/// `assets/scenes/pi-blocks-10000.toml`.
pub const PI_BLOCKS_10000: SceneFile = scene_file!("pi-blocks-10000.toml");
/// `assets/scenes/pi-blocks-1000000.toml`.
pub const PI_BLOCKS_1000000: SceneFile = scene_file!("pi-blocks-1000000.toml");
/// `assets/scenes/preset-0-pile.toml`.
pub const PRESET_0_PILE: SceneFile = scene_file!("preset-0-pile.toml");
/// `assets/scenes/preset-1-head-on.toml`.
pub const PRESET_1_HEAD_ON: SceneFile = scene_file!("preset-1-head-on.toml");
/// `assets/scenes/preset-2-heavy-hits-light.toml`.
pub const PRESET_2_HEAVY_HITS_LIGHT: SceneFile = scene_file!("preset-2-heavy-hits-light.toml");
/// `assets/scenes/preset-3-light-hits-heavy.toml`.
pub const PRESET_3_LIGHT_HITS_HEAVY: SceneFile = scene_file!("preset-3-light-hits-heavy.toml");
/// `assets/scenes/preset-4-glancing.toml`.
pub const PRESET_4_GLANCING: SceneFile = scene_file!("preset-4-glancing.toml");
/// `assets/scenes/preset-5-inelastic.toml`.
pub const PRESET_5_INELASTIC: SceneFile = scene_file!("preset-5-inelastic.toml");
/// `assets/scenes/preset-6-cradle.toml`.
pub const PRESET_6_CRADLE: SceneFile = scene_file!("preset-6-cradle.toml");
/// `assets/scenes/preset-7-pi-blocks.toml`.
pub const PRESET_7_PI_BLOCKS: SceneFile = scene_file!("preset-7-pi-blocks.toml");
/// `assets/scenes/preset-8-gas.toml`.
pub const PRESET_8_GAS: SceneFile = scene_file!("preset-8-gas.toml");
/// `assets/scenes/preset-9-billiards.toml`.
pub const PRESET_9_BILLIARDS: SceneFile = scene_file!("preset-9-billiards.toml");
/// `assets/scenes/preset-empty.toml`.
pub const PRESET_EMPTY: SceneFile = scene_file!("preset-empty.toml");
/// `assets/scenes/preset-rough-gas.toml`.
pub const PRESET_ROUGH_GAS: SceneFile = scene_file!("preset-rough-gas.toml");
/// `assets/scenes/preset-spin-off-a-wall.toml`.
pub const PRESET_SPIN_OFF_A_WALL: SceneFile = scene_file!("preset-spin-off-a-wall.toml");
/// `assets/scenes/stress-bullet.toml`.
pub const STRESS_BULLET: SceneFile = scene_file!("stress-bullet.toml");
/// `assets/scenes/stress-collapse.toml`.
pub const STRESS_COLLAPSE: SceneFile = scene_file!("stress-collapse.toml");
/// `assets/scenes/stress-corner.toml`.
pub const STRESS_CORNER: SceneFile = scene_file!("stress-corner.toml");
/// `assets/scenes/stress-cradle.toml`.
pub const STRESS_CRADLE: SceneFile = scene_file!("stress-cradle.toml");
/// `assets/scenes/stress-degenerate.toml`.
pub const STRESS_DEGENERATE: SceneFile = scene_file!("stress-degenerate.toml");
/// `assets/scenes/stress-dense-start.toml`.
pub const STRESS_DENSE_START: SceneFile = scene_file!("stress-dense-start.toml");
/// `assets/scenes/stress-long-run.toml`.
pub const STRESS_LONG_RUN: SceneFile = scene_file!("stress-long-run.toml");
/// `assets/scenes/stress-mass-ratio.toml`.
pub const STRESS_MASS_RATIO: SceneFile = scene_file!("stress-mass-ratio.toml");
/// `assets/scenes/stress-pi-blocks.toml`.
pub const STRESS_PI_BLOCKS: SceneFile = scene_file!("stress-pi-blocks.toml");
/// `assets/scenes/stress-pile.toml`.
pub const STRESS_PILE: SceneFile = scene_file!("stress-pile.toml");
/// `assets/scenes/stress-pile-large.toml`.
pub const STRESS_PILE_LARGE: SceneFile = scene_file!("stress-pile-large.toml");
/// `assets/scenes/stress-pile-tall.toml`.
pub const STRESS_PILE_TALL: SceneFile = scene_file!("stress-pile-tall.toml");
/// `assets/scenes/stress-relaxation.toml`.
pub const STRESS_RELAXATION: SceneFile = scene_file!("stress-relaxation.toml");
/// `assets/scenes/stress-rough.toml`.
pub const STRESS_ROUGH: SceneFile = scene_file!("stress-rough.toml");
/// `assets/scenes/stress-three-discs.toml`.
pub const STRESS_THREE_DISCS: SceneFile = scene_file!("stress-three-discs.toml");

/// Every shipped scene file, in file-name order.
pub const ALL: [SceneFile; 33] = [
    DEFAULT,
    EMPTY,
    PI_BLOCKS_1,
    PI_BLOCKS_10000,
    PI_BLOCKS_1000000,
    PRESET_0_PILE,
    PRESET_1_HEAD_ON,
    PRESET_2_HEAVY_HITS_LIGHT,
    PRESET_3_LIGHT_HITS_HEAVY,
    PRESET_4_GLANCING,
    PRESET_5_INELASTIC,
    PRESET_6_CRADLE,
    PRESET_7_PI_BLOCKS,
    PRESET_8_GAS,
    PRESET_9_BILLIARDS,
    PRESET_EMPTY,
    PRESET_ROUGH_GAS,
    PRESET_SPIN_OFF_A_WALL,
    STRESS_BULLET,
    STRESS_COLLAPSE,
    STRESS_CORNER,
    STRESS_CRADLE,
    STRESS_DEGENERATE,
    STRESS_DENSE_START,
    STRESS_LONG_RUN,
    STRESS_MASS_RATIO,
    STRESS_PI_BLOCKS,
    STRESS_PILE_LARGE,
    STRESS_PILE_TALL,
    STRESS_PILE,
    STRESS_RELAXATION,
    STRESS_ROUGH,
    STRESS_THREE_DISCS,
];

/// The shipped file at `path` (as in [`SceneFile::path`]).
pub fn find(path: &str) -> Option<&'static SceneFile> {
    ALL.iter().find(|f| f.path == path)
}
