//! Run-time errors found by `cncc check`: one small program per kind under
//! `tests/programs/<dialect>/runtime/`, each with a snapshot of the
//! rendered report (exit 1).
//!
//! [`PENDING_CORE`] lists the programs whose error comes from block
//! statements the interpreter core does not run yet (the run stops there
//! silently): while one checks clean it is reported as pending, not failed;
//! once it reports, its snapshot is checked like the others.

mod common;
use common::*;

const PENDING_CORE: &[&str] = &[];

/// Subprogram files that programs here call (not run on their own).
const HELPERS: &[&str] = &["linuxcnc/runtime/halve.ngc"];

fn programs() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for dialect in ["linuxcnc", "fanuc", "siemens840d"] {
        let dir = root().join("tests/programs").join(dialect).join("runtime");
        let mut files: Vec<String> = std::fs::read_dir(&dir)
            .expect("runtime dir")
            .filter_map(|e| e.ok())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        files.sort();
        let rel = files.into_iter().map(|f| format!("{dialect}/runtime/{f}"));
        out.extend(
            rel.filter(|r| !HELPERS.contains(&r.as_str()))
                .map(|r| (dialect.to_string(), r)),
        );
    }
    out
}

#[test]
fn runtime_errors_are_reported_with_their_spans() {
    let mut pending = Vec::new();
    for (dialect, rel) in programs() {
        let file = format!("tests/programs/{rel}");
        let o = cncc(&[
            "check",
            "--dialect",
            &dialect,
            "--max-loop",
            "10000",
            "--max-depth",
            "50",
            &file,
        ]);
        if o.status.code() == Some(0) && PENDING_CORE.contains(&rel.as_str()) {
            pending.push(rel);
            continue;
        }
        assert_eq!(o.status.code(), Some(1), "{file}: {}", stderr(&o));
        let name = format!(
            "runtime_{}",
            rel.replace(['/', '.'], "_").replace("_runtime_", "_")
        );
        insta::assert_snapshot!(name, stderr(&o));
    }
    if !pending.is_empty() {
        eprintln!(
            "note: {} run-time checks wait for the interpreter core: {}",
            pending.len(),
            pending.join(", ")
        );
    }
}
