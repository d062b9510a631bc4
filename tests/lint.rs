//! The lint rules (W07xx): each has, in at least two dialects, a program
//! that breaks it and one that does not (`tests/programs/lint/`, named
//! `CODE-DIALECT-bad|good.ext`). Also: the defaults, `cncc.toml`,
//! `--select`/`--ignore`, inline directives and SARIF output.

mod common;
use common::*;
use std::collections::BTreeSet;

/// The lint codes a check of `file` reports with every rule selected.
fn lint_codes(args: &[&str]) -> BTreeSet<String> {
    let mut a = vec!["check", "--format", "json"];
    a.extend_from_slice(args);
    let o = cncc(&a);
    assert!(
        matches!(o.status.code(), Some(0) | Some(1)),
        "{}",
        stderr(&o)
    );
    stderr(&o)
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter_map(|v| v["code"].as_str().map(str::to_string))
        .filter(|c| c.starts_with("W07"))
        .collect()
}

#[test]
fn every_rule_has_a_bad_and_a_good_program_in_two_dialects() {
    let dir = root().join("tests/programs/lint");
    let mut dialects: std::collections::BTreeMap<String, BTreeSet<String>> = Default::default();
    for e in std::fs::read_dir(&dir).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_stem().unwrap().to_str().unwrap().to_string();
        let parts: Vec<&str> = name.split('-').collect();
        let [code, dialect, kind] = parts[..] else {
            panic!("{name}: CODE-DIALECT-bad|good")
        };
        let p = path.to_str().unwrap();
        let found = lint_codes(&["--dialect", dialect, "--select", "ALL", p]);
        match kind {
            "bad" => assert!(
                found.contains(code),
                "{name}: {code} not reported ({found:?})"
            ),
            "good" => assert!(found.is_empty(), "{name}: reported {found:?}"),
            _ => panic!("{name}"),
        }
        dialects
            .entry(code.to_string())
            .or_default()
            .insert(dialect.to_string());
    }
    for rule in cncc::lint::rules::RULES {
        let code = rule.code.code();
        let n = dialects.get(code).map_or(0, |d| d.len());
        assert!(n >= 2, "{code}: programs in {n} dialect(s)");
        let o = cncc(&["explain", code]);
        let text = stdout(&o);
        assert!(
            text.contains("Bad:") && text.contains("Good:"),
            "{code}: explain text"
        );
    }
}

#[test]
fn defaults_leave_out_the_rules_often_wrong() {
    let p = "tests/programs/lint/W0711-fanuc-bad.nc";
    assert!(lint_codes(&["--dialect", "fanuc", p]).is_empty());
    let p = "tests/programs/lint/W0709-fanuc-bad.nc";
    assert!(lint_codes(&["--dialect", "fanuc", p]).is_empty());
    let p = "tests/programs/lint/W0701-fanuc-bad.nc";
    assert!(lint_codes(&["--dialect", "fanuc", p]).contains("W0701"));
    // A finding is a warning: the check still passes.
    assert_eq!(
        cncc(&["check", "--dialect", "fanuc", p]).status.code(),
        Some(0)
    );
    assert!(lint_codes(&["--dialect", "fanuc", "--no-lint", p]).is_empty());
    assert!(lint_codes(&[
        "--dialect",
        "fanuc",
        "--ignore",
        "feed-with-spindle-stopped",
        p
    ])
    .is_empty());
}

#[test]
fn the_shops_cncc_toml_selects_ignores_and_raises() {
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("jobs/part1");
    std::fs::create_dir_all(&sub).unwrap();
    let prog = sub.join("p.nc");
    std::fs::copy(root().join("tests/programs/lint/W0711-fanuc-bad.nc"), &prog).unwrap();
    let p = prog.to_str().unwrap();
    std::fs::write(
        dir.path().join("cncc.toml"),
        "[lint]\nextend-select = [\"no-work-offset\"]\nerror = [\"W0711\"]\n",
    )
    .unwrap();
    let o = cncc(&["check", "--dialect", "fanuc", p]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("error[W0711 no-work-offset]"));
    // The command line's --ignore comes after the file's selection.
    assert!(lint_codes(&["--dialect", "fanuc", "--ignore", "W07", p]).is_empty());
    std::fs::write(
        dir.path().join("cncc.toml"),
        "[lint]\nselect = [\"E0201\"]\n",
    )
    .unwrap();
    let o = cncc(&["check", "--dialect", "fanuc", p]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("not a lint rule"), "{}", stderr(&o));
}

