//! Entry points for fuzz targets and property tests: whatever the input,
//! reading, checking and writing must not panic, hang or blow up memory.

use crate::dialect::builtin::builtin;
use crate::driver::{decode, read_program};
use crate::emit::write_program;
use crate::span::FileId;

/// Reads `data` as a program of `dialect`; if it reads without errors,
/// writes it back and reads the result again.
pub fn read_and_write(dialect: &str, data: &[u8]) {
    let Some(spec) = builtin(dialect) else { return };
    let text = decode(data);
    let (program, diags) = read_program(&text, FileId(0), &spec);
    if diags.iter().any(|d| d.is_error()) {
        return;
    }
    if let Ok(out) = write_program(&program, &spec) {
        let _ = read_program(&out, FileId(1), &spec);
    }
}

/// The dialects every target below goes through.
pub const DIALECTS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// Reads `data` as a program of `dialect` and runs it in the interpreter
/// (canonical calls counted, never kept), with small run limits so that a
/// fuzzed loop ends quickly.
pub fn interpret(dialect: &str, data: &[u8]) {
    let Some(spec) = builtin(dialect) else { return };
    let text = decode(data);
    let (program, diags) = read_program(&text, FileId(0), &spec);
    if diags.iter().any(|d| d.is_error()) {
        return;
    }
    let mut opts = crate::interp::Options::default();
    opts.limits.loop_iterations = 1000;
    opts.limits.blocks = 100_000;
    let mut calls = 0u64;
    let mut sink = |_: crate::canon::Canon, _: crate::span::Span| calls += 1;
    let mut loader = crate::interp::flow::NoLoader;
    let _ = crate::interp::run(
        std::rc::Rc::new(program),
        &spec,
        &opts,
        &mut loader,
        &mut sink,
    );
}

/// Reads `data` as a program of `from` and ports it to every other
/// dialect; what is written is read back.
pub fn port(from: &str, data: &[u8]) {
    let Some(spec) = builtin(from) else { return };
    let text = decode(data);
    let (program, diags) = read_program(&text, FileId(0), &spec);
    if diags.iter().any(|d| d.is_error()) {
        return;
    }
    for to in DIALECTS.iter().filter(|t| **t != from) {
        let Some(target) = builtin(to) else { continue };
        let (ported, d) = crate::port::port_program(&program, &spec, &target, &Default::default());
        if d.iter().any(|d| d.is_error()) {
            continue;
        }
        if let Ok(out) = write_program(&ported, &target) {
            let _ = read_program(&out, FileId(1), &target);
        }
    }
}

/// Reads `data` as STEP-NC Part 21 and posts it to every dialect.
pub fn post(data: &[u8]) {
    let text = decode(data);
    let read = crate::stepnc::read_text(&text, FileId(0));
    let Some(project) = read.project else { return };
    for to in DIALECTS {
        if let Some(target) = builtin(to) {
            if let Ok(p) = crate::post::post(&project, &target) {
                let _ = read_program(&p.text, FileId(1), &target);
            }
        }
    }
}
