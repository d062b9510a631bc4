//! Security and retract planes (issue 15): ISO 14649-10 gives a
//! workingstep's security plane and its operation's retract_plane both in
//! the feature's frame. `tests/stepnc/planes.stp` shares one plane at
//! z 75 between the setup and a workingstep over a hole whose top is at
//! z 50 (read as z 125: safe, never below the retract plane at z 60), and
//! gives a second workingstep a plane 5 mm above its hole, below the
//! 10 mm retract plane: that is a located warning (W0904) and the post
//! rapids at the retract plane, never a refusal. Every target posts it,
//! each post checks clean in its dialect and the LinuxCNC one runs in rs274.

mod common;

use std::path::{Path, PathBuf};

const TARGETS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

fn plan() -> PathBuf {
    common::root().join("tests/stepnc/planes.stp")
}

/// Posts to `target`, checks the post clean; the text and the stderr.
fn post_and_check(plan: &Path, target: &str) -> (String, String) {
    let dir = common::root().join("target/tmp/post-planes");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join(format!("planes.{target}"));
    let o = common::cncc(&[
        "post",
        plan.to_str().unwrap(),
        "--to",
        target,
        "-o",
        out.to_str().unwrap(),
    ]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{target}: {err}");
    let c = common::cncc(&["check", "--dialect", target, out.to_str().unwrap()]);
    assert_eq!(c.status.code(), Some(0), "{target}: {}", common::stderr(&c));
    if target == "linuxcnc" {
        common::runs_in_rs274(&out);
    }
    (std::fs::read_to_string(&out).unwrap(), err)
}

#[test]
fn both_planes_are_read_in_the_feature_frame_and_a_low_plane_is_a_warning() {
    for t in TARGETS {
        let (text, err) = post_and_check(&plan(), t);
        // One warning, at the workingstep whose plane is low (line 26).
        assert_eq!(err.matches("warning[W0904").count(), 1, "{t}: {err}");
        assert!(err.contains("`WS DRILL HOLE B`"), "{t}: {err}");
        assert!(err.contains("planes.stp:26:1"), "{t}: {err}");
        // Hole A: clearance 50 + 75; hole B: the retract plane 50 + 10.
        match *t {
            "siemens840d" => {
                assert!(text.contains("MCALL CYCLE81(125,50,10,30,)"), "{text}");
                assert!(text.contains("MCALL CYCLE81(60,50,10,30,)"), "{text}");
            }
            "heidenhain" => {
                assert!(text.contains("Q203=50 Q204=75"), "{text}");
                assert!(text.contains("Q203=50 Q204=10"), "{text}");
                assert!(text.contains("L Z125 R0 FMAX"), "{text}");
            }
            "linuxcnc" => {
                assert!(text.contains("G98 G81 X30 Y40 Z30 R60"), "{text}");
                assert!(text.contains("G0 Z125"), "{text}");
            }
            _ => {
                assert!(text.contains("G98 G81 X30. Y40. Z30. R60."), "{text}");
                assert!(text.contains("G0 Z125."), "{text}");
            }
        }
    }
}