#[test]
fn inline_directives_in_each_comment_syntax() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("fanuc", "a.nc", "%\nO1\nG21 G90 G54\nT1 M6\nG43 H1 Z5.\nG1 Z-1. F100. (cncc: ignore[W0701])\nM30\n%\n"),
        ("fanuc", "b.nc", "%\nO1\nG21 G90 G54\nT1 M6\nG43 H1 Z5.\n(cncc: ignore[feed-with-spindle-stopped])\nG1 Z-1. F100.\nM30\n%\n"),
        ("siemens840d", "c.mpf", "G71 G90 G54\nT1 D1 M6\nG1 Z-1 F100 ; cncc: ignore[W0701]\nM30\n"),
        ("heidenhain", "d.h", "BEGIN PGM D MM\n; cncc: ignore-file[W0701]\nTOOL CALL 1 Z S3000\nL Z-1 R0 F100\nEND PGM D MM\n"),
    ];
    for (d, name, text) in cases {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        let p = p.to_str().unwrap();
        assert!(lint_codes(&["--dialect", d, p]).is_empty(), "{name}");
        let plain = text.replace("cncc:", "note:");
        std::fs::write(p, plain).unwrap();
        assert!(
            lint_codes(&["--dialect", d, p]).contains("W0701"),
            "{name} without the directive"
        );
    }
}

#[test]
fn sarif_output_for_ci() {
    let p = "tests/programs/lint/W0703-fanuc-bad.nc";
    let o = cncc(&["check", "--dialect", "fanuc", "--format", "sarif", p]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("one SARIF document");
    assert_eq!(v["version"], "2.1.0");
    let run = &v["runs"][0];
    assert_eq!(run["tool"]["driver"]["name"], "cncc");
    let r = &run["results"][0];
    assert_eq!(r["ruleId"], "W0703");
    assert_eq!(r["level"], "warning");
    let region = &r["locations"][0]["physicalLocation"]["region"];
    assert_eq!(region["startLine"], 6);
    let idx = r["ruleIndex"].as_u64().unwrap() as usize;
    assert_eq!(run["tool"]["driver"]["rules"][idx]["id"], "W0703");
    // A clean program still gets a document, with no results.
    let o = cncc(&[
        "check",
        "--dialect",
        "fanuc",
        "--format",
        "sarif",
        "tests/programs/lint/W0703-fanuc-good.nc",
    ]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["runs"][0]["results"].as_array().unwrap().len(), 0);
}

#[test]
fn inch_values_in_a_program_without_units_are_a_note_on_w0710() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("p.nc");
    let text = "%\nO1\nG90 G54\nT1 M6\nS3000 M3\nG43 H1 Z.2\nG0 X0 Y0\nG1 Z-.25 F10.\nG1 X2. Y1.5\nG0 Z.2\nM30\n%\n";
    std::fs::write(&p, text).unwrap();
    let p = p.to_str().unwrap();
    let o = cncc(&[
        "check",
        "--dialect",
        "fanuc",
        "--select",
        "W07",
        "--format",
        "json",
        p,
    ]);
    let found: Vec<serde_json::Value> = stderr(&o)
        .lines()
        .filter_map(|l| serde_json::from_str(l).ok())
        .collect();
    assert!(!found.iter().any(|v| v["code"] == "W0719"), "{found:?}");
    let w0710 = found.iter().find(|v| v["code"] == "W0710").expect("W0710");
    assert!(
        w0710["notes"].to_string().contains("look like inches"),
        "{w0710}"
    );
    // With G21 in the program the same values are W0719.
    std::fs::write(p, text.replace("G90 G54", "G21 G90 G54")).unwrap();
    assert!(lint_codes(&["--dialect", "fanuc", "--select", "W0719", p]).contains("W0719"));
}
