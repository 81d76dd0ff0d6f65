//! Failure behaviour (issue 16, docs/failure.md) of the library's inputs: campaign specs and
//! scene files it cannot honour are refused naming the key, never with a panic. (The command
//! line's failure behaviour is crates/cli/tests/failure.rs.)

mod common;

use common::*;
use pressridge::scene::Scene;
use std::path::Path;

#[test]
fn campaign_seeds_and_duplicate_axis_values_are_refused() {
    use pressridge::campaign::CampaignSpec;
    let e = CampaignSpec::from_toml("name = \"x\"\nseeds = 4294967295")
        .unwrap_err()
        .to_string();
    assert!(e.contains("seeds") && e.contains("[1, 1000]"), "{e}");
    let spec = CampaignSpec::from_toml(
        "name = \"x\"\nseeds = 1\n[[axis]]\nkey = \"contact.mu\"\nvalues = [0.4, 1.0, 0.4]",
    )
    .unwrap();
    let e = spec.plan(Path::new(".")).unwrap_err().to_string();
    assert!(
        e.contains("axis 0") && e.contains("0.4") && e.contains("twice"),
        "{e}"
    );
    let spec = CampaignSpec::from_toml(
        "name = \"x\"\nseeds = 1\n[[axis]]\nkey = \"contact.mu\"\nvalues = [0.4]\n[[axis]]\nkey = \"contact.mu\"\nvalues = [1.0]",
    )
    .unwrap();
    let e = spec.plan(Path::new(".")).unwrap_err().to_string();
    assert!(
        e.contains("contact.mu") && e.contains("earlier axis"),
        "{e}"
    );
}

/// Malformed scene files: every key of the default scene set to wrong types and extreme
/// values, unknown keys, broken syntax. Each parses and validates or gives a one-line error
/// naming the key; a valid one builds without a panic.
#[test]
fn fuzz_malformed_scene_files() {
    let base: toml::Table = toml::from_str(&Scene::default().to_toml()).unwrap();
    let mut keys: Vec<(String, String)> = Vec::new();
    for (sec, v) in &base {
        match v {
            toml::Value::Table(t) => {
                for k in t.keys() {
                    keys.push((sec.clone(), k.clone()));
                }
            }
            _ => keys.push((String::new(), sec.clone())),
        }
    }
    let values = [
        "nan",
        "inf",
        "-inf",
        "-1.0",
        "0",
        "1e308",
        "-1e308",
        "1e-300",
        "\"text\"",
        "true",
        "[1.0, 2.0]",
        "4294967295",
        "18446744073709551615",
        "-9223372036854775808",
        "{ a = 1 }",
    ];
    let mut rng = Rng(0x5ce7e);
    for case in 0..400 {
        let (sec, key) = &keys[rng.below(keys.len())];
        let val = values[rng.below(values.len())];
        let text = if sec.is_empty() {
            format!("{key} = {val}\n")
        } else {
            format!("[{sec}]\n{key} = {val}\n")
        };
        let r = std::panic::catch_unwind(|| {
            Scene::from_toml(&text).map(|s| {
                // Building is bounded by the limits; running is not tried here.
                s.build().map(|_| ())
            })
        });
        let r = r.unwrap_or_else(|_| panic!("panic on case {case}: {text}"));
        let e = match r {
            Ok(Ok(())) => continue,
            Ok(Err(e)) | Err(e) => e.to_string(),
        };
        assert!(
            !e.trim().contains('\n') || e.contains(key.as_str()),
            "case {case}: {text}: {e}"
        );
        assert!(
            e.contains(key.as_str()) || e.contains(sec.as_str()) && !sec.is_empty(),
            "case {case}: error does not name `{key}`: {text}: {e}"
        );
    }
    for text in [
        "[sheet\nthickness = 1",
        "sheet = 3",
        "[sheet]\nthicknes = 0.3",
        "= 1",
    ] {
        assert!(Scene::from_toml(text).is_err(), "{text}");
    }
}
