//! A Fanuc-family machine added as a user adds one: a Makino profile
//! (`tests/dialects/makino.xml`, extending fanuc with `G05 P2` high-speed
//! mode and `G84.2` rigid tapping), loaded with `--dialect-file`, with no
//! Rust written for it: check, canon, and port to and from it with
//! `--verify`. Posting STEP-NC to it, with its post folder
//! `tests/posts/makino/`: `tests/post_dir.rs`.

mod common;
use common::*;

const SPEC: &str = "tests/dialects/makino.xml";
const PROGRAM: &str = "tests/programs/makino/hsm-tap.nc";

fn with_spec(args: &[&str]) -> std::process::Output {
    let mut all = vec!["--dialect-file", SPEC];
    all.extend_from_slice(args);
    cncc(&all)
}

#[test]
fn a_makino_program_checks_and_runs() {
    let o = with_spec(&["check", "--dialect", "makino", PROGRAM]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = with_spec(&["canon", "--dialect", "makino", PROGRAM]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    // G84.2 taps: reverse at the bottom, two holes.
    assert_eq!(
        out.matches("START_SPINDLE_COUNTERCLOCKWISE").count(),
        2,
        "{out}"
    );
}

#[test]
fn a_makino_program_ports_out_with_verify() {
    for to in ["fanuc", "linuxcnc", "heidenhain", "haas"] {
        let o = with_spec(&["port", "--from", "makino", "--to", to, "--verify", PROGRAM]);
        assert_eq!(o.status.code(), Some(0), "{to}: {}", stderr(&o));
        let out = stdout(&o);
        if to != "fanuc" {
            // G05 P2 is no code there (LinuxCNC's G5 is a spline).
            let live = out
                .lines()
                .any(|l| l.trim_start().starts_with("G5 ") || l.trim_start().starts_with("G05 "));
            assert!(!live, "{to}: {out}");
            assert!(
                stderr(&o).contains("G5 (path.smoothing) has no code"),
                "{to}"
            );
        }
    }
}

#[test]
fn a_fanuc_program_ports_to_the_makino_with_verify() {
    let o = with_spec(&[
        "port",
        "--from",
        "fanuc",
        "--to",
        "makino",
        "--verify",
        "tests/programs/fanuc/port_demo.nc",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}
