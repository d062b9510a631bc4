//! Every STEP-NC file of `../shared/stepnc-samples/` and its `field/`
//! folder (issue 15's judge): it reads without errors, writes, and reads
//! back to the same model (a fixpoint); it posts to all five dialects, or
//! each refusal is a located error with a code the table below gives and
//! explains; whatever posts has been read back clean by the target's own
//! front end (the post does that before returning). Skipped with a note
//! when `../shared` is absent.

use cncc::diag::{Code, Diagnostic};
use cncc::source::SourceMap;
use cncc::stepnc::{self, query::locate_diagnostics};
use std::path::{Path, PathBuf};

const TARGETS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// Files that do not post, the first error's code on every target, and
/// why (what in the file the validator or the post refuses). A file not
/// listed must post to every target.
const REFUSED: &[(&str, &str, &str)] = &[
    ("sanssouci__Cavidade.p21", "E0908", "80x50 pocket at (110,75) in a 120x100 block: outside the stock even with --profiles-absolute (the profile repeats the feature's placement)"),
    ("sanssouci__FuroBaseArredondada.p21", "E0908", "hole placed at z 100 on a 50 mm block"),
    ("sanssouci__FuroBaseConica.p21", "E0908", "hole placed at z 100 on a 50 mm block"),
    ("sanssouci__FuroBaseEsferica.p21", "E0908", "hole placed at z 100 on a 50 mm block"),
    ("sanssouci__FuroConico.p21", "E0908", "hole placed at z 100 on a 50 mm block"),
    ("sanssouci__RanhuraPerfilBezier.p21", "E0908", "the slot's depth plane is at its top (z 0 in its frame)"),
    ("sanssouci__RanhuraPerfilCircularParcial.p21", "E0908", "the slot's depth plane is at its top (z 0 in its frame)"),
    ("TesteFinalUNBLAB.p21", "E0908", "a U slot whose profile repeats the feature's absolute placement lands outside the 120x100 block"),
    ("sanssouci__Frasen_Prufung", "E0901", "the slot's MILLING_TECHNOLOGY gives a feed only: no spindle speed nor cutting speed (ISO 14649-11 wants two of the four)"),
    ("sanssouci__OneHoleOneSlot", "E0901", "the slot's MILLING_TECHNOLOGY gives no spindle speed"),
    ("sanssouci__OneHoleOneSlotIntegration", "E0901", "the slot's MILLING_TECHNOLOGY gives no spindle speed"),
    ("sanssouci__OneHoleOneSlotReaderTest.p21", "E0901", "the slot's MILLING_TECHNOLOGY gives no spindle speed"),
    ("sanssouci__Ranhura.p21", "E0901", "the roughing MILLING_TECHNOLOGY's feedrate is 0.0 and its feed per tooth `$`: no feed (posted before as `G1 ... F0`, which LinuxCNC refuses and no control can run)"),
    ("sanssouci__STEP-NC_2HolesFile.p21", "E0901", "the MILLING_TECHNOLOGY gives a feed only: no spindle speed (its BORING_TOOL is the 840D's boring bar, type 210)"),
    ("sanssouci__STEP-NC_Slot1_File.p21", "E0908", "a 120 mm slot across a 100 mm block (its profile's radii `$` now read)"),
    ("sanssouci__STEP-NC2DifHOLES.p21", "E0901", "the DRILLING technologies give a feed only: no spindle speed (the holes' its_workpiece `$` is read as the project's one workpiece)"),
    ("sanssouci__STEP-NC_File.p21", "E0901", "MULTISTEP_DRILLING #47 with its technology `$` (mandatory, no default in ISO 14649-11: no feed, no spindle speed), located at that `$`; the other workingsteps' technology gives a feed only"),
    ("sanssouci__STEP-NC_slot_File.p21", "E0901", "its tool #18 is MILLING_CUTTING_TOOL($,$,$,$,$,$): no tool body (type, diameter), and its LINEAR_PATH has no distance nor direction; ISO 14649 gives no default: located at #18's `$`"),
    ("sanssouci__STEP-NC_pocket_File.p21", "", "every placement's axis is +X (axis and ref_direction swapped?): E0900 where the target cannot tilt; where it can (840D, Heidenhain), the depth planes at +30/+50 are not below the tops and the pocket lies outside the block (E0908)"),
    ("sanssouci__testBoxy.p21", "", "holes on the part's sides: E0900 where the target cannot tilt; where it can (840D, Heidenhain) the side holes post as 3+2 and the validator refuses the holes placed at z 100 facing up, the front holes at z 107..195 and the pockets whose profile repeats their placement (E0908)"),
];

