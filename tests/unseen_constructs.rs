//! Constructs met in real programs from sources beyond `../shared`
//! (issue 12, "the same rates hold on real programs from sources you have
//! not seen"), each on a small program of our own: what the control does
//! with it, not what one file needs.

mod common;
use common::*;

fn check(dialect: &str, file: &str) -> (Option<i32>, String) {
    let o = cncc(&["check", "--dialect", dialect, file]);
    (o.status.code(), stderr(&o))
}

/// Q and QR parameters outlive the program on a TNC: one this run never
/// set is a value from outside (W0590), not 0 and not an error; QL are the
/// program's own and start at 0.
#[test]
fn heidenhain_q_parameters_are_the_controls() {
    let (code, e) = check("heidenhain", "tests/programs/heidenhain/global_q.h");
    assert_eq!(code, Some(0), "{e}");
    assert!(e.contains("W0590") && e.contains("`Q1800`"), "{e}");
    assert!(!e.contains("QL5"), "{e}");
    let (code, e) = check("heidenhain", "tests/programs/heidenhain/global_q_set.h");
    assert_eq!(code, Some(0), "{e}");
    assert_eq!(e, "", "set before they are read, they run");
}

/// `DEF REAL A[MAXN]`: an array size from the machine's DEFINE macros or
/// GUD constants is not known at check time (W0517), read and written back
/// as it was; the PROC file checked alone returns to its caller at M17.
#[test]
fn siemens_array_sized_by_a_machine_macro() {
    let f = "tests/programs/siemens840d/macro_sized.spf";
    let (code, e) = check("siemens840d", f);
    assert_eq!(code, Some(0), "{e}");
    assert_eq!(e.matches("W0517").count(), 3, "{e}");
    assert!(e.contains("`MAXSTAGES`"), "{e}");
    let o = cncc(&["port", "--from", "siemens840d", "--to", "siemens840d", f]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("DEF REAL SPEEDS[MAXSTAGES], LIMITS[2,MAXSTAGES]"),
        "{out}"
    );
    assert!(out.contains("DEF STRING[16] NAMES[MAXSTAGES]"), "{out}");
}

/// A subprogram file that runs to its return with nothing unknown on the
/// way ends there (back to a caller cncc does not have) instead of running
/// again from the top until the loop limit.
#[test]
fn a_subprogram_checked_alone_ends_at_its_return() {
    let (code, e) = check("siemens840d", "tests/programs/siemens840d/macro_sized.spf");
    assert_eq!(code, Some(0), "{e}");
    assert!(!e.contains("E0506"), "{e}");
}

