//! The scene that is open, and what the person has made of it.

use super::Sandbox;
use impulse::{Scene, World};

/// The scene that is open: its file (name, caption, the discs as they
/// opened), where it came from, and whether its discs were edited since.
#[derive(Clone)]
pub struct OpenScene {
    pub scene: Scene,
    pub origin: String,
    /// The discs were edited since the scene opened: its caption may no
    /// longer hold.
    pub edited: bool,
    /// Something the person made (a launch, an edit, a law) has not been
    /// saved since: on the desktop, only then is the sandbox kept for
    /// recovery, and only then does the next start ask.
    pub unsaved: bool,
    /// The file this session last saved the scene as: saved again under
    /// the same name, the scene goes back into it (not into `-2`, `-3`).
    pub saved_to: Option<std::path::PathBuf>,
    /// Scenes opened so far (an undo back to one counts): the ledger's
    /// scroll starts again when it changes.
    pub opened: u32,
    /// The discs as the person last set them up (their last change: an
    /// edit, a launch, a law): a reset brings them back first, and only a
    /// second the scene as it opened. A teacher who set 2 kg, ran the
    /// collision and pressed R lost the 2 kg.
    pub setup: Option<World>,
    /// The start screen's lesson this scene was opened as: until its
    /// answer is seen, the strip asks the tile's question instead of
    /// giving the answer ([`Sandbox::lesson_question`]).
    pub lesson: Option<super::start::Tile>,
}

impl Sandbox {
    /// The record after the world went back to the person's set-up: the
    /// rewind keeps what led up to it, the Totals tab starts afresh there.
    pub(super) fn back_to_setup(&mut self) {
        let at = self.world.time;
        self.record.history.keep_before(at);
        self.record.history.record(&self.world);
        self.record.totals.restart(&self.world);
        if self.selected_disc().is_none() {
            self.selected = None;
        }
        self.pointer.cancel();
    }
}
