//! Subprograms, macros, PROCs and subroutine libraries checked alone
//! (shops keep them as files of their own): `check` reads them whole,
//! runs them with their caller's values unknown, and stops the run-time
//! checks with W0590 at the first such value instead of failing. A call to
//! a program that is not beside the file is W0591 and the run goes on.

mod common;
use common::*;

fn check(dialect: &str, file: &str) -> (i32, String) {
    let path = format!("tests/programs/fragments/{file}");
    let o = cncc(&["check", "--dialect", dialect, &path]);
    (o.status.code().unwrap_or(-1), stderr(&o))
}

#[test]
fn a_macro_stops_at_its_first_argument_with_a_warning() {
    let (code, err) = check("fanuc", "o9001.nc");
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("warning[W0590 value-from-outside]"), "{err}");
    assert!(err.contains("`#1` gets its value from the caller"), "{err}");
    assert!(
        err.contains("o9001.nc:3:"),
        "stops where #1 is first read: {err}"
    );
}

#[test]
fn a_subprogram_cuts_at_its_callers_feed() {
    let (code, err) = check("fanuc", "o9002.nc");
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("`F` gets its value from the caller"), "{err}");
}

#[test]
fn a_mistake_before_the_first_argument_is_still_found() {
    let (code, err) = check("fanuc", "o9003.nc");
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("E0508"),
        "the arc's end is off its circle: {err}"
    );
}

#[test]
fn a_proc_runs_with_its_parameters_unknown() {
    let (code, err) = check("siemens840d", "SLOT.SPF");
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("`DEPTH` gets its value from the caller"),
        "{err}"
    );
}

#[test]
fn each_subroutine_of_a_library_is_run() {
    let (code, err) = check("linuxcnc", "library.ngc");
    assert_eq!(code, 0, "{err}");
    // Both subroutines stop at their first parameter: two warnings, and no
    // "file ended with no percent sign" for a file that is no main program.
    assert_eq!(err.matches("W0590").count(), 2, "{err}");
    assert!(!err.contains("E0305"), "{err}");
}

#[test]
fn a_call_to_a_program_the_control_holds_is_a_warning() {
    let (code, err) = check("fanuc", "o1000.nc");
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("warning[W0591 called-program-missing]"),
        "{err}"
    );
    assert!(err.contains("subprogram 9810"), "{err}");
}

#[test]
fn a_main_program_is_still_run_by_its_own_rules() {
    // #100 is vacant in a main program: Fanuc takes it as 0 in arithmetic,
    // and the division alarms.
    let (code, err) = check("fanuc", "o1001.nc");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("E0503"), "{err}");
}

#[test]
fn canon_keeps_a_missing_program_an_error_as_rs274_does() {
    let o = cncc(&[
        "canon",
        "--dialect",
        "fanuc",
        "tests/programs/fragments/o1000.nc",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("E0301"), "{}", stderr(&o));
}
