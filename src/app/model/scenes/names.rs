//! Saved files' names: a scene's name as a file name, the first free name
//! in a folder, and a file kept for the user (written on the desktop,
//! downloaded in the browser).

#[cfg(not(target_arch = "wasm32"))]
use crate::app::lang::tr;
#[cfg(not(target_arch = "wasm32"))]
use crate::files::write_durably;
use std::path::{Path, PathBuf};

/// A file name for saving a scene called `name`: its letters and digits,
/// in any script and lower case ("choc-frontal-masses-égales"), the rest
/// turned into single hyphens.
pub fn slug(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars().flat_map(char::to_lowercase) {
        if c.is_alphanumeric() {
            out.push(c);
        } else if !out.ends_with('-') && !out.is_empty() {
            out.push('-');
        }
    }
    let out = out.trim_end_matches('-').to_string();
    if out.is_empty() {
        "scene".into()
    } else {
        out
    }
}

/// The scene file a person typed, found: as typed, else (a name alone, as
/// the Save note gives it) in `saved_in`, the folder the window saves
/// into; either with `.toml` added where the name has no extension.
/// `None` when there is no such file.
pub fn find_scene_file(typed: &Path, saved_in: &Path) -> Option<PathBuf> {
    let mut places = vec![typed.to_path_buf()];
    if typed.is_relative() {
        places.push(saved_in.join(typed));
    }
    places
        .into_iter()
        .flat_map(|p| {
            let with_toml = p.extension().is_none().then(|| p.with_extension("toml"));
            std::iter::once(p).chain(with_toml)
        })
        .find(|p| p.is_file())
}

/// Keeps `bytes` for the user as `stem.ext`: on the desktop written into
/// `dir` (created if needed) under the first free name, atomically and
/// durably; in the browser downloaded. Returns the file, or why not.
#[cfg(not(target_arch = "wasm32"))]
pub fn keep_file(dir: &Path, stem: &str, ext: &str, bytes: &[u8]) -> Result<PathBuf, String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| {
            tr!(
                "file-cannot-create",
                folder = dir.display().to_string(),
                error = e.to_string()
            )
        })
        .and_then(|()| write_kept(free_file(dir, stem, ext), bytes))
}

/// Writes `bytes` to `path`, atomically and durably: the file, or why not.
#[cfg(not(target_arch = "wasm32"))]
pub fn write_kept(path: PathBuf, bytes: &[u8]) -> Result<PathBuf, String> {
    write_durably(&path, bytes)
        .map(|()| path.clone())
        .map_err(|e| {
            tr!(
                "file-cannot-write",
                file = path.display().to_string(),
                error = e.to_string()
            )
        })
}

/// Keeps `bytes` for the user as `stem.ext`: downloaded by the browser.
#[cfg(target_arch = "wasm32")]
pub fn keep_file(_dir: &Path, stem: &str, ext: &str, bytes: &[u8]) -> Result<PathBuf, String> {
    let name = format!("{stem}.{ext}");
    crate::web::download(&name, bytes);
    Ok(PathBuf::from(name))
}

/// Whether a file's stem is `stem` or one of [`free_file`]'s next ones
/// (`stem-2`, `stem-3`, …).
pub(super) fn named_after(file_stem: &str, stem: &str) -> bool {
    file_stem == stem
        || file_stem
            .strip_prefix(stem)
            .and_then(|rest| rest.strip_prefix('-'))
            .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()))
}

/// The first of `dir/stem.ext`, `dir/stem-2.ext`, … that does not exist.
pub fn free_file(dir: &Path, stem: &str, ext: &str) -> PathBuf {
    let mut path = dir.join(format!("{stem}.{ext}"));
    let mut k = 2;
    while path.exists() {
        path = dir.join(format!("{stem}-{k}.{ext}"));
        k += 1;
    }
    path
}
