//! The window's side of the browser page around the canvas (a no-op on the
//! desktop, apart from letting go of what was said): the page's language
//! and title, the accessible mirror's controls (`model::mirror`) and what
//! they ask for, the lines for its `aria-live` region, and whether the
//! world has the keys (so that Shift+Tab can leave the canvas for the
//! mirror: no keyboard trap).

use super::lang::{self, Lang};
use super::model::{Command, Sandbox};

/// What the page was last told.
#[derive(Default)]
pub struct Page {
    language: Option<Lang>,
    mirror: String,
    world_keys: Option<bool>,
}

impl Page {
    /// The commands the mirror's controls gave since the last frame.
    pub fn commands(&mut self) -> Vec<Command> {
        #[cfg(target_arch = "wasm32")]
        return crate::web::take_mirror_uses()
            .into_iter()
            .filter_map(|(list, index)| super::model::mirror::Mirror::command(list, index as usize))
            .collect();
        #[cfg(not(target_arch = "wasm32"))]
        Vec::new()
    }

    /// After the frame's commands: tells the page what changed (its
    /// language and title, the mirror, the lines to say, whether the world
    /// has the keys).
    pub fn update(&mut self, model: &mut Sandbox, world_keys: bool) {
        let said = model.take_announcements();
        if !cfg!(target_arch = "wasm32") {
            return; // the desktop shows them in the In words tab
        }
        let now = lang::language();
        if self.language != Some(now) {
            self.language = Some(now);
            #[cfg(target_arch = "wasm32")]
            crate::web::set_page_language(now.code(), &lang::tr!("page-title"));
        }
        let mirror = serde_json::to_string(&model.mirror()).unwrap_or_default();
        if mirror != self.mirror {
            #[cfg(target_arch = "wasm32")]
            crate::web::set_mirror(&mirror);
            self.mirror = mirror;
        }
        for line in said {
            #[cfg(target_arch = "wasm32")]
            crate::web::say(&line);
            let _ = line;
        }
        if self.world_keys != Some(world_keys) {
            self.world_keys = Some(world_keys);
            #[cfg(target_arch = "wasm32")]
            crate::web::set_world_keys(world_keys);
        }
    }
}
