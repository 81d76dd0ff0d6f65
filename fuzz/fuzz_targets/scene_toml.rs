//! The scene parser on arbitrary text: it returns a scene or an error, never panics, and a
//! scene it accepts writes back to TOML that parses to the same scene.
#![no_main]

use libfuzzer_sys::fuzz_target;
use pressridge::scene::Scene;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(scene) = Scene::from_toml(text) {
        let again = Scene::from_toml(&scene.to_toml()).expect("a written scene parses");
        assert_eq!(again.to_toml(), scene.to_toml());
    }
});
