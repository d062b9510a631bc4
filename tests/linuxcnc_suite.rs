//! LinuxCNC's own interpreter regression tests (`../shared/conformance/
//! linuxcnc/`, the `tests/` fixtures of LinuxCNC's repository) run through
//! the live `rs274` and through `cncc canon --dialect linuxcnc` by that
//! folder's `run.sh`, and judged here (issue 16):
//!
//! * every case rs274 runs to the end must give identical canonical calls
//!   (`canon-diff`), and every case rs274 rejects must be rejected by cncc at
//!   the same place, unless it is listed in [`KNOWN`] with its reason;
//! * every case `run.sh` cannot run (N/A) must be listed in [`NOT_APPLICABLE`]
//!   with its reason;
//! * a listed case that now passes fails the test, so the list shrinks;
//! * the N/A cases that need only an INI or a parameter file are run by
//!   [`linuxcnc_ini_cases`] with `--ini`/`--var-file` (`run.sh` runs cncc
//!   without them): see `linuxcnc_suite/ini_cases.rs`.
//!
//! Skipped with a note when `../shared` or `rs274` (Debian
//! `linuxcnc-uspace`) is absent; `CNCC_REQUIRE_ORACLE=1` (CI) turns the skip
//! into a failure. One `run.sh` pass takes about 70 s on two cores; it runs
//! each case in its own scratch folder with a private `$HOME` (rs274 2.9
//! keeps its tool table in `$HOME/.tool.mmap`), so it is parallel-safe.

mod common;
#[path = "linuxcnc_suite/ini_cases.rs"]
mod ini_cases;

use std::collections::BTreeMap;
use std::process::Command;

/// Cases that do not match yet, or never will, with the reason.
const KNOWN: &[(&str, &str)] = &[
    // ---- LinuxCNC's own bugs, not matched
    (
        "interp/g71-endless-loop",
        "rs274 2.9-pre never ends (the bug the test was written for); cncc stops with E0506 where the passes would not end",
    ),
    (
        "interp/g71-endless-loop_2",
        "rs274 2.9-pre never ends (the bug the test was written for); cncc stops with E0506 where the passes would not end",
    ),
];

/// Runs of [`ini_cases::INI_CASES`] that do not match, with the reason.
const KNOWN_INI: &[(&str, &str)] = &[(
    "interp/nested-sub-error",
    "rs274 2.9 runs a sub defined inside a called sub as part of its body (LinuxCNC#3880, fixed in master, whose expected output is this error); cncc refuses the nested definition as master does (E0306)",
)];

/// Cases `run.sh` cannot run, by id prefix, with the reason.
const NOT_APPLICABLE: &[(&str, &str)] = &[
    (
        "remap/",
        "REMAP= lines and embedded Python from the INI: out of scope",
    ),
    ("abort/", "linuxcnc -r with HAL: a motion/task test"),
    ("mdi-queue/", "linuxcnc -r with HAL: a motion/task test"),
    ("motion-logger/", "linuxcnc -r with HAL: a motion/task test"),
    ("motion/", "linuxcnc -r with HAL: a motion/task test"),
    ("single-step", "linuxcnc -r with HAL: a motion/task test"),
    (
        "statbuffer-g5x-abort",
        "linuxcnc -r with HAL: a motion/task test",
    ),
    (
        "trajectory-planner/",
        "linuxcnc -r with HAL: a motion/task test",
    ),
    (
        "interp_initcode",
        "linuxcnc -r with HAL (RS274NGC_STARTUP_CODE)",
    ),
    (
        "interp/mdi-oword-m66",
        "linuxcnc -r with HAL, MDI and a Python UI",
    ),
    (
        "interp/oword-mdi-sub-update",
        "linuxcnc -r with HAL, MDI and a Python UI",
    ),
    (
        "interp/subroutine-return",
        "linuxcnc -r with HAL, MDI and a Python UI",
    ),
    ("interp/pymove", "embedded Python o-word subs"),
    ("interp/python-self", "embedded Python o-word subs"),
    ("interp/value-returned", "embedded Python o-word subs"),
    ("interp/python/error", "the LinuxCNC Python module"),
    (
        "interp/oword-unwind",
        "rs274 -n 0 (continue after errors); cncc stops at the first error",
    ),
];

fn skip(why: &str) {
    common::skip_oracle("the LinuxCNC regression suite", why);
}

/// One line of `run.sh`: verdict, case id, detail.
fn parse(line: &str) -> Option<(String, String, String)> {
    let (head, detail) = line.split_once("  -- ").unwrap_or((line, ""));
    let mut words = head.split_whitespace();
    let verdict = words.next()?.to_string();
    if !matches!(
        verdict.as_str(),
        "IDENTICAL" | "DIFFERENT" | "CNCC-ERROR" | "N/A" | "RS274-ERROR"
    ) {
        return None;
    }
    let id = words.collect::<Vec<_>>().join(" ");
    Some((verdict, id, detail.to_string()))
}

