//! `cncc canon --ini FILE --var-file FILE`: a LinuxCNC configuration's
//! `[RS274NGC]` settings and parameter file, as `rs274 -i` and `-v` take
//! them (facts checked with rs274 2.9; the suite's cases run against the
//! live rs274 in `linuxcnc_suite.rs`). These tests need no rs274.

use std::path::Path;
use std::process::{Command, Output};

/// Runs `cncc canon PROG --dialect linuxcnc ARGS...` in `dir`.
fn canon(dir: &Path, prog: &str, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(["canon", prog, "--dialect", "linuxcnc", "--color", "never"])
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .output()
        .expect("run cncc")
}

fn out(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A scratch folder holding `files` (name, text).
fn folder(files: &[(&str, &str)]) -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    for (name, text) in files {
        let p = d.path().join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }
    d
}

/// The JSON diagnostics of a run.
fn diags(o: &Output) -> Vec<serde_json::Value> {
    err(o)
        .lines()
        .filter_map(|l| serde_json::from_str(l).ok())
        .collect()
}

#[test]
fn orient_offset_is_added_to_every_m19_angle() {
    let d = folder(&[
        ("t.ngc", "M19 R45 Q2\nM19 P1\nM2\n"),
        ("t.ini", "[RS274NGC]\nORIENT_OFFSET = 42.0\n"),
    ]);
    let o = canon(d.path(), "t.ngc", &["--ini", "t.ini"]);
    assert!(o.status.success(), "{}", err(&o));
    assert!(
        out(&o).contains("ORIENT_SPINDLE(0, 87.0000, 0)"),
        "{}",
        out(&o)
    );
    assert!(
        out(&o).contains("ORIENT_SPINDLE(0, 42.0000, 1)"),
        "{}",
        out(&o)
    );
    let plain = canon(d.path(), "t.ngc", &[]);
    assert!(out(&plain).contains("ORIENT_SPINDLE(0, 45.0000, 0)"));
}

