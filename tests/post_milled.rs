//! `cncc post` of milled round holes and general pockets (issue 15):
//! `tests/stepnc/milled_holes.stp` (a blind hole roughed and finished
//! with an end mill, a through hole with a face mill entering on a helix)
//! and `tests/stepnc/general_pockets.stp` (a convex pentagon with corner
//! radii, a concave L given as a composite curve, a half disc whose arc
//! is a trimmed circle). Every target posts
//! them, each post checks clean in its dialect, the LinuxCNC post runs in
//! rs274 (skipped with a note where it is absent), and each hole is the
//! target's circular pocket cycle or exact helical moves.

mod common;

use std::path::{Path, PathBuf};

const TARGETS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

fn plan(name: &str) -> PathBuf {
    common::root().join("tests/stepnc").join(name)
}

/// Posts `plan` to `target` into target/tmp, checks the post clean with
/// `cncc check`; returns the posted text.
fn post_and_check(plan: &Path, target: &str) -> String {
    let dir = common::root().join("target/tmp/post-milled");
    std::fs::create_dir_all(&dir).unwrap();
    let stem = plan.file_stem().unwrap().to_string_lossy();
    let out = dir.join(format!("{stem}.{target}"));
    let o = common::cncc(&[
        "post",
        plan.to_str().unwrap(),
        "--to",
        target,
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{target}: {}", common::stderr(&o));
    let c = common::cncc(&["check", "--dialect", target, out.to_str().unwrap()]);
    assert_eq!(c.status.code(), Some(0), "{target}: {}", common::stderr(&c));
    if target == "linuxcnc" {
        common::runs_in_rs274(&out);
    }
    std::fs::read_to_string(&out).unwrap()
}

/// Helical blocks: G2/G3 with a Z word (a Heidenhain helix is `CP IPA`).
fn helix_blocks(text: &str) -> usize {
    text.lines()
        .filter(|l| {
            ((l.starts_with("G2 ") || l.starts_with("G3 ")) && l.contains(" Z"))
                || l.starts_with("CP IPA")
        })
        .count()
}

#[test]
fn milled_holes_are_circular_pocket_cycles_or_helices() {
    let p = plan("milled_holes.stp");
    for t in TARGETS {
        let text = post_and_check(&p, t);
        match *t {
            "siemens840d" => {
                // The end mill cuts across its centre: POCKET2; the face
                // mill does not: POCKET4, entering on a helix (VARI 21).
                assert_eq!(text.matches("POCKET2(").count(), 2, "{text}");
                let p4 = text.lines().find(|l| l.starts_with("POCKET4(")).unwrap();
                assert!(p4.contains(",21,"), "{p4}");
            }
            "heidenhain" => {
                assert_eq!(text.matches("CYCL DEF 252").count(), 2, "{text}");
                // The face mill: helical moves (no centre-cutting cycle).
                assert!(helix_blocks(&text) > 0, "{text}");
            }
            _ => {
                assert!(!text.contains("G12") && !text.contains("G13"), "{text}");
                assert!(text.contains("milled round hole: helix"), "{text}");
                assert!(helix_blocks(&text) > 20, "{text}");
            }
        }
    }
}

#[test]
fn general_pockets_post_as_generated_paths_everywhere() {
    let p = plan("general_pockets.stp");
    for t in TARGETS {
        let text = post_and_check(&p, t);
        assert!(text.contains("5 corners, convex"), "{t}: {text}");
        assert!(text.contains("6 corners, concave"), "{t}: {text}");
        // The half disc's arc as chords within 0.002 mm: many corners.
        assert!(text.contains("94 corners, convex"), "{t}: {text}");
    }
}

#[test]
fn a_pocket_narrower_than_its_tool_is_a_located_refusal() {
    let dir = common::root().join("target/tmp/post-milled");
    std::fs::create_dir_all(&dir).unwrap();
    // The L's arm 20 mm wide, the tool 24 mm.
    let text = std::fs::read_to_string(plan("general_pockets.stp"))
        .unwrap()
        .replace(
            "#93=MILLING_TOOL_DIMENSION(8.,",
            "#93=MILLING_TOOL_DIMENSION(24.,",
        );
    let bad = dir.join("too-narrow.stp");
    std::fs::write(&bad, text).unwrap();
    let o = common::cncc(&["post", bad.to_str().unwrap(), "--to", "fanuc"]);
    assert_eq!(o.status.code(), Some(1));
    let err = common::stderr(&o);
    assert!(err.contains("`L POCKET`"), "{err}");
    assert!(err.contains("too-narrow.stp:"), "located: {err}");
}
