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
