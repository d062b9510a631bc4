//! Controller semantics that are data, not LinuxCNC's for everyone: tools
//! the control holds (no tool table needed), the program's own tool list,
//! cutter-compensation start-up rules, and the machine's reference point.

mod common;
use common::*;

fn run(args: &[&str]) -> (i32, String, String) {
    let o = cncc(args);
    (o.status.code().unwrap_or(-1), stdout(&o), stderr(&o))
}

const T: &str = "tests/programs/tools";

#[test]
fn a_fanuc_tool_missing_from_the_table_runs_with_no_size() {
    let (code, _, err) = run(&["check", &format!("{T}/holds.nc")]);
    assert_eq!(code, 0, "{err}");
    // Compensation needed the radius: said once, with what was not checked.
    assert!(err.contains("W0592"), "{err}");
    assert!(
        err.contains("T23 ran with no length and no diameter"),
        "{err}"
    );
    assert!(err.contains("gouges were not checked"), "{err}");
}

#[test]
fn linuxcnc_still_needs_the_tool_in_its_table() {
    let (code, _, err) = run(&["check", &format!("{T}/holds.ngc")]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("E0501"), "{err}");
}

#[test]
fn a_short_entry_move_is_linuxcncs_rule_only() {
    let table = format!("{T}/mm.tbl");
    let args = |f: &str| {
        vec![
            "check".to_string(),
            format!("{T}/{f}"),
            "--tool-table".into(),
            table.clone(),
            "--machine-units".into(),
            "mm".into(),
        ]
    };
    let o = cncc(
        &args("short_entry.nc")
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "Fanuc starts up on a short entry: {}",
        stderr(&o)
    );
    let o = cncc(
        &args("short_entry.ngc")
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("E0552"), "{}", stderr(&o));
}

#[test]
fn g41_while_on_changes_the_offset_on_fanuc() {
    let (code, _, err) = run(&[
        "check",
        &format!("{T}/comp_again.nc"),
        "--tool-table",
        &format!("{T}/mm.tbl"),
        "--machine-units",
        "mm",
    ]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn the_programs_tool_list_gives_the_sizes() {
    let (code, out, err) = run(&["stats", "tests/programs/fusion/bracket.nc"]);
    assert_eq!(code, 0, "{err}");
    let row = |t: &str| {
        out.lines()
            .find(|l| l.starts_with(t))
            .unwrap_or("")
            .to_string()
    };
    assert!(row("T1 ").split_whitespace().nth(1) == Some("10"), "{out}");
    assert!(row("T2 ").split_whitespace().nth(1) == Some("6.8"), "{out}");
    assert!(!err.contains("W0592"), "no invented sizes: {err}");
}

#[test]
fn a_reference_return_goes_up_to_the_machines_reference_point() {
    // The default machine: work zero 500 mm below the reference point.
    let (code, out, err) = run(&["stats", "tests/programs/fusion/bracket.nc"]);
    assert_eq!(code, 0, "{err}");
    let total = out.lines().find(|l| l.starts_with("total")).unwrap();
    assert!(total.ends_with("Z -12..500"), "{out}");
    // A machine file moves it: G54 300 mm below the reference point.
    let (code, out, err) = run(&[
        "stats",
        &format!("{T}/home.nc"),
        "--machine",
        &format!("{T}/vmc.toml"),
        "--tool-table",
        &format!("{T}/mm.tbl"),
        "--machine-units",
        "mm",
    ]);
    assert_eq!(code, 0, "{err}");
    // The tip of the 50 mm tool, with the spindle at the reference point.
    let total = out.lines().find(|l| l.starts_with("total")).unwrap();
    assert!(total.ends_with("Z -2..250"), "{out}");
}

#[test]
fn a_wrong_machine_file_is_a_usage_error() {
    let (code, _, err) = run(&[
        "check",
        &format!("{T}/home.nc"),
        "--machine",
        &format!("{T}/bad.toml"),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("bad.toml"), "{err}");
    assert!(err.contains("unknown field"), "{err}");
}

#[test]
fn canon_keeps_rs274s_machine_without_a_file() {
    // rs274's standalone state: every stored position 0, so G28 goes to
    // work Z0 less the tool length. canon stays comparable with it.
    let (code, out, err) = run(&["canon", "--dialect", "fanuc", &format!("{T}/home.nc")]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000"),
        "{out}"
    );
}

#[test]
fn one_check_reports_every_independent_run_time_mistake() {
    // A bad arc, then a zero feed, then a move that still has none: each
    // is reported with its place, and the run goes on after each.
    let (code, _, err) = run(&["check", &format!("{T}/three_mistakes.nc")]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("three_mistakes.nc:6:"), "{err}");
    assert!(err.contains("three_mistakes.nc:9:"), "{err}");
    assert!(err.contains("three_mistakes.nc:10:"), "{err}");
    assert!(err.contains("3 errors"), "{err}");
    // canon stops at the first, as rs274 does.
    let o = cncc(&[
        "canon",
        "--dialect",
        "fanuc",
        &format!("{T}/three_mistakes.nc"),
    ]);
    assert_eq!(stderr(&o).matches("error[").count(), 1, "{}", stderr(&o));
}
