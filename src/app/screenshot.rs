//! The window's frame saved as a PNG: where `--screenshot` asked when the
//! window closes, and into the output folder on F12 (in the browser, a
//! download), said in the window's language.

use super::model::Sandbox;
use crate::app::lang::tr;
use crate::files::write_atomically;
use macroquad::prelude::get_screen_data;
use std::path::Path;

/// A frame read back: width, height and RGBA rows bottom-up.
pub type ScreenImage = (u32, u32, Vec<u8>);

/// The window's frame as drawn so far (world and panels), read back from
/// the framebuffer; call it after the panels are drawn.
pub fn screen_image() -> ScreenImage {
    let image = get_screen_data();
    (u32::from(image.width), u32::from(image.height), image.bytes)
}

/// Saves an RGBA frame (rows bottom-up, as OpenGL reads them) as a PNG.
pub fn write_png(
    path: &Path,
    width: u32,
    height: u32,
    rgba_bottom_up: &[u8],
) -> std::io::Result<()> {
    write_atomically(path, &png_bytes(width, height, rgba_bottom_up)?)
}

/// An RGBA frame (rows bottom-up) encoded as a PNG.
pub fn png_bytes(width: u32, height: u32, rgba_bottom_up: &[u8]) -> std::io::Result<Vec<u8>> {
    let row = width as usize * 4;
    let rgb: Vec<u8> = rgba_bottom_up
        .chunks_exact(row)
        .rev()
        .flat_map(|line| line.chunks_exact(4).flat_map(|px| [px[0], px[1], px[2]]))
        .collect();
    let mut png = Vec::new();
    image::write_buffer_with_format(
        &mut std::io::Cursor::new(&mut png),
        &rgb,
        width,
        height,
        image::ColorType::Rgb8,
        image::ImageFormat::Png,
    )
    .map_err(std::io::Error::other)?;
    Ok(png)
}

/// Saves the last frame where `--screenshot` asked.
pub fn save_screenshot(path: &Path, image: &ScreenImage) {
    let (w, h, rgba) = image;
    match write_png(path, *w, *h, rgba) {
        Ok(()) => eprintln!("impulse: screenshot saved to {}", path.display()),
        Err(e) => eprintln!("impulse: cannot save screenshot {}: {e}", path.display()),
    }
}

/// Saves the frame F12 asked for and says where (in the browser:
/// downloads it).
pub fn save_screenshot_key(model: &mut Sandbox, image: &ScreenImage, path: &Path) {
    let (w, h, rgba) = image;
    let dir = path.parent().unwrap_or(Path::new("."));
    let stem = path.file_stem().unwrap_or_default().to_string_lossy();
    let saved = png_bytes(*w, *h, rgba)
        .map_err(|e| e.to_string())
        .and_then(|png| super::model::scenes::keep_file(dir, &stem, "png", &png));
    match saved {
        Ok(path) => {
            eprintln!("impulse: screenshot saved to {}", path.display());
            model.toast(if cfg!(target_arch = "wasm32") {
                tr!("screenshot-downloaded", file = crate::files::shown(&path))
            } else {
                // Its name alone, whole on a projector's one line: the
                // Scene section says where saves go.
                let (file, _) = crate::files::name_and_folder(&path);
                tr!("screenshot-saved", file = file)
            });
        }
        Err(e) => model.report(tr!("screenshot-not-saved", error = e)),
    }
}
