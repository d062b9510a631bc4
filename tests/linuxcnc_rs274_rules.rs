//! rs274 2.9's rules that LinuxCNC's regression suite pins (issue 16), each
//! on a small program of ours (`tests/programs/linuxcnc/rs274_rules/`),
//! with the calls rs274 printed for it; they run without rs274.
//! `tests/linuxcnc_suite.rs` runs the suite itself where rs274 is present.

mod common;
use common::*;

fn canon(dialect: &str, file: &str) -> String {
    let o = cncc(&["canon", "--dialect", dialect, file]);
    assert_eq!(o.status.code(), Some(0), "{file}: {}", stderr(&o));
    stdout(&o)
}

fn rules(name: &str) -> String {
    canon(
        "linuxcnc",
        &format!("tests/programs/linuxcnc/rs274_rules/{name}"),
    )
}

/// G10 L2 R turns the work frame: a G53 target, `#<_abs_*>` and a G10 L20
/// under the rotation go through it (machine = R (program + G92) + offset).
#[test]
fn xy_rotation_applies_to_machine_coordinates() {
    let out = rules("rotation.ngc");
    assert!(
        out.contains("STRAIGHT_TRAVERSE(1.4142, 0.0000, 0.0000"),
        "{out}"
    );
    assert!(out.contains("MESSAGE(\" abs 1.000000 1.000000\")"), "{out}");
    assert!(
        out.contains("SET_G5X_OFFSET(2, 0.7071, 0.7071, 0.0000"),
        "{out}"
    );
    assert!(
        out.contains("MESSAGE(\" now -1.000000 0.000000\")"),
        "{out}"
    );
}

/// `EXISTS[#n]` (in the parameter range), `##1`, and `#atan[1]/[1]` as a
/// parameter number (#45).
#[test]
fn numbered_exists_and_indirection() {
    let out = rules("parameters.ngc");
    assert!(
        out.contains("STRAIGHT_TRAVERSE(1.0000, 0.0000, 1.0000"),
        "{out}"
    );
    assert!(
        out.contains("STRAIGHT_TRAVERSE(1.0000, 0.0000, 3.0000"),
        "{out}"
    );
}

/// `o#<s> call` and `O[expr] call` call o2; `#<_value>` reads 0 before any
/// return.
#[test]
fn computed_oword_calls() {
    let out = rules("computed_call.ngc");
    assert_eq!(out.matches("MESSAGE(\" in two\")").count(), 2, "{out}");
    assert!(out.contains("MESSAGE(\" value 0.000000\")"), "{out}");
}

/// `O<title>` alone on the first line, `N12.5` (the fraction dropped), and
/// the `%d` `%.2f` `%f` value formats of DEBUG.
#[test]
fn title_line_fractional_n_and_debug_formats() {
    let out = rules("title_line.ngc");
    assert!(out.contains("SET_SPINDLE_SPEED(0, 100.0000)"), "{out}");
    assert!(out.contains("MESSAGE(\" 3 2.70 2.7000\")"), "{out}");
}

/// O0002 and O2 are one number: LinuxCNC calls the first; Fanuc keeps
/// reporting the second definition.
#[test]
fn first_program_of_a_number_wins_in_linuxcnc_only() {
    let out = rules("first_program.ngc");
    assert!(out.contains("MESSAGE(\" first\")"), "{out}");
    assert!(!out.contains("second"), "{out}");
    let o = cncc(&[
        "check",
        "--dialect",
        "fanuc",
        "tests/programs/fanuc/duplicate_program_number.nc",
    ]);
    assert!(stderr(&o).contains("E0304"), "{}", stderr(&o));
}

/// rs274 2.9 permutes the G84 feeds twice in G18 (a LinuxCNC bug kept for
/// the linuxcnc dialect only); Fanuc taps along Y.
#[test]
fn g84_in_g18_keeps_linuxcncs_bug_only_there() {
    let out = rules("g84_g18.ngc");
    assert!(
        out.contains("STRAIGHT_FEED(-1.0000, 1.0000, 1.0000"),
        "{out}"
    );
    assert!(
        out.contains("STRAIGHT_FEED(2.0000, 1.0000, 1.0000"),
        "{out}"
    );
    let out = canon("fanuc", "tests/programs/linuxcnc/rs274_rules/g84_g18.ngc");
    assert!(
        out.contains("STRAIGHT_FEED(0.0010, -0.0010, 0.0010"),
        "{out}"
    );
}

/// #5221 stays in machine units across G21; G10 L1 on row 1 (rs274's
/// spindle row before any change) rewrites row 0 and #5400; an arc whose
/// radii differ by 0.028 mm (inside 0.02 * sqrt 2) runs.
#[test]
fn stored_offsets_tool_row_and_arc_tolerance() {
    let out = rules("stored.ngc");
    assert_eq!(out.matches("MESSAGE(\" 1.000000\")").count(), 2, "{out}");
    assert!(
        out.contains("SET_TOOL_TABLE_ENTRY(0, 1, 0.0000 0.0000 0.0394"),
        "{out}"
    );
    assert!(out.contains("ARC_FEED(50.0000, 0.0000, 24.9860"), "{out}");
}