/// Whether a case passes: identical, or refused by both at the same place.
fn passes(verdict: &str, detail: &str) -> bool {
    match verdict {
        "IDENTICAL" => true,
        "RS274-ERROR" => {
            detail.contains("cncc errors on the SAME line")
                || detail.contains("cncc errors the same error")
        }
        _ => false,
    }
}

fn not_applicable_reason(id: &str) -> Option<&'static str> {
    NOT_APPLICABLE
        .iter()
        .find(|(prefix, _)| id.starts_with(prefix))
        .map(|(_, why)| *why)
}

#[test]
fn linuxcnc_regression_suite() {
    let Some(shared) = common::shared() else {
        return skip("../shared is absent");
    };
    let script = shared.join("conformance/linuxcnc/run.sh");
    if !script.is_file() {
        return skip("../shared/conformance/linuxcnc/run.sh is absent");
    }
    if !common::rs274_present() {
        return skip("rs274 is not installed (apt-get install linuxcnc-uspace)");
    }
    let out = Command::new("bash")
        .arg(&script)
        .arg(env!("CARGO_BIN_EXE_cncc"))
        .output()
        .expect("run run.sh");
    let text = String::from_utf8_lossy(&out.stdout);
    let cases: BTreeMap<String, (String, String)> = text
        .lines()
        .filter_map(parse)
        .map(|(v, id, d)| (id, (v, d)))
        .collect();
    assert!(
        cases.len() > 100,
        "run.sh printed {} cases; stderr:\n{}",
        cases.len(),
        String::from_utf8_lossy(&out.stderr)
    );
    let known: BTreeMap<&str, &str> = KNOWN.iter().copied().collect();
    let mut problems = Vec::new();
    for (id, (verdict, detail)) in &cases {
        let listed = known.get(id.as_str());
        if verdict == "N/A" {
            if not_applicable_reason(id).is_none() && !ini_cases::run_here(id) {
                problems.push(format!("N/A but not listed: {id} -- {detail}"));
            }
            continue;
        }
        match (passes(verdict, detail), listed) {
            (true, Some(_)) => problems.push(format!(
                "now passes, remove it from KNOWN: {id} ({verdict})"
            )),
            (false, None) => problems.push(format!("{verdict} {id} -- {detail}")),
            _ => {}
        }
    }
    for id in known.keys() {
        if !cases.contains_key(*id) {
            problems.push(format!("listed in KNOWN but not run: {id}"));
        }
    }
    let summary = text.lines().last().unwrap_or("");
    eprintln!("{summary}");
    assert!(
        problems.is_empty(),
        "{} problem(s) with LinuxCNC's regression suite:\n{}\n{summary}",
        problems.len(),
        problems.join("\n")
    );
}

/// The N/A cases that need an INI or a parameter file, run here with
/// `--ini`/`--var-file` given to cncc as `-i`/`-v` to rs274.
#[test]
fn linuxcnc_ini_cases() {
    let Some(shared) = common::shared() else {
        return skip("../shared is absent");
    };
    let suite = shared.join("conformance/linuxcnc");
    let canon_diff = shared.join("tools/canon-diff");
    if !suite.is_dir() || !canon_diff.is_file() {
        return skip("../shared/conformance/linuxcnc or tools/canon-diff is absent");
    }
    if !common::rs274_present() {
        return skip("rs274 is not installed (apt-get install linuxcnc-uspace)");
    }
    let known: BTreeMap<&str, &str> = KNOWN_INI.iter().copied().collect();
    let mut problems = Vec::new();
    let mut passed = 0;
    for c in ini_cases::INI_CASES {
        let result = ini_cases::run(&suite, &canon_diff, c);
        match (result, known.get(c.id)) {
            (None, None) => passed += 1,
            (None, Some(_)) => {
                problems.push(format!("now passes, remove it from KNOWN_INI: {}", c.id))
            }
            (Some(why), None) => problems.push(format!("{}: {why}", c.id)),
            (Some(_), Some(_)) => {}
        }
    }
    eprintln!(
        "{passed} of {} INI / parameter-file runs identical or stopped on the same line",
        ini_cases::INI_CASES.len()
    );
    assert!(
        problems.is_empty(),
        "{} problem(s) with the INI cases:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn lists_have_reasons_and_no_duplicates() {
    let mut seen = std::collections::BTreeSet::new();
    for (id, why) in KNOWN {
        assert!(!why.trim().is_empty(), "{id}: no reason");
        assert!(seen.insert(*id), "{id} listed twice");
    }
    for (prefix, why) in NOT_APPLICABLE {
        assert!(!why.trim().is_empty(), "{prefix}: no reason");
    }
    assert_eq!(
        parse("IDENTICAL    interp/exists  -- 18 calls, exact"),
        Some((
            "IDENTICAL".into(),
            "interp/exists".into(),
            "18 calls, exact".into()
        ))
    );
}
