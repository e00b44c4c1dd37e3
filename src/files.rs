//! Writing files so that a reader never sees half of one and a failure
//! leaves the old file intact.

use std::io::Write;
use std::path::Path;

/// Writes `bytes` to `path` through a temporary file in the same folder and
/// a rename. If anything fails (a full disk, a read-only folder), the
/// temporary file is removed and the old file is left as it was.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    replace(path, bytes, false)
}

#[cfg(not(target_arch = "wasm32"))]
/// [`write_atomically`], and the data is on the disk before the rename, so
/// that a power cut leaves either the old file or the new one, never an
/// empty one. For what the user must not lose: saves and the autosave.
pub fn write_durably(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    replace(path, bytes, true)
}

fn replace(path: &Path, bytes: &[u8], sync: bool) -> std::io::Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let written = std::fs::File::create(&tmp).and_then(|mut file| {
        file.write_all(bytes)?;
        if sync {
            file.sync_all()?;
        }
        Ok(())
    });
    written
        .and_then(|()| std::fs::rename(&tmp, path))
        .inspect_err(|_| {
            let _ = std::fs::remove_file(&tmp);
        })
}

/// A file written, as the window names it to the person: from the root of
/// the file system, since a folder named from the working directory
/// ("impulse-out/…") says nothing to someone who started the program from
/// a menu. In the browser, the download's own name.
pub fn shown(path: &Path) -> String {
    match cfg!(target_arch = "wasm32") {
        true => path.display().to_string(),
        false => std::path::absolute(path)
            .unwrap_or_else(|_| path.to_path_buf())
            .display()
            .to_string(),
    }
}

/// A file written, as a message names it: its name, then the folder it is
/// in as [`shown`] writes it. Where a message is cut short (a projector's
/// caption), what goes is the folder, not the name.
pub fn name_and_folder(path: &Path) -> (String, String) {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let folder = path.parent().map(shown).unwrap_or_default();
    (name, folder)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_named_from_the_root() {
        let shown = shown(Path::new("impulse-out/glancing-collision.toml"));
        assert!(Path::new(&shown).is_absolute(), "{shown}");
        assert!(
            shown.ends_with(&format!(
                "impulse-out{}glancing-collision.toml",
                std::path::MAIN_SEPARATOR
            )),
            "{shown}"
        );
    }

    #[test]
    fn a_message_names_the_file_then_its_folder_from_the_root() {
        let (name, folder) = name_and_folder(Path::new("impulse-out/glancing-collision.toml"));
        assert_eq!(name, "glancing-collision.toml");
        assert!(Path::new(&folder).is_absolute(), "{folder}");
        assert!(folder.ends_with("impulse-out"), "{folder}");
    }

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("scene.toml");
        write_durably(&path, b"old").unwrap();
        // A folder where the temporary file should go: the write fails.
        std::fs::create_dir(dir.path().join("scene.toml.tmp")).unwrap();
        assert!(write_durably(&path, b"new").is_err());
        assert_eq!(std::fs::read(&path).unwrap(), b"old");
        std::fs::remove_dir(dir.path().join("scene.toml.tmp")).unwrap();
        write_atomically(&path, b"new").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"new");
        let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(left.len(), 1, "only the file itself remains");
    }
}