#[test]
fn ini_values_are_read_as_ini_parameters_unless_ini_vars_is_0() {
    let prog = "G0 X#<_ini[vars]toolchange_x> Y#<_InI[vars]toolchange_y>\nM2\n";
    let d = folder(&[
        ("t.ngc", prog),
        (
            "on.ini",
            "[RS274NGC]\n[VARS]\nTOOLCHANGE_X = 10\nTOOLCHANGE_Y = 2.5\n",
        ),
        (
            "off.ini",
            "[RS274NGC]\nINI_VARS = 0\n[VARS]\nTOOLCHANGE_X = 10\nTOOLCHANGE_Y = 2.5\n",
        ),
    ]);
    let o = canon(d.path(), "t.ngc", &["--ini", "on.ini"]);
    assert!(o.status.success(), "{}", err(&o));
    assert!(
        out(&o).contains("STRAIGHT_TRAVERSE(10.0000, 2.5000, 0.0000"),
        "{}",
        out(&o)
    );
    let o = canon(d.path(), "t.ngc", &["--ini", "off.ini", "--format", "json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(diags(&o)[0]["code"], "E0504", "{}", err(&o));
}

#[test]
fn an_ini_parameter_is_read_only() {
    let d = folder(&[
        ("t.ngc", "#<_ini[vars]x> = 3\nM2\n"),
        ("t.ini", "[VARS]\nX = 10\n"),
    ]);
    let o = canon(d.path(), "t.ngc", &["--ini", "t.ini"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        err(&o).contains("Cannot assign to read-only parameter #<_ini[vars]x>"),
        "{}",
        err(&o)
    );
}

#[test]
fn subroutine_path_is_searched_relative_to_the_ini() {
    let d = folder(&[
        ("prog/t.ngc", "o<helper> call [4]\nM2\n"),
        (
            "cfg/subs/helper.ngc",
            "o<helper> sub\n(debug, helper #1)\no<helper> endsub\nM2\n",
        ),
        (
            "cfg/machine.ini",
            "[RS274NGC]\nSUBROUTINE_PATH = nothere:subs\n",
        ),
    ]);
    let o = canon(
        d.path(),
        "prog/t.ngc",
        &["--ini", "cfg/machine.ini", "--format", "json"],
    );
    assert!(o.status.success(), "{}", err(&o));
    assert!(
        out(&o).contains("MESSAGE(\" helper 4.000000\")"),
        "{}",
        out(&o)
    );
    // The folder that does not exist is said, with its place in the INI.
    let d0 = diags(&o);
    assert_eq!(d0.len(), 1, "{}", err(&o));
    assert_eq!(d0[0]["code"], "W0595");
    assert_eq!(d0[0]["line"], 2);
    let without = canon(d.path(), "prog/t.ngc", &[]);
    assert_eq!(without.status.code(), Some(1), "{}", out(&without));
}

#[test]
fn disable_fanuc_style_sub_refuses_m98() {
    let prog = "M98 P1\nM30\nO1\nG0 X1\nM99\n";
    let d = folder(&[
        ("t.ngc", prog),
        ("no.ini", "[RS274NGC]\nDISABLE_FANUC_STYLE_SUB = 1\n"),
        ("yes.ini", "[RS274NGC]\nDISABLE_FANUC_STYLE_SUB = 0\n"),
    ]);
    let o = canon(d.path(), "t.ngc", &["--ini", "no.ini", "--format", "json"]);
    assert_eq!(o.status.code(), Some(1));
    let d0 = diags(&o);
    assert_eq!(d0[0]["code"], "E0594", "{}", err(&o));
    assert_eq!(d0[0]["line"], 1);
    assert!(canon(d.path(), "t.ngc", &["--ini", "yes.ini"])
        .status
        .success());
}

#[test]
fn the_parameter_file_sets_the_offsets_and_is_written_back() {
    let var = "31\t7.5\n5211 1\n5220 2\n5241 1.0\n5250 30\n";
    let d = folder(&[
        (
            "t.ngc",
            "(debug, #31 #5210 #5220)\nG10 L2 P1 X4\n#31 = 9\n#101 = 3\nM2\n",
        ),
        ("run.var", var),
    ]);
    let o = canon(d.path(), "t.ngc", &["--var-file", "run.var"]);
    assert!(o.status.success(), "{}", err(&o));
    let text = out(&o);
    // G55 (#5220 = 2) at X 1 inch, rotated 30 degrees; #5210 = 0: no G92.
    assert!(
        text.contains("SET_G5X_OFFSET(2, 25.4000, 0.0000, 0.0000"),
        "{text}"
    );
    assert!(
        text.contains("SET_G92_OFFSET(0.0000, 0.0000, 0.0000"),
        "{text}"
    );
    assert!(text.contains("SET_XY_ROTATION(30.0000)"), "{text}");
    assert!(
        text.contains("MESSAGE(\" 7.500000 0.000000 2.000000\")"),
        "{text}"
    );
    let back = std::fs::read_to_string(d.path().join("run.var")).unwrap();
    let lines: Vec<&str> = back.lines().collect();
    // The file's own number #31 and the 119 persistent ones, ascending.
    assert_eq!(lines.len(), 1 + 119, "{back}");
    assert_eq!(lines[0], "31\t9.000000");
    assert!(lines.contains(&"5211\t1.000000"), "kept though not applied");
    assert!(
        lines.contains(&"5221\t0.157480"),
        "G10 L2 P1 X4 (mm) in inches"
    );
    assert!(!back.contains("101\t"), "a parameter the file did not have");
}

#[test]
fn g92_persists_unless_the_ini_disables_it() {
    let var = "5210 1\n5211 1\n";
    let d = folder(&[
        ("t.ngc", "(debug, #5210 #5211)\nM2\n"),
        ("a.var", var),
        ("b.var", var),
        ("off.ini", "[RS274NGC]\nDISABLE_G92_PERSISTENCE = 1\n"),
    ]);
    let on = canon(d.path(), "t.ngc", &["--var-file", "a.var"]);
    assert!(
        out(&on).contains("SET_G92_OFFSET(25.4000, 0.0000"),
        "{}",
        out(&on)
    );
    assert!(out(&on).contains("MESSAGE(\" 1.000000 1.000000\")"));
    let off = canon(
        d.path(),
        "t.ngc",
        &["--var-file", "b.var", "--ini", "off.ini"],
    );
    assert!(
        out(&off).contains("SET_G92_OFFSET(0.0000, 0.0000"),
        "{}",
        out(&off)
    );
    assert!(out(&off).contains("MESSAGE(\" 0.000000 0.000000\")"));
    let b = std::fs::read_to_string(d.path().join("b.var")).unwrap();
    assert!(b.contains("5210\t0.000000\n5211\t0.000000\n"), "{b}");
}

#[test]
fn the_ini_names_the_parameter_file() {
    let d = folder(&[
        ("t.ngc", "(debug, #5161)\nM2\n"),
        ("cfg/m.ini", "[RS274NGC]\nPARAMETER_FILE = m.var\n"),
        ("cfg/m.var", "5161 2.5\n"),
    ]);
    let o = canon(d.path(), "t.ngc", &["--ini", "cfg/m.ini"]);
    assert!(out(&o).contains("MESSAGE(\" 2.500000\")"), "{}", out(&o));
}

#[test]
fn a_missing_parameter_file_starts_at_zero_and_is_created() {
    let d = folder(&[("t.ngc", "G10 L20 P1 X1\nM2\n")]);
    let o = canon(d.path(), "t.ngc", &["--var-file", "new.var"]);
    assert!(o.status.success(), "{}", err(&o));
    let text = std::fs::read_to_string(d.path().join("new.var")).unwrap();
    assert_eq!(text.lines().count(), 119);
}

#[test]
fn a_parameter_file_out_of_order_is_refused_and_left_alone() {
    let var = "5221 3\n5161 1\n";
    let d = folder(&[("t.ngc", "G0 X1\nM2\n"), ("bad.var", var)]);
    let o = canon(
        d.path(),
        "t.ngc",
        &["--var-file", "bad.var", "--format", "json"],
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(out(&o).is_empty(), "the program is not run: {}", out(&o));
    let d0 = diags(&o);
    assert_eq!(d0[0]["code"], "E0593", "{}", err(&o));
    assert_eq!(d0[0]["line"], 2);
    assert!(d0[0]["file"].as_str().unwrap().ends_with("bad.var"));
    assert_eq!(
        std::fs::read_to_string(d.path().join("bad.var")).unwrap(),
        var
    );
}

#[test]
fn a_parameter_line_rs274_skips_is_a_located_warning() {
    let d = folder(&[
        ("t.ngc", "(debug, #5162)\nM2\n"),
        ("w.var", "5161 x\n5162 2\n"),
    ]);
    let o = canon(
        d.path(),
        "t.ngc",
        &["--var-file", "w.var", "--format", "json"],
    );
    assert!(o.status.success(), "{}", err(&o));
    let d0 = diags(&o);
    assert_eq!(d0[0]["code"], "W0593", "{}", err(&o));
    assert_eq!(d0[0]["line"], 1);
    assert!(out(&o).contains("MESSAGE(\" 2.000000\")"));
}

#[test]
fn bad_ini_lines_and_settings_are_located_warnings() {
    let ini = "[RS274NGC]\nORIENT_OFFSET = abc\nnonsense\nREMAP = M400 modalgroup=10 ngc=m400\n";
    let d = folder(&[("t.ngc", "M19 R10\nM2\n"), ("t.ini", ini)]);
    let o = canon(d.path(), "t.ngc", &["--ini", "t.ini", "--format", "json"]);
    assert!(o.status.success(), "{}", err(&o));
    let mut got: Vec<(String, u64)> = diags(&o)
        .iter()
        .map(|j| {
            (
                j["code"].as_str().unwrap().to_string(),
                j["line"].as_u64().unwrap(),
            )
        })
        .collect();
    got.sort();
    assert_eq!(
        got,
        [
            ("W0594".into(), 3),
            ("W0595".into(), 2),
            ("W0596".into(), 4)
        ],
        "{}",
        err(&o)
    );
    assert!(
        out(&o).contains("ORIENT_SPINDLE(0, 10.0000, 0)"),
        "default offset 0"
    );
}

#[test]
fn a_dialect_without_the_capability_refuses_the_files() {
    let d = folder(&[("t.nc", "G0 X1\nM30\n"), ("t.ini", "[RS274NGC]\n")]);
    let o = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(["canon", "t.nc", "--dialect", "fanuc", "--ini", "t.ini"])
        .current_dir(d.path())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", err(&o));
    assert!(err(&o).contains("var-and-ini-files"), "{}", err(&o));
}

#[test]
fn an_abort_comment_stops_the_run_with_its_text() {
    let d = folder(&[("t.ngc", "#1 = 20\n(abort, stop at #1)\nG0 X1\nM2\n")]);
    let o = canon(d.path(), "t.ngc", &["--format", "json"]);
    assert_eq!(o.status.code(), Some(1));
    let d0 = diags(&o);
    assert_eq!(d0[0]["code"], "E0595", "{}", err(&o));
    assert_eq!(d0[0]["message"], " stop at 20.000000");
    assert!(!out(&o).contains("STRAIGHT_TRAVERSE"));
}

#[test]
fn check_reads_the_configuration_too() {
    let d = folder(&[
        ("t.ngc", "o<helper> call [4]\nG0 X#<_ini[vars]x>\nM2\n"),
        (
            "cfg/subs/helper.ngc",
            "o<helper> sub\nG0 X#1\no<helper> endsub\nM2\n",
        ),
        (
            "cfg/m.ini",
            "[RS274NGC]\nSUBROUTINE_PATH = subs\n[VARS]\nX = 3\n",
        ),
    ]);
    let check = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_cncc"))
            .args([
                "check",
                "t.ngc",
                "--dialect",
                "linuxcnc",
                "--format",
                "json",
            ])
            .args(args)
            .current_dir(d.path())
            .output()
            .unwrap()
    };
    let codes = |o: &Output| -> Vec<String> {
        diags(o)
            .iter()
            .map(|j| j["code"].as_str().unwrap().to_string())
            .collect()
    };
    // Alone: the sub is not found and the INI value is unknown.
    assert_eq!(codes(&check(&[])), ["W0591", "W0590"]);
    let with = check(&["--ini", "cfg/m.ini"]);
    assert!(with.status.success(), "{}", err(&with));
    assert!(codes(&with).is_empty(), "{}", err(&with));
}
