//! The command-line contract, tried as a user would: exit codes, silence on
//! clean programs, rendered diagnostics, `explain`, `dialects`, `port`.

mod common;
use common::*;

#[test]
fn clean_programs_check_silently() {
    for (dialect, file) in [
        ("fanuc", "tests/programs/fanuc/bracket.nc"),
        ("haas", "tests/programs/haas/plate.nc"),
        ("linuxcnc", "tests/programs/linuxcnc/subs.ngc"),
        ("siemens840d", "tests/programs/siemens840d/plate.mpf"),
    ] {
        let o = check_clean(dialect, file);
        assert_eq!(o.status.code(), Some(0), "{file}: {}", stderr(&o));
        assert_eq!(stdout(&o), "", "{file}");
        assert_eq!(stderr(&o), "", "{file}");
    }
}

/// `check` with the program's own tool table (`NAME.tbl` beside it) if it has one.
fn check_clean(dialect: &str, file: &str) -> std::process::Output {
    let table = std::path::Path::new(file).with_extension("tbl");
    if root().join(&table).exists() {
        cncc(&[
            "check",
            "--dialect",
            dialect,
            "--tool-table",
            table.to_str().unwrap(),
            file,
        ])
    } else {
        cncc(&["check", "--dialect", dialect, file])
    }
}