/// Mist and flood coolant may be on together (LinuxCNC: "M7 and M8 may be
/// active at the same time"; the 840D passes both to the PLC): not a modal
/// group conflict. M8 with M9 still is.
#[test]
fn mist_and_flood_in_one_block() {
    let f = "tests/programs/linuxcnc/mist_and_flood.ngc";
    let (code, e) = check("linuxcnc", f);
    assert_eq!(code, Some(0), "{e}");
    let out = stdout(&cncc(&["canon", "--dialect", "linuxcnc", f]));
    assert!(out.contains("MIST_ON()\nFLOOD_ON()"), "{out}");
    let dir = std::env::temp_dir().join(format!("cncc-coolant-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("m8m9.ngc");
    std::fs::write(&bad, "G0 X1 M8 M9\nM2\n").unwrap();
    let (code, e) = check("linuxcnc", bad.to_str().unwrap());
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("E0202"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Machine functions nothing the run computes depends on (Haas chip
/// conveyor M31/M33, rotary brake M10/M11; Fanuc rigid tapping mode M29;
/// coolant through the tool) are passed to the machine and the run goes on
/// to the end of the program.
#[test]
fn machine_functions_do_not_stop_the_run() {
    let f = "tests/programs/haas/chip_conveyor.nc";
    let (code, e) = check("haas", f);
    assert_eq!(code, Some(0), "{e}");
    assert!(!e.contains("W0511"), "{e}");
    let out = stdout(&cncc(&["canon", "--dialect", "haas", f]));
    assert!(out.contains("PROGRAM_END()"), "{out}");
}

/// Operate's program blocks (GROUP_BEGIN/GROUP_END) and its blank
/// (WORKPIECE) describe the program, they machine nothing: the run goes on
/// through them silently and they are written back as read.
#[test]
fn operate_program_blocks_describe_and_run_on() {
    let f = "tests/programs/siemens840d/operate_groups.mpf";
    let (code, e) = check("siemens840d", f);
    assert_eq!(code, Some(0), "{e}");
    assert!(!e.contains("W0511") && !e.contains("W0510"), "{e}");
    let out = stdout(&cncc(&["canon", "--dialect", "siemens840d", f]));
    assert!(out.contains("STRAIGHT_FEED(100.0000"), "{out}");
    let o = cncc(&["port", "--from", "siemens840d", "--to", "siemens840d", f]);
    let out = stdout(&o);
    assert!(out.contains("GROUP_BEGIN(0,\"FACE TOP\",0,0)"), "{out}");
    assert!(out.contains("GROUP_END(0,0)"), "{out}");
}

/// `TCH PROBE n ...` touch probe cycles (workpiece and tool measurement,
/// datum setting) are read with their Q parameters, reported as not run
/// (W0513), and written back as read; a result they leave (Q160) is a
/// value from the machine.
#[test]
fn heidenhain_touch_probe_cycles() {
    let f = "tests/programs/heidenhain/touch_probe.h";
    let (code, e) = check("heidenhain", f);
    assert_eq!(code, Some(0), "{e}");
    assert!(e.contains("W0513") && e.contains("TCH PROBE 417"), "{e}");
    assert!(e.contains("W0590") && e.contains("`Q160`"), "{e}");
    let port = |file: &str| {
        let o = cncc(&["port", "--from", "heidenhain", "--to", "heidenhain", file]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        stdout(&o)
    };
    let once = port(f);
    assert!(
        once.contains("4 TCH PROBE 417 DATUM IN TS AXIS ~\n  Q263=-20 ;1ST POINT 1ST AXIS ~\n"),
        "{once}"
    );
    assert!(
        once.contains("  Q303=+1 ;MEAS. VALUE TRANSFER\n5 L Z+50 FMAX"),
        "{once}"
    );
    let dir = std::env::temp_dir().join(format!("cncc-tch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let again = dir.join("once.h");
    std::fs::write(&again, &once).unwrap();
    assert_eq!(port(again.to_str().unwrap()), once, "a fixpoint");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `L Z+0 R0 FMAX M92` (to the machine builder's tool change position):
/// run as machine coordinates with one W0517 note, instead of stopping
/// the run; written back as M92.
#[test]
fn heidenhain_m92_moves_run_in_machine_coordinates() {
    let f = "tests/programs/heidenhain/machine_datum.h";
    let (code, e) = check("heidenhain", f);
    assert_eq!(code, Some(0), "{e}");
    assert_eq!(e.matches("note[W0517").count(), 1, "{e}");
    assert!(!e.contains("W0511"), "{e}");
    let out = stdout(&cncc(&["canon", "--dialect", "heidenhain", f]));
    assert!(out.contains("PROGRAM_END()"), "{out}");
    let o = cncc(&["port", "--from", "heidenhain", "--to", "heidenhain", f]);
    assert!(stdout(&o).contains("2 L Z+0 R0 FMAX M92"), "{}", stdout(&o));
}

/// Fanuc custom macro words by their first two letters (`WH[..]DO1`,
/// `GO`, `EN1`), as 0i-MD shop macros are written: read as the full words,
/// the loop runs three passes, and they are written back in full. Haas
/// removes the capability, so there `WH` stays an unknown keyword.
#[test]
fn fanuc_macro_word_abbreviations() {
    let f = "tests/programs/fanuc/macro_abbreviations.nc";
    let (code, e) = check("fanuc", f);
    assert_eq!(code, Some(0), "{e}");
    assert_eq!(e, "", "{e}");
    let out = stdout(&cncc(&["canon", "--dialect", "fanuc", f]));
    assert_eq!(out.matches("STRAIGHT_FEED").count(), 9, "{out}");
    assert!(out.contains("-3.0000, 0.0000"), "{out}");
    let o = cncc(&["port", "--from", "fanuc", "--to", "fanuc", f]);
    let back = stdout(&o);
    assert!(
        back.contains("WHILE [#1 GT #2] DO1") && back.contains("END1"),
        "{back}"
    );
    assert!(back.contains("GOTO 90") && !back.contains("WH["), "{back}");
    let (code, e) = check("haas", f);
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("E0104") && e.contains("`WH`"), "{e}");
}

/// Centre and radius words in a block without a motion code are an arc's
/// only when the modal motion is an arc: in G0/G1 mode the block is no
/// arc and gets no "arc given both a radius and a centre" (E0207) but a
/// warning that the words are not used (W0597); in G2 mode the run
/// reports the mixed format (E0512) on that block. An explicit G2 with
/// both still gets E0207 when it is read.
#[test]
fn arc_words_only_make_an_arc_in_arc_mode() {
    let (code, e) = check("fanuc", "tests/programs/fanuc/arc_words_outside_arc.nc");
    assert_eq!(code, Some(1), "{e}");
    assert!(!e.contains("E0207"), "{e}");
    assert_eq!(e.matches("error[").count(), 1, "{e}");
    assert!(
        e.contains("E0512") && e.contains("arc_words_outside_arc.nc:10:"),
        "{e}"
    );
    let (_, e) = check("fanuc", "tests/programs/fanuc/mistakes.nc");
    assert!(e.contains("E0207") && e.contains("mistakes.nc:13:"), "{e}");
}

/// Siemens CYCLE832 takes its machining type by name (`_ROUGH`,
/// `_FINISH`, `_OFF`: names CYCLE832/CUST_832.SPF define on every
/// control, Operate commissioning manual): they are the spec's
/// `<constant>`s, not undefined variables (E0504), and the run sets the
/// tolerance they go with.
#[test]
fn siemens_cycle832_machining_types_by_name() {
    let f = "tests/programs/siemens840d/cycle832_types.mpf";
    let (code, e) = check("siemens840d", f);
    assert_eq!(code, Some(0), "{e}");
    assert!(!e.contains("E0504"), "{e}");
    let o = cncc(&["canon", "--dialect", "siemens840d", f]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("SET_NAIVECAM_TOLERANCE(0.1000)"),
        "{}",
        stdout(&o)
    );
    // A name the program does not define and the control does not either
    // is still an error.
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("rough.mpf");
    std::fs::write(&bad, "G0 X0 Y0 Z5\nCYCLE832(0.01,_ROUGHLY,1)\nM30\n").unwrap();
    let (code, e) = check("siemens840d", bad.to_str().unwrap());
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("E0504") && e.contains("_ROUGHLY"), "{e}");
}

/// Klartext `F AUTO` (iTNC 530 output) is `FAUTO`, as `F MAX` is `FMAX`:
/// the feed of the last TOOL CALL. cncc keeps it (W0005), not an error.
#[test]
fn heidenhain_f_auto_with_a_space() {
    let (code, e) = check("heidenhain", "tests/programs/heidenhain/f_auto.h");
    assert_eq!(code, Some(0), "{e}");
    assert_eq!(e.matches("`FAUTO` is kept as text").count(), 2, "{e}");
    assert!(!e.contains("E0122"), "{e}");
}

/// `G0 G90 G0 X0.` (a Fadal shop program): on Fanuc and Haas a code of a
/// group written again replaces the first, so the same code twice counts
/// once (W0598); rs274 refuses two codes of one group (E0201).
#[test]
fn the_same_code_twice_in_a_block() {
    let f = "tests/programs/fanuc/repeated_code.nc";
    for d in ["fanuc", "haas"] {
        let (code, e) = check(d, f);
        assert_eq!(code, Some(0), "{d}: {e}");
        assert_eq!(e.matches("W0598").count(), 2, "{d}: {e}");
    }
    let (code, e) = check("linuxcnc", f);
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("E0201"), "{e}");
}
