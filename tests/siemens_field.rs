//! Constructs of real 840D programs (`../shared/field/siemens840d`), on
//! small programs of our own: they check clean, run as the control runs
//! them, and port back to the 840D unchanged.

mod common;
use common::*;

const CONSTRUCTS: &str = "tests/programs/siemens840d/field_constructs.mpf";
const OEM: &str = "tests/programs/siemens840d/oem_cincinnati.mpf";

#[test]
fn field_constructs_check_clean_and_run() {
    let o = cncc(&["check", "--dialect", "siemens840d", CONSTRUCTS]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("W0530"), "{e}");
    assert!(e.contains("W0531"), "{e}");
    let o = cncc(&["canon", "--dialect", "siemens840d", CONSTRUCTS]);
    let out = stdout(&o);
    // G1 from reset; CASE to the lower-case label; the second IF of a block
    // jumps; GOTOF GRESKA finds `greska:`.
    assert!(
        out.contains("STRAIGHT_FEED(0.0000, 0.0000, 10.0000"),
        "{out}"
    );
    assert!(out.contains("STRAIGHT_FEED(2.0000"), "{out}");
    assert!(!out.contains("(1.0000, 0.0000, 10.0000"), "{out}");
    assert!(
        !out.contains("99.0000") && !out.contains("98.0000"),
        "{out}"
    );
    assert!(
        out.contains("STRAIGHT_FEED(20.0000, 10.0000, 5.0000"),
        "{out}"
    );
}

#[test]
fn field_constructs_port_back_unchanged() {
    let o = cncc(&[
        "port",
        "--from",
        "siemens840d",
        "--to",
        "siemens840d",
        CONSTRUCTS,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let src = std::fs::read_to_string(root().join(CONSTRUCTS)).unwrap();
    let comments = |t: &str| -> Vec<String> {
        t.lines()
            .filter_map(|l| l.find(';').map(|i| l[i..].to_string()))
            .collect()
    };
    assert_eq!(comments(&src), comments(&stdout(&o)));
    for line in [
        "CASE(_AXN) OF 1 GOTOF _AX1 2 GOTOF _ax2 DEFAULT GOTOF _AX3",
        "SETMS(1)",
        "D8",
    ] {
        assert!(stdout(&o).contains(line), "{line}: {}", stdout(&o));
    }
    assert!(
        stdout(&o).contains("IF R1==1 GOTOF greska IF R2==5 GOTOF Dalje"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn axis_words_after_reset_feed_at_g1() {
    let o = cncc(&[
        "check",
        "--dialect",
        "siemens840d",
        "tests/programs/siemens840d/reset_g1.mpf",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("E0507"), "{}", stderr(&o));
}

#[test]
fn an_oem_function_is_an_error_whose_help_names_a_dialect_file() {
    let o = cncc(&["check", "--dialect", "siemens840d", OEM]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(e.contains("`M202` cannot take arguments"), "{e}");
    assert!(e.contains("--dialect-file"), "{e}");
    assert!(e.contains("<command name=\"M202\""), "{e}");
}

#[test]
fn a_dialect_file_for_the_machine_makes_it_check_clean() {
    let o = cncc(&[
        "--dialect-file",
        "tests/dialects/cincinnati-840d.xml",
        "check",
        "--dialect",
        "ftv5",
        OEM,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("error["), "{}", stderr(&o));
}

#[test]
fn machine_state_is_read_and_kept_not_guessed() {
    const P: &str = "tests/programs/siemens840d/machine_state.mpf";
    let o = cncc(&["check", "--dialect", "siemens840d", P]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let e = stderr(&o);
    assert_eq!(e.matches("W0005").count(), 2, "{e}");
    assert!(e.contains("W0511") && e.contains("ISAXIS"), "{e}");
    let o = cncc(&["port", "--from", "siemens840d", "--to", "siemens840d", P]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let src = std::fs::read_to_string(root().join(P)).unwrap();
    assert_eq!(stdout(&o).trim_end(), src.trim_end());
    // Another dialect cannot say it.
    let o = cncc(&["port", "--from", "siemens840d", "--to", "fanuc", P]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
}

/// `TURN=` counts the full circles a helix adds to its arc (840D
/// programming manual: 0 to 999). An NX post writes `TURN=.5` for a half
/// turn that the end point already gives: not a whole number, so the
/// control either alarms or rounds it to one more full circle; either way
/// not the half turn meant. Whole numbers run.
#[test]
fn turn_is_a_whole_number_of_full_circles() {
    let dir = tempfile::tempdir().unwrap();
    let run = |turn: &str| {
        let path = dir.path().join("helix.mpf");
        let text = format!(
            "G17 G90 G71 T1 D1\nG0 X39 Y0 Z0 S1000 M3\n\
             G2 X-39 Y0 Z-3 I=AC(0) J=AC(0) TURN={turn} F200\nG3 X-36 Y3 CR=3\nM30\n"
        );
        std::fs::write(&path, text).unwrap();
        cncc(&["check", "--dialect", "siemens840d", path.to_str().unwrap()])
    };
    for ok in ["0", "2", "999"] {
        let o = run(ok);
        assert_eq!(o.status.code(), Some(0), "TURN={ok}: {}", stderr(&o));
    }
    for bad in [".5", "1000"] {
        let o = run(bad);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "TURN={bad}: {e}");
        assert!(e.contains("E0511") && e.contains("0 to 999"), "{e}");
        assert!(e.contains("help: TURN= counts the full circles"), "{e}");
        // The run goes on from the helix's end point: the arc after it,
        // which starts there, is not reported.
        assert_eq!(e.matches("error[").count(), 1, "{e}");
    }
}

/// `M1=3 S1=1000` (address extension: spindle 1, the master spindle) is
/// `M3 S1000`, with a computed value too (`M1=DIR` in a PROC); a computed
/// spindle code runs as the code it turns out to be.
#[test]
fn spindle_one_address_extensions_run_as_the_master_spindle() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("spindle.mpf");
    let text = "G17 G90 G71 T1 D1\nR1=4\nG0 X0 Y0 Z10 M1=3 S1=1000\nG1 Z0 F100\n\
                M1=R1 S1=R1*100\nG1 X10\nM1=5\nM30\n";
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let o = cncc(&["check", "--dialect", "siemens840d", p]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{e}");
    assert!(!e.contains("warning["), "{e}");
    let out = stdout(&cncc(&["canon", "--dialect", "siemens840d", p]));
    let spindle: Vec<&str> = out
        .lines()
        .filter(|l| l.contains("SPINDLE_SPEED") || l.contains("START_SPINDLE"))
        .collect();
    assert_eq!(
        spindle,
        [
            "SET_SPINDLE_SPEED(0, 1000.0000)",
            "START_SPINDLE_CLOCKWISE(0)",
            "SET_SPINDLE_SPEED(0, 400.0000)",
            "START_SPINDLE_COUNTERCLOCKWISE(0)",
        ],
        "{out}"
    );
}