#[test]
fn detection_without_dialect_is_quiet_on_clean_files() {
    let o = cncc(&[
        "check",
        "--tool-table",
        "tests/programs/siemens840d/plate.tbl",
        "tests/programs/siemens840d/plate.mpf",
        "tests/programs/linuxcnc/subs.ngc",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "");
}

fn check_snapshot(name: &str, dialect: &str, file: &str) {
    let o = cncc(&["check", "--dialect", dialect, file]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    insta::assert_snapshot!(name, stderr(&o));
}

#[test]
fn fanuc_mistakes_are_all_reported() {
    check_snapshot(
        "check_fanuc_mistakes",
        "fanuc",
        "tests/programs/fanuc/mistakes.nc",
    );
}

#[test]
fn linuxcnc_mistakes_are_all_reported() {
    check_snapshot(
        "check_linuxcnc_mistakes",
        "linuxcnc",
        "tests/programs/linuxcnc/mistakes.ngc",
    );
}

#[test]
fn siemens_mistakes_are_all_reported() {
    check_snapshot(
        "check_siemens_mistakes",
        "siemens840d",
        "tests/programs/siemens840d/mistakes.mpf",
    );
}

#[test]
fn json_diagnostics_one_object_per_line() {
    let o = cncc(&[
        "check",
        "--dialect",
        "fanuc",
        "--format",
        "json",
        "tests/programs/fanuc/mistakes.nc",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let text = stderr(&o);
    let mut n = 0;
    for line in text.lines() {
        let v: serde_json::Value = serde_json::from_str(line).expect("one JSON object per line");
        for key in [
            "code",
            "name",
            "severity",
            "message",
            "file",
            "line",
            "column",
            "end_line",
            "end_column",
            "labels",
        ] {
            assert!(v.get(key).is_some(), "missing {key} in {line}");
        }
        n += 1;
    }
    assert!(n >= 10, "expected every mistake reported, got {n}");
}

#[test]
fn every_reported_code_is_explained() {
    let o = cncc(&[
        "check",
        "--dialect",
        "fanuc",
        "--format",
        "json",
        "tests/programs/fanuc/mistakes.nc",
    ]);
    for line in stderr(&o).lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        let code = v["code"].as_str().unwrap();
        let e = cncc(&["explain", code]);
        assert_eq!(e.status.code(), Some(0), "explain {code}");
        assert!(stdout(&e).contains(v["name"].as_str().unwrap()));
    }
}

#[test]
fn explain_unknown_code_is_usage_error() {
    assert_eq!(cncc(&["explain", "E9999"]).status.code(), Some(2));
}

#[test]
fn missing_file_is_io_error() {
    let o = cncc(&["check", "no/such/file.nc"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no/such/file.nc"));
}

#[test]
fn dialects_lists_the_built_ins() {
    let o = cncc(&["dialects"]);
    assert_eq!(o.status.code(), Some(0));
    for id in ["fanuc", "haas", "linuxcnc", "siemens840d"] {
        assert!(stdout(&o).contains(id), "{id} missing");
    }
}

#[test]
fn aliases_resolve() {
    for alias in ["sinumerik", "840d"] {
        let o = cncc(&[
            "check",
            "--dialect",
            alias,
            "tests/programs/siemens840d/control.mpf",
        ]);
        assert_eq!(o.status.code(), Some(0), "{alias}: {}", stderr(&o));
    }
    let o = cncc(&[
        "check",
        "--dialect",
        "rs274ngc",
        "tests/programs/linuxcnc/subs.ngc",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn port_to_own_dialect_is_a_fixpoint() {
    let dir = tempfile::tempdir().unwrap();
    for (dialect, file) in [
        ("fanuc", "tests/programs/fanuc/macro.nc"),
        ("linuxcnc", "tests/programs/linuxcnc/flow.ngc"),
        ("siemens840d", "tests/programs/siemens840d/control.mpf"),
        ("fanuc", "tests/programs/fanuc/bracket.nc"),
        ("haas", "tests/programs/haas/plate.nc"),
        ("linuxcnc", "tests/programs/linuxcnc/subs.ngc"),
        ("siemens840d", "tests/programs/siemens840d/plate.mpf"),
    ] {
        let once = dir.path().join(format!("once.{dialect}"));
        let twice = dir.path().join(format!("twice.{dialect}"));
        let o = cncc(&[
            "port",
            file,
            "--from",
            dialect,
            "--to",
            dialect,
            "-o",
            once.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{file}: {}", stderr(&o));
        let o = cncc(&[
            "port",
            once.to_str().unwrap(),
            "--from",
            dialect,
            "--to",
            dialect,
            "-o",
            twice.to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{file} (second port): {}",
            stderr(&o)
        );
        let a = std::fs::read_to_string(&once).unwrap();
        let b = std::fs::read_to_string(&twice).unwrap();
        assert_eq!(a, b, "{file}: porting the port changed it");
    }
}

#[test]
fn fanuc_port_writes_decimal_points_on_lengths() {
    let o = cncc(&[
        "port",
        "tests/programs/linuxcnc/subs.ngc",
        "--from",
        "linuxcnc",
        "--to",
        "linuxcnc",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = cncc(&["port", "tests/programs/fanuc/bracket.nc", "--to", "fanuc"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.contains("X135."), "{text}");
}

#[test]
fn failed_port_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.nc");
    let o = cncc(&[
        "port",
        "tests/programs/fanuc/mistakes.nc",
        "--to",
        "fanuc",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(!out.exists(), "a failed port left a file");
}

#[test]
fn no_run_only_reads() {
    let file = "tests/programs/linuxcnc/runtime/division-by-zero.ngc";
    let o = cncc(&["check", file]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("E0503"));
    let o = cncc(&["check", "--no-run", file]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// A Siemens tool called by name: without `--tool-table` the run goes on
/// with W0516 (a tool of no size); with a table the name is a row's
/// comment, and a name missing from a given table is E0501.
#[test]
fn named_tools_without_a_table_warn_and_with_one_must_be_there() {
    let dir = tempfile::tempdir().unwrap();
    let mpf = dir.path().join("named.mpf");
    std::fs::write(&mpf, "T=\"FACEMILL 63\"\nM6\nD1\nG0 X0 Y0 Z10\nM30\n").unwrap();
    let mpf = mpf.to_str().unwrap();
    let o = cncc(&["check", mpf]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        err.contains("warning[W0516 named-tool-without-table]"),
        "{err}"
    );
    let with = dir.path().join("with.tbl");
    std::fs::write(&with, "T7 P7 Z2.0 D2.48 ;FACEMILL 63\n").unwrap();
    let o = cncc(&["check", "--tool-table", with.to_str().unwrap(), mpf]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("W0516"), "{}", stderr(&o));
    let without = dir.path().join("without.tbl");
    std::fs::write(&without, "T7 P7 Z2.0 D2.48 ;CUTTER 16\n").unwrap();
    let o = cncc(&["check", "--tool-table", without.to_str().unwrap(), mpf]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("E0501"), "{}", stderr(&o));
}

/// Several files are checked on every core: the notes and diagnostics
/// come out as they do file by file, in the order the files were given.
#[test]
fn a_multi_file_check_reports_each_file_in_input_order() {
    let root = common::root().join("tests/programs");
    let files: Vec<String> = [
        "fanuc/mistakes.nc",
        "linuxcnc/mistakes.ngc",
        "fanuc/demo_part.nc",
        "linuxcnc/g81-no-r.ngc",
        "fanuc/oriented_boring_mistakes.nc",
        "linuxcnc/flow.ngc",
        "fanuc/duplicate_program_number.nc",
        "linuxcnc/g82-no-p.ngc",
    ]
    .iter()
    .map(|f| root.join(f).display().to_string())
    .collect();
    let summary = |l: &&str| {
        let l = l.trim();
        !(l.ends_with(" warnings") || l.ends_with(" warning") || l.contains(" error"))
            || l.starts_with("error[")
    };
    let body = |o: &std::process::Output| -> Vec<String> {
        common::stderr(o)
            .lines()
            .filter(summary)
            .map(str::to_string)
            .collect()
    };
    let mut args = vec!["check", "--color", "never"];
    args.extend(files.iter().map(String::as_str));
    let together = body(&common::cncc(&args));
    let (mut notes, mut alone) = (Vec::new(), Vec::new());
    for f in &files {
        for l in body(&common::cncc(&["check", "--color", "never", f])) {
            if l.starts_with("note: reading") {
                notes.push(l);
            } else {
                alone.push(l);
            }
        }
    }
    notes.extend(alone);
    assert!(together.len() > 40, "{}", together.join("\n"));
    assert_eq!(together, notes);
}
