//! Scenes in a link: the scene file, deflated and in URL-safe base64, in the
//! page address's fragment (`#scene=…`), so a teacher can send a set-up to
//! a class as a link. The fragment never reaches a server. Only scenes up to
//! [`MAX_DISCS`] discs go into a link; larger ones are saved as a file.

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine;
use impulse::Scene;

/// Most discs a shared link carries (a few hundred: the link stays under
/// about 40 kB, which every browser and chat program passes on).
pub const MAX_DISCS: usize = 500;

/// The fragment's key.
const KEY: &str = "scene=";

/// Largest scene file a link may unpack to (bytes): a link cannot make the
/// page allocate without bound.
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
const MAX_UNPACKED: usize = 4 << 20;

/// The fragment (without `#`) that carries `scene`, or why it cannot.
pub fn fragment_for(scene: &Scene) -> Result<String, String> {
    let discs = scene.particles.len() + scene.fill.as_ref().map_or(0, |f| f.count);
    if discs > MAX_DISCS {
        return Err(crate::app::lang::tr!(
            "link-too-many-discs",
            discs = discs,
            most = MAX_DISCS
        ));
    }
    let packed = miniz_oxide::deflate::compress_to_vec(scene.to_toml().as_bytes(), 9);
    Ok(format!("{KEY}{}", URL_SAFE_NO_PAD.encode(packed)))
}

/// The scene a fragment carries: `None` when it carries none, an error in
/// words when it is damaged.
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub fn scene_in(fragment: &str) -> Option<Result<Scene, String>> {
    let packed = fragment.strip_prefix(KEY)?;
    Some(unpack(packed))
}

#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
fn unpack(packed: &str) -> Result<Scene, String> {
    let damaged = |why: String| crate::app::lang::tr!("link-damaged", error = why);
    let bytes = URL_SAFE_NO_PAD
        .decode(packed.trim())
        .map_err(|e| damaged(e.to_string()))?;
    let text = miniz_oxide::inflate::decompress_to_vec_with_limit(&bytes, MAX_UNPACKED)
        .map_err(|e| damaged(format!("{e:?}")))?;
    let text = String::from_utf8(text).map_err(|_| damaged("UTF-8".into()))?;
    Scene::parse(&text, &crate::app::lang::tr!("origin-shared-link")).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scene_goes_into_a_link_and_comes_back_the_same() {
        for file in impulse::catalogue::ALL {
            let scene = Scene::parse(file.text, file.path).unwrap();
            let world = scene.build(file.path).unwrap();
            let saved = Scene::from_world(&world, scene.name.clone(), scene.description.clone());
            match fragment_for(&saved) {
                Ok(fragment) => {
                    assert!(fragment.len() < 60_000, "{}: {}", file.path, fragment.len());
                    let back = scene_in(&fragment).unwrap().unwrap();
                    assert_eq!(back, saved, "{}", file.path);
                    let rebuilt = back.build("link").unwrap();
                    assert_eq!(rebuilt.state_hash(), world.state_hash(), "{}", file.path);
                }
                Err(e) => assert!(
                    world.particles.len() > MAX_DISCS && e.contains("file"),
                    "{e}"
                ),
            }
        }
    }

    #[test]
    fn damaged_or_foreign_fragments_are_told_apart() {
        assert!(scene_in("").is_none());
        assert!(scene_in("section-2").is_none());
        for bad in ["scene=%%%", "scene=AAAA", "scene="] {
            let e = scene_in(bad).unwrap().unwrap_err();
            assert!(
                e.contains("damaged") || e.contains("shared link"),
                "{bad}: {e}"
            );
        }
        // A link that unpacks to far more than any scene is refused.
        let bomb = miniz_oxide::deflate::compress_to_vec(&vec![b'#'; MAX_UNPACKED + 1], 9);
        let e = scene_in(&format!("scene={}", URL_SAFE_NO_PAD.encode(bomb)))
            .unwrap()
            .unwrap_err();
        assert!(e.contains("damaged"), "{e}");
    }
}
