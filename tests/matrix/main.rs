//! The port matrix: one folder per topic under `tests/matrix/`, each with
//! source programs `from-<dialect>[-<variant>].<ext>` and, for every target dialect,
//! one cell:
//!
//! * `from-<dialect>.to-<target>`: the exact text `cncc port --verify`
//!   must write (and the verification must pass);
//! * `from-<dialect>.to-<target>.error`: the diagnostic code the port must
//!   refuse with ("cannot express" is an asserted cell, not a gap);
//! * `from-<dialect>.to-<target>.gap`: a known gap outside the port (its
//!   first line says which); the cell fails as long as the port does not
//!   succeed, and reports "gap closed" once it does, so the gap cannot be
//!   forgotten when it is fixed.
//!
//! Every port runs with `--verify`. A missing cell fails the test. With
//! `MATRIX_UPDATE=1` missing cells are written from the current output (to
//! be read before they are committed).

use std::path::{Path, PathBuf};
use std::process::Command;

const TARGETS: [&str; 5] = ["fanuc", "haas", "heidenhain", "linuxcnc", "siemens840d"];

fn sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        let Some(rest) = name.strip_prefix("from-") else {
            continue;
        };
        if rest.contains(".to-") {
            continue;
        }
        // `from-<dialect>[-<variant>].<ext>`
        let dialect = rest.split(['.', '-']).next().unwrap().to_string();
        out.push((p, dialect));
    }
    out.sort();
    out
}

fn port(src: &Path, from: &str, to: &str) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(["port", "--strict", "--from", from, "--to", to, "--verify"])
        .arg(src)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Checks one cell; returns a failure message.
fn cell(src: &Path, from: &str, to: &str, update: bool) -> Option<String> {
    let stem = src.with_extension("");
    let text_cell = PathBuf::from(format!("{}.to-{to}", stem.display()));
    let error_cell = PathBuf::from(format!("{}.to-{to}.error", stem.display()));
    let (code, stdout, stderr) = port(src, from, to);
    let what = format!("{} -> {to}", src.display());
    if let Ok(expected) = std::fs::read_to_string(&text_cell) {
        if code != 0 {
            return Some(format!("{what}: exit {code}\n{stderr}"));
        }
        if !stderr.contains("verify: OK") {
            return Some(format!("{what}: no verification verdict\n{stderr}"));
        }
        return (stdout != expected)
            .then(|| format!("{what}: text differs\n--- expected\n{expected}--- got\n{stdout}"));
    }
    if let Ok(codes) = std::fs::read_to_string(&error_cell) {
        let codes: Vec<&str> = codes.split_whitespace().collect();
        if code != 1 {
            return Some(format!(
                "{what}: expected refusal {codes:?}, got exit {code}\n{stdout}"
            ));
        }
        let missing: Vec<_> = codes
            .iter()
            .filter(|c| !stderr.contains(&format!("[{c}")))
            .collect();
        return (!missing.is_empty())
            .then(|| format!("{what}: refusal without {missing:?}\n{stderr}"));
    }
    let gap_cell = PathBuf::from(format!("{}.to-{to}.gap", stem.display()));
    if let Ok(why) = std::fs::read_to_string(&gap_cell) {
        eprintln!("known gap: {what}: {}", why.lines().next().unwrap_or(""));
        return (code == 0).then(|| {
            format!(
                "{what}: gap closed: replace {} by the expected text",
                gap_cell.display()
            )
        });
    }
    if update {
        if code == 0 {
            std::fs::write(&text_cell, stdout).unwrap();
        } else {
            let mut codes: Vec<String> = stderr
                .lines()
                .filter_map(|l| l.strip_prefix("error["))
                .filter_map(|l| l.split_whitespace().next().map(str::to_string))
                .collect();
            codes.sort();
            codes.dedup();
            std::fs::write(&error_cell, codes.join("\n") + "\n").unwrap();
        }
        return None;
    }
    Some(format!(
        "{what}: no cell (write {} or {})",
        text_cell.display(),
        error_cell.display()
    ))
}

#[test]
fn port_matrix() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/matrix");
    let update = std::env::var("MATRIX_UPDATE").is_ok();
    let mut topics: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .collect();
    topics.sort();
    let mut failures = Vec::new();
    let mut cells = 0;
    for t in &topics {
        for (src, from) in sources(t) {
            for to in TARGETS {
                cells += 1;
                failures.extend(cell(&src, &from, to, update));
            }
        }
    }
    assert!(cells > 0, "no matrix cells under {}", root.display());
    assert!(
        failures.is_empty(),
        "{} of {cells} cells fail:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
