//! Constructs real Fanuc, Haas and LinuxCNC programs use (issue 12): ISO
//! `:` program numbers, Ctrl-Z after the closing `%`, the high-speed codes
//! posts write (G05 P10000, G5.1 Q1, G08 P1; Haas G187, G103), G84.2/G84.3
//! rigid tapping, G31 skip, and the cycle words each control may leave out
//! (Fanuc/Haas: G82 without P dwells 0, G81 without R feeds from the
//! initial level; LinuxCNC refuses both), and LinuxCNC's nested comments.

mod common;
use common::*;

fn errors(err: &str) -> Vec<&str> {
    err.lines().filter(|l| l.starts_with("error[")).collect()
}

#[test]
fn a_fanuc_iso_tape_with_high_speed_codes_checks_clean() {
    let o = cncc(&[
        "check",
        "--dialect",
        "fanuc",
        "tests/programs/fanuc/iso-tape.nc",
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(errors(&err).is_empty(), "{err}");
    // The smoothing codes do not stop the run: nothing was left unchecked.
    assert!(!err.contains("W0511"), "{err}");
}

#[test]
fn a_haas_program_with_colon_number_smoothing_and_m97_checks_clean() {
    let o = cncc(&[
        "check",
        "--dialect",
        "haas",
        "tests/programs/haas/iso-tape.nc",
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(errors(&err).is_empty() && !err.contains("W0511"), "{err}");
}

#[test]
fn fanuc_cycles_without_p_or_r_dwell_zero_and_start_at_the_initial_level() {
    let o = cncc(&[
        "canon",
        "--dialect",
        "fanuc",
        "tests/programs/fanuc/iso-tape.nc",
    ]);
    let out = stdout(&o);
    assert!(o.status.success(), "{}", stderr(&o));
    // G82 without P: a dwell of 0 at the bottom.
    assert!(
        out.contains(
            "STRAIGHT_FEED(10.0000, 10.0000, -2.0000, 0.0000, 0.0000, 0.0000)\nDWELL(0.0000)"
        ),
        "{out}"
    );
    // G81 without R: from the initial level Z5 straight down.
    assert!(out.contains("STRAIGHT_TRAVERSE(20.0000, 10.0000, 5.0000, 0.0000, 0.0000, 0.0000)\nSTRAIGHT_FEED(20.0000, 10.0000, -3.0000"), "{out}");
    // G84.2 / G84.3: rigid tapping right and left hand.
    assert!(out.contains("START_SPINDLE_COUNTERCLOCKWISE"), "{out}");
    // G31: the skip move probes.
    assert!(out.contains("STRAIGHT_PROBE(30.0000"), "{out}");
}

#[test]
fn linuxcnc_refuses_cycles_without_p_or_r() {
    for (file, msg) in [
        ("g82-no-p", "dwell time P word missing with G82"),
        ("g81-no-r", "R clearance plane unspecified in cycle"),
    ] {
        let path = format!("tests/programs/linuxcnc/{file}.ngc");
        let o = cncc(&["check", "--dialect", "linuxcnc", &path]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(err.contains("E0541") && err.contains(msg), "{err}");
    }
}

#[test]
fn a_nested_comment_is_one_error_in_linuxcnc() {
    let path = "tests/programs/linuxcnc/nested-comment.ngc";
    let o = cncc(&["check", "--dialect", "linuxcnc", path]);
    let err = stderr(&o);
    assert_eq!(
        errors(&err),
        ["error[E0006 nested-comment]: nested comment found"],
        "{err}"
    );
    assert!(err.contains("nested-comment.ngc:1:12"), "{err}");
}

#[test]
fn a_colon_is_no_program_number_in_linuxcnc() {
    let dir = std::env::temp_dir().join(format!("cncc-colon-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("colon.ngc");
    std::fs::write(&path, ":0097\nG0 X1\nM2\n").unwrap();
    let o = cncc(&["check", "--dialect", "linuxcnc", path.to_str().unwrap()]);
    assert!(stderr(&o).contains("E0002"), "{}", stderr(&o));
}

#[test]
fn a_round_trip_keeps_the_high_speed_switches_as_written() {
    let path = "tests/programs/fanuc/iso-tape.nc";
    let o = cncc(&["port", path, "--from", "fanuc", "--to", "fanuc"]);
    let out = stdout(&o);
    assert!(o.status.success(), "{}", stderr(&o));
    for line in ["G5 P10000 (AICC ON)\n", "G5.1 Q1\n", "G8 P1\n"] {
        assert!(out.contains(line), "{line:?} in\n{out}");
    }
}

/// `T01 T02 M06` (NX posts for Mazak and other Fanuc-family machines):
/// M6 loads T1 and T2 is made ready, so a later `M6` alone loads T2.
#[test]
fn fanuc_second_t_in_a_change_block_preselects_the_next_tool() {
    let file = "tests/programs/fanuc/tool-preselect.nc";
    let o = cncc(&["check", "--dialect", "fanuc", file]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(!err.contains("E0205"), "{err}");
    let o = cncc(&["canon", "--dialect", "fanuc", file]);
    let out = stdout(&o);
    let tools: Vec<&str> = out
        .lines()
        .filter(|l| l.starts_with("SELECT_TOOL") || l.starts_with("CHANGE_TOOL"))
        .collect();
    assert_eq!(
        tools,
        [
            "SELECT_TOOL(1)",
            "CHANGE_TOOL(1)",
            "SELECT_TOOL(2)",
            "CHANGE_TOOL(2)"
        ],
        "{out}"
    );
    // Ported to a control that names one T per block: the next tool
    // gets a block of its own after the change; to Fanuc it stays.
    let o = cncc(&["port", "--from", "fanuc", "--to", "linuxcnc", file]);
    assert!(stdout(&o).contains("T1 M6\nT2\n"), "{}", stdout(&o));
    let o = cncc(&["port", "--from", "fanuc", "--to", "fanuc", file]);
    assert!(stdout(&o).contains("T1 T2 M6\n"), "{}", stdout(&o));
}

/// Without a tool change, or where the control names one T per block
/// (LinuxCNC), a second T is still a repeated word.
#[test]
fn a_second_t_without_a_change_or_on_linuxcnc_is_a_repeated_word() {
    let dir = tempfile::tempdir().unwrap();
    let alone = dir.path().join("alone.nc");
    std::fs::write(&alone, "O1\nG21 G90\nT1 T2\nM30\n").unwrap();
    let o = cncc(&["check", "--dialect", "fanuc", alone.to_str().unwrap()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("E0205") && err.contains("tool-change block"),
        "{err}"
    );
    let o = cncc(&[
        "check",
        "--dialect",
        "linuxcnc",
        "tests/programs/fanuc/tool-preselect.nc",
    ]);
    assert!(stderr(&o).contains("E0205"), "{}", stderr(&o));
}

/// A `G02` alone sets the motion mode on Fanuc (a bare motion code does
/// not move there): the mistake is the next block, which moves in G02
/// with no centre, and that is where it is reported. LinuxCNC refuses
/// the bare `G2` itself ("R i j k words all missing for arc", rs274 2.9).
#[test]
fn an_arc_without_a_centre_is_reported_on_the_block_that_moves() {
    let file = "tests/programs/fanuc/bare-arc-code.nc";
    let o = cncc(&["check", "--dialect", "fanuc", file]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    let errs = errors(&err);
    assert_eq!(errs.len(), 1, "{err}");
    assert!(errs[0].contains("E0512"), "{err}");
    assert!(err.contains(":10:1") && !err.contains(":9:"), "{err}");
    assert!(err.contains("help: give the centre"), "{err}");
    let o = cncc(&["check", "--dialect", "linuxcnc", file]);
    let err = stderr(&o);
    assert!(err.contains(":9:"), "{err}");
}