/// An A word in a canned-cycle block: rs274's "Cannot put an a in canned
/// cycle", on that line.
#[test]
fn rotary_word_in_a_cycle_is_refused() {
    let o = cncc(&[
        "canon",
        "--dialect",
        "linuxcnc",
        "tests/programs/linuxcnc/rs274_rules/a_in_cycle.ngc",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(
        e.contains("Cannot put an a in canned cycle") && e.contains(":2:"),
        "{e}"
    );
}

/// An o-word sub defined inside another: rs274's "Nested subroutine
/// definition", at the inner `sub`.
#[test]
fn nested_sub_definition_is_refused() {
    let o = cncc(&[
        "canon",
        "--dialect",
        "linuxcnc",
        "tests/programs/linuxcnc/rs274_rules/nested_sub.ngc",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(
        e.contains("Nested subroutine definition") && e.contains(":3:"),
        "{e}"
    );
}

/// M73's restore turns back on the mist that was on when saved, and turns
/// off nothing (rs274 2.9: the flood the sub turned on stays on).
#[test]
fn m73_restores_coolant_that_was_on() {
    let out = rules("m73_coolant.ngc");
    let tail = &out[out.find("FLOOD_ON()").expect("flood on in the sub")..];
    assert!(tail.contains("MIST_ON()"), "{out}");
    assert_eq!(out.matches("FLOOD_OFF()").count(), 2, "{out}");
}

/// rs274 drops blanks inside words (`o100 end sub`, `else if`, `end if`),
/// keeps only the last of two comments on a line, orients with M19 only
/// when R or P is given and waits only when Q is, and ends at a
/// main-program M99 as at M2, showing that line's comment (the calls rs274
/// printed, line for line).
#[test]
fn blanks_comments_m19_and_main_m99() {
    let out = rules("blanks_and_comments.ngc");
    let calls: Vec<&str> = out.lines().skip(6).take(9).collect();
    assert_eq!(
        calls,
        [
            "STRAIGHT_TRAVERSE(0.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)",
            "SET_FEED_RATE(100.0000)",
            "STRAIGHT_FEED(3.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)",
            "COMMENT(\"second\")",
            "STRAIGHT_TRAVERSE(1.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)",
            "ORIENT_SPINDLE(0, 45.0000, 0)",
            "ORIENT_SPINDLE(0, 0.0000, 1)",
            "SPINDLE.0.WAIT_ORIENT_COMPLETE(2.0000)",
            "COMMENT(\"the end\")",
        ],
        "{out}"
    );
    assert!(out.contains("PROGRAM_END()"), "{out}");
    assert!(!out.contains("PALLET_SHUTTLE"), "{out}");
}

/// Sub styles do not mix, and flow must not run into a sub it called:
/// rs274's error, on the line rs274 shows.
#[test]
fn mixed_sub_styles_are_refused_where_rs274_stops() {
    for (file, msg, line) in [
        (
            "sub_style_call.ngc",
            "Fanuc 'O....' subroutine must be called with 'M98'",
            5,
        ),
        (
            "sub_style_m98.ngc",
            "'O.... sub' subroutine must be called with 'O.... call'",
            5,
        ),
        (
            "sub_style_m99.ngc",
            "'O.... endsub' or 'O.... return' must follow",
            7,
        ),
        (
            "sub_after_call.ngc",
            "sub: o|7| found in illegal location",
            3,
        ),
    ] {
        let o = cncc(&[
            "canon",
            "--dialect",
            "linuxcnc",
            &format!("tests/programs/linuxcnc/rs274_rules/{file}"),
        ]);
        assert_eq!(o.status.code(), Some(1), "{file}");
        let e = stderr(&o);
        assert!(
            e.contains(msg) && e.contains(&format!("{file}:{line}:")),
            "{file}: {e}"
        );
    }
}

/// Nothing after the closing `%` is read (a nested comment and a bad word
/// there are no errors), with a note.
#[test]
fn text_after_the_closing_percent_is_not_read() {
    let o = cncc(&[
        "canon",
        "--dialect",
        "linuxcnc",
        "tests/programs/linuxcnc/rs274_rules/after_percent.ngc",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("W0007"), "{}", stderr(&o));
}

/// Zero-radius compensation (G41.1 D0) in G18: the arc is written in the
/// plane's axis order (Z X, then Y), as rs274 writes it.
#[test]
fn zero_radius_comp_arc_in_xz_keeps_the_plane_order() {
    let out = rules("d0_xz_arc.ngc");
    assert!(
        out.contains("ARC_FEED(3.0000, 1.0000, 2.0000, 1.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)"),
        "{out}"
    );
}
