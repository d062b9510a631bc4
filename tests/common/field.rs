//! The real programs of `../shared/field/` and `../shared/corpus/` and
//! the list of those that do not check clean (`tests/field/*.expect`):
//! shared by the check and the port judges.

use super::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

pub const DIALECTS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// One expected rejection: the first error's code and why it is right.
pub struct Expected {
    pub code: String,
    pub reason: String,
}

pub fn expectations() -> BTreeMap<String, Expected> {
    let mut out = BTreeMap::new();
    for d in DIALECTS {
        let path = root().join("tests/field").join(format!("{d}.expect"));
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim_end();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let mut parts = line.splitn(3, '\t');
            let (Some(file), Some(code), Some(reason)) = (parts.next(), parts.next(), parts.next())
            else {
                panic!(
                    "{}:{}: want `file<TAB>code<TAB>reason`",
                    path.display(),
                    n + 1
                );
            };
            assert!(
                reason.len() > 10 && !reason.starts_with("TODO"),
                "{}:{}: say why the rejection is right",
                path.display(),
                n + 1
            );
            out.insert(
                file.to_string(),
                Expected {
                    code: code.to_string(),
                    reason: reason.to_string(),
                },
            );
        }
    }
    out
}

/// (dialect, path relative to `../shared`) of every program judged.
pub fn programs(shared: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for top in ["field", "corpus"] {
        for d in DIALECTS {
            collect(shared, &shared.join(top).join(d), d, &mut out);
        }
    }
    for f in files_in(&shared.join("field/big")) {
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        let d = DIALECTS
            .iter()
            .find(|d| name.starts_with(&format!("{d}_")))
            .copied()
            .unwrap_or("linuxcnc");
        out.push((d.to_string(), rel(shared, &f)));
    }
    out
}

fn collect(shared: &Path, dir: &Path, d: &str, out: &mut Vec<(String, String)>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()).collect())
        .unwrap_or_default();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect(shared, &p, d, out);
        } else if !p.file_name().unwrap().to_string_lossy().ends_with(".md") {
            out.push((d.to_string(), rel(shared, &p)));
        }
    }
}

pub fn rel(shared: &Path, p: &Path) -> String {
    p.strip_prefix(shared)
        .unwrap()
        .to_string_lossy()
        .replace('\\', "/")
}

/// The code of the first error `check` printed (`error[E0122 ...]`).
pub fn first_error(stderr: &str) -> Option<String> {
    stderr.lines().find_map(|l| {
        let rest = l.strip_prefix("error[")?;
        Some(rest.split([' ', ']']).next()?.to_string())
    })
}
