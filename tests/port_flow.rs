//! Issue 13: control flow, parameters and called programs for targets
//! that lack the source's forms. Each test ports a small program of its
//! own (`tests/programs/port_flow/`) with `--verify`.

mod common;
use common::{cncc, stderr, stdout};

const DIR: &str = "tests/programs/port_flow";

fn port_verified(to: &str, file: &str) -> String {
    let path = format!("{DIR}/{file}");
    let out = cncc(&["port", "--to", to, "--verify", &path]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{file} -> {to}:\n{err}");
    assert!(err.contains("verify: OK"), "{file} -> {to}: {err}");
    stdout(&out)
}

/// Macro B has only `IF [c] GOTO n`: IF/ELSE (Siemens) and
/// if/elseif/else (LinuxCNC) become jumps on the exact negation of each
/// condition (De Morgan for AND).
#[test]
fn structured_if_becomes_conditional_jumps() {
    for to in ["fanuc", "haas"] {
        for file in ["if_else.mpf", "if_elseif.ngc"] {
            let out = port_verified(to, file);
            assert!(out.contains("IF [#2 LE 3] GOTO"), "{to}:\n{out}");
            let code: Vec<&str> = out.lines().filter(|l| !l.starts_with('(')).collect();
            assert!(
                !code
                    .iter()
                    .any(|l| l.contains("ELSE") || l.contains("ENDIF")),
                "{out}"
            );
            // The port's own labels are numbers only, not comments.
            assert!(!out.contains("CNCC_"), "{out}");
        }
        let out = port_verified(to, "if_else.mpf");
        assert!(out.contains("IF [[#1 NE #2] OR [#2 GE 5]] GOTO"), "{out}");
    }
    port_verified("linuxcnc", "if_else.mpf");
}

/// A loop tested at its end is a backward jump; `break` jumps past it,
/// `continue` to its test.
#[test]
fn do_while_becomes_a_backward_jump() {
    for to in ["fanuc", "haas"] {
        let out = port_verified(to, "do_while.ngc");
        assert!(out.contains("IF [#1 LT 10] GOTO"), "{to}:\n{out}");
        let code: Vec<&str> = out.lines().filter(|l| !l.starts_with('(')).collect();
        assert!(
            !code.iter().any(|l| l.contains("do") || l.contains("while")),
            "{out}"
        );
    }
}

/// Named parameters become free common variables, a subroutine's locals
/// apart from the main program's (the main program's `step` stays 5
/// after the call sets the subroutine's).
#[test]
fn named_parameters_become_common_variables() {
    let out = port_verified("fanuc", "named_params.ngc");
    assert!(out.contains("#100=-2 (#100 = _DEPTH)"), "{out}");
    assert!(out.contains("#101=5 (#101 = STEP)"), "{out}");
    assert!(out.contains("#102=[#1*2] (#102 = STEP)"), "{out}");
    assert!(out.contains("G1 X#102 Z#100 F200"), "{out}");
    port_verified("haas", "named_params.ngc");
}

/// A PROC file is a macro program whose parameters arrive on the
/// argument letters in order; the body's own R1 (Fanuc `#1`) moves off
/// the first argument's local. For LinuxCNC it is a subroutine file.
#[test]
fn proc_file_is_the_target_s_called_program() {
    let fanuc = port_verified("fanuc", "KONUS.SPF");
    assert!(
        fanuc.contains("(G65 ARGUMENTS A=RSTART B=DEPTH)"),
        "{fanuc}"
    );
    assert!(fanuc.contains("#4=#1\n"), "{fanuc}");
    assert!(fanuc.contains("#3=#2\n"), "{fanuc}");
    assert!(fanuc.trim_end().ends_with("M99"), "{fanuc}");
    let lcnc = port_verified("linuxcnc", "KONUS.SPF");
    assert!(
        lcnc.trim_start()
            .starts_with("o<konus> sub\n#<rstart>=#1\n#<depth>=#2\n"),
        "{lcnc}"
    );
    assert!(lcnc.trim_end().ends_with("o<konus> endsub"), "{lcnc}");
}

/// `L140(1, 2.5)` passes its arguments as the ported PROC reads them;
/// an empty slot passes 0, each letter with its decimal point.
#[test]
fn procedure_calls_pass_arguments_in_order() {
    let fanuc = port_verified("fanuc", "calls.mpf");
    assert!(fanuc.contains("G65 P140 A1. B2.5\n"), "{fanuc}");
    assert!(fanuc.contains("G65 P140 A3. B0.\n"), "{fanuc}");
    let lcnc = port_verified("linuxcnc", "calls.mpf");
    assert!(lcnc.contains("o<l140> call [1] [2.5]"), "{lcnc}");
}

/// The same G number is another function on another control: LinuxCNC's
/// G5.1 spline is never written as Fanuc's G5.1 (AI contour control).
#[test]
fn a_source_g_function_is_not_written_by_number() {
    for to in ["fanuc", "haas"] {
        let out = cncc(&["port", "--to", to, &format!("{DIR}/spline.ngc")]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(1), "{err}");
        assert!(err.contains("E0601") && err.contains("G5.1"), "{err}");
        assert!(stdout(&out).is_empty());
    }
}

/// G642 smoothing changes no programmed position: a comment and a note.
#[test]
fn smoothing_modes_the_target_lacks_are_comments() {
    let path = format!("{DIR}/smoothing.mpf");
    let out = cncc(&["port", "--to", "fanuc", "--verify", &path]);
    let err = stderr(&out);
    assert!(err.contains("W0610") && err.contains("G642"), "{err}");
    let text = stdout(&out);
    assert!(
        text.contains("(G642: continuous path with smoothing"),
        "{text}"
    );
    let code: Vec<String> = text
        .lines()
        .map(|l| l.split('(').next().unwrap_or("").to_string())
        .collect();
    assert!(
        !code
            .iter()
            .any(|l| l.contains("G642") || l.contains("G601")),
        "{text}"
    );
}
