//! `pressridge animate` end to end: a short run's snapshots become a looping GIF (also
//! written by `simulate` itself as ridge.gif); a run directory without snapshots is refused
//! with its name.

#[path = "../../../tests/common/mod.rs"]
mod common;
use common::bin;

/// Frames in a GIF: its image descriptors that follow a graphic control extension.
fn gif_frames(bytes: &[u8]) -> usize {
    bytes
        .windows(10)
        .filter(|w| w[0] == 0x21 && w[1] == 0xF9 && w[2] == 0x04 && w[8] == 0x2C)
        .count()
}

#[test]
fn animate_a_short_run() {
    let dir = common::simulate(
        "animate",
        &["--set", "duration=2", "--set", "output.snapshot_interval=1"],
    );
    let own = std::fs::read(dir.join("ridge.gif")).expect("simulate writes ridge.gif");
    assert_eq!(&own[..6], b"GIF89a");

    let gif = dir.join("anim.gif");
    let out = bin()
        .args(["animate", "--fps", "5", "--out"])
        .arg(&gif)
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&gif).unwrap();
    assert_eq!(&bytes[..6], b"GIF89a");
    assert_eq!(*bytes.last().unwrap(), 0x3B, "GIF trailer");
    let n = gif_frames(&bytes);
    assert!(n >= 2, "{n} frames");
    assert_eq!(n, gif_frames(&own));
    // No temporary file left beside it.
    for e in std::fs::read_dir(&dir).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(!name.starts_with(".tmp-"), "left {name}");
    }

    let bad = bin()
        .args(["animate", "--fps", "0"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--fps"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_run_without_snapshots_is_named() {
    let dir = common::scratch("nosnap");
    let out = bin().arg("animate").arg(&dir).output().unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(&dir.display().to_string()), "{err}");
    assert!(err.contains("no snapshots"), "{err}");
    assert!(!dir.join("ridge.gif").exists());
    let _ = std::fs::remove_dir_all(&dir);
}