fn dir() -> Option<PathBuf> {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/stepnc-samples");
    if d.is_dir() {
        Some(d)
    } else {
        eprintln!("note: ../shared/stepnc-samples is absent; the STEP-NC field test is skipped");
        None
    }
}

/// The ISO 14649 ARM files of the samples and the field folder.
fn files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for d in [dir.to_path_buf(), dir.join("field")] {
        let Ok(rd) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in rd.flatten() {
            let p = e.path();
            let name = p.file_name().unwrap().to_string_lossy().to_string();
            let arm =
                name.starts_with("sanssouci__") || name.ends_with(".stp") || name.ends_with(".p21");
            if p.is_file() && arm {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// A posted program runs to its end in cncc's interpreter for its
/// target without an error (issue 15: every posted program checks clean;
/// a feed of 0 reads back fine and only fails when run).
fn runs_clean(fname: &str, spec: &std::sync::Arc<cncc::dialect::DialectSpec>, text: &str) {
    let mut map = SourceMap::new();
    let id = map.add("posted", text.to_string());
    let opts = cncc::interp::Options::default();
    let mut sink = |_: cncc::canon::Canon, _: cncc::span::Span| {};
    let dir = std::env::temp_dir();
    let d = cncc::interp::file::run_text(text, id, &dir, spec, &opts, &mut map, &mut sink)
        .expect("runs from memory");
    let e = errors(&d);
    assert!(e.is_empty(), "{fname} posted to {}: {:?}", spec.id, e);
}

fn errors(d: &[Diagnostic]) -> Vec<&Diagnostic> {
    d.iter().filter(|d| d.is_error()).collect()
}

#[test]
fn every_field_file_reads_writes_and_reads_back() {
    let Some(dir) = dir() else { return };
    let all = files(&dir);
    assert!(all.len() >= 30, "expected the samples and 27 field files");
    for path in all {
        let mut map = SourceMap::new();
        let r = stepnc::read_file(&path, &mut map).expect("readable");
        let name = path.display();
        assert!(
            errors(&r.diagnostics).is_empty(),
            "{name}: {:?}",
            errors(&r.diagnostics)
        );
        let p1 = r.project.unwrap_or_else(|| panic!("{name}: no model"));
        let text1 = stepnc::write_project(&p1);
        let id = map.add("again.stp", text1.clone());
        let r2 = stepnc::read_text(&text1, id);
        assert!(
            errors(&r2.diagnostics).is_empty(),
            "{name} rewritten: {:?}",
            errors(&r2.diagnostics)
        );
        let p2 = r2.project.expect("model of the rewritten file");
        assert_eq!(p1, p2, "{name}: the model changed through write and read");
        assert_eq!(text1, stepnc::write_project(&p2), "{name}: not a fixpoint");
    }
}

#[test]
fn every_field_file_posts_or_is_refused_at_a_located_entity() {
    let Some(dir) = dir() else { return };
    for path in files(&dir) {
        let fname = path.file_name().unwrap().to_string_lossy().to_string();
        let mut map = SourceMap::new();
        let r = stepnc::read_file(&path, &mut map).expect("readable");
        let project = r.project.expect("reads (see the other test)");
        let expected = REFUSED.iter().find(|(f, _, _)| *f == fname);
        for t in TARGETS {
            let spec = cncc::dialect::builtin(t).expect("built-in dialect");
            match (cncc::post::post(&project, &spec), expected) {
                (Ok(posted), None) => runs_clean(&fname, &spec, &posted.text),
                (Ok(_), Some((_, _, why))) => {
                    panic!("{fname} posts to {t} now; drop it from REFUSED ({why})")
                }
                (Err(mut d), exp) => {
                    locate_diagnostics(&r.graph, &mut d);
                    let first = errors(&d)
                        .first()
                        .copied()
                        .unwrap_or_else(|| panic!("{fname}/{t}: refused without an error"))
                        .clone();
                    let Some((_, code, _)) = exp else {
                        panic!("{fname} no longer posts to {t}: {first:?}")
                    };
                    if !code.is_empty() {
                        assert_eq!(first.code.code(), *code, "{fname}/{t}: {}", first.message);
                    }
                    for e in errors(&d) {
                        assert!(
                            e.code != Code::PostTemplate && e.code != Code::PostReadBack,
                            "{fname}/{t}: a post bug: {}",
                            e.message
                        );
                    }
                    let located = errors(&d).iter().filter(|e| !e.labels.is_empty()).count();
                    assert!(
                        located > 0,
                        "{fname}/{t}: no refusal points into the file: {d:?}"
                    );
                }
            }
        }
    }
}
