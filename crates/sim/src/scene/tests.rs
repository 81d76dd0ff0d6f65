use super::*;
use crate::dem::{ContactOnset, Dashpot};

#[test]
fn dotted_keys_are_read_and_left_out() {
    let s = Scene::default()
        .with_overrides(&["contact.mu=0.4", "floe.thickness=3.5"])
        .unwrap();
    assert_eq!(s.value_at("contact.mu").as_deref(), Some("0.4"));
    assert_eq!(s.value_at("floe.thickness").as_deref(), Some("3.5"));
    assert_eq!(s.value_at("floe.nosuch"), None);
    assert_eq!(s.value_at("nosuch.key"), None);
    // Two scenes that differ only in the keys left out give the same text.
    let t = s.with_overrides(&["floe.thickness=7.0"]).unwrap();
    let keys = ["floe.thickness".to_string(), "absent.key".to_string()];
    assert_eq!(s.toml_without(&keys), t.toml_without(&keys));
    assert_ne!(s.toml_without(&keys[1..]), t.toml_without(&keys[1..]));
}

#[test]
fn default_scene_round_trips_through_toml() {
    let s = Scene::default();
    assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
}

#[test]
fn unknown_keys_are_rejected_by_name() {
    let e = Scene::from_toml("duraton = 3.0").unwrap_err().to_string();
    assert!(e.contains("duraton"), "{e}");
    let e = Scene::from_toml("[contact]\nmuu = 0.3")
        .unwrap_err()
        .to_string();
    assert!(e.contains("muu"), "{e}");
    let e = Scene::default()
        .with_overrides(&["contact.mew=1"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("mew"), "{e}");
}

#[test]
fn overrides_set_nested_values() {
    let s = Scene::default()
        .with_overrides(&[
            "contact.mu=0.4",
            "pile.blocks=12",
            "water.enabled=false",
            "name=x",
        ])
        .unwrap();
    assert_eq!(s.contact.mu, 0.4);
    assert_eq!(s.pile.as_ref().unwrap().blocks, 12);
    assert!(!s.water.enabled);
    assert_eq!(s.name, "x");
    assert!(s.world_params().water.is_none());
}

#[test]
fn invalid_values_are_named() {
    let e = Scene::default()
        .with_overrides(&["duration=-1"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("duration"), "{e}");
    let e = Scene::default()
        .with_overrides(&["contact.normal_stiffness=-5"])
        .unwrap()
        .build()
        .unwrap_err()
        .to_string();
    assert!(e.contains("normal_stiffness"), "{e}");
    let e = Scene::from_toml("duration = nan").unwrap_err().to_string();
    assert!(e.contains("duration"), "{e}");
    let e = Scene::default()
        .with_overrides(&["joint.incubation_time=0"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("joint.incubation_time"), "{e}");
    let e = Scene::default()
        .with_overrides(&[
            "joint.incubation_time=0.002",
            "numerics.fracture_step_mean=true",
        ])
        .unwrap_err()
        .to_string();
    assert!(e.contains("numerics.fracture_step_mean"), "{e}");
}

/// The incubation time is absent unless set, and then absent from the scene's TOML too,
/// so that the scenes (and campaign digests) of earlier runs are unchanged.
#[test]
fn incubation_time_is_optional_and_not_written_when_absent() {
    let s = Scene::default();
    assert_eq!(s.joint.incubation_time, None);
    assert!(!s.to_toml().contains("incubation_time"));
    let s = s.with_overrides(&["joint.incubation_time=0.002"]).unwrap();
    assert_eq!(s.joint.incubation_time, Some(0.002));
    assert_eq!(s.world_params().incubation_time, Some(0.002));
    assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
}

/// A scene option off by default: absent from the default scene's TOML (`key` not in it);
/// `key=value` set gives a scene that round-trips through TOML (returned), and each of
/// `bad` values is refused, at parsing or at building, with a message naming `key`.
fn option_absent_unless_set(key: &str, value: &str, bad: &[&str]) -> Scene {
    let name = key.rsplit('.').next().unwrap();
    assert!(!Scene::default().to_toml().contains(name));
    let s = Scene::default()
        .with_overrides(&[format!("{key}={value}")])
        .unwrap();
    assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
    for b in bad {
        let e = Scene::default()
            .with_overrides(&[format!("{key}={b}")])
            .and_then(|s| s.build().map(|_| ()))
            .unwrap_err()
            .to_string();
        assert!(e.contains(name), "{key}={b}: {e}");
    }
    s
}

/// The joint dashpot is explicit unless set and then absent from the scene's TOML;
/// "implicit" reaches the world; a misspelt value is refused naming the key.
#[test]
fn joint_dashpot_is_explicit_unless_set_and_not_written_then() {
    assert_eq!(Scene::default().numerics.joint_dashpot, Dashpot::Explicit);
    let s = option_absent_unless_set("numerics.joint_dashpot", "implicit", &["centered"]);
    assert_eq!(s.world_params().joint_dashpot, Dashpot::Implicit);
}

/// The contact onset is eq (3)'s own unless set, and then absent from the scene's TOML;
/// "velocity" reaches the world.
#[test]
fn contact_onset_is_the_area_rate_unless_set_and_not_written_then() {
    assert_eq!(Scene::default().numerics.contact_onset, ContactOnset::Area);
    let s = option_absent_unless_set("numerics.contact_onset", "velocity", &["speed"]);
    assert_eq!(s.world_params().contact_onset, ContactOnset::Velocity);
}

/// Eq (8)'s length is the sheet thickness unless set, and then absent from the scene's
/// TOML; a set length reaches the sheet's k′, and a non-positive one is refused by name.
#[test]
fn eq8_length_is_the_thickness_unless_set() {
    let s = option_absent_unless_set("sheet.viscous_length", "1.0", &["0", "-1", "nan"]);
    assert_eq!(s.sheet.as_ref().unwrap().viscous_length, Some(1.0));
}

/// Eq (4)'s k_te has one reading, per contact (0.6·k_ne·L): the key that chose the
/// withdrawn reading (k_ne·h) is refused by name, in a scene and in `--set`.
#[test]
fn the_withdrawn_tangential_reference_is_refused_by_name() {
    let e = Scene::default()
        .with_overrides(&["contact.tangential_reference=thickness".to_string()])
        .unwrap_err()
        .to_string();
    assert!(e.contains("tangential_reference"), "{e}");
    let e = Scene::from_toml("[contact]\ntangential_reference = \"chord\"\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("tangential_reference"), "{e}");
}

/// The contact dashpot's sweeps are 0 (each contact alone) unless set, and then absent
/// from the scene's TOML; a count reaches the world, and too many are refused by name.
#[test]
fn contact_dashpot_sweeps_are_off_unless_set() {
    assert_eq!(Scene::default().numerics.contact_dashpot_sweeps, 0);
    let s = option_absent_unless_set("numerics.contact_dashpot_sweeps", "4", &["51", "-1"]);
    assert_eq!(s.world_params().contact_dashpot_sweeps, 4);
}

/// The numerics options once kept in an `[experimental]` section are read at their keys in
/// `[numerics]` (the incubation time in `[joint]`); a scene or `--set` that still names the
/// section is refused, the section named.
#[test]
fn the_former_experimental_section_is_refused_by_name() {
    let e = Scene::from_toml("[experimental]\ncontact_onset = \"velocity\"\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("experimental"), "{e}");
    let e = Scene::default()
        .with_overrides(&["experimental.contact_onset=velocity".to_string()])
        .unwrap_err()
        .to_string();
    assert!(e.contains("experimental"), "{e}");
}

/// One parser for `--set`: the key trimmed, the value as given, `None` without `=`; and
/// `with_overrides` reads a spaced key as `split_override` names it.
#[test]
fn overrides_are_split_once_with_the_key_trimmed() {
    assert_eq!(
        split_override(" contact.mu =0.4"),
        Some(("contact.mu", "0.4"))
    );
    assert_eq!(split_override("name=a=b"), Some(("name", "a=b")));
    assert_eq!(split_override("contact.mu"), None);
    let s = Scene::default()
        .with_overrides(&[" contact.mu =0.4"])
        .unwrap();
    assert_eq!(s.value_at("contact.mu").as_deref(), Some("0.4"));
}

/// The keys of the register's open options: absent from a written scene at their defaults
/// (so that the records made before them keep their digests), written and read back when
/// set, refused with their names when out of range.
#[test]
fn the_open_options_are_left_out_at_their_defaults_and_checked_when_set() {
    let text = Scene::default().to_toml();
    for key in [
        "crushing_pressure",
        "damping_law",
        "shielding_contacts",
        "boundary_damping_fraction",
        "tip_bevel_slope",
    ] {
        assert!(!text.contains(key), "{key} is written at its default");
    }
    // The nose ramp's default (20°) is not the meaning of an absent key (45°, as files of
    // model revisions 1-2 were written): the built-in scene writes it; a 45° scene omits it
    // and reads back at 45°.
    assert!(text.contains("nose_slope = 0.36397"), "{text}");
    let steep = Scene::default()
        .with_overrides(&["floe.nose_slope=1"])
        .unwrap();
    assert!(!steep.to_toml().contains("nose_slope"));
    assert_eq!(Scene::from_toml(&steep.to_toml()).unwrap(), steep);
    let partial = Scene::from_toml("[floe]\nthickness = 2.0").unwrap();
    assert_eq!(partial.floe.unwrap().nose_slope, 1.0);
    let s = Scene::default()
        .with_overrides(&[
            "contact.crushing_pressure=1e6",
            "contact.damping_law=\"contact\"",
            "water.shielding_contacts=2",
            "sheet.boundary_damping_fraction=0.3",
            "sheet.tip_bevel_slope=0.8",
            "floe.nose_slope=0.36397",
        ])
        .unwrap();
    assert_eq!(Scene::from_toml(&s.to_toml()).unwrap(), s);
    assert_eq!(s.contact.damping_law, crate::dem::DampingLaw::Contact);
    for (set, key) in [
        ("contact.crushing_pressure=-1", "contact.crushing_pressure"),
        // A 1-m floe cannot hold the 2-m nose block of a 20° ramp.
        ("floe.length=1", "floe.length"),
        ("floe.nose_slope=0", "floe.nose_slope"),
        ("sheet.tip_bevel_slope=0.3", "sheet.tip_bevel_slope"),
        (
            "sheet.boundary_damping_fraction=-0.5",
            "sheet.boundary_damping_fraction",
        ),
    ] {
        let e = Scene::default()
            .with_overrides(&[set])
            .and_then(|s| s.build().map(|_| s));
        let e = e.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.contains(key), "{set}: {e}");
    }
}

/// The default nose ramp at 20° (slope tan 20° = 0.364) drops its 0.5 m over a run of
/// 1.37 m: the nose block becomes two floe blocks wide, the floe keeps its length, and the
/// ramp's outline has that slope. At 45° the floe is built as in model revisions 1–2, one
/// block per metre.
#[test]
fn a_shallow_nose_ramp_widens_the_nose_block() {
    let s = Scene::default();
    assert_eq!(
        s.floe.as_ref().unwrap().nose_slope,
        crate::scene::NOSE_SLOPE
    );
    let w = s.build().unwrap();
    let b = w.bodies();
    let floe: Vec<usize> = (0..b.len()).filter(|&i| b.role[i] == Role::Floe).collect();
    let nose = b.block[floe[0]].unwrap();
    assert_eq!(nose.width, 2.0);
    assert_eq!(floe.len(), 39);
    let length: f64 = floe.iter().map(|&i| b.block[i].unwrap().width).sum();
    assert_eq!(length, 40.0);
    let run = nose.bevel_run.unwrap()[3];
    assert!((nose.bevel[3] / run - 0.36397).abs() < 1e-12);
    let d = Scene::default()
        .with_overrides(&["floe.nose_slope=1"])
        .unwrap()
        .build()
        .unwrap();
    let n = (0..d.bodies().len())
        .filter(|&i| d.bodies().role[i] == Role::Floe)
        .count();
    assert_eq!(n, 40);
    assert!(
        d.bodies()
            .block
            .iter()
            .flatten()
            .all(|b| b.bevel_run.is_none())
    );
}
