//! `cncc port --verify` on every real program that checks clean (see
//! `tests/field_check.rs`), to each of the other four dialects, and the
//! port back to the program's own dialect, verified too: the matrix a new
//! user would try.
//!
//! Every cell that does not port is listed in `tests/field/port.expect` as
//! `file<TAB>target<TAB>code<TAB>construct` (the target `fanuc+back` is
//! the way back from Fanuc to the program's dialect): the code is the
//! first error, the construct what the target has no form for. A listed
//! cell that now ports fails the test as well, so the list only shrinks.
//! Set `CNCC_PORT_MATRIX_OUT=file` to write the cells observed (to review
//! them before they replace the list).

mod common;
use common::field::*;
use common::*;
use std::collections::BTreeMap;
use std::path::Path;

fn listed() -> BTreeMap<(String, String), String> {
    let path = root().join("tests/field/port.expect");
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    let mut out = BTreeMap::new();
    for (n, line) in text.lines().enumerate() {
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let f: Vec<&str> = line.splitn(4, '\t').collect();
        assert!(
            f.len() == 4 && f[3].len() > 5,
            "port.expect:{}: want `file<TAB>target<TAB>code<TAB>construct`",
            n + 1
        );
        out.insert((f[0].to_string(), f[1].to_string()), f[2].to_string());
    }
    out
}

/// What one cell gave: `None` when it ported and verified, else the code
/// and message of its first error (or the verdict line).
type Cell = Option<(String, String)>;

fn first_problem(stderr: &str) -> (String, String) {
    let err = stderr.lines().find(|l| l.starts_with("error["));
    let verdict = stderr.lines().find(|l| l.starts_with("verify: FAILED"));
    match (err, verdict) {
        (Some(e), _) => {
            let code = first_error(e).unwrap_or_default();
            let msg = e.split_once("]: ").map_or(e, |x| x.1);
            (code, msg.chars().take(140).collect())
        }
        (None, Some(v)) => ("VERIFY".into(), v.chars().take(140).collect()),
        (None, None) => ("EXIT".into(), "failed without a message".into()),
    }
}

fn port(from: &str, to: &str, src: &Path, out: &Path) -> Cell {
    let o = cncc(&[
        "port",
        "--from",
        from,
        "--to",
        to,
        "--verify",
        src.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    match o.status.code() {
        Some(0) => None,
        Some(1) => Some(first_problem(&stderr(&o))),
        other => Some((
            "CRASH".into(),
            format!(
                "exit {other:?}: {}",
                stderr(&o).lines().last().unwrap_or("")
            ),
        )),
    }
}

fn extension(d: &str) -> &'static str {
    match d {
        "siemens840d" => "mpf",
        "heidenhain" => "h",
        "linuxcnc" => "ngc",
        _ => "nc",
    }
}

/// The cells of one program: there and back for each other dialect.
fn cells(
    shared: &Path,
    d: &str,
    file: &str,
    dir: &Path,
    i: usize,
) -> Vec<((String, String), Cell)> {
    let src = shared.join(file);
    let mut out = Vec::new();
    for t in DIALECTS.iter().filter(|t| *t != &d) {
        let there = dir.join(format!("{i}-{t}.{}", extension(t)));
        let cell = port(d, t, &src, &there);
        let ok = cell.is_none();
        out.push(((file.to_string(), t.to_string()), cell));
        if ok {
            let back = dir.join(format!("{i}-{t}-back.{}", extension(d)));
            out.push((
                (file.to_string(), format!("{t}+back")),
                port(t, d, &there, &back),
            ));
        }
    }
    out
}

#[test]
fn clean_field_programs_port_to_every_dialect_and_back() {
    let Some(shared) = shared() else {
        return;
    };
    let rejected = expectations();
    let progs: Vec<(String, String)> = programs(&shared)
        .into_iter()
        .filter(|(_, f)| !rejected.contains_key(f) && !f.starts_with("field/big/"))
        .collect();
    let dir = tempfile::tempdir().unwrap();
    let results: Vec<((String, String), Cell)> = std::thread::scope(|s| {
        let chunks: Vec<_> = (0..2)
            .map(|k| {
                let (progs, shared, dir) = (&progs, &shared, dir.path());
                s.spawn(move || {
                    let mut v = Vec::new();
                    for (i, (d, f)) in progs.iter().enumerate().filter(|(i, _)| i % 2 == k) {
                        v.extend(cells(shared, d, f, dir, i));
                    }
                    v
                })
            })
            .collect();
        chunks.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    if let Ok(path) = std::env::var("CNCC_PORT_MATRIX_OUT") {
        let mut text = String::new();
        let mut sorted: Vec<_> = results.iter().filter(|(_, c)| c.is_some()).collect();
        sorted.sort_by(|a, b| a.0.cmp(&b.0));
        for ((f, t), c) in sorted {
            let (code, msg) = c.as_ref().unwrap();
            text.push_str(&format!("{f}\t{t}\t{code}\t{msg}\n"));
        }
        std::fs::write(path, text).unwrap();
    }
    let list = listed();
    let mut failures = Vec::new();
    let there: Vec<_> = results
        .iter()
        .filter(|((_, t), _)| !t.ends_with("+back"))
        .collect();
    let passed = there.iter().filter(|(_, c)| c.is_none()).count();
    let back = results.iter().filter(|((_, t), _)| t.ends_with("+back"));
    let back_passed = back.clone().filter(|(_, c)| c.is_none()).count();
    eprintln!(
        "{passed}/{} (program, target) pairs port and verify; {back_passed}/{} of them port back, verified",
        there.len(),
        back.count()
    );
    for (key, cell) in &results {
        match (cell, list.get(key)) {
            (None, None) => {}
            (None, Some(code)) => failures.push(format!(
                "{} -> {}: listed as refused ({code}) but ports now: take it off tests/field/port.expect",
                key.0, key.1
            )),
            (Some((code, _)), Some(want)) if code == want => {}
            (Some((code, msg)), _) if code == "CRASH" => {
                failures.push(format!("{} -> {}: crashed: {msg}", key.0, key.1))
            }
            (Some((code, msg)), want) => failures.push(format!(
                "{} -> {}: {code} {msg} (listed: {want:?})",
                key.0, key.1
            )),
        }
    }
    for key in list.keys() {
        if !results.iter().any(|(k, _)| k == key) {
            failures.push(format!(
                "{} -> {} is listed but was not tried",
                key.0, key.1
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
