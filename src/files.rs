//! Writing files so that a reader never sees half of one and a failure
//! leaves the old file intact.

use std::path::Path;

/// Writes `bytes` to `path` through a temporary file in the same folder and
/// a rename.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}
