//! The walker's program with its plain moves held as text
//! (`src/interp/lazy.rs`): on every test program and every real program
//! of `../shared` (skipped with a note when it is absent), each block of
//! the lazily read program is the block the whole reading gives, a stub
//! once it is read again from its text (and when the walker reaches it
//! again, from the blocks kept read); and the stubs are most of a CAM
//! program, or the memory they save is not there.

mod common;

use cncc::dialect::builtin::builtin;
use cncc::driver::read_program;
use cncc::interp::lazy::read_program_lazy;
use cncc::span::FileId;
use std::path::Path;

const DIALECTS: [&str; 5] = ["fanuc", "haas", "heidenhain", "linuxcnc", "siemens840d"];

/// Compares the two readings of `path`; counts (blocks, stubs).
fn compare(dialect: &str, path: &Path, diffs: &mut Vec<String>) -> (usize, usize) {
    let Ok(bytes) = std::fs::read(path) else {
        return (0, 0);
    };
    let text = cncc::driver::decode(&bytes);
    let spec = builtin(dialect).unwrap();
    let (whole, d1) = read_program(&text, FileId(0), &spec);
    let (lazy_program, mut lazy, d2) = read_program_lazy(text.as_str(), FileId(0), &spec);
    let name = path.display();
    if d1 != d2 {
        diffs.push(format!("{name}: the diagnostics differ"));
    }
    if whole.blocks.len() != lazy_program.blocks.len() {
        diffs.push(format!(
            "{name}: {} blocks, lazily {}",
            whole.blocks.len(),
            lazy_program.blocks.len()
        ));
        return (0, 0);
    }
    let mut stubs = 0;
    for (i, (w, l)) in whole.blocks.iter().zip(&lazy_program.blocks).enumerate() {
        let got = match lazy.is_stub(i) {
            true => {
                stubs += 1;
                if !l.stmts.is_empty() {
                    diffs.push(format!("{name}: block {i} is a stub with statements"));
                }
                // Read again, then again (kept read from the second time).
                let first = lazy.reread(l);
                for _ in 0..3 {
                    if lazy.fetch(i, l).as_deref() != first.as_ref() {
                        diffs.push(format!("{name}: block {i} fetched is not the block read"));
                    }
                }
                first
            }
            false => Some(l.clone()),
        };
        if got.as_ref() != Some(w) {
            diffs.push(format!("{name}: block {i} differs: {w:?} / {got:?}"));
        }
    }
    (whole.blocks.len(), stubs)
}

fn tree(root: &Path, diffs: &mut Vec<String>) -> (usize, usize) {
    let mut n = (0, 0);
    for d in DIALECTS {
        for f in common::files_in(&root.join(d)) {
            let (b, s) = compare(d, &f, diffs);
            n = (n.0 + b, n.1 + s);
        }
    }
    n
}

#[test]
fn a_lazily_read_program_is_the_program_on_the_test_programs() {
    let mut diffs = Vec::new();
    let (blocks, stubs) = tree(&common::root().join("tests/programs"), &mut diffs);
    assert!(diffs.is_empty(), "{}", diffs.join("\n"));
    assert!(
        stubs * 4 > blocks,
        "only {stubs} of {blocks} blocks are stubs"
    );
}

#[test]
fn a_lazily_read_program_is_the_program_on_real_programs() {
    let Some(shared) = common::shared() else {
        eprintln!("../shared is absent: the real programs are not compared");
        return;
    };
    let mut diffs = Vec::new();
    let (mut blocks, mut stubs) = (0, 0);
    for top in ["corpus", "field"] {
        let (b, s) = tree(&shared.join(top), &mut diffs);
        blocks += b;
        stubs += s;
    }
    assert!(diffs.is_empty(), "{}", diffs.join("\n"));
    // Real programs are mostly moves.
    assert!(
        stubs * 2 > blocks,
        "only {stubs} of {blocks} blocks are stubs"
    );
}
