//! `port --verify` run side by side (`src/port/verify_lockstep.rs`, the
//! two programs on two threads, their operations compared as they come)
//! against the proof over the two runs held whole: every program of
//! `tests/programs/`, `../shared/corpus/` and `../shared/field/` that
//! reads cleanly and runs as a stream is ported to each other dialect,
//! and both proofs must give the same verdict, to the same first
//! difference. A port made wrong on purpose must fail both ways. The
//! real programs are skipped with a note when `../shared` is absent.

mod common;

use cncc::dialect::builtin::builtin;
use cncc::interp::flow::NoLoader;
use cncc::interp::Options;
use cncc::port::verify_lockstep::{self, Side};
use cncc::port::{port_program, verify, verify_text, PortOptions, ToolMap};
use cncc::source::SourceMap;
use std::path::Path;
use std::sync::Arc;

const DIALECTS: [&str; 5] = ["fanuc", "haas", "heidenhain", "linuxcnc", "siemens840d"];

/// The two proofs of `out` (the port of `text`), or None where the
/// side-by-side proof does not apply (or a run stops).
fn both_proofs(
    files: &mut SourceMap,
    (text, from): (&str, &Arc<cncc::dialect::DialectSpec>),
    (out, to): (&str, &Arc<cncc::dialect::DialectSpec>),
) -> Option<(String, String)> {
    let opts = Options::default();
    let ida = files.add("source", text.to_string());
    let idb = files.add("port", out.to_string());
    let side = |t: &'_ str, id, spec| verify_text::scan(t, id, spec);
    let (sa, sb) = (side(text, ida, from), side(out, idb, to));
    if sa.has_errors() || sb.has_errors() {
        return None;
    }
    let a = Side {
        text,
        id: ida,
        scan: sa,
        spec: from,
        opts: &opts,
    };
    let b = Side {
        text: out,
        id: idb,
        scan: sb,
        spec: to,
        opts: &opts,
    };
    if !a.streams() || !b.streams() {
        return None;
    }
    let tol = verify::tolerance_for(to);
    let tools = ToolMap::default();
    // The whole proof: each run held, then compared.
    let (ea, da) =
        verify_text::events(text, ida, side(text, ida, from), from, &opts, &mut NoLoader);
    let (eb, db) = verify_text::events(out, idb, side(out, idb, to), to, &opts, &mut NoLoader);
    if da.iter().chain(&db).any(|d| d.is_error()) {
        return None;
    }
    let whole = verify::compare_owned(ea, eb, &tools, tol);
    let lock = verify_lockstep::compare(a, b, &tools, tol);
    assert!(!lock.source.iter().chain(&lock.port).any(|d| d.is_error()));
    Some((format!("{whole:?}"), format!("{:?}", lock.verdict)))
}

/// Ports `path` (read as `from`) to every other dialect and compares the
/// two proofs; the differences found, and how many ports were proved.
fn check_file(from: &str, path: &Path, proved: &mut usize) -> Vec<String> {
    let mut out = Vec::new();
    let Ok(bytes) = std::fs::read(path) else {
        return out;
    };
    let text = cncc::driver::decode(&bytes);
    let spec = builtin(from).unwrap();
    let mut files = SourceMap::new();
    let id = files.add(path.display().to_string(), text.clone());
    let (program, read) = cncc::driver::read_program(&text, id, &spec);
    if read.iter().any(|d| d.is_error()) {
        return out;
    }
    for to in DIALECTS.iter().filter(|t| **t != from) {
        let target = builtin(to).unwrap();
        let (ported, diags) = port_program(&program, &spec, &target, &PortOptions::default());
        if diags.iter().any(|d| d.is_error()) {
            continue;
        }
        let Ok(written) = cncc::emit::write_program(&ported, &target) else {
            continue;
        };
        if let Some((whole, lock)) = both_proofs(&mut files, (&text, &spec), (&written, &target)) {
            *proved += 1;
            if whole != lock {
                out.push(format!(
                    "{} -> {to}:\n  whole: {whole}\n  side by side: {lock}",
                    path.display()
                ));
            }
        }
    }
    out
}

fn check_tree(root: &Path, dialect: &str, diffs: &mut Vec<String>, proved: &mut usize) {
    for f in common::files_in(&root.join(dialect)) {
        if f.extension().is_some_and(|e| e == "md") {
            continue;
        }
        diffs.extend(check_file(dialect, &f, proved));
    }
}

fn judge(diffs: &[String], proved: usize, at_least: usize) {
    assert!(
        diffs.is_empty(),
        "{} differ:\n{}",
        diffs.len(),
        diffs.join("\n")
    );
    assert!(
        proved >= at_least,
        "only {proved} ports were proved side by side"
    );
    eprintln!("{proved} ports proved side by side, the same verdict as held whole");
}

#[test]
fn side_by_side_and_whole_proofs_agree_on_the_test_programs() {
    let (mut diffs, mut proved) = (Vec::new(), 0);
    for d in DIALECTS {
        check_tree(
            &common::root().join("tests/programs"),
            d,
            &mut diffs,
            &mut proved,
        );
    }
    judge(&diffs, proved, 50);
}

#[test]
fn side_by_side_and_whole_proofs_agree_on_real_programs() {
    let Some(shared) = common::shared() else {
        return;
    };
    let (mut diffs, mut proved) = (Vec::new(), 0);
    for top in ["corpus", "field"] {
        for d in DIALECTS {
            check_tree(&shared.join(top), d, &mut diffs, &mut proved);
        }
    }
    judge(&diffs, proved, 100);
}

/// A long program (well past the batches and the aligner's window) with
/// one wrong move in the middle, one rapid through the part after the
/// last cut, or both right: the side-by-side proof finds each where the
/// whole one does.
#[test]
fn a_wrong_port_fails_side_by_side_as_it_does_whole() {
    let spec = builtin("fanuc").unwrap();
    let program_from = |wrong_at: Option<usize>, shifted_from: Option<usize>, low_exit: bool| {
        let mut t =
            String::from("G21 G90 G17\nT1 M6\nG0 X0 Y0 S5000 M3\nG43 H1 Z5.\nG1 Z-1. F300.\n");
        for i in 1..20_000 {
            let mut y = if Some(i) == wrong_at {
                0.5
            } else {
                (i % 2) as f64
            };
            if shifted_from.is_some_and(|k| i >= k) {
                y += 0.25;
            }
            t.push_str(&format!("X{i}. Y{y:.1}\n"));
        }
        t.push_str(if low_exit {
            "G0 X0 Y0\nG0 Z5.\nM30\n"
        } else {
            "G0 Z5.\nG0 X0 Y0\nM30\n"
        });
        t
    };
    let program = |wrong_at: Option<usize>, low_exit: bool| program_from(wrong_at, None, low_exit);
    let good = program(None, false);
    let mut files = SourceMap::new();
    let run = |files: &mut SourceMap, other: &str| {
        let (whole, lock) = both_proofs(files, (&good, &spec), (other, &spec)).expect("both run");
        assert_eq!(whole, lock);
        lock
    };
    assert!(run(&mut files, &good).contains("cutting: None"));
    let moved = run(&mut files, &program(Some(12_345), false));
    assert!(
        moved.contains("A: line to X12345 Y1 Z-1; B: line to X12345 Y0.5 Z-1"),
        "{moved}"
    );
    // Never back in step: the rest of both is one difference, read to
    // the end of both runs.
    let apart = run(&mut files, &program_from(None, Some(10_000), false));
    assert!(apart.contains("A: 10000 operations from line to X10000 Y0 Z-1; B: 10000 operations from line to X10000 Y0.2 Z-1"), "{apart}");
    let low = run(&mut files, &program(None, true));
    assert!(
        low.contains("cutting: None") && low.contains("below the highest cutting height"),
        "{low}"
    );
}
